#pragma once
/// @file detail/contact_circle.hpp
/// The contact of a circle with a circle, a capsule, a polygon or a box, each without building
/// cores: the centre against the other shape's defining values, the generic path of
/// contact_base.hpp for what falls within the rounding band.

#include "collide/detail/contact_base.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

namespace collide::detail {

/// The separation of circles of radii ra and rb whose centres are dist apart: negative when they
/// overlap, else at least 0 (a rounded gap of shapes apart is not let below it).
[[gnu::always_inline]] inline Calc circles_separation(bool overlapping, Calc dist, Calc ra, Calc rb) noexcept {
  return overlapping ? dist - ra - rb : std::max(Calc(0), dist - ra - rb);
}

/// The normal, depth and point of circles whose centres are dist > band apart (offset d from a's
/// centre ca, plain as quotient_or_unit() takes it): the normal along the centres, the point
/// midway between the surfaces.
[[gnu::always_inline]] inline void circles_along_centres(CoreContact& out, const Vec2c& ca, const Vec2c& d, Calc dist,
                                                         bool plain, Calc ra, Calc separation) noexcept {
  out.normal = quotient_or_unit(d, dist, plain);
  out.depth = std::max(Calc(0), -separation);
  out.points[0] = ca + out.normal * (ra + separation * 0.5);
}

/// Circle against circle: the centres' offset gives normal, depth and the one point; coincident
/// centres (within rounding) give normal (1, 0), as contact_cores() does. Every case;
/// contact_circles() takes the common one first.
/// sign: filtered_sign_dist2() of the pair, 2 when it could not tell.
template <Scalar T>
[[gnu::noinline]] std::optional<CoreContact> contact_circles_in_general(const Circle<T>& a, const Circle<T>& b,
                                                                        int sign, Calc speculative) {
  const Vec2c ca = widen(a.center()), cb = widen(b.center());
  const Calc ra = a.radius(), rb = b.radius();
  const Vec2c d = cb - ca;
  const Calc s = std::max(ca.cwiseAbs().maxCoeff(), cb.cwiseAbs().maxCoeff());
  if (!(std::max({s, ra, rb}) >= kTinyCore)) return contact_generic(a, b, speculative);
  if (sign == 2) sign = decide::circle_circle(a, b) ? -1 : 1;
  if (sign > 0 && !(speculative > 0)) return std::nullopt;
  const Calc d2 = d.squaredNorm();
  const bool plain = d2 > kUnderflowMargin && d2 < kOverflowMargin;  // no underflow or overflow in the square
  const Calc dist = plain ? std::sqrt(d2) : norm_of(d);
  CoreContact out;
  out.count = 1;
  out.overlapping = !(sign > 0);
  const Calc separation = circles_separation(out.overlapping, dist, ra, rb);
  if (!out.overlapping && !(separation <= speculative)) return std::nullopt;
  store_separations(out.separations, separation, 0);
  if (dist > band_of(s)) {
    circles_along_centres(out, ca, d, dist, plain, ra, separation);
  } else {
    if (sign <= 0) {
      out.depth = ra + rb;
      out.separations[0] = -out.depth;
    }
    out.points[0] = (ca + cb) * 0.5 + out.normal * ((ra - rb) * 0.5);
  }
  return out;
}

/// contact_circles_in_general(), bit for bit, with the common case in one straight line: circles
/// overlapping for certain, their centres apart by more than the band and their squared distance
/// free of underflow and overflow. Kept out of line (so that the filter before it inlines into
/// the caller) and apart from the general steps, whose calls would give it a stack frame.
template <Scalar T>
[[gnu::noinline]] std::optional<CoreContact> contact_circles(const Circle<T>& a, const Circle<T>& b, int sign,
                                                             Calc speculative) {
  if (sign < 0) {
    const Vec2c ca = widen(a.center()), cb = widen(b.center());
    const Calc ra = a.radius(), rb = b.radius();
    const Vec2c d = cb - ca;
    const Calc s = std::max(ca.cwiseAbs().maxCoeff(), cb.cwiseAbs().maxCoeff());
    const Calc d2 = d.squaredNorm();
    if (d2 > kUnderflowMargin && d2 < kOverflowMargin && s >= kTinyCore) {
      const Calc dist = square_root(d2);
      if (dist > band_of(s)) [[likely]] {
        CoreContact out;
        out.count = 1;
        const Calc separation = circles_separation(true, dist, ra, rb);
        store_separations(out.separations, separation, 0);
        circles_along_centres(out, ca, d, dist, true, ra, separation);
        return out;
      }
    }
  }
  return contact_circles_in_general(a, b, sign, speculative);
}
template <Scalar T>
std::optional<CoreContact> contact_pair(const Circle<T>& a, const Circle<T>& b, Calc speculative, Rounding = {}) {
  const Vec2c d = widen(b.center()) - widen(a.center());
  // The filter is proven at every scale: a pair it finds apart needs nothing else.
  const int sign = filtered_sign_dist2(d.x(), d.y(), Calc(a.radius()) + Calc(b.radius()));
  if (sign == 1 && !(speculative > 0)) return std::nullopt;
  return contact_circles(a, b, sign, speculative);
}

/// Circle against capsule: the centre against the capsule's segment, the steps of
/// contact_of_cores() for a point and a segment without building cores. A centre within the band
/// of the segment (possibly on it), a capsule whose ends coincide and tiny pairs take the generic
/// path. Kept out of line, as the other specialised pairs are.
template <Scalar T>
[[gnu::noinline]] std::optional<CoreContact> contact_circle_capsule(const Circle<T>& a, const Capsule<T>& b,
                                                                    Calc speculative) {
  const Vec2c c = widen(a.center()), s0 = widen(b.a()), s1 = widen(b.b());
  const Calc ra = a.radius(), rb = b.radius(), radii = ra + rb;
  const Calc points = std::max({c.cwiseAbs().maxCoeff(), s0.cwiseAbs().maxCoeff(), s1.cwiseAbs().maxCoeff()});
  const Calc scale = std::max(points, radii), band = band_of(scale);
  if (!(std::min(scale, std::max({points, ra, rb})) >= kTinyCore) || s0 == s1)
    return contact_generic(a, b, speculative);
  // The closest points as closest_points() finds them: the centre against the segment, then
  // each end against the centre when strictly closer.
  const Vec2c d = s1 - s0;
  const Calc dd = d.squaredNorm();
  const Calc t = std::clamp((c - s0).dot(d) / dd, Calc(0), Calc(1));
  Vec2c on_q = s0 + d * t;
  Calc dist2 = squared_distance_to_segment(c, s0, d, dd, t);
  CoreFeature feature{t >= 1 ? 1u : 0u, t > 0 && t < 1};
  if (feature.edge) feature.index = d.x() * (c.y() - s0.y()) - d.y() * (c.x() - s0.x()) < 0 ? 0u : 1u;
  for (const unsigned k : {0u, 1u}) {
    const Vec2c& end = k == 0 ? s0 : s1;
    const Calc e2 = (end - c).squaredNorm();
    if (e2 < dist2) {
      dist2 = e2;
      on_q = end;
      feature = CoreFeature{k, false};
    }
  }
  const Calc dist = std::sqrt(dist2);
  if (!(dist > band)) return contact_generic(a, b, speculative);
  const Calc gap = dist - radii;
  if (!(gap < -band || (!(gap > band) && decide_exactly(a, b)))) {
    return speculative > 0 ? speculative_contact_cores(core_of(a), core_of(b), speculative) : std::nullopt;
  }
  // As contact_from_closest(): beside the segment (no shorter than the offset) its normal, else
  // the direction between the points.
  const Vec2c dq = on_q - c;
  Vec2c n = Vec2c::Zero();
  if (feature.edge && !(dd < dq.squaredNorm())) {
    n = unit_of(Vec2c(d.y(), -d.x()));
    if (n.dot(dq) < 0) n = -n;
  }
  const bool side = n != Vec2c::Zero();
  // |dq| is dist (the same square root), except beside the segment: dist is from its line there.
  const Calc reach = side || !feature.edge ? dist : norm_of(dq);
  if (!side) n = direction_of(dq, reach);
  const Calc along = side ? dq.dot(n) : reach;
  if (!(along > band_of(points))) return contact_generic(a, b, speculative);
  CoreContact out;
  out.normal = n;
  out.depth = std::max(Calc(0), radii - along);
  out.points[0] = ((c + n * ra) + (on_q - n * rb)) * 0.5;
  store_separations(out.separations, along - radii, 0);
  store_ids(out.ids, id_of(CoreFeature{0, false}, feature), FeatureId{});
  out.count = 1;
  return out;
}

/// The face of the largest excess of a circle's centre against a polygon (excesses[i]: its signed
/// distance to face i's line), the first of equals; with the centre inside, a face equally deep up
/// to rounding (kFaceOrderTie of its values' scale, own: the centre's and the radius') does not
/// take over, so that ids stay put on a ridge. Returns the face and its excess.
template <Scalar T>
std::pair<unsigned, Calc> face_of_largest_excess(const ConvexPolygon<T>& b, const Calc* excesses, Calc own) noexcept {
  const std::size_t m = b.size();
  Calc excess = excesses[0];
  unsigned face = 0;
  for (std::size_t i = 1; i < m; ++i) {
    if (excesses[i] > excess) {
      excess = excesses[i];
      face = unsigned(i);
    }
  }
  if (!(excess > 0)) {
    excess = excesses[0];
    face = 0;
    for (std::size_t i = 1; i < m; ++i) {
      const Calc si = std::max(own, widen(b[i]).cwiseAbs().maxCoeff());
      if (excesses[i] > excess + (excesses[i] < 0 ? tie_of(si) : Calc(0))) {
        excess = excesses[i];
        face = unsigned(i);
      }
    }
  }
  return {face, excess};
}

/// The feature of polygon b closest to a centre c beyond its face `face` of largest excess: the
/// face when c projects inside its span (every excess is at most the distance, so c is that
/// excess away); beyond an end, that vertex when c also projects beyond it on the neighbouring
/// face; otherwise nothing (rounding ranked the faces within a hair of each other: the faces must
/// be searched). Always inlined: returned from a call, the optional is stored a field
/// at a time and loaded back whole, and the load waits for the stores.
template <Scalar T>
[[gnu::always_inline]] inline std::optional<CoreFeature> feature_beyond_face(const ConvexPolygon<T>& b, const Vec2c& c,
                                                                             unsigned face) noexcept {
  const std::size_t m = b.size(), next = next_index(face, m);
  const Vec2c v0 = widen(b[face]), v1 = widen(b[next]), d = v1 - v0;
  const Calc along_face = (c - v0).dot(d);
  if (along_face > 0 && along_face < d.squaredNorm()) return CoreFeature{face, true};
  const bool first = !(along_face > 0);
  const Vec2c vk = first ? v0 : v1;
  const Vec2c other = widen(b[first ? (face == 0 ? m - 1 : face - 1) : next_index(next, m)]);
  const Calc beyond = first ? (c - vk).dot(vk - other) : (c - vk).dot(other - vk);
  if (first ? beyond >= 0 : beyond <= 0) return CoreFeature{unsigned(first ? face : next), false};
  return std::nullopt;
}

/// Whether centre c projects onto the line of polygon b's face `face` beyond the face's ends by
/// more than band. A centre within the band of the face's line may still lie far outside a
/// polygon with a vertex sharper than the band (every excess rounds to about 0 along the
/// vertex's bisector): inside, it would project within the span of its least deep face.
template <Scalar T>
bool projects_beyond_face(const ConvexPolygon<T>& b, const Vec2c& c, unsigned face, Calc band) noexcept {
  const Vec2c v0 = widen(b[face]), d = widen(b[next_index(face, b.size())]) - v0;
  const Calc along = (c - v0).dot(d), dd = d.squaredNorm();
  if (along >= 0 && along <= dd) [[likely]]
    return false;
  const Calc len = norm_of(d);
  return along < -band * len || along > (len + band) * len;
}

/// A circle's contact from its centre c (radius r), the closest point on_q of the other shape, at
/// distance dist > 0, and the feature there, with face normal n_face (outward, unit) when that
/// feature is a face: inside a face its normal (see closest_normal()), at a vertex the direction
/// to it; one point midway. A face the centre lies behind (a sliver's far side, as close as its
/// near side up to rounding) has no normal toward the centre: the direction to the point is taken.
inline CoreContact circle_contact_from_closest(const Vec2c& c, Calc r, const Vec2c& on_q, Calc dist,
                                               const CoreFeature& feature, const Vec2c& n_face) noexcept {
  CoreContact out;
  out.count = 1;
  const Vec2c dq = on_q - c;
  const bool facing = feature.edge && dq.dot(n_face) < 0;
  out.normal = facing ? Vec2c(-n_face) : direction_of(dq, dist);
  const Calc along = facing ? dq.dot(out.normal) : dist;
  out.depth = std::max(Calc(0), r - along);
  out.points[0] = ((c + out.normal * r) + on_q) * 0.5;
  store_separations(out.separations, along - r, 0);
  store_ids(out.ids, id_of(CoreFeature{0, false}, feature), FeatureId{});
  return out;
}

/// A circle's contact with its centre c inside a polygon's face of outward unit normal n (excess
/// <= 0 behind it), the reference face, the centre its one incident point (as contact_from_axis()).
inline CoreContact circle_contact_inside(const Vec2c& c, Calc r, const Vec2c& n, Calc excess, unsigned face) noexcept {
  CoreContact out;
  out.count = 1;
  out.normal = -n;
  out.depth = std::max(Calc(0), r - excess);
  out.points[0] = c + n * ((-excess - r) * 0.5);
  store_separations(out.separations, excess - r, 0);
  store_ids(out.ids, id_of(CoreFeature{0, false}, CoreFeature{face, true}), FeatureId{});
  return out;
}

/// Circle against a polygon with cached normals (at most 8 vertices) that circle_beyond_a_face()
/// did not find apart (excesses: the ones it computed), by the face the centre lies least deep
/// behind or farthest beyond (face_of_largest_excess()): with the centre inside, that face is the
/// reference face; outside, the closest point of the boundary. Kept out of line, so that
/// circle_beyond_a_face() before it inlines into the caller.
template <Scalar T>
[[gnu::noinline]] std::optional<CoreContact> contact_circle_polygon(const Circle<T>& a, const ConvexPolygon<T>& b,
                                                                    const Calc* excesses, Calc speculative) {
  const Vec2c* normals = PolygonAccess::normals(b);
  const std::size_t m = b.size();
  const Vec2c c = widen(a.center());
  const Calc r = a.radius(), own = std::max(c.cwiseAbs().maxCoeff(), r);
  const Calc scale = std::max(own, PolygonAccess::largest_coordinate(b));  // the pair's largest coordinate
  if (!(scale >= kTinyCore)) return contact_generic(a, b, speculative);
  const auto [face, excess] = face_of_largest_excess(b, excesses, own);
  const Calc band = band_of(scale);
  const auto speculative_or_none = [&]() -> std::optional<CoreContact> {
    return speculative > 0 ? speculative_contact_cores(core_of(a), core_of(b), speculative) : std::nullopt;
  };
  if (!(excess > 0)) {
    // The centre inside (certain when inside by more than the band). Projecting beyond the face's
    // span, it lies behind a face that rounding tied with this one (or outside, past a vertex
    // sharper than the band): the faces decide.
    if (projects_beyond_face(b, c, face, band)) return contact_generic(a, b, speculative);
    if (!(excess < -band) && !decide_exactly(a, b)) return speculative_or_none();
    return circle_contact_inside(c, r, normals[face], excess, face);
  }
  std::optional<CoreFeature> feature = feature_beyond_face(b, c, face);
  Vec2c on_q = c - normals[face] * excess;
  Calc dist = excess;
  if (!feature || !feature->edge) {
    if (feature) {
      on_q = widen(b[feature->index]);
    } else {
      std::array<Vec2c, ConvexPolygon<T>::kInline> v;
      for (std::size_t i = 0; i < m; ++i) v[i] = widen(b[i]);
      Closest cl;
      // The three faces around first; the others too, since faces tied with this one up to
      // rounding (a run of tiny faces) may hide the closest face beyond them.
      closest_of_points_to_edges(cl, std::span<const Vec2c>(&c, 1), std::span<const Vec2c>(v.data(), m), false,
                                 face + m - 1, m);
      feature = cl.feature_q;
      on_q = cl.on_q;
    }
    dist = norm_of(on_q - c);
  }
  const Calc gap = dist - r;
  const bool overlapping = gap < -band || (!(gap > band) && decide_exactly(a, b));
  if (!overlapping) return speculative_or_none();
  if (!(dist > band)) {
    // A gap at the level of rounding has no reliable direction: the faces decide (contact_cores).
    const Core pc = core_of(a), pb = core_of(b);
    return contact_from_axis(pc, pb, least_penetration(pc, pb), speculative);
  }
  return circle_contact_from_closest(c, r, on_q, dist, *feature, normals[feature->index]);
}

/// Whether the circle's centre lies beyond a face of the polygon (by its cached normals, which it
/// must have) by more than the radius, the speculative distance and the band of that face's
/// values: then they are apart by more than the speculative distance. Otherwise every face's
/// excess (the centre's signed distance to its line) is in excesses, for contact_circle_polygon().
template <Scalar T>
bool circle_beyond_a_face(const Circle<T>& a, const ConvexPolygon<T>& b, Calc speculative, Calc* excesses) noexcept {
  const Vec2c* n = PolygonAccess::normals(b);
  const Vec2c c = widen(a.center());
  const Calc r = a.radius(), reach = r + std::max(speculative, Calc(0));
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Vec2c v = widen(b[i]);
    const Calc e = (c - v).dot(n[i]);
    excesses[i] = e;
    if (e > reach) {
      // The excess is within a few roundings of |c| + |v|; tiny values underflow instead.
      const Calc scale = std::max({c.cwiseAbs().maxCoeff(), r, v.cwiseAbs().maxCoeff()});
      if (scale >= kTinyCore && e > reach + band_of(scale)) return true;
    }
  }
  return false;
}

/// The rounding scale of a circle (centre c, radius r) and a box: their largest coordinate.
inline Calc rect_scale(const Vec2c& c, Calc r, const Rect& k) noexcept {
  return std::max(
      {c.cwiseAbs().maxCoeff(), r, k.c.cwiseAbs().maxCoeff() + (k.hx + k.hy) * std::max(k.w.squaredNorm(), Calc(1))});
}

/// Whether the circle's centre lies beyond a face of the box by more than r plus the speculative
/// distance and the band of the pair's scale (at least kTinyCore): then they are apart by more
/// than the speculative distance. The excess over a face is (|s| - hx |w|^2) / |w| with s the
/// centre's coordinate times |w|^2, compared without the square root (|w| <= max(|w|^2, 1)).
inline bool circle_beyond_rect(const Vec2c& c, Calc r, const Rect& k, Calc speculative, Calc scale) noexcept {
  const Calc ww = k.w.squaredNorm();
  const Vec2c d = c - k.c;
  const Calc sw = d.dot(k.w), tw = d.dot(perp(k.w));
  const Calc reach = r + std::max(speculative, Calc(0)) + band_of(scale);
  return std::max(std::fabs(sw) - k.hx * ww, std::fabs(tw) - k.hy * ww) > reach * std::max(ww, Calc(1));
}

/// Whether a float circle lies beyond a face of a float box by more than its radius, told in
/// float arithmetic (what circle_beyond_rect() tells in double, without the conversions). With
/// s, t the centre's offset along w and perp(w) times |w|, the excess over a face is
/// (|s| - h_x |w|^2) / |w|; the test asks max(|s| - h_x |w|^2, |t| - h_y |w|^2) > r + margin.
/// In roundings of 2^-24 of S = |dx| + |dy| + h_x + h_y + r, the computed maximum lies within 4
/// of the exact one, r |w| within 4 of r (a stored axis has | |w|^2 - 1 | <= 2^-21) and the sum
/// r + margin rounds by 1: a margin of kFloatFilterRoundings (16) of them, plus 2^-100 for
/// products that underflow, proves the exact excess beyond r |w|. Nothing overflows but S itself,
/// which makes the margin infinite: stored values are at most 2^125 (max_magnitude) and |w| is
/// about 1.
inline bool circle_beyond_box_in_float(const Circle<float>& a, const Obb<float>& b) noexcept {
  const float dx = a.center().x() - b.center().x(), dy = a.center().y() - b.center().y();
  const float wx = b.axis().x(), wy = b.axis().y(), hx = b.half_extents().x(), hy = b.half_extents().y();
  const float r = a.radius(), ww = wx * wx + wy * wy;
  const float sw = dx * wx + dy * wy, tw = dx * wy - dy * wx;
  const float size = std::fabs(dx) + std::fabs(dy) + hx + hy + r;
  const float margin = kFloatFilterRoundings * 0x1p-24f * size + 0x1p-100f;
  return std::max(std::fabs(sw) - hx * ww, std::fabs(tw) - hy * ww) > r + margin;
}
/// The same for an AABB, exactly: rounding is monotone and r a float, so a computed difference
/// beyond r is an exact one beyond r.
inline bool circle_beyond_box_in_float(const Circle<float>& a, const Aabb<float>& b) noexcept {
  const float cx = a.center().x(), cy = a.center().y();
  const float ex = std::max(b.min().x() - cx, cx - b.max().x()), ey = std::max(b.min().y() - cy, cy - b.max().y());
  return std::max(ex, ey) > a.radius();
}

/// A circle's centre in a box's frame (the steps of contact_circle_rect()): the box's Rect k, the
/// pair's scale and band, the box's axes w and v = perp(w) with 1 / |w| and |w|, the centre's
/// coordinates s, t along them and its excesses over the half extents (in units of |w|).
struct CentreInRect {
  Vec2c c;
  Calc r;
  Rect k;
  Calc scale, band;
  Vec2c w, v;
  Calc inv, len, s, t, ex, ey;
};
/// The frame's values for a box that is proper (is_proper) and a pair of scale >= kTinyCore.
template <bool aligned>
[[gnu::always_inline]] inline CentreInRect centre_in_rect(const Vec2c& c, Calc r, const Rect& k, Calc scale) noexcept {
  CentreInRect f{c, r, k, scale, band_of(scale), {}, {}, 0, 0, 0, 0, 0, 0};
  // An AABB's axis is (1, 0) exactly: its divisions and square root fold away.
  f.w = aligned ? Vec2c(1, 0) : k.w;
  f.v = perp(f.w);
  const Vec2c d = c - k.c;
  // 1 / |w| without a square root or division for a stored unit axis (inverse_norm_near_unit).
  const Calc ww = aligned ? Calc(1) : f.w.squaredNorm();
  f.inv = aligned ? Calc(1) : inverse_norm_near_unit(ww);
  f.len = ww * f.inv;
  const Calc inv2 = f.inv * f.inv;
  f.s = d.dot(f.w) * inv2;
  f.t = d.dot(f.v) * inv2;
  f.ex = std::fabs(f.s) - k.hx;
  f.ey = std::fabs(f.t) - k.hy;
  return f;
}
/// The gap of a circle whose centre lies beside one side of the box (one excess positive): the
/// centre is that excess away from the box.
[[gnu::always_inline]] inline Calc side_gap(const CentreInRect& f) noexcept {
  return std::max(f.ex, f.ey) * f.len - f.r;
}
/// The offset from the centre to the box's nearest corner, for a centre beyond it (both excesses
/// positive): its coordinates clamped to the box.
[[gnu::always_inline]] inline Vec2c offset_to_corner(const CentreInRect& f) noexcept {
  const Calc cs = std::clamp(f.s, -f.k.hx, f.k.hx), ct = std::clamp(f.t, -f.k.hy, f.k.hy);
  const Vec2c q = f.k.c + f.w * cs + f.v * ct;
  return q - f.c;
}
/// The contact of a centre beyond a corner of the box (both excesses positive): dq from the
/// centre to the corner, at distance dist > band; out.overlapping says whether the shapes overlap.
[[gnu::always_inline]] inline void circle_rect_corner(CoreContact& out, const CentreInRect& f, const Vec2c& dq,
                                                      Calc dist, bool plain) noexcept {
  // Beyond a corner: the direction to it. Beyond one side, that side's normal (circle_rect_face):
  // the closest point's rounding at the box's scale would tilt the normal by about rounding /
  // dist, and a deep push along it would fall short of clearing the flat side.
  const Calc gap = dist - f.r;
  const unsigned corner = f.s < 0 ? (f.t < 0 ? 0u : 3u) : (f.t < 0 ? 1u : 2u);
  store_ids(out.ids, id_of(CoreFeature{0, false}, CoreFeature{corner, false}), FeatureId{});
  out.normal = quotient_or_unit(dq, dist, plain);
  const Calc separation = out.overlapping ? gap : std::max(gap, Calc(0));
  store_separations(out.separations, separation, 0);
  out.depth = std::max(Calc(0), -separation);
  out.points[0] = f.c + out.normal * (f.r + separation * 0.5);
}
/// The contact by the face the centre is least deep behind or lies beyond (its excess the
/// largest); out.overlapping says whether the shapes overlap.
[[gnu::always_inline]] inline void circle_rect_face(CoreContact& out, const CentreInRect& f) noexcept {
  // Inside, within a tie (kFaceOrderTie) of a ridge of the box's interior, equally deep behind two
  // faces, rounding cannot tell the faces apart: the w faces, then the negative side, win there,
  // so that a centre moving along the ridge keeps its face and id.
  const Calc tie = tie_of(f.scale);
  const bool along_w = std::max(f.ex, f.ey) > 0 ? f.ex >= f.ey : f.ex >= f.ey - tie;
  const bool positive = along_w ? f.s > tie : f.t > tie;
  const unsigned face = along_w ? (positive ? 1u : 3u) : (positive ? 2u : 0u);
  const Vec2c n_face = (along_w ? f.w : f.v) * (positive ? f.inv : -f.inv);
  const Calc e = ((along_w ? f.s : f.t) * (positive ? 1 : -1) - (along_w ? f.k.hx : f.k.hy)) * f.len;  // <= 0 inside
  out.normal = -n_face;
  const Calc separation = out.overlapping ? e - f.r : std::max(e - f.r, Calc(0));
  store_separations(out.separations, separation, 0);
  out.depth = std::max(Calc(0), -separation);
  out.points[0] = f.c + n_face * ((-e - f.r) * 0.5);
  store_ids(out.ids, id_of(CoreFeature{0, false}, CoreFeature{face, true}), FeatureId{});
}

/// Circle against a box (b the shape, for the exact decision) in the box's frame: the centre's
/// coordinates along w and perp(w), clamped to the box, give the closest point and its feature
/// (feature.hpp numbering); a centre inside takes the face it is least deep behind. A box that
/// is not proper (see is_proper) takes the generic path. Every case; contact_circle_rect() takes
/// the common ones first.
template <Scalar T, class B>
[[gnu::noinline]] std::optional<CoreContact> contact_circle_rect_in_general(const Circle<T>& a, const B& b,
                                                                            Calc speculative) {
  const Vec2c c = widen(a.center());
  const Calc r = a.radius();
  const Rect k = rect_of(b);
  const Calc scale = rect_scale(c, r, k);
  if (!(scale >= kTinyCore) || !is_proper(b, k)) return contact_generic(a, b, speculative);
  const CentreInRect f = centre_in_rect<std::is_same_v<B, Aabb<T>>>(c, r, k, scale);
  const Calc band = f.band;
  CoreContact out;
  out.count = 1;
  if (f.ex > 0 && f.ey > 0) {
    const Vec2c dq = offset_to_corner(f);
    const Calc dist = norm_of(dq), gap = dist - r;
    out.overlapping = gap < -band || (!(gap > band) && decide_exactly(a, b));
    if (!out.overlapping && !(speculative > 0 && gap <= speculative)) return std::nullopt;
    if (dist > band) {
      const Calc m = dq.cwiseAbs().maxCoeff();
      circle_rect_corner(out, f, dq, dist, is_plain_magnitude(m));
      return out;
    }
  } else if (f.ex > 0 || f.ey > 0) {
    // Beside one side: the centre is its excess away from the box.
    const Calc gap = side_gap(f);
    out.overlapping = gap < -band || (!(gap > band) && decide_exactly(a, b));
    if (!out.overlapping && !(speculative > 0 && gap <= speculative)) return std::nullopt;
  } else if (!(std::max(f.ex, f.ey) * f.len < -band) && !decide_exactly(a, b)) {
    return speculative > 0 ? speculative_contact_cores(core_of(a), core_of(b), speculative) : std::nullopt;
  }
  circle_rect_face(out, f);
  return out;
}

/// contact_circle_rect_in_general(), bit for bit, with the common cases in straight lines: a
/// proper box, and a circle overlapping it by more than the band (beyond a corner at a distance
/// free of underflow and overflow, beside a side, or with its centre inside). The caller rules
/// out most pairs apart first (circle_beyond_rect(), circle_beyond_box_in_float()). Kept out of
/// line, so that those tests inline into the caller, and apart from the general steps, whose
/// calls would give it a stack frame; the box's Rect is taken here again, not passed: read back
/// right after the caller's stores, a passed one waits on them.
template <Scalar T, class B>
[[gnu::noinline]] std::optional<CoreContact> contact_circle_rect(const Circle<T>& a, const B& b, Calc speculative) {
  const Vec2c c = widen(a.center());
  const Calc r = a.radius();
  const Rect k = rect_of(b);
  const Calc scale = rect_scale(c, r, k);
  // Whether the box is proper is asked here, out of line, so that the test for apart pairs before
  // the call does not compute it.
  if (scale >= kTinyCore && is_proper(b, k)) {
    const CentreInRect f = centre_in_rect<std::is_same_v<B, Aabb<T>>>(c, r, k, scale);
    CoreContact out;
    out.count = 1;
    if (f.ex > 0 && f.ey > 0) {
      const Vec2c dq = offset_to_corner(f);
      const Calc m = dq.cwiseAbs().maxCoeff();
      if (is_plain_magnitude(m)) {
        const Calc dist = square_root(dq.squaredNorm());
        if (dist - r < -f.band && dist > f.band) {
          circle_rect_corner(out, f, dq, dist, true);
          return out;
        }
      }
    } else if (const Calc e = std::max(f.ex, f.ey) * f.len; e > 0 ? side_gap(f) < -f.band : e < -f.band) {
      circle_rect_face(out, f);
      return out;
    }
  }
  return contact_circle_rect_in_general(a, b, speculative);
}

}  // namespace collide::detail
