#pragma once
// The consumer programs' one check: prints each expectation and counts the failures.
#include <cstdio>

namespace consumer {

inline int failures = 0;

inline void check(bool ok, const char* what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what);
  if (!ok) ++failures;
}

}  // namespace consumer
