#pragma once
/// @file detail/exact_signs.hpp
/// The exact signs behind decide.hpp's pair functions: OBB corners kept as polynomials of the
/// stored values, the radii of dilated shapes, and the filtered signs (a floating-point filter
/// with a proven error bound, then exact arithmetic) of distances between points, segments, boxes
/// and cores.

#include "collide/detail/convex_core.hpp"
#include "collide/predicates.hpp"
#include "collide/shapes.hpp"

namespace collide {

namespace detail {

// ---------------------------------------------------------------------------------------------
// Points whose coordinates are polynomials of the stored values.

/// A corner c + s hx u + t hy perp(u) of an OBB (s, t = +-1), kept unevaluated.
struct ObbCorner {
  Vec2c c, u;
  Calc shx, thy;  ///< s hx and t hy (exact: a sign change)
};

/// p - a in number type N.
template <class N>
std::array<N, 2> offset(const Vec2c& p, const Vec2c& a) noexcept {
  return {N(p.x()) - N(a.x()), N(p.y()) - N(a.y())};
}
template <class N>
std::array<N, 2> offset(const ObbCorner& p, const Vec2c& a) noexcept {
  const N sx(p.shx), ty(p.thy), ux(p.u.x()), uy(p.u.y());
  return {N(p.c.x()) + sx * ux - ty * uy - N(a.x()), N(p.c.y()) + sx * uy + ty * ux - N(a.y())};
}

/// An OBB's stored values, in the computation type.
struct ObbValues {
  Vec2c c, u;
  Calc hx, hy;
  std::array<ObbCorner, 4> corners() const noexcept {
    return {ObbCorner{c, u, -hx, -hy}, ObbCorner{c, u, hx, -hy}, ObbCorner{c, u, hx, hy}, ObbCorner{c, u, -hx, hy}};
  }
};
template <Scalar T>
ObbValues values_of(const Obb<T>& o) noexcept {
  return {widen(o.center()), widen(o.axis()), Calc(o.half_extents().x()), Calc(o.half_extents().y())};
}

/// The summed radius of a pair, kept as its two terms: their rounded sum would not be exact.
struct Radii {
  Calc a = 0, b = 0;
  template <class N>
  N value() const noexcept {
    return N(a) + N(b);
  }
};

// ---------------------------------------------------------------------------------------------
// Exact signs on such points.

/// sign of |p - a|^2 - r^2
template <class P>
int sign_dist2_minus(const P& p, const Vec2c& a, const Radii& r) noexcept {
  return exact_sign([&](auto tag) {
    using N = decltype(tag);
    const auto [dx, dy] = offset<N>(p, a);
    const N rr = r.template value<N>();
    return dx * dx + dy * dy - rr * rr;
  });
}

/// sign of (p - a) . (b - a)
template <class P>
int sign_dot(const P& p, const Vec2c& a, const Vec2c& b) noexcept {
  return exact_sign([&](auto tag) {
    using N = decltype(tag);
    const auto [wx, wy] = offset<N>(p, a);
    const auto [ex, ey] = offset<N>(b, a);
    return wx * ex + wy * ey;
  });
}

/// sign of cross(b - a, p - a): the turn a -> b -> p (orient() for an unevaluated p).
template <class P>
int sign_turn(const Vec2c& a, const Vec2c& b, const P& p) noexcept {
  return exact_sign([&](auto tag) {
    using N = decltype(tag);
    const auto [wx, wy] = offset<N>(p, a);
    const auto [ex, ey] = offset<N>(b, a);
    return ex * wy - ey * wx;
  });
}

/// sign of cross(b - a, p - a)^2 - r^2 |b - a|^2: p's line distance against r
template <class P>
int sign_line_dist2_minus(const P& p, const Vec2c& a, const Vec2c& b, const Radii& r) noexcept {
  return exact_sign([&](auto tag) {
    using N = decltype(tag);
    const auto [wx, wy] = offset<N>(p, a);
    const auto [ex, ey] = offset<N>(b, a);
    const N rr = r.template value<N>();
    const N c = ex * wy - ey * wx;
    return c * c - rr * rr * (ex * ex + ey * ey);
  });
}

/// sign of dx^2 + dy^2 - r^2 when a static bound proves it, else 2. dx, dy and r each carry at
/// most one rounding of the exact values; the computed difference is then within
/// 5.02 u (dx^2 + dy^2 + r^2) of the exact one (u = 2^-53), below the 8 u used. Sums below
/// kFilterFloor are left undecided: an underflowing square breaks the relative bound.
inline int filtered_sign_dist2(Calc dx, Calc dy, Calc r) noexcept {
  const Calc l = dx * dx + dy * dy, q = r * r;
  const Calc m = l + q, d = l - q;
  if (m > kFilterFloor) [[likely]] {
    const Calc bound = 8 * kUnitRoundoff * m;
    if (d > bound) return 1;
    if (-d > bound) return -1;
  }
  return 2;
}

/// sign of dist(p, [a, b])^2 - r^2 for a stored point, by static bounds; 2 when unsure. r carries
/// at most one rounding. With w = p - a, e = b - a: t = w . e and |e|^2 are within 4.01 u of
/// mt = |w_x e_x| + |w_y e_y| + |e|^2 (8 u used), which tells the nearest feature; inside the
/// slab, c = cross(e, w) is within 4.01 u mc (mc = |e_x w_y| + |e_y w_x|), so c^2 - r^2 |e|^2 is
/// within 10.1 u (mc^2 + r^2 |e|^2) (16 u used). Sums below 2^-900, or an r^2 that is not normal
/// (it is multiplied by |e|^2), are left undecided.
inline int filtered_point_segment(const Vec2c& p, const Vec2c& a, const Vec2c& b, Calc r) noexcept {
  const Calc wx = p.x() - a.x(), wy = p.y() - a.y();
  if (a == b) return filtered_sign_dist2(wx, wy, r);
  const Calc ex = b.x() - a.x(), ey = b.y() - a.y();
  const Calc t = wx * ex + wy * ey, ee = ex * ex + ey * ey;
  const Calc mt = std::fabs(wx * ex) + std::fabs(wy * ey) + ee;
  if (!(mt > kFilterFloor)) return 2;
  const Calc tb = 8 * kUnitRoundoff * mt;
  if (t < -tb) return filtered_sign_dist2(wx, wy, r);                            // nearest: a
  if (t - ee > tb) return filtered_sign_dist2(p.x() - b.x(), p.y() - b.y(), r);  // nearest: b
  if (t > tb && ee - t > tb && (r == 0 || r * r > kUnderflowMargin)) {
    const Calc c = ex * wy - ey * wx;
    const Calc mc = std::fabs(ex * wy) + std::fabs(ey * wx);
    const Calc rr = r * r * ee;
    const Calc m = mc * mc + rr;
    if (m > kFilterFloor) {
      const Calc q = c * c - rr, qb = 16 * kUnitRoundoff * m;
      if (q > qb) return 1;
      if (-q > qb) return -1;
    }
  }
  return 2;
}

/// The closed disc of radius r around p meets the segment [a, b] (a == b allowed).
template <class P>
bool point_segment_within(const P& p, const Vec2c& a, const Vec2c& b, const Radii& r) noexcept {
  if constexpr (std::is_same_v<P, Vec2c>) {
    if (const int s = filtered_point_segment(p, a, b, r.a + r.b); s != 2) [[likely]]
      return s <= 0;
  }
  if (sign_dist2_minus(p, a, r) <= 0) return true;
  if (a == b) return false;
  if (sign_dist2_minus(p, b, r) <= 0) return true;
  // Past either end the nearest point is that end, tested above.
  if (sign_dot(p, a, b) <= 0 || sign_dot(p, b, a) <= 0) return false;
  return sign_line_dist2_minus(p, a, b, r) <= 0;
}

/// sign of sigma (p - c) . w - h |u|^2, w = u (axis 0) or perp(u) (axis 1): p's excess beyond
/// the OBB's face on that side, times |u|.
template <class P>
int sign_face_excess(const P& p, const ObbValues& o, int axis, int sigma) noexcept {
  return exact_sign([&](auto tag) {
    using N = decltype(tag);
    const auto [dx, dy] = offset<N>(p, o.c);
    const N ux(o.u.x()), uy(o.u.y()), h(axis == 0 ? o.hx : o.hy);
    const N along = axis == 0 ? dx * ux + dy * uy : dy * ux - dx * uy;
    return (sigma > 0 ? along : -along) - h * (ux * ux + uy * uy);
  });
}

/// Some face of the OBB has every point strictly beyond it.
template <class P>
bool obb_face_separates(const ObbValues& o, std::span<const P> pts) noexcept {
  for (int axis = 0; axis < 2; ++axis) {
    for (int sigma = -1; sigma <= 1; sigma += 2) {
      bool all_out = true;
      for (const P& p : pts) {
        if (sign_face_excess(p, o, axis, sigma) <= 0) {
          all_out = false;
          break;
        }
      }
      if (all_out) return true;
    }
  }
  return false;
}

/// The turn a -> b -> p for an OBB corner (found by has_separating_edge through its argument).
inline int turn_of(const Vec2c& a, const Vec2c& b, const ObbCorner& p) noexcept {
  return sign_turn(a, b, p);
}

/// Some edge of a core (a segment counts both ways) has every corner of the OBB strictly outside.
inline bool core_edge_separates_obb(const Core& k, const ObbValues& o) noexcept {
  if (k.size() < 2) return false;
  const std::array<ObbCorner, 4> q = o.corners();
  return has_separating_edge(k.pts(), std::span<const ObbCorner>(q));
}

/// The OBB and a core (point, segment or convex polygon of stored points) share a point: no
/// separating axis among the OBB's two axes and the core's edge normals. The OBB's axes also
/// cover the degenerate cases (a point or a segment against a segment).
inline bool obb_meets_core(const ObbValues& o, const Core& k) noexcept {
  return !obb_face_separates(o, k.pts()) && !core_edge_separates_obb(k, o);
}

/// OBB against OBB by the four face axes in double: +1 overlapping, -1 separated, 2 when some
/// axis is too close to call. On the axis w of box P (w = u_P or perp(u_P)) the boxes are
/// separated iff g = |d . w| - h_P |u_P|^2 - hx_Q |u_Q . w| - hy_Q |perp(u_Q) . w| > 0, d = c_Q - c_P
/// (the corner test of obb_face_separates, summed). Each term of g carries at most seven
/// roundings of its exact value, so |error| <= 7.01 u M, M the sum of the terms' magnitudes; 16 u M
/// is used. Sums M below 2^-900 are left undecided (an underflowing product breaks the bound).
inline int filtered_obb_obb(const ObbValues& a, const ObbValues& b) noexcept {
  bool unsure = false;
  auto axis = [&unsure](const ObbValues& p, const ObbValues& q, const Vec2c& w, Calc hp) {
    const Vec2c d = q.c - p.c;
    const Vec2c vq = perp(q.u);
    const Calc along = d.x() * w.x() + d.y() * w.y();
    const Calc uq = q.u.x() * w.x() + q.u.y() * w.y(), vw = vq.x() * w.x() + vq.y() * w.y();
    const Calc rp = hp * (p.u.x() * p.u.x() + p.u.y() * p.u.y());
    const Calc rq = q.hx * std::fabs(uq) + q.hy * std::fabs(vw);
    const Calc g = std::fabs(along) - rp - rq;
    const Calc aw = std::fabs(w.x()), bw = std::fabs(w.y());
    const Calc m = std::fabs(d.x()) * aw + std::fabs(d.y()) * bw + rp +
                   q.hx * (std::fabs(q.u.x()) * aw + std::fabs(q.u.y()) * bw) +
                   q.hy * (std::fabs(vq.x()) * aw + std::fabs(vq.y()) * bw);
    const Calc bound = 16 * kUnitRoundoff * m;
    if (!(m > kFilterFloor) || !(std::fabs(g) > bound)) unsure = true;
    return g > bound && m > kFilterFloor;
  };
  if (axis(a, b, a.u, a.hx) || axis(a, b, perp(a.u), a.hy) || axis(b, a, b.u, b.hx) || axis(b, a, perp(b.u), b.hy))
    return -1;
  return unsure ? 2 : 1;
}

inline bool obb_meets_obb(const ObbValues& a, const ObbValues& b) noexcept {
  if (const int s = filtered_obb_obb(a, b); s != 2) [[likely]]
    return s > 0;
  const std::array<ObbCorner, 4> ca = a.corners(), cb = b.corners();
  return !obb_face_separates(a, std::span<const ObbCorner>(cb)) &&
         !obb_face_separates(b, std::span<const ObbCorner>(ca));
}

/// The disc of radius r around p meets the OBB: with e_k = |(p - c) . w_k| - h_k |u|^2 (the
/// excess beyond the faces times |u|), the squared distance times |u|^2 is the sum of the
/// positive e_k^2.
inline bool point_obb_within(const Vec2c& p, const ObbValues& o, const Radii& r) noexcept {
  {
    // One filtered pass over the whole decision; the exact signs below only when it is unsure.
    const Bounded ux(o.u.x()), uy(o.u.y());
    const Bounded uu = ux * ux + uy * uy;
    const Bounded dx = Bounded(p.x()) - Bounded(o.c.x()), dy = Bounded(p.y()) - Bounded(o.c.y());
    const Bounded along[2] = {dx * ux + dy * uy, dy * ux - dx * uy};
    const Calc h[2] = {o.hx, o.hy};
    Bounded sum = Bounded(0.0);
    bool sure = true, outside = false;
    for (int axis = 0; axis < 2 && sure; ++axis) {
      // ||x| - |y|| <= |x - y|: |along| keeps along's bound whatever its rounded sign.
      const Bounded a = along[axis].v < 0 ? -along[axis] : along[axis];
      const Bounded e = a - Bounded(h[axis]) * uu;
      const int se = e.certain_sign();
      if (se == 2) sure = false;
      if (se > 0) {
        outside = true;
        sum = sum + e * e;
      }
    }
    if (sure) {
      if (!outside) return true;
      const Bounded rr = r.value<Bounded>();
      const int sg = (sum - rr * rr * uu).certain_sign();
      if (sg != 2) return sg <= 0;
    }
  }
  int side[2] = {0, 0};  // the side (+-1) p is strictly beyond, per axis; 0 when within the slab
  for (int axis = 0; axis < 2; ++axis) {
    if (sign_face_excess(p, o, axis, 1) > 0) {
      side[axis] = 1;
    } else if (sign_face_excess(p, o, axis, -1) > 0) {
      side[axis] = -1;
    }
  }
  if (side[0] == 0 && side[1] == 0) return true;
  return exact_sign([&](auto tag) {
           using N = decltype(tag);
           const N ux(o.u.x()), uy(o.u.y()), rr = r.template value<N>();
           const N uu = ux * ux + uy * uy;
           const auto [dx, dy] = offset<N>(p, o.c);
           N sum = -(rr * rr * uu);
           for (int axis = 0; axis < 2; ++axis) {
             if (side[axis] == 0) continue;
             const N along = axis == 0 ? dx * ux + dy * uy : dy * ux - dx * uy;
             const N e = (side[axis] > 0 ? along : -along) - N(axis == 0 ? o.hx : o.hy) * uu;
             sum = sum + e * e;
           }
           return sum;
         }) <= 0;
}

}  // namespace detail

namespace detail {

/// Calls f(a, b) for each edge of a core: the point itself (a == b), the segment, or each side.
template <class F>
bool any_edge(const Core& k, F&& f) noexcept {
  const std::size_t n = k.size();
  if (n <= 2) return f(k[0], k[n - 1]);
  for (std::size_t i = 0; i < n; ++i) {
    if (f(k[i], k[next_index(i, n)])) return true;
  }
  return false;
}

/// Two cores of stored points, dilated by the radii r, meet. When the cores are disjoint their
/// distance is attained between a vertex of one and an edge of the other.
inline bool dilated_cores_meet(const Core& p, const Core& q, const Radii& r) noexcept {
  if (cores_intersect(p, q)) return true;
  if (!(r.a > 0) && !(r.b > 0)) return false;
  auto vertices_near_edges = [&r](const Core& v, const Core& e) {
    for (const Vec2c& x : v.pts()) {
      if (any_edge(e, [&](const Vec2c& a, const Vec2c& b) { return point_segment_within(x, a, b, r); })) return true;
    }
    return false;
  };
  // A point's only edge is itself, and a point's distance to the other core's edges covers the
  // other direction; a point against a point is either way round.
  if (p.size() == 1) return vertices_near_edges(p, q);
  if (q.size() == 1) return vertices_near_edges(q, p);
  return vertices_near_edges(p, q) || vertices_near_edges(q, p);
}

}  // namespace detail

}  // namespace collide
