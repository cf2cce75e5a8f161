#pragma once
/// @file image.hpp
/// The world image of a primitive stored in a local frame: its defining points mapped by a pose
/// and rounded to double, its radii and half extents kept, an OBB's axis turned. Images are built
/// without validation (the exact image of a valid shape is valid; rounding is covered by
/// transform_tolerance()) and hold at most 8 polygon vertices inline, so imaging does not
/// allocate for the shapes whose factories do not.

#include "collide/config.hpp"
#include "collide/predicates.hpp"
#include "collide/shapes.hpp"
#include "collide/transform.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

namespace collide::detail {

/// Builds shapes from values already known valid (images, exact widenings).
struct ShapeAccess {
  template <Scalar T>
  static Circle<T> circle(const Vec2<T>& c, T r) noexcept {
    return Circle<T>(Unchecked{}, c, r);
  }
  template <Scalar T>
  static Aabb<T> aabb(const Vec2<T>& lo, const Vec2<T>& hi) noexcept {
    return Aabb<T>(Unchecked{}, lo, hi);
  }
  template <Scalar T>
  static Obb<T> obb(const Vec2<T>& c, const Vec2<T>& h, const Vec2<T>& u) noexcept {
    return Obb<T>(Unchecked{}, c, h, u);
  }
  template <Scalar T>
  static Capsule<T> capsule(const Vec2<T>& a, const Vec2<T>& b, T r) noexcept {
    return Capsule<T>(Unchecked{}, a, b, r);
  }
  /// A polygon of n >= 1 vertices, vertex k = at(k) (called once for each k, in order), with its
  /// box; allocates only beyond kInline vertices.
  template <Scalar T, class At>
  static ConvexPolygon<T> polygon(std::size_t n, At&& at) {
    ConvexPolygon<T> poly;
    poly.size_ = n;
    if (n > ConvexPolygon<T>::kInline) poly.heap_.resize(n);
    Vec2<T>* out = n > ConvexPolygon<T>::kInline ? poly.heap_.data() : poly.inline_.data();
    Vec2<T> lo = at(0), hi = lo;
    out[0] = lo;
    for (std::size_t k = 1; k < n; ++k) {
      const Vec2<T> v = at(k);
      out[k] = v;
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    poly.lo_ = lo;
    poly.hi_ = hi;
    return poly;
  }
  /// Caches normal(k) as edge k's unit outward normal (a polygon of at most kInline vertices).
  template <Scalar T, class Normal>
  static void cache_normals(ConvexPolygon<T>& poly, Normal&& normal) noexcept {
    for (std::size_t k = 0; k < poly.size_; ++k) poly.normals_[k] = normal(k);
    poly.normals_cached_ = true;
  }
};

/// A defining point's image, x(v).
inline Vec2c image_point(const Pose& x, const Vec2c& v) noexcept {
  return x.apply(v);
}

/// The same shape with double values (exact: every float is a double).
template <Scalar T>
Circle<Calc> widened_shape(const Circle<T>& s) noexcept {
  return ShapeAccess::circle<Calc>(widen(s.center()), s.radius());
}
/// The same shape with double values (exact).
template <Scalar T>
Aabb<Calc> widened_shape(const Aabb<T>& s) noexcept {
  return ShapeAccess::aabb<Calc>(widen(s.min()), widen(s.max()));
}
/// The same shape with double values (exact).
template <Scalar T>
Obb<Calc> widened_shape(const Obb<T>& s) noexcept {
  return ShapeAccess::obb<Calc>(widen(s.center()), widen(s.half_extents()), widen(s.axis()));
}
/// The same shape with double values (exact).
template <Scalar T>
Capsule<Calc> widened_shape(const Capsule<T>& s) noexcept {
  return ShapeAccess::capsule<Calc>(widen(s.a()), widen(s.b()), s.radius());
}
/// The same shape with double values (exact).
template <Scalar T>
ConvexPolygon<Calc> widened_shape(const ConvexPolygon<T>& s) {
  ConvexPolygon<Calc> out = ShapeAccess::polygon<Calc>(s.size(), [&](std::size_t k) { return widen(s[k]); });
  if (const Vec2c* normals = PolygonAccess::normals(s))
    ShapeAccess::cache_normals(out, [&](std::size_t i) { return normals[i]; });
  return out;
}

/// The error bound of an image, per point (Hausdorff distance from the exact image):
/// 16 * 2^-53 * (|p|_inf + 2 L) + 2^-1070, where L is the local magnitude (see
/// transform_tolerance() in compound.hpp for the derivation).
inline Calc image_tolerance(const Pose& x, Calc local) noexcept {
  return 16 * kUnitRoundoff * (x.p.cwiseAbs().maxCoeff() + 2 * local) + 16 * kSmallestDouble;
}

/// Calls f with the image of s under x (x not the identity). The image's type is that of s,
/// except: an AABB turned by a rotation with both components non-zero is an OBB (its centre and
/// half extents computed in double), and a polygon whose rounded image no longer turns strictly
/// left at every vertex is the convex hull of the rounded vertices (a segment if rounding
/// flattened it entirely).
template <Scalar T, class F>
decltype(auto) with_image(const Circle<T>& s, const Pose& x, F&& f) {
  return f(ShapeAccess::circle<Calc>(image_point(x, widen(s.center())), s.radius()));
}
/// As for a circle: both ends mapped, radius kept.
template <Scalar T, class F>
decltype(auto) with_image(const Capsule<T>& s, const Pose& x, F&& f) {
  return f(ShapeAccess::capsule<Calc>(image_point(x, widen(s.a())), image_point(x, widen(s.b())), s.radius()));
}
/// Centre mapped, half extents kept, axis turned by R(q).
template <Scalar T, class F>
decltype(auto) with_image(const Obb<T>& s, const Pose& x, F&& f) {
  return f(
      ShapeAccess::obb<Calc>(image_point(x, widen(s.center())), widen(s.half_extents()), x.rotate(widen(s.axis()))));
}
/// Under a translation (q = (1, 0)) an AABB's image is an AABB (the mapped corners); under any
/// other rotation, quarter turns included, an OBB with axis q, whose corners keep the AABB's
/// numbering (feature.hpp: the ids name the stored box's features however it is turned). The
/// centre and half extents are exact when min + max and max - min are (float boxes always).
template <Scalar T, class F>
decltype(auto) with_image(const Aabb<T>& s, const Pose& x, F&& f) {
  const Vec2c lo = widen(s.min()), hi = widen(s.max());
  if (x.q.x() == 1 && x.q.y() == 0) {
    const Vec2c a = image_point(x, lo), b = image_point(x, hi);
    return f(ShapeAccess::aabb<Calc>(a.cwiseMin(b), b.cwiseMax(a)));
  }
  const Vec2c c = (lo + hi) * 0.5, h = (hi - lo) * 0.5;
  return f(ShapeAccess::obb<Calc>(image_point(x, c), h, x.q));
}
/// The image of a polygon that rounding made not strictly convex: the hull of its rounded
/// vertices, or nothing when they are all on one line (kept out of line: a rare path).
[[gnu::noinline]] inline std::optional<ConvexPolygon<Calc>> rounded_hull(const ConvexPolygon<Calc>& img) {
  Expected<ConvexPolygon<Calc>> hull = ConvexPolygon<Calc>::make_hull(img.vertices());
  if (!hull) return std::nullopt;
  return std::move(hull).value();
}

/// Vertices mapped; see above for the polygon that rounding made not strictly convex.
template <Scalar T, class F>
decltype(auto) with_image(const ConvexPolygon<T>& s, const Pose& x, F&& f) {
  const std::size_t n = s.size();
  const Calc local = PolygonAccess::largest_coordinate(s);
  ConvexPolygon<Calc> img = ShapeAccess::polygon<Calc>(n, [&](std::size_t k) { return image_point(x, widen(s[k])); });
  // Every mapped vertex lies within image_tolerance() of its exact image under x's own values
  // (composed or not), whose turns are all strictly left: a turn margin beyond that tolerance
  // keeps the mapped turns left without testing them.
  bool strict = PolygonAccess::turn_margin(s) > image_tolerance(x, local);
  if (!strict) {
    strict = true;
    for (std::size_t k = 0; k < n && strict; ++k)
      strict = orient(img[k], img[next_index(k, n)], img[next_index(next_index(k, n), n)]) > 0;
  }
  if (strict) {
    // The stored shape's normals turned: the exact image's edges turn by q / |q|, and this costs
    // one square root for the polygon instead of one per edge.
    if (const Vec2c* normals = PolygonAccess::normals(s)) {
      const Calc k = inverse_norm_near_unit(x.q.squaredNorm());
      const Calc c = x.q.x() * k, sn = x.q.y() * k;
      ShapeAccess::cache_normals(img, [&](std::size_t i) {
        const Calc nx = normals[i].x(), ny = normals[i].y();
        return Vec2c(c * nx - sn * ny, sn * nx + c * ny);
      });
    }
    return f(img);
  }
  if (const std::optional<ConvexPolygon<Calc>> hull = rounded_hull(img)) return f(*hull);
  // Flattened to a segment (or a point): its extreme points in lexicographic order.
  const auto less = [](const Vec2c& a, const Vec2c& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); };
  const auto [lo, hi] = std::minmax_element(img.vertices().begin(), img.vertices().end(), less);
  return f(ShapeAccess::capsule<Calc>(*lo, *hi, 0.0));
}

}  // namespace collide::detail
