#pragma once
/// @file queries.hpp
/// Pair queries: overlaps, contact, resolve, distance, and their error contract.
///
/// Every function accepts any shape type: the six concrete shapes, Primitive<T> or Shape<T>, in
/// either order, with one scalar. Concrete types dispatch at compile time; variants dispatch by
/// std::visit (no virtual call). Reversed argument orders call the same decision, so
/// overlaps(a, b) == overlaps(b, a) holds to the bit.
///
/// Error contract (the one definition; README and the oracle properties refer to it):
/// - S(a, b) = the largest absolute coordinate of bounds(a) and bounds(b).
/// - overlaps(a, b) is exact for every pair and both scalars: it equals the exact answer for the
///   stored values, touching included (decide.hpp); overlap_tolerance(a, b) = 0 (except for
///   compounds with child transforms, below).
/// - rounding_tolerance(a, b) = 64 * 2^-53 * S + 2^-500 is the error unit of the rounded outputs
///   (contact depth, normal and points, distance, resolution margin).
/// - contact(a, b) exists exactly when overlaps(a, b) is true.
/// - Tiny shapes (every value below 2^-400) have their rounded outputs computed on exactly
///   rescaled cores, so those are relative-accurate; the 2^-500 floor is a bound.
/// - contains() is exact for every kind (contains.hpp); raycast() states its bound in raycast.hpp.
/// - Shapes placed by transforms (transformed.hpp, every query with a Transform per shape): the
///   exact shape is the exact image of the stored values; the identity computes nothing and
///   gives these answers. Otherwise the image is rounded in double within transform_tolerance(s,
///   x) = 16 * 2^-53 * (|position|_inf + 2 L) + 2^-1070 (L the local magnitude; 0 for the
///   identity), exact for exact translations and quarter turns: overlaps() is exact outside a
///   band of the two transform_tolerance()s, and rounded outputs add them to their bound. A
///   compound whose children carry transforms is placed the same way in world space
///   (placement_tolerance(), included in overlap_tolerance() and rounding_tolerance()).

#include "collide/compound.hpp"
#include "collide/decide.hpp"
#include "collide/feature.hpp"
#include "collide/detail/contact_cores.hpp"
#include "collide/detail/contact_pairs.hpp"
#include "collide/detail/core.hpp"
#include "collide/registry.hpp"
#include "collide/shape_traits.hpp"
#include "collide/shapes.hpp"
#include "collide/translate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <variant>
#include <vector>

namespace collide {

namespace detail {

/// The pair decision for two primitives in either order. A stored float shape met by a double
/// image (a transformed query) is widened first, exactly.
template <PrimitiveShape A, PrimitiveShape B>
bool decide_primitives(const A& a, const B& b) {
  if constexpr (!std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>) {
    if constexpr (std::is_same_v<scalar_of_t<A>, float>) {
      return decide_primitives(widened_shape(a), b);
    } else {
      return decide_primitives(a, widened_shape(b));
    }
  } else if constexpr (static_cast<int>(kind_of_v<A>) <= static_cast<int>(kind_of_v<B>)) {
    return decide::pair(a, b);
  } else {
    return decide::pair(b, a);
  }
}

/// A shape's conservative box with double values (exact for a float box).
template <class S>
Aabb<Calc> calc_bounds(const S& s) {
  const auto b = bounds(s);
  return ShapeAccess::aabb<Calc>(widen(b.min()), widen(b.max()));
}

/// The overlap decision for concrete shapes, stored or placed (images, placed compounds).
template <class A, class B>
bool overlaps_concrete(const A& a, const B& b) {
  if constexpr (is_compound_v<A> || is_compound_v<B>) {
    // A hierarchy: the cheap bounding boxes first, then the children.
    if (!decide::aabb_aabb(calc_bounds(a), calc_bounds(b))) return false;
    bool hit = false;
    for_each_primitive(a, [&](const auto& ca) {
      if (hit) return;
      for_each_primitive(b, [&](const auto& cb) { hit = hit || decide_primitives(ca, cb); });
    });
    return hit;
  } else {
    return decide_primitives(a, b);
  }
}

}  // namespace detail

/// True when the closed shapes share at least one point (touching counts).
/// Error: exact for every pair (see the contract at the top of this file).
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>
bool overlaps(const A& a, const B& b) {
  return detail::visit_shapes(a, b, [](const auto& ca, const auto& cb) { return detail::overlaps_concrete(ca, cb); });
}

/// The error bound of the placement of s in the world (see the contract at the top of this file):
/// 0 for a stored shape and for a compound whose children are all placed by the identity;
/// transform_tolerance(c, identity) for a compound with child transforms.
template <AnyShape S>
Calc placement_tolerance(const S& s) noexcept {
  return detail::visit_shape(s, [](const auto& x) -> Calc {
    if constexpr (detail::is_compound_v<decltype(x)>) {
      return x.has_child_transforms() ? detail::image_tolerance(detail::Pose{}, x.local_extent()) : 0;
    } else {
      return 0;
    }
  });
}

/// The error unit of this pair's rounded outputs (contact depth, normal and points, distance,
/// resolution margin): 64 * 2^-53 * S + 2^-500, where S is the largest absolute coordinate of
/// either bounding box, plus the placement tolerance of compounds with child transforms. Each
/// query states its bound as a multiple of it.
template <AnyShape A, AnyShape B>
Calc rounding_tolerance(const A& a, const B& b) {
  const Calc s = std::max(detail::scale_of(bounds(a)), detail::scale_of(bounds(b)));
  return kOverlapErrorFactor * kUnitRoundoff * s + kAbsoluteFloor + placement_tolerance(a) + placement_tolerance(b);
}

/// The error bound of overlaps() for this pair: the width of the band of exact signed distance
/// around touching inside which an answer may differ from the exact one. 0 for stored shapes,
/// every pair being decided exactly; the placement tolerance of a compound with child transforms.
template <AnyShape A, AnyShape B>
Calc overlap_tolerance(const A& a, const B& b) noexcept {
  return placement_tolerance(a) + placement_tolerance(b);
}

// ---------------------------------------------------------------------------------------------
// Contact.

/// Where two shapes touch: a contact manifold of one or two points, for a physics solver.
///
/// Units are the shapes' own; the normal points from a toward b. A point's separation is the
/// signed distance between the two surfaces along the normal at that point: negative when they
/// penetrate (then -separation is that point's penetration), positive for a speculative point of
/// shapes still apart. The point itself lies midway between the surfaces, so a's surface point is
/// point - normal * separation / 2 and b's is point + normal * separation / 2.
template <Scalar T>
struct Contact {
  Vec2<T> normal;                 ///< unit vector pointing from a toward b (a moves along -normal to separate)
  T depth;                        ///< penetration depth along normal, >= 0 (0 when only touching or apart)
  int count;                      ///< number of valid entries in points, ids and separations: 1 or 2
  std::array<Vec2<T>, 2> points;  ///< contact points, midway between the two surfaces
  std::array<FeatureId, 2> ids;   ///< per point, the features of a and b that produced it (feature.hpp)
  std::array<T, 2> separations;   ///< per point, signed surface distance along normal (< 0 penetrating)
};

namespace detail {

/// A CoreContact rounded to T, as the value that initialises a Contact<T>: emplace() builds the
/// contact from it in place, field by field, without zeroing it first (every field is written) or
/// copying it (a copy of a contact written piecewise would be read back in wider pieces than it
/// was stored).
template <Scalar T>
struct RoundedContact {
  const CoreContact& c;
  operator Contact<T>() const {
    return {c.normal.template cast<T>(),
            static_cast<T>(c.depth),
            c.count,
            {c.points[0].template cast<T>(), c.points[1].template cast<T>()},
            c.ids,
            {static_cast<T>(c.separations[0]), static_cast<T>(c.separations[1])}};
  }
};

/// Makes out hold c rounded to T (RoundedContact).
template <Scalar T>
void round_into(const CoreContact& c, std::optional<Contact<T>>& out) {
  out.emplace(RoundedContact<T>{c});
}

/// The contact of two primitives in either order (contact_pair() takes registry order; the other
/// order is the same contact seen from b: normal reversed, ids swapped). A stored float shape met
/// by a double image (a transformed query) is widened first, exactly. rounding: as contact_pair().
template <PrimitiveShape A, PrimitiveShape B>
std::optional<CoreContact> contact_primitives(const A& a, const B& b, Calc speculative, Rounding rounding = {}) {
  if constexpr (!std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>) {
    if constexpr (std::is_same_v<scalar_of_t<A>, float>) {
      return contact_primitives(widened_shape(a), b, speculative, rounding);
    } else {
      return contact_primitives(a, widened_shape(b), speculative, rounding);
    }
  } else if constexpr (static_cast<int>(kind_of_v<A>) <= static_cast<int>(kind_of_v<B>)) {
    return contact_pair(a, b, speculative, rounding);
  } else {
    std::optional<CoreContact> c = contact_pair(b, a, speculative, rounding);
    if (c) *c = reversed(*c);
    return c;
  }
}

/// The index of a contact's deepest point: the least separation, the first of equals.
inline std::size_t deepest_point(const CoreContact& c) noexcept {
  return c.count > 1 && c.separations[1] < c.separations[0] ? 1 : 0;
}
/// The largest coordinate of a contact's deepest point. A speculative distance only adds points
/// farther apart, so this scale is the same with and without it.
inline Calc deepest_point_scale(const CoreContact& c) noexcept {
  return c.points[deepest_point(c)].cwiseAbs().maxCoeff();
}

/// Overlapping contacts before speculative ones, then the deeper (or the nearer) by more than a
/// tie (kFaceOrderTie units of roundoff of the deepest points' scale): child pairs equally deep up
/// to rounding keep their order, so that the ids stay put while such a pair slides.
inline bool deeper_contact(const CoreContact& c, const CoreContact& than) noexcept {
  if (c.overlapping != than.overlapping) return c.overlapping;
  const Calc tie = tie_of(std::max(deepest_point_scale(c), deepest_point_scale(than)));
  return c.overlapping ? c.depth > than.depth + tie
                       : c.separations[deepest_point(c)] < than.separations[deepest_point(than)] - tie;
}

/// The contact of concrete shapes, stored or placed (images, placed compounds). rounding: as
/// contact_pair() takes it (empty for stored primitives).
template <class A, class B>
std::optional<CoreContact> contact_concrete(const A& a, const B& b, Calc speculative = 0, Rounding rounding = {}) {
  if constexpr (is_compound_v<A> || is_compound_v<B>) {
    // The cached bounding boxes first (without a speculative distance), then every child pair.
    if (!(speculative > 0) && !decide::aabb_aabb(calc_bounds(a), calc_bounds(b))) return std::nullopt;
    std::optional<CoreContact> best;
    std::uint16_t ia = 0;
    for_each_primitive(a, [&](const auto& ca) {
      std::uint16_t ib = 0;
      for_each_primitive(b, [&](const auto& cb) {
        std::optional<CoreContact> c = contact_primitives(ca, cb, speculative, rounding);
        if (c && (!best || deeper_contact(*c, *best))) {
          for (FeatureId& id : c->ids) {
            id.child_a = ia;
            id.child_b = ib;
          }
          best = c;
        }
        ++ib;
      });
      ++ia;
    });
    if (best) {
      name_child_features(a, *best, false);
      name_child_features(b, *best, true);
    }
    return best;
  } else {
    return contact_primitives(a, b, speculative, rounding);
  }
}

/// A speculative distance as contact() takes it: negative or NaN counts as 0.
template <Scalar T>
Calc speculative_distance(T speculative) noexcept {
  return speculative > 0 ? Calc(speculative) : Calc(0);
}

/// contact() with its result in T, for shapes stored or placed; speculative as contact() takes it.
template <Scalar T, class A, class B>
std::optional<Contact<T>> contact_as(const A& a, const B& b, T speculative = T(0)) {
  const Calc spec = speculative_distance(speculative);
  const std::optional<CoreContact> c = visit_shapes(a, b, [&](const auto& ca, const auto& cb) {
    // A compound's children placed by child transforms are images; primitives are stored exactly.
    const auto placements = [&] { return placement_tolerance(ca) + placement_tolerance(cb); };
    constexpr bool compound = is_compound_v<std::decay_t<decltype(ca)>> || is_compound_v<std::decay_t<decltype(cb)>>;
    return contact_concrete(ca, cb, spec, compound ? Rounding(placements) : Rounding());
  });
  std::optional<Contact<T>> out;
  if (c) round_into(*c, out);
  return out;
}

}  // namespace detail

/// Contact with a speculative distance (in the shapes' units), as a solver uses to stop shapes
/// before they meet: present when overlaps(a, b), and also when the shapes are apart by at most
/// `speculative` (decided on the rounded gap: a pair within a few rounding_tolerance(a, b) of
/// that distance may go either way). A speculative contact of shapes apart has depth 0 and, when
/// the closest points lie inside a face, the other shape's facing side clipped to it (a point per
/// end apart by at most `speculative`), else one point between the closest points; its least
/// separation is the gap (>= 0); an overlapping pair keeps the points of contact(a, b) and adds
/// clipped points apart by at most `speculative`.
/// overlaps() stays the exact answer. A negative or NaN `speculative` counts as 0 (contact(a, b));
/// an infinite one reports every pair. For compounds, an overlapping child pair wins over the
/// nearest pair apart.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> std::optional<Contact<scalar_of_t<A>>> contact(
    const A& a, const B& b, scalar_of_t<A> speculative) {
  return detail::contact_as<scalar_of_t<A>>(a, b, speculative);
}

/// Contact of two shapes: present exactly when overlaps(a, b). For a compound, the deepest contact
/// among its overlapping child pairs (the ids name the children; pairs equally deep up to rounding
/// keep their order). Coincident circle centres give normal (1, 0).
/// Error: normal, depth, points and separations are rounded results, each within a few
/// rounding_tolerance(a, b) of the exact values (depth of the exact depth; each separation of the
/// exact signed distance of the surfaces along the normal at its point).
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> std::optional<Contact<scalar_of_t<A>>> contact(const A& a,
                                                                                                       const B& b) {
  return contact(a, b, scalar_of_t<A>(0));
}

// ---------------------------------------------------------------------------------------------
// Resolution.

namespace detail {

/// h(n) = max over the dilated core of x . n, for unit n.
inline Calc dilated_support(const Core& c, const Vec2c& n) {
  return support(c, n) + c.radius;
}

/// v rounded to T with each component's magnitude rounded down, so |result| <= |v|: the push
/// never exceeds depth + margin because of the final rounding.
template <Scalar T>
Vec2<T> round_toward_zero(const Vec2c& v) noexcept {
  Vec2<T> out;
  for (int i = 0; i < 2; ++i) {
    T f = static_cast<T>(v[i]);
    if (std::fabs(static_cast<Calc>(f)) > std::fabs(v[i])) f = std::nextafter(f, T(0));
    out[i] = f;
  }
  return out;
}

/// Push along -n that separates every pair of children that would meet while a slides along -n:
///   t(n) = max over child pairs whose shadows across n overlap (within tol) of  h_a(n) + h_b(-n)
/// (the support gap; for one convex pair along its least-penetration axis it equals the depth).
/// tol covers the rounding of the supports, of n and of a + v to T: shadows that miss by less
/// may still meet. (Without it, a needle lying on a capsule child's own line, 1e-9 from a circle
/// child, was pushed out of the circle and onto the capsule.)
template <class A, class B>
Calc push_along(const A& a, const B& b, const Vec2c& n, Calc tol) {
  const Vec2c side = perp(n);
  Calc t = 0;
  for_each_primitive(a, [&](const auto& ca) {
    const Core pa = core_of(ca);
    for_each_primitive(b, [&](const auto& cb) {
      const Core pb = core_of(cb);
      const bool shadows_meet = dilated_support(pa, side) + tol >= -dilated_support(pb, -side) &&
                                dilated_support(pb, side) + tol >= -dilated_support(pa, -side);
      if (shadows_meet) t = std::max(t, dilated_support(pa, n) + dilated_support(pb, -n));
    });
  });
  return t;
}

/// Whether a, moved by v and rounded to T as translated() would, still overlaps b; nullopt when
/// the move has no representation in T (translated() would return an error). A compound is
/// judged child by child, so that no moved copy of it is built (which would allocate).
template <ConcreteShape A, class B>
std::optional<bool> moved_overlaps(const A& a, const Vec2<scalar_of_t<A>>& v, const B& b) {
  if constexpr (is_compound_v<A>) {
    const auto& kids = a.children();
    bool representable = true;
    for (std::size_t i = 0; i < kids.size(); ++i) {
      if (a.child_transform(i).is_identity()) {
        std::visit([&](const auto& c) { representable = representable && bool(translated(c, v)); }, kids[i]);
      } else {
        representable = representable && bool(a.child_transform(i).moved(v));
      }
    }
    if (!representable) return std::nullopt;
    bool any = false;
    for (std::size_t i = 0; i < kids.size() && !any; ++i) {
      if (a.child_transform(i).is_identity()) {
        std::visit([&](const auto& c) { any = overlaps_concrete(translated(c, v).value(), b); }, kids[i]);
      } else {
        const Pose x = a.child_transform(i).moved(v)->pose();
        std::visit(
            [&](const auto& c) { any = with_image(c, x, [&](const auto& img) { return overlaps_concrete(img, b); }); },
            kids[i]);
      }
    }
    return any;
  } else {
    const auto moved = translated(a, v);
    if (!moved) return std::nullopt;
    return overlaps_concrete(moved.value(), b);
  }
}

/// The margin formula with its magnitudes given: s_pair the computation's scale (the largest
/// coordinate the depth was computed from), s_moved the largest coordinate of the moved shape's
/// stored values (what is rounded to T when it moves).
template <Scalar T>
Calc margin_of(Calc s_pair, Calc s_moved, Calc depth) noexcept {
  return 4 * kOverlapErrorFactor * kUnitRoundoff * s_pair +
         8 * Calc(std::numeric_limits<T>::epsilon()) * (s_moved + depth) + 16 * kSmallestDouble +
         2 * Calc(std::numeric_limits<T>::denorm_min());
}

/// The largest stored magnitude that moving s rounds to T: its box's coordinates and, for a
/// compound, the position of each child placed by a transform (a move shifts that position).
template <AnyShape S>
Calc moved_scale(const S& s) {
  return visit_shape(s, [](const auto& c) {
    Calc m = scale_of(bounds(c));
    if constexpr (is_compound_v<decltype(c)>) {
      for (std::size_t i = 0; c.has_child_transforms() && i < c.children().size(); ++i) {
        m = std::max(m, widen(c.child_transform(i).position()).cwiseAbs().maxCoeff());
      }
    }
    return m;
  });
}

}  // namespace detail

/// The margin resolve() adds beyond the computed depth, from the magnitudes that round:
/// 4 * 64 * 2^-53 * S (four times the relative part of rounding_tolerance: the depth is computed
/// in double from both shapes' coordinates, S as in rounding_tolerance), plus 8 eps_T (S_a +
/// depth), where S_a is the largest absolute coordinate of bounds(a) alone, or of a compound
/// child's position when larger (detail::moved_scale()): it covers rounding a's moved coordinates
/// (each within S_a + depth) to T, and does not grow with b's extent. Plus 16
/// subnormal units of double and two of T for rounding near zero (a push along a diagonal moves
/// each coordinate by a whole unit: sqrt(2) units in all), plus 2 placement_tolerance of each
/// shape (a compound with child transforms is imaged once for the depth and once for the test).
/// No 2^-500 floor: tiny shapes are decided after exact rescaling, so their depths are
/// relative-accurate, and a push of 2^-500 would collapse a subnormal polygon.
template <AnyShape A, AnyShape B>
Calc resolve_margin(const A& a, const B& b, Calc depth) {
  using T = scalar_of_t<A>;
  const Calc sa = detail::moved_scale(a);
  const Calc s = std::max(detail::scale_of(bounds(a)), detail::scale_of(bounds(b)));
  return detail::margin_of<T>(s, sa, depth) + 2 * (placement_tolerance(a) + placement_tolerance(b));
}

namespace detail {

/// resolve() on concrete shapes, stored or placed: the push in T. s_moved is the largest stored
/// magnitude of a that a move rounds; extra is added to the margin (the placements' bound);
/// still_overlaps(v) tests a moved by v (nullopt when the move has no representation in T).
template <Scalar T, class A, class B, class Moved>
Vec2<T> resolve_as(const A& ca, const B& cb, Calc s_moved, Calc extra, Moved&& still_overlaps) {
  if (!overlaps_concrete(ca, cb)) return Vec2<T>::Zero();
  const Calc s_pair = std::max(scale_of(bounds(ca)), scale_of(bounds(cb)));
  constexpr bool compound = is_compound_v<A> || is_compound_v<B>;
  // A push is at most about the shapes' extent, 2 S.
  const Calc shadow_tol = margin_of<T>(s_pair, s_pair, 2 * s_pair) + extra;
  Vec2c best_n(1, 0);
  Calc best_t = std::numeric_limits<Calc>::infinity();
  for_each_primitive(ca, [&](const auto& pa) {
    for_each_primitive(cb, [&](const auto& pb) {
      if (!decide_primitives(pa, pb)) return;
      const CoreContact c = contact_cores(core_of(pa), core_of(pb));
      const Calc t = compound ? push_along(ca, cb, c.normal, shadow_tol) : c.depth;
      if (t < best_t) {
        best_t = t;
        best_n = c.normal;
      }
    });
  });
  Calc margin = margin_of<T>(s_pair, s_moved, best_t) + extra;
  Vec2<T> v = round_toward_zero<T>(-best_n * (best_t + margin));
  // The moved shape is tested: for subnormal shapes of very different sizes the rounded depth
  // can fall short by more than the margin.
  for (int attempt = 0; attempt < 8; ++attempt) {
    const std::optional<bool> still = still_overlaps(v);
    if (!still || !*still) break;
    margin *= 2;
    v = round_toward_zero<T>(-best_n * (best_t + margin));
  }
  return v;
}

}  // namespace detail

/// Minimum translation of a that separates it from b (the shortest push,
/// as the course notes resolve penetration, generalised to every pair): zero if they do not overlap; otherwise -normal
/// * (depth + margin), so a moved by it no longer overlaps b, strictly (margin: resolve_margin(); when a polygon or a
/// compound is involved, doubled up to 8 times if the moved shape still tests as overlapping after rounding to T — the
/// other pairs need no test, the margin covering their rounding).
///
/// Minimal for the 15 pairs of primitives (depth is the least penetration over the Minkowski
/// difference's faces). For compounds the push is the smallest among the child contacts'
/// directions, each long enough to clear every child it would meet on the way.
///
/// Caveat: a + v may have no representation in T: beyond max_magnitude(), or a polygon (or
/// compound child) thin next to |v| whose vertices round onto one line. translated(a, v) then
/// returns that named error (OutOfRange, Collinear, TooFewVertices); v still separates the exact,
/// unrounded a + v.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Vec2<scalar_of_t<A>> resolve(const A& a, const B& b) {
  using T = scalar_of_t<A>;
  return detail::visit_shapes(a, b, [&](const auto& ca, const auto& cb) -> Vec2<T> {
    const Calc extra = 2 * (placement_tolerance(ca) + placement_tolerance(cb));
    return detail::resolve_as<T>(ca, cb, detail::moved_scale(ca), extra,
                                 [&](const Vec2<T>& v) { return detail::moved_overlaps(ca, v, cb); });
  });
}

// ---------------------------------------------------------------------------------------------
// Distance.

namespace detail {

/// distance() in T, for concrete shapes stored or placed.
template <Scalar T, class A, class B>
T distance_as(const A& ca, const B& cb) {
  if (overlaps_concrete(ca, cb)) return T(0);
  Calc best = std::numeric_limits<Calc>::infinity();
  for_each_primitive(ca, [&](const auto& pa) {
    for_each_primitive(cb, [&](const auto& pb) { best = std::min(best, core_gap(core_of(pa), core_of(pb))); });
  });
  // Separated (decided exactly): a gap that rounds to zero is reported as the least positive T.
  const T gap = static_cast<T>(std::max(Calc(0), best));
  return gap > T(0) ? gap : std::numeric_limits<T>::denorm_min();
}

}  // namespace detail

/// Euclidean distance between the closed shapes: 0 exactly when they overlap, otherwise the gap,
/// at least the smallest positive T (a separated pair whose gap rounds to 0 is not reported as
/// touching). Error: a rounded result, within a few rounding_tolerance(a, b) of the exact gap.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> scalar_of_t<A> distance(const A& a, const B& b) {
  using T = scalar_of_t<A>;
  return detail::visit_shapes(a, b, [](const auto& ca, const auto& cb) { return detail::distance_as<T>(ca, cb); });
}

}  // namespace collide
