#pragma once
/// @file detail/convex_core.hpp
/// Every primitive is a convex core (a point, a segment or a convex polygon) dilated by a radius:
/// circle = point + r, capsule = segment + r, AABB / OBB / polygon = polygon + 0. The generic
/// algorithms here work on cores in the computation type (double).

#include "collide/predicates.hpp"
#include "collide/shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <span>
#include <vector>

namespace collide::detail {

/// A convex core: 1 point, 2 distinct points (segment) or n >= 3 counter-clockwise vertices.
class Core {
 public:
  Core() = default;
  void push(const Vec2c& p) {
    if (n_ < small_.size()) [[likely]] {
      small_[n_++] = p;
      return;
    }
    push_big(p);
  }
  /// push() of every point of xs, widened. The count is kept in a register while they fit inline:
  /// a vector store may alias the count, which a loop of push() would then reload from memory.
  template <class Points>
  void push_each(const Points& xs) {
    if (n_ + std::size(xs) <= small_.size()) [[likely]] {
      std::size_t n = n_;
      for (const auto& x : xs) small_[n++] = widen(x);
      n_ = n;
    } else {
      for (const auto& x : xs) push(widen(x));
    }
  }
  /// Drops every point (the radius stays), so that the core can be filled again in place.
  void clear() noexcept {
    n_ = 0;
    big_.clear();
  }
  std::span<const Vec2c> pts() const noexcept { return {n_ > small_.size() ? big_.data() : small_.data(), n_}; }
  std::size_t size() const noexcept { return n_; }
  const Vec2c& operator[](std::size_t i) const noexcept { return pts()[i]; }
  Calc radius = 0;

 private:
  void push_big(const Vec2c& p) {
    if (big_.empty()) big_.assign(small_.begin(), small_.end());
    big_.push_back(p);
    ++n_;
  }
  std::array<Vec2c, 8> small_;  // entries past n_ are never read
  std::vector<Vec2c> big_;
  std::size_t n_ = 0;
};

template <Scalar T>
Core core_of(const Circle<T>& s) {
  Core c;
  c.push(widen(s.center()));
  c.radius = s.radius();
  return c;
}
template <Scalar T>
Core core_of(const Capsule<T>& s) {
  Core c;
  c.push(widen(s.a()));
  if (s.b() != s.a()) c.push(widen(s.b()));
  c.radius = s.radius();
  return c;
}
template <Scalar T>
Core core_of(const Aabb<T>& s) {
  const Vec2c lo = widen(s.min()), hi = widen(s.max());
  Core c;
  c.push(lo);
  c.push({hi.x(), lo.y()});
  c.push(hi);
  c.push({lo.x(), hi.y()});
  if (lo.x() == hi.x() || lo.y() == hi.y()) {
    // Degenerate box: a vertical or horizontal segment, or a point.
    Core d;
    d.push(lo);
    if (hi != lo) d.push(hi);
    return d;
  }
  return c;
}
/// The convex hull of up to four points as a core (point, segment or counter-clockwise polygon),
/// by the exact orient(). Used when rounding has collapsed or bent a box's computed corners.
inline Core hull_core(std::array<Vec2c, 4> p) {
  std::sort(p.begin(), p.end(),
            [](const Vec2c& a, const Vec2c& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  std::array<Vec2c, 8> h{};
  std::size_t k = 0;
  for (std::size_t i = 0; i < 4; ++i) {  // lower chain
    while (k >= 2 && orient(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  const std::size_t lower = k + 1;
  for (std::size_t i = 3; i-- > 0;) {  // upper chain
    while (k >= lower && orient(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  Core c;
  if (k >= 2) --k;                    // the last point repeats the first
  if (k <= 2 && p[0] == p[3]) k = 1;  // every point equal
  if (k == 2 && h[0] == h[1]) k = 1;
  for (std::size_t i = 0; i < k; ++i) c.push(h[i]);
  return c;
}

/// OBB corners center +- hx u +- hy v, computed in double (exact products for float input;
/// error at most a few units of roundoff of the largest coordinate). When rounding makes the four
/// corners coincide or fail to turn strictly left (a box thinner than the rounding of its
/// centre), the core is their convex hull instead, so the core is always a valid convex core.
template <Scalar T>
Core core_of(const Obb<T>& s) {
  const Vec2c c = widen(s.center()), u = widen(s.axis());
  const Vec2c v = perp(u);
  const Vec2c ex = u * Calc(s.half_extents().x()), ey = v * Calc(s.half_extents().y());
  Core k;
  if (s.half_extents().x() == 0 || s.half_extents().y() == 0) {
    const Vec2c p0 = c - ex - ey, p1 = c + ex + ey;
    k.push(p0);
    if (p1 != p0) k.push(p1);
    return k;
  }
  const std::array<Vec2c, 4> q = {Vec2c(c - ex - ey), Vec2c(c + ex - ey), Vec2c(c + ex + ey), Vec2c(c - ex + ey)};
  // Corners are off by a few units of roundoff of |c| + the larger half extent; sides longer than
  // 2^-40 of that (and not subnormal-sized) keep every turn strictly left, so only thinner boxes
  // pay for the check. (Measured against |c| alone, a 1e38 x 1e-245 box at the origin kept its
  // four corners although they had rounded to two points, and the duplicate corners hid every
  // separating edge.)
  const Calc hmin = std::min(Calc(s.half_extents().x()), Calc(s.half_extents().y()));
  const Calc hmax = std::max(Calc(s.half_extents().x()), Calc(s.half_extents().y()));
  if (!(hmin > kThinBoxRatio * (c.cwiseAbs().maxCoeff() + hmax) && hmin > kUnderflowMargin)) {
    for (std::size_t i = 0; i < 4; ++i) {
      if (orient(q[i], q[(i + 1) % 4], q[(i + 2) % 4]) <= 0) return hull_core(q);
    }
  }
  k.push_each(q);
  return k;
}
template <Scalar T>
Core core_of(const ConvexPolygon<T>& s) {
  Core c;
  c.push_each(s.vertices());
  return c;
}

// ---------------------------------------------------------------------------------------------
// Tiny shapes. Squares of coordinates below about 2^-537 underflow, which would make every
// rounded decision absolute-accurate only (to about 2^-537). Cores whose coordinates and radii are
// all below kTinyCore are first scaled by a power of two (exact: scaling up never rounds), so
// decisions, depths and distances stay relative-accurate down to the subnormal range.

inline Calc max_abs(const Core& c) noexcept {
  Calc m = std::fabs(c.radius);
  for (const Vec2c& p : c.pts()) m = std::max({m, std::fabs(p.x()), std::fabs(p.y())});
  return m;
}

/// The power of two that brings a tiny pair of cores to magnitude ~1; 0 when no rescaling is needed.
inline int tiny_scale(const Core& p, const Core& q) noexcept {
  const Calc m = std::max(max_abs(p), max_abs(q));
  if (!(m < kTinyCore) || m == 0) return 0;
  int e = 0;
  static_cast<void>(std::frexp(m, &e));
  return -e;
}

/// The core multiplied by 2^k (exact for k >= 0 within range).
inline Core scaled(const Core& c, int k) {
  Core out;
  for (const Vec2c& p : c.pts()) out.push(Vec2c(std::ldexp(p.x(), k), std::ldexp(p.y(), k)));
  out.radius = std::ldexp(c.radius, k);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Exact intersection of cores (closed sets). Every decision is an orient() sign or a comparison.

inline bool in_box_of(const Vec2c& p, const Vec2c& a, const Vec2c& b) noexcept {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}

inline bool point_on_segment(const Vec2c& p, const Vec2c& a, const Vec2c& b) noexcept {
  return orient(a, b, p) == 0 && in_box_of(p, a, b);
}

/// Closed segments [a, b] and [c, d] share a point.
inline bool segments_intersect(const Vec2c& a, const Vec2c& b, const Vec2c& c, const Vec2c& d) noexcept {
  // Segments whose boxes are apart share no point: comparisons, cheaper than the four turns.
  if (std::max(a.x(), b.x()) < std::min(c.x(), d.x()) || std::max(c.x(), d.x()) < std::min(a.x(), b.x()) ||
      std::max(a.y(), b.y()) < std::min(c.y(), d.y()) || std::max(c.y(), d.y()) < std::min(a.y(), b.y()))
    return false;
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && in_box_of(c, a, b)) || (o2 == 0 && in_box_of(d, a, b)) || (o3 == 0 && in_box_of(a, c, d)) ||
         (o4 == 0 && in_box_of(b, c, d));
}

/// p inside or on the boundary of a counter-clockwise convex polygon.
inline bool point_in_polygon(const Vec2c& p, std::span<const Vec2c> poly) noexcept {
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (orient(poly[i], poly[next_index(i, n)], p) < 0) return false;
  }
  return true;
}

/// The turn a -> b -> p (orient()); decide.hpp adds it for points kept unevaluated.
inline int turn_of(const Vec2c& a, const Vec2c& b, const Vec2c& p) noexcept {
  return orient(a, b, p);
}

/// Some edge of `poly` has every point of `other` strictly outside it.
template <class P>
bool has_separating_edge(std::span<const Vec2c> poly, std::span<const P> other) noexcept {
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2c& a = poly[i];
    const Vec2c& b = poly[next_index(i, n)];
    bool all_out = true;
    for (const P& q : other) {
      if (turn_of(a, b, q) >= 0) {
        all_out = false;
        break;
      }
    }
    if (all_out) return true;
  }
  return false;
}

/// The cores (without radius) share a point. Exact.
inline bool cores_intersect(const Core& p, const Core& q) noexcept {
  const Core& s = p.size() <= q.size() ? p : q;  // smaller first
  const Core& l = p.size() <= q.size() ? q : p;
  if (s.size() == 1) {
    if (l.size() == 1) return s[0] == l[0];
    if (l.size() == 2) return point_on_segment(s[0], l[0], l[1]);
    return point_in_polygon(s[0], l.pts());
  }
  if (s.size() == 2) {
    if (l.size() == 2) return segments_intersect(s[0], s[1], l[0], l[1]);
    if (point_in_polygon(s[0], l.pts())) return true;
    const std::size_t n = l.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (segments_intersect(s[0], s[1], l[i], l[next_index(i, n)])) return true;
    }
    return false;
  }
  // Separating axis theorem: convex polygons are disjoint iff an edge of one has the other
  // strictly outside it.
  return !has_separating_edge(s.pts(), l.pts()) && !has_separating_edge(l.pts(), s.pts());
}

// ---------------------------------------------------------------------------------------------
// Distances between cores (rounded; used where the cores do not intersect).

/// A feature of a core as a contact point names it (see feature.hpp): vertex or edge, and index.
struct CoreFeature {
  unsigned index = 0;
  bool edge = false;
};

struct Closest {
  Calc dist2 = std::numeric_limits<Calc>::infinity();
  Vec2c on_p = Vec2c::Zero();  ///< closest point of the first core
  Vec2c on_q = Vec2c::Zero();  ///< closest point of the second core
  CoreFeature feature_p{};     ///< the feature of the first core that on_p lies on
  CoreFeature feature_q{};     ///< the feature of the second core that on_q lies on
};

/// Updates best with the closest pairs between the points pts and the edges of the core whose
/// points are `edges` (swap: the edges belong to the first core). The loop keeps the best pair's
/// indices and parameter and builds the result once (the values of rebuilding it at every
/// improvement, without a struct copy per candidate).
inline void closest_of_points_to_edges(Closest& best, std::span<const Vec2c> pts, std::span<const Vec2c> edges,
                                       bool swap, std::size_t first = 0, std::size_t count = 8) noexcept {
  const std::size_t n = edges.size();
  const std::size_t start = n <= 2 ? 0 : first % n;  // indices wrap by subtraction, not division
  const std::size_t m = n == 1 || n == 2 ? 1 : std::min(n, count);
  Calc best_d2 = best.dist2, best_t = 0;
  std::size_t best_k = 0, best_i = 0;
  bool found = false;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Vec2c& v = pts[k];
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t i = start + j < n ? start + j : start + j - n;
      const Vec2c& a = edges[i];
      const Vec2c d = edges[i + 1 < n ? i + 1 : 0] - a;
      const Calc dd = d.squaredNorm();
      const Calc t = dd > 0 ? std::clamp((v - a).dot(d) / dd, Calc(0), Calc(1)) : Calc(0);
      const Calc d2 = squared_distance_to_segment(v, a, d, dd, t);
      if (!(d2 < best_d2)) continue;
      best_d2 = d2;
      best_t = t;
      best_k = k;
      best_i = i;
      found = true;
    }
  }
  if (!found) return;
  const Vec2c& v = pts[best_k];
  const Vec2c& a = edges[best_i];
  const Vec2c d = edges[best_i + 1 < n ? best_i + 1 : 0] - a;
  const Vec2c c = a + d * best_t;
  CoreFeature fe{unsigned(best_i), false};
  if (best_t >= 1) {
    fe.index = unsigned(next_index(best_i, n));
  } else if (best_t > 0) {
    fe.edge = true;  // a segment's side: 0 right of a -> b, 1 left
    if (n == 2) fe.index = d.x() * (v.y() - a.y()) - d.y() * (v.x() - a.x()) < 0 ? 0u : 1u;
  }
  const CoreFeature fv{unsigned(best_k), false};
  best = swap ? Closest{best_d2, c, v, fe, fv} : Closest{best_d2, v, c, fv, fe};
}

/// Closest points between two cores' boundaries, with the features they lie on; exact only up to
/// rounding. Meaningful when the cores do not intersect (then the closest pair involves a vertex
/// of one of them).
inline Closest closest_points(const Core& p, const Core& q) noexcept {
  Closest best;
  closest_of_points_to_edges(best, p.pts(), q.pts(), false, 0, q.size());
  closest_of_points_to_edges(best, q.pts(), p.pts(), true, 0, p.size());
  return best;
}

/// The gap of two dilated cores from their closest points (closest_points(p, q)): the one formula
/// of distance() and of its witness points, so that both give the same value to the bit.
inline Calc gap_of(const Closest& c, const Core& p, const Core& q) noexcept {
  return std::sqrt(c.dist2) - p.radius - q.radius;
}

// ---------------------------------------------------------------------------------------------
// Penetration by separating axes, for cores that intersect.

/// max over the core of x . n
inline Calc support(const Core& c, const Vec2c& n) noexcept {
  // Two running maxima, so that the comparisons of even and odd points do not wait on each other.
  const std::span<const Vec2c> pts = c.pts();
  Calc m0 = -std::numeric_limits<Calc>::infinity(), m1 = m0;
  std::size_t i = 0;
  for (; i + 1 < pts.size(); i += 2) {
    m0 = std::max(m0, pts[i].dot(n));
    m1 = std::max(m1, pts[i + 1].dot(n));
  }
  if (i < pts.size()) m0 = std::max(m0, pts[i].dot(n));
  return std::max(m0, m1);
}

/// Unit outward normals of a core's edges (both sides for a segment, none for a point).
template <class F>
void for_each_face(const Core& c, F&& f) {
  const std::size_t n = c.size();
  if (n == 1) return;
  if (n == 2) {
    const Vec2c d = c[1] - c[0];
    if (d == Vec2c::Zero()) return;
    const Vec2c nrm = unit_of(Vec2c(d.y(), -d.x()));
    f(nrm, 0u);
    f(Vec2c(-nrm), 1u);
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2c d = c[next_index(i, n)] - c[i];
    if (d == Vec2c::Zero()) continue;
    f(unit_of(Vec2c(d.y(), -d.x())), static_cast<unsigned>(i));
  }
}

struct Axis {
  Vec2c normal = Vec2c(1, 0);  ///< unit, from the first core toward the second
  Calc depth = 0;              ///< translation along -normal that separates, radius included
  int owner = -1;              ///< 0: a face of the first core, 1: of the second, -1: none
  unsigned face = 0;
  Calc slack = 0;  ///< the rounding within which the first core's face was kept (least_penetration_by())
};

/// How far the shapes' values may lie from the shapes they stand for, computed only when asked:
/// when a face of the second core would take over from a parallel face of the first
/// (least_penetration_by()).
/// Empty, it is 0: stored shapes are what they stand for. It refers to its function object,
/// which must outlive it (it is made and passed down within one call).
class Rounding {
 public:
  Rounding() = default;
  template <class F>
  explicit Rounding(const F& f) noexcept
      : fn_([](const void* c) { return Calc((*static_cast<const F*>(c))()); }), ctx_(&f) {}
  Calc operator()() const { return fn_ ? fn_(ctx_) : Calc(0); }

 private:
  Calc (*fn_)(const void*) = nullptr;
  const void* ctx_ = nullptr;
};

/// Axis of least penetration among the faces of two cores, each core's faces listed by faces_p / faces_q (called
/// as faces(f), f(unit normal, index)) and each face's depth (the cores' overlap along its normal, radii included)
/// given by depth_p / depth_q (called with the normal and the index). A face (of q over p, or a later face of one
/// core over an earlier one) is taken over the best so far only when it is shallower by more than `tie`, so that
/// faces equally deep up to rounding (parallel faces, a side split by a vertex one ulp off its line) keep their
/// order while the pair moves, and the depth found is within 2 tie of the least. Stops at the first face
/// shallower than `stop_below` and returns it (a separating face, when the caller needs only that). r: the
/// cores' radii, the depth of the answer when neither core has a face (two points).
/// rounding: for images, whose values carry the rounding of their stored magnitude and position (far larger than
/// their own scale for a shape stored far from its local origin), two parallel faces equally deep in the exact
/// shapes may differ by more than the tie. A face of q parallel to p's best (kParallelFaceCosine) and shallower by
/// more than the tie takes over only when shallower by more than tie + rounding() as well; else p's face is kept,
/// with that rounding as the answer's slack, and the depth found is within 2 tie + slack of the least.
template <class FacesP, class FacesQ, class DepthP, class DepthQ>
Axis least_penetration_by(FacesP&& faces_p, FacesQ&& faces_q, DepthP&& depth_p, DepthQ&& depth_q, Calc r, Calc tie,
                          Calc stop_below, Rounding rounding = {}) {
  Axis best, best_q;
  best.depth = best_q.depth = std::numeric_limits<Calc>::infinity();
  bool stop = false;
  faces_p([&](const Vec2c& n, unsigned i) {
    if (stop) return;
    const Calc d = depth_p(n, i);
    stop = d < stop_below;
    if (d < best.depth - tie || stop) best = {n, d, 0, i};
  });
  if (stop) return best;
  faces_q([&](const Vec2c& n, unsigned i) {
    if (stop) return;
    const Calc d = depth_q(n, i);
    stop = d < stop_below;
    if (d < best_q.depth - tie || stop) best_q = {Vec2c(-n), d, 1, i};
  });
  if (stop || (best_q.depth < best.depth - tie && best.owner < 0)) {
    best = best_q;
  } else if (best_q.depth < best.depth - tie) {
    const Calc slack = best_q.normal.dot(best.normal) > kParallelFaceCosine ? rounding() : Calc(0);
    if (best_q.depth < best.depth - tie - slack) {
      best = best_q;
    } else {
      best.slack = slack;
    }
  }
  if (best.owner < 0) best = {Vec2c(1, 0), r, -1, 0};  // two points: any direction will do
  return best;
}

/// least_penetration_by() with each face's depth from its own support, its first vertex's (the
/// core's extreme along it, up to rounding), and the other core's support (Minkowski-difference
/// faces).
template <class FacesP, class FacesQ>
Axis least_penetration_with(const Core& p, FacesP&& faces_p, const Core& q, FacesQ&& faces_q, Calc tie, Calc stop_below,
                            Rounding rounding = {}) {
  const Calc r = p.radius + q.radius;
  return least_penetration_by(
      faces_p, faces_q, [&](const Vec2c& n, unsigned i) { return p[i].dot(n) + support(q, -n) + r; },
      [&](const Vec2c& n, unsigned i) { return q[i].dot(n) + support(p, -n) + r; }, r, tie, stop_below, rounding);
}

/// least_penetration_with() over the faces of the cores' own edges (for_each_face).
inline Axis least_penetration(const Core& p, const Core& q, Calc tie = 0,
                              Calc stop_below = -std::numeric_limits<Calc>::infinity()) {
  return least_penetration_with(
      p, [&p](auto&& f) { for_each_face(p, f); }, q, [&q](auto&& f) { for_each_face(q, f); }, tie, stop_below);
}

}  // namespace collide::detail
