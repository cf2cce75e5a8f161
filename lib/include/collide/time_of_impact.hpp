#pragma once
/// @file time_of_impact.hpp
/// Time of impact with rotation: two bodies, each moving its centre of rotation linearly and
/// turning at a constant rate over the step (as Box2D's b2Sweep), and the first time they touch.
///
/// Motion (the one definition, evaluated exactly as written here in double): for a time s, a
/// sweep's pose is sweep_pose(sweep, s):
///   angle = a0 + (a1 - a0) * s,  q = (cos angle, sin angle)  (std::cos, std::sin of the double),
///   c = c0 + (c1 - c0) * s,  position = c - R(q) local_center,
/// each operation rounded to double as written. The shape at time s is the exact image of its
/// stored local values under that pose: local point x maps to R(q) x + position computed exactly
/// (transform.hpp's meaning, with the pose's doubles), radii and half extents kept.
///
/// Error contract (eps = toi_tolerance(a, sweep_a, b, sweep_b, max_t), a distance):
/// - Never later than the first contact: for a Hit with t > 0 and for IterationLimit, the shapes
///   placed at every time s in [0, t] (both the posed images above and the continuous motion) are
///   apart.
/// - At a Hit's t the posed shapes are at most eps apart; a Hit at t = 0 means they overlap at
///   s = 0 or are within eps there.
/// - A Miss means the shapes are apart at every time in [0, max_t].
/// - eps = 3 * target + 2 eps_T V max_t + 2 denorm_min_T V + 2 delta, target =
///   kCastTargetFactor * 2^-53 * M + 2^-500, with V the bound on how fast any point of one body
///   moves relative to the other (|c1 - c0| + |a1 - a0| * rho per body, rho the reach of its core
///   from its centre of rotation), M the motion's scale: the positions' magnitude plus
///   (2 |local_center| + the shapes' scale) times (2 + |a0| + |a1|), which bounds the rounding of
///   the poses (large angles lose absolute accuracy in their cosines), and delta =
///   placement_tolerance(a) + placement_tolerance(b) (0 but for compounds whose children carry
///   transforms: their children's images lie within it of the exact ones).
/// - Defined answers for shapes that start in contact, for no motion, for pure rotation. NaN or
///   infinite input, max_t outside [0, 1], or a value beyond max_magnitude<T>() give
///   CastOutcome::InvalidInput; beyond kCastMaxIterations steps per pair of primitives the answer
///   is IterationLimit with the last time proven free of contact. No allocation for shapes of at
///   most 8 vertices.
///
/// Method: conservative advancement. Along any fixed axis n the separation falls no faster than
/// the centres' closing speed along n plus each body's turn rate times its reach, so the time it
/// takes to fall to target is a safe step; and each point's coordinate along n has a second
/// derivative of at most turn rate^2 times its arm, so a Taylor bound that follows the points
/// near the support (their rates now) gives a second, far larger step near contact. A face's
/// normal turns with its body, so along a face the separation is followed in that body's own
/// frame: there the face stands still and each point of the other body has its rate now and a
/// bounded second derivative (turn rates, relative speed and distance), a quadratic bound per
/// point that reaches target about where the turning face meets it. Each step takes the largest
/// over every face normal of both posed cores (the kept local normals turned by the pose) and
/// the closest points' direction. Every point of a body moves at most V per
/// unit of time relative to the other, so from a gap g the bodies cannot meet before
/// (g - target) / V: the least step (it always moves s), for when rounding leaves no axis
/// separating by much more than target. A
/// pair of bodies neither of which turns (a1 == a0) only translates: it is cast as shape_cast()
/// casts it, from the poses at s = 0 (two polygons in one step, a grazing corner through its
/// disc), its cores dilated by how far the poses' rounding strays from that translation. A
/// compound whose children carry their own transforms is advanced on its children's images,
/// which lie within placement_tolerance() of the exact ones: the cores are dilated by it, as
/// shape_cast() dilates by overlap_tolerance().

#include "collide/cast.hpp"
#include "collide/compound.hpp"
#include "collide/detail/advance.hpp"
#include "collide/detail/convex_core.hpp"
#include "collide/tolerances.hpp"
#include "collide/shape_traits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

namespace collide {

/// A body's motion over one step, for time_of_impact(): its centre of rotation moves linearly
/// from c0 to c1 while its angle goes linearly from a0 to a1 (radians, counter-clockwise).
template <Scalar T>
struct Sweep {
  Vec2<T> local_center = Vec2<T>::Zero();  ///< centre of rotation in the body's local frame
  Vec2<T> c0 = Vec2<T>::Zero();            ///< world position of the centre at time 0
  Vec2<T> c1 = Vec2<T>::Zero();            ///< world position of the centre at time 1
  T a0 = 0;                                ///< angle at time 0 (radians)
  T a1 = 0;                                ///< angle at time 1 (radians)
};

/// A body's pose at one time of its sweep, in double: a local point x is at R(rotation) x + position.
struct SweepPose {
  Vec2c rotation;  ///< (cos angle, sin angle) as computed (|rotation| is 1 up to rounding)
  Vec2c position;  ///< image of the local origin
};

namespace detail {

/// The rotation (cos angle, sin angle) of a sweep at time s, as its motion defines it.
template <Scalar T>
Vec2c sweep_rotation(const Sweep<T>& sweep, Calc s) noexcept {
  const Calc a0 = static_cast<Calc>(sweep.a0), a1 = static_cast<Calc>(sweep.a1);
  const Calc angle = a0 + (a1 - a0) * s;
  return Vec2c(std::cos(angle), std::sin(angle));
}

/// The pose of a sweep at time s, given its rotation at s (sweep_rotation()).
template <Scalar T>
SweepPose sweep_pose_with(const Sweep<T>& sweep, const Vec2c& rotation, Calc s) noexcept {
  const Calc c = rotation.x(), sn = rotation.y();
  const Vec2c c0 = widen(sweep.c0), c1 = widen(sweep.c1), lc = widen(sweep.local_center);
  const Calc cx = c0.x() + (c1.x() - c0.x()) * s, cy = c0.y() + (c1.y() - c0.y()) * s;
  const Calc rx = c * lc.x() - sn * lc.y(), ry = sn * lc.x() + c * lc.y();
  return SweepPose{rotation, Vec2c(cx - rx, cy - ry)};
}

/// Poses of one sweep at many times. A sweep that does not turn (a1 == a0) has the angle a0 + 0 * s, the same
/// double at every s >= 0, so its rotation is computed once: the same bits as sweep_pose() at every s.
template <Scalar T>
class SweepPoser {
 public:
  explicit SweepPoser(const Sweep<T>& sweep) noexcept
      : sweep_(sweep), turns_(sweep.a1 != sweep.a0), still_(turns_ ? Vec2c::Zero() : sweep_rotation(sweep, 0)) {}
  SweepPose operator()(Calc s) const noexcept {
    return sweep_pose_with(sweep_, turns_ ? sweep_rotation(sweep_, s) : still_, s);
  }

 private:
  const Sweep<T>& sweep_;
  bool turns_;
  Vec2c still_;
};

}  // namespace detail

/// The pose of a sweep at time s, computed exactly as time_of_impact.hpp's motion defines it.
template <Scalar T>
SweepPose sweep_pose(const Sweep<T>& sweep, Calc s) noexcept {
  return detail::sweep_pose_with(sweep, detail::sweep_rotation(sweep, s), s);
}

namespace detail {

/// Fills out with the core c placed by a pose (every point mapped and rounded).
inline void pose_core(const Core& c, const SweepPose& pose, Core& out) {
  out.clear();
  const Calc qc = pose.rotation.x(), qs = pose.rotation.y();
  for (const Vec2c& p : c.pts()) {
    out.push(Vec2c(qc * p.x() - qs * p.y() + pose.position.x(), qs * p.x() + qc * p.y() + pose.position.y()));
  }
  out.radius = c.radius;
}

/// The core of one sweep posed step after step. A sweep that does not move (c1 == c0, a1 == a0) adds
/// (c1 - c0) * s = ±0 of one sign to its position at every s >= 0, and its rotation is computed once
/// (SweepPoser), so its pose has the same bits at every s and the core is posed once.
template <Scalar T>
class PosedCore {
 public:
  PosedCore(const Core& local, const Sweep<T>& sweep, const SweepPoser<T>& poser)
      : local_(local), still_(sweep.c1 == sweep.c0 && sweep.a1 == sweep.a0) {
    if (still_) pose_core(local_, poser(0), core_);
  }
  /// The core placed by pose, the pose of the sweep at some s >= 0.
  const Core& at(const SweepPose& pose) {
    if (!still_) pose_core(local_, pose, core_);
    return core_;
  }

 private:
  const Core& local_;
  bool still_;
  Core core_;
};

/// n turned by the rotation (cos, sin).
inline Vec2c turned(const Vec2c& rotation, const Vec2c& n) noexcept {
  return Vec2c(rotation.x() * n.x() - rotation.y() * n.y(), rotation.y() * n.x() + rotation.x() * n.y());
}

/// The kept faces turned by the rotation (cos, sin); faces not all kept stay so (computed from the
/// posed core when asked).
inline KeptFaces turned_faces(const Vec2c& rotation, KeptFaces k) noexcept {
  if (k.complete) {
    for (std::size_t i = 0; i < k.count; ++i) k.normal[i] = turned(rotation, k.normal[i]);
  }
  return k;
}

/// Upper bound on how far any point of the local core lies from the centre of rotation.
inline Calc reach_of(const Core& c, const Vec2c& center) noexcept {
  Calc r = 0;
  for (const Vec2c& p : c.pts()) r = std::max(r, norm_of(p - center));
  return r * (1 + kMotionBoundSlack);
}

/// reach_of() for a sweep's core, or 0 when the sweep does not turn: every use of a reach multiplies it by the
/// turn rate's magnitude, which is then +0.
template <Scalar T>
Calc sweep_reach(const Sweep<T>& sw, const Core& local) noexcept {
  return sw.a1 != sw.a0 ? reach_of(local, widen(sw.local_center)) : Calc(0);
}

/// Upper bound on the speed of any point of the core relative to the centre's world frame, given its reach
/// (sweep_reach()).
template <Scalar T>
Calc sweep_speed(const Sweep<T>& sw, Calc reach) noexcept {
  const Calc travel = norm_of(widen(sw.c1) - widen(sw.c0));
  const Calc turn = std::fabs(static_cast<Calc>(sw.a1) - static_cast<Calc>(sw.a0));
  return (travel + turn * reach) * (1 + kMotionBoundSlack);
}

/// A sweep's contribution to the motion's scale M (see the contract at the top of this file).
template <Scalar T>
Calc sweep_scale(const Sweep<T>& sw, Calc shape_scale) noexcept {
  const Calc pos = std::max(widen(sw.c0).cwiseAbs().maxCoeff(), widen(sw.c1).cwiseAbs().maxCoeff());
  const Calc turns = 2 + std::fabs(static_cast<Calc>(sw.a0)) + std::fabs(static_cast<Calc>(sw.a1));
  return pos + (2 * widen(sw.local_center).cwiseAbs().maxCoeff() + shape_scale) * turns;
}

/// The offsets of a local core's points from its centre of rotation, kept for the bound on how fast each point
/// moves (at most 8 points; kept = false for a larger core).
struct Arms {
  std::array<Vec2c, 8> arm;
  bool kept = false;
};

inline Arms arms_of(const Core& local, const Vec2c& center) {
  Arms a;
  a.kept = local.size() <= a.arm.size();
  if (!a.kept) return a;
  for (std::size_t i = 0; i < local.size(); ++i) a.arm[i] = local[i] - center;
  return a;
}

/// How a posed core leads along a fixed unit axis n over the next stretch of time: for each of its points that
/// may lead (none both further behind the support and slower than another), how far it lies behind the support
/// and its rate now. With the curvature bound K of its motion, support(s + h) <= support + max_i(rate_i h -
/// behind_i) + K h^2 / 2 for every h >= 0 (each point's coordinate along n has a second derivative of at most
/// turn rate^2 times its arm).
struct Lead {
  std::array<Calc, 8> behind;
  std::array<Calc, 8> rate;
  std::size_t count = 0;
};

/// Lead of the posed core p (arms turned by rotation) moving its centre at velocity and turning at turn per unit
/// time, along n.
inline Lead lead_along(const Core& p, const Arms& arms, const Vec2c& rotation, const Vec2c& n, const Vec2c& velocity,
                       Calc turn) {
  std::array<Calc, 8> along, rate;
  Calc support = -std::numeric_limits<Calc>::infinity();
  const Calc slide = n.dot(velocity);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2c arm = turned(rotation, arms.arm[i]);
    along[i] = p[i].dot(n);
    rate[i] = slide + turn * (n.y() * arm.x() - n.x() * arm.y());
    support = std::max(support, along[i]);
  }
  Lead out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < p.size() && !dominated; ++j) {
      dominated =
          j != i && along[j] >= along[i] && rate[j] >= rate[i] && (along[j] > along[i] || rate[j] > rate[i] || j < i);
    }
    if (dominated) continue;
    out.behind[out.count] = support - along[i];
    out.rate[out.count++] = rate[i];
  }
  return out;
}

/// The first h >= 0 at which room - c h - k h^2 / 2 falls to 0 (room > 0, k >= 0): +inf when it never does.
inline Calc first_reach(Calc room, Calc c, Calc k) noexcept {
  const Calc den = c + std::sqrt(c * c + 2 * k * room);
  return den > 0 ? 2 * room / den : std::numeric_limits<Calc>::infinity();
}

/// The time the separation (room = separation - target > 0) of p leading along n and q along -n may take to fall
/// to target: the first reach of the quadratic bound of each pair of their leading points, less the rounding of
/// the rates (rate_error) and the slack of the result.
inline Calc lead_step(Calc room, const Lead& lp, const Lead& lq, Calc rate_error, Calc curvature) noexcept {
  Calc h = std::numeric_limits<Calc>::infinity();
  for (std::size_t i = 0; i < lp.count; ++i) {
    for (std::size_t j = 0; j < lq.count; ++j) {
      h = std::min(h, first_reach(room + lp.behind[i] + lq.behind[j], lp.rate[i] + lq.rate[j] + rate_error, curvature));
    }
  }
  return h * (1 - kMotionBoundSlack);
}

/// A body's motion at one time, for the bounds of a face that turns with it: its centre of rotation now, the
/// centre's velocity and the turn rate (per unit time).
struct BodyMotion {
  Vec2c center;
  Vec2c velocity;
  Calc turn = 0;
};

template <Scalar T>
BodyMotion body_motion(const Sweep<T>& sw, Calc s) noexcept {
  const Vec2c c0 = widen(sw.c0), c1 = widen(sw.c1);
  return BodyMotion{Vec2c(c0.x() + (c1.x() - c0.x()) * s, c0.y() + (c1.y() - c0.y()) * s), c1 - c0,
                    static_cast<Calc>(sw.a1) - static_cast<Calc>(sw.a0)};
}

/// How fast the points of the posed core o may leave the frame of a body f that turns (a face's normal and
/// support turn with f): in f's frame each point x of o moves with rate of separation
/// n . (v_o - v_f + w_o J (x - c_o) - w_f J (x - c_f)) along a face's unit normal n now, and its second derivative
/// is at most curvature = w_o^2 reach_o + 2 |w_f| U + w_f^2 (D + U remaining) up to time 1 (U bounds the speed of
/// o's points relative to c_f, D their distance from it now); rate_error bounds the rounding of the rates (the
/// offsets of o's points from either centre are differences of coordinates up to m in magnitude).
struct TurningFrame {
  Calc curvature = 0;
  Calc rate_error = 0;
};

inline TurningFrame turning_frame(const Core& o, const BodyMotion& mf, const BodyMotion& mo, Calc reach_o,
                                  Calc rate_error, Calc remaining) noexcept {
  Calc d = 0;
  Calc m = std::max(mf.center.cwiseAbs().maxCoeff(), mo.center.cwiseAbs().maxCoeff());
  for (const Vec2c& x : o.pts()) d = std::max(d, norm_of(x - mf.center)), m = std::max(m, x.cwiseAbs().maxCoeff());
  d *= 1 + kMotionBoundSlack;
  const Calc wf = std::fabs(mf.turn), wo = std::fabs(mo.turn);
  const Calc u = norm_of(mo.velocity - mf.velocity) * (1 + kMotionBoundSlack) + wo * reach_o;
  return TurningFrame{(wo * wo * reach_o + 2 * wf * u + wf * wf * (d + u * remaining)) * (1 + kMotionBoundSlack),
                      rate_error + 8 * kUnitRoundoff * (wf * (d + m) + wo * m)};
}

/// The time the separation along the outward unit normal n of a face of the posed core f, which turns with f,
/// may take to fall to target against the points of the posed core o (radii: both radii and the skin): each
/// point's separation falls at most at its rate now plus the frame's curvature (turning_frame()), and the first
/// reach of target over all points is safe. 0 when some point is not above target.
inline Calc turning_face_step(const Core& f, const BodyMotion& mf, const Core& o, const BodyMotion& mo,
                              const TurningFrame& frame, const Vec2c& n, Calc radii, Calc target) noexcept {
  const Calc base = support(f, n) + radii + target;
  const Calc slide = n.dot(mo.velocity - mf.velocity);
  Calc h = std::numeric_limits<Calc>::infinity();
  for (const Vec2c& x : o.pts()) {
    const Calc room = x.dot(n) - base;
    if (!(room > 0)) return 0;
    const Vec2c ao = x - mo.center, af = x - mf.center;
    const Calc rate = slide + mo.turn * (n.y() * ao.x() - n.x() * ao.y()) - mf.turn * (n.y() * af.x() - n.x() * af.y());
    h = std::min(h, first_reach(room, frame.rate_error - rate, frame.curvature));
  }
  return h * (1 - kMotionBoundSlack);
}

/// Conservative advancement of two local cores whose sweeps do not turn (a1 == a0): each pose only
/// translates, so the pair is cast as shape_cast() casts it (advance_linear()), from the cores posed at
/// s = 0 and at the difference of the centres' velocities, with the point taken to time s by the
/// velocity of q. A pose at s lies within jitter of the pose at 0 moved by (c1 - c0) s: the rounding
/// of c0 + (c1 - c0) s and of its offset by the rotated local centre, a few units of 2^-53 M per body
/// (M bounds every position; target / 4 is 64 of them), and of the velocities themselves over s <= 1.
/// The cores are dilated by it, so the posed shapes and the continuous motion stay apart wherever
/// the cast proves them apart; a hit's gap grows by at most 2 jitter, within the contract's eps.
/// fpl, fql: the local cores' face normals, turned here by the poses at s = 0.
template <Scalar T>
CoreCast advance_translating(const Core& pl, const KeptFaces& fpl, const Sweep<T>& sp, const Core& ql,
                             const KeptFaces& fql, const Sweep<T>& sq, Calc s_max, Calc target, Calc skin) {
  const SweepPose xp = sweep_pose(sp, 0), xq = sweep_pose(sq, 0);
  Core p, q;
  pose_core(pl, xp, p);
  pose_core(ql, xq, q);
  const Vec2c vp = widen(sp.c1) - widen(sp.c0), vq = widen(sq.c1) - widen(sq.c0);
  const Calc jitter = target / 4 + 4 * kUnitRoundoff * (vp.cwiseAbs().sum() + vq.cwiseAbs().sum());
  CoreCast c = advance_linear(p, turned_faces(xp.rotation, fpl), q, turned_faces(xq.rotation, fql), vp - vq, s_max,
                              target, skin + jitter);
  if (c.outcome == CastOutcome::Hit) c.point += vq * c.s;
  return c;
}

/// Conservative advancement of two local cores moved by their sweeps, from s = 0 to s_max, both dilated by skin
/// in all (the images' distance from the exact shapes). Along a fixed axis n the separation falls no faster than
/// n . (centre velocity of p - that of q) plus each body's turn rate times its reach, and along a face turning
/// with its body no faster than turning_face_step() allows, so every face normal of both posed cores and the
/// closest points' direction bound a safe step, and the largest is taken; when rounding leaves no axis separating by
/// more than target, the gap itself falls no faster than the bound on all motion. fp, fq: the local cores' face
/// normals (part_of()). A pair neither of which turns is advance_translating()'s.
template <Scalar T>
CoreCast advance_swept(const Core& pl, const KeptFaces& fp, const Sweep<T>& sp, const Core& ql, const KeptFaces& fq,
                       const Sweep<T>& sq, Calc s_max, Calc target, Calc skin) {
  if (sp.a1 == sp.a0 && sq.a1 == sq.a0) return advance_translating(pl, fp, sp, ql, fq, sq, s_max, target, skin);
  const Calc r = pl.radius + ql.radius + skin;
  const Calc reach_p = sweep_reach(sp, pl), reach_q = sweep_reach(sq, ql);
  const Calc speed = sweep_speed(sp, reach_p) + sweep_speed(sq, reach_q);
  const Vec2c v = (widen(sp.c1) - widen(sp.c0)) - (widen(sq.c1) - widen(sq.c0));
  const Calc turning = (std::fabs(static_cast<Calc>(sp.a1) - static_cast<Calc>(sp.a0)) * reach_p +
                        std::fabs(static_cast<Calc>(sq.a1) - static_cast<Calc>(sq.a0)) * reach_q) *
                       (1 + kMotionBoundSlack);
  const Calc closing_error =
      8 * kUnitRoundoff *
      ((widen(sp.c1) - widen(sp.c0)).cwiseAbs().sum() + (widen(sq.c1) - widen(sq.c0)).cwiseAbs().sum());
  // A Taylor bound on each point's motion: its rate now and turn rate^2 times its arm after.
  const Vec2c vp = widen(sp.c1) - widen(sp.c0), vq = widen(sq.c1) - widen(sq.c0);
  const Calc wp = static_cast<Calc>(sp.a1) - static_cast<Calc>(sp.a0);
  const Calc wq = static_cast<Calc>(sq.a1) - static_cast<Calc>(sq.a0);
  const Arms arms_p = arms_of(pl, widen(sp.local_center)), arms_q = arms_of(ql, widen(sq.local_center));
  const Calc rate_error = closing_error + 8 * kUnitRoundoff * turning;
  const Calc curvature = (wp * wp * reach_p + wq * wq * reach_q) * (1 + kMotionBoundSlack);
  // Without curvature (no point off a centre turns) the Taylor bound is the linear one.
  const bool taylor = arms_p.kept && arms_q.kept && curvature > 0;
  const SweepPoser pose_p(sp), pose_q(sq);
  PosedCore posed_p(pl, sp, pose_p), posed_q(ql, sq, pose_q);
  Calc s = 0;
  for (int step = 0; step < kCastMaxIterations; ++step) {
    const SweepPose xp = pose_p(s), xq = pose_q(s);
    const Core &p = posed_p.at(xp), &q = posed_q.at(xq);
    // The posed faces' normals: the kept local ones turned by the pose (unit to a few roundings, well inside
    // target), from p toward q.
    const auto each_axis = [&](auto&& f) {
      if (fp.complete) {
        for (std::size_t i = 0; i < fp.count; ++i) f(turned(xp.rotation, fp.normal[i]));
      } else {
        for_each_face(p, [&](const Vec2c& n, unsigned) { f(n); });
      }
      if (fq.complete) {
        for (std::size_t i = 0; i < fq.count; ++i) f(Vec2c(-turned(xq.rotation, fq.normal[i])));
      } else {
        for_each_face(q, [&](const Vec2c& n, unsigned) { f(Vec2c(-n)); });
      }
    };
    // The separation along a fixed axis falling at the bound on all motion along it.
    const auto linear_along = [&](const Vec2c& n, Calc separation) {
      const Calc closing = std::max(n.dot(v), Calc(0)) + turning + closing_error;
      return separation > target ? (separation - target) / closing : Calc(0);  // +inf when still
    };
    // The closest points' direction is fixed: the larger of the linear step and the leads' Taylor bound (which
    // follows the points that can touch).
    const auto safe_along = [&](const Vec2c& n) {
      const Calc separation = separation_along(p, q, n) - skin;
      const Calc linear = linear_along(n, separation);
      if (!taylor || !(linear > 0)) return linear;
      const Lead lp = lead_along(p, arms_p, xp.rotation, n, vp, wp);
      const Lead lq = lead_along(q, arms_q, xq.rotation, Vec2c(-n), vq, wq);
      return std::max(linear, lead_step(separation - target, lp, lq, rate_error, curvature));
    };
    // Every face's linear step, and the face separating most (widest). A face's normal turns with its body:
    // along the widest, the bound that follows the face as it turns (turning_face_step()) as well; where it
    // meets a vertex over it, their distance is the gap.
    FaceAxis widest;
    Calc widest_separation = -std::numeric_limits<Calc>::infinity(), ds = 0;
    const auto face = [&](const FaceAxis& axis) {
      const Calc separation = separation_along(p, q, axis.normal) - skin;
      if (separation > widest_separation) widest_separation = separation, widest = axis;
      ds = std::max(ds, linear_along(axis.normal, separation));
    };
    if (fp.complete) {
      for (std::size_t i = 0; i < fp.count; ++i) face(FaceAxis{0, fp.index[i], turned(xp.rotation, fp.normal[i])});
    } else {
      for_each_face(p, [&](const Vec2c& n, unsigned i) { face(FaceAxis{0, i, n}); });
    }
    if (fq.complete) {
      for (std::size_t i = 0; i < fq.count; ++i) {
        face(FaceAxis{1, fq.index[i], Vec2c(-turned(xq.rotation, fq.normal[i]))});
      }
    } else {
      for_each_face(q, [&](const Vec2c& m, unsigned i) { face(FaceAxis{1, i, Vec2c(-m)}); });
    }
    if (ds > 0) {
      // Bounded up to time 1, not s_max: a pair's steps must not depend on how far the query follows it (the
      // earliest of the pairs before it), so that swapping the shapes gives the same bits.
      const BodyMotion mp = body_motion(sp, s), mq = body_motion(sq, s);
      const Calc turning_step =
          widest.owner == 0 ? turning_face_step(p, mp, q, mq, turning_frame(q, mp, mq, reach_q, rate_error, 1 - s),
                                                widest.normal, r, target)
                            : turning_face_step(q, mq, p, mp, turning_frame(p, mq, mp, reach_p, rate_error, 1 - s),
                                                Vec2c(-widest.normal), r, target);
      ds = std::max(ds, turning_step);
    }
    if (s == 0 && !(ds > 0) && cores_intersect(p, q)) return hit_overlapping(p, q, s, step);
    Closest cl;
    const bool on_face = face_witness(p, q, widest, cl);
    if (!on_face) cl = closest_points(p, q);
    const Calc gap = std::sqrt(cl.dist2) - r;
    const auto hit = [&] { return hit_between(p, q, cl, s, step, on_face ? &widest.normal : nullptr, each_axis); };
    if (gap <= 2 * target) return hit();
    // The closest points' direction (when not the widest face's normal, already bounded).
    const Vec2c n = unit_of(cl.on_q - cl.on_p);
    if (!on_face && n != Vec2c::Zero()) ds = std::max(ds, safe_along(n));
    // Never less than the gap over the bound on all motion. It moves s: gap > 2 target here, and
    // speed <= 2.9 M (the travel of each centre is at most twice its position's magnitude, each
    // turn times reach at most its share of M), so it exceeds 2^-53, beyond half an ulp of s <= 1;
    // +inf when nothing moves.
    const Calc by_gap = (gap - target) / speed;
    if (!(ds > by_gap)) ds = by_gap;
    if (s + ds > s_max) return CoreCast{CastOutcome::Miss, s_max, Vec2c::Zero(), Vec2c::Zero(), step + 1};
    s += ds;
  }
  return CoreCast{CastOutcome::IterationLimit, s, Vec2c::Zero(), Vec2c::Zero(), kCastMaxIterations};
}

template <Scalar T>
bool sweep_valid(const Sweep<T>& sw) noexcept {
  const Calc lim = static_cast<Calc>(max_magnitude<T>());
  const T values[] = {sw.local_center.x(), sw.local_center.y(), sw.c0.x(), sw.c0.y(),
                      sw.c1.x(),           sw.c1.y(),           sw.a0,     sw.a1};
  for (const T v : values) {
    const Calc x = static_cast<Calc>(v);
    if (!std::isfinite(x) || std::fabs(x) > lim) return false;
  }
  return true;
}

/// The motion's scale M of a pair of sweeps.
template <AnyShape A, AnyShape B>
Calc toi_scale(const A& a, const Sweep<scalar_of_t<A>>& sa, const B& b, const Sweep<scalar_of_t<A>>& sb) {
  const Transform<scalar_of_t<A>> local;
  return sweep_scale(sa, world_scale_of(a, local)) + sweep_scale(sb, world_scale_of(b, local));
}

/// Upper bound on the relative speed of any two points of the bodies.
template <AnyShape A, AnyShape B>
Calc toi_speed(const A& a, const Sweep<scalar_of_t<A>>& sa, const B& b, const Sweep<scalar_of_t<A>>& sb) {
  Calc v = 0;
  visit_shape(a, [&](const auto& ca) {
    for_each_primitive(ca, [&](const auto& pa) { v = std::max(v, sweep_speed(sa, sweep_reach(sa, core_of(pa)))); });
  });
  Calc w = 0;
  visit_shape(b, [&](const auto& cb) {
    for_each_primitive(cb, [&](const auto& pb) { w = std::max(w, sweep_speed(sb, sweep_reach(sb, core_of(pb)))); });
  });
  return v + w;
}

}  // namespace detail

/// The distance bound eps of time_of_impact()'s contract for these sweeps (see the top of
/// time_of_impact.hpp): at a hit's t the posed shapes are at most eps apart.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Calc toi_tolerance(const A& a, const Sweep<scalar_of_t<A>>& sa,
                                                                           const B& b, const Sweep<scalar_of_t<A>>& sb,
                                                                           scalar_of_t<A> max_t) {
  using T = scalar_of_t<A>;
  const Calc speed = detail::toi_speed(a, sa, b, sb);
  return 3 * detail::advance_target(detail::toi_scale(a, sa, b, sb)) +
         2 * Calc(std::numeric_limits<T>::epsilon()) * speed * static_cast<Calc>(max_t) +
         2 * Calc(std::numeric_limits<T>::denorm_min()) * speed + 2 * (placement_tolerance(a) + placement_tolerance(b));
}

/// The first time in [0, max_t] (max_t <= 1) at which shape a, stored in its body's local frame
/// and moved by sweep_a, meets b moved by sweep_b; the normal from a toward b and the point
/// between the surfaces there, in world coordinates. See the contract at the top of this file.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> CastResult<scalar_of_t<A>> time_of_impact(
    const A& a, const Sweep<scalar_of_t<A>>& sweep_a, const B& b, const Sweep<scalar_of_t<A>>& sweep_b,
    scalar_of_t<A> max_t = 1) {
  using T = scalar_of_t<A>;
  const Calc s_max = static_cast<Calc>(max_t);
  if (!detail::sweep_valid(sweep_a) || !detail::sweep_valid(sweep_b) || !(s_max >= 0 && s_max <= 1)) {
    return detail::invalid_cast<T>();
  }
  const Calc target = detail::advance_target(detail::toi_scale(a, sweep_a, b, sweep_b));
  const Calc skin = placement_tolerance(a) + placement_tolerance(b);
  const detail::CoreCast best =
      detail::earliest_over_pairs(a, b, s_max, [&](const detail::Part& p, const detail::Part& q, Calc until) {
        return detail::core_before(q.core, p.core)
                   ? detail::reversed(
                         detail::advance_swept(q.core, q.faces, sweep_b, p.core, p.faces, sweep_a, until, target, skin))
                   : detail::advance_swept(p.core, p.faces, sweep_a, q.core, q.faces, sweep_b, until, target, skin);
      });
  return detail::to_result<T>(best, s_max);
}

}  // namespace collide
