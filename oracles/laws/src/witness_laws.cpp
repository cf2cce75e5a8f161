// The laws of the distance queries' points: signed_distance() of a point, and the witness points
// of closest_points().

#include "support.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace collide::laws {

using detail::describe;
using detail::judged;
using detail::Judgement;
using detail::num;
using detail::vec;
using detail::yes;

template <Scalar T>
Verdict signed_distance_law(const Shape<T>& s, const Vec2<T>& p) {
  return judged("s = " + describe(s) + "; p = " + vec(p), [&](Judgement& r) {
    const auto require = [&](bool holds, const std::string& e, const std::string& g) { r.require(holds, e, g); };
    const T got = signed_distance(s, p);
    const bool in = contains(s, p);
    r.v.relation = in ? Relation::Contained : Relation::Separated;
    r.note("signed_distance " + num(got) + ", contains " + yes(in));
    const Vec2c q = widen(p);
    if (std::isnan(q.x()) || std::isnan(q.y())) {
      r.require(std::isnan(got), "NaN for a NaN point", num(got));
      return;
    }
    if (!q.allFinite()) {
      r.require(got == std::numeric_limits<T>::infinity(), "+infinity for an infinite point", num(got));
      return;
    }
    // The sign: contains()'s to the bit, and so the oracle's (a compound with child transforms:
    // within its placement's band, where the library's images decide).
    r.require((got <= T(0)) == in, "signed_distance <= 0 exactly when contains() (" + yes(in) + ")", num(got));
    const bool exact_in = oracle::contains(s, q);
    if (exact_in != in) {
      r.v.disagreement = true;
      const double band = placement_tolerance(s);
      bool near = false;
      for (const oracle::Placed& part : detail::exact_parts(s)) near = near || detail::near_boundary(part, q, band);
      r.require(near && oracle::contains(detail::computed_geometry(s), q) == in,
                "the oracle's containment " + yes(exact_in) + " outside the placement's band " + num(band),
                "contains " + yes(in));
    }
    // The magnitude, against the exact signed distance.
    const double tol = detail::documented_point_bound(bounds(s), p, placement_tolerance(s));
    detail::judge_signed_magnitude(require, detail::exact_parts(s), q, double(got), tol,
                                   double(std::numeric_limits<T>::max()));
  });
}

template <Scalar T>
Verdict closest_points_law(const Shape<T>& a, const Shape<T>& b) {
  return judged("a = " + describe(a) + "; b = " + describe(b), [&](Judgement& r) {
    const auto require = [&](bool holds, const std::string& e, const std::string& g) { r.require(holds, e, g); };
    r.v.relation = relation(a, b);
    // Both argument orders, each judged on its own.
    for (const bool swap : {false, true}) {
      const Shape<T>& x = swap ? b : a;
      const Shape<T>& y = swap ? a : b;
      const ClosestPoints<T> c = closest_points(x, y);
      const std::string order = swap ? "(b, a)" : "(a, b)";
      r.note("closest_points" + order + " " + num(c.distance) + " at " + vec(c.point_a) + ", " + vec(c.point_b));
      detail::judge_witness<T>(
          [&](bool holds, const std::string& e, const std::string& g) { require(holds, order + ": " + e, g); },
          oracle::Placed(oracle::as_exact_input(x)), oracle::Placed(oracle::as_exact_input(y)), c, distance(x, y),
          detail::documented_witness_bound(rounding_tolerance(x, y), bounds(x), bounds(y)));
    }
  });
}

template Verdict signed_distance_law<float>(const Shape<float>&, const Vec2<float>&);
template Verdict signed_distance_law<double>(const Shape<double>&, const Vec2<double>&);
template Verdict closest_points_law<float>(const Shape<float>&, const Shape<float>&);
template Verdict closest_points_law<double>(const Shape<double>&, const Shape<double>&);

}  // namespace collide::laws
