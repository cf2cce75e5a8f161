#pragma once
/// @file bounds.hpp
/// Conservative bounding boxes of the primitives, and the box arithmetic behind them: a box in
/// double rounded outward to a stored scalar, the scale of a box.

#include "collide/config.hpp"
#include "collide/predicates.hpp"
#include "collide/shapes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <variant>

namespace collide {

namespace detail {
/// A U not above v, at most three units in the last place below it: v rounded to nearest when
/// that is not above, else v lowered by 1 to 2 units (|v| eps_U, plus U's smallest subnormal)
/// and then rounded, which half a unit cannot lift back above v. Picked by a mask, not a
/// branch: which way the rounding goes is a coin flip.
template <Scalar U>
U round_down_to(Calc v) noexcept {
  const U nearest = static_cast<U>(v);
  if constexpr (std::is_same_v<U, Calc>) {
    return nearest;
  } else {
    static_assert(sizeof(U) == sizeof(std::uint32_t));
    const U below = static_cast<U>(v - std::fabs(v) * Calc(std::numeric_limits<U>::epsilon()) -
                                   Calc(std::numeric_limits<U>::denorm_min()));
    const std::uint32_t keep = 0u - std::uint32_t(static_cast<Calc>(nearest) <= v);
    return std::bit_cast<U>((std::bit_cast<std::uint32_t>(nearest) & keep) |
                            (std::bit_cast<std::uint32_t>(below) & ~keep));
  }
}
}  // namespace detail

namespace detail {
/// Largest absolute coordinate of a box: the scale of the rounding errors of what lies in it.
template <Scalar T>
Calc scale_of(const Aabb<T>& b) noexcept {
  return std::max(widen(b.min()).cwiseAbs().maxCoeff(), widen(b.max()).cwiseAbs().maxCoeff());
}

/// A primitive's box as computed in Calc from its stored values, before bounds() pads it and
/// rounds it outward to T: exact for an AABB and a polygon, a few roundings off otherwise.
template <Scalar T>
Aabb<Calc> calc_box(const Aabb<T>& s) noexcept {
  return AabbAccess::unchecked<Calc>(widen(s.min()), widen(s.max()));
}
template <Scalar T>
Aabb<Calc> calc_box(const Circle<T>& s) noexcept {
  const Vec2c c = widen(s.center());
  const Calc r = s.radius();
  return AabbAccess::unchecked<Calc>((c.array() - r).matrix(), (c.array() + r).matrix());
}
template <Scalar T>
Aabb<Calc> calc_box(const Capsule<T>& s) noexcept {
  const Vec2c a = widen(s.a()), b = widen(s.b());
  const Calc r = s.radius();
  return AabbAccess::unchecked<Calc>((a.cwiseMin(b).array() - r).matrix(), (a.cwiseMax(b).array() + r).matrix());
}
template <Scalar T>
Aabb<Calc> calc_box(const Obb<T>& s) noexcept {
  const Vec2c c = widen(s.center()), u = widen(s.axis());
  const Vec2c ext = (u * Calc(s.half_extents().x())).cwiseAbs() + (perp(u) * Calc(s.half_extents().y())).cwiseAbs();
  return AabbAccess::unchecked<Calc>(c - ext, c + ext);
}
/// The box of a polygon's stored vertices (cached): exact.
template <Scalar T>
Aabb<T> vertex_box(const ConvexPolygon<T>& s) noexcept {
  const auto [lo, hi] = PolygonAccess::box(s);
  return AabbAccess::unchecked<T>(lo, hi);
}
template <Scalar T>
Aabb<Calc> calc_box(const ConvexPolygon<T>& s) noexcept {
  const Aabb<T> b = vertex_box(s);
  return AabbAccess::unchecked<Calc>(widen(b.min()), widen(b.max()));
}
}  // namespace detail

/// Rounds a box computed in Calc outward to T, after padding it by the rounding of the few
/// operations that computed it, so the result is never smaller than the exact box.
template <Scalar U>
Aabb<U> bounds_from_calc(const Vec2c& lo, const Vec2c& hi) noexcept {
  // Each bound computed as a scalar and the vectors built whole: components stored one by one
  // and read back as a pair would stall the load.
  const auto pad = [&](int i) {
    return 8 * kUnitRoundoff * std::max(std::fabs(lo[i]), std::fabs(hi[i])) + kSmallestDouble;
  };
  const Calc px = pad(0), py = pad(1);
  const Vec2<U> out_lo(detail::round_down_to<U>(lo.x() - px), detail::round_down_to<U>(lo.y() - py));
  const Vec2<U> out_hi(-detail::round_down_to<U>(-(hi.x() + px)), -detail::round_down_to<U>(-(hi.y() + py)));
  return Aabb<U>(detail::Unchecked{}, out_lo, out_hi);
}

/// Conservative bounding box: it contains the exact shape; rounding may grow it by a few ulps,
/// never shrink it. An AABB is its own bounds, exactly.
template <Scalar T>
Aabb<T> bounds(const Aabb<T>& s) noexcept {
  return s;
}
/// Conservative bounding box: contains the exact shape, a few ulps larger at most.
template <Scalar T>
Aabb<T> bounds(const Circle<T>& s) noexcept {
  const Aabb<Calc> b = detail::calc_box(s);
  return bounds_from_calc<T>(b.min(), b.max());
}
/// Conservative bounding box: contains the exact shape, a few ulps larger at most.
template <Scalar T>
Aabb<T> bounds(const Capsule<T>& s) noexcept {
  const Aabb<Calc> b = detail::calc_box(s);
  return bounds_from_calc<T>(b.min(), b.max());
}
/// Conservative bounding box: contains the exact shape, a few ulps larger at most.
template <Scalar T>
Aabb<T> bounds(const Obb<T>& s) noexcept {
  const Aabb<Calc> b = detail::calc_box(s);
  return bounds_from_calc<T>(b.min(), b.max());
}
/// Conservative bounding box: contains the exact shape, a few ulps larger at most.
template <Scalar T>
Aabb<T> bounds(const ConvexPolygon<T>& s) noexcept {
  return detail::vertex_box(s);
}
/// Conservative bounding box: contains the exact shape, a few ulps larger at most.
template <Scalar T>
Aabb<T> bounds(const Primitive<T>& s) noexcept {
  return std::visit([](const auto& x) { return bounds(x); }, s);
}

}  // namespace collide
