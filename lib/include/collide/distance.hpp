#pragma once
/// @file distance.hpp
/// Distances: the gap between two shapes, the closest points that realise it, and the signed
/// distance from a point to a shape. Error contract: tolerances.hpp.

#include "collide/detail/convex_core.hpp"
#include "collide/detail/witness.hpp"
#include "collide/overlaps.hpp"
#include "collide/shape_traits.hpp"
#include "collide/tolerances.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

namespace collide {

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

/// The answer of closest_points(): the distance and a point of each shape that realises it.
template <Scalar T>
struct ClosestPoints {
  T distance = 0;                     ///< distance(a, b), bit for bit
  Vec2<T> point_a = Vec2<T>::Zero();  ///< a point of a
  Vec2<T> point_b = Vec2<T>::Zero();  ///< a point of b; point_a itself when the shapes overlap
};

namespace detail {

/// closest_points() in T, for concrete shapes stored or placed.
///   1. Overlapping (the decision distance_as() takes): a point both hold, of the first child
///      pair that overlaps, as both witnesses.
///   2. Apart: the child pair of least gap, found as distance_as() finds it (the same gaps, the
///      same order, so the same distance), and its surface points facing each other.
template <Scalar T, class A, class B>
ClosestPoints<T> closest_as(const A& ca, const B& cb) {
  const auto both = [](const Vec2c& x) {
    const Vec2<T> p = x.template cast<T>();
    return ClosestPoints<T>{T(0), p, p};
  };
  if constexpr (!is_compound_v<A> && !is_compound_v<B>) {
    if (decide_primitives(ca, cb)) return both(common_point(ca, cb));
  } else if (overlaps_concrete(ca, cb)) {
    std::optional<Vec2c> at;
    for_each_primitive(ca, [&](const auto& pa) {
      for_each_primitive(cb, [&](const auto& pb) {
        if (!at && decide_primitives(pa, pb)) at = common_point(pa, pb);
      });
    });
    return both(at.value_or(Vec2c::Zero()));  // some child pair overlaps: always found
  }
  CoreWitness best;
  Calc ra = 0, rb = 0;
  for_each_primitive(ca, [&](const auto& pa) {
    for_each_primitive(cb, [&](const auto& pb) {
      const Core p = core_of(pa), q = core_of(pb);
      const CoreWitness w = core_witness(p, q);
      if (w.gap < best.gap) {
        best = w;
        ra = p.radius;
        rb = q.radius;
      }
    });
  });
  // The gap as distance_as() rounds it (a separated pair is never reported as touching).
  const T gap = static_cast<T>(std::max(Calc(0), best.gap));
  const PointPair s = surface_points(best, ra, rb);
  return {gap > T(0) ? gap : std::numeric_limits<T>::denorm_min(), s.a.template cast<T>(), s.b.template cast<T>()};
}

/// signed_distance() in T, for a concrete shape stored or placed, at a point v of any value.
/// A compound: the least of its children's signed distances.
template <Scalar T, class S>
T signed_distance_as(const S& s, const Vec2c& v) {
  if (std::isnan(v.x()) || std::isnan(v.y())) return std::numeric_limits<T>::quiet_NaN();
  if (!std::isfinite(v.x()) || !std::isfinite(v.y())) return std::numeric_limits<T>::infinity();
  Calc best = std::numeric_limits<Calc>::infinity();
  for_each_primitive(s, [&](const auto& x) { best = std::min(best, primitive_signed_distance(x, v)); });
  // Rounded to T with its sign kept: a point outside whose distance underflows T stays outside.
  const T out = static_cast<T>(best);
  if (best > 0 && !(out > T(0))) return std::numeric_limits<T>::denorm_min();
  return out == T(0) ? T(0) : out;
}

}  // namespace detail

/// The closest points of two shapes: `distance` is distance(a, b) bit for bit; for shapes apart,
/// point_a on a's boundary and point_b on b's, facing each other across the gap, with
/// |point_b - point_a| the distance; for shapes that overlap (touching included), distance 0 and
/// point_a == point_b, one point both shapes hold (for the depth and the direction that
/// separates them: contact()). Which common point: where the shapes' inner cores meet (a box's
/// or polygon's area, a capsule's segment, a circle's centre), a corner or end of one inside the
/// other, or where their edges cross; where only the round parts meet, the point that divides the
/// segment between the cores' closest points in the ratio of their radii (where they touch, when
/// they just touch). A compound answers with its closest child, or its first child overlapping.
/// Error: each point lies within closest_points_tolerance(a, b) of its shape, and |point_b -
/// point_a| within it of the distance; the distance has distance()'s bound.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> ClosestPoints<scalar_of_t<A>> closest_points(const A& a,
                                                                                                     const B& b) {
  using T = scalar_of_t<A>;
  return detail::visit_shapes(a, b, [](const auto& ca, const auto& cb) { return detail::closest_as<T>(ca, cb); });
}

/// The signed distance from p to the closed shape s: the distance to its boundary, negative
/// inside, 0 on it. Its sign is contains()'s, exactly: signed_distance(s, p) <= 0 exactly when
/// contains(s, p). So a negative answer means p is held, and a positive one that it is not, however
/// close to the boundary (a distance that rounds to 0 outside is the least positive T); a point on
/// the boundary gets 0 or a negative value within the bound. A compound: the least over its
/// children, so outside it the distance to the union, and inside minus the depth in the deepest
/// child holding p (where children overlap, the union may be deeper). A NaN coordinate gives NaN
/// (contains() is false there); an infinite point, or a distance beyond the largest finite T,
/// +infinity.
/// Error: within signed_distance_tolerance(s, p) of the exact signed distance (for a compound,
/// of the least of its children's).
template <AnyShape S>
scalar_of_t<S> signed_distance(const S& s, const Vec2<scalar_of_t<S>>& p) {
  using T = scalar_of_t<S>;
  const Vec2c v = widen(p);
  return detail::visit_shape(s, [&](const auto& x) { return detail::signed_distance_as<T>(x, v); });
}

}  // namespace collide
