#pragma once
/// @file predicates.hpp
/// Sign predicates. orient() is exact for every input in the library's domain (values of magnitude
/// 0 or within [2^-500, 2^500]); everything built only on it (AABB and polygon decisions) is exact.

#include "collide/config.hpp"

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
template <int N>
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

/// Sign of the turn a -> b -> c: +1 counter-clockwise (c left of a->b), -1 clockwise, 0 collinear.
///
/// A floating-point filter answers most calls (bound (3 + 16u)u * (|l| + |r|), Shewchuk); the rest
/// expand the determinant into six exact products and sum them exactly.
inline int orient(const Vec2c& a, const Vec2c& b, const Vec2c& c) noexcept {
  const double l = (b.x() - a.x()) * (c.y() - a.y());
  const double r = (b.y() - a.y()) * (c.x() - a.x());
  const double det = l - r;
  const double bound = 3.3306690738754716e-16 * (std::fabs(l) + std::fabs(r));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  // det = bx*cy - bx*ay - ax*cy - by*cx + by*ax + ay*cx, each product split exactly in two.
  const detail::Term p[6] = {
      detail::two_product(b.x(), c.y()),  detail::two_product(-b.x(), a.y()),
      detail::two_product(-a.x(), c.y()), detail::two_product(-b.y(), c.x()),
      detail::two_product(b.y(), a.x()),  detail::two_product(a.y(), c.x()),
  };
  const double terms[12] = {p[0].hi, p[0].lo, p[1].hi, p[1].lo, p[2].hi, p[2].lo,
                            p[3].hi, p[3].lo, p[4].hi, p[4].lo, p[5].hi, p[5].lo};
  return detail::exact_sign_of_sum(terms);
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
