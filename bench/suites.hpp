#pragma once
// The benchmark suites. Each cross-checks its answers against the peers first, registers its
// benchmarks, and returns false (after printing why) if any answer differs.

namespace bench {
bool register_narrowphase();
bool register_broadphase();
bool register_game_loop();
bool register_mass();      // bench/mass.cpp: mass, centroid and inertia
bool register_chain();     // bench/chain.cpp: chain segments against Box2D's one-sided edges
bool register_distance();  // bench/distance.cpp: closest points and signed distances
bool register_cast();      // bench/cast.cpp, built when the exact oracle is available
}  // namespace bench
