// The character mover: move_and_slide() of a character walking, falling and jumping through a
// World of 1,000 boxes (a floor of flush tiles, walls, platforms and crates), 1,000 moves per
// iteration, timed per move. The same walk for a capsule and a circle, in float and double.
// Box2D 2.4.1 has no counterpart (its mover, b2World_CastMover with b2SolvePlanes and
// b2ClipVector, came with Box2D 3.1), so there is no side-by-side row.
// Run: build/<dir>/bench/collide_mover_bench (not part of ctest; cmake --build <dir> --target
// collide_mover_bench).

#include <collide/broadphase.hpp>
#include <collide/collide.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace {

namespace bp = collide::broadphase;

constexpr int kMoves = 1000;
constexpr int kBoxes = 1000;

/// The level: 400 floor tiles of width 0.5 from x = -100, 40 walls, and crates and platforms in
/// the air above the floor, 1,000 boxes in all, in world space.
template <class T>
bp::World<T> level() {
  using V = collide::Vec2<T>;
  bp::World<T> world;
  int n = 0;
  for (int i = 0; i < 400; ++i, ++n) world.add(collide::Aabb<T>(V(T(-100 + 0.5 * i), -1), V(T(-99.5 + 0.5 * i), 0)));
  for (int i = 0; i < 40; ++i, ++n) world.add(collide::Aabb<T>(V(T(-100 + 5 * i), 0), V(T(-99.6 + 5 * i), T(1.5))));
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> x(-100, 100), y(0.5f, 12), w(0.3f, 3), h(0.2f, 1);
  for (; n < kBoxes; ++n) {
    const T x0 = T(x(rng)), y0 = T(y(rng));
    world.add(collide::Aabb<T>(V(x0, y0), V(T(x0 + T(w(rng))), T(y0 + T(h(rng))))));
  }
  return world;
}

/// A character that walks at 6 units per second, turns at walls and wherever it is wedged, falls
/// under gravity and jumps every 150 moves (a second in the air), one move per 60th of a second;
/// its body is a capsule or a circle.
template <class T>
void Walk(benchmark::State& state) {
  using V = collide::Vec2<T>;
  const bp::World<T> world = level<T>();
  const bool capsule = state.range(0) == 1;
  const collide::Shape<T> body = capsule ? collide::Shape<T>(collide::Capsule<T>(V(0, T(-0.4)), V(0, T(0.4)), T(0.3)))
                                         : collide::Shape<T>(collide::Circle<T>(V(0, 0), T(0.5)));
  const T dt = T(1) / 60;
  std::size_t planes = 0, blocked = 0;
  for (auto _ : state) {
    collide::Transform<T> at = collide::Transform<T>::make_translation(V(0, 3)).value();
    V velocity(6, 0);
    for (int move = 0; move < kMoves; ++move) {
      velocity.y() -= T(9.8) * dt;
      if (move % 150 == 75) velocity.y() = 5;
      const bp::MoveResult<T> r = bp::move_and_slide(world, body, at, V(velocity * dt));
      at = r.transform;
      planes += r.plane_count;
      // Landed: no more falling. Against a wall, under a low crate, in a corner: back the way it came.
      bool turn = r.outcome == bp::MoveOutcome::Blocked;
      for (const bp::MovePlane<T>& p : r.contacts()) {
        if (p.normal.y() < T(-0.7)) velocity.y() = std::fmax(velocity.y(), T(0));
        turn = turn || (std::fabs(p.normal.x()) > T(0.7) && p.normal.x() * velocity.x() > 0);
      }
      if (turn) velocity.x() = -velocity.x();
      blocked += r.outcome == bp::MoveOutcome::Blocked;
      benchmark::DoNotOptimize(at);
    }
  }
  const double moves = double(state.iterations()) * kMoves;
  state.SetItemsProcessed(std::int64_t(moves));
  state.counters["per_move"] =
      benchmark::Counter(kMoves, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["planes_per_move"] = double(planes) / moves;
  state.counters["blocked_share"] = double(blocked) / moves;
}

BENCHMARK_TEMPLATE(Walk, float)->Arg(1)->Arg(0)->ArgName("capsule");
BENCHMARK_TEMPLATE(Walk, double)->Arg(1)->ArgName("capsule");

}  // namespace

BENCHMARK_MAIN();
