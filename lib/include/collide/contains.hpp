#pragma once
/// @file contains.hpp
/// Point containment: does a closed shape hold a point?
///
/// Error contract:
/// - AABB and polygon (and compounds made only of them): exact, by comparisons and the exact
///   orient().
/// - circle, capsule, OBB: the answer equals the exact one for the stored values whenever the
///   distance from p to the shape's boundary exceeds contains_tolerance(s, p)
///   = 64 * 2^-53 * max(S, |p|_inf) + 2^-500, S = largest absolute coordinate of bounds(s).
///   (Squared distances are rounded; OBB corners are rounded before the exact point test.)
/// - Round shapes below detail::kTinyCore are decided after exact rescaling, so the 2^-500 floor
///   is a bound, not the typical error, for subnormal shapes.

#include "collide/compound.hpp"
#include "collide/decide.hpp"
#include "collide/detail/core.hpp"
#include "collide/queries.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace collide {

namespace detail {

/// Tiny round shapes are decided on exactly rescaled cores (as overlaps() does), so that squares
/// of subnormal distances do not underflow to zero.
inline bool contains_tiny(const Core& shape, const Vec2c& p) {
  Core pc;
  pc.push(p);
  return decide::dilated_cores(pc, shape);
}

template <Scalar T>
bool contains_concrete(const Circle<T>& s, const Vec2c& p) {
  const Calc r = s.radius();
  if (r < kTinyCore) return contains_tiny(core_of(s), p);
  return (p - widen(s.center())).squaredNorm() <= r * r;
}
template <Scalar T>
bool contains_concrete(const Aabb<T>& s, const Vec2c& p) noexcept {
  return s.min().x() <= p.x() && p.x() <= s.max().x() && s.min().y() <= p.y() && p.y() <= s.max().y();
}
template <Scalar T>
bool contains_concrete(const Obb<T>& s, const Vec2c& p) {
  Core pc;
  pc.push(p);
  return cores_intersect(pc, core_of(s));
}
template <Scalar T>
bool contains_concrete(const Capsule<T>& s, const Vec2c& p) {
  const Calc r = s.radius();
  if (r < kTinyCore) return contains_tiny(core_of(s), p);
  return (p - closest_on_segment(p, widen(s.a()), widen(s.b()))).squaredNorm() <= r * r;
}
template <Scalar T>
bool contains_concrete(const ConvexPolygon<T>& s, const Vec2c& p) noexcept {
  const auto v = s.vertices();
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (orient(widen(v[i]), widen(v[(i + 1) % n]), p) < 0) return false;
  }
  return true;
}
template <Scalar T>
bool contains_concrete(const Compound<T>& s, const Vec2c& p) {
  if (!contains_concrete(s.bounds(), p)) return false;  // bounds are conservative: exact early-out
  for (const Primitive<T>& c : s.children()) {
    if (std::visit([&](const auto& x) { return contains_concrete(x, p); }, c)) return true;
  }
  return false;
}

}  // namespace detail

/// True when p lies in the closed shape (boundary included). p may be any value: NaN gives false
/// (comparisons with NaN fail), infinities give false for every bounded shape.
/// Error: exact for AABBs and polygons; otherwise see contains_tolerance().
template <AnyShape S>
bool contains(const S& s, const Vec2<scalar_of_t<S>>& p) {
  const Vec2c q = widen(p);
  if (!std::isfinite(q.x()) || !std::isfinite(q.y())) return false;
  return detail::visit_shape(s, [&](const auto& x) { return detail::contains_concrete(x, q); });
}

/// The error bound of contains(s, p) for the rounded shapes (circle, capsule, OBB):
/// 64 * 2^-53 * max(S, |p|_inf) + 2^-500, S = largest absolute coordinate of bounds(s).
template <AnyShape S>
Calc contains_tolerance(const S& s, const Vec2<scalar_of_t<S>>& p) {
  const Calc m = std::max(detail::scale_of(bounds(s)), widen(p).cwiseAbs().maxCoeff());
  return kOverlapErrorFactor * 0x1p-53 * m + kAbsoluteFloor;
}

}  // namespace collide
