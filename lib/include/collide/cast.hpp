#pragma once
/// @file cast.hpp
/// Shape casts: when two shapes moving at constant velocities first touch.
///
/// Semantics: a moves to a + va * s and b to b + vb * s for s in [0, max_t]; both are closed sets
/// and touching counts, as everywhere. shape_cast() returns the first time the moving shapes meet,
/// with the unit normal from a toward b and the point midway between the surfaces there. Shapes
/// that overlap at the start (touching included, decided by overlaps()) hit at t = 0 with the
/// normal and first point of contact(a, b). A compound casts as the earliest of its child pairs.
/// Shapes stored in local frames cast with their transforms (shape_cast(a, xa, va, b, xb, vb,
/// max_t)): each is the exact image of its stored values under its transform (transform.hpp),
/// moving with it; the world-space cast is this with the identities.
///
/// Error contract (eps = cast_tolerance(a, xa, va, b, xb, vb, max_t), a distance):
/// - Never later than the first contact: for a Hit with t > 0, and for IterationLimit, the exact
///   shapes are apart (share no point) at every time in [0, t]. Nothing tunnels.
/// - Not much earlier: at a Hit's t the exact gap between the moved shapes is at most eps. (When
///   they go on to touch, the first contact follows once that gap has closed; a motion grazing
///   past within eps may be reported as a hit.)
/// - A Hit at t = 0 means the shapes overlap at the start or their exact gap there is <= eps;
///   shapes whose exact images overlap at the start always hit at t = 0.
/// - A Miss means the exact shapes are apart at every time in [0, max_t].
/// - eps = 3 * target + 2 eps_T |w| max_t + 2 denorm_min_T |w| + 2 delta, with w = va - vb, |.|
///   the largest component, target = kCastTargetFactor * 2^-53 * M + 2^-500 and M = S + |w| max_t
///   (S the largest absolute coordinate of both world bounding boxes, bounds(s, x), taken before
///   its outward rounding to T for a primitive placed by the identity): the rounding of the
///   moved cores, and of t down to T. delta = transform_tolerance(a, xa) +
///   transform_tolerance(b, xb) (overlap_tolerance(a, xa, b, xb); 0 for stored shapes placed by
///   the identity): the computed images lie within it of the exact ones, so the cast advances
///   them dilated by delta and the exact shapes stay apart wherever the dilated images do.
/// - Only the relative motion matters: the answer depends on va - vb (computed in double) alone,
///   and a pair is computed in one fixed order of its primitives, so swapping a and b (with
///   their transforms) gives the same t and the reversed normal, bit for bit.
/// - Defined answers everywhere: zero relative velocity, motion parallel to a face (a box sliding
///   along flat ground), shapes starting in contact. NaN or infinite input, max_t < 0, a velocity
///   beyond max_magnitude<T>() or a travel (|w|, |va| or |vb| times max_t) beyond
///   2 max_magnitude<T>() give
///   CastOutcome::InvalidInput. At most kCastMaxIterations steps per pair of primitives; beyond
///   that the answer is IterationLimit with the last time proven free of contact.
/// No allocation for shapes of at most 8 vertices (a compound's children are imaged one at a
/// time, never copied).
///
/// Leaving an overlap (CastOptions::stop_at_overlap = false): the start is ignored when the
/// motion does not close along the contact normal, so that a cast can carry shapes out of an
/// overlap. Exactly: when contact(a, xa, b, xb) exists (the computed images overlap at the start)
/// and its normal n satisfies n . (va - vb) <= 0 (in double), every pair of primitives that
/// touches at the start (whose advancement stops at s = 0: overlapping, or within eps) is left
/// out, and the answer is the first contact of the others, under the contract above: each pair
/// apart by more than eps at the start is apart on [0, t] (on [0, max_t] after a Miss), and a Hit
/// is within eps of a pair that did not overlap at the start. Two convex primitives meet over one
/// interval of time, so a pair left out never begins to touch again after it has come apart;
/// between two primitives the answer is then a Miss. Otherwise (no contact at the start, or a
/// motion that closes along n) the answer is the default one, bit for bit. The option decides the
/// shapes as a whole, by contact()'s normal: for compounds, pairs of children that touch at the
/// start are left out with the rest.
///
/// Method: conservative advancement on the dilated cores (detail/convex_core.hpp). Along any unit axis n
/// the separation is at most the gap and falls no faster than the closing speed n . w (plus its
/// rounding), so the time it takes to fall to target is a safe step, and the largest over all
/// axes is taken. Face normals do not turn under translation, so the faces of both cores bound
/// the motion once, from s = 0: for two polygons they are the faces of the Minkowski difference
/// and that one step reaches the first contact up to target (or proves a miss: a face separating
/// that does not close). Where that face meets a vertex over it, the vertex and its foot on the
/// face are the closest points, found without a search (face_witness()). Where the closest
/// points are two vertices, each in the other's normal cone, the next step reaches the disc of
/// that corner of the difference, aimed at 1.5 target: past the face step the motion lies within
/// every face's offset, where the way into the dilated difference leads through that disc. Else
/// each step takes the closest points' direction, and never less than the gap over |w| (which
/// always moves s), until the gap is within 2 target.
/// The start needs no separate test: shapes that overlap stop at s = 0, and contact() gives them
/// their normal and point.

#include "collide/compound.hpp"
#include "collide/detail/advance.hpp"
#include "collide/detail/convex_core.hpp"
#include "collide/overlaps.hpp"
#include "collide/tolerances.hpp"
#include "collide/shape_traits.hpp"
#include "collide/transform.hpp"
#include "collide/transformed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace collide {

/// Options of shape_cast().
struct CastOptions {
  /// true: shapes touching at the start hit at t = 0. false: the start is left out when the
  /// motion leaves the overlap (see "Leaving an overlap" at the top of cast.hpp).
  bool stop_at_overlap = true;
};

namespace detail {

/// The core moved by v (every point plus v, rounded).
inline Core moved_core(const Core& c, const Vec2c& v) {
  Core out;
  for (const Vec2c& p : c.pts()) out.push(p + v);
  out.radius = c.radius;
  return out;
}

/// A face of one of two cores: its owner (0: the first, 1: the second), its index (for_each_face()) and
/// its unit normal from the first core toward the second.
struct FaceAxis {
  int owner = -1;
  unsigned index = 0;
  Vec2c normal = Vec2c::Zero();
};

/// The closest points of the cores p and q (apart) when the point of the other core deepest along the
/// face's normal has its foot on the face: that point and its foot (the separation along the face is then
/// the gap). False when the foot falls off the face (a vertex meets a vertex), the point is not outside the
/// face, or there is no face.
inline bool face_witness(const Core& p, const Core& q, const FaceAxis& face, Closest& out) noexcept {
  if (face.owner < 0) return false;
  const Core& f = face.owner == 0 ? p : q;
  const Core& o = face.owner == 0 ? q : p;
  const Vec2c n = face.owner == 0 ? face.normal : Vec2c(-face.normal);  // outward from f
  const std::size_t i = f.size() == 2 ? 0 : face.index;
  const Vec2c a = f[i], d = f[i + 1 < f.size() ? i + 1 : 0] - a;
  std::size_t deepest = 0;
  for (std::size_t j = 1; j < o.size(); ++j) {
    if (o[j].dot(n) < o[deepest].dot(n)) deepest = j;
  }
  const Vec2c x = o[deepest];
  const Calc dd = d.squaredNorm(), along = (x - a).dot(d);
  if (!(dd > 0) || along < 0 || along > dd || !((x - a).dot(n) > 0)) return false;
  const Vec2c foot = a + d * (along / dd);
  out.dist2 = (x - foot).squaredNorm();
  out.on_p = face.owner == 0 ? foot : x;
  out.on_q = face.owner == 0 ? x : foot;
  return true;
}

/// Whether d, from vertex j of q to vertex i of p, lies in both vertices' normal cones: no edge
/// from vertex j of q leads toward d, and none from vertex i of p leads away from it.
inline bool in_vertex_cones(const Core& p, std::size_t i, const Core& q, std::size_t j, const Vec2c& d) noexcept {
  const auto outward = [](const Core& c, std::size_t k, const Vec2c& dir) {
    const std::size_t n = c.size();
    if (n == 1) return true;
    if (dir.dot(c[next_index(k, n)] - c[k]) > 0) return false;
    return n == 2 || dir.dot(c[k == 0 ? n - 1 : k - 1] - c[k]) <= 0;
  };
  return outward(q, j, d) && outward(p, i, Vec2c(-d));
}

/// The time a point at d from a fixed centre, moving by w per unit time, takes to come within aim
/// of it: +inf when it never does, 0 when it already is. Measured from the line's closest
/// approach, so that a grazing line keeps its accuracy.
inline Calc disc_entry_time(const Vec2c& d, const Vec2c& w, Calc aim) noexcept {
  const Calc speed = norm_of(w), dist = norm_of(d);
  if (!(dist > aim)) return 0;
  if (!(speed > 0)) return std::numeric_limits<Calc>::infinity();
  const Vec2c u = unit_of(w);
  const Calc along = -d.dot(u), off = std::fabs(d.x() * u.y() - d.y() * u.x());
  if (!(along > 0) || !(off < aim)) return std::numeric_limits<Calc>::infinity();
  const Calc chord = std::sqrt((aim - off) * (aim + off));
  return (dist - aim) / speed * ((dist + aim) / (along + chord));
}

/// Conservative advancement of core p moving by w per unit time against the fixed core q, from
/// s = 0 up to s_max; both dilated by skin in all (the images' distance from the exact shapes),
/// so that the exact shapes stay apart too. fp, fq: the cores' face normals as they stand
/// (part_of(), kept_faces()).
inline CoreCast advance_linear(const Core& p, const KeptFaces& fp, const Core& q, const KeptFaces& fq, const Vec2c& w,
                               Calc s_max, Calc target, Calc skin) {
  const Calc r = p.radius + q.radius + skin;
  // n . w is off by a few roundings of |w| (n is a rounded unit vector).
  const Calc closing_error = 4 * kUnitRoundoff * (std::fabs(w.x()) + std::fabs(w.y()));
  // The time the separation along unit n (never more than the gap) takes to fall to target at
  // the closing speed n . w: 0 when it is not above target, +inf when nothing closes along n.
  const auto safe_along = [&](const Core& pm, const Vec2c& n) {
    const Calc separation = separation_along(pm, q, n) - skin;
    const Calc closing = std::max(n.dot(w), Calc(0)) + closing_error;
    return separation > target ? (separation - target) / closing : Calc(0);
  };
  // Face normals do not turn under translation: fp and fq hold them for the whole advancement.
  const auto each_face = [&](auto&& f) {
    for_each_kept_face(fp, p, [&](const Vec2c& n, unsigned i) { f(FaceAxis{0, i, n}); });
    for_each_kept_face(fq, q, [&](const Vec2c& n, unsigned i) { f(FaceAxis{1, i, Vec2c(-n)}); });
  };
  const auto each_axis = [&](auto&& f) { each_face([&](const FaceAxis& face) { f(face.normal); }); };
  // Face axes first: under translation the separation along a fixed axis falls exactly linearly,
  // so every face's bound from s = 0 holds at once and the largest is safe. For polygons these
  // are the faces of the Minkowski difference: the largest is the first contact, up to target,
  // and its face meets the other core there (lead).
  Calc s = 0;
  FaceAxis lead;
  each_face([&](const FaceAxis& face) {
    const Calc ds = safe_along(p, face.normal);
    if (ds > s) s = ds, lead = face;
  });
  const bool apart = s > 0;
  if (apart && s > s_max) return CoreCast{CastOutcome::Miss, s_max, Vec2c::Zero(), Vec2c::Zero(), 1};
  for (int step = 0; step < kCastMaxIterations; ++step) {
    const Core pm = moved_core(p, w * s);
    if (!apart && step == 0 && cores_intersect(pm, q)) return hit_overlapping(pm, q, s, step);
    // Where the leading face meets a vertex over it, their distance is the gap and the face's normal
    // separates best: no search for the closest points.
    Closest cl;
    const bool on_face = step == 0 && face_witness(pm, q, lead, cl);
    if (!on_face) cl = closest_points(pm, q);
    const Calc gap = std::sqrt(cl.dist2) - r;
    if (gap <= 2 * target) return hit_between(pm, q, cl, s, step, on_face ? &lead.normal : nullptr, each_axis);
    // A vertex nearest a vertex, each in the other's normal cone: from within every face's
    // offset by target (where the face step leaves the moving core), the only way into the
    // dilated Minkowski difference leads through this corner's disc, so its entry time, aimed at
    // 1.5 target, is safe; it lands in one step where a grazing motion would otherwise shrink
    // its steps geometrically.
    Calc ds = 0;
    if (!on_face && !cl.feature_p.edge && !cl.feature_q.edge) {
      const std::size_t i = cl.feature_p.index, j = cl.feature_q.index;
      const Vec2c d = pm[i] - q[j];
      if (in_vertex_cones(pm, i, q, j, d)) ds = disc_entry_time(d, w, r + 1.5 * target);
    }
    // Else the closest points' direction.
    if (!(ds > 0)) {
      const Vec2c n = unit_of(cl.on_q - cl.on_p);
      ds = n == Vec2c::Zero() ? Calc(0) : safe_along(pm, n);
    }
    // Never less than the gap over |w|, which falls no faster: where rounding leaves the direction
    // separating by little more than target (or less), this bound carries the step. It moves s:
    // gap > 2 target here, and target >= 128 * 2^-53 |w|_max s (the motion's scale M is at least
    // |w|_max s_max in a cast, and |w|_max / 2 in time of impact, where s <= 1), so it exceeds
    // 90 * 2^-53 s, beyond half an ulp of s; +inf when w = 0.
    const Calc by_gap = (gap - target) / (norm_of(w) * (1 + kMotionBoundSlack));
    if (!(ds > by_gap)) ds = by_gap;
    if (s + ds > s_max) return CoreCast{CastOutcome::Miss, s_max, Vec2c::Zero(), Vec2c::Zero(), step + 1};
    s += ds;
  }
  return CoreCast{CastOutcome::IterationLimit, s, Vec2c::Zero(), Vec2c::Zero(), kCastMaxIterations};
}

/// One pair of primitives known apart at s = 0, advanced in the fixed order of core_before()
/// (the one moving at the relative velocity, the other still), with the point taken back to the
/// world frame of time s by the velocity of the one held still.
inline CoreCast cast_cores(const Part& p, const Vec2c& vp, const Part& q, const Vec2c& vq, Calc s_max, Calc target,
                           Calc skin) {
  const bool swap = core_before(q.core, p.core);
  CoreCast c = swap ? reversed(advance_linear(q.core, q.faces, p.core, p.faces, vq - vp, s_max, target, skin))
                    : advance_linear(p.core, p.faces, q.core, q.faces, vp - vq, s_max, target, skin);
  if (c.outcome == CastOutcome::Hit) c.point += (swap ? vp : vq) * c.s;
  return c;
}

/// The scale S of s placed by x: the largest absolute coordinate of its world bounding box,
/// bounds(s, x); for a primitive placed by the identity, of that box before its outward rounding.
template <AnyShape S>
Calc world_scale_of(const S& s, const Transform<scalar_of_t<S>>& x) {
  if (!x.is_identity()) return scale_of(bounds(s, x));
  return visit_shape(s, [](const auto& c) {
    if constexpr (is_compound_v<decltype(c)>) {
      return scale_of(bounds(c));
    } else {
      return scale_of(calc_box(c));
    }
  });
}

/// The motion's scale M: the largest coordinate the moving shapes reach (relative motion), from
/// their world bounding boxes (world_scale_of()).
template <AnyShape A, AnyShape B>
Calc cast_scale(const A& a, const Transform<scalar_of_t<A>>& xa, const B& b, const Transform<scalar_of_t<A>>& xb,
                const Vec2c& w, Calc max_t) {
  const Calc s = std::max(world_scale_of(a, xa), world_scale_of(b, xb));
  return s + w.cwiseAbs().maxCoeff() * max_t;
}

/// The inputs are finite and within range (see shape_cast's contract).
template <Scalar T>
bool cast_input_valid(const Vec2<T>& va, const Vec2<T>& vb, T max_t) noexcept {
  const Calc lim = static_cast<Calc>(max_magnitude<T>());
  const Calc m = static_cast<Calc>(max_t);
  if (!std::isfinite(m) || m < 0) return false;
  for (const Vec2<T>* v : {&va, &vb}) {
    for (int k = 0; k < 2; ++k) {
      const Calc x = static_cast<Calc>((*v)[k]);
      if (!std::isfinite(x) || std::fabs(x) > lim) return false;
    }
  }
  // Each shape's own travel too: the hit's point is reported in the world at time t.
  const Vec2c w = widen(va) - widen(vb);
  const Calc travel =
      std::max({w.cwiseAbs().maxCoeff(), widen(va).cwiseAbs().maxCoeff(), widen(vb).cwiseAbs().maxCoeff()});
  return travel * m <= 2 * lim;
}

}  // namespace detail

/// The distance bound eps of shape_cast()'s contract for this motion of a placed by xa and b
/// placed by xb (see the top of cast.hpp): at a hit's t the exact shapes are at most eps apart.
/// Inputs as for shape_cast().
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Calc
cast_tolerance(const A& a, const Transform<scalar_of_t<A>>& xa, const Vec2<scalar_of_t<A>>& va, const B& b,
               const Transform<scalar_of_t<A>>& xb, const Vec2<scalar_of_t<A>>& vb, scalar_of_t<A> max_t) {
  using T = scalar_of_t<A>;
  const Vec2c w = widen(va) - widen(vb);
  const Calc speed = w.cwiseAbs().maxCoeff();
  const Calc m = static_cast<Calc>(max_t);
  return 3 * detail::advance_target(detail::cast_scale(a, xa, b, xb, w, m)) +
         2 * Calc(std::numeric_limits<T>::epsilon()) * speed * m +
         2 * Calc(std::numeric_limits<T>::denorm_min()) * speed + 2 * overlap_tolerance(a, xa, b, xb);
}

/// cast_tolerance() of shapes in world space (both transforms the identity).
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Calc cast_tolerance(const A& a, const Vec2<scalar_of_t<A>>& va,
                                                                            const B& b, const Vec2<scalar_of_t<A>>& vb,
                                                                            scalar_of_t<A> max_t) {
  using X = Transform<scalar_of_t<A>>;
  return cast_tolerance(a, X(), va, b, X(), vb, max_t);
}

/// The first time in [0, max_t] at which a, stored in its local frame and placed by xa, moving at
/// va meets b placed by xb moving at vb (velocities in world distance per unit of t), with the
/// normal from a toward b and the point between the surfaces there, in world coordinates. Any
/// shape types, either order, one scalar. See the contract at the top of cast.hpp; options: see
/// CastOptions.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> CastResult<scalar_of_t<A>> shape_cast(
    const A& a, const Transform<scalar_of_t<A>>& xa, const Vec2<scalar_of_t<A>>& va, const B& b,
    const Transform<scalar_of_t<A>>& xb, const Vec2<scalar_of_t<A>>& vb, scalar_of_t<A> max_t,
    const CastOptions& options = {}) {
  using T = scalar_of_t<A>;
  if (!detail::cast_input_valid(va, vb, max_t)) return detail::invalid_cast<T>();
  const Vec2c wa = widen(va), wb = widen(vb), w = wa - wb;
  const Calc s_max = static_cast<Calc>(max_t);
  const Calc target = detail::advance_target(detail::cast_scale(a, xa, b, xb, w, s_max));
  const Calc skin = overlap_tolerance(a, xa, b, xb);
  // Leaving an overlap: the motion does not close along the contact normal at the start.
  bool leaving = false;
  if (!options.stop_at_overlap) {
    if (const auto c = contact(a, xa, b, xb)) leaving = !(widen(c->normal).dot(w) > 0);
  }
  const auto step = [&](const detail::Part& p, const detail::Part& q, Calc until) {
    const detail::CoreCast c = detail::cast_cores(p, wa, q, wb, until, target, skin);
    // A pair touching at the start is left out: a Miss to the bound, which every other answer beats.
    if (leaving && c.outcome == CastOutcome::Hit && c.s == 0) {
      return detail::CoreCast{CastOutcome::Miss, until, Vec2c::Zero(), Vec2c::Zero(), c.iterations};
    }
    return c;
  };
  const detail::CoreCast best = xa.is_identity() && xb.is_identity()
                                    ? detail::earliest_over_pairs(a, b, s_max, step)
                                    : detail::with_placed_pair(a, xa, b, xb, [&](const auto& pa, const auto& pb) {
                                        return detail::earliest_over_pairs(pa, pb, s_max, step);
                                      });
  CastResult<T> out = detail::to_result<T>(best, s_max);
  // Starting in contact (the computed images overlap, so the advancement stopped at once): the
  // normal and point of contact().
  if (out.hit() && out.t == T(0) && !leaving) {
    if (const auto c = contact(a, xa, b, xb)) {
      out.point = c->points[0];
      out.normal = c->normal;
    }
  }
  return out;
}

/// The first time in [0, max_t] at which a moving at va meets b moving at vb, both in world
/// space: shape_cast() with both transforms the identity. See the contract at the top of cast.hpp.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> CastResult<scalar_of_t<A>> shape_cast(
    const A& a, const Vec2<scalar_of_t<A>>& va, const B& b, const Vec2<scalar_of_t<A>>& vb, scalar_of_t<A> max_t,
    const CastOptions& options = {}) {
  using X = Transform<scalar_of_t<A>>;
  return shape_cast(a, X(), va, b, X(), vb, max_t, options);
}

}  // namespace collide
