#pragma once
/// @file judge_target.hpp
/// A libFuzzer target over one in-process adapter (fuzz targets judge_<adapter>): the input
/// bytes decode into one judge Input (two of our shapes, by the fuzz targets' decoder
/// collide/fuzz/decode.hpp, so the pair mutator and its touching moves apply), the adapter
/// answers, judge_answer() judges the answer exactly on the geometry the library stored, and a
/// finding aborts with its account.
///
/// A finding is what the judge's reports count as the library failing: a Crash (an exception, a
/// non-finite push) or a Wrong answer of severity Gross. Agreement, conventions, and wrong
/// answers at touching or rounding level are measurements, never a finding. A target may name
/// documented classes (class-key prefixes, e.g. a teaching library's deliberate slips): answers
/// in them are measurements too, unless the environment sets COLLIDE_JUDGE_FUZZ_SLIPS=1.
///
/// Inputs outside the judge's own domain are skipped, as its generator never sends them: kinds
/// the adapter does not build, and values that are not a clean shape (is_clean_input).
///
/// The adapter is called directly, not through InProcess<A>: that wrapper's signal guard and
/// hang watchdog take SIGSEGV, SIGABRT and SIGALRM from the sanitizers and libFuzzer, which then
/// could neither print the stack of a crash inside the library, nor save its input, nor apply
/// -timeout. Here a signal inside the library is the engine's crash, a hang its timeout.

#include "collide/fuzz/pair_target.hpp"
#include "collide/judge/judge.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace collide::judge::fuzz_target {

/// Reads "flags byte (bit 0: double values, else float), shape a, shape b" and calls f(a, b)
/// when both decode.
template <class F>
void decode_case(collide::fuzz::Reader& r, F&& f) {
  collide::fuzz::with_pair(r, collide::fuzz::pair_only(f));
}

/// "aabb 0x0p+0 0x0p+0 0x1p+0 0x1p+0": a shape's kind and values, exactly.
inline std::string hex_values(const ShapeData& d) {
  std::string out(name(d.kind));
  for (double v : d.values) {
    char buf[40];
    std::snprintf(buf, sizeof buf, " %a", v);
    out += buf;
  }
  return out;
}

/// COLLIDE_JUDGE_FUZZ_SLIPS set and not "0": documented classes are findings too.
inline bool slips_are_findings() {
  const char* v = std::getenv("COLLIDE_JUDGE_FUZZ_SLIPS");
  return v != nullptr && *v != '\0' && std::string_view(v) != "0";
}

inline bool is_failure(const Judgement& j) {
  return j.outcome == Outcome::Crash || (j.outcome == Outcome::Wrong && j.severity == Severity::Gross);
}

inline bool is_documented(const std::string& key, const std::vector<std::string_view>& documented) {
  return std::any_of(documented.begin(), documented.end(),
                     [&](std::string_view prefix) { return key.rfind(prefix, 0) == 0; });
}

/// One target: its adapter, the adapter's declared contract, the documented classes.
template <InProcessAdapter A>
class Target {
 public:
  explicit Target(std::vector<std::string_view> documented = {})
      : info_(adapter_.info()), documented_(std::move(documented)), slips_(slips_are_findings()) {}

  template <Scalar T>
  void check(const Shape<T>& a, const Shape<T>& b) {
    Input in;
    in.a = laws::to_data(a);
    in.b = laws::to_data(b);
    if (!takes(in.a) || !takes(in.b)) return;
    const Answer answer = ask(in);
    const Judgement j = judge_answer(info_, in, answer);
    if (!is_failure(j)) return;
    const std::string key = class_key(in, j);
    const bool documented = is_documented(key, documented_);
    if (documented && !slips_) return;
    report(in, answer, j, key, documented);
  }

 private:
  bool takes(const ShapeData& d) const {
    return std::find(info_.kinds.begin(), info_.kinds.end(), d.kind) != info_.kinds.end() && is_clean_input(d);
  }

  /// The adapter's answer; an exception is the library's (a Threw answer, as InProcess makes it).
  Answer ask(const Input& in) {
    try {
      return adapter_.answer(in);
    } catch (const std::exception& e) {
      Answer out;
      out.status = Status::Threw;
      out.error = e.what();
      return out;
    }
  }

  [[noreturn]] void report(const Input& in, const Answer& answer, const Judgement& j, const std::string& key,
                           bool documented) const {
    using collide::fuzz::cat;
    std::string account = cat("\n== collide fuzz target ", collide::fuzz::kTarget, ": finding ", key,
                              documented ? " (a documented slip)\n" : "\n");
    account += cat("  library:  ", info_.library, " ", info_.version, "\n");
    account += cat("  a:        ", hex_values(in.a), "\n  b:        ", hex_values(in.b), "\n");
    if (answer.status == Status::Ok)
      account += cat("  stored a: ", hex_values(answer.stored_a), "\n  stored b: ", hex_values(answer.stored_b), "\n");
    account += cat("  got:      ", j.got, "\n  expected: ", j.expected, "\n");
    std::fputs(account.c_str(), stderr);
    std::fflush(stderr);
    std::abort();
  }

  A adapter_;
  Info info_;
  std::vector<std::string_view> documented_;
  bool slips_;
};

}  // namespace collide::judge::fuzz_target
