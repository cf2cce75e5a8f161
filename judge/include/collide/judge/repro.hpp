#pragma once
/// @file repro.hpp
/// Helpers for in-process adapters writing C++ reproducers: values written as their raw bits
/// (every bit survives, with the hex float beside for the reader), and the common prelude.

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace collide::judge::repro {

/// `bits(0x3ff8000000000000) /* 0x1.8p+0 */`: the double, exactly, in C++ source.
inline std::string cpp(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, 8);
  char buf[96];
  std::snprintf(buf, sizeof buf, "bits(0x%016llxULL) /* %a */", static_cast<unsigned long long>(b), v);
  return buf;
}

/// Includes and the bits() helper every C++ reproducer starts with; `what` is its first comment.
inline std::string cpp_prelude(const std::string& what) {
  return "// " + what +
         "\n// Prints the library's answer (first line) beside the exact one, computed in exact\n"
         "// rational arithmetic on the geometry the library stores.\n"
         "#include <cstdint>\n#include <cstdio>\n#include <cstring>\n\n"
         "static double bits(std::uint64_t b) {\n  double v;\n  std::memcpy(&v, &b, 8);\n  return v;\n}\n\n";
}

/// A C string literal of s.
inline std::string cpp_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

}  // namespace collide::judge::repro
