// Plain replay executable: the fuzz target without an engine. Runs every file given (directories
// recursively, in sorted order) through LLVMFuzzerTestOneInput, each in a heap buffer of exactly
// its size so that ASan catches any read past the end.
//
//   replay PATH...                 replay corpus files
//   replay --repeat N PATH...      replay the corpus files N times over (read once, before the
//                                  clock starts) and print the target's own rate, inputs/s:
//                                  the cost of one execution without the engine's bookkeeping
//   replay --cases-of DIR...       replay the regression cases of this target found under DIR:
//                                  *.case files whose source is "fuzz <target> input <hex>" (the
//                                  input bytes through the target, then the law on the values)
//                                  and <target>-*.input raw inputs. A file named instead of a
//                                  directory must be such a case of this target.
//
// Exit status: 0 when everything passed (a failing input aborts, as under the engine); 1 when a
// case's law fails on replay; 2 on usage or I/O errors.

#include "collide/fuzz/failure.hpp"
#include "collide/laws/case_file.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

std::optional<std::vector<std::uint8_t>> read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return std::nullopt;
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void run_bytes(const std::vector<std::uint8_t>& bytes) {
  // Exact-size heap copy: no slack after the last byte.
  const std::unique_ptr<std::uint8_t[]> buf(new std::uint8_t[bytes.size()]);
  if (!bytes.empty()) std::memcpy(buf.get(), bytes.data(), bytes.size());
  LLVMFuzzerTestOneInput(buf.get(), bytes.size());
}

std::vector<fs::path> files_under(const fs::path& root) {
  std::vector<fs::path> out;
  if (fs::is_directory(root)) {
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      if (e.is_regular_file()) out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
  } else {
    out.push_back(root);
  }
  return out;
}

std::optional<std::vector<std::uint8_t>> from_hex(const std::string& s) {
  if (s.size() % 2 != 0) return std::nullopt;
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < s.size(); i += 2) {
    auto digit = [](char c) -> int {
      if (c >= '0' && c <= '9') return c - '0';
      if (c >= 'a' && c <= 'f') return c - 'a' + 10;
      return -1;
    };
    const int hi = digit(s[i]), lo = digit(s[i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    out.push_back(static_cast<std::uint8_t>(hi * 16 + lo));
  }
  return out;
}

}  // namespace

/// Replays every file under roots `repeat` times; prints inputs/s. Returns the exit status.
int replay_repeatedly(const std::vector<fs::path>& roots, unsigned long repeat) {
  std::vector<std::vector<std::uint8_t>> inputs;
  for (const fs::path& root : roots) {
    for (const fs::path& p : files_under(root)) {
      auto bytes = read_bytes(p);
      if (!bytes) {
        std::fprintf(stderr, "%s: cannot read\n", p.string().c_str());
        return 2;
      }
      inputs.push_back(std::move(*bytes));
    }
  }
  const auto start = std::chrono::steady_clock::now();
  for (unsigned long r = 0; r < repeat; ++r) {
    for (const auto& bytes : inputs) run_bytes(bytes);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double runs = static_cast<double>(inputs.size()) * static_cast<double>(repeat);
  std::printf("%s: %zu inputs x %lu in %.3f s: %.0f inputs/s\n", std::string(collide::fuzz::kTarget).c_str(),
              inputs.size(), repeat, seconds, seconds > 0 ? runs / seconds : 0.0);
  return 0;
}

constexpr const char* kUsage = "usage: %s [--cases-of | --repeat N] PATH...\n";

int main(int argc, char** argv) {
  bool cases = false;
  unsigned long repeat = 0;
  std::vector<fs::path> roots;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--cases-of") {
      cases = true;
    } else if (arg == "--repeat") {
      const char* v = i + 1 < argc ? argv[++i] : "";
      const char* end = v + std::char_traits<char>::length(v);
      if (std::from_chars(v, end, repeat).ptr != end || repeat == 0) {
        std::fprintf(stderr, "--repeat needs a positive whole number, got '%s'\n", v);
        return 2;
      }
    } else if (arg == "--help" || arg == "-h") {
      std::printf(kUsage, argv[0]);
      return 0;
    } else {
      roots.emplace_back(arg);
    }
  }
  if (roots.empty() || (cases && repeat > 0)) {
    std::fprintf(stderr, kUsage, argv[0]);
    return 2;
  }
  if (repeat > 0) return replay_repeatedly(roots, repeat);
  const std::string target(collide::fuzz::kTarget);
  const std::string prefix = collide::fuzz::cat("fuzz ", target, " input ");
  std::size_t inputs = 0, case_files = 0, raw = 0;
  int status = 0;
  for (const fs::path& root : roots) {
    if (!fs::exists(root)) {
      if (cases) continue;  // no regression folder yet: nothing of this target to replay
      std::fprintf(stderr, "%s: no such file or directory\n", root.string().c_str());
      return 2;
    }
    const std::size_t replayed_before = case_files + raw;
    for (const fs::path& p : files_under(root)) {
      if (!cases) {
        const auto bytes = read_bytes(p);
        if (!bytes) {
          std::fprintf(stderr, "%s: cannot read\n", p.string().c_str());
          return 2;
        }
        run_bytes(*bytes);
        ++inputs;
        continue;
      }
      const std::string file = p.filename().string();
      if (p.extension() == ".input" && file.rfind(target + "-", 0) == 0) {
        const auto bytes = read_bytes(p);
        if (!bytes) return 2;
        std::printf("replaying %s\n", p.string().c_str());
        run_bytes(*bytes);
        ++raw;
      } else if (p.extension() == ".case") {
        collide::laws::Case c;
        try {
          c = collide::laws::read_case(p);
        } catch (const std::exception& e) {
          std::fprintf(stderr, "%s: %s\n", p.string().c_str(), e.what());
          status = 1;
          continue;
        }
        if (c.source.rfind(prefix, 0) != 0) continue;  // another target's or a property's case
        const auto bytes = from_hex(c.source.substr(prefix.size()));
        if (!bytes) {
          std::fprintf(stderr, "%s: malformed input hex in source line\n", p.string().c_str());
          status = 1;
          continue;
        }
        std::printf("replaying %s\n", p.string().c_str());
        run_bytes(*bytes);
        const collide::laws::Verdict v = collide::laws::replay(c);
        if (!v.ok) {
          std::fprintf(stderr, "%s: law %s still broken\n  expected: %s\n  got: %s\n  %s\n", p.string().c_str(),
                       std::string(collide::laws::name(c.law)).c_str(), v.expected.c_str(), v.got.c_str(),
                       v.account.c_str());
          status = 1;
        }
        ++case_files;
      }
    }
    // A case named on the command line that this target does not replay would pass unseen.
    if (cases && status == 0 && !fs::is_directory(root) && case_files + raw == replayed_before) {
      std::fprintf(stderr, "%s: not a regression case of fuzz target %s\n", root.string().c_str(), target.c_str());
      return 2;
    }
  }
  if (cases) {
    std::printf("%s: replayed %zu case files and %zu raw inputs\n", target.c_str(), case_files, raw);
  } else {
    std::printf("%s: replayed %zu inputs\n", target.c_str(), inputs);
  }
  return status;
}
