#pragma once
/// @file broadphase/world.hpp
/// The course notes' hierarchy end to end: a broadphase on the shapes' conservative bounding boxes
/// proposes pairs, the exact pair decisions (overlaps, contact) settle them. World keeps bodies
/// between steps and reports contacts that began and ended; the find_* helpers below answer once
/// for a list of shapes (they build a broadphase on every call).

#include "collide/broadphase/events.hpp"
#include "collide/broadphase/pair_map.hpp"
#include "collide/broadphase/tree.hpp"
#include "collide/chain.hpp"
#include "collide/contains.hpp"
#include "collide/contact.hpp"
#include "collide/overlaps.hpp"
#include "collide/raycast.hpp"
#include "collide/registry.hpp"
#include "collide/transform.hpp"
#include "collide/transformed.hpp"

#include <algorithm>
#include <optional>
#include <ranges>
#include <span>
#include <type_traits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace collide::broadphase {

/// Two shapes of the input list, by index, a < b.
struct ShapePair {
  std::size_t a;  ///< index of the first shape
  std::size_t b;  ///< index of the second shape, b > a
  /// Field-wise equality.
  friend constexpr bool operator==(const ShapePair&, const ShapePair&) = default;
  /// Field-wise order (a total order of handles).
  friend constexpr auto operator<=>(const ShapePair&, const ShapePair&) = default;
};

/// A contact between shapes a < b of the input list (normal points from a toward b).
template <Scalar T>
struct ShapeContact {
  std::size_t a;       ///< index of the first shape
  std::size_t b;       ///< index of the second shape, b > a
  Contact<T> contact;  ///< contact(shapes[a], shapes[b])
};

/// Every pair of shapes that overlaps(), sorted by (a, b). Same answer as testing all pairs:
/// bounds() never shrinks a shape, and the broadphase reports every pair of touching boxes.
/// BP is DynamicTree<T> (default), SweepAndPrune<T> or UniformGrid<T>, built by `make_bp`.
template <Scalar T, class BP = DynamicTree<T>>
std::vector<ShapePair> find_overlapping_shapes(std::span<const Shape<T>> shapes, BP bp = BP()) {
  for (std::size_t i = 0; i < shapes.size(); ++i) bp.add(bounds(shapes[i]), i);
  std::vector<ShapePair> out;
  for (const ProxyPair& p : bp.pairs()) {
    std::size_t a = bp.user_data(p.a), b = bp.user_data(p.b);
    if (a > b) std::swap(a, b);
    if (overlaps(shapes[a], shapes[b])) out.push_back({a, b});
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Every contact between overlapping shapes, sorted by (a, b); contact(a, b) exists exactly
/// when overlaps(a, b), so the pairs are those of find_overlapping_shapes().
template <Scalar T, class BP = DynamicTree<T>>
std::vector<ShapeContact<T>> find_contacts(std::span<const Shape<T>> shapes, BP bp = BP()) {
  std::vector<ShapeContact<T>> out;
  for (const ShapePair& p : find_overlapping_shapes<T, BP>(shapes, std::move(bp))) {
    if (auto c = contact(shapes[p.a], shapes[p.b])) out.push_back({p.a, p.b, *c});
  }
  return out;
}

/// bounds(shape) padded by 16 eps_T of its scale: a hit that collide::raycast reports within its
/// own rounding tolerance just outside a shape still finds that shape's box. Contains bounds().
template <Scalar T>
Aabb<T> raycast_bounds(const Shape<T>& shape) {
  const Aabb<T> b = bounds(shape);
  const T scale = std::max(b.min().cwiseAbs().maxCoeff(), b.max().cwiseAbs().maxCoeff());
  const T pad = T(16) * std::numeric_limits<T>::epsilon() * scale + std::numeric_limits<T>::min();
  const Expected<Aabb<T>> padded = Aabb<T>::make((b.min().array() - pad).matrix(), (b.max().array() + pad).matrix());
  return padded ? padded.value() : b;
}

/// A contiguous list of Shape<T> other than a span of them (std::vector, std::array, a C array):
/// the helpers below take one with T deduced, e.g. find_contacts(std::vector<Shape<float>>).
template <class R>
concept ShapeList = std::ranges::contiguous_range<R> && VariantShape<std::ranges::range_value_t<R>> &&
    std::is_same_v<std::ranges::range_value_t<R>, Shape<scalar_of_t<std::ranges::range_value_t<R>>>> &&
    !std::is_same_v<std::remove_cvref_t<R>, std::span<const std::ranges::range_value_t<R>>>;

/// The scalar of a ShapeList.
template <class R>
using list_scalar_t = scalar_of_t<std::ranges::range_value_t<R>>;

/// find_overlapping_shapes() on any ShapeList (T deduced).
template <ShapeList R, class BP = DynamicTree<list_scalar_t<R>>>
std::vector<ShapePair> find_overlapping_shapes(const R& shapes, BP bp = BP()) {
  using T = list_scalar_t<R>;
  return find_overlapping_shapes<T, BP>(std::span<const Shape<T>>(std::ranges::data(shapes), std::ranges::size(shapes)),
                                        std::move(bp));
}

/// find_contacts() on any ShapeList (T deduced).
template <ShapeList R, class BP = DynamicTree<list_scalar_t<R>>>
std::vector<ShapeContact<list_scalar_t<R>>> find_contacts(const R& shapes, BP bp = BP()) {
  using T = list_scalar_t<R>;
  return find_contacts<T, BP>(std::span<const Shape<T>>(std::ranges::data(shapes), std::ranges::size(shapes)),
                              std::move(bp));
}

/// The first shape a ray meets: index into the input list and the hit.
template <Scalar T>
struct ShapeHit {
  std::size_t index;  ///< index of the shape in the input list
  RayHit<T> hit;      ///< where the ray meets it
};

/// The nearest hit of origin + t direction, t in [0, max_t], over the shapes (ties: lowest
/// index), or nothing. The broadphase proposes the shapes whose bounding boxes the segment meets;
/// collide::raycast settles each. Total, as raycast(): a NaN or infinite ray, or a negative or NaN
/// max_t, meets no shape.
template <Scalar T, class BP = DynamicTree<T>>
std::optional<ShapeHit<T>> raycast_shapes(std::span<const Shape<T>> shapes, const Ray<T>& ray, T max_t, BP bp = BP()) {
  if (!ray.origin.allFinite() || !ray.direction.allFinite() || !(max_t >= T(0)) || !std::isfinite(max_t)) return {};
  for (std::size_t i = 0; i < shapes.size(); ++i) bp.add(raycast_bounds(shapes[i]), i);
  std::optional<ShapeHit<T>> best;
  bp.raycast(ray, max_t, [&](ProxyId id, Calc) {
    const std::size_t i = bp.user_data(id);
    const auto h = raycast(shapes[i], ray, max_t);
    if (h && (!best || h->t < best->hit.t || (h->t == best->hit.t && i < best->index))) best = ShapeHit<T>{i, *h};
  });
  return best;
}

/// raycast_shapes() on any ShapeList (T deduced).
template <ShapeList R, class BP = DynamicTree<list_scalar_t<R>>>
std::optional<ShapeHit<list_scalar_t<R>>> raycast_shapes(const R& shapes, const Ray<list_scalar_t<R>>& ray,
                                                         list_scalar_t<R> max_t, BP bp = BP()) {
  using T = list_scalar_t<R>;
  return raycast_shapes<T, BP>(std::span<const Shape<T>>(std::ranges::data(shapes), std::ranges::size(shapes)), ray,
                               max_t, std::move(bp));
}

/// A body of a World met by a ray: its handle and the hit.
template <Scalar T>
struct BodyHit {
  ProxyId body;   ///< the body
  RayHit<T> hit;  ///< where the ray meets its shape
};

/// Handle of one contact of a World: it names the same contact from the step that began it to the
/// step that ends it, so a solver can keep its impulses per contact (warm starting). A slot is
/// reused by a later contact with a new generation, as ProxyId's.
struct ContactId {
  std::uint32_t index = std::numeric_limits<std::uint32_t>::max();  ///< the slot, below contact_capacity()
  std::uint32_t generation = 0;  ///< the slot's use: a reused slot has a new generation
  /// Field-wise equality.
  friend constexpr bool operator==(const ContactId&, const ContactId&) = default;
  /// Field-wise order (a total order of handles).
  friend constexpr auto operator<=>(const ContactId&, const ContactId&) = default;
};

/// A contact between two bodies of a World, as of the last step.
template <Scalar T>
struct BodyContact {
  ContactId id;  ///< the contact's handle, the same for as long as the contact lasts
  ProxyId a;     ///< the body with the smaller slot index
  ProxyId b;     ///< the other body
  Contact<T>
      contact;  ///< contact(shape(a), transform(a), shape(b), transform(b), speculative()): normal from a toward b
};

/// A persistent world of bodies. Each body is a shape (any kind, compounds included) kept in its
/// own frame, placed by a Transform, with user data and a filter; a world-space shape is the case
/// of the identity transform. Each frame the game moves bodies by new transforms (move(id, x): no
/// shape is copied, nothing is allocated) and calls step().
///
/// Contacts. A pair of bodies is in contact when contact(a, xa, b, xb, speculative()) exists: the
/// placed shapes overlap (closed sets, touching counts; exact outside the band of
/// overlap_tolerance(a, xa, b, xb), exact for identities), or with a speculative distance d > 0,
/// lie within d of each other. step() computes the contact of every pair of bodies of which one
/// changed, keeps the others, and reports the pairs whose contact began or ended since the last
/// step, each once; filters apply (`accepts`). Every contact is contact() bit for bit (a chain
/// segment's: the chain's contact(), below), with its error contract and feature ids, and keeps
/// its ContactId while it lasts. Work per step is proportional to the bodies changed and their
/// broadphase partners.
///
/// Queries by point, by any shape and by ray run against the placed shapes at any time. They are
/// total, as contains() and raycast() are: a point or a ray with a NaN or an infinite value, or a
/// negative or NaN max_t, meets no body. Stored input is checked: a bad handle is InvalidProxy, a
/// bad speculative distance BadMargin.
///
/// Chains. A chain segment (add(ChainSegment) or add(Chain), one body per segment) is a body in
/// world space whose contacts follow the chain's rules (chain.hpp: one-sided, no ghost normals at
/// its joints); two segments never touch. Its shape is the two-sided segment (a capsule of radius
/// 0), which the queries and the mover meet. It stays where it was added: move(id, x) on it is
/// ChainMoved; set_shape() makes it an ordinary body.
///
/// The broadphase indexes each body by bounds(shape, x), padded by the speculative distance and by
/// the rounding of a ray's hit, so that it proposes every pair and every body the queries can
/// find.
///
/// Thread safety: const members may run on many threads at once, and from each other's
/// callbacks, while no thread calls a non-const member (add, move, set_shape, set_filter, remove,
/// step).
template <Scalar T, class BP = DynamicTree<T>>
class World {
 public:
  /// A world whose bodies are indexed by bp (which must be empty), with speculative distance
  /// `speculative` (see the class). Errors: BadMargin (speculative negative, NaN, infinite or
  /// above max_magnitude<T>()).
  explicit World(BP bp = BP(), T speculative = T(0)) : tracker_(std::move(bp)), speculative_(speculative) {
    if (!(speculative >= T(0)) || speculative > max_magnitude<T>())
      throw BroadphaseError(BroadphaseErrc::BadMargin, "speculative distance is negative, NaN or too large");
  }

  /// Adds a body: shape in its own frame, placed by x. Its contacts begin at the next step.
  /// Returns its handle.
  ProxyId add(const Shape<T>& shape, const Transform<T>& x, std::uint64_t user = 0, Filter filter = {}) {
    const ProxyId id = tracker_.add(body_box(shape, x), user, filter);
    grow(id.index);
    shapes_[id.index] = shape;
    transforms_[id.index] = x;
    segments_[id.index].reset();
    has_segment_[id.index] = 0;
    mark(id);
    return id;
  }
  /// Adds a body whose shape is given in world space (the identity transform).
  ProxyId add(const Shape<T>& shape, std::uint64_t user = 0, Filter filter = {}) {
    return add(shape, Transform<T>(), user, filter);
  }
  /// Adds a chain segment body (see the class), in world space. Returns its handle.
  ProxyId add(const ChainSegment<T>& segment, std::uint64_t user = 0, Filter filter = {}) {
    const ProxyId id = add(Shape<T>(segment.as_capsule()), Transform<T>(), user, filter);
    segments_[id.index] = segment;
    has_segment_[id.index] = 1;
    return id;
  }
  /// Adds every segment of a chain as a body (add(ChainSegment)), all with the same user data and
  /// filter. Returns their handles in segment order.
  std::vector<ProxyId> add(const Chain<T>& chain, std::uint64_t user = 0, Filter filter = {}) {
    std::vector<ProxyId> ids;
    ids.reserve(chain.size());
    for (std::size_t i = 0; i < chain.size(); ++i) ids.push_back(add(chain.segment(i), user, filter));
    return ids;
  }
  /// Places a body by a new transform. Allocates nothing once the world's buffers have grown.
  /// Errors: InvalidProxy, ChainMoved (a chain segment body).
  void move(ProxyId id, const Transform<T>& x) {
    const std::uint32_t i = checked(id);
    if (has_segment_[i]) throw BroadphaseError(BroadphaseErrc::ChainMoved, "a chain segment stays where it was added");
    tracker_.move(id, body_box(*shapes_[i], x));
    transforms_[id.index] = x;
    mark(id);
  }
  /// Gives a body a new shape in world space: the shape is replaced and the transform becomes the
  /// identity. Errors: InvalidProxy.
  void move(ProxyId id, const Shape<T>& shape) { set_shape(id, shape, Transform<T>()); }
  /// Replaces a body's shape (in its own frame) and transform. Errors: InvalidProxy.
  void set_shape(ProxyId id, const Shape<T>& shape, const Transform<T>& x) {
    tracker_.move(id, body_box(shape, x));
    shapes_[id.index] = shape;
    transforms_[id.index] = x;
    segments_[id.index].reset();
    has_segment_[id.index] = 0;
    mark(id);
  }
  /// Replaces a body's filter. Errors: InvalidProxy.
  void set_filter(ProxyId id, Filter filter) {
    tracker_.set_filter(id, filter);
    mark(id);
  }
  /// Removes a body; its contacts end at the next step. Errors: InvalidProxy.
  void remove(ProxyId id) {
    tracker_.remove(id);
    shapes_[id.index].reset();
    segments_[id.index].reset();
    has_segment_[id.index] = 0;
  }
  /// True when id names a live body.
  bool contains(ProxyId id) const noexcept { return tracker_.structure().contains(id); }
  /// Number of live bodies.
  std::size_t size() const noexcept { return tracker_.structure().size(); }
  /// The body's shape, in its own frame. Errors: InvalidProxy.
  const Shape<T>& shape(ProxyId id) const { return *shapes_[checked(id)]; }
  /// The body's chain segment, or nullptr for a body that is not one. Errors: InvalidProxy.
  const ChainSegment<T>* chain_segment(ProxyId id) const {
    const std::optional<ChainSegment<T>>& s = segments_[checked(id)];
    return s ? &*s : nullptr;
  }
  /// The body's transform. Errors: InvalidProxy.
  const Transform<T>& transform(ProxyId id) const { return transforms_[checked(id)]; }
  /// Errors: InvalidProxy.
  std::uint64_t user_data(ProxyId id) const { return tracker_.structure().user_data(id); }
  /// The speculative distance of every contact.
  T speculative() const noexcept { return speculative_; }

  /// Computes the contacts of the bodies changed since the last step and returns the pairs whose
  /// contact began and ended, each once (handles as in PairEvents: a removed body's handle is
  /// already stale). The lists stay valid until the next step.
  const PairEvents& step() {
    tracker_.update(box_events_);
    events_.clear();
    for (const ProxyPair& p : box_events_.ended) end_contact(p);
    std::sort(changed_.begin(), changed_.end());
    for (const std::uint32_t i : changed_) {
      if (!contains(ids_[i])) continue;
      tracker_.for_each_partner(ids_[i], [&](ProxyId o) {
        if (changed_mark_[o.index] && o.index < i) return;  // settled from o's side
        settle(ordered_pair(ids_[i], o));
      });
    }
    for (const std::uint32_t i : changed_) changed_mark_[i] = 0;
    changed_.clear();
    return events_;
  }

  /// Calls f for every contact as of the last step, in the order of their slots: f(const
  /// BodyContact<T>&), or f(ProxyId a, ProxyId b) for the bodies alone.
  template <class F>
  void for_each_contact(F&& f) const {
    for (const Record& r : contacts_) {
      if (!r.live) continue;
      if constexpr (std::is_invocable_v<F&, ProxyId, ProxyId>) {
        f(r.contact.a, r.contact.b);
      } else {
        f(r.contact);
      }
    }
  }
  /// The contact of bodies a and b (either order) as of the last step, or nullptr. The pointer
  /// stays valid until the next step.
  const BodyContact<T>* find_contact(ProxyId a, ProxyId b) const noexcept {
    if (!contains(a) || !contains(b) || a.index == b.index) return nullptr;
    const std::uint32_t* slot = by_pair_.find(detail::pair_key(a.index, b.index));
    return slot ? &contacts_[*slot].contact : nullptr;
  }
  /// Number of contacts as of the last step.
  std::size_t contact_count() const noexcept { return by_pair_.size(); }
  /// One more than the largest ContactId::index in use: a solver's per-contact arrays of this size
  /// hold every contact.
  std::size_t contact_capacity() const noexcept { return contacts_.size(); }

  /// Calls f(ProxyId) for every body whose placed shape contains p (closed; contains(s, x, p)) and
  /// whose filter accepts `filter`. f may return bool; false stops. A NaN or infinite p meets no body.
  template <class F>
  void query_point(const Vec2<T>& p, F&& f, Filter filter = Filter::everything()) const {
    if (!p.allFinite()) return;
    tracker_.structure().query_point(
        p,
        [&](ProxyId id) {
          return !collide::contains(*shapes_[id.index], transforms_[id.index], p) || call_continue(f, id);
        },
        filter);
  }
  /// Calls f(ProxyId) for every body whose placed shape overlaps() `shape` placed by x (world
  /// space when x is omitted) and whose filter accepts `filter`; a circle query is
  /// query_shape(Circle). f may return bool; false stops.
  template <class F>
  void query_shape(const Shape<T>& shape, const Transform<T>& x, F&& f, Filter filter = Filter::everything()) const {
    tracker_.structure().query(
        bounds(shape, x),
        [&](ProxyId id) {
          return !overlaps(shape, x, *shapes_[id.index], transforms_[id.index]) || call_continue(f, id);
        },
        filter);
  }
  /// query_shape() of a world-space shape.
  template <class F>
  void query_shape(const Shape<T>& shape, F&& f, Filter filter = Filter::everything()) const {
    query_shape(shape, Transform<T>(), std::forward<F>(f), filter);
  }
  /// The body whose placed shape the ray meets first (smallest t; ties: lowest slot index) among
  /// those whose filter accepts `filter`, or nothing; raycast(s, x, ray, max_t) of each. A NaN or
  /// infinite ray, or a negative or NaN max_t, meets no body.
  std::optional<BodyHit<T>> raycast(const Ray<T>& ray, T max_t, Filter filter = Filter::everything()) const {
    if (!ray.origin.allFinite() || !ray.direction.allFinite() || !(max_t >= T(0)) || !std::isfinite(max_t)) return {};
    std::optional<BodyHit<T>> best;
    tracker_.structure().raycast(
        ray, max_t,
        [&](ProxyId id, Calc) {
          const auto h = collide::raycast(*shapes_[id.index], transforms_[id.index], ray, max_t);
          if (h && (!best || h->t < best->hit.t || (h->t == best->hit.t && id.index < best->body.index)))
            best = BodyHit<T>{id, *h};
        },
        filter);
    return best;
  }
  /// The broadphase, for box queries. Its boxes are the bodies' padded boxes (see the class).
  const BP& broadphase() const noexcept { return tracker_.structure(); }

 private:
  /// A contact slot: live while its pair is in contact; its generation counts its uses.
  struct Record {
    BodyContact<T> contact;
    bool live = false;
  };

  /// The box the broadphase keeps for a body: bounds(shape, x) padded by the speculative distance
  /// (a pair within it must be proposed) and by raycast_bounds()'s 16 eps_T of its scale (a hit
  /// reported within raycast's rounding outside the shape must find the box), rounded outward and
  /// kept within the range every box may have (the shape lies inside it anyway). One rounding
  /// per corner suffices: the pad is far above the rounding of a corner minus the pad in Calc.
  Aabb<T> body_box(const Shape<T>& shape, const Transform<T>& x) const {
    const Aabb<T> b = bounds(shape, x);
    const Vec2c lo = widen(b.min()), hi = widen(b.max());
    const Calc scale = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
    const Calc rounding =
        Calc(16) * Calc(std::numeric_limits<T>::epsilon()) * scale + Calc(std::numeric_limits<T>::min());
    const Calc pad = rounding + Calc(speculative_);
    const T top = max_magnitude<T>();
    const auto down = [&](Calc v) { return std::max(collide::detail::round_down_to<T>(v - pad), -top); };
    const auto up = [&](Calc v) { return std::min(-collide::detail::round_down_to<T>(-(v + pad)), top); };
    return collide::detail::AabbAccess::unchecked<T>(Vec2<T>(down(lo.x()), down(lo.y())),
                                                     Vec2<T>(up(hi.x()), up(hi.y())));
  }

  /// id's slot, after checking the handle (InvalidProxy).
  std::uint32_t checked(ProxyId id) const {
    if (!contains(id)) throw BroadphaseError(BroadphaseErrc::InvalidProxy, "body handle is stale or was never issued");
    return id.index;
  }

  /// Computes the contact of pair p (both bodies live) and records what began, ended or changed.
  void settle(const ProxyPair& p) {
    const std::uint32_t a = p.a.index, b = p.b.index;
    const std::optional<Contact<T>> c = body_contact(a, b);
    const std::uint64_t k = detail::pair_key(a, b);
    if (std::uint32_t* slot = by_pair_.find(k)) {
      if (c) {
        contacts_[*slot].contact.contact = *c;
      } else {
        end_contact(p);
      }
      return;
    }
    if (!c) return;
    std::uint32_t slot;
    if (!free_.empty()) {
      slot = free_.back();
      free_.pop_back();
    } else {
      slot = std::uint32_t(contacts_.size());
      contacts_.emplace_back();
    }
    Record& r = contacts_[slot];
    r.live = true;
    r.contact.id = ContactId{slot, r.contact.id.generation};
    r.contact.a = p.a;
    r.contact.b = p.b;
    r.contact.contact = *c;
    by_pair_.insert(k, slot);
    events_.began.push_back(p);
  }

  /// The contact of the bodies in slots a and b, normal from a toward b: by the chain's rules when
  /// one is a chain segment, none between two segments.
  std::optional<Contact<T>> body_contact(std::uint32_t a, std::uint32_t b) const {
    if (!(has_segment_[a] | has_segment_[b])) [[likely]]
      return contact(*shapes_[a], transforms_[a], *shapes_[b], transforms_[b], speculative_);
    if (has_segment_[a] && has_segment_[b]) return std::nullopt;
    if (has_segment_[a]) return detail::chain_contact_as(*segments_[a], *shapes_[b], transforms_[b], speculative_);
    return detail::chain_contact_as(*segments_[b], *shapes_[a], transforms_[a], speculative_, true);
  }

  /// Ends pair p's contact, if it has one: its slot is freed for a later contact.
  void end_contact(const ProxyPair& p) {
    std::uint32_t slot = 0;
    if (!by_pair_.erase(detail::pair_key(p.a.index, p.b.index), &slot)) return;
    Record& r = contacts_[slot];
    r.live = false;
    ++r.contact.id.generation;
    free_.push_back(slot);
    events_.ended.push_back(p);
  }

  void grow(std::uint32_t i) {
    if (i >= shapes_.size()) {
      shapes_.resize(std::size_t(i) + 1);
      transforms_.resize(std::size_t(i) + 1);
      segments_.resize(std::size_t(i) + 1);
      has_segment_.resize(std::size_t(i) + 1, 0);
      ids_.resize(std::size_t(i) + 1);
      changed_mark_.resize(std::size_t(i) + 1, 0);
    }
  }
  void mark(ProxyId id) {
    const std::uint32_t i = id.index;
    ids_[i] = id;
    if (!changed_mark_[i]) {
      changed_mark_[i] = 1;
      changed_.push_back(i);
    }
  }

  PairTracker<BP, T> tracker_;
  T speculative_;
  std::vector<std::optional<Shape<T>>> shapes_;           ///< per slot: the body's shape in its frame
  std::vector<Transform<T>> transforms_;                  ///< per slot: the body's transform
  std::vector<std::optional<ChainSegment<T>>> segments_;  ///< per slot: the chain segment it is, if any
  std::vector<char> has_segment_;       ///< per slot: segments_[i] holds one (read for every pair: one byte)
  std::vector<ProxyId> ids_;            ///< per slot: the current handle
  std::vector<std::uint32_t> changed_;  ///< slots added, moved or re-filtered since the last step
  std::vector<char> changed_mark_;
  std::vector<Record> contacts_;     ///< contact slots
  std::vector<std::uint32_t> free_;  ///< contact slots not in use
  detail::PairMap by_pair_;          ///< pair of body slots -> contact slot
  PairEvents box_events_, events_;
};

}  // namespace collide::broadphase
