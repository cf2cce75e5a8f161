#pragma once
/// @file detail/contains_point.hpp
/// Whether a concrete shape, stored or placed, holds a point in double: the exact signs of
/// decide.hpp, shared by contains() and by raycast()'s test of a ray's origin.

#include "collide/decide.hpp"
#include "collide/detail/convex_core.hpp"
#include "collide/predicates.hpp"
#include "collide/shape_traits.hpp"
#include "collide/shapes.hpp"
#include "collide/tolerances.hpp"

#include <cstddef>

namespace collide {

namespace detail {

template <Scalar T>
bool contains_concrete(const Circle<T>& s, const Vec2c& p) noexcept {
  return sign_dist2_minus(p, widen(s.center()), Radii{Calc(s.radius()), 0}) <= 0;
}
template <Scalar T>
bool contains_concrete(const Aabb<T>& s, const Vec2c& p) noexcept {
  return s.min().x() <= p.x() && p.x() <= s.max().x() && s.min().y() <= p.y() && p.y() <= s.max().y();
}
template <Scalar T>
bool contains_concrete(const Obb<T>& s, const Vec2c& p) noexcept {
  return point_obb_within(p, values_of(s), Radii{});
}
template <Scalar T>
bool contains_concrete(const Capsule<T>& s, const Vec2c& p) noexcept {
  return point_segment_within(p, widen(s.a()), widen(s.b()), Radii{Calc(s.radius()), 0});
}
template <Scalar T>
bool contains_concrete(const ConvexPolygon<T>& s, const Vec2c& p) noexcept {
  const auto v = s.vertices();
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (orient(widen(v[i]), widen(v[next_index(i, n)]), p) < 0) return false;
  }
  return true;
}
/// A compound, stored or placed: its box first (conservative, so an exact early-out), then each
/// child as placed.
template <class S>
requires is_compound_v<S>
bool contains_concrete(const S& s, const Vec2c& p) {
  if (!contains_concrete(calc_bounds(s), p)) return false;
  bool in = false;
  for_each_primitive(s, [&](const auto& x) { in = in || contains_concrete(x, p); });
  return in;
}

}  // namespace detail

}  // namespace collide
