#pragma once
/// @file decide.hpp
/// The sign decisions of every pair: the one place where the library decides "overlapping or
/// not". Every other query (contact, resolve, distance, the compound pairs) asks these functions,
/// so making a pair exact means changing only its function here.
///
/// Convention: shapes are closed sets; touching counts as overlapping.
///
/// Exact for every pair and both scalars: each answer is the exact answer for the stored values
/// (OBB corners are never rounded: they enter as the polynomials c +- hx u +- hy perp(u)). Every
/// decision is the sign of a polynomial of degree <= 6 in the stored values; a floating-point
/// filter with a proven error bound (a static bound for circle-circle, circle-AABB and OBB-OBB,
/// detail::Bounded elsewhere; AABB-AABB is comparisons only) decides almost every call, and the
/// rest are evaluated exactly (detail::Exact).
///
/// Each function takes the pair in registry order (circle < aabb < obb < capsule < polygon).

#include "collide/detail/convex_core.hpp"
#include "collide/detail/exact_signs.hpp"

namespace collide {

namespace decide {

using detail::Core;
using detail::Radii;

/// Exact: the closed circle a and the closed circle b share a point (touching counts).
template <Scalar T>
bool circle_circle(const Circle<T>& a, const Circle<T>& b) {
  const Vec2c ca = widen(a.center()), cb = widen(b.center());
  const Calc ra = a.radius(), rb = b.radius();
  const int s = detail::filtered_sign_dist2(cb.x() - ca.x(), cb.y() - ca.y(), ra + rb);
  if (s != 2) [[likely]]
    return s <= 0;
  return detail::sign_dist2_minus(ca, cb, Radii{ra, rb}) <= 0;
}

/// Exact: the closed circle a and the closed box b share a point (touching counts).
template <Scalar T>
bool circle_aabb(const Circle<T>& a, const Aabb<T>& b) {
  const Vec2c c = widen(a.center());
  const Vec2c nearest = c.cwiseMax(widen(b.min())).cwiseMin(widen(b.max()));  // stored values
  const Calc r = a.radius();
  const int s = detail::filtered_sign_dist2(c.x() - nearest.x(), c.y() - nearest.y(), r);
  if (s != 2) [[likely]]
    return s <= 0;
  return detail::sign_dist2_minus(c, nearest, Radii{r, 0}) <= 0;
}

/// Exact: the closed circle a and the closed oriented box b share a point (touching counts).
template <Scalar T>
bool circle_obb(const Circle<T>& a, const Obb<T>& b) {
  return detail::point_obb_within(widen(a.center()), detail::values_of(b), Radii{Calc(a.radius()), 0});
}

/// Exact: the closed circle a and the closed capsule b share a point (touching counts).
template <Scalar T>
bool circle_capsule(const Circle<T>& a, const Capsule<T>& b) {
  return detail::point_segment_within(widen(a.center()), widen(b.a()), widen(b.b()),
                                      Radii{Calc(a.radius()), Calc(b.radius())});
}

/// Exact: the closed circle a and the closed polygon b share a point (touching counts).
template <Scalar T>
bool circle_polygon(const Circle<T>& a, const ConvexPolygon<T>& b) {
  return detail::dilated_cores_meet(detail::core_of(a), detail::core_of(b), Radii{Calc(a.radius()), 0});
}

/// Exact: the closed box a and the closed box b share a point (touching counts).
template <Scalar T>
bool aabb_aabb(const Aabb<T>& a, const Aabb<T>& b) {
  return !(a.max().x() < b.min().x() || b.max().x() < a.min().x() || a.max().y() < b.min().y() ||
           b.max().y() < a.min().y());
}

/// Exact: the closed box a and the closed oriented box b share a point (touching counts).
template <Scalar T>
bool aabb_obb(const Aabb<T>& a, const Obb<T>& b) {
  return detail::obb_meets_core(detail::values_of(b), detail::core_of(a));
}

/// Exact: the closed box a and the closed capsule b share a point (touching counts).
template <Scalar T>
bool aabb_capsule(const Aabb<T>& a, const Capsule<T>& b) {
  return detail::dilated_cores_meet(detail::core_of(b), detail::core_of(a), Radii{Calc(b.radius()), 0});
}

/// Exact: the closed box a and the closed polygon b share a point (touching counts).
template <Scalar T>
bool aabb_polygon(const Aabb<T>& a, const ConvexPolygon<T>& b) {
  return detail::cores_intersect(detail::core_of(a), detail::core_of(b));
}

/// Exact: the closed oriented box a and the closed oriented box b share a point (touching counts).
template <Scalar T>
bool obb_obb(const Obb<T>& a, const Obb<T>& b) {
  return detail::obb_meets_obb(detail::values_of(a), detail::values_of(b));
}

/// Exact: the closed oriented box a and the closed capsule b share a point (touching counts).
template <Scalar T>
bool obb_capsule(const Obb<T>& a, const Capsule<T>& b) {
  const detail::ObbValues o = detail::values_of(a);
  const Vec2c p = widen(b.a()), q = widen(b.b());
  const Radii r{Calc(b.radius()), 0};
  if (detail::point_obb_within(p, o, r)) return true;
  if (p == q) return false;
  if (detail::point_obb_within(q, o, r)) return true;
  Core k;
  k.push(p);
  k.push(q);
  if (detail::obb_meets_core(o, k)) return true;
  // Disjoint: the distance is attained at an end of the segment (tested) or at a corner.
  for (const detail::ObbCorner& c : o.corners()) {
    if (detail::point_segment_within(c, p, q, r)) return true;
  }
  return false;
}

/// Exact: the closed oriented box a and the closed polygon b share a point (touching counts).
template <Scalar T>
bool obb_polygon(const Obb<T>& a, const ConvexPolygon<T>& b) {
  return detail::obb_meets_core(detail::values_of(a), detail::core_of(b));
}

/// Exact: the closed capsule a and the closed capsule b share a point (touching counts).
template <Scalar T>
bool capsule_capsule(const Capsule<T>& a, const Capsule<T>& b) {
  return detail::dilated_cores_meet(detail::core_of(a), detail::core_of(b), Radii{Calc(a.radius()), Calc(b.radius())});
}

/// Exact: the closed capsule a and the closed polygon b share a point (touching counts).
template <Scalar T>
bool capsule_polygon(const Capsule<T>& a, const ConvexPolygon<T>& b) {
  return detail::dilated_cores_meet(detail::core_of(a), detail::core_of(b), Radii{Calc(a.radius()), 0});
}

/// Exact: the closed polygon a and the closed polygon b share a point (touching counts).
template <Scalar T>
bool polygon_polygon(const ConvexPolygon<T>& a, const ConvexPolygon<T>& b) {
  return detail::cores_intersect(detail::core_of(a), detail::core_of(b));
}

/// The decision for a pair of primitives in registry order, by overload.
template <Scalar T>
bool pair(const Circle<T>& a, const Circle<T>& b) {
  return circle_circle(a, b);
}
/// @cond COLLIDE_SPECIALISATIONS
template <Scalar T>
bool pair(const Circle<T>& a, const Aabb<T>& b) {
  return circle_aabb(a, b);
}
template <Scalar T>
bool pair(const Circle<T>& a, const Obb<T>& b) {
  return circle_obb(a, b);
}
template <Scalar T>
bool pair(const Circle<T>& a, const Capsule<T>& b) {
  return circle_capsule(a, b);
}
template <Scalar T>
bool pair(const Circle<T>& a, const ConvexPolygon<T>& b) {
  return circle_polygon(a, b);
}
template <Scalar T>
bool pair(const Aabb<T>& a, const Aabb<T>& b) {
  return aabb_aabb(a, b);
}
template <Scalar T>
bool pair(const Aabb<T>& a, const Obb<T>& b) {
  return aabb_obb(a, b);
}
template <Scalar T>
bool pair(const Aabb<T>& a, const Capsule<T>& b) {
  return aabb_capsule(a, b);
}
template <Scalar T>
bool pair(const Aabb<T>& a, const ConvexPolygon<T>& b) {
  return aabb_polygon(a, b);
}
template <Scalar T>
bool pair(const Obb<T>& a, const Obb<T>& b) {
  return obb_obb(a, b);
}
template <Scalar T>
bool pair(const Obb<T>& a, const Capsule<T>& b) {
  return obb_capsule(a, b);
}
template <Scalar T>
bool pair(const Obb<T>& a, const ConvexPolygon<T>& b) {
  return obb_polygon(a, b);
}
template <Scalar T>
bool pair(const Capsule<T>& a, const Capsule<T>& b) {
  return capsule_capsule(a, b);
}
template <Scalar T>
bool pair(const Capsule<T>& a, const ConvexPolygon<T>& b) {
  return capsule_polygon(a, b);
}
template <Scalar T>
bool pair(const ConvexPolygon<T>& a, const ConvexPolygon<T>& b) {
  return polygon_polygon(a, b);
}
/// @endcond

}  // namespace decide

}  // namespace collide
