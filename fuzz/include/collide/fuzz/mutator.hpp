#pragma once
/// @file mutator.hpp
/// The custom mutator shared by the targets (libFuzzer's LLVMFuzzerCustomMutator).
///
/// clang does not instrument floating-point comparisons, so coverage feedback cannot steer
/// coordinates toward the boundary between "overlapping" and "separated" where the library may
/// err. This mutator works on decoded fields instead of bytes:
/// - nudge a coordinate by a few ulps (or scale it slightly),
/// - copy a coordinate, or a whole point, from one shape to another (shared vertices, edges on
///   one line),
/// - place two shapes exactly touching: bisect a translation of one shape until the library's
///   overlaps() flips, then write the translated coordinates back,
/// - set a scalar to a special value (0, -0, NaN, +-inf, subnormal, limits of the valid range),
/// - or hand the bytes to libFuzzer's own mutator (structure changes: kinds, counts, flags).
///
/// Only libFuzzer builds include this header's entry point (the replay build has no
/// LLVMFuzzerMutate to call).

#include "collide/fuzz/decode.hpp"
#include "collide/fuzz/reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <vector>

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace collide::fuzz {

using Rng = std::minstd_rand;

inline std::size_t pick(Rng& rng, std::size_t n) {
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
}

/// Reads a field's value (float fields widen exactly).
inline double load(const std::uint8_t* data, const Field& f) {
  if (f.width == 4) {
    float v;
    std::memcpy(&v, data + f.offset, 4);
    return v;
  }
  double v;
  std::memcpy(&v, data + f.offset, 8);
  return v;
}

/// double -> float as the hardware rounds, without the undefined behaviour of converting a value
/// beyond float's range: those become infinities.
inline float to_float(double v) {
  if (std::isfinite(v) && std::fabs(v) > double(std::numeric_limits<float>::max())) {
    return std::copysign(std::numeric_limits<float>::infinity(), static_cast<float>(std::copysign(1.0, v)));
  }
  return static_cast<float>(v);
}

/// Writes a value into a field, rounding to float for 4-byte fields.
inline void store(std::uint8_t* data, const Field& f, double v) {
  if (f.width == 4) {
    const float x = to_float(v);
    std::memcpy(data + f.offset, &x, 4);
  } else {
    std::memcpy(data + f.offset, &v, 8);
  }
}

/// Moves a value by k units in the last place of its own width (k may be negative).
inline void nudge_ulps(std::uint8_t* data, const Field& f, int k) {
  if (f.width == 4) {
    float x;
    std::memcpy(&x, data + f.offset, 4);
    const float to = k > 0 ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
    for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, to);
    std::memcpy(data + f.offset, &x, 4);
  } else {
    double x;
    std::memcpy(&x, data + f.offset, 8);
    const double to = k > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, to);
    std::memcpy(data + f.offset, &x, 8);
  }
}

/// A translation that brings group `moving` into exact touching with another group, or nothing.
/// Supplied per target (pair targets use touch_pair below).
struct TouchRequest {
  int moving;
  int other;
};

namespace detail {

template <class S>
Vec2c bounds_center(const S& s) {
  const auto b = bounds(s);
  return (widen(b.min()) + widen(b.max())) * 0.5;
}

template <class S>
Calc bounds_diagonal(const S& s) {
  const auto b = bounds(s);
  return (widen(b.max()) - widen(b.min())).norm();
}

}  // namespace detail

/// Bisects t so that `moving` translated by t * dir just touches `other` according to the
/// library's overlaps(); returns the translation on the overlapping or the separated side of the
/// flip (chosen at random), or nothing when no bracket is found or a translation is rejected.
template <Scalar T>
std::optional<Vec2<T>> touching_translation(const Shape<T>& moving, const Shape<T>& other, Rng& rng) {
  const Vec2c cm = detail::bounds_center(moving), co = detail::bounds_center(other);
  Vec2c dir = co - cm;
  const Calc len = dir.norm();
  if (!(len > 0) || pick(rng, 2) == 0) {
    const double angle = std::uniform_real_distribution<double>(0, 6.283185307179586)(rng);
    dir = Vec2c(std::cos(angle), std::sin(angle));
  } else {
    dir /= len;
  }
  auto meets = [&](Calc t) -> std::optional<bool> {
    if (!(std::fabs(t) <= Calc(max_magnitude<T>()))) return std::nullopt;  // keeps the cast to T defined
    const Vec2<T> v = (dir * t).template cast<T>();
    if (!v.allFinite()) return std::nullopt;
    const Expected<Shape<T>> m = translated(moving, v);
    if (!m) return std::nullopt;
    return overlaps(m.value(), other);
  };
  const Calc reach = len + detail::bounds_diagonal(moving) + detail::bounds_diagonal(other);
  if (!std::isfinite(reach)) return std::nullopt;
  // Bracket: `apart` separated, `close` overlapping.
  Calc apart = -(reach + 1), close = 0;
  std::optional<bool> at0 = meets(0);
  if (!at0) return std::nullopt;
  if (!*at0) {
    // Separated now: move toward the other shape; its bounds center is a likely overlap.
    apart = 0;
    close = dir.dot(co - cm);
    const std::optional<bool> c = meets(close);
    if (!c || !*c) return std::nullopt;
  } else {
    const std::optional<bool> a = meets(apart);
    if (!a || *a) return std::nullopt;
  }
  for (int i = 0; i < 80; ++i) {
    const Calc mid = apart + (close - apart) * 0.5;
    if (mid == apart || mid == close) break;
    const std::optional<bool> m = meets(mid);
    if (!m) return std::nullopt;
    (*m ? close : apart) = mid;
  }
  const Calc t = pick(rng, 2) == 0 ? close : apart;
  return (dir * t).template cast<T>();
}

/// Mutation for a pair input: decodes it and returns the translation of `req.moving` found by
/// touching_translation, as doubles.
template <class DecodePair>
std::optional<Vec2c> touch_pair(const std::uint8_t* data, std::size_t size, TouchRequest req, Rng& rng,
                                DecodePair&& decode_pair) {
  std::optional<Vec2c> out;
  Reader r(data, size);
  decode_pair(r, [&]<Scalar T>(const Shape<T>& a, const Shape<T>& b) {
    const Shape<T>& moving = req.moving == 0 ? a : b;
    const Shape<T>& other = req.moving == 0 ? b : a;
    if (auto v = touching_translation<T>(moving, other, rng)) out = v->template cast<Calc>();
  });
  return out;
}

/// Tuning of the mutator per target.
struct MutatorOptions {
  unsigned special_weight = 1;  ///< relative weight of "set a special value" (shapes_from_bytes: high)
  bool touch = true;            ///< whether the target supports touching placement
};

/// One mutation. parse(data, size) -> std::vector<Field>; touch(data, size, req, rng) ->
/// std::optional<Vec2c> (ignored when options.touch is false).
template <class Parse, class Touch>
std::size_t mutate(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed, Parse&& parse,
                   Touch&& touch, MutatorOptions options = {}) {
  Rng rng(seed == 0 ? 1u : seed);
  if (size == 0 || pick(rng, 4) == 0) return LLVMFuzzerMutate(data, size, max_size);
  std::vector<Field> fields = parse(static_cast<const std::uint8_t*>(data), size);
  // Materialise fields read past the end (zero bytes), when they fit.
  std::size_t needed = size;
  for (const Field& f : fields) needed = std::max(needed, f.offset + f.width);
  if (needed > max_size) {
    std::erase_if(fields, [&](const Field& f) { return f.offset + f.width > size; });
  } else if (needed > size) {
    std::memset(data + size, 0, needed - size);
    size = needed;
  }
  if (fields.empty()) return LLVMFuzzerMutate(data, size, max_size);

  const unsigned w_nudge = 6, w_copy = 3, w_point = 2, w_touch = options.touch ? 4 : 0, w_scale = 1;
  const unsigned w_special = options.special_weight;
  const unsigned total = w_nudge + w_copy + w_point + w_touch + w_scale + w_special;
  unsigned op = static_cast<unsigned>(pick(rng, total));

  auto by_group = [&](int g) {
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (fields[i].group == g) idx.push_back(i);
    }
    return idx;
  };

  if (op < w_nudge) {
    const Field& f = fields[pick(rng, fields.size())];
    static constexpr int kSteps[] = {1, -1, 1, -1, 2, -2, 3, -3, 8, -8, 64, -64};
    nudge_ulps(data, f, kSteps[pick(rng, std::size(kSteps))]);
    return size;
  }
  op -= w_nudge;
  if (op < w_copy) {
    // Copy a coordinate from another group; same role preferred, X <-> Y allowed.
    const Field& to = fields[pick(rng, fields.size())];
    std::vector<std::size_t> from;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (fields[i].offset != to.offset && (fields[i].group != to.group || pick(rng, 4) == 0)) from.push_back(i);
    }
    if (from.empty()) return LLVMFuzzerMutate(data, size, max_size);
    store(data, to, load(data, fields[from[pick(rng, from.size())]]));
    return size;
  }
  op -= w_copy;
  if (op < w_point) {
    // Copy a whole point (an X field followed by its Y field) onto a point of another group.
    std::vector<std::size_t> points;
    for (std::size_t i = 0; i + 1 < fields.size(); ++i) {
      if (fields[i].role == Role::X && fields[i + 1].role == Role::Y) points.push_back(i);
    }
    if (points.size() < 2) return LLVMFuzzerMutate(data, size, max_size);
    const std::size_t a = points[pick(rng, points.size())], b = points[pick(rng, points.size())];
    if (a == b) return LLVMFuzzerMutate(data, size, max_size);
    store(data, fields[b], load(data, fields[a]));
    store(data, fields[b + 1], load(data, fields[a + 1]));
    return size;
  }
  op -= w_point;
  if (op < w_touch) {
    const int moving = static_cast<int>(pick(rng, 2));
    const std::optional<Vec2c> v =
        touch(static_cast<const std::uint8_t*>(data), size, TouchRequest{moving, 1 - moving}, rng);
    if (!v) return LLVMFuzzerMutate(data, size, max_size);
    for (std::size_t i : by_group(moving)) {
      const Field& f = fields[i];
      if (f.role != Role::X && f.role != Role::Y) continue;
      const double d = f.role == Role::X ? v->x() : v->y();
      // Same arithmetic as translated(): the sum in the field's own width.
      if (f.width == 4) {
        store(data, f, static_cast<float>(load(data, f)) + to_float(d));
      } else {
        store(data, f, load(data, f) + d);
      }
    }
    return size;
  }
  op -= w_touch;
  if (op < w_scale) {
    const Field& f = fields[pick(rng, fields.size())];
    static constexpr double kFactors[] = {0.5, 2.0, -1.0, 1.0 + 0x1p-20, 1.0 - 0x1p-20, 0x1p-60, 0x1p+60};
    store(data, f, load(data, f) * kFactors[pick(rng, std::size(kFactors))]);
    return size;
  }
  {
    const Field& f = fields[pick(rng, fields.size())];
    const bool is_float = f.width == 4;
    const double big = is_float ? double(max_magnitude<float>()) : max_magnitude<double>();
    const double kSpecial[] = {
        0.0,
        -0.0,
        1.0,
        -1.0,
        std::numeric_limits<double>::quiet_NaN(),
        -std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity(),
        is_float ? double(std::numeric_limits<float>::denorm_min()) : std::numeric_limits<double>::denorm_min(),
        is_float ? double(std::numeric_limits<float>::min()) : std::numeric_limits<double>::min(),
        big,
        -big,
        is_float ? double(std::nextafter(max_magnitude<float>(), std::numeric_limits<float>::infinity()))
                 : std::nextafter(big, std::numeric_limits<double>::infinity()),
        1e38,
        -1e38,
        0x1p-500,
        is_float ? double(std::numeric_limits<float>::max()) : std::numeric_limits<double>::max()};
    store(data, f, kSpecial[pick(rng, std::size(kSpecial))]);
    return size;
  }
}

/// The mutator of a target without a pair of shapes to place touching: read_input(reader) reads
/// an input the way the target does, so that the reader records its fields; the mutation then
/// works on those fields.
template <class ReadInput>
std::size_t mutate_fields(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed,
                          ReadInput&& read_input, MutatorOptions options) {
  options.touch = false;
  auto parse = [&](const std::uint8_t* d, std::size_t n) {
    std::vector<Field> fields;
    Reader r(d, n, &fields);
    read_input(r);
    return fields;
  };
  auto no_touch = [](const std::uint8_t*, std::size_t, TouchRequest, Rng&) { return std::optional<Vec2c>(); };
  return mutate(data, size, max_size, seed, parse, no_touch, options);
}

}  // namespace collide::fuzz
