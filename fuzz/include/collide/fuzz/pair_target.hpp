#pragma once
/// @file pair_target.hpp
/// Plumbing shared by the targets whose input is a pair of shapes: the entry point records the
/// input, and (libFuzzer builds only) the custom mutator works on the pair's decoded fields.

#include "collide/fuzz/decode.hpp"
#include "collide/fuzz/failure.hpp"
#include "collide/fuzz/reader.hpp"

#include <optional>

#if defined(COLLIDE_FUZZ_ENGINE)
#include "collide/fuzz/mutator.hpp"
#endif

namespace collide::fuzz {

/// Wraps a generic callback f(a, b) as the callback with_pair expects.
template <class F>
auto pair_only(F&& f) {
  return [&](const PairHeader&, const auto& a, const auto& b, Reader&) { f(a, b); };
}

/// Wraps a callback f(a, xa, b, xb) as the callback with_placed_pair expects.
template <class F>
auto placed_pair_only(F&& f) {
  return [&](const PairHeader&, const auto& a, const auto& xa, const auto& b, const auto& xb, Reader&) {
    f(a, xa, b, xb);
  };
}

/// std::optional holding b, for laws that take an optional second shape.
template <Scalar T>
std::optional<Shape<T>> some(const Shape<T>& s) {
  return s;
}

#if defined(COLLIDE_FUZZ_ENGINE)
/// The custom mutator for a pair target. decode_case(reader, f) must read the whole input the
/// way the target does and call f(a, b) with the decoded pair when it is valid.
template <class DecodeCase>
std::size_t mutate_pair_case(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed,
                             DecodeCase&& decode_case) {
  auto parse = [&](const std::uint8_t* d, std::size_t n) {
    std::vector<Field> fields;
    Reader r(d, n, &fields);
    decode_case(r, [](const auto&, const auto&) {});
    return fields;
  };
  auto touch = [&](const std::uint8_t* d, std::size_t n, TouchRequest req, Rng& rng) {
    return touch_pair(d, n, req, rng, [&](Reader& r, auto&& f) { decode_case(r, f); });
  };
  return mutate(data, size, max_size, seed, parse, touch);
}
#endif

}  // namespace collide::fuzz

/// Defines the entry points of a pair target: LLVMFuzzerTestOneInput records the input, decodes it
/// with decode_case(reader, f) and calls check(a, b); libFuzzer builds also get the pair mutator.
#if defined(COLLIDE_FUZZ_ENGINE)
#define COLLIDE_PAIR_MUTATOR(decode_case)                                                                      \
  extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,   \
                                                 unsigned int seed) {                                          \
    return ::collide::fuzz::mutate_pair_case(data, size, max_size, seed,                                       \
                                             [](::collide::fuzz::Reader& r, auto&& f) { decode_case(r, f); }); \
  }
#else
#define COLLIDE_PAIR_MUTATOR(decode_case)
#endif
/// As COLLIDE_PAIR_FUZZ_TARGET for a target whose decode_case(reader, f) calls f(a, xa, b, xb)
/// (with_placed_pair) and whose check takes the shapes with their transforms; the mutator sees the
/// stored shapes.
#define COLLIDE_PLACED_PAIR_FUZZ_TARGET(decode_case, check)                                                    \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {                          \
    ::collide::fuzz::current_input() = {data, size};                                                           \
    ::collide::fuzz::Reader r(data, size);                                                                     \
    decode_case(r, [](const auto& a, const auto& xa, const auto& b, const auto& xb) { check(a, xa, b, xb); }); \
    return 0;                                                                                                  \
  }                                                                                                            \
  COLLIDE_PAIR_MUTATOR(([](::collide::fuzz::Reader& r, auto&& f) {                                             \
    decode_case(r, [&](const auto& a, const auto&, const auto& b, const auto&) { f(a, b); });                  \
  }))
/// As COLLIDE_PLACED_PAIR_FUZZ_TARGET for a target whose decode_case(reader, f) calls
/// f(a, xa, b, xb, extra) with what the target reads after the pair, and whose check takes it too.
#define COLLIDE_PLACED_PAIR_EXTRA_FUZZ_TARGET(decode_case, check)                                          \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {                      \
    ::collide::fuzz::current_input() = {data, size};                                                       \
    ::collide::fuzz::Reader r(data, size);                                                                 \
    decode_case(r, [](const auto& a, const auto& xa, const auto& b, const auto& xb, const auto& extra) {   \
      check(a, xa, b, xb, extra);                                                                          \
    });                                                                                                    \
    return 0;                                                                                              \
  }                                                                                                        \
  COLLIDE_PAIR_MUTATOR(([](::collide::fuzz::Reader& r, auto&& f) {                                         \
    decode_case(r, [&](const auto& a, const auto&, const auto& b, const auto&, const auto&) { f(a, b); }); \
  }))

#define COLLIDE_PAIR_FUZZ_TARGET(decode_case, check)                                  \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    ::collide::fuzz::current_input() = {data, size};                                  \
    ::collide::fuzz::Reader r(data, size);                                            \
    decode_case(r, [](const auto& a, const auto& b) { check(a, b); });                \
    return 0;                                                                         \
  }                                                                                   \
  COLLIDE_PAIR_MUTATOR(decode_case)
