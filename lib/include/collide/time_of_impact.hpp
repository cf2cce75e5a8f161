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
/// - eps = 3 * target + 2 eps_T V max_t + 2 denorm_min_T V, target = kCastTargetFactor * 2^-53 * M
///   + 2^-500, with V the bound on how fast any point of one body moves relative to the other
///   (|c1 - c0| + |a1 - a0| * rho per body, rho the reach of its core from its centre of rotation)
///   and M the motion's scale: the positions' magnitude plus (2 |local_center| + the shapes' scale)
///   times (2 + |a0| + |a1|), which bounds the rounding of the poses (large angles lose absolute
///   accuracy in their cosines).
/// - Defined answers for shapes that start in contact, for no motion, for pure rotation. NaN or
///   infinite input, max_t outside [0, 1], or a value beyond max_magnitude<T>() give
///   CastOutcome::InvalidInput; beyond kCastMaxIterations steps per pair of primitives the answer
///   is IterationLimit with the last time proven free of contact. No allocation for shapes of at
///   most 8 vertices.
///
/// Method: conservative advancement. Along the best separating axis n (a face normal or the
/// closest points' direction) the separation falls no faster than the centres' closing speed
/// along n plus each body's turn rate times its reach; and every point of a body moves at most V
/// per unit of time relative to the other, so from a gap g the bodies cannot meet before
/// (g - target) / V. A step advances by the axis bound, or by the gap bound when rounding leaves
/// no axis separating by more than target.

#include "collide/cast.hpp"
#include "collide/compound.hpp"
#include "collide/detail/advance.hpp"
#include "collide/detail/core.hpp"
#include "collide/shape_traits.hpp"

#include <algorithm>
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

/// The pose of a sweep at time s, computed exactly as time_of_impact.hpp's motion defines it.
template <Scalar T>
SweepPose sweep_pose(const Sweep<T>& sweep, Calc s) noexcept {
  const Calc a0 = static_cast<Calc>(sweep.a0), a1 = static_cast<Calc>(sweep.a1);
  const Calc angle = a0 + (a1 - a0) * s;
  const Calc c = std::cos(angle), sn = std::sin(angle);
  const Vec2c c0 = widen(sweep.c0), c1 = widen(sweep.c1), lc = widen(sweep.local_center);
  const Calc cx = c0.x() + (c1.x() - c0.x()) * s, cy = c0.y() + (c1.y() - c0.y()) * s;
  const Calc rx = c * lc.x() - sn * lc.y(), ry = sn * lc.x() + c * lc.y();
  return SweepPose{Vec2c(c, sn), Vec2c(cx - rx, cy - ry)};
}

namespace detail {

/// The core placed by a pose (every point mapped and rounded).
inline Core posed_core(const Core& c, const SweepPose& pose) {
  Core out;
  const Calc qc = pose.rotation.x(), qs = pose.rotation.y();
  for (const Vec2c& p : c.pts()) {
    out.push(Vec2c(qc * p.x() - qs * p.y() + pose.position.x(), qs * p.x() + qc * p.y() + pose.position.y()));
  }
  out.radius = c.radius;
  return out;
}

/// Upper bound on how far any point of the local core lies from the centre of rotation.
inline Calc reach_of(const Core& c, const Vec2c& center) noexcept {
  Calc r = 0;
  for (const Vec2c& p : c.pts()) r = std::max(r, norm_of(p - center));
  return r * (1 + kMotionBoundSlack);
}

/// Upper bound on the speed of any point of the core relative to the centre's world frame.
template <Scalar T>
Calc sweep_speed(const Sweep<T>& sw, const Core& local) noexcept {
  const Calc travel = norm_of(widen(sw.c1) - widen(sw.c0));
  const Calc turn = std::fabs(static_cast<Calc>(sw.a1) - static_cast<Calc>(sw.a0));
  return (travel + turn * reach_of(local, widen(sw.local_center))) * (1 + kMotionBoundSlack);
}

/// A sweep's contribution to the motion's scale M (see the contract at the top of this file).
template <Scalar T>
Calc sweep_scale(const Sweep<T>& sw, Calc shape_scale) noexcept {
  const Calc pos = std::max(widen(sw.c0).cwiseAbs().maxCoeff(), widen(sw.c1).cwiseAbs().maxCoeff());
  const Calc turns = 2 + std::fabs(static_cast<Calc>(sw.a0)) + std::fabs(static_cast<Calc>(sw.a1));
  return pos + (2 * widen(sw.local_center).cwiseAbs().maxCoeff() + shape_scale) * turns;
}

/// Conservative advancement of two local cores moved by their sweeps, from s = 0 to s_max.
/// Along a fixed axis n the separation falls no faster than n . (centre velocity of p - that of q)
/// plus each body's turn rate times its reach, so a translating pair steps as a linear cast does
/// (a box sliding along flat ground is a miss in one step); when rounding leaves no axis
/// separating by more than target, the gap itself falls no faster than the bound on all motion.
template <Scalar T>
CoreCast advance_swept(const Core& pl, const Sweep<T>& sp, const Core& ql, const Sweep<T>& sq, Calc s_max,
                       Calc target) {
  const Calc r = pl.radius + ql.radius;
  const Calc speed = sweep_speed(sp, pl) + sweep_speed(sq, ql);
  const Vec2c vp = widen(sp.c1) - widen(sp.c0), vq = widen(sq.c1) - widen(sq.c0);
  const Calc turning =
      (std::fabs(static_cast<Calc>(sp.a1) - static_cast<Calc>(sp.a0)) * reach_of(pl, widen(sp.local_center)) +
       std::fabs(static_cast<Calc>(sq.a1) - static_cast<Calc>(sq.a0)) * reach_of(ql, widen(sq.local_center))) *
      (1 + kMotionBoundSlack);
  const Calc closing_error = 8 * kUnitRoundoff * (vp.cwiseAbs().sum() + vq.cwiseAbs().sum());
  Calc s = 0;
  for (int step = 0; step < kCastMaxIterations; ++step) {
    const Core p = posed_core(pl, sweep_pose(sp, s)), q = posed_core(ql, sweep_pose(sq, s));
    if (s == 0 && cores_intersect(p, q)) return hit_overlapping(p, q, s, step);
    const Closest cl = closest_points(p, q);
    const Calc gap = std::sqrt(cl.dist2) - r;
    if (gap <= 2 * target) return hit_between(p, q, cl, s, step);
    const Vec2c n = best_axis(p, q, cl);
    const Calc separation = separation_along(p, q, n);
    const Calc closing = std::max(n.dot(vp - vq), Calc(0)) + turning + closing_error;
    Calc ds = separation > target ? (separation - target) / closing : Calc(0);  // +inf when still
    if (!(ds > 0)) ds = (gap - target) / speed;
    if (!(ds > 0)) return hit_between(p, q, cl, s, step);
    if (s + ds >= s_max) return CoreCast{CastOutcome::Miss, s_max, Vec2c::Zero(), Vec2c::Zero(), step + 1};
    const Calc next = s + ds;
    if (!(next > s)) return hit_between(p, q, cl, s, step);
    s = next;
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
  return sweep_scale(sa, scale_of(bounds(a))) + sweep_scale(sb, scale_of(bounds(b)));
}

/// Upper bound on the relative speed of any two points of the bodies.
template <AnyShape A, AnyShape B>
Calc toi_speed(const A& a, const Sweep<scalar_of_t<A>>& sa, const B& b, const Sweep<scalar_of_t<A>>& sb) {
  Calc v = 0;
  visit_shape(a, [&](const auto& ca) {
    for_each_primitive(ca, [&](const auto& pa) { v = std::max(v, sweep_speed(sa, core_of(pa))); });
  });
  Calc w = 0;
  visit_shape(b, [&](const auto& cb) {
    for_each_primitive(cb, [&](const auto& pb) { w = std::max(w, sweep_speed(sb, core_of(pb))); });
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
         2 * Calc(std::numeric_limits<T>::denorm_min()) * speed;
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
  const detail::CoreCast best =
      detail::earliest_over_pairs(a, b, s_max, [&](const detail::Core& p, const detail::Core& q, Calc until) {
        return detail::core_before(q, p)
                   ? detail::reversed(detail::advance_swept(q, sweep_b, p, sweep_a, until, target))
                   : detail::advance_swept(p, sweep_a, q, sweep_b, until, target);
      });
  return detail::to_result<T>(best, s_max);
}

}  // namespace collide
