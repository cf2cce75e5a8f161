#pragma once
/// @file predicates.hpp
/// Sign predicates. orient() is exact for every input the shapes accept (see its caveat on
/// coordinates more than 2^995 apart in magnitude); everything built only on it and on comparisons
/// (AABB and polygon decisions) is exact.

#include "collide/config.hpp"

#include <algorithm>
#include <cmath>

namespace collide {

namespace detail {

struct Term {
  double hi;
  double lo;
};

inline Term two_sum(double a, double b) noexcept {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

inline Term two_product(double a, double b) noexcept {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

/// Sign of a sum of exact products, by Shewchuk's grow-expansion: the components stay
/// non-overlapping and sorted by magnitude, so the last non-zero one carries the sign.
template <std::size_t N>
int exact_sign_of_sum(const double (&terms)[N]) noexcept {
  double e[2 * N + 1];
  int n = 0;
  for (double t : terms) {
    double q = t;
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const Term s = two_sum(q, e[i]);
      q = s.hi;
      if (s.lo != 0.0) e[m++] = s.lo;
    }
    if (q != 0.0) e[m++] = q;
    n = m;
  }
  if (n == 0) return 0;
  return e[n - 1] > 0.0 ? 1 : -1;
}

}  // namespace detail

namespace detail {

/// Exact sign of the orientation determinant by expansion arithmetic. Products and their fma
/// error terms are exact when no product underflows; callers scale the inputs so that this holds.
inline int orient_expansion(const Vec2c& a, const Vec2c& b, const Vec2c& c) noexcept {
  // det = bx*cy - bx*ay - ax*cy - by*cx + by*ax + ay*cx, each product split exactly in two.
  const Term p[6] = {
      two_product(b.x(), c.y()),  two_product(-b.x(), a.y()), two_product(-a.x(), c.y()),
      two_product(-b.y(), c.x()), two_product(b.y(), a.x()),  two_product(a.y(), c.x()),
  };
  const double terms[12] = {p[0].hi, p[0].lo, p[1].hi, p[1].lo, p[2].hi, p[2].lo,
                            p[3].hi, p[3].lo, p[4].hi, p[4].lo, p[5].hi, p[5].lo};
  return exact_sign_of_sum(terms);
}

}  // namespace detail

/// Sign of the turn a -> b -> c: +1 counter-clockwise (c left of a->b), -1 clockwise, 0 collinear.
///
/// A floating-point filter answers most calls (bound (3 + 16u)u * (|l| + |r|), Shewchuk); the rest
/// expand the determinant into six exact products and sum them exactly.
///
/// Exact for every input the shapes accept (finite, |v| <= 2^500, subnormals included) provided
/// every non-zero coordinate is at least 2^-995 times the largest one of the call. The fallback
/// first scales all six coordinates by one power of two (exact, sign-preserving) so that the
/// largest is near 2^510: no product can then overflow, and no product of coordinates within
/// that ratio can underflow. The filter is skipped when its products are tiny, since underflow
/// breaks its relative error bound.
inline int orient(const Vec2c& a, const Vec2c& b, const Vec2c& c) noexcept {
  const double l = (b.x() - a.x()) * (c.y() - a.y());
  const double r = (b.y() - a.y()) * (c.x() - a.x());
  const double det = l - r;
  const double mag = std::fabs(l) + std::fabs(r);
  if (mag > 0x1p-900) {
    const double bound = 3.3306690738754716e-16 * mag;
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  const double m = std::max({std::fabs(a.x()), std::fabs(a.y()), std::fabs(b.x()), std::fabs(b.y()),
                             std::fabs(c.x()), std::fabs(c.y())});
  if (m == 0.0) return 0;
  int e = 0;
  static_cast<void>(std::frexp(m, &e));  // m in [2^(e-1), 2^e)
  const int k = 510 - e;
  if (k == 0) return detail::orient_expansion(a, b, c);
  auto s = [k](const Vec2c& v) { return Vec2c(std::ldexp(v.x(), k), std::ldexp(v.y(), k)); };
  return detail::orient_expansion(s(a), s(b), s(c));
}

/// 2D cross product (z component), computed in Calc.
inline Calc cross(const Vec2c& a, const Vec2c& b) noexcept { return a.x() * b.y() - a.y() * b.x(); }

/// Left perpendicular (rotated +90 degrees).
inline Vec2c perp(const Vec2c& v) noexcept { return {-v.y(), v.x()}; }

/// Exact widening of a stored vector into the computation type.
template <Scalar T>
inline Vec2c widen(const Vec2<T>& v) noexcept {
  return v.template cast<Calc>();
}

}  // namespace collide
