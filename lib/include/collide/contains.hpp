#pragma once
/// @file contains.hpp
/// Point containment: does a closed shape hold a point?
///
/// Error contract: exact for every kind. The answer is the exact answer for the stored values
/// and point (the same exact signs as overlaps(), see decide.hpp); contains_tolerance() is 0,
/// except for a compound with child transforms: its children are imaged (transformed.hpp), so
/// points within its placement_tolerance() of a child's boundary may be answered either way.

#include "collide/compound.hpp"
#include "collide/decide.hpp"
#include "collide/detail/core.hpp"
#include "collide/queries.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

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

/// True when p lies in the closed shape (boundary included). p may be any value: NaN gives false
/// (comparisons with NaN fail), infinities give false for every bounded shape.
/// Error: exact for every kind; within contains_tolerance() for a compound with child transforms.
template <AnyShape S>
bool contains(const S& s, const Vec2<scalar_of_t<S>>& p) {
  const Vec2c q = widen(p);
  if (!std::isfinite(q.x()) || !std::isfinite(q.y())) return false;
  return detail::visit_shape(s, [&](const auto& x) { return detail::contains_concrete(x, q); });
}

/// The error bound of contains(s, p): the distance from the boundary within which the answer
/// may differ from the exact one. 0 for stored shapes, every kind being decided exactly;
/// placement_tolerance(s) for a compound with child transforms (its children's images round).
template <AnyShape S>
Calc contains_tolerance(const S& s, const Vec2<scalar_of_t<S>>&) noexcept {
  return placement_tolerance(s);
}

}  // namespace collide
