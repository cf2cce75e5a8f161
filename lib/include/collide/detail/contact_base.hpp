#pragma once
/// @file detail/contact_base.hpp
/// What every specialised contact pair shares: a core with its known face normals (Hull), the
/// rounding band of a filtered signed distance and the exact decision asked inside it, the rough
/// boxes that tell pairs apart early, the generic path on cores (contact_of_cores(),
/// contact_generic()), a box as a centre, axis and half extents (Rect), and the kind traits of
/// the dispatch.

#include "collide/decide.hpp"
#include "collide/detail/contact_cores.hpp"
#include "collide/detail/convex_core.hpp"
#include "collide/shape_traits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

namespace collide::detail {

/// A core with the unit outward normal of each face when known without a square root per face.
/// Box normals come from the stored axes (exact up to one rounding), not from the rounded corners;
/// a capsule's two sides share one square root; a polygon's are those it cached (at construction,
/// or its stored polygon's turned, for an image). Without them the core's own faces are computed
/// when asked (most pairs apart stop at the first face).
struct Hull {
  Core core;
  std::array<Vec2c, 4> own_normals;
  const Vec2c* cached = nullptr;  ///< the polygon's cached normals, if any
  bool own = false;               ///< own_normals holds the faces' normals
  Calc scale = 0;                 ///< the largest absolute coordinate of the core
  /// Pushes the points and sets scale.
  template <class Points>
  void push_all(const Points& xs) {
    Calc m = 0;
    for (const auto& x : xs) m = std::max(m, widen(x).cwiseAbs().maxCoeff());
    core.push_each(xs);
    scale = m;
  }
  /// Every face's normal when known (a box, a capsule, a polygon's cache), else nullptr.
  const Vec2c* normals() const noexcept { return own ? own_normals.data() : cached; }
};

/// The error bound of a filtered signed distance (a face depth, a closest distance) of shapes at
/// scale s: every value entering it carries a few roundings of s (corners, differences, dots),
/// below 32 units; 64 are used.
inline Calc band_of(Calc s) noexcept {
  return kOverlapErrorFactor * kUnitRoundoff * s;
}

/// A box around a box or polygon, in double: exact for an AABB and a polygon, within a few
/// roundings of its largest coordinate for an OBB (its extents computed from the axis).
struct RoughBox {
  Vec2c lo, hi;
};
template <Scalar T>
RoughBox rough_box(const Aabb<T>& s) noexcept {
  return {widen(s.min()), widen(s.max())};
}
template <Scalar T>
RoughBox rough_box(const Obb<T>& s) noexcept {
  const Vec2c c = widen(s.center()), u = widen(s.axis()).cwiseAbs();
  const Calc hx = s.half_extents().x(), hy = s.half_extents().y();
  const Vec2c ext(u.x() * hx + u.y() * hy, u.y() * hx + u.x() * hy);
  return {c - ext, c + ext};
}
template <Scalar T>
RoughBox rough_box(const ConvexPolygon<T>& s) noexcept {
  const auto [lo, hi] = PolygonAccess::box(s);
  return {widen(lo), widen(hi)};
}

/// Whether the rough boxes of a and b are apart by more than the speculative distance plus the
/// band of their scale along an axis (an axis gap is at most the distance): then so are a and b,
/// and no contact exists. False for tiny pairs, whose roundings underflow.
template <class A, class B>
bool apart_by_boxes(const A& a, const B& b, Calc speculative) noexcept {
  const RoughBox p = rough_box(a), q = rough_box(b);
  const Calc scale = std::max(
      {p.lo.cwiseAbs().maxCoeff(), p.hi.cwiseAbs().maxCoeff(), q.lo.cwiseAbs().maxCoeff(), q.hi.cwiseAbs().maxCoeff()});
  const Calc reach = band_of(scale) + std::max(speculative, Calc(0));
  return scale >= kTinyCore && (((q.lo - p.hi).array() > reach).any() || ((p.lo - q.hi).array() > reach).any());
}

/// Builds h from a box whose core is a proper rectangle; false for a box flat on an axis.
template <Scalar T>
bool hull_of(const Aabb<T>& s, Hull& h) {
  if (!(s.min().x() < s.max().x() && s.min().y() < s.max().y())) return false;
  const Vec2c lo = widen(s.min()), hi = widen(s.max());
  h.push_all(std::array<Vec2c, 4>{lo, Vec2c(hi.x(), lo.y()), hi, Vec2c(lo.x(), hi.y())});
  h.own_normals = {Vec2c(0, -1), Vec2c(1, 0), Vec2c(0, 1), Vec2c(-1, 0)};
  h.own = true;
  return true;
}

/// Builds h from an oriented box whose four computed corners turn strictly left (core_of keeps
/// them); false for boxes flat on an axis or thinner than their corners' rounding.
template <Scalar T>
bool hull_of(const Obb<T>& s, Hull& h) {
  const Calc hmin = std::min(Calc(s.half_extents().x()), Calc(s.half_extents().y()));
  const Calc hmax = std::max(Calc(s.half_extents().x()), Calc(s.half_extents().y()));
  const Vec2c c = widen(s.center()), w = widen(s.axis());
  if (!(hmin > kThinBoxRatio * (c.cwiseAbs().maxCoeff() + hmax) && hmin > kUnderflowMargin)) return false;
  // The corners as core_of() computes them (it keeps them in this order for such a box).
  const Vec2c ex = w * Calc(s.half_extents().x()), ey = perp(w) * Calc(s.half_extents().y());
  h.push_all(std::array<Vec2c, 4>{c - ex - ey, c + ex - ey, c + ex + ey, c - ex + ey});
  const Calc ww = w.squaredNorm();  // within a few eps_T of 1
  const Vec2c u = w * inverse_norm_near_unit(ww), v = perp(u);
  h.own_normals = {Vec2c(-v), u, v, Vec2c(-u)};
  h.own = true;
  return true;
}

/// Builds h from a polygon of at most 8 vertices (the rest take the generic path).
template <Scalar T>
bool hull_of(const ConvexPolygon<T>& s, Hull& h) {
  if (s.size() > ConvexPolygon<T>::kInline) return false;
  h.core.push_each(s.vertices());
  h.scale = PolygonAccess::largest_coordinate(s);
  h.cached = PolygonAccess::normals(s);
  return true;
}

/// Builds h from a capsule whose ends differ: its sides as faces 0 and 1, as for_each_face()
/// numbers a segment's.
template <Scalar T>
bool hull_of(const Capsule<T>& s, Hull& h) {
  if (s.b() == s.a()) return false;
  // The ends are kept in registers: read back from the core, they would wait on its stores.
  const Vec2c a = widen(s.a()), b = widen(s.b()), d = b - a;
  h.push_all(std::array<Vec2c, 2>{a, b});
  h.core.radius = s.radius();
  const Vec2c n = unit_of(Vec2c(d.y(), -d.x()));
  h.own_normals[0] = n;
  h.own_normals[1] = -n;
  h.own = true;
  return true;
}

/// Calls f(normal, index) for each face of a core: its known normals, else its own (for_each_face).
inline auto faces_of(const Core& c, const Vec2c* normals) {
  return [&c, normals](auto&& f) {
    if (normals) {
      for (std::size_t i = 0; i < c.size(); ++i) f(normals[i], unsigned(i));
    } else {
      for_each_face(c, f);
    }
  };
}
/// Calls f(normal, index) for each face of a hull.
inline auto faces_of(const Hull& h) {
  return faces_of(h.core, h.normals());
}

/// The exact decision for a pair of primitives in registry order.
template <class A, class B>
bool decide_exactly(const A& a, const B& b) {
  return decide::pair(a, b);
}

/// The contact of two primitives without a specialisation, as contact_cores() computes it. The
/// rounded cores (within a few roundings of the scale of the exact ones) decide when clear of the
/// band: cores penetrating deeper than it along the least-penetration axis, or meeting under radii
/// wider than it, overlap; cores apart by a gap beyond it do not (each with the exact cores within
/// the band of the rounded ones). Otherwise, and for tiny pairs, the exact decision.
/// p and q: the cores of a and b; np and nq: their faces' normals when known, else nullptr;
/// points: point_scale(p, q).
template <class A, class B, class Search>
[[gnu::always_inline]] inline std::optional<CoreContact> contact_of_cores(const A& a, const B& b, const Core& p,
                                                                          const Vec2c* np, const Core& q,
                                                                          const Vec2c* nq, Calc points,
                                                                          Calc speculative, Search&& search) {
  const bool radius_free = !std::is_same_v<A, Circle<scalar_of_t<A>>> && !std::is_same_v<A, Capsule<scalar_of_t<A>>> &&
                           !std::is_same_v<B, Capsule<scalar_of_t<A>>>;
  const Calc radii = p.radius + q.radius, scale = std::max(points, radii);
  const auto speculative_or_none = [&]() -> std::optional<CoreContact> {
    return speculative > 0 ? speculative_contact_cores(p, q, speculative) : std::nullopt;
  };
  const Calc largest = std::max({points, p.radius, q.radius});  // tiny_scale(p, q) != 0: nonzero, below kTinyCore
  if (!(scale >= kTinyCore) || (largest < kTinyCore && largest != 0)) {
    if (decide_exactly(a, b)) return contact_cores(p, q, speculative, radius_free);
    return speculative_or_none();
  }
  const Calc band = band_of(scale), tie = tie_of(points);  // owner_tie(p, q)
  // With a polygon, the least penetration over the faces tells cores clearly apart or clearly
  // meeting at once, and a face separating them by more than the band ends the search; a point
  // or a segment against a point or a segment has no such faces, and their test is cheap.
  const bool polygon = std::max(p.size(), q.size()) > 2;
  const auto axis = [&](Calc stop_below) { return search(tie, stop_below); };
  const auto contact_on = [&](const Axis& found) { return contact_from_axis(p, q, found, speculative, np, nq); };
  const Axis ax = polygon ? axis(radii - band) : Axis{};
  const Calc core_depth = ax.depth - radii;  // within 2 ties and the slack of the cores' least penetration
  const bool deep = polygon && core_depth > band + 2 * tie + ax.slack;
  if (deep || (!(polygon && core_depth < -band) && cores_intersect(p, q))) {
    if (!(deep || radii > band || decide_exactly(a, b))) return speculative_or_none();
    return contact_on(polygon ? ax : axis(-std::numeric_limits<Calc>::infinity()));
  }
  // A face separating the shapes themselves by more than the band and the speculative distance.
  if (polygon && ax.depth < -band - std::max(speculative, Calc(0))) return std::nullopt;
  // Cores clearly apart along a face with the other core's nearest vertex over it: the face's
  // separation is the cores' distance, and the face is the reference face, without the closest
  // points (a capsule resting on a box).
  if (!radius_free && polygon && core_depth < -band && ax.owner >= 0 &&
      nearest_vertex_over_face(find_reference_face(p, q, ax))) {
    if (!(ax.depth > band || (!(ax.depth < -band) && decide_exactly(a, b)))) return speculative_or_none();
    return contact_on(ax);
  }
  const Closest cl = closest_points(p, q);
  const Calc gap = std::sqrt(cl.dist2) - radii;
  if (!(gap < -band || (!(gap > band) && decide_exactly(a, b)))) return speculative_or_none();
  if (!radius_free) {
    if (const std::optional<CoreContact> c = contact_from_closest(p, q, cl, speculative, np, nq)) return c;
  }
  return contact_on(axis(-std::numeric_limits<Calc>::infinity()));
}

/// contact_of_cores() with the least-penetration axis over both cores' faces (least_penetration_with()).
template <class A, class B>
std::optional<CoreContact> contact_of_cores(const A& a, const B& b, const Core& p, const Vec2c* np, const Core& q,
                                            const Vec2c* nq, Calc points, Calc speculative, Rounding rounding) {
  return contact_of_cores(a, b, p, np, q, nq, points, speculative, [&](Calc tie, Calc stop_below) {
    return least_penetration_with(p, faces_of(p, np), q, faces_of(q, nq), tie, stop_below, rounding);
  });
}

/// The contact of two primitives without a specialisation (contact_of_cores() on their cores).
template <class A, class B>
std::optional<CoreContact> contact_generic(const A& a, const B& b, Calc speculative, Rounding rounding = {}) {
  const Core p = core_of(a), q = core_of(b);
  return contact_of_cores(a, b, p, nullptr, q, nullptr, point_scale(p, q), speculative, rounding);
}

/// A box as a centre c, a stored axis w (|w| = 1 up to T's rounding) and half extents along w and
/// perp(w): the point set c + s w + t perp(w), |s| <= hx, |t| <= hy.
struct Rect {
  Vec2c c, w;
  Calc hx, hy;
};
/// The Rect of a box.
template <Scalar T>
Rect rect_of(const Aabb<T>& s) noexcept {
  const Vec2c lo = widen(s.min()), hi = widen(s.max()), h = (hi - lo) * 0.5;
  return {(lo + hi) * 0.5, Vec2c(1, 0), h.x(), h.y()};
}
template <Scalar T>
Rect rect_of(const Obb<T>& s) noexcept {
  return {widen(s.center()), widen(s.axis()), Calc(s.half_extents().x()), Calc(s.half_extents().y())};
}
/// A box's half-lengths along its unit axes u and perp(u) (u: its hull's normal 1), h_x |w| and
/// h_y |w|: w . u = |w|.
struct HalfLengths {
  Calc x, y;
};
inline HalfLengths half_lengths(const Rect& k, const Vec2c& u) noexcept {
  const Calc len = k.w.dot(u);
  return {k.hx * len, k.hy * len};
}
/// Whether a box (k its rect_of()) is proper: it has an interior and its corners keep their order
/// when computed (see hull_of).
template <Scalar T>
bool is_proper(const Aabb<T>& s, const Rect&) noexcept {
  return s.min().x() < s.max().x() && s.min().y() < s.max().y();
}
template <Scalar T>
bool is_proper(const Obb<T>&, const Rect& k) noexcept {
  const Calc hmin = std::min(k.hx, k.hy), hmax = std::max(k.hx, k.hy);
  return hmin > kThinBoxRatio * (k.c.cwiseAbs().maxCoeff() + hmax) && hmin > kUnderflowMargin;
}

template <class S>
inline constexpr bool is_box_v = std::is_same_v<S, Aabb<scalar_of_t<S>>> || std::is_same_v<S, Obb<scalar_of_t<S>>>;

template <class S>
inline constexpr bool is_capsule_v = std::is_same_v<S, Capsule<scalar_of_t<S>>>;
template <class S>
inline constexpr bool is_hull_kind_v =
    std::is_same_v<S, Aabb<scalar_of_t<S>>> || std::is_same_v<S, Obb<scalar_of_t<S>>> ||
    std::is_same_v<S, ConvexPolygon<scalar_of_t<S>>>;

}  // namespace collide::detail
