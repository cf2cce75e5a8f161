// Transforms: the cost of placing a body (Transform::make from an angle, make_with_rotation from a
// direction, moved) against Box2D 2.4.1's b2Transform::Set, and of a transformed contact against
// the world-space contact of the same shapes already placed, on the same 1024 pairs.
// Run: build/ci/bench/collide_transform_bench (not part of ctest).

#include <collide/collide.hpp>

#include <box2d/box2d.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace {

using V = collide::Vec2<float>;
using Xf = collide::Transform<float>;
constexpr std::size_t kN = 1024;

struct Placement {
  V position;
  float angle;
};

std::vector<Placement> placements() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> pos(-50.0f, 50.0f), ang(-3.14f, 3.14f);
  std::vector<Placement> out;
  for (std::size_t i = 0; i < kN; ++i) out.push_back({V(pos(rng), pos(rng)), ang(rng)});
  return out;
}

void TransformMake(benchmark::State& state) {
  const auto in = placements();
  for (auto _ : state) {
    for (const Placement& p : in) benchmark::DoNotOptimize(Xf::make(p.position, p.angle));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kN));
}
BENCHMARK(TransformMake);

void TransformMakeWithRotation(benchmark::State& state) {
  const auto in = placements();
  std::vector<V> dirs;
  for (const Placement& p : in) dirs.emplace_back(std::cos(p.angle), std::sin(p.angle));
  for (auto _ : state) {
    for (std::size_t i = 0; i < kN; ++i) benchmark::DoNotOptimize(Xf::make_with_rotation(in[i].position, dirs[i]));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kN));
}
BENCHMARK(TransformMakeWithRotation);

void Box2dTransformSet(benchmark::State& state) {
  const auto in = placements();
  for (auto _ : state) {
    for (const Placement& p : in) {
      b2Transform xf;
      xf.Set(b2Vec2(p.position.x(), p.position.y()), p.angle);
      benchmark::DoNotOptimize(xf);
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kN));
}
BENCHMARK(Box2dTransformSet);

/// Pairs of local shapes near each other (about half overlapping), each with its transform, and
/// the same shapes placed in world space by the factories (what a caller without transforms
/// rebuilds every frame).
template <class S>
struct Pairs {
  std::vector<S> a, b;
  std::vector<Xf> xa, xb;
  std::vector<collide::Obb<float>> wa, wb;
};

Pairs<collide::Aabb<float>> box_pairs() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> pos(-50.0f, 50.0f), off(-1.5f, 1.5f), ang(-3.14f, 3.14f), size(0.3f, 1.0f);
  Pairs<collide::Aabb<float>> p;
  for (std::size_t i = 0; i < kN; ++i) {
    const V h(size(rng), size(rng)), g(size(rng), size(rng));
    const V c(pos(rng), pos(rng));
    const float aa = ang(rng), ab = ang(rng);
    p.a.emplace_back(V(-h), h);
    p.b.emplace_back(V(-g), g);
    p.xa.push_back(Xf::make(c, aa).value());
    p.xb.push_back(Xf::make(V(c + V(off(rng), off(rng))), ab).value());
    p.wa.push_back(collide::Obb<float>::make_with_axis(p.xa.back().position(), h, p.xa.back().rotation()).value());
    p.wb.push_back(collide::Obb<float>::make_with_axis(p.xb.back().position(), g, p.xb.back().rotation()).value());
  }
  return p;
}

void ContactTransformedBoxes(benchmark::State& state) {
  const auto p = box_pairs();
  for (auto _ : state) {
    for (std::size_t i = 0; i < kN; ++i) benchmark::DoNotOptimize(collide::contact(p.a[i], p.xa[i], p.b[i], p.xb[i]));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kN));
}
BENCHMARK(ContactTransformedBoxes);

void ContactWorldBoxes(benchmark::State& state) {
  const auto p = box_pairs();
  for (auto _ : state) {
    for (std::size_t i = 0; i < kN; ++i) benchmark::DoNotOptimize(collide::contact(p.wa[i], p.wb[i]));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kN));
}
BENCHMARK(ContactWorldBoxes);

void ContactIdentityBoxes(benchmark::State& state) {
  const auto p = box_pairs();
  const Xf id;
  for (auto _ : state) {
    for (std::size_t i = 0; i < kN; ++i) benchmark::DoNotOptimize(collide::contact(p.wa[i], id, p.wb[i], id));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kN));
}
BENCHMARK(ContactIdentityBoxes);

/// Rebuilding the world shapes every frame (the way without transforms) then the contact.
void ContactRebuiltBoxes(benchmark::State& state) {
  const auto p = box_pairs();
  for (auto _ : state) {
    for (std::size_t i = 0; i < kN; ++i) {
      const auto wa = collide::Obb<float>::make_with_axis(p.xa[i].position(), p.a[i].max(), p.xa[i].rotation());
      const auto wb = collide::Obb<float>::make_with_axis(p.xb[i].position(), p.b[i].max(), p.xb[i].rotation());
      benchmark::DoNotOptimize(collide::contact(*wa, *wb));
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kN));
}
BENCHMARK(ContactRebuiltBoxes);

void ContactTransformedCircles(benchmark::State& state) {
  const auto p = box_pairs();
  std::vector<collide::Circle<float>> ca, cb, wa, wb;
  for (std::size_t i = 0; i < kN; ++i) {
    ca.emplace_back(V(0.2f, 0.1f), p.a[i].max().x());
    cb.emplace_back(V(-0.1f, 0.3f), p.b[i].max().x());
    wa.emplace_back(V(p.xa[i].apply(collide::Vec2c(0.2, 0.1)).cast<float>()), p.a[i].max().x());
    wb.emplace_back(V(p.xb[i].apply(collide::Vec2c(-0.1, 0.3)).cast<float>()), p.b[i].max().x());
  }
  const bool world = state.range(0) == 1;
  for (auto _ : state) {
    for (std::size_t i = 0; i < kN; ++i) {
      if (world) {
        benchmark::DoNotOptimize(collide::contact(wa[i], wb[i]));
      } else {
        benchmark::DoNotOptimize(collide::contact(ca[i], p.xa[i], cb[i], p.xb[i]));
      }
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(kN));
}
BENCHMARK(ContactTransformedCircles)->Arg(0)->Arg(1)->ArgName("world");

}  // namespace

BENCHMARK_MAIN();
