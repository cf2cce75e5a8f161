#pragma once
/// @file detail/witness.hpp
/// The points behind closest_points() and signed_distance(), on convex cores in double (see
/// detail/convex_core.hpp):
///   - core_witness: the gap of two dilated cores apart and their closest core points, the gap
///     being core_gap()'s value to the bit (the same closest_points() and gap_of());
///   - surface_points: those closest points moved onto the two surfaces, facing each other;
///   - common_point: a point of two overlapping primitives;
///   - primitive_signed_distance: a point's signed distance to one primitive, with the sign of
///     the exact containment (in closed form for circles and AABBs).

#include "collide/config.hpp"
#include "collide/detail/contains_point.hpp"
#include "collide/detail/convex_core.hpp"
#include "collide/detail/math.hpp"
#include "collide/predicates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace collide::detail {

/// Two dilated cores that do not overlap: their gap (core_gap()'s value) and the closest points
/// of their cores.
struct CoreWitness {
  Calc gap = std::numeric_limits<Calc>::infinity();
  Vec2c on_p = Vec2c::Zero();  ///< closest point of the first core
  Vec2c on_q = Vec2c::Zero();  ///< closest point of the second core
};

/// v times 2^k, coordinate by coordinate (exact unless the result leaves the normal range).
inline Vec2c scaled_point(const Vec2c& v, int k) noexcept {
  return {std::ldexp(v.x(), k), std::ldexp(v.y(), k)};
}

/// The gap and closest points of two cores apart, rescaled when tiny as core_gap() is, so that the
/// gap is core_gap(p, q) to the bit.
inline CoreWitness core_witness(const Core& p, const Core& q) {
  const int k = tiny_scale(p, q);
  if (k == 0) {
    const Closest c = closest_points(p, q);
    return {gap_of(c, p, q), c.on_p, c.on_q};
  }
  const Core ps = scaled(p, k), qs = scaled(q, k);
  const Closest c = closest_points(ps, qs);
  return {std::ldexp(gap_of(c, ps, qs), -k), scaled_point(c.on_p, -k), scaled_point(c.on_q, -k)};
}

/// One point on each of two shapes.
struct PointPair {
  Vec2c a = Vec2c::Zero();
  Vec2c b = Vec2c::Zero();
};

/// The surface points of two dilated cores apart: each closest core point moved by its radius
/// toward the other core. Where the closest points coincide (cores apart by less than their
/// rounding) there is no direction, and the points stay on the cores. Then |a - b| is the gap
/// as computed, up to one rounding per coordinate.
inline PointPair surface_points(const CoreWitness& w, Calc ra, Calc rb) noexcept {
  const Vec2c n = unit_of(Vec2c(w.on_q - w.on_p));
  return {w.on_p + n * ra, w.on_q - n * rb};
}

/// The closed point set of the core holds v (exact: equality, orient() and comparisons).
inline bool core_holds(const Core& c, const Vec2c& v) noexcept {
  if (c.size() == 1) return c[0] == v;
  if (c.size() == 2) return point_on_segment(v, c[0], c[1]);
  return point_in_polygon(v, c.pts());
}

/// Calls f(start, end) for each edge of a core: a segment's one, a polygon's n, a point's none.
template <class F>
void for_each_edge(const Core& c, F&& f) {
  const std::size_t n = c.size();
  if (n < 2) return;
  if (n == 2) {
    f(c[0], c[1]);
    return;
  }
  for (std::size_t i = 0; i < n; ++i) f(c[i], c[next_index(i, n)]);
}

/// The exponent that brings the largest component of v to [1/2, 1) (0 for the zero vector).
inline int exponent_of(const Vec2c& v) noexcept {
  int e = 0;
  static_cast<void>(std::frexp(v.cwiseAbs().maxCoeff(), &e));
  return e;
}

/// Where the segment [a, b] crosses [c, d] (segments that cross, not collinear): a + (b - a) t
/// with t = cross(c - a, d - c) / cross(b - a, d - c) clamped to [0, 1], so that the point stays
/// on [a, b] whatever the rounding of t. The quotient is taken on the edges scaled by powers of
/// two, d - c to magnitude 1 and b - a with c - a to magnitude 1 (t is the same: each scale
/// divides out): unscaled, an edge 1e-130 long crossing one 1e-310 long has a cross product that
/// underflows to 0, and t would lose every bit.
inline Vec2c crossing_point(const Vec2c& a, const Vec2c& b, const Vec2c& c, const Vec2c& d) noexcept {
  const Vec2c e = b - a, f = d - c, g = c - a;
  const int ke = -exponent_of(Vec2c(e.cwiseAbs().cwiseMax(g.cwiseAbs()))), kf = -exponent_of(f);
  const Vec2c es = scaled_point(e, ke), gs = scaled_point(g, ke), fs = scaled_point(f, kf);
  const Calc den = cross(es, fs), t = cross(gs, fs) / den;
  return a + e * (den != 0 && std::isfinite(t) ? std::clamp(t, Calc(0), Calc(1)) : Calc(0));
}

/// A point of both cores, or nullopt when the cores do not meet (decided exactly, as
/// cores_intersect() decides it: two convex sets meet exactly when a vertex of one lies in the
/// other or their boundaries cross):
///   1. a vertex of p that q holds, else a vertex of q that p holds;
///   2. else the crossing point of the first pair of edges that meet. Edges lying along each other
///      have an end in the other core, found in step 1.
inline std::optional<Vec2c> point_of_both_cores(const Core& p, const Core& q) {
  for (const Vec2c& v : p.pts()) {
    if (core_holds(q, v)) return v;
  }
  for (const Vec2c& v : q.pts()) {
    if (core_holds(p, v)) return v;
  }
  std::optional<Vec2c> crossing;
  for_each_edge(p, [&](const Vec2c& a, const Vec2c& b) {
    for_each_edge(q, [&](const Vec2c& c, const Vec2c& d) {
      if (!crossing && segments_intersect(a, b, c, d)) crossing = crossing_point(a, b, c, d);
    });
  });
  return crossing;
}

/// A point of two primitives that overlap (decided exactly, decide_primitives()): in both cores
/// when they meet (point_of_both_cores()); otherwise only the radii meet, and the point divides
/// the segment between the cores' closest points in the ratio of the radii, so that it lies within
/// each radius of its core (the point where they touch, when they just touch).
template <class A, class B>
Vec2c common_point(const A& a, const B& b) {
  const Core p = core_of(a), q = core_of(b);
  if (const std::optional<Vec2c> both = point_of_both_cores(p, q)) return *both;
  const CoreWitness w = core_witness(p, q);
  const Calc r = p.radius + q.radius;
  if (!(r > 0)) return (w.on_p + w.on_q) * 0.5;  // sharp cores apart only by rounding
  return w.on_p + (w.on_q - w.on_p) * (p.radius / r);
}

/// Distance from v to the core c, its radius left out (for v inside a polygon core: to its
/// boundary). The closest points of c and the point v, rescaled by a power of two where the
/// squares would underflow (tiny cores, as core_gap()) or overflow (a point beyond 2^500).
inline Calc core_point_distance(const Core& c, const Vec2c& v) {
  Core point;
  point.push(v);
  const Calc m = std::max(max_abs(c), v.cwiseAbs().maxCoeff());
  int k = tiny_scale(c, point);
  if (m > kPlainNormHigh) {
    int e = 0;
    static_cast<void>(std::frexp(m, &e));
    k = -e;
  }
  if (k == 0) return std::sqrt(closest_points(c, point).dist2);
  return std::ldexp(std::sqrt(closest_points(scaled(c, k), scaled(point, k)).dist2), -k);
}

/// A signed distance s of v to x, computed in double with an error below `bound`, given the sign
/// of the exact containment (contains_concrete()): where s lies within the bound of 0 the exact
/// containment decides, 0 for a point x holds and the least positive double for one it does not.
/// Beyond the bound the sign is already the exact one.
template <class S>
Calc with_exact_sign(const S& x, const Vec2c& v, Calc s, Calc bound) {
  if (!(std::fabs(s) > bound)) {
    const bool in = contains_concrete(x, v);
    if (in && s > 0) s = 0;
    if (!in && !(s > 0)) s = kSmallestDouble;
  }
  return s == 0 ? Calc(0) : s;  // 0, not -0, on the boundary
}

/// The error bound of a signed distance computed at magnitude m (the larger of the shape's and
/// the point's coordinates): the rounding unit of the pair queries, far above the few roundings
/// the distance takes.
inline Calc signed_distance_bound(Calc m) noexcept {
  return kOverlapErrorFactor * kUnitRoundoff * m + kAbsoluteFloor;
}

/// The signed distance from v (finite) to the primitive x, stored or imaged: the distance to its
/// boundary, negative inside, with the sign of the exact containment:
///   1. the distance to the core, less the radius; minus the distance to the core's boundary for
///      v inside a polygon core (orient(), exact on the core);
///   2. its sign made exact where it lies within the error bound of 0 (an OBB's rounded corners,
///      the square root): with_exact_sign().
template <class S>
Calc primitive_signed_distance(const S& x, const Vec2c& v) {
  const Core c = core_of(x);
  const Calc g = core_point_distance(c, v);
  const bool in_core = c.size() >= 3 && point_in_polygon(v, c.pts());
  const Calc s = in_core ? -g : g - c.radius;
  return with_exact_sign(x, v, s, signed_distance_bound(std::max(max_abs(c), v.cwiseAbs().maxCoeff())));
}

/// A circle's signed distance in closed form, |v - centre| - radius (norm_of() keeps tiny and
/// huge offsets from underflowing or overflowing), its sign made exact by with_exact_sign().
template <Scalar T>
Calc primitive_signed_distance(const Circle<T>& circle, const Vec2c& v) {
  const Vec2c c = widen(circle.center());
  const Calc r = circle.radius();
  const Calc m = std::max({c.cwiseAbs().maxCoeff(), r, v.cwiseAbs().maxCoeff()});
  return with_exact_sign(circle, v, norm_of(Vec2c(v - c)) - r, signed_distance_bound(m));
}

/// An AABB's signed distance in closed form, its sign exactly contains()'s: outside, the length of
/// the point's excess over the box per axis (a point outside has a positive excess on some axis,
/// since a difference of two distinct doubles is never 0); inside, minus the distance to the
/// nearest side.
template <Scalar T>
Calc primitive_signed_distance(const Aabb<T>& box, const Vec2c& v) {
  const Vec2c lo = widen(box.min()), hi = widen(box.max());
  const Vec2c excess = Vec2c(lo - v).cwiseMax(Vec2c(v - hi)).cwiseMax(Vec2c::Zero());
  if (excess.x() > 0 || excess.y() > 0) return norm_of(excess);
  const Calc depth = std::min({v.x() - lo.x(), hi.x() - v.x(), v.y() - lo.y(), hi.y() - v.y()});
  return depth == 0 ? Calc(0) : -depth;
}

}  // namespace collide::detail
