#pragma once
// The benchmark suites. Each cross-checks its answers against the peers first, registers its
// benchmarks, and returns false (after printing why) if any answer differs.

namespace bench {
bool register_narrowphase();
bool register_broadphase();
bool register_game_loop();
}  // namespace bench
