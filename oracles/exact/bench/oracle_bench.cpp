/// Oracle speed by pair family: ns per exact overlaps() call (and the other queries), on plain
/// random placements (about half overlapping) and on near-boundary placements (within a few ulps
/// of touching, where the interval pass cannot decide and the rational pass runs).

#include "collide/oracle/oracle.hpp"
#include "../tests/sample_shapes.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace {

using namespace collide;
using V = Vec2<double>;

struct Case {
  Shape<double> a, b;
};

/// A shape maker: same shape (same random draws) at any center.
using Maker = std::function<Shape<double>(const V& center)>;

template <ShapeKind K>
Maker maker_of(std::uint64_t seed) {
  return [seed](const V& c) {
    std::mt19937_64 rng(seed);
    return Shape<double>(oracle::testing::sample_shape<K>(rng, c, 1.0));
  };
}

/// A convex 8-gon: 8 evenly spaced directions, radii in [0.95, 1] (every vertex stays convex).
Maker octagon_maker(std::uint64_t seed) {
  return [seed](const V& c) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> radius(0.95, 1.0), phase(0.0, 1.0);
    const double p = phase(rng);
    std::vector<V> pts;
    for (int i = 0; i < 8; ++i) {
      const double t = p + 6.283185307179586 * i / 8, r = radius(rng);
      pts.emplace_back(c.x() + r * std::cos(t), c.y() + r * std::sin(t));
    }
    return Shape<double>(ConvexPolygon<double>(std::span<const V>(pts)));
  };
}

/// b placed around a (at the origin): random offsets (plain), or along a random direction at the
/// distance where the shapes touch, found by bisection to the last bit (near).
Case place(const Maker& ma, const Maker& mb, std::mt19937_64& rng, bool near) {
  const Shape<double> a = ma(V(0, 0));
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586), dist(0.0, 2.6);
  const double t = angle(rng);
  const V dir(std::cos(t), std::sin(t));
  if (!near) return {a, mb(dist(rng) * dir)};
  double lo = 0.0, hi = 8.0;  // overlapping at lo, apart at hi
  for (int i = 0; i < 200 && lo < hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (collide::overlaps(a, mb(mid * dir)) ? lo : hi) = mid;
  }
  return {a, mb(((rng() & 1) ? lo : hi) * dir)};
}

std::vector<Case> round_cases(bool near) {
  // The six pairs among circle, AABB and capsule, taken from the registry.
  std::vector<Case> out;
  std::mt19937_64 rng(near ? 11 : 12);
  for_each_pair([&]<ShapeKind A, ShapeKind B>() {
    constexpr auto round = [](ShapeKind k) {
      return k == ShapeKind::Circle || k == ShapeKind::Aabb || k == ShapeKind::Capsule;
    };
    if constexpr (round(A) && round(B)) {
      for (int i = 0; i < 256; ++i) out.push_back(place(maker_of<A>(rng()), maker_of<B>(rng()), rng, near));
    }
  });
  return out;
}

std::vector<Case> octagon_cases(bool near) {
  std::vector<Case> out;
  std::mt19937_64 rng(near ? 21 : 22);
  for (int i = 0; i < 1024; ++i) out.push_back(place(octagon_maker(rng()), octagon_maker(rng()), rng, near));
  return out;
}

const std::vector<Case>& cases(int family, bool near) {
  static const std::vector<Case> all[2][2] = {{round_cases(false), round_cases(true)},
                                              {octagon_cases(false), octagon_cases(true)}};
  return all[family][near ? 1 : 0];
}

template <class F>
void run(benchmark::State& state, F&& query) {
  const std::vector<Case>& cs = cases(static_cast<int>(state.range(0)), state.range(1) != 0);
  std::size_t i = 0;
  long hits = 0;
  for (auto _ : state) {
    const Case& c = cs[i];
    i = i + 1 == cs.size() ? 0 : i + 1;
    const auto r = query(c);
    hits += r ? 1 : 0;
    benchmark::DoNotOptimize(r);
  }
  state.counters["positive"] = benchmark::Counter(static_cast<double>(hits) / static_cast<double>(state.iterations()));
}

void BM_overlaps(benchmark::State& state) {
  run(state, [](const Case& c) { return oracle::exact::overlaps(c.a, c.b); });
}
void BM_compare_distance(benchmark::State& state) {
  run(state, [](const Case& c) { return oracle::exact::compare_distance(c.a, c.b, 0.01) <= 0; });
}
void BM_within_band(benchmark::State& state) {
  run(state, [](const Case& c) { return oracle::exact::within_band(c.a, c.b, 1e-9); });
}
void BM_compare_depth(benchmark::State& state) {
  run(state, [](const Case& c) { return oracle::exact::compare_depth(c.a, c.b, 0.01) > 0; });
}

// Args: family (0 = circle/AABB/capsule pairs, 1 = two 8-gons), near-boundary (0/1).
#define FAMILIES ArgNames({"octagons", "near"})->Args({0, 0})->Args({0, 1})->Args({1, 0})->Args({1, 1})
BENCHMARK(BM_overlaps)->FAMILIES;
BENCHMARK(BM_compare_distance)->FAMILIES;
BENCHMARK(BM_within_band)->FAMILIES;
BENCHMARK(BM_compare_depth)->FAMILIES;

}  // namespace

BENCHMARK_MAIN();
