// Fuzz target cast: shape_cast() and time_of_impact() against the exact oracle for moving shapes
// (laws "cast", "cast_symmetry" and the time-of-impact law). Invalid motions (NaN, infinity,
// max_t < 0, beyond the range) must give CastOutcome::InvalidInput.
//
// Input: flags byte (bit 0: double; bit 2: grazing: when the decoded pair touches, a's velocity
// is turned along the contact's tangent, plus vb.y times its normal, and a is moved back along it
// by half of max_t, so the shapes pass each other at about max_t / 2), shape a, shape b, then
// va x y, vb x y, max_t, and the turns of a and b for time_of_impact (a's sweep: centre of
// rotation at the local origin, moving by va over the step and turning by its angle; b's by vb).
// Flags bit 3: a transform for a follows (px py qx qy, through make_with_rotation), bit 4: one
// for b: the shapes are then local, placed by them (a transform that is not made stays the
// identity); time of impact uses the local shapes as they are.

#include "collide/fuzz/pair_target.hpp"
#include "collide/laws/laws.hpp"
#include "collide/oracle/oracle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace {

using namespace collide;
using namespace collide::fuzz;

template <Scalar T>
struct MotionCase {
  laws::CastInput<T> in;
  T turn_a, turn_b;
};

template <Scalar T>
MotionCase<T> read_motion(Reader& r) {
  r.set_group(2);
  MotionCase<T> m{};
  m.in.va.x() = r.scalar<T>(Role::Other);
  m.in.va.y() = r.scalar<T>(Role::Other);
  m.in.vb.x() = r.scalar<T>(Role::Other);
  m.in.vb.y() = r.scalar<T>(Role::Other);
  m.in.max_t = r.scalar<T>(Role::Size);
  m.turn_a = r.scalar<T>(Role::Other);
  m.turn_b = r.scalar<T>(Role::Other);
  return m;
}

/// The optional transforms after the motion (flags bits 3 and 4).
template <Scalar T>
void read_transforms(Reader& r, std::uint8_t bits, laws::CastInput<T>& in) {
  for (const auto& [bit, x] : {std::pair{8, &in.xa}, std::pair{16, &in.xb}}) {
    if ((bits & bit) == 0) continue;
    const Expected<Transform<T>> made = decode_transform<T>(r);
    if (made) *x = *made;
  }
}

/// Calls f(a, b, motion) with a valid pair and the motion read after it; the grazing bit aims a.
template <class F>
void decode_case(Reader& r, F&& f) {
  with_pair(r, [&](const PairHeader& h, const auto& a, const auto& b, Reader& rest) {
    using T = scalar_of_t<std::remove_cvref_t<decltype(a)>>;
    MotionCase<T> m = read_motion<T>(rest);
    read_transforms<T>(rest, h.bits, m.in);
    if ((h.bits & 4) == 0) {
      f(a, b, m);
      return;
    }
    const auto c = contact(a, m.in.xa, b, m.in.xb);
    const Vec2c va = widen(m.in.va), vb = widen(m.in.vb);
    if (!c || !va.allFinite() || !vb.allFinite() || !std::isfinite(double(m.in.max_t))) {
      f(a, b, m);
      return;
    }
    const Vec2c n = widen(c->normal), tangent(-n.y(), n.x());
    const Vec2c v = tangent * va.norm() + n * vb.y();
    m.in.va = v.template cast<T>();
    m.in.vb = Vec2<T>(0, 0);
    const Vec2<T> back((-widen(m.in.va) * (double(m.in.max_t) / 2)).template cast<T>());
    if (!m.in.xa.is_identity()) {  // a placed: its transform moves back
      if (const auto x = m.in.xa.moved(back)) m.in.xa = *x;
      f(a, b, m);
      return;
    }
    const auto moved = translated(a, back);
    if (moved) {
      f(moved.value(), b, m);
    } else {
      f(a, b, m);
    }
  });
}

template <Scalar T>
bool valid_motion(const laws::CastInput<T>& in) {
  const double lim = double(max_magnitude<T>());
  const double mt = double(in.max_t);
  if (!std::isfinite(mt) || mt < 0) return false;
  for (const double v : {double(in.va.x()), double(in.va.y()), double(in.vb.x()), double(in.vb.y())}) {
    if (!std::isfinite(v) || std::fabs(v) > lim) return false;
  }
  const double travel = std::max({(widen(in.va) - widen(in.vb)).cwiseAbs().maxCoeff(),
                                  widen(in.va).cwiseAbs().maxCoeff(), widen(in.vb).cwiseAbs().maxCoeff()});
  return travel * mt <= 2 * lim;
}

template <Scalar T>
void check(const Shape<T>& a, const Shape<T>& b, const MotionCase<T>& m) {
  if (!valid_motion(m.in)) {
    if (shape_cast(a, m.in.xa, m.in.va, b, m.in.xb, m.in.vb, m.in.max_t).outcome != CastOutcome::InvalidInput) {
      fail_raw("shape_cast accepted an invalid motion: va ", format_point(widen(m.in.va)), " vb ",
               format_point(widen(m.in.vb)), " max_t ", format_value(double(m.in.max_t)));
    }
  } else {
    for (const laws::Verdict& v : {laws::cast_law(a, b, m.in), laws::cast_symmetry(a, b, m.in)}) {
      if (!v.ok) fail_raw("law broken: ", v.account);
    }
  }
  // Time of impact: a's centre of rotation at its local origin, moving by va over the step.
  Sweep<T> sa, sb;
  sa.c1 = m.in.va;
  sa.a1 = m.turn_a;
  sb.c1 = m.in.vb;
  sb.a1 = m.turn_b;
  const T max_t = std::isfinite(double(m.in.max_t)) ? T(std::fmod(std::fabs(double(m.in.max_t)), 1.0)) : T(1);
  const bool valid = valid_motion(laws::CastInput<T>{m.in.va, m.in.vb, T(1), {}, {}}) &&
                     std::fabs(double(m.turn_a)) <= double(max_magnitude<T>()) &&
                     std::fabs(double(m.turn_b)) <= double(max_magnitude<T>());
  if (!valid) {
    if (time_of_impact(a, sa, b, sb, max_t).outcome != CastOutcome::InvalidInput) {
      fail_raw("time_of_impact accepted an invalid sweep: turns ", format_value(double(m.turn_a)), " ",
               format_value(double(m.turn_b)));
    }
    return;
  }
  static constexpr std::array<double, 6> kSamples = {0, 0.25, 0.5, 0.75, 0.9990234375, 1};
  const laws::Verdict v = laws::toi_law(a, sa, b, sb, max_t, std::span<const double>(kSamples));
  if (!v.ok) fail_raw("law broken: ", v.account);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  current_input() = {data, size};
  Reader r(data, size);
  decode_case(r, [](const auto& a, const auto& b, const auto& m) { check(a, b, m); });
  return 0;
}

#if defined(COLLIDE_FUZZ_ENGINE)
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  return mutate_pair_case(data, size, max_size, seed, [](Reader& r, auto&& f) {
    decode_case(r, [&](const auto& a, const auto& b, const auto&) { f(a, b); });
  });
}
#endif
