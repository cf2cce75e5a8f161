#pragma once
/// @file detail/image.hpp
/// The world image of a primitive stored in a local frame: its defining points mapped by a pose
/// and rounded to double, its radii and half extents kept, an OBB's axis turned. Images are built
/// without validation (the exact image of a valid shape is valid; rounding is covered by
/// transform_tolerance()) and hold at most 8 polygon vertices inline, so imaging does not
/// allocate for the shapes whose factories do not.

#include "collide/config.hpp"
#include "collide/feature.hpp"
#include "collide/predicates.hpp"
#include "collide/shapes.hpp"
#include "collide/transform.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

namespace collide::detail {

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
/// vertices, or nothing when they are all on one line (kept out of line: a rare path). Not
/// validated, as every image: a vertex may lie beyond max_magnitude() by the placement.
[[gnu::noinline]] inline std::optional<ConvexPolygon<Calc>> rounded_hull(const ConvexPolygon<Calc>& img) {
  std::size_t distinct = 0;
  const HullPoints<Calc> h = hull_points(img.vertices(), distinct);
  if (h.size() < 3) return std::nullopt;
  return ShapeAccess::polygon<Calc>(h.size(), [&](std::size_t k) { return h[k]; });
}

/// The vertices of s mapped by x, in s's order (no normals cached).
template <Scalar T>
ConvexPolygon<Calc> mapped_polygon(const ConvexPolygon<T>& s, const Pose& x) {
  return ShapeAccess::polygon<Calc>(s.size(), [&](std::size_t k) { return image_point(x, widen(s[k])); });
}

/// Whether s's turn margin alone shows that its vertices mapped by x still turn strictly left:
/// every mapped vertex lies within image_tolerance() of its exact image under x's own values
/// (composed or not), whose turns are all strictly left, so a margin beyond that tolerance keeps
/// the mapped turns left without testing them.
template <Scalar T>
bool turns_survive_rounding(const ConvexPolygon<T>& s, const Pose& x) noexcept {
  return PolygonAccess::turn_margin(s) > image_tolerance(x, PolygonAccess::largest_coordinate(s));
}

/// Whether img = mapped_polygon(s, x) still turns strictly left at every vertex (with_image()
/// then uses it as is).
template <Scalar T>
bool mapped_is_strict(const ConvexPolygon<T>& s, const Pose& x, const ConvexPolygon<Calc>& img) noexcept {
  if (turns_survive_rounding(s, x)) return true;
  const std::size_t n = img.size();
  for (std::size_t k = 0; k < n; ++k)
    if (!(orient(img[k], img[next_index(k, n)], img[next_index(next_index(k, n), n)]) > 0)) return false;
  return true;
}

/// The segment a polygon flattened by rounding is imaged as: its extreme mapped vertices in
/// lexicographic order.
inline Capsule<Calc> flattened_segment(const ConvexPolygon<Calc>& img) noexcept {
  const auto less = [](const Vec2c& a, const Vec2c& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); };
  const auto [lo, hi] = std::minmax_element(img.vertices().begin(), img.vertices().end(), less);
  return ShapeAccess::capsule<Calc>(*lo, *hi, 0.0);
}

/// Vertices mapped; see above for the polygon that rounding made not strictly convex.
template <Scalar T, class F>
decltype(auto) with_image(const ConvexPolygon<T>& s, const Pose& x, F&& f) {
  ConvexPolygon<Calc> img = mapped_polygon(s, x);
  if (mapped_is_strict(s, x, img)) {
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
  return f(flattened_segment(img));
}

/// The index of the first mapped vertex at v (a vertex of the hull or segment made of img).
inline std::size_t mapped_index(const ConvexPolygon<Calc>& img, const Vec2c& v) noexcept {
  std::size_t k = 0;
  while (k + 1 < img.size() && img[k] != v) ++k;
  return k;
}

/// Distances to the mapped edges of a polygon image, with coordinates scaled by a power of two
/// first, so that squares neither overflow nor vanish.
struct MappedEdges {
  const ConvexPolygon<Calc>& img;
  Vec2c v;    ///< the point, scaled
  Calc unit;  ///< the scale

  MappedEdges(const ConvexPolygon<Calc>& image, const Vec2c& p) noexcept : img(image) {
    const Calc big = std::max(PolygonAccess::largest_coordinate(img), p.cwiseAbs().maxCoeff());
    unit = big > 0 && std::isfinite(big) ? std::ldexp(1.0, -std::ilogb(big)) : 1.0;
    v = p * unit;
  }
  /// Edge i's start and direction, scaled.
  std::pair<Vec2c, Vec2c> edge(std::size_t i) const noexcept {
    const Vec2c a = img[i] * unit;
    return {a, img[next_index(i, img.size())] * unit - a};
  }
  /// The squared distance from the point to edge i (scaled).
  Calc squared_distance(std::size_t i) const noexcept {
    const auto [a, d] = edge(i);
    const Calc dd = d.squaredNorm();
    const Calc t = dd > 0 ? std::clamp((v - a).dot(d) / dd, Calc(0), Calc(1)) : Calc(0);
    return squared_distance_to_segment(v, a, d, dd, t);
  }
  /// Of the edges first, ..., first + count - 1 (mod n), the one nearest the point; of edges
  /// equally near (a polygon flattened onto one line), the one facing most along `toward`.
  std::size_t nearest_edge(const Vec2c& toward, std::size_t first, std::size_t count) const noexcept {
    const std::size_t n = img.size();
    std::size_t best = first % n;
    Calc best_d2 = std::numeric_limits<Calc>::infinity(), best_facing = 0;
    for (std::size_t j = 0; j < count; ++j) {
      const std::size_t i = (first + j) % n;
      const Calc d2 = squared_distance(i);
      const auto [a, d] = edge(i);
      const Calc facing = (d.y() * toward.x() - d.x() * toward.y()) / d.norm();  // outward normal . toward
      if (d2 < best_d2 || (d2 == best_d2 && facing > best_facing)) {
        best_d2 = d2;
        best_facing = facing;
        best = i;
      }
    }
    return best;
  }
  /// Vertex `at`, or of the vertices first, ..., first + count - 1 (mod n) that `candidate`
  /// accepts, one whose edges (the two that meet there, which a vertex feature spans) lie strictly
  /// nearer the point.
  template <class Candidate>
  std::size_t nearest_vertex(std::size_t at, std::size_t first, std::size_t count,
                             Candidate&& candidate) const noexcept {
    const std::size_t n = img.size();
    const auto reach = [&](std::size_t k) { return std::min(squared_distance(k), squared_distance((k + n - 1) % n)); };
    std::size_t best = at;
    Calc best_d2 = reach(at);
    for (std::size_t j = 0; j < count; ++j) {
      const std::size_t k = (first + j) % n;
      if (!candidate(k)) continue;
      if (const Calc d2 = reach(k); d2 < best_d2) {
        best_d2 = d2;
        best = k;
      }
    }
    return best;
  }
  std::size_t nearest_vertex(std::size_t at, std::size_t first, std::size_t count) const noexcept {
    return nearest_vertex(at, first, count, [](std::size_t) { return true; });
  }
  /// Whether mapped vertex k lies strictly nearer `end` than `other` (scaled, so no square
  /// overflows).
  bool nearer(std::size_t k, const Vec2c& end, const Vec2c& other) const noexcept {
    const Vec2c p = img[k] * unit;
    return (p - end * unit).squaredNorm() < (p - other * unit).squaredNorm();
  }
};

/// Renames the features of one side of c (side_b: b's, else a's), a contact computed on
/// with_image(s, x)'s image, as s's own (feature.hpp numbers a polygon by its stored vertices). Only
/// the hull or segment that replaces an image rounding made not strictly convex numbers them its
/// own way. An edge of it becomes the stored edge nearest that side's surface point among those it
/// covers (several when rounding merged them). A vertex becomes the stored vertex mapped there, or
/// one merged into it or dropped beside it whose edges lie nearer the point: an incident vertex
/// clipped back along the hull's edge keeps its id, and its point lies on that edge.
template <Scalar T, class C>
void name_stored_features(const ConvexPolygon<T>& s, const Pose& x, C& c, bool side_b) {
  if (turns_survive_rounding(s, x)) [[likely]]
    return;
  const ConvexPolygon<Calc> img = mapped_polygon(s, x);
  if (mapped_is_strict(s, x, img)) return;
  const std::size_t n = img.size();
  const std::optional<ConvexPolygon<Calc>> hull = rounded_hull(img);
  // The stored vertices from `from` up to `to` (mod n), `to` excluded.
  const auto span = [n](std::size_t from, std::size_t to) { return to > from ? to - from : to + n - from; };
  for (int i = 0; i < c.count; ++i) {
    FeatureId& id = c.ids[std::size_t(i)];
    std::uint8_t& index = side_b ? id.index_b : id.index_a;
    const FeatureKind kind = side_b ? id.kind_b : id.kind_a;
    // The side's surface point: the contact point is midway between the surfaces.
    const Vec2c mid = widen(c.points[std::size_t(i)]), normal = widen(c.normal);
    const MappedEdges edges(img, mid + normal * (Calc(c.separations[std::size_t(i)]) / (side_b ? 2 : -2)));
    const Vec2c facing = side_b ? Vec2c(-normal) : normal;  // the way this side's surface faces
    std::size_t stored = 0;
    if (hull) {
      const std::size_t m = hull->size(), j = index % m;
      const std::size_t at = mapped_index(img, (*hull)[j]);
      const std::size_t after = mapped_index(img, (*hull)[next_index(j, m)]);
      if (kind == FeatureKind::Vertex) {
        const std::size_t before = mapped_index(img, (*hull)[(j + m - 1) % m]);
        stored = edges.nearest_vertex(at, next_index(before, n), span(before, after) - 1);
      } else {
        stored = edges.nearest_edge(facing, at, span(at, after));
      }
    } else {
      const Capsule<Calc> segment = flattened_segment(img);
      if (kind == FeatureKind::Vertex) {
        // Of the stored vertices, those at this end or dropped nearer it: one at the other end
        // names the other end's point, and a contact's two points are two features.
        const Vec2c& end = index == 0 ? segment.a() : segment.b();
        const Vec2c& other = index == 0 ? segment.b() : segment.a();
        stored = edges.nearest_vertex(mapped_index(img, end), 0, n,
                                      [&](std::size_t k) { return edges.nearer(k, end, other); });
      } else {
        stored = edges.nearest_edge(facing, 0, n);
      }
    }
    index = static_cast<std::uint8_t>(stored);
  }
}

}  // namespace collide::detail
