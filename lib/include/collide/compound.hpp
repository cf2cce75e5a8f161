#pragma once
/// @file compound.hpp
/// Conservative bounding boxes of the primitives, and Compound, which caches the box of its children.

#include "collide/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace collide {

/// Rounds a box computed in Calc outward to T, after padding it by the rounding of the few
/// operations that computed it, so the result is never smaller than the exact box.
template <Scalar U>
Aabb<U> bounds_from_calc(const Vec2c& lo, const Vec2c& hi) noexcept {
  Vec2<U> out_lo, out_hi;
  for (int i = 0; i < 2; ++i) {
    const Calc pad = 8 * kUnitRoundoff * std::max(std::fabs(lo[i]), std::fabs(hi[i])) + kSmallestDouble;
    const Calc l = lo[i] - pad, h = hi[i] + pad;
    U fl = static_cast<U>(l), fh = static_cast<U>(h);
    if (static_cast<Calc>(fl) > l) fl = std::nextafter(fl, -std::numeric_limits<U>::infinity());
    if (static_cast<Calc>(fh) < h) fh = std::nextafter(fh, std::numeric_limits<U>::infinity());
    out_lo[i] = fl;
    out_hi[i] = fh;
  }
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
  const Vec2c c = widen(s.center());
  const Calc r = s.radius();
  return bounds_from_calc<T>((c.array() - r).matrix(), (c.array() + r).matrix());
}
/// Conservative bounding box: contains the exact shape, a few ulps larger at most.
template <Scalar T>
Aabb<T> bounds(const Capsule<T>& s) noexcept {
  const Vec2c a = widen(s.a()), b = widen(s.b());
  const Calc r = s.radius();
  return bounds_from_calc<T>((a.cwiseMin(b).array() - r).matrix(), (a.cwiseMax(b).array() + r).matrix());
}
/// Conservative bounding box: contains the exact shape, a few ulps larger at most.
template <Scalar T>
Aabb<T> bounds(const Obb<T>& s) noexcept {
  const Vec2c c = widen(s.center()), u = widen(s.axis());
  const Vec2c v = perp(u);
  const Calc hx = s.half_extents().x(), hy = s.half_extents().y();
  const Vec2c ext = (u * hx).cwiseAbs() + (v * hy).cwiseAbs();
  return bounds_from_calc<T>(c - ext, c + ext);
}
/// Conservative bounding box: contains the exact shape, a few ulps larger at most.
template <Scalar T>
Aabb<T> bounds(const ConvexPolygon<T>& s) noexcept {
  Vec2<T> lo = s[0], hi = s[0];
  for (const Vec2<T>& p : s.vertices()) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return detail::AabbAccess::unchecked<T>(lo, hi);
}
/// Conservative bounding box: contains the exact shape, a few ulps larger at most.
template <Scalar T>
Aabb<T> bounds(const Primitive<T>& s) noexcept {
  return std::visit([](const auto& x) { return bounds(x); }, s);
}

/// A body made of several shapes (a "list of geometries"): the union of its children, with a cached bounding box that
/// every query checks before looking at any child.
template <Scalar T>
class Compound {
 public:
  /// Errors: EmptyCompound. Children are valid by construction.
  static Expected<Compound> make(std::vector<Primitive<T>> children) {
    if (children.empty()) return ShapeError(Error::EmptyCompound, -1, "compound has no children");
    Vec2<T> lo = collide::bounds(children[0]).min(), hi = collide::bounds(children[0]).max();
    for (const Primitive<T>& c : children) {
      const Aabb<T> b = collide::bounds(c);
      lo = lo.cwiseMin(b.min());
      hi = hi.cwiseMax(b.max());
    }
    // Unchecked: children's boxes may exceed max_magnitude<T>() (see AabbAccess).
    return Compound(std::move(children), detail::AabbAccess::unchecked<T>(lo, hi));
  }
  /// As make(), throwing the ShapeError.
  explicit Compound(std::vector<Primitive<T>> children) : Compound(make(std::move(children)).value()) {}

  /// The children, in the order given.
  const std::vector<Primitive<T>>& children() const noexcept { return children_; }
  /// Cached conservative bounding box of all children.
  const Aabb<T>& bounds() const noexcept { return bounds_; }

 private:
  Compound(std::vector<Primitive<T>> c, const Aabb<T>& b) : children_(std::move(c)), bounds_(b) {}
  std::vector<Primitive<T>> children_;
  Aabb<T> bounds_;
};

/// The compound's cached box (the union of its children's boxes).
template <Scalar T>
Aabb<T> bounds(const Compound<T>& s) noexcept {
  return s.bounds();
}

}  // namespace collide
