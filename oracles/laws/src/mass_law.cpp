// The mass law: mass_properties() of every kind, its placed form and its exact moves, judged
// against the oracle's exact mass, centroid and inertia with the bounds mass.hpp documents.

#include "support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace collide::laws {

using detail::describe;
using detail::num;
using detail::vec;

namespace {

using oracle::kMassOutputs;
using oracle::MassValues;

constexpr const char* kOutputNames[kMassOutputs] = {"mass", "centroid x", "centroid y", "inertia", "origin inertia"};

/// n of mass.hpp's contract, counted here: a polygon's vertices, 4 for each other primitive.
template <Scalar T>
double vertex_terms(const Shape<T>& s) {
  double n = 0;
  for (const Primitive<T>& p : primitives_of(s)) {
    const auto* poly = std::get_if<ConvexPolygon<T>>(&p);
    n += poly ? double(poly->size()) : 4.0;
  }
  return n;
}

/// mass.hpp's bounds, written out from its contract and evaluated on the exact outputs (taken
/// 2^-40 high, for their rounding to double), so that the law judges the library's outputs by
/// the documented bound rather than by the library's own mass_tolerance(). `reach` is the body
/// transform's |position|_inf (0 in world space).
template <Scalar T>
MassValues documented_bounds(const Shape<T>& s, double reach, const MassValues& exact) {
  const double u = 0x1p-53, eps = detail::eps<T>(), d = double(std::numeric_limits<T>::denorm_min());
  const double nu = vertex_terms(s) * u;
  const Aabb<T> box = bounds(s);
  const double w = (box.max().template cast<double>() - box.min().template cast<double>()).maxCoeff();
  const auto* c = std::get_if<Compound<T>>(&s);
  const double l = c && c->has_child_transforms() ? c->local_extent() : 0.0;
  const double big = 1 + 0x1p-40;
  const double sc = ::collide::detail::scale_of(box) + reach;
  const double m = std::fabs(exact[0]) * big, inertia = std::fabs(exact[3]) * big, origin = std::fabs(exact[4]) * big;
  const double centroid = 16 * nu * w + 16 * u * l + 4 * u * sc;
  const double i = (64 * nu * w * w + 32 * u * w * l) * m;
  MassValues out = {(8 * nu + eps) * m + d, centroid + eps * sc + d, centroid + eps * sc + d, i + eps * inertia + d,
                    i + 16 * nu * m * sc * sc + 4 * m * sc * centroid + (4 * u + eps) * origin + d};
  // A bound past double's range (a density near T's largest) is judged as double's largest: stricter.
  for (double& b : out) b = std::min(b, std::numeric_limits<double>::max());
  return out;
}

template <Scalar T>
MassValues values_of(const MassProperties<T>& p) {
  return {double(p.mass), double(p.centroid.x()), double(p.centroid.y()), double(p.inertia), double(p.origin_inertia)};
}

/// The library's mass_tolerance() as a list in the oracle's order.
inline MassValues tolerance_values(const MassTolerance& t) {
  return {t.mass, t.centroid, t.centroid, t.inertia, t.origin_inertia};
}

std::string list(const MassValues& v) {
  std::string out;
  for (std::size_t k = 0; k < kMassOutputs; ++k)
    out += (k ? ", " : "") + std::string(kOutputNames[k]) + " " + num(v[k]);
  return out;
}

/// One answer of mass_properties() for the shape `what` (judged as `exact_input` by the oracle):
/// a value whose every output lies within the documented bound of the exact one, or OutOfRange
/// where an exact mass, inertia or origin inertia (plus its bound) passes T's largest value.
/// Empty when it holds, else what failed.
template <Scalar T, class Input>
std::string judge_answer(const Expected<MassProperties<T>>& got, const Input& exact_input, double density,
                         const MassValues& exact, const MassValues& bound, const std::string& what) {
  const double top = double(std::numeric_limits<T>::max());
  bool beyond = false;
  for (const std::size_t k : {std::size_t(0), std::size_t(3), std::size_t(4)})
    beyond = beyond || exact[k] + bound[k] > top;
  if (!got) {
    if (got.error().code() == Error::OutOfRange && beyond) return {};
    return what + ": expected a value (exact " + list(exact) + "); got " + got.error().what();
  }
  const MassValues v = values_of(*got);
  for (const double x : v) {
    if (!std::isfinite(x)) return what + ": a non-finite output (" + list(v) + ")";
  }
  const std::array<bool, kMassOutputs> within = oracle::mass_within(exact_input, density, v, bound);
  for (std::size_t k = 0; k < kMassOutputs; ++k) {
    if (!within[k])
      return what + ": " + kOutputNames[k] + " " + num(v[k]) + " off the exact ~" + num(exact[k]) + " by more than " +
             num(bound[k]);
  }
  return {};
}

/// The library's mass_tolerance() agrees with the documented bound to 2^-20 (it evaluates the
/// same formula on the computed values taken high): neither looser nor tighter than promised.
std::string judge_tolerance(const MassValues& library, const MassValues& documented, const std::string& what) {
  for (std::size_t k = 0; k < kMassOutputs; ++k) {
    if (documented[k] == std::numeric_limits<double>::max()) continue;  // past double's range: no closeness
    const double lo = documented[k] * (1 - 0x1p-20), hi = documented[k] * (1 + 0x1p-20);
    if (!(library[k] >= lo && library[k] <= hi))
      return what + ": mass_tolerance()'s " + kOutputNames[k] + " bound " + num(library[k]) + ", documented " +
             num(documented[k]);
  }
  return {};
}

}  // namespace

template <Scalar T>
Verdict mass_law(const Shape<T>& s, T density, const Vec2<T>& t, const Transform<T>& x) {
  Verdict v;
  // Fills the failure and returns the verdict.
  auto fail = [&](const std::string& why) {
    v.ok = false;
    v.expected = "mass properties within their documented bounds";
    v.got = why;
    v.account = "expected " + v.expected + "; got " + why + "; s = " + describe(s) + "; density " + num(density) +
                "; t = " + vec(t) + "; x = p " + vec(x.position()) + " q " + vec(x.rotation());
    return v;
  };
  try {
    // Bad densities: their named error, in every form.
    if (!std::isfinite(double(density)) || density < T(0)) {
      const Error want = std::isfinite(double(density)) ? Error::NegativeDensity : Error::NonFinite;
      const auto a = mass_properties(s, density), b = mass_properties(s, x, density);
      if (a || b || a.error().code() != want || b.error().code() != want)
        return fail(std::string("density ") + num(density) + " not rejected with " + std::string(name(want)));
      v.account = "density " + num(density) + ": " + std::string(name(want));
      return v;
    }
    const double rho = density;
    // World space: every output against the exact one.
    const MassValues exact = oracle::approx_mass(s, rho);
    const MassValues bound = documented_bounds(s, 0, exact);
    const auto got = mass_properties(s, density);
    if (std::string why = judge_answer(got, s, rho, exact, bound, "world"); !why.empty()) return fail(why);
    v.account = got ? "mass " + list(values_of(*got)) : "OutOfRange (exact " + list(exact) + ")";
    if (got) {
      const MassValues lib = tolerance_values(mass_tolerance(s, density));
      if (std::string why = judge_tolerance(lib, bound, "world"); !why.empty()) return fail(why);
    }
    // Placed by x: the centroid is x's exact image, mass and inertia are the world ones to the bit.
    const oracle::Placed placed = oracle::placed(s, x);
    const MassValues exact_x = oracle::approx_mass(placed, rho);
    const double reach = x.position().template cast<double>().cwiseAbs().maxCoeff();
    const MassValues bound_x = documented_bounds(s, reach, exact_x);
    const auto got_x = mass_properties(s, x, density);
    if (std::string why = judge_answer(got_x, placed, rho, exact_x, bound_x, "placed"); !why.empty()) return fail(why);
    if (got && got_x && (got_x->mass != got->mass || got_x->inertia != got->inertia))
      return fail("placed: mass " + num(got_x->mass) + " and inertia " + num(got_x->inertia) + ", world " +
                  num(got->mass) + " and " + num(got->inertia));
    if (got_x) {
      const MassValues lib = tolerance_values(mass_tolerance(s, x, density));
      if (std::string why = judge_tolerance(lib, bound_x, "placed"); !why.empty()) return fail(why);
    }
    // Moved by t: judged again; an exact move keeps mass and inertia to the bit.
    const Expected<Shape<T>> moved = translated(s, t);
    if (!moved) {
      v.account += "; move by " + vec(t) + " rejected (" + moved.error().what() + ")";
      return v;
    }
    const MassValues exact_t = oracle::approx_mass(*moved, rho);
    const auto got_t = mass_properties(*moved, density);
    if (std::string why = judge_answer(got_t, *moved, rho, exact_t, documented_bounds(*moved, 0, exact_t), "moved");
        !why.empty())
      return fail(why);
    const bool exact_move = detail::exact_move(s, *moved, t);
    v.account += std::string("; ") + (exact_move ? "exact" : "rounded") + " move by " + vec(t);
    if (exact_move && got && got_t && (got_t->mass != got->mass || got_t->inertia != got->inertia))
      return fail("exact move: mass " + num(got_t->mass) + " and inertia " + num(got_t->inertia) + ", unmoved " +
                  num(got->mass) + " and " + num(got->inertia));
  } catch (const std::exception& e) {
    v.ok = false;
    v.expected = "no exception";
    v.got = e.what();
    v.account = std::string("exception: ") + e.what() + "; s = " + describe(s);
  }
  return v;
}

template Verdict mass_law<float>(const Shape<float>&, float, const Vec2<float>&, const Transform<float>&);
template Verdict mass_law<double>(const Shape<double>&, double, const Vec2<double>&, const Transform<double>&);

}  // namespace collide::laws
