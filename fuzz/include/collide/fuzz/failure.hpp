#pragma once
/// @file failure.hpp
/// What a fuzz target does when a law breaks: print a readable account of the case, write it as a
/// regression case (the same .case + .svg files the property suite writes) when
/// COLLIDE_FUZZ_CASE_DIR names a directory, then abort so the engine records the input.
///
/// The case's `source` line is "fuzz <target> input <hex bytes>": the replay executable runs those
/// exact bytes through the target again, and the regression replay runs the law on the values.

#include "collide/fuzz/decode.hpp"
#include "collide/laws/case_file.hpp"
#include "collide/laws/hash.hpp"
#include "collide/laws/laws.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#ifndef COLLIDE_FUZZ_TARGET
#error "COLLIDE_FUZZ_TARGET must name the fuzz target (set by fuzz/CMakeLists.txt)"
#endif

namespace collide::fuzz {

/// The target's name, e.g. "overlap_oracle".
inline constexpr std::string_view kTarget = COLLIDE_FUZZ_TARGET;

/// The input being run, recorded by the entry point so that a failure can store it.
struct CurrentInput {
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
};
inline CurrentInput& current_input() {
  static CurrentInput input;
  return input;
}

inline std::string to_hex(const std::uint8_t* data, std::size_t size) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * size);
  for (std::size_t i = 0; i < size; ++i) {
    out.push_back(kDigits[data[i] >> 4]);
    out.push_back(kDigits[data[i] & 15]);
  }
  return out;
}

/// Concatenates strings by appending (g++ 12 warns falsely, -Wrestrict, on `"..." + std::string`).
template <class... Parts>
std::string cat(const Parts&... parts) {
  std::string out;
  ((out += parts), ...);
  return out;
}

/// "fuzz <target> input <hex>": the case's source line.
inline std::string source_line() {
  return cat("fuzz ", kTarget, " input ", to_hex(current_input().data, current_input().size));
}

/// FNV-1a of the input, for file names of raw regression inputs.
inline std::uint32_t input_hash(const std::uint8_t* data, std::size_t size) {
  return laws::fnv1a(std::span<const std::uint8_t>(data, size));
}

inline const char* case_dir() {
  const char* dir = std::getenv("COLLIDE_FUZZ_CASE_DIR");
  return dir != nullptr && *dir != '\0' ? dir : nullptr;
}

/// A broken law on shapes: account, case file, abort. `complete` fills the law's other inputs
/// into the case (the ray of a raycast case, the values of a rejection case).
template <Scalar T>
[[noreturn]] void fail(laws::Law law, const Shape<T>& a, const std::optional<Shape<T>>& b, const laws::Verdict& v,
                       const std::function<void(laws::Case&)>& complete = {}) {
  std::fprintf(stderr,
               "\n== collide fuzz target %s: law '%.*s' broken (%s)\n"
               "  a: %s\n",
               std::string(kTarget).c_str(), int(name(law).size()), name(law).data(), scalar_name<T>(),
               describe(a).c_str());
  if (b) std::fprintf(stderr, "  b: %s\n", describe(*b).c_str());
  std::fprintf(stderr, "  expected: %s\n  got:      %s\n  account:  %s\n", v.expected.c_str(), v.got.c_str(),
               v.account.c_str());
  if (const char* dir = case_dir()) {
    try {
      std::filesystem::create_directories(dir);
      laws::Case c = laws::make_case(law, a, b, v, source_line());
      if (complete) complete(c);
      const std::filesystem::path path = laws::save_case(dir, c);
      std::fprintf(stderr, "  case file: %s\n", path.string().c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "  case file not written: %s\n", e.what());
    }
  }
  std::fflush(stderr);
  std::abort();
}

/// A broken check that has no case-file law (e.g. broadphase against brute force, or a factory
/// and its throwing constructor disagreeing): account, raw input file, abort. The raw input is
/// written as <dir>/<target>-<hash>.input with the account beside it (.txt).
template <class... Parts>
[[noreturn]] void fail_raw(const Parts&... parts) {
  const std::string account = cat(parts...);
  std::fprintf(stderr, "\n== collide fuzz target %s: check failed\n  %s\n", std::string(kTarget).c_str(),
               account.c_str());
  if (const char* dir = case_dir()) {
    const CurrentInput& in = current_input();
    char stem[64];
    std::snprintf(stem, sizeof stem, "%s-%08x", std::string(kTarget).c_str(), input_hash(in.data, in.size));
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    const std::filesystem::path base = std::filesystem::path(dir) / stem;
    std::ofstream bin(base.string() + ".input", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(in.data), static_cast<std::streamsize>(in.size));
    std::ofstream txt(base.string() + ".txt");
    txt << "fuzz target " << kTarget << "\n" << account << "\n";
    std::fprintf(stderr, "  regression input: %s.input\n", base.string().c_str());
  }
  std::fflush(stderr);
  std::abort();
}

/// A broken transform law (laws.hpp, law 10) on shapes placed by transforms: the account with
/// both placed shapes, and the raw input kept as the regression input (fail_raw).
template <Scalar T>
void require_placed(std::string_view law, const laws::Verdict& v, const Shape<T>& a, const Transform<T>& xa,
                    const std::optional<Shape<T>>& b = std::nullopt, const Transform<T>& xb = Transform<T>()) {
  if (v.ok) return;
  fail_raw("law '", law, "' broken (", scalar_name<T>(), ")\n  a: ", describe(a), "\n  xa: ", describe(xa),
           b ? cat("\n  b: ", describe(*b), "\n  xb: ", describe(xb)) : std::string(), "\n  expected: ", v.expected,
           "\n  got:      ", v.got, "\n  account:  ", v.account);
}

/// Checks a law's verdict: a broken law fails; an allowed disagreement passes.
template <Scalar T>
void require(laws::Law law, const laws::Verdict& v, const Shape<T>& a, const std::optional<Shape<T>>& b) {
  if (!v.ok) fail(law, a, b, v);
}

}  // namespace collide::fuzz
