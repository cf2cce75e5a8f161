#pragma once
/// @file detail/contains_shape.hpp
/// Whether a convex primitive holds a whole shape, exactly. The inner shape is the convex hull of
/// a few discs: a circle is one, a capsule its two end discs, a box or polygon its corners (radius
/// 0). A convex outer shape holds that hull exactly when it holds every disc, and each disc test
/// is a few signs of polynomials in the stored values (exact_sign: a filter with a proven bound,
/// then exact arithmetic), so the answer is exact. An OBB's corners enter as their polynomials
/// (ObbCorner), never rounded.

#include "collide/detail/exact_signs.hpp"
#include "collide/predicates.hpp"
#include "collide/shape_traits.hpp"
#include "collide/shapes.hpp"

#include <cstddef>

namespace collide {

namespace detail {

// ---------------------------------------------------------------------------------------------
// The disc of centre p (a stored point or an OBB corner) and radius r >= 0 inside one outer kind.

/// sign of (p - a)[axis] + k r, k = +-1: p's room to a box side, less or more the radius.
template <class P>
int sign_side_minus(const P& p, const Vec2c& a, int axis, Calc r, int k) noexcept {
  return exact_sign([&](auto tag) {
    using N = decltype(tag);
    const auto d = offset<N>(p, a);
    return d[std::size_t(axis)] + (k > 0 ? N(r) : -N(r));
  });
}

/// sign of e^2 - r^2 |u|^2, e = sign_face_excess(p, o, axis, sigma): against a face p is beyond
/// by e / |u| (negative inside), whether the room inside is at least r.
template <class P>
int sign_face_room_minus(const P& p, const ObbValues& o, int axis, int sigma, Calc r) noexcept {
  return exact_sign([&](auto tag) {
    using N = decltype(tag);
    const auto [dx, dy] = offset<N>(p, o.c);
    const N ux(o.u.x()), uy(o.u.y()), h(axis == 0 ? o.hx : o.hy), rr(r);
    const N uu = ux * ux + uy * uy;
    const N along = axis == 0 ? dx * ux + dy * uy : dy * ux - dx * uy;
    const N e = (sigma > 0 ? along : -along) - h * uu;
    return e * e - rr * rr * uu;
  });
}

/// Circle (c, R) holds the disc: R >= r and |p - c| <= R - r (the radii kept as two terms).
template <class P, Scalar T>
bool disc_inside(const Circle<T>& s, const P& p, Calc r) noexcept {
  const Calc big = s.radius();
  if (r > big) return false;
  if constexpr (std::is_same_v<P, Vec2c>) {
    const Vec2c c = widen(s.center());
    if (const int f = filtered_sign_dist2(p.x() - c.x(), p.y() - c.y(), big - r); f != 2) [[likely]]
      return f <= 0;
  }
  return sign_dist2_minus(p, widen(s.center()), Radii{big, -r}) <= 0;
}

/// Box [lo, hi] holds the disc: lo + r <= p <= hi - r on both axes.
template <class P, Scalar T>
bool disc_inside(const Aabb<T>& s, const P& p, Calc r) noexcept {
  const Vec2c lo = widen(s.min()), hi = widen(s.max());
  for (int axis = 0; axis < 2; ++axis) {
    if (sign_side_minus(p, lo, axis, r, -1) < 0 || sign_side_minus(p, hi, axis, r, 1) > 0) return false;
  }
  return true;
}

/// OBB holds the disc: against each of its four faces p is inside with room r.
template <class P, Scalar T>
bool disc_inside(const Obb<T>& s, const P& p, Calc r) noexcept {
  const ObbValues o = values_of(s);
  for (int axis = 0; axis < 2; ++axis) {
    for (int sigma = -1; sigma <= 1; sigma += 2) {
      const int e = sign_face_excess(p, o, axis, sigma);
      if (e > 0 || (r > 0 && (e == 0 || sign_face_room_minus(p, o, axis, sigma, r) < 0))) return false;
    }
  }
  return true;
}

/// Capsule ([a, b], R) holds the disc: R >= r and dist(p, [a, b]) <= R - r.
template <class P, Scalar T>
bool disc_inside(const Capsule<T>& s, const P& p, Calc r) noexcept {
  const Calc big = s.radius();
  if (r > big) return false;
  return point_segment_within(p, widen(s.a()), widen(s.b()), Radii{big, -r});
}

/// Polygon holds the disc: left of every edge (counter-clockwise) with room r.
template <class P, Scalar T>
bool disc_inside(const ConvexPolygon<T>& s, const P& p, Calc r) noexcept {
  const auto v = s.vertices();
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2c a = widen(v[i]), b = widen(v[next_index(i, n)]);
    const int turn = sign_turn(a, b, p);
    if (turn < 0 || (r > 0 && (turn == 0 || sign_line_dist2_minus(p, a, b, Radii{r, 0}) < 0))) return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// The discs of an inner primitive: f(p, r) for each, stopping at the first false.

template <Scalar T, class F>
bool all_discs(const Circle<T>& s, F&& f) {
  return f(widen(s.center()), Calc(s.radius()));
}
template <Scalar T, class F>
bool all_discs(const Capsule<T>& s, F&& f) {
  return f(widen(s.a()), Calc(s.radius())) && f(widen(s.b()), Calc(s.radius()));
}
template <Scalar T, class F>
bool all_discs(const Aabb<T>& s, F&& f) {
  const Vec2c lo = widen(s.min()), hi = widen(s.max());
  return f(lo, Calc(0)) && f(hi, Calc(0)) && f(Vec2c(lo.x(), hi.y()), Calc(0)) && f(Vec2c(hi.x(), lo.y()), Calc(0));
}
template <Scalar T, class F>
bool all_discs(const Obb<T>& s, F&& f) {
  for (const ObbCorner& c : values_of(s).corners()) {
    if (!f(c, Calc(0))) return false;
  }
  return true;
}
template <Scalar T, class F>
bool all_discs(const ConvexPolygon<T>& s, F&& f) {
  for (const auto& q : s.vertices()) {
    if (!f(widen(q), Calc(0))) return false;
  }
  return true;
}

/// The convex primitive `outer` holds every primitive of `inner` (a compound: each child, as
/// placed; a primitive: itself).
template <class O, class I>
bool primitive_holds(const O& outer, const I& inner) {
  bool all = true;
  for_each_primitive(inner, [&](const auto& x) {
    all = all && all_discs(x, [&](const auto& p, Calc r) { return disc_inside(outer, p, r); });
  });
  return all;
}

}  // namespace detail

}  // namespace collide
