#pragma once
/// @file predicates.hpp
/// Sign predicates: orient(), exact for every input the shapes accept, and the machinery of the
/// exact decisions (a filter with a running error bound, exact binary arithmetic).

#include "collide/config.hpp"
#include "collide/detail/math.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

/// Shewchuk's grow-expansion: the exact sum of the terms as non-overlapping components in e,
/// sorted by magnitude, zeros dropped; returns how many.
template <std::size_t N>
int grow_expansion(const double (&terms)[N], double (&e)[2 * N + 1]) noexcept {
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
  return n;
}

/// Sign of a sum of exact products: the last non-zero component of its expansion carries it.
template <std::size_t N>
int exact_sign_of_sum(const double (&terms)[N]) noexcept {
  double e[2 * N + 1];
  const int n = grow_expansion(terms, e);
  if (n == 0) return 0;
  return e[n - 1] > 0.0 ? 1 : -1;
}

/// A sum of exact terms rounded to double, within 2 units of roundoff of the exact sum: its
/// expansion's components added from the smallest up (each lies below the next one's last bit).
template <std::size_t N>
double rounded_sum(const double (&terms)[N]) noexcept {
  double e[2 * N + 1];
  const int n = grow_expansion(terms, e);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += e[i];
  return sum;
}

}  // namespace detail

namespace detail {

// ---------------------------------------------------------------------------------------------
// Exact signs of polynomials in the stored values: a filter with a running error bound decides
// almost every call; the rest are evaluated exactly in binary floating point of unbounded width.
// A decision is written once as a generic function of its number type and evaluated with
// Bounded first, then with Exact when the filter cannot tell the sign.

/// A double with a proven bound on its absolute error: |value - exact| <= err. Every operation
/// adds its own rounding (u |result|, u = 2^-53) and, for products, 2^-1069, which covers an
/// underflowing product and the underflows of the bound's own few operations. The bound itself
/// is computed in rounded arithmetic; certain() inflates it by 2^-40 relative to cover that (the
/// polynomials here have far fewer than 2^12 operations). Overflow gives an infinite bound, and
/// infinities or NaN are never certain.
struct Bounded {
  double v = 0;
  double err = 0;
  Bounded() = default;
  explicit Bounded(double x) noexcept : v(x) {}
  Bounded(double x, double e) noexcept : v(x), err(e) {}
  /// The sign, when the bound proves it; 2 when it does not.
  int certain_sign() const noexcept {
    const double e = err * (1 + kBoundSlack);
    if (v > e) return 1;
    if (-v > e) return -1;
    return 2;
  }
};
inline Bounded operator+(const Bounded& a, const Bounded& b) noexcept {
  const double s = a.v + b.v;
  return {s, a.err + b.err + std::fabs(s) * kUnitRoundoff};
}
inline Bounded operator-(const Bounded& a, const Bounded& b) noexcept {
  const double s = a.v - b.v;
  return {s, a.err + b.err + std::fabs(s) * kUnitRoundoff};
}
inline Bounded operator-(const Bounded& a) noexcept {
  return {-a.v, a.err};
}
inline Bounded operator*(const Bounded& a, const Bounded& b) noexcept {
  const double p = a.v * b.v;
  return {p, std::fabs(a.v) * b.err + std::fabs(b.v) * a.err + a.err * b.err + std::fabs(p) * kUnitRoundoff +
                 kProductUnderflow};
}

/// An exact binary number sign * mag * 2^exp of up to kLimbs 32-bit limbs: enough for every
/// polynomial of degree <= 6 in values between 2^-1074 and 2^501 (at most 6 * 1575 + 6 * 53
/// bits plus carries, under 9,600). Sums and products are exact; nothing allocates.
class Exact {
 public:
  static constexpr int kLimbs = 304;
  Exact() = default;
  Exact(const Exact& o) noexcept : sign_(o.sign_), exp_(o.exp_), n_(o.n_) {
    for (int i = 0; i < n_; ++i) mag_[i] = o.mag_[i];
  }
  Exact& operator=(const Exact& o) noexcept {
    sign_ = o.sign_;
    exp_ = o.exp_;
    n_ = o.n_;
    for (int i = 0; i < n_; ++i) mag_[i] = o.mag_[i];
    return *this;
  }
  explicit Exact(double x) noexcept {
    if (x == 0) return;
    int e = 0;
    const double f = std::frexp(std::fabs(x), &e);  // |x| = f 2^e, f in [0.5, 1)
    sign_ = x < 0 ? -1 : 1;
    const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));
    mag_[0] = static_cast<std::uint32_t>(m);
    mag_[1] = static_cast<std::uint32_t>(m >> 32);
    n_ = 2;
    exp_ = e - 53;
    trim();
  }
  int sign() const noexcept { return sign_; }

  friend Exact operator*(const Exact& a, const Exact& b) noexcept {
    Exact r;
    if (a.sign_ == 0 || b.sign_ == 0) return r;
    r.sign_ = a.sign_ * b.sign_;
    r.exp_ = a.exp_ + b.exp_;
    r.n_ = std::min(a.n_ + b.n_, kLimbs);
    for (int i = 0; i < r.n_; ++i) r.mag_[i] = 0;
    for (int i = 0; i < a.n_; ++i) {
      std::uint64_t carry = 0;
      for (int j = 0; j < b.n_ && i + j < kLimbs; ++j) {
        carry += std::uint64_t(a.mag_[i]) * b.mag_[j] + r.mag_[i + j];
        r.mag_[i + j] = static_cast<std::uint32_t>(carry);
        carry >>= 32;
      }
      if (i + b.n_ < kLimbs) r.mag_[i + b.n_] = static_cast<std::uint32_t>(carry);
    }
    r.trim();
    return r;
  }
  friend Exact operator+(const Exact& a, const Exact& b) noexcept { return add(a, b, b.sign_); }
  friend Exact operator-(const Exact& a, const Exact& b) noexcept { return add(a, b, -b.sign_); }
  friend Exact operator-(const Exact& a) noexcept {
    Exact r = a;
    r.sign_ = -r.sign_;
    return r;
  }

 private:
  /// mag of x shifted left by `bits`, into out (n limbs).
  static int shifted(const Exact& x, int bits, std::uint32_t* out) noexcept {
    const int limbs = bits / 32, rest = bits % 32;
    const int n = std::min(x.n_ + limbs + 1, kLimbs);
    for (int i = 0; i < n; ++i) out[i] = 0;
    for (int i = 0; i < x.n_ && i + limbs < kLimbs; ++i) {
      out[i + limbs] |= x.mag_[i] << rest;
      if (rest != 0 && i + limbs + 1 < kLimbs) out[i + limbs + 1] |= x.mag_[i] >> (32 - rest);
    }
    return n;
  }
  /// a + sb |b|, where sb is the sign b is taken with.
  static Exact add(const Exact& a, const Exact& b, int sb) noexcept {
    if (sb == 0) return a;
    if (a.sign_ == 0) {
      Exact r = b;
      r.sign_ = sb;
      return r;
    }
    const int e = std::min(a.exp_, b.exp_);
    std::uint32_t x[kLimbs], y[kLimbs];
    const int nx = shifted(a, a.exp_ - e, x), ny = shifted(b, b.exp_ - e, y);
    Exact r;
    r.exp_ = e;
    r.n_ = std::max(nx, ny);
    for (int i = nx; i < r.n_; ++i) x[i] = 0;
    for (int i = ny; i < r.n_; ++i) y[i] = 0;
    if (a.sign_ == sb) {
      std::uint64_t carry = 0;
      for (int i = 0; i < r.n_; ++i) {
        carry += std::uint64_t(x[i]) + y[i];
        r.mag_[i] = static_cast<std::uint32_t>(carry);
        carry >>= 32;
      }
      if (carry != 0 && r.n_ < kLimbs) r.mag_[r.n_++] = static_cast<std::uint32_t>(carry);
      r.sign_ = a.sign_;
    } else {
      int cmp = 0;
      for (int i = r.n_; i-- > 0 && cmp == 0;) cmp = x[i] < y[i] ? -1 : (x[i] > y[i] ? 1 : 0);
      if (cmp == 0) return Exact();
      const std::uint32_t* big = cmp > 0 ? x : y;
      const std::uint32_t* small = cmp > 0 ? y : x;
      std::int64_t borrow = 0;
      for (int i = 0; i < r.n_; ++i) {
        const std::int64_t d = std::int64_t(big[i]) - small[i] - borrow;
        borrow = d < 0 ? 1 : 0;
        r.mag_[i] = static_cast<std::uint32_t>(d + (borrow << 32));
      }
      r.sign_ = cmp > 0 ? a.sign_ : sb;
    }
    r.trim();
    return r;
  }
  /// Drops zero limbs at both ends (the value is unchanged).
  void trim() noexcept {
    while (n_ > 0 && mag_[n_ - 1] == 0) --n_;
    if (n_ == 0) {
      sign_ = 0;
      exp_ = 0;
      return;
    }
    int lo = 0;
    while (mag_[lo] == 0) ++lo;
    if (lo > 0) {
      for (int i = lo; i < n_; ++i) mag_[i - lo] = mag_[i];
      n_ -= lo;
      exp_ += 32 * lo;
    }
  }
  int sign_ = 0;
  int exp_ = 0;
  int n_ = 0;
  std::uint32_t mag_[kLimbs];
};

/// Signs this thread has had to evaluate exactly (the filter could not prove them). Counted only
/// on that rare path; benchmarks read it to report the filter's hit rate.
inline thread_local std::uint64_t exact_evaluations = 0;

/// The exact sign of f's polynomial: f(Bounded{}) when its bound proves the sign, else f(Exact{}).
/// f is a generic callable taking a number-type tag and returning the polynomial's value.
template <class F>
int exact_sign(F&& f) noexcept {
  const int s = f(Bounded{}).certain_sign();
  if (s != 2) [[likely]]
    return s;
  ++exact_evaluations;
  return f(Exact{}).sign();
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

/// orient() where its filter cannot tell: kept out of line, so that the filter inlines.
[[gnu::noinline]] inline int orient_beyond_filter(const Vec2c& a, const Vec2c& b, const Vec2c& c) noexcept {
  const double m = std::max(
      {std::fabs(a.x()), std::fabs(a.y()), std::fabs(b.x()), std::fabs(b.y()), std::fabs(c.x()), std::fabs(c.y())});
  if (m == 0.0) return 0;
  ++exact_evaluations;
  // The expansion needs every non-zero coordinate within kExpansionSpread of the largest.
  double lo = m;
  for (const double v : {a.x(), a.y(), b.x(), b.y(), c.x(), c.y()}) {
    if (v != 0.0) lo = std::min(lo, std::fabs(v));
  }
  if (lo < kExpansionSpread * m) {
    const Exact ax(a.x()), ay(a.y());
    return ((Exact(b.x()) - ax) * (Exact(c.y()) - ay) - (Exact(b.y()) - ay) * (Exact(c.x()) - ax)).sign();
  }
  int e = 0;
  static_cast<void>(std::frexp(m, &e));  // m in [2^(e-1), 2^e)
  const int k = 510 - e;
  if (k == 0) return orient_expansion(a, b, c);
  auto s = [k](const Vec2c& v) { return Vec2c(std::ldexp(v.x(), k), std::ldexp(v.y(), k)); };
  return orient_expansion(s(a), s(b), s(c));
}

/// The squared distance from v to the segment from a to a + d, given dd = |d|^2 > 0 (or 0 with t = 0)
/// and t, the parameter of v's foot clamped to [0, 1]. Beside the segment it is taken from the
/// cross product: the foot a + d t rounds by up to an ulp of a, enough to make an end look closer
/// than the segment it lies beyond. Not where dd or the cross product is subnormal (a segment
/// shorter than 10^-154, say): their lost bits would cost more than the foot's rounding.
inline Calc squared_distance_to_segment(const Vec2c& v, const Vec2c& a, const Vec2c& d, Calc dd, Calc t) noexcept {
  // Both computed and one chosen: a select, where a branch on t mispredicts.
  const Calc cross = d.x() * (v.y() - a.y()) - d.y() * (v.x() - a.x());
  const Calc beside = cross * (cross / dd), from_foot = (v - (a + d * t)).squaredNorm();
  const Calc normal = std::numeric_limits<Calc>::min();
  return t > 0 && t < 1 && dd >= normal && std::fabs(cross) >= normal ? beside : from_foot;
}

}  // namespace detail

/// Sign of the turn a -> b -> c: +1 counter-clockwise (c left of a->b), -1 clockwise, 0 collinear.
///
/// A floating-point filter answers most calls (bound (3 + 16u)u * (|l| + |r|), Shewchuk); the rest
/// expand the determinant into six exact products and sum them exactly.
///
/// Exact for every input the shapes accept (finite, |v| <= 2^500, subnormals included). When
/// every non-zero coordinate is at least 2^-995 times the largest one of the call, the fallback
/// first scales all six coordinates by one power of two (exact, sign-preserving) so that the
/// largest is near 2^510: no product can then overflow, and no product of coordinates within
/// that ratio can underflow. Wider spreads are evaluated with detail::Exact. The filter is
/// skipped when its products are tiny, since underflow breaks its relative error bound.
inline int orient(const Vec2c& a, const Vec2c& b, const Vec2c& c) noexcept {
  const double l = (b.x() - a.x()) * (c.y() - a.y());
  const double r = (b.y() - a.y()) * (c.x() - a.x());
  const double det = l - r;
  const double mag = std::fabs(l) + std::fabs(r);
  if (mag > kFilterFloor) {
    const double bound = 3.3306690738754716e-16 * mag;
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  return detail::orient_beyond_filter(a, b, c);
}

}  // namespace collide
