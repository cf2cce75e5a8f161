/// @file cast_laws.cpp
/// The laws of shape_cast() and time_of_impact(), judged by the exact oracle for moving shapes
/// (oracle::meets_during, oracle::meets_posed). See laws.hpp for each law's statement.

#include "collide/cast.hpp"
#include "collide/time_of_impact.hpp"
#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace collide::laws {

namespace {

using detail::describe;
using detail::num;
using detail::vec;

std::string_view outcome_name(CastOutcome o) {
  switch (o) {
    case CastOutcome::Hit:
      return "hit";
    case CastOutcome::Miss:
      return "miss";
    case CastOutcome::IterationLimit:
      return "iteration limit";
    case CastOutcome::InvalidInput:
      return "invalid input";
  }
  return "?";
}

template <Scalar T>
std::string describe_result(const CastResult<T>& r) {
  std::string out(outcome_name(r.outcome));
  out += " t=" + num(double(r.t)) + " point=" + vec(r.point) + " normal=" + vec(r.normal) +
         " iterations=" + std::to_string(r.iterations);
  return out;
}

/// Fails the verdict (first failure kept).
void fail(Verdict& v, const std::string& expected, const std::string& got) {
  if (!v.ok) return;
  v.ok = false;
  v.expected = expected;
  v.got = got;
  v.account += "; FAILED: expected " + expected + ", got " + got;
}

/// Largest extent of a placed shape's bounding box.
template <Scalar T>
double size_of(const Shape<T>& s, const Transform<T>& x) {
  const Aabb<T> b = bounds(s, x);
  return (widen(b.max()) - widen(b.min())).maxCoeff();
}

/// A point shape (zero-radius circle) for distance questions, or nullopt beyond the range.
std::optional<Shape<double>> point_shape(const Vec2<double>& p) {
  auto c = Circle<double>::make(p, 0.0);
  if (!c) return std::nullopt;
  return Shape<double>(c.value());
}

/// The point q lies farther than d from s moving at v, at time t (exact); true when q cannot be
/// represented (it then lies beyond every shape of the range).
template <Scalar T>
bool far_at(const Vec2<double>& q, const oracle::Placed& s, const Vec2<T>& v, double t, double d) {
  if (d <= 0) return true;
  const auto p = point_shape(q);
  if (!p) return true;
  return !oracle::exact::meets_during(*p, Vec2<double>(0, 0), s, v.template cast<double>(), t, t, d);
}

/// A shape and its placement, for accounts (the placement only when it is not the identity).
template <Scalar T>
std::string describe_placed(const Shape<T>& s, const Transform<T>& x) {
  if (x.is_identity()) return describe(s);
  return describe(s) + " placed at p=" + vec(x.position()) + " q=" + vec(x.rotation());
}

/// The parts of s: each child of a compound as a one-child compound under its own transform, or s.
template <Scalar T>
std::vector<Shape<T>> parts_of(const Shape<T>& s) {
  std::vector<Shape<T>> out;
  if (const auto* c = std::get_if<Compound<T>>(&s)) {
    for (std::size_t i = 0; i < c->children().size(); ++i) {
      out.push_back(Compound<T>::make_placed({{c->children()[i], c->child_transform(i)}}).value());
    }
  } else {
    out.push_back(s);
  }
  return out;
}

/// The exact primitives of s placed by x, one oracle input each (a compound child under its own
/// transform, then under x).
template <Scalar T>
std::vector<oracle::Placed> placed_parts(const Shape<T>& s, const Transform<T>& x) {
  std::vector<oracle::Placed> out;
  for (const Shape<T>& part : parts_of(s)) out.push_back(oracle::placed(part, x));
  return out;
}

/// The cast the input asks for: the world-space overload when both transforms are the identity.
template <Scalar T>
CastResult<T> cast_of(const Shape<T>& a, const Shape<T>& b, const CastInput<T>& in) {
  if (in.xa.is_identity() && in.xb.is_identity()) return shape_cast(a, in.va, b, in.vb, in.max_t);
  return shape_cast(a, in.xa, in.va, b, in.xb, in.vb, in.max_t);
}

/// A hit's normal and point where the shapes are apart at t: the normal points from a toward b
/// (beyond the point along it lies only b's side, and back along it only a's; for compounds, for
/// some pair of parts, the pair that met), and the point lies between the two surfaces, within the
/// gap (<= eps) of both. far_a(x, s, d): x lies farther than d from s (a or one of its parts) at t;
/// far_b likewise for b. size: the larger of the shapes' sizes.
template <Scalar T, class Part, class FarA, class FarB>
void judge_normal_and_point(Verdict& v, const CastResult<T>& r, double size, double eps, const Part& a,
                            const std::vector<Part>& parts_a, FarA&& far_a, const Part& b,
                            const std::vector<Part>& parts_b, FarB&& far_b) {
  const double L = std::max(size, 256 * eps);
  const Vec2<double> p = widen(r.point), n = widen(r.normal);
  // A normal found at a gap of a few roundings is good to about 1/100 rad: L / 32 of slack.
  const double slack = 2 * eps + 16 * detail::eps<T>() * (L + p.cwiseAbs().maxCoeff()) + L / 32;
  bool sides = false;
  for (const Part& ca : parts_a) {
    for (const Part& cb : parts_b) {
      sides = sides || (far_a(Vec2<double>(p + n * L), ca, L - slack) && far_b(Vec2<double>(p - n * L), cb, L - slack));
    }
  }
  if (!sides)
    fail(v, "point + L normal at least L - slack from a and point - L normal from b (normal toward b)",
         describe_result(r));
  const double reach = 2 * eps + 8 * detail::eps<T>() * (std::fabs(p.x()) + std::fabs(p.y()));
  if (far_a(p, a, reach) || far_b(p, b, reach))
    fail(v, "the point within the tolerance of both shapes at t", describe_result(r));
}

/// The account of a cast input: both shapes with their placements, the motion.
template <Scalar T>
std::string describe_input(const Shape<T>& a, const Shape<T>& b, const CastInput<T>& in) {
  return describe_placed(a, in.xa) + ", va=" + vec(in.va) + ", " + describe_placed(b, in.xb) + ", vb=" + vec(in.vb) +
         ", max_t=" + num(double(in.max_t));
}

}  // namespace

template <Scalar T>
Verdict cast_law(const Shape<T>& a, const Shape<T>& b, const CastInput<T>& in) {
  Verdict v;
  const CastResult<T> r = cast_of(a, b, in);
  const double eps = cast_tolerance(a, in.xa, in.va, b, in.xb, in.vb, in.max_t);
  const double t = double(r.t), max_t = double(in.max_t);
  const oracle::Placed ea = oracle::placed(a, in.xa), eb = oracle::placed(b, in.xb);
  const bool start = oracle::overlaps(ea, eb);
  v.relation = start ? Relation::Overlapping : Relation::Separated;
  v.account = "shape_cast(" + describe_input(a, b, in) + ") = " + describe_result(r) + ", tolerance " + num(eps);
  if (r.outcome == CastOutcome::InvalidInput) {
    fail(v, "a valid answer for valid input", "invalid input");
    return v;
  }
  if (!(t >= 0 && t <= max_t)) fail(v, "0 <= t <= max_t", num(t));
  if (start && !(r.hit() && r.t == T(0)))
    fail(v, "a hit at t = 0 (the shapes overlap at the start)", describe_result(r));
  if (!v.ok) return v;
  switch (r.outcome) {
    case CastOutcome::Miss:
      if (oracle::meets_during(ea, in.va, eb, in.vb, 0.0, max_t))
        fail(v, "no contact in [0, max_t] after a miss", "the exact shapes meet in [0, max_t]");
      break;
    case CastOutcome::IterationLimit:
      if (oracle::meets_during(ea, in.va, eb, in.vb, 0.0, t))
        fail(v, "apart on [0, t] at the iteration limit", "the exact shapes meet in [0, t]");
      break;
    case CastOutcome::Hit: {
      const double len = std::hypot(double(r.normal.x()), double(r.normal.y()));
      if (!(std::fabs(len - 1) <= 8 * detail::eps<T>())) fail(v, "a unit normal", "|normal| = " + num(len));
      if (start) {
        // The computed images may be apart within their tolerance: then no contact to compare.
        const auto c = contact(a, in.xa, b, in.xb);
        if (c && (c->normal != r.normal || c->points[0] != r.point))
          fail(v, "contact(a, xa, b, xb)'s normal and first point at t = 0", describe_result(r));
        if (!c && !oracle::within_band(ea, eb, overlap_tolerance(a, in.xa, b, in.xb)))
          fail(v, "contact(a, xa, b, xb) for shapes overlapping beyond the transforms' band", "none");
        break;
      }
      // Never later than the first contact: apart over [0, t] (t > 0), and within eps at t.
      if (t > 0 && oracle::meets_during(ea, in.va, eb, in.vb, 0.0, t))
        fail(v, "apart on [0, t] (t no later than the first contact)", "the exact shapes meet in [0, t]: tunnelled");
      if (!oracle::meets_during(ea, in.va, eb, in.vb, t, t, eps))
        fail(v, "the exact shapes within the tolerance at t", "farther apart at t");
      judge_normal_and_point(
          v, r, std::max(size_of(a, in.xa), size_of(b, in.xb)), eps, ea, placed_parts(a, in.xa),
          [&](const Vec2<double>& x, const oracle::Placed& s, double d) { return far_at(x, s, in.va, t, d); }, eb,
          placed_parts(b, in.xb),
          [&](const Vec2<double>& x, const oracle::Placed& s, double d) { return far_at(x, s, in.vb, t, d); });
      break;
    }
    case CastOutcome::InvalidInput:
      break;
  }
  return v;
}

template <Scalar T>
Verdict cast_leaving(const Shape<T>& a, const Shape<T>& b, const CastInput<T>& in) {
  Verdict v;
  CastOptions leave;
  leave.stop_at_overlap = false;
  const CastResult<T> r = in.xa.is_identity() && in.xb.is_identity()
                              ? shape_cast(a, in.va, b, in.vb, in.max_t, leave)
                              : shape_cast(a, in.xa, in.va, b, in.xb, in.vb, in.max_t, leave);
  const double eps = cast_tolerance(a, in.xa, in.va, b, in.xb, in.vb, in.max_t);
  const double t = double(r.t), max_t = double(in.max_t);
  const oracle::Placed ea = oracle::placed(a, in.xa), eb = oracle::placed(b, in.xb);
  v.relation = oracle::overlaps(ea, eb) ? Relation::Overlapping : Relation::Separated;
  const auto c = contact(a, in.xa, b, in.xb);
  const bool leaving = c && !(widen(c->normal).dot(widen(in.va) - widen(in.vb)) > 0);
  v.account = "shape_cast(" + describe_input(a, b, in) + ", leaving an overlap) = " + describe_result(r) +
              ", tolerance " + num(eps) +
              (c ? ", contact normal " + vec(c->normal) + (leaving ? " (leaving)" : " (closing)") : ", no contact");
  if (r.outcome == CastOutcome::InvalidInput) {
    fail(v, "a valid answer for valid input", "invalid input");
    return v;
  }
  if (!leaving) {
    const CastResult<T> d = cast_of(a, b, in);
    if (r.outcome != d.outcome || r.t != d.t || r.normal != d.normal || r.point != d.point)
      fail(v, "the default cast's answer, bit for bit (the start is not left): " + describe_result(d),
           describe_result(r));
    return v;
  }
  if (!(t >= 0 && t <= max_t)) fail(v, "0 <= t <= max_t", num(t));
  if (!v.ok) return v;
  const std::vector<oracle::Placed> pa = placed_parts(a, in.xa), pb = placed_parts(b, in.xb);
  const double until = r.outcome == CastOutcome::Miss ? max_t : t;
  bool all_overlap = true, near_at_t = false;
  for (const oracle::Placed& p : pa) {
    for (const oracle::Placed& q : pb) {
      const bool overlap = oracle::overlaps(p, q);
      all_overlap = all_overlap && overlap;
      // Never later than the first contact of a pair apart at the start.
      if (!oracle::meets_during(p, in.va, q, in.vb, 0.0, 0.0, eps) && (!r.hit() || t > 0) &&
          oracle::meets_during(p, in.va, q, in.vb, 0.0, until)) {
        fail(v, "a pair of primitives apart at the start stays apart on [0, " + num(until) + "]",
             "the exact pair meets there: tunnelled");
      }
      near_at_t = near_at_t || (!overlap && oracle::meets_during(p, in.va, q, in.vb, t, t, eps));
    }
  }
  if (all_overlap && r.outcome != CastOutcome::Miss)
    fail(v, "a miss (every pair of primitives overlaps at the start and is left out)", describe_result(r));
  if (r.hit()) {
    if (!near_at_t) fail(v, "a pair that did not overlap at the start within the tolerance at t", "none");
    const double len = std::hypot(double(r.normal.x()), double(r.normal.y()));
    if (!(std::fabs(len - 1) <= 8 * detail::eps<T>())) fail(v, "a unit normal", "|normal| = " + num(len));
  }
  return v;
}

template <Scalar T>
Verdict cast_symmetry(const Shape<T>& a, const Shape<T>& b, const CastInput<T>& in) {
  Verdict v;
  const CastResult<T> r = cast_of(a, b, in);
  const CastResult<T> s = cast_of(b, a, CastInput<T>{in.vb, in.va, in.max_t, in.xb, in.xa});
  v.relation = oracle::overlaps(oracle::placed(a, in.xa), oracle::placed(b, in.xb)) ? Relation::Overlapping
                                                                                    : Relation::Separated;
  v.account = "shape_cast(a, va, b, vb) = " + describe_result(r) + "; swapped: " + describe_result(s) + "; " +
              describe_input(a, b, in);
  if (r.outcome != s.outcome || r.t != s.t)
    fail(v, "the swapped cast gives the same outcome and t", describe_result(s));
  // At t = 0 from an overlap the normal is contact()'s, symmetric within its own tolerance
  // (contact law); elsewhere it is computed in one order and negated: bit for bit.
  const bool start = r.hit() && r.t == T(0) && overlaps(a, in.xa, b, in.xb);
  if (r.hit() && !start && s.normal != Vec2<T>(-r.normal))
    fail(v, "the swapped cast's normal reversed", describe_result(s));
  // Relative motion: only va - vb matters (when T represents it exactly).
  const Vec2<T> w = in.va - in.vb;
  if (widen(w) == widen(in.va) - widen(in.vb)) {
    const CastResult<T> q = cast_of(a, b, CastInput<T>{w, Vec2<T>(0, 0), in.max_t, in.xa, in.xb});
    // The point is in the world of the hit's time s, which t rounds toward zero (s below the next
    // T after t): b's motion moves it by vb s, vb t up to one rounding of T and vb times that gap.
    const double moved = (widen(q.point) + widen(in.vb) * double(r.t) - widen(r.point)).cwiseAbs().maxCoeff();
    const double vb_max = widen(in.vb).cwiseAbs().maxCoeff();
    const double gap = double(std::nextafter(r.t, std::numeric_limits<T>::infinity())) - double(r.t);
    const double bound =
        4 * detail::eps<T>() * (widen(r.point).cwiseAbs().maxCoeff() + vb_max * double(r.t)) + vb_max * gap;
    if (q.outcome != r.outcome || q.t != r.t || (!start && q.normal != r.normal) || (r.hit() && !(moved <= bound))) {
      fail(v, "cast(a, va - vb, b, 0): the same outcome, t and normal, the point moved by vb t", describe_result(q));
    }
  }
  return v;
}

template <Scalar T>
Verdict cast_translation(const Shape<T>& a, const Shape<T>& b, const CastInput<T>& in, const Vec2<T>& d) {
  Verdict v;
  const oracle::Placed ea = oracle::placed(a, in.xa), eb = oracle::placed(b, in.xb);
  v.relation = oracle::overlaps(ea, eb) ? Relation::Overlapping : Relation::Separated;
  v.account = "translation by " + vec(d) + " of " + describe_input(a, b, in);
  // The moved pair: the shapes translated in world space, or their transforms moved when placed.
  Shape<T> a2 = a, b2 = b;
  CastInput<T> in2 = in;
  bool exact = false;
  if (in.xa.is_identity() && in.xb.is_identity()) {
    const auto ma = translated(a, d), mb = translated(b, d);
    if (!ma || !mb) {
      v.account += ": the move is not representable (named error), nothing to compare";
      return v;
    }
    a2 = ma.value();
    b2 = mb.value();
    exact = detail::exact_move(a, a2, d) && detail::exact_move(b, b2, d);
  } else {
    const auto xa = in.xa.moved(d), xb = in.xb.moved(d);
    if (!xa || !xb) {
      v.account += ": the move is not representable (named error), nothing to compare";
      return v;
    }
    in2.xa = *xa;
    in2.xb = *xb;
    exact = true;
    for (const auto& [x, x2] : {std::pair{in.xa, in2.xa}, std::pair{in.xb, in2.xb}}) {
      for (int k = 0; k < 2; ++k)
        exact = exact && detail::exact_sum(double(x.position()[k]), double(d[k]), double(x2.position()[k]));
    }
  }
  const CastResult<T> r = cast_of(a, b, in);
  const CastResult<T> s = cast_of(a2, b2, in2);
  v.account += "; before: " + describe_result(r) + "; after: " + describe_result(s);
  // The moved pair is itself judged by the cast law.
  const Verdict moved = cast_law(a2, b2, in2);
  if (!moved.ok) fail(v, "the moved pair obeys the cast law", moved.account);
  if (!exact) return v;  // rounded moves: a new pair
  // An exact move: the same motion. A hit and a miss agree only for a motion that passes within
  // the larger tolerance without touching (the contract allows either there).
  if (r.hit() != s.hit() && r.outcome != CastOutcome::IterationLimit && s.outcome != CastOutcome::IterationLimit) {
    const double eps = std::max(cast_tolerance(a, in.xa, in.va, b, in.xb, in.vb, in.max_t),
                                cast_tolerance(a2, in2.xa, in.va, b2, in2.xb, in.vb, in.max_t));
    const bool grazes = oracle::meets_during(ea, in.va, eb, in.vb, 0.0, double(in.max_t), eps) &&
                        !oracle::meets_during(ea, in.va, eb, in.vb, 0.0, double(in.max_t));
    if (!grazes) fail(v, "the same outcome after an exact translation", describe_result(s));
    v.disagreement = grazes;
  }
  if (r.hit() && s.hit() && (r.t == T(0)) != (s.t == T(0)) && v.relation == Relation::Overlapping) {
    fail(v, "t = 0 in both (the start overlaps)", describe_result(s));
  }
  return v;
}

template <Scalar T>
Verdict cast_raycast(const Shape<T>& s, const Ray<T>& ray, T max_t) {
  Verdict v;
  const Circle<T> dot(ray.origin, T(0));
  const Vec2<T> zero(0, 0);
  const CastResult<T> c = shape_cast(dot, ray.direction, s, zero, max_t);
  const auto h = raycast(s, Ray<T>{ray.origin, ray.direction}, max_t);
  const double eps = cast_tolerance(dot, ray.direction, s, zero, max_t);
  const double delta = raycast_tolerance(s, Ray<T>{ray.origin, ray.direction});
  const Shape<T> p = dot;
  v.relation = oracle::overlaps(p, s) ? Relation::Overlapping : Relation::Separated;
  v.account = "zero-radius circle cast from " + vec(ray.origin) + " along " + vec(ray.direction) + " to " +
              describe(s) + ", max_t=" + num(double(max_t)) + ": " + describe_result(c) +
              "; raycast: " + (h ? "hit t=" + num(double(h->t)) : std::string("miss"));
  if (c.outcome == CastOutcome::IterationLimit || c.outcome == CastOutcome::InvalidInput) return v;
  if (c.hit() == bool(h)) {
    // Both start inside: both at t = 0, unless the origin lies within the larger tolerance of the
    // boundary (a placed child's image rounds; the cast's skin counts as touching).
    if (c.hit() && (c.t == T(0)) != (h->t == T(0)) && oracle::contains(s, ray.origin)) {
      const double pad = std::max(eps, delta);
      // Deeper than pad inside one child: deeper inside the union too.
      bool deep = false;
      for (const auto& child : detail::placed_primitives_of(s)) {
        const oracle::Placed x = oracle::placed(child.shape, child.transform);
        deep = deep || (oracle::contains(x, ray.origin) && oracle::compare_boundary_distance(x, ray.origin, pad) > 0);
      }
      if (deep) {
        fail(v, "both at t = 0 from inside (deeper than " + num(pad) + ")", "");
      } else {
        v.disagreement = true;
        v.account += "; origin within " + num(pad) + " of the boundary: either answer allowed";
      }
    }
    return v;
  }
  // A cast that misses never meets the shape exactly (its contract), whatever the ray says.
  if (!c.hit() && oracle::meets_during(p, ray.direction, s, zero, 0.0, double(max_t), 0.0)) {
    fail(v, "a cast that misses never meets the shape", "ray hit, cast missed an exact contact");
    return v;
  }
  // Otherwise they differ only for a ray passing within the larger tolerance of the shape.
  const double pad = std::max(eps, delta);
  const bool near = oracle::meets_during(p, ray.direction, s, zero, 0.0, double(max_t), pad);
  if (!near)
    fail(v, "the cast and the ray agree on hit or miss", c.hit() ? "cast hit, ray missed" : "ray hit, cast missed");
  v.disagreement = near;
  return v;
}

template <Scalar T>
Verdict toi_law(const Shape<T>& a, const Sweep<T>& sa, const Shape<T>& b, const Sweep<T>& sb, T max_t,
                std::span<const double> samples) {
  Verdict v;
  const CastResult<T> r = time_of_impact(a, sa, b, sb, max_t);
  const double eps = toi_tolerance(a, sa, b, sb, max_t);
  auto sweep_text = [](const Sweep<T>& s) {
    return "{lc=" + vec(s.local_center) + " c0=" + vec(s.c0) + " c1=" + vec(s.c1) + " a0=" + num(double(s.a0)) +
           " a1=" + num(double(s.a1)) + "}";
  };
  v.account = "time_of_impact(" + describe(a) + " " + sweep_text(sa) + ", " + describe(b) + " " + sweep_text(sb) +
              ", max_t=" + num(double(max_t)) + ") = " + describe_result(r) + ", tolerance " + num(eps);
  auto meets = [&](double s, double pad) {
    const SweepPose pa = sweep_pose(sa, s), pb = sweep_pose(sb, s);
    return oracle::meets_posed(a, pa.rotation, pa.position, b, pb.rotation, pb.position, pad);
  };
  v.relation = meets(0, 0) ? Relation::Overlapping : Relation::Separated;
  if (r.outcome == CastOutcome::InvalidInput) {
    fail(v, "a valid answer for valid input", "invalid input");
    return v;
  }
  const double t = double(r.t);
  if (!(t >= 0 && t <= double(max_t))) fail(v, "0 <= t <= max_t", num(t));
  // Apart at the sample times before t (every sample up to max_t after a miss), and at t itself
  // when t > 0.
  const double until = r.outcome == CastOutcome::Miss ? double(max_t) : t;
  for (const double f : samples) {
    const double s = f * until;
    if (s > until || (r.hit() && t == 0)) continue;
    if (meets(s, 0)) {
      fail(v, "the posed shapes apart at time " + num(s) + " <= " + num(until), "they meet there");
      break;
    }
  }
  if (r.hit()) {
    if (!meets(t, eps)) fail(v, "the posed shapes within the tolerance at t", "farther apart");
    const double len = std::hypot(double(r.normal.x()), double(r.normal.y()));
    if (!(std::fabs(len - 1) <= 8 * detail::eps<T>())) fail(v, "a unit normal", "|normal| = " + num(len));
  }
  if (r.hit() && v.ok && !meets(t, 0)) {
    // Apart at t: the normal and point as for a shape cast, on the shapes posed at t.
    const SweepPose pa = sweep_pose(sa, t), pb = sweep_pose(sb, t);
    const auto far_posed = [](const SweepPose& pose) {
      return [pose](const Vec2<double>& x, const Shape<T>& s, double d) {
        if (d <= 0) return true;
        const auto dot = point_shape(x);
        return !dot ||
               !oracle::meets_posed(*dot, Vec2<double>(1, 0), Vec2<double>(0, 0), s, pose.rotation, pose.position, d);
      };
    };
    const Transform<T> local;
    judge_normal_and_point(v, r, std::max(size_of(a, local), size_of(b, local)), eps, a, parts_of(a), far_posed(pa), b,
                           parts_of(b), far_posed(pb));
  }
  // Swapped: same time, reversed normal. A hit at t = 0 of shapes that overlap or touch within
  // the tolerance there has a contact normal, judged by its own law: inside that band the two
  // orders may compute the very same cores (a point on a point), which have no direction.
  const CastResult<T> s = time_of_impact(b, sb, a, sa, max_t);
  const bool start = r.hit() && t == 0 && (v.relation == Relation::Overlapping || meets(0, eps));
  if (s.outcome != r.outcome || s.t != r.t || (r.hit() && !start && s.normal != Vec2<T>(-r.normal))) {
    fail(v, "the swapped query gives the same t and the reversed normal", describe_result(s));
  }
  return v;
}

#define COLLIDE_CAST_LAWS(T)                                                                                   \
  template Verdict cast_law<T>(const Shape<T>&, const Shape<T>&, const CastInput<T>&);                         \
  template Verdict cast_leaving<T>(const Shape<T>&, const Shape<T>&, const CastInput<T>&);                     \
  template Verdict cast_symmetry<T>(const Shape<T>&, const Shape<T>&, const CastInput<T>&);                    \
  template Verdict cast_translation<T>(const Shape<T>&, const Shape<T>&, const CastInput<T>&, const Vec2<T>&); \
  template Verdict cast_raycast<T>(const Shape<T>&, const Ray<T>&, T);                                         \
  template Verdict toi_law<T>(const Shape<T>&, const Sweep<T>&, const Shape<T>&, const Sweep<T>&, T,           \
                              std::span<const double>);
COLLIDE_CAST_LAWS(float)
COLLIDE_CAST_LAWS(double)
#undef COLLIDE_CAST_LAWS

}  // namespace collide::laws
