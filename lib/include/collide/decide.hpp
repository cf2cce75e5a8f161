#pragma once
/// @file decide.hpp
/// The sign decisions of every pair: the one place where the library decides "overlapping or
/// not". Every other query (contact, resolve, distance, the compound pairs) asks these functions,
/// so making a pair exact means changing only its function here.
///
/// Convention: shapes are closed sets; touching counts as overlapping.
///
/// Exactness today (property-checked against the CGAL oracle):
/// - exact: aabb_aabb, aabb_polygon, polygon_polygon (comparisons and the exact orient()).
/// - within overlap_tolerance() of the exact answer: every pair with a circle, a capsule or an OBB
///   (squared distances are rounded; OBB corners are rounded).
/// - The three hot pairs (circle_circle, circle_aabb, aabb_aabb) are inline formulas; a round pair
///   whose summed radius is below detail::kTinyCore takes the rescaled core path instead, so tiny
///   (subnormal) shapes are decided to relative, not absolute, accuracy.
///
/// Each function takes the pair in registry order (circle < aabb < obb < capsule < polygon).

#include "collide/detail/core.hpp"

namespace collide::decide {

using detail::Core;

/// Dilated cores overlap: the cores meet (exact), or their rounded squared distance is within
/// the summed radius. Tiny cores (every value below detail::kTinyCore) are compared after exact
/// rescaling, so their squares do not underflow.
inline bool dilated_cores(const Core& p, const Core& q) {
  if (detail::cores_intersect(p, q)) return true;
  const Calc r = p.radius + q.radius;
  if (!(r > 0)) return false;
  if (r < detail::kTinyCore) {
    if (const int k = detail::tiny_scale(p, q); k != 0) {
      const Core ps = detail::scaled(p, k), qs = detail::scaled(q, k);
      const Calc rs = ps.radius + qs.radius;
      return detail::closest_points(ps, qs).dist2 <= rs * rs;
    }
  }
  return detail::closest_points(p, q).dist2 <= r * r;
}

template <Scalar T>
bool circle_circle(const Circle<T>& a, const Circle<T>& b) {
  const Vec2c d = widen(b.center()) - widen(a.center());
  const Calc r = Calc(a.radius()) + Calc(b.radius());
  if (r < detail::kTinyCore) [[unlikely]] return dilated_cores(detail::core_of(a), detail::core_of(b));
  return d.squaredNorm() <= r * r;
}

template <Scalar T>
bool circle_aabb(const Circle<T>& a, const Aabb<T>& b) {
  const Vec2c c = widen(a.center());
  const Vec2c nearest = c.cwiseMax(widen(b.min())).cwiseMin(widen(b.max()));
  const Calc r = a.radius();
  if (r < detail::kTinyCore) [[unlikely]] return dilated_cores(detail::core_of(a), detail::core_of(b));
  return (c - nearest).squaredNorm() <= r * r;
}

template <Scalar T>
bool circle_obb(const Circle<T>& a, const Obb<T>& b) {
  return dilated_cores(detail::core_of(a), detail::core_of(b));
}

template <Scalar T>
bool circle_capsule(const Circle<T>& a, const Capsule<T>& b) {
  const Vec2c c = widen(a.center());
  const Calc r = Calc(a.radius()) + Calc(b.radius());
  if (r < detail::kTinyCore) [[unlikely]] return dilated_cores(detail::core_of(a), detail::core_of(b));
  const Vec2c nearest = detail::closest_on_segment(c, widen(b.a()), widen(b.b()));
  return (c - nearest).squaredNorm() <= r * r;
}

template <Scalar T>
bool circle_polygon(const Circle<T>& a, const ConvexPolygon<T>& b) {
  return dilated_cores(detail::core_of(a), detail::core_of(b));
}

template <Scalar T>
bool aabb_aabb(const Aabb<T>& a, const Aabb<T>& b) {
#if defined(COLLIDE_PLANTED_FAULT)
  // The lecture's slip, kept behind a switch so the test suite can prove it notices:
  // `b.max.y < a.min.x` where `a.min.y` is meant.
  return !(a.max().x() < b.min().x() || b.max().x() < a.min().x() || a.max().y() < b.min().y() ||
           b.max().y() < a.min().x());
#else
  return !(a.max().x() < b.min().x() || b.max().x() < a.min().x() || a.max().y() < b.min().y() ||
           b.max().y() < a.min().y());
#endif
}

template <Scalar T>
bool aabb_obb(const Aabb<T>& a, const Obb<T>& b) {
  return dilated_cores(detail::core_of(a), detail::core_of(b));
}

template <Scalar T>
bool aabb_capsule(const Aabb<T>& a, const Capsule<T>& b) {
  return dilated_cores(detail::core_of(a), detail::core_of(b));
}

template <Scalar T>
bool aabb_polygon(const Aabb<T>& a, const ConvexPolygon<T>& b) {
  return detail::cores_intersect(detail::core_of(a), detail::core_of(b));
}

template <Scalar T>
bool obb_obb(const Obb<T>& a, const Obb<T>& b) {
  return dilated_cores(detail::core_of(a), detail::core_of(b));
}

template <Scalar T>
bool obb_capsule(const Obb<T>& a, const Capsule<T>& b) {
  return dilated_cores(detail::core_of(a), detail::core_of(b));
}

template <Scalar T>
bool obb_polygon(const Obb<T>& a, const ConvexPolygon<T>& b) {
  return dilated_cores(detail::core_of(a), detail::core_of(b));
}

template <Scalar T>
bool capsule_capsule(const Capsule<T>& a, const Capsule<T>& b) {
  return dilated_cores(detail::core_of(a), detail::core_of(b));
}

template <Scalar T>
bool capsule_polygon(const Capsule<T>& a, const ConvexPolygon<T>& b) {
  return dilated_cores(detail::core_of(a), detail::core_of(b));
}

template <Scalar T>
bool polygon_polygon(const ConvexPolygon<T>& a, const ConvexPolygon<T>& b) {
  return detail::cores_intersect(detail::core_of(a), detail::core_of(b));
}

/// The decision for a pair of primitives in registry order, by overload.
template <Scalar T> bool pair(const Circle<T>& a, const Circle<T>& b) { return circle_circle(a, b); }
template <Scalar T> bool pair(const Circle<T>& a, const Aabb<T>& b) { return circle_aabb(a, b); }
template <Scalar T> bool pair(const Circle<T>& a, const Obb<T>& b) { return circle_obb(a, b); }
template <Scalar T> bool pair(const Circle<T>& a, const Capsule<T>& b) { return circle_capsule(a, b); }
template <Scalar T> bool pair(const Circle<T>& a, const ConvexPolygon<T>& b) { return circle_polygon(a, b); }
template <Scalar T> bool pair(const Aabb<T>& a, const Aabb<T>& b) { return aabb_aabb(a, b); }
template <Scalar T> bool pair(const Aabb<T>& a, const Obb<T>& b) { return aabb_obb(a, b); }
template <Scalar T> bool pair(const Aabb<T>& a, const Capsule<T>& b) { return aabb_capsule(a, b); }
template <Scalar T> bool pair(const Aabb<T>& a, const ConvexPolygon<T>& b) { return aabb_polygon(a, b); }
template <Scalar T> bool pair(const Obb<T>& a, const Obb<T>& b) { return obb_obb(a, b); }
template <Scalar T> bool pair(const Obb<T>& a, const Capsule<T>& b) { return obb_capsule(a, b); }
template <Scalar T> bool pair(const Obb<T>& a, const ConvexPolygon<T>& b) { return obb_polygon(a, b); }
template <Scalar T> bool pair(const Capsule<T>& a, const Capsule<T>& b) { return capsule_capsule(a, b); }
template <Scalar T> bool pair(const Capsule<T>& a, const ConvexPolygon<T>& b) { return capsule_polygon(a, b); }
template <Scalar T> bool pair(const ConvexPolygon<T>& a, const ConvexPolygon<T>& b) { return polygon_polygon(a, b); }

}  // namespace collide::decide
