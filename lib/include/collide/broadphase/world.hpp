#pragma once
/// @file broadphase/world.hpp
/// The course notes' hierarchy end to end: a broadphase on the shapes' conservative bounding boxes
/// proposes pairs, the exact pair decisions (overlaps, contact) settle them. World keeps bodies
/// between steps and reports contacts that began and ended; the find_* helpers below answer once
/// for a list of shapes (they build a broadphase on every call).

#include "collide/broadphase/events.hpp"
#include "collide/broadphase/tree.hpp"
#include "collide/contains.hpp"
#include "collide/contact.hpp"
#include "collide/overlaps.hpp"
#include "collide/raycast.hpp"
#include "collide/registry.hpp"

#include <algorithm>
#include <optional>
#include <ranges>
#include <span>
#include <type_traits>
#include <cstddef>
#include <limits>
#include <span>
#include <unordered_set>
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
/// collide::raycast settles each. Errors: BadRay (NaN/inf ray, negative max_t).
template <Scalar T, class BP = DynamicTree<T>>
std::optional<ShapeHit<T>> raycast_shapes(std::span<const Shape<T>> shapes, const Ray<T>& ray, T max_t, BP bp = BP()) {
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

/// A persistent world of bodies: each a world-space shape with user data and a filter, kept in a
/// broadphase BP (DynamicTree<T> by default) on its padded bounding box. Add, move and remove
/// bodies, then step(): it reports the pairs of bodies whose shapes began or stopped overlapping
/// (exact overlaps(), touching counts; filters applied) since the last step, each once. Work per
/// step is proportional to the bodies changed and their broadphase partners. Queries by point,
/// by any shape and by ray run against the current shapes at any time.
///
/// Thread safety: const members may run on many threads at once, and from each other's
/// callbacks, while no thread calls a non-const member (add, move, remove, set_filter, step).
template <Scalar T, class BP = DynamicTree<T>>
class World {
 public:
  /// A world whose bodies are indexed by bp (which must be empty).
  explicit World(BP bp = BP()) : tracker_(std::move(bp)) {}

  /// Adds a body; its contacts begin at the next step. Returns its handle.
  ProxyId add(const Shape<T>& shape, std::uint64_t user = 0, Filter filter = {}) {
    const ProxyId id = tracker_.add(raycast_bounds(shape), user, filter);
    if (id.index >= shapes_.size()) shapes_.resize(std::size_t(id.index) + 1);
    shapes_[id.index] = shape;
    mark(id);
    return id;
  }
  /// Replaces a body's shape (its new world-space shape). Errors: InvalidProxy.
  void move(ProxyId id, const Shape<T>& shape) {
    tracker_.move(id, raycast_bounds(shape));
    shapes_[id.index] = shape;
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
  }
  /// True when id names a live body.
  bool contains(ProxyId id) const noexcept { return tracker_.structure().contains(id); }
  /// Number of live bodies.
  std::size_t size() const noexcept { return tracker_.structure().size(); }
  /// The body's shape. Errors: InvalidProxy.
  const Shape<T>& shape(ProxyId id) const {
    tracker_.structure().box(id);  // checks the handle
    return *shapes_[id.index];
  }
  /// Errors: InvalidProxy.
  std::uint64_t user_data(ProxyId id) const { return tracker_.structure().user_data(id); }

  /// Contacts that began and ended since the last step, each once (handles as in PairEvents).
  /// The returned lists stay valid until the next step.
  const PairEvents& step() {
    tracker_.update(box_events_);
    events_.clear();
    for (const ProxyPair& p : box_events_.ended)
      if (touching_.erase(key(p.a.index, p.b.index)) != 0) events_.ended.push_back(p);
    std::sort(changed_.begin(), changed_.end());
    for (const std::uint32_t i : changed_) {
      if (!contains(ids_[i])) continue;
      tracker_.for_each_partner(ids_[i], [&](ProxyId o) {
        if (changed_mark_[o.index] && o.index < i) return;  // settled from o's side
        const bool now = overlaps(*shapes_[i], *shapes_[o.index]);
        const std::uint64_t k = key(i, o.index);
        if (now && touching_.insert(k).second) events_.began.push_back(ordered_pair(ids_[i], o));
        if (!now && touching_.erase(k) != 0) events_.ended.push_back(ordered_pair(ids_[i], o));
      });
    }
    for (const std::uint32_t i : changed_) changed_mark_[i] = 0;
    changed_.clear();
    return events_;
  }

  /// Calls f(ProxyId a, ProxyId b) for every pair of bodies in contact as of the last step.
  template <class F>
  void for_each_contact(F&& f) const {
    for (const std::uint64_t k : touching_) {
      const auto a = std::uint32_t(k >> 32), b = std::uint32_t(k);
      f(ids_[a], ids_[b]);
    }
  }

  /// Calls f(ProxyId) for every body whose shape contains p (closed) and whose filter accepts
  /// `filter`. f may return bool; false stops. Errors: BadBox (p NaN or infinite).
  template <class F>
  void query_point(const Vec2<T>& p, F&& f, Filter filter = Filter::everything()) const {
    const auto& bp = tracker_.structure();
    bp.query_point(
        p, [&](ProxyId id) { return !collide::contains(*shapes_[id.index], p) || call_continue(f, id); }, filter);
  }
  /// Calls f(ProxyId) for every body whose shape overlaps() `shape` (any kind, world space) and
  /// whose filter accepts `filter`; a circle query is query_shape(Circle). f may return bool.
  template <class F>
  void query_shape(const Shape<T>& shape, F&& f, Filter filter = Filter::everything()) const {
    const auto& bp = tracker_.structure();
    bp.query(
        bounds(shape), [&](ProxyId id) { return !overlaps(shape, *shapes_[id.index]) || call_continue(f, id); },
        filter);
  }
  /// The body whose shape the ray meets first (smallest t; ties: lowest slot index) among those
  /// whose filter accepts `filter`, or nothing. Errors: BadRay.
  std::optional<BodyHit<T>> raycast(const Ray<T>& ray, T max_t, Filter filter = Filter::everything()) const {
    std::optional<BodyHit<T>> best;
    tracker_.structure().raycast(
        ray, max_t,
        [&](ProxyId id, Calc) {
          const auto h = collide::raycast(*shapes_[id.index], ray, max_t);
          if (h && (!best || h->t < best->hit.t || (h->t == best->hit.t && id.index < best->body.index)))
            best = BodyHit<T>{id, *h};
        },
        filter);
    return best;
  }
  /// The broadphase, for box queries.
  const BP& broadphase() const noexcept { return tracker_.structure(); }

 private:
  static std::uint64_t key(std::uint32_t a, std::uint32_t b) noexcept {
    if (a > b) std::swap(a, b);
    return (std::uint64_t(a) << 32) | b;
  }
  void mark(ProxyId id) {
    const std::uint32_t i = id.index;
    if (i >= ids_.size()) {
      ids_.resize(std::size_t(i) + 1);
      changed_mark_.resize(std::size_t(i) + 1, 0);
    }
    ids_[i] = id;
    if (!changed_mark_[i]) {
      changed_mark_[i] = 1;
      changed_.push_back(i);
    }
  }

  PairTracker<BP, T> tracker_;
  std::vector<std::optional<Shape<T>>> shapes_;
  std::vector<ProxyId> ids_;
  std::vector<std::uint32_t> changed_;
  std::vector<char> changed_mark_;
  std::unordered_set<std::uint64_t> touching_;
  PairEvents box_events_, events_;
};

}  // namespace collide::broadphase
