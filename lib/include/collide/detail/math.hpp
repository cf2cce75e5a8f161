#pragma once
/// @file detail/math.hpp
/// The numeric helpers every floor uses, in the computation type: widening, the cross product
/// and the perpendicular, the cycle index, square roots without a library call, and norms and
/// unit vectors safe from underflow and overflow.

#include "collide/config.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace collide {

namespace detail {

/// The index after i in a cycle of n: a compare, where i % n would divide.
constexpr std::size_t next_index(std::size_t i, std::size_t n) noexcept {
  return i + 1 < n ? i + 1 : 0;
}

}  // namespace detail

/// 2D cross product (z component), computed in Calc.
inline Calc cross(const Vec2c& a, const Vec2c& b) noexcept {
  return a.x() * b.y() - a.y() * b.x();
}

#if defined(__SSE2__)
/// The vector in an SSE2 register (the store and the caller's loads become register moves).
inline Vec2c vec_of(__m128d r) noexcept {
  Vec2c out;
  _mm_storeu_pd(out.data(), r);
  return out;
}
#endif

/// Left perpendicular (rotated +90 degrees).
inline Vec2c perp(const Vec2c& v) noexcept {
#if defined(__SSE2__)
  // One shuffle and a sign flip: built from two scalars, the vector went through the stack.
  const __m128d p = _mm_loadu_pd(v.data());
  return vec_of(_mm_xor_pd(_mm_shuffle_pd(p, p, 1), _mm_set_pd(0.0, -0.0)));
#else
  return {-v.y(), v.x()};
#endif
}

/// Exact widening of a stored vector into the computation type.
template <Scalar T>
inline Vec2c widen(const Vec2<T>& v) noexcept {
  return v.template cast<Calc>();
}

namespace detail {

/// sqrt(x) for x >= 0, the same correctly rounded value, by the instruction alone: std::sqrt also
/// checks for a negative x to set errno, through a library call that gives its caller a stack
/// frame.
[[gnu::always_inline]] inline Calc square_root(Calc x) noexcept {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_sqrt_sd(_mm_setzero_pd(), _mm_set_sd(x)));
#else
  return std::sqrt(x);
#endif
}

/// 1 / sqrt(ww) for the squared length ww of a stored rotation (within a few roundings of T of
/// 1): for |ww - 1| <= 2^-18 by its series about 1 to the second order (the rest is below
/// 2^-55, so the value is within about one rounding of double, as the square root and division
/// are), without their latency; otherwise by them. Exactly 1 for ww = 1 (quarter turns).
inline Calc inverse_norm_near_unit(Calc ww) noexcept {
  const Calc e = ww - 1;  // exact near 1
  if (std::fabs(e) <= 0x1p-18) [[likely]]
    return 1 + e * (Calc(0.375) * e - Calc(0.5));
  return 1 / square_root(ww);
}

/// |v| and v / |v| for a vector v with a component outside [2^-500, 2^500], scaled first by a
/// power of two (see norm_of). Out of line: the common case inlines without them.
[[gnu::noinline]] inline Calc norm_of_scaled(const Vec2c& v, Calc m) noexcept {
  int e = 0;
  static_cast<void>(std::frexp(m, &e));
  return std::ldexp(Vec2c(std::ldexp(v.x(), -e), std::ldexp(v.y(), -e)).norm(), e);
}
[[gnu::noinline]] inline Vec2c unit_of_scaled(const Vec2c& v, Calc m) noexcept {
  int e = 0;
  static_cast<void>(std::frexp(m, &e));
  const Vec2c s(std::ldexp(v.x(), -e), std::ldexp(v.y(), -e));
  return s / s.norm();
}

/// Whether a vector whose largest absolute component is m has a plain norm: |v|^2 neither
/// underflows nor overflows (config.hpp, kPlainNormLow).
[[gnu::always_inline]] inline bool is_plain_magnitude(Calc m) noexcept {
  return m >= kPlainNormLow && m <= kPlainNormHigh;
}

/// |v| without underflow or overflow of |v|^2: a vector with a component outside [2^-500, 2^500]
/// is first scaled by a power of two (exact when scaling up), so a direction between points
/// 1e-159 apart keeps its 53 bits instead of the few left in a subnormal square.
[[gnu::always_inline]] inline Calc norm_of(const Vec2c& v) noexcept {
  const Calc m = std::max(std::fabs(v.x()), std::fabs(v.y()));
  if (!(m > 0) || is_plain_magnitude(m)) [[likely]]
    return v.norm();
  return norm_of_scaled(v, m);
}

/// v / |v| (see norm_of); the zero vector for a zero v.
[[gnu::always_inline]] inline Vec2c unit_of(const Vec2c& v) noexcept {
  const Calc m = std::max(std::fabs(v.x()), std::fabs(v.y()));
#if defined(__SSE2__)
  // The choice is made between registers: between a quotient in registers and unit_of_scaled()'s
  // result in memory, the compiler keeps the chosen vector in memory, and every later use of it
  // waits on the store.
  __m128d r;
  if (!(m > 0)) {
    r = _mm_setzero_pd();
  } else if (is_plain_magnitude(m)) [[likely]] {
    r = _mm_div_pd(_mm_loadu_pd(v.data()), _mm_set1_pd(v.norm()));
  } else {
    r = _mm_loadu_pd(unit_of_scaled(v, m).data());
  }
  return vec_of(r);
#else
  if (!(m > 0)) return Vec2c::Zero();
  if (is_plain_magnitude(m)) [[likely]]
    return v / v.norm();
  return unit_of_scaled(v, m);
#endif
}

/// d / dist where plain, else unit_of(d), chosen between registers as unit_of() chooses.
[[gnu::always_inline]] inline Vec2c quotient_or_unit(const Vec2c& d, Calc dist, bool plain) noexcept {
#if defined(__SSE2__)
  const __m128d r = plain ? _mm_div_pd(_mm_loadu_pd(d.data()), _mm_set1_pd(dist)) : _mm_loadu_pd(unit_of(d).data());
  return vec_of(r);
#else
  return plain ? Vec2c(d / dist) : unit_of(d);
#endif
}

/// unit_of(d) given dist = norm_of(d), bit for bit, without a second square root (always inlined:
/// a call spills the caller's registers around the division it waits on).
[[gnu::always_inline]] inline Vec2c direction_of(const Vec2c& d, Calc dist) noexcept {
  const Calc m = std::max(std::fabs(d.x()), std::fabs(d.y()));
  return quotient_or_unit(d, dist, is_plain_magnitude(m));
}

}  // namespace detail

}  // namespace collide
