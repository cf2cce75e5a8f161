// collide_bench: cross-checks every suite against Box2D and the naive baselines, then times them.
// Exits with status 1 before timing anything if an answer differs.

#include "suites.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  const bool narrow = bench::register_narrowphase();
  const bool broad = bench::register_broadphase();
  const bool loop = bench::register_game_loop();
  const bool dist = bench::register_distance();
  const bool mass = bench::register_mass();
  const bool chain = bench::register_chain();
#if defined(COLLIDE_BENCH_CAST)
  bench::register_cast();
#endif
  if (!narrow || !broad || !loop || !dist || !mass || !chain) {
    std::fprintf(stderr, "cross-check FAILED: collide and its peers disagree; nothing was timed\n");
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
