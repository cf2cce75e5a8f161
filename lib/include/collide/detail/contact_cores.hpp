#pragma once
/// @file detail/contact_cores.hpp
/// Contact generation for two convex cores (a point, a segment or a convex polygon, each dilated
/// by a radius: see detail/convex_core.hpp) that are known to overlap, in named steps:
///   1. contact_of_separate_cores: cores apart (only the radii meet): the closest points give the
///      normal; when they lie inside a face, the other core's facing side is clipped to it as in
///      steps 3 to 5 (a capsule resting on a box touches under both ends), else one point midway.
///   2. find_reference_face: otherwise the face of least penetration over both cores' faces.
///   3. find_incident_face: the other core's face most anti-parallel to it (or its point).
///   4. clip_to_reference_face: the incident face clipped to the reference face's side planes.
///   5. keep_points_within_reach: the clipped ends deep enough, each moved midway between surfaces.
///   6. find_witness_point: when clipping found nothing, the candidate nearest to both shapes.
///   7. name_end_vertex: a single incident point (or a witness) at or beyond an end of the
///      reference face names that end.
/// Each point carries its feature id (feature.hpp) and its separation: the signed distance between
/// the two surfaces along the normal at that point (negative when penetrating). A speculative
/// distance keeps clipped points apart by up to it; speculative_contact_cores() is the contact of
/// cores that do not overlap. Everything is computed in Calc (double); Contact<T> in contact.hpp
/// is the result rounded to T.

#include "collide/config.hpp"
#include "collide/detail/convex_core.hpp"
#include "collide/feature.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace collide::detail {

/// A contact of two dilated cores in the computation's precision.
struct CoreContact {
  Vec2c normal = Vec2c(1, 0);  ///< unit, from the first core toward the second
  Calc depth = 0;              ///< penetration along normal, >= 0
  int count = 0;               ///< valid entries in points: 1 or 2
  bool overlapping = true;     ///< false for a speculative contact of shapes apart
  std::array<Vec2c, 2> points{Vec2c::Zero(), Vec2c::Zero()};
  std::array<Calc, 2> separations{0, 0};  ///< per point, signed distance of the surfaces along normal
  std::array<FeatureId, 2> ids{};         ///< per point, the features that produced it
};

/// Writes a contact's two ids in one 16-byte store where it can. A contact is copied and read
/// back in 16-byte pieces, and a load cannot take its bytes from several narrower stores still on
/// their way to the cache: it waits for them. Fields written one by one would make it wait. Used
/// where a contact gets its one point; the clipped points (keep_points_within_reach) keep writing
/// an id each, which measured faster than gathering both for one store.
inline void store_ids(std::array<FeatureId, 2>& ids, const FeatureId& a, const FeatureId& b) noexcept {
#if defined(__SSE2__)
  if constexpr (std::endian::native == std::endian::little) {
    // FeatureId's bytes in order: child_a (2), child_b (2), index_a, index_b, kind_a, kind_b.
    static_assert(sizeof(FeatureId) == 8 && sizeof(ids) == 16);
    static_assert(offsetof(FeatureId, child_b) == 2 && offsetof(FeatureId, index_a) == 4 &&
                  offsetof(FeatureId, index_b) == 5 && offsetof(FeatureId, kind_a) == 6 &&
                  offsetof(FeatureId, kind_b) == 7);
    const auto bits = [](const FeatureId& id) {
      return static_cast<long long>(std::uint64_t(id.child_a) | std::uint64_t(id.child_b) << 16 |
                                    std::uint64_t(id.index_a) << 32 | std::uint64_t(id.index_b) << 40 |
                                    std::uint64_t(id.kind_a) << 48 | std::uint64_t(id.kind_b) << 56);
    };
    _mm_storeu_si128(reinterpret_cast<__m128i*>(ids.data()), _mm_set_epi64x(bits(b), bits(a)));
    return;
  }
#endif
  ids = {a, b};
}

/// Writes a contact's two separations in one 16-byte store, for the reason store_ids() gives.
inline void store_separations(std::array<Calc, 2>& separations, Calc first, Calc second) noexcept {
#if defined(__SSE2__)
  _mm_storeu_pd(separations.data(), _mm_set_pd(second, first));
#else
  separations = {first, second};
#endif
}

/// The same contact seen from the other shape (the pair asked in the other order): normal
/// reversed, ids swapped.
inline CoreContact reversed(CoreContact c) noexcept {
  c.normal = -c.normal;
  store_ids(c.ids, c.ids[0].swapped(), c.ids[1].swapped());
  return c;
}

/// The feature id of a point from the features of the first and of the second core.
inline FeatureId id_of(const CoreFeature& p, const CoreFeature& q) noexcept {
  return {0,
          0,
          static_cast<std::uint8_t>(p.index),
          static_cast<std::uint8_t>(q.index),
          p.edge ? FeatureKind::Edge : FeatureKind::Vertex,
          q.edge ? FeatureKind::Edge : FeatureKind::Vertex};
}

/// The largest absolute coordinate of two cores' points (their rounding scale).
inline Calc point_scale(const Core& p, const Core& q) noexcept {
  Calc scale = 0;
  for (const Vec2c& x : p.pts()) scale = std::max(scale, x.cwiseAbs().maxCoeff());
  for (const Vec2c& x : q.pts()) scale = std::max(scale, x.cwiseAbs().maxCoeff());
  return scale;
}

/// The tolerance within which a face does not take over from an equally deep face found before it
/// (feature.hpp: ids stay put for parallel faces): a quarter of the pair's rounding unit, so that
/// the chosen depth (within 2 ties of the least) stays within half a unit in either argument order.
inline Calc tie_of(Calc scale) noexcept {
  return kFaceOrderTie * kUnitRoundoff * scale;
}

/// A face of a core that one of the closest points lies on: its first vertex and its index (a
/// segment's side 0 or 1).
struct FaceOn {
  std::size_t start;
  unsigned index;
};

/// The face of core c that its closest point (on feature f; toward: the offset from it to the
/// other core's, d up to sign) lies on: an edge's own, or at a vertex a face through it
/// perpendicular to the offset up to tie and facing the other core (the point lies on it too).
/// Where two parallel faces overlap, which of their points the search returns is rounding's
/// choice, and the face found must not follow it. nullopt for a point core or no such face.
inline std::optional<FaceOn> face_on(const Core& c, const CoreFeature& f, const Vec2c& toward, Calc tie) {
  const std::size_t n = c.size();
  if (n < 2) return std::nullopt;
  // |e| lies between its larger coordinate and their sum: the square root only in between.
  const auto perpendicular = [&](const Vec2c& e) {
    const Calc along = std::abs(toward.dot(e)), ex = std::abs(e.x()), ey = std::abs(e.y());
    if (e == Vec2c::Zero() || along > tie * (ex + ey)) return false;
    return along <= tie * std::max(ex, ey) || along <= tie * norm_of(e);
  };
  if (n == 2) {  // a segment's sides share its one edge; side 0 faces right of a -> b
    const Vec2c e = c[1] - c[0];
    if (f.edge) return FaceOn{0, f.index};
    if (!perpendicular(e)) return std::nullopt;
    return FaceOn{0, Vec2c(e.y(), -e.x()).dot(toward) > 0 ? 0u : 1u};
  }
  if (f.edge) return FaceOn{f.index, f.index};
  for (const std::size_t i : {std::size_t(f.index), f.index == 0 ? n - 1 : f.index - 1}) {
    const Vec2c e = c[next_index(i, n)] - c[i];
    if (perpendicular(e) && Vec2c(e.y(), -e.x()).dot(toward) > 0) return FaceOn{i, unsigned(i)};
  }
  return std::nullopt;
}

/// The faces the closest points cl lie on (face_on()), a face found at a vertex only beside a face
/// of the other core: the two are then parallel up to the tie and overlap, and every pair of
/// points on their common span is closest. A vertex nearest a vertex or the inside of a face is
/// the feature itself. points: point_scale(p, q).
inline std::pair<std::optional<FaceOn>, std::optional<FaceOn>> closest_faces(const Core& p, const Core& q,
                                                                             const Closest& cl, Calc points) {
  const Vec2c d = cl.on_q - cl.on_p;
  const Calc tie = tie_of(points);
  std::optional<FaceOn> fp = face_on(p, cl.feature_p, d, tie), fq = face_on(q, cl.feature_q, -d, tie);
  if (!fq && !cl.feature_p.edge) fp.reset();
  if (!fp && !cl.feature_q.edge) fq.reset();
  return {fp, fq};
}

/// The closest points' features, a vertex named by the face it lies on (fp and fq from
/// closest_faces()), so that a single point between parallel faces names them whichever of their
/// points the search found.
inline std::pair<CoreFeature, CoreFeature> named_features(const Closest& cl, const std::optional<FaceOn>& fp,
                                                          const std::optional<FaceOn>& fq) noexcept {
  return {fp ? CoreFeature{fp->index, true} : cl.feature_p, fq ? CoreFeature{fq->index, true} : cl.feature_q};
}

/// The normal closest_normal() finds for two cores' closest points, and the face it names.
struct ClosestNormal {
  Vec2c normal;
  Calc distance;
  int owner = -1;     ///< the core whose face is named (0: p, 1: q), -1 for the points' own direction
  unsigned face = 0;  ///< that face's index (a segment's side 0 or 1)
  /// The closest points' features as named_features() names them, when closest_normal() needed
  /// the faces to find the normal (else the caller finds them, if it needs them).
  std::optional<std::pair<CoreFeature, CoreFeature>> features;
};

/// cn's named features, found now unless closest_normal() found them. points: point_scale(p, q).
inline std::pair<CoreFeature, CoreFeature> closest_features(const Core& p, const Core& q, const Closest& cl,
                                                            const ClosestNormal& cn, Calc points) {
  if (cn.features) return *cn.features;
  const auto [fp, fq] = closest_faces(p, q, cl, points);
  return named_features(cl, fp, fq);
}

/// Face f of core c's unit normal toward the other core along d (the offset from p to q), when
/// the face is no shorter than d (d2: its squared length); else zero.
inline Vec2c face_normal_along(const Core& c, const FaceOn& f, const Vec2c& d, Calc d2) noexcept {
  const Vec2c e = c[next_index(f.start, c.size())] - c[f.start];
  if (e.squaredNorm() < d2) return Vec2c::Zero();
  const Vec2c n = unit_of(Vec2c(e.y(), -e.x()));
  return n.dot(d) < 0 ? Vec2c(-n) : n;
}

/// closest_normal() beyond its common cases: a vertex on a face, parallel faces, short faces.
[[gnu::noinline]] inline ClosestNormal closest_normal_by_faces(const Core& p, const Core& q, const Closest& cl,
                                                               Calc points) {
  const Vec2c d = cl.on_q - cl.on_p;
  const Calc d2 = d.squaredNorm();
  const auto [fp, fq] = closest_faces(p, q, cl, points < 0 ? point_scale(p, q) : points);
  const std::pair<CoreFeature, CoreFeature> features = named_features(cl, fp, fq);
  if (fp) {
    if (const Vec2c n = face_normal_along(p, *fp, d, d2); n != Vec2c::Zero())
      return {n, d.dot(n), 0, fp->index, features};
  }
  if (fq) {
    if (const Vec2c n = face_normal_along(q, *fq, d, d2); n != Vec2c::Zero())
      return {n, d.dot(n), fp ? 0 : 1, (fp ? fp : fq)->index, features};
  }
  const Calc dist = norm_of(d);
  return {direction_of(d, dist), dist, -1, 0, features};
}

/// The unit normal of two cores' closest points cl (from p toward q) and their distance along it.
/// When a closest point lies on a face (closest_faces()) at least as long as the offset, that
/// face's normal: its direction is off by the rounding of its ends over its length, the offset's
/// by the same rounding over the offset's length, and over a short offset and a deep overlap that
/// tilt would push a shape off a flat face short of clearing it. Else the points' own direction
/// (at two vertices the tilt costs little; a face shorter than the offset is the less certain
/// one). When both cores have a face (parallel up to the tie) the first core's is named, with the
/// longer one's normal, as least_penetration_by() keeps the first core's face on a tie: a pair
/// resting face to face names the same face whether found by its closest points or by its faces.
/// points: point_scale(p, q), computed if negative and needed.
inline ClosestNormal closest_normal(const Core& p, const Core& q, const Closest& cl, Calc points = -1) {
  // The common cases first, as closest_normal_by_faces() would find them: the first core's point
  // inside a long face, or the second's beside a vertex with no face through it along the offset.
  const Vec2c d = cl.on_q - cl.on_p;
  const Calc d2 = d.squaredNorm();
  if (cl.feature_p.edge && p.size() > 1) {
    const FaceOn f{p.size() == 2 ? 0 : cl.feature_p.index, cl.feature_p.index};
    if (const Vec2c n = face_normal_along(p, f, d, d2); n != Vec2c::Zero())
      return {n, d.dot(n), 0, f.index, std::nullopt};
  } else if (cl.feature_q.edge && q.size() > 1 && points >= 0 && !face_on(p, cl.feature_p, d, tie_of(points))) {
    const FaceOn f{q.size() == 2 ? 0 : cl.feature_q.index, cl.feature_q.index};
    if (const Vec2c n = face_normal_along(q, f, d, d2); n != Vec2c::Zero())
      return {n, d.dot(n), 1, f.index, std::nullopt};
  }
  return closest_normal_by_faces(p, q, cl, points);
}

/// The face of least penetration: which core owns it, its ends and its outward normal.
struct ReferenceFace {
  const Core* ref;  ///< the core that owns the face
  const Core* inc;  ///< the other core
  Vec2c r1, r2;     ///< the face's ends, counter-clockwise on ref
  Vec2c normal;     ///< outward normal of the face, toward inc
  int owner;        ///< 0: the first core owns the face, 1: the second
  unsigned face;    ///< the face's edge index on ref
};

/// Step 2: the reference face of the least-penetration axis (owner >= 0).
inline ReferenceFace find_reference_face(const Core& p, const Core& q, const Axis& ax) {
  ReferenceFace f{ax.owner == 0 ? &p : &q, ax.owner == 0 ? &q : &p, {}, {}, {}, ax.owner, ax.face};
  f.normal = ax.owner == 0 ? ax.normal : Vec2c(-ax.normal);
  const Core& ref = *f.ref;
  if (ref.size() == 2) {
    f.r1 = ax.face == 0 ? ref[0] : ref[1];
    f.r2 = ax.face == 0 ? ref[1] : ref[0];
  } else {
    f.r1 = ref[ax.face];
    f.r2 = ref[next_index(ax.face, ref.size())];
  }
  return f;
}

/// Whether the incident core's vertex least far along the reference face's normal (the first of
/// equals) projects strictly inside the face. Then, for cores apart along the face, that vertex
/// lies in the face's Voronoi region and the cores' distance is the face's separation: the whole
/// incident core lies at least that far beyond the face's line, and the vertex that far from a
/// point of the face.
inline bool nearest_vertex_over_face(const ReferenceFace& f) noexcept {
  const Core& inc = *f.inc;
  std::size_t k = 0;
  Calc least = (inc[0] - f.r1).dot(f.normal);
  for (std::size_t j = 1; j < inc.size(); ++j) {
    const Calc s = (inc[j] - f.r1).dot(f.normal);
    if (s < least) {
      least = s;
      k = j;
    }
  }
  const Vec2c tangent = f.r2 - f.r1;
  const Calc along = (inc[k] - f.r1).dot(tangent);
  return along > 0 && along < tangent.squaredNorm();
}

/// The rounding of (x - r1) . tangent for the points x of two cores, tangent = r2 - r1 of squared
/// length len2 (kFaceOrderTie units of roundoff): within it, two such values are equal.
inline Calc along_tie(const ReferenceFace& f, Calc len2) noexcept {
  return kFaceOrderTie * kUnitRoundoff * (point_scale(*f.ref, *f.inc) * std::sqrt(len2) + len2);
}

/// The incident face (one or two points) as it is clipped.
struct IncidentFace {
  std::array<Vec2c, 2> ends{};
  std::array<unsigned, 2> vertices{0, 0};  ///< the incident core's vertex index of each end
  int count = 0;
};

/// Edge j of a core of at least 2 points as an incident face.
inline IncidentFace incident_edge(const Core& inc, std::size_t j) noexcept {
  const std::size_t after = next_index(j, inc.size());
  return {{inc[j], inc[after]}, {unsigned(j), unsigned(after)}, 2};
}

/// The dot product of normal with the outward unit normal of a counter-clockwise core's face
/// along e: the lower, the more anti-parallel. A face whose squared length would underflow or
/// overflow is measured on its unit direction.
inline Calc face_alignment(const Vec2c& e, const Vec2c& normal) noexcept {
  return is_plain_magnitude(e.cwiseAbs().maxCoeff()) ? Vec2c(e.y(), -e.x()).dot(normal) / e.norm()
                                                     : -perp(unit_of(e)).dot(normal);
}

/// Step 3: the incident core's face most anti-parallel to the reference normal. Among faces as
/// anti-parallel as the best up to rounding (a polygon side split by a vertex one ulp off the
/// line), the one that spans most of the reference face: the other may lie beside it entirely,
/// and clipping would then find nothing.
inline IncidentFace find_incident_face(const ReferenceFace& f, const Vec2c* inc_normals = nullptr) {
  const Core& inc = *f.inc;
  if (inc.size() == 1) return {{inc[0], Vec2c::Zero()}, {0, 0}, 1};
  if (inc.size() == 2) return incident_edge(inc, 0);
  std::array<Calc, 8> dots{};  // the alignments of the first 8 faces, computed once
  auto anti_parallel = [&](std::size_t j) {
    if (inc_normals) return inc_normals[j].dot(f.normal);
    if (j < dots.size() && dots[j] != 0) return dots[j];
    const Calc dot = face_alignment(inc[next_index(j, inc.size())] - inc[j], f.normal);
    if (j < dots.size()) dots[j] = dot;
    return dot;
  };
  std::size_t best = 0;
  Calc best_dot = std::numeric_limits<Calc>::infinity(), next_dot = best_dot;  // the least and the next
  bool unordered = false;
  for (std::size_t j = 0; j < inc.size(); ++j) {
    const Calc dot = anti_parallel(j);
    unordered |= dot != dot;
    if (dot < best_dot) {
      next_dot = best_dot;
      best_dot = dot;
      best = j;
    } else if (dot < next_dot) {
      next_dot = dot;
    }
  }
  // A face as anti-parallel as the best up to kFaceTieTolerance (NaN counts as one) takes over when
  // it comes first or spans more by more than the spans' rounding (faces of a square at 45 degrees
  // to the reference face span it equally), so that the face, and its ids, stay put while the pair
  // moves. Usually there is none.
  if (next_dot > best_dot + kFaceTieTolerance && !unordered) return incident_edge(inc, best);
  const Vec2c tangent = f.r2 - f.r1;
  const Calc len2 = tangent.squaredNorm();
  Calc best_span = 0, span_tie = -1;
  bool found = false;
  for (std::size_t j = 0; j < inc.size(); ++j) {
    if (anti_parallel(j) > best_dot + kFaceTieTolerance) continue;
    const Vec2c a0 = inc[j], a1 = inc[next_index(j, inc.size())];
    const Calc t0 = (a0 - f.r1).dot(tangent), t1 = (a1 - f.r1).dot(tangent);
    const Calc span = std::min(std::max(t0, t1), len2) - std::max(std::min(t0, t1), Calc(0));
    if (found) {
      if (span_tie < 0) span_tie = along_tie(f, len2);
      if (!(span > best_span + span_tie)) continue;
    }
    found = true;
    best_span = span;
    best = j;
  }
  return incident_edge(inc, best);
}

/// Step 4: clips a two-point incident face to the reference face's span, 0 <= (x - r1) . u <=
/// (r2 - r1) . u along the face's unit direction u = perp(normal). u comes from the face's normal,
/// not from r2 - r1: the normal is a box's axis or a polygon's cached normal, turned exactly up to
/// rounding, while r2 - r1 of a short face far from the origin points off by the rounding of its
/// ends over its length, and the incident face, clipped a separation away, would be cut that far
/// off the face's end. Returns false when the face misses the reference face, or when clipping
/// cannot be trusted: an incident face 2^20 times longer than the reference face moves its ends by
/// ulps of the long face, more than the short face is long.
inline bool clip_to_reference_face(IncidentFace& face, const ReferenceFace& f) {
  const Vec2c span = f.r2 - f.r1;
  const Calc len2 = span.squaredNorm();
  std::array<Vec2c, 2>& ip = face.ends;
  const Calc inc_len2 = face.count == 2 ? (ip[1] - ip[0]).squaredNorm() : 0;
  if (inc_len2 > kClipLengthRatio * len2) return false;
  const Calc extent = span.cwiseAbs().maxCoeff();
  if (!(len2 >= kPlainNormLow * kPlainNormLow) && extent > 0 && face.count == 2 &&
      norm_of(ip[1] - ip[0]) > kClipLengthRatioRoot * norm_of(span))
    return false;  // squares that underflowed compare nothing: the lengths do
  if (face.count != 2 || !(extent > 0)) return true;
  const Vec2c tangent(-f.normal.y(), f.normal.x());
  const Calc end = span.dot(tangent);
  for (int side = 0; side < 2; ++side) {
    const Calc lim = side == 0 ? 0 : end;
    const Calc sgn = side == 0 ? 1 : -1;
    const Calc d0 = sgn * ((ip[0] - f.r1).dot(tangent) - lim), d1 = sgn * ((ip[1] - f.r1).dot(tangent) - lim);
    if (d0 < 0 && d1 < 0) return false;
    if (d0 < 0) ip[0] = ip[0] + (ip[1] - ip[0]) * (d0 / (d0 - d1));
    if (d1 < 0) ip[1] = ip[1] + (ip[0] - ip[1]) * (d1 / (d1 - d0));
  }
  return true;
}

/// The id of a point on the reference face (an edge of ref) from the incident vertex v.
inline FeatureId face_point_id(const ReferenceFace& f, unsigned v) noexcept {
  const CoreFeature face{f.face, true}, vertex{v, false};
  return f.owner == 0 ? id_of(face, vertex) : id_of(vertex, face);
}

/// How much further toward the reference face than a clipped end's own circle the incident
/// shape reaches at the end's place along the face: 0 except for a segment with a radius tilted
/// to the face, whose points nearer the face have circles reaching below the end's. In
/// coordinates along the face (u) and the normal (s) from the segment's first end, the circle of
/// the segment's point at length l reaches down to l t_s - sqrt(r^2 - (l t_u - u_x)^2) at u_x,
/// (t_u, t_s) the segment's unit direction: least at l t_u - u_x = -r t_s sign(t_u), clamped to
/// the segment. Unclamped, that is the straight side of the shape, u_x t_s / t_u - r / |t_u|,
/// taken without a square root where the segment lies within 60 degrees of the face (|t_u| >=
/// 1/2, so that neither term is large); at the segment's end nearer the face it is that end's own
/// circle (0). The segment's terms are the same for both ends, so they are computed once.
class IncidentSink {
 public:
  explicit IncidentSink(const ReferenceFace& f) noexcept : f_(f) {
    const Core& inc = *f.inc;
    r_ = inc.radius;
    if (inc.size() != 2 || !(r_ > 0)) return;
    const Vec2c d = inc[1] - inc[0];
    const Calc rise = d.dot(f.normal);
    if (rise == 0) return;  // parallel to the face
    len_ = norm_of(d);
    tangent_ = Vec2c(-f.normal.y(), f.normal.x());
    // Both divisions wait on the square root only, not on each other.
    const Calc along = d.dot(tangent_), inv_len = 1 / len_;
    tu_ = along * inv_len;
    ts_ = rise * inv_len;
    lower_ = rise > 0 ? 0 : 1;
    if (std::fabs(tu_) >= 0.5) {
      const Calc inv = len_ / along;  // 1 / t_u
      slope_ = ts_ * inv;
      secant_ = std::fabs(inv);
      straight_ = true;
    }
    tilted_ = true;
  }
  /// The sink at the clipped end x.
  Calc at(const Vec2c& x) const noexcept {
    if (!tilted_ || x == (*f_.inc)[lower_]) return 0;
    const Vec2c& o = (*f_.inc)[0];
    const Vec2c xo = x - o;
    const Calc ux = xo.dot(tangent_);
    const Calc lift = ux + (tu_ > 0 ? -r_ : r_) * ts_;  // l t_u
    if (straight_ && (tu_ > 0 ? lift > 0 && lift < len_ * tu_ : lift < 0 && lift > len_ * tu_))
      return std::max(Calc(0), xo.dot(f_.normal) - r_ - (ux * slope_ - r_ * secant_));
    const Calc l = tu_ == 0 ? (ts_ > 0 ? Calc(0) : len_) : std::clamp(lift / tu_, Calc(0), len_);
    const Calc k = std::min(std::fabs(l * tu_ - ux) / r_, Calc(1));  // r^2 - z^2 = r^2 (1 - k)(1 + k), unsquared
    const Calc lowest = l * ts_ - r_ * std::sqrt((1 - k) * (1 + k));
    return std::max(Calc(0), xo.dot(f_.normal) - r_ - lowest);
  }

 private:
  const ReferenceFace& f_;
  Vec2c tangent_ = Vec2c::Zero();
  Calc r_ = 0, len_ = 0, tu_ = 0, ts_ = 0, slope_ = 0, secant_ = 0;
  std::size_t lower_ = 0;  // the end nearer the face
  bool tilted_ = false, straight_ = false;
};

/// Step 5: the clipped ends within reach of the radii plus the speculative distance, each moved
/// midway between the surfaces, with its separation (s - the radii). An end beyond reach by no
/// more than the rounding of s is kept: an end exactly at reach (a segment lying on a face) must
/// not come and go with the rounding as the pair moves. The end of a tilted segment with a radius
/// is first lowered by IncidentSink, so that its surface point is the shape's there.
inline void keep_points_within_reach(const IncidentFace& face, const ReferenceFace& f, CoreContact& out,
                                     Calc speculative = 0) {
  const Calc ref_radius = f.ref->radius, inc_radius = f.inc->radius;
  const Calc reach = ref_radius + inc_radius + speculative;
  Calc band = -1;  // computed only for an end beyond reach
  const IncidentSink sink(f);
  // The count in a register: the points' vector stores may alias out.count.
  std::size_t k = std::size_t(out.count);
  for (std::size_t i = 0; i < std::size_t(face.count); ++i) {
    const Vec2c end = face.ends[i] - f.normal * sink.at(face.ends[i]);
    const Calc s = (end - f.r1).dot(f.normal);
    if (s > reach) {
      if (band < 0) band = kOverlapErrorFactor * kUnitRoundoff * std::max(point_scale(*f.ref, *f.inc), reach);
      if (s > reach + band) continue;
    }
    out.points[k] = end + f.normal * ((ref_radius - s - inc_radius) * 0.5);
    out.separations[k] = s - ref_radius - inc_radius;
    out.ids[k] = face_point_id(f, face.vertices[i]);
    ++k;
  }
  if (k == 2 && out.points[0] == out.points[1]) {
    // Clipping carried one end onto the other: one point, named by the end that lies there
    // unclipped, the vertex that keeps the point once the ends part.
    const Core& inc = *f.inc;
    if (face.ends[0] != inc[face.vertices[0]] && face.ends[1] == inc[face.vertices[1]]) out.ids[0] = out.ids[1];
    k = 1;
  }
  out.count = int(k);
}

/// Step 1, with the normal of a face (closest_normal() found the closest points inside it) and
/// neither core a point: the other core's incident face clipped to that face as steps 3 to 5 clip
/// it, so that a side lying along the face (a capsule resting on a box, a box within a speculative
/// distance of another) gets a point at each end of their common span, each with its own
/// separation. Count 0 (the one point between the closest points stands) when clipping keeps
/// nothing or loses the closest points, whose separation must be the least.
inline CoreContact clip_to_closest_face(const Core& p, const Core& q, const ClosestNormal& cn, Calc speculative,
                                        const Vec2c* normals_p, const Vec2c* normals_q) {
  CoreContact out;
  out.normal = cn.normal;
  if (cn.owner < 0 || p.size() < 2 || q.size() < 2) return out;
  const Calc radii = p.radius + q.radius;
  const ReferenceFace f = find_reference_face(p, q, Axis{cn.normal, radii - cn.distance, cn.owner, cn.face});
  IncidentFace face = find_incident_face(f, cn.owner == 0 ? normals_q : normals_p);
  if (clip_to_reference_face(face, f)) keep_points_within_reach(face, f, out, speculative);
  const Calc least = out.count > 1 ? std::min(out.separations[0], out.separations[1]) : out.separations[0];
  if (out.count > 0 && !(least <= cn.distance - radii)) {
    const Calc band = kOverlapErrorFactor * kUnitRoundoff * std::max(point_scale(p, q), radii);
    if (!(least <= cn.distance - radii + band)) out.count = 0;
  }
  return out;
}

/// Step 1 from the closest points cl of the cores p and q (see contact_of_separate_cores()).
/// speculative: clipped points apart by up to it are kept too; normals_p and normals_q as for
/// contact_from_axis().
inline std::optional<CoreContact> contact_from_closest(const Core& p, const Core& q, const Closest& cl,
                                                       Calc speculative = 0, const Vec2c* normals_p = nullptr,
                                                       const Vec2c* normals_q = nullptr) {
  const Calc points = point_scale(p, q);
  const ClosestNormal cn = closest_normal(p, q, cl, points);
  if (!(cn.distance > kOverlapErrorFactor * kUnitRoundoff * points)) return std::nullopt;
  CoreContact out = clip_to_closest_face(p, q, cn, speculative, normals_p, normals_q);
  out.depth = std::max(Calc(0), p.radius + q.radius - cn.distance);
  if (out.count > 0) return out;
  const Vec2c sp = cl.on_p + out.normal * p.radius, sq = cl.on_q - out.normal * q.radius;
  out.points[0] = (sp + sq) * 0.5;
  store_separations(out.separations, cn.distance - p.radius - q.radius, out.separations[1]);
  const auto [fp, fq] = closest_features(p, q, cl, cn, points);
  store_ids(out.ids, id_of(fp, fq), out.ids[1]);
  out.count = 1;
  return out;
}

/// Step 1: cores apart, radii overlapping. Contact along the closest points, or nullopt when the
/// gap is at the level of rounding (a point that misses a segment through it only because the
/// segment's ends were rounded): such a gap has no reliable direction, the faces decide instead.
inline std::optional<CoreContact> contact_of_separate_cores(const Core& p, const Core& q, Calc speculative = 0) {
  return contact_from_closest(p, q, closest_points(p, q), speculative);
}

/// How far x lies outside the dilated core c (0 inside).
inline Calc excess_over(const Vec2c& x, const Core& c) {
  Core pt;
  pt.push(x);
  if (cores_intersect(pt, c)) return Calc(0);
  const Closest cl = closest_points(pt, c);
  return std::max(Calc(0), norm_of(cl.on_q - cl.on_p) - c.radius);
}

/// Step 6: when clipping found nothing (the incident face misses a short reference face) or was
/// not trusted, the candidate whose surface points lie nearest to the dilated cores: an incident
/// vertex moved halfway to the reference surface (the deepest first: vertices equally deep by
/// rounding may lie far apart, one at the reference face's end and one beyond it), the reference
/// face's midpoint moved halfway to the incident surface, or a vertex of either core (often
/// inside the other, when the shapes differ in size by orders of magnitude). The surface points
/// are where the contact puts them, the candidate moved half the depth along the normal either
/// way: a point inside both shapes but far from one surface (on a segment, say) is not midway.
/// deepest: the incident vertex that names the point, the one moved when such a candidate wins.
inline Vec2c find_witness_point(const Core& p, const Core& q, const ReferenceFace& f, Calc depth, unsigned& deepest) {
  const Core& inc = *f.inc;
  Calc best = std::numeric_limits<Calc>::infinity();
  Vec2c witness = p[0];
  const Vec2c half = (f.owner == 0 ? f.normal : Vec2c(-f.normal)) * (depth * 0.5);  // from p toward q
  std::size_t k = 0;
  for (std::size_t j = 1; j < inc.size(); ++j) {
    if ((inc[j] - f.r1).dot(f.normal) < (inc[k] - f.r1).dot(f.normal)) k = j;
  }
  // The offsets round at the pair's scale: vertices as deep as k up to that (a long incident side
  // split by nearly collinear vertices) may lie far apart along the face. Of those, the one nearest
  // the face's span names the point, so that its edges reach under the face.
  const Vec2c tangent = f.r2 - f.r1;
  const Calc len2 = tangent.squaredNorm(), tie = tie_of(point_scale(p, q));
  const Calc least = (inc[k] - f.r1).dot(f.normal);
  const auto beside = [&](std::size_t j) {
    const Calc t = (inc[j] - f.r1).dot(tangent);
    return t < 0 ? -t : std::max(t - len2, Calc(0));
  };
  for (std::size_t j = 0; j < inc.size(); ++j) {
    if ((inc[j] - f.r1).dot(f.normal) <= least + tie && beside(j) < beside(k)) k = j;
  }
  deepest = unsigned(k);
  // name: the incident vertex naming x (the deepest, unless x is another one moved).
  auto consider_witness = [&](const Vec2c& x, std::size_t name) {
    const Calc e = std::max(excess_over(x + half, p), excess_over(x - half, q));
    if (e < best) {
      best = e;
      witness = x;
      deepest = unsigned(name);
    }
  };
  auto consider_vertex = [&](std::size_t j) {
    const Calc s = (inc[j] - f.r1).dot(f.normal);
    consider_witness(inc[j] + f.normal * ((f.ref->radius - s - inc.radius) * 0.5), j);
  };
  consider_vertex(k);
  for (std::size_t j = 0; j < inc.size(); ++j) {
    if (j != k) consider_vertex(j);
  }
  consider_witness((f.r1 + f.r2) * 0.5 + f.normal * (f.ref->radius - depth * 0.5), k);
  for (const Vec2c& x : p.pts()) consider_witness(x, k);
  for (const Vec2c& x : q.pts()) consider_witness(x, k);
  return witness;
}

/// The feature of a polygon reference core that x, beyond the face's end vertex `end` (forward:
/// past r2), lies along when the faces past that end are the face's continuation: each at the
/// same offset from x as the face up to rounding (nearly collinear faces, tied as reference faces
/// whichever the search kept). The first such face x projects inside, else the vertex where the
/// walk stops.
inline CoreFeature feature_along_tied_faces(const ReferenceFace& f, const Vec2c& x, unsigned end, bool forward) {
  const Core& ref = *f.ref;
  const std::size_t n = ref.size();
  if (n < 3) return {end, false};
  Calc scale = x.cwiseAbs().maxCoeff();
  for (const Vec2c& v : ref.pts()) scale = std::max(scale, v.cwiseAbs().maxCoeff());
  const Calc band = kOverlapErrorFactor * kUnitRoundoff * scale;
  const Calc offset = (x - f.r1).dot(f.normal);
  for (std::size_t step = 1; step < n - 1; ++step) {
    const unsigned face = forward ? end : unsigned((end + n - 1) % n);
    const Vec2c a = ref[face], b = ref[next_index(face, n)], e = b - a;
    if (e == Vec2c::Zero()) break;
    if (!(std::abs((x - a).dot(unit_of(Vec2c(e.y(), -e.x()))) - offset) <= band)) break;
    const Calc along = (x - a).dot(e);
    if (along > 0 && along < e.squaredNorm()) return {face, true};
    if (forward ? along <= 0 : along >= e.squaredNorm()) break;  // at the vertex between
    end = forward ? unsigned(next_index(face, n)) : face;
  }
  return {end, false};
}

/// Names the one point of out by the reference face's end vertex, with the incident vertex v, when
/// x projects onto that end of the face or beyond it; otherwise leaves it. Past an end, faces
/// continuing the reference face (feature_along_tied_faces()) name the point where it lies.
inline void name_end_vertex_at(const ReferenceFace& f, const Vec2c& x, unsigned v, CoreContact& out) {
  const Vec2c tangent = f.r2 - f.r1;
  const Calc along = (x - f.r1).dot(tangent);
  if (along > 0 && along < tangent.squaredNorm()) return;
  // r1 is the reference core's point f.face and r2 the next (a segment's face 1 runs from its point 1).
  const bool forward = along > 0;
  const unsigned end = forward ? unsigned(next_index(f.face, f.ref->size())) : f.face;
  const CoreFeature feature = feature_along_tied_faces(f, x, end, forward), point{v, false};
  store_ids(out.ids, f.owner == 0 ? id_of(feature, point) : id_of(point, feature), out.ids[1]);
}

/// Step 7, for a single incident point (a circle's centre, a capsule's coincident ends): a point
/// that projects onto an end of the reference face, or beyond it, names that end's vertex, as
/// closest_points() names it once the point leaves the core (so a point on a segment's end keeps
/// its id as it moves off along the normal).
inline void name_end_vertex(const ReferenceFace& f, CoreContact& out) {
  if (f.inc->size() != 1 || out.count != 1) return;
  name_end_vertex_at(f, (*f.inc)[0], 0, out);
}

/// Steps 2 to 7 from the axis of least penetration of two cores known to overlap. normals_p and
/// normals_q: each core's unit edge normals when known (else nullptr: computed where needed).
inline CoreContact contact_from_axis(const Core& p, const Core& q, const Axis& ax, Calc speculative = 0,
                                     const Vec2c* normals_p = nullptr, const Vec2c* normals_q = nullptr) {
  CoreContact out;
  out.normal = ax.normal;
  out.depth = std::max(Calc(0), ax.depth);
  if (ax.owner < 0) {
    // Two points: the surfaces along the normal are p + n rp and q - n rq; the point between them.
    out.points[0] = (p[0] + q[0]) * 0.5 + ax.normal * ((p.radius - q.radius) * 0.5);
    store_separations(out.separations, -ax.depth, 0);
    out.count = 1;
    return out;
  }
  const ReferenceFace f = find_reference_face(p, q, ax);
  IncidentFace face = find_incident_face(f, ax.owner == 0 ? normals_q : normals_p);
  if (clip_to_reference_face(face, f)) keep_points_within_reach(face, f, out, speculative);
  if (out.count == 0) {
    unsigned deepest = 0;
    out.points[0] = find_witness_point(p, q, f, out.depth, deepest);
    store_separations(out.separations, -out.depth, out.separations[1]);
    store_ids(out.ids, face_point_id(f, deepest), out.ids[1]);
    out.count = 1;
    // A witness beyond the face's span (the incident face lies past its end, so clipping kept
    // nothing) is not on the face: it names the end.
    name_end_vertex_at(f, out.points[0], deepest, out);
  }
  name_end_vertex(f, out);
  return out;
}

/// tie_of() the pair's point scale.
inline Calc owner_tie(const Core& p, const Core& q) noexcept {
  return tie_of(point_scale(p, q));
}

/// Contact of two dilated cores known to overlap, at their own scale (see contact_cores()).
/// cores_meet: the caller knows the cores themselves intersect (radius-free shapes that overlap).
inline CoreContact contact_cores_at_scale(const Core& p, const Core& q, Calc speculative = 0, bool cores_meet = false) {
  if (!cores_meet && !cores_intersect(p, q)) {
    if (const std::optional<CoreContact> c = contact_of_separate_cores(p, q, speculative)) return *c;
  }
  return contact_from_axis(p, q, least_penetration(p, q, owner_tie(p, q)), speculative);
}

/// The contact scaled back by 2^-k (after exact rescaling of tiny cores).
inline CoreContact unscaled(CoreContact c, int k) {
  c.depth = std::ldexp(c.depth, -k);
  for (Vec2c& pt : c.points) pt = Vec2c(std::ldexp(pt.x(), -k), std::ldexp(pt.y(), -k));
  for (Calc& s : c.separations) s = std::ldexp(s, -k);
  return c;
}

/// contact_cores_at_scale() after exact rescaling of tiny cores (see tiny_scale()).
inline CoreContact contact_cores(const Core& p, const Core& q, Calc speculative = 0, bool cores_meet = false) {
  const int k = tiny_scale(p, q);
  if (k == 0) return contact_cores_at_scale(p, q, speculative, cores_meet);
  return unscaled(contact_cores_at_scale(scaled(p, k), scaled(q, k), std::ldexp(speculative, k), cores_meet), k);
}

/// Speculative contact of two dilated cores that do not overlap, at their own scale: as step 1,
/// the facing side clipped to the face the closest points lie inside (each point apart by at most
/// speculative), else one point between the closest points, its separation the gap; nullopt when
/// the gap exceeds speculative. A gap at the level of rounding takes its normal from the faces (as
/// contact_of_separate_cores). Separations are at least 0.
inline std::optional<CoreContact> speculative_contact_at_scale(const Core& p, const Core& q, Calc speculative) {
  const Closest cl = closest_points(p, q);
  const Calc d = norm_of(cl.on_q - cl.on_p);
  const Calc gap = std::max(Calc(0), d - p.radius - q.radius);
  if (!(gap <= speculative)) return std::nullopt;
  CoreContact out;
  const Calc points = point_scale(p, q);
  std::pair<CoreFeature, CoreFeature> features{cl.feature_p, cl.feature_q};
  if (d > kOverlapErrorFactor * kUnitRoundoff * points) {
    const ClosestNormal cn = closest_normal(p, q, cl, points);
    out = clip_to_closest_face(p, q, cn, speculative, nullptr, nullptr);
    if (out.count > 0) {
      out.overlapping = false;
      for (Calc& s : out.separations) s = std::max(s, Calc(0));
      return out;
    }
    features = closest_features(p, q, cl, cn, points);
  } else {
    out.normal = least_penetration(p, q).normal;
  }
  out.overlapping = false;
  const Vec2c sp = cl.on_p + out.normal * p.radius, sq = cl.on_q - out.normal * q.radius;
  out.points[0] = sp + (sq - sp) * 0.5;
  store_separations(out.separations, gap, out.separations[1]);
  store_ids(out.ids, id_of(features.first, features.second), out.ids[1]);
  out.count = 1;
  return out;
}

/// speculative_contact_at_scale() after exact rescaling of tiny cores.
inline std::optional<CoreContact> speculative_contact_cores(const Core& p, const Core& q, Calc speculative) {
  const int k = tiny_scale(p, q);
  if (k == 0) return speculative_contact_at_scale(p, q, speculative);
  const std::optional<CoreContact> c =
      speculative_contact_at_scale(scaled(p, k), scaled(q, k), std::ldexp(speculative, k));
  if (!c) return std::nullopt;
  return unscaled(*c, k);
}

/// Distance between two dilated cores that do not overlap (rescaled when tiny).
inline Calc core_gap(const Core& p, const Core& q) {
  const int k = tiny_scale(p, q);
  if (k == 0) return gap_of(closest_points(p, q), p, q);
  const Core ps = scaled(p, k), qs = scaled(q, k);
  return std::ldexp(gap_of(closest_points(ps, qs), ps, qs), -k);
}

}  // namespace collide::detail
