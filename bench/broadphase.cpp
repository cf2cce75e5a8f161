// Broadphase benchmarks: N boxes (each overlapping about 2 others): build, all pairs, and move
// 10% then find the pairs of the moved boxes; collide's three structures against Box2D's
// b2DynamicTree (queried once per box) and brute force (N <= 10k). Pair events: every box moves
// every frame, then one update reports the pairs that began and ended (PairTracker) against
// Box2D's b2BroadPhase (MoveProxy for every box, then UpdatePairs over its move buffer).

#include "collide/broadphase.hpp"
#include "suites.hpp"

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace bench {
namespace {

namespace bp = collide::broadphase;
using V = collide::Vec2<float>;
using Pair = std::pair<std::uint32_t, std::uint32_t>;

/// N boxes with sides in [0.5, 1.5] in a square world of side sqrt(2N): about 2 overlaps each.
struct World {
  std::vector<collide::Aabb<float>> boxes;
  std::vector<std::uint32_t> moved;               // every 10th box
  std::vector<collide::Aabb<float>> there, back;  // moved boxes displaced, and returned
};

std::shared_ptr<World> make_world(std::size_t n) {
  auto w = std::make_shared<World>();
  std::mt19937 rng{static_cast<unsigned>(n)};
  const float side = std::sqrt(2.0f * float(n));
  std::uniform_real_distribution<float> pos(0, side), size(0.5f, 1.5f), step(-0.2f, 0.2f);
  for (std::size_t i = 0; i < n; ++i) {
    const V lo(pos(rng), pos(rng));
    w->boxes.emplace_back(lo, lo + V(size(rng), size(rng)));
  }
  for (std::uint32_t i = 0; i < n; i += 10) {
    w->moved.push_back(i);
    const V d(step(rng), step(rng));
    w->there.emplace_back(w->boxes[i].min() + d, w->boxes[i].max() + d);
    w->back.push_back(w->boxes[i]);
  }
  return w;
}

b2AABB to_b2(const collide::Aabb<float>& b) {
  b2AABB a;
  a.lowerBound = {b.min().x(), b.min().y()};
  a.upperBound = {b.max().x(), b.max().y()};
  return a;
}

/// Box2D's tree, queried once per box with the box itself; candidates from fat boxes are
/// filtered on the stored boxes, each pair counted once (lower id first), like b2BroadPhase.
struct Box2dTree {
  b2DynamicTree tree;
  std::vector<int32> proxy;
  const std::vector<collide::Aabb<float>>* boxes = nullptr;
  std::vector<b2AABB> stored;
  int32 self = 0;
  std::vector<Pair>* out = nullptr;
  const std::vector<char>* is_moved = nullptr;

  void build(const std::vector<collide::Aabb<float>>& b) {
    stored.clear();
    proxy.clear();
    for (std::size_t i = 0; i < b.size(); ++i) {
      stored.push_back(to_b2(b[i]));
      proxy.push_back(tree.CreateProxy(stored.back(), reinterpret_cast<void*>(i)));
    }
  }
  bool QueryCallback(int32 id) {
    const auto other = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(tree.GetUserData(id)));
    const auto me = static_cast<std::uint32_t>(self);
    if (other == me) return true;
    // Count a pair once: from the lower index, or from the moved box when only one moved.
    if (is_moved == nullptr ? other < me : ((*is_moved)[other] && other < me)) return true;
    if (!b2TestOverlap(stored[me], stored[other])) return true;
    out->emplace_back(std::min(me, other), std::max(me, other));
    return true;
  }
  void all_pairs(std::vector<Pair>& o) {
    out = &o;
    is_moved = nullptr;
    for (std::size_t i = 0; i < proxy.size(); ++i) {
      self = int32(i);
      tree.Query(this, stored[i]);
    }
  }
  void move(const std::vector<std::uint32_t>& ids, const std::vector<collide::Aabb<float>>& to) {
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const b2AABB nb = to_b2(to[k]);
      const b2Vec2 d = nb.lowerBound - stored[ids[k]].lowerBound;
      stored[ids[k]] = nb;
      tree.MoveProxy(proxy[ids[k]], nb, d);
    }
  }
  void moved_pairs(const std::vector<std::uint32_t>& ids, const std::vector<char>& mark, std::vector<Pair>& o) {
    out = &o;
    is_moved = &mark;
    for (const std::uint32_t i : ids) {
      self = int32(i);
      tree.Query(this, stored[i]);
    }
  }
};

template <class B>
B make_structure();
template <>
bp::DynamicTree<float> make_structure() {
  return bp::DynamicTree<float>(0.1f);
}  // Box2D's margin
template <>
bp::SweepAndPrune<float> make_structure() {
  return {};
}
template <>
bp::UniformGrid<float> make_structure() {
  return bp::UniformGrid<float>(2.0f);
}

template <class B>
std::vector<bp::ProxyId> fill(B& s, const std::vector<collide::Aabb<float>>& boxes) {
  std::vector<bp::ProxyId> ids;
  ids.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) ids.push_back(s.add(boxes[i], i));
  if constexpr (requires { s.flush(); }) s.flush();  // a batch of additions: sort once
  return ids;
}

template <class B>
std::vector<Pair> as_pairs(const B& s, const std::vector<bp::ProxyPair>& p) {
  std::vector<Pair> out;
  for (const auto& q : p) {
    const auto a = std::uint32_t(s.user_data(q.a)), b = std::uint32_t(s.user_data(q.b));
    out.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Pair> brute(const std::vector<collide::Aabb<float>>& b) {
  std::vector<Pair> out;
  for (std::uint32_t i = 0; i < b.size(); ++i)
    for (std::uint32_t j = i + 1; j < b.size(); ++j)
      if (collide::decide::aabb_aabb(b[i], b[j])) out.emplace_back(i, j);
  return out;
}

template <class B>
void register_structure(const std::string& label, const std::shared_ptr<World>& w) {
  const std::string n = std::to_string(w->boxes.size());
  benchmark::RegisterBenchmark(("broadphase/build/" + label + "/" + n).c_str(), [w](benchmark::State& st) {
    for (auto _ : st) {
      B s = make_structure<B>();
      benchmark::DoNotOptimize(fill(s, w->boxes).data());
      if constexpr (!std::is_same_v<B, bp::DynamicTree<float>>) benchmark::DoNotOptimize(s.pairs().size());
    }
    st.counters["boxes"] = double(w->boxes.size());
  })->Unit(benchmark::kMillisecond);
  auto shared = std::make_shared<B>(make_structure<B>());
  auto ids = std::make_shared<std::vector<bp::ProxyId>>(fill(*shared, w->boxes));
  benchmark::RegisterBenchmark(("broadphase/pairs/" + label + "/" + n).c_str(), [w, shared](benchmark::State& st) {
    for (auto _ : st) benchmark::DoNotOptimize(shared->pairs().size());
    st.counters["boxes"] = double(w->boxes.size());
  })->Unit(benchmark::kMillisecond);
  const std::string move_name = "broadphase/move10/" + label + "/" + n;
  benchmark::RegisterBenchmark(move_name.c_str(), [w, shared, ids](benchmark::State& st) {
    std::vector<bp::ProxyId> moved;
    for (const std::uint32_t i : w->moved) moved.push_back((*ids)[i]);
    bool out = true;
    for (auto _ : st) {
      const auto& to = out ? w->there : w->back;
      for (std::size_t k = 0; k < moved.size(); ++k) shared->move(moved[k], to[k]);
      benchmark::DoNotOptimize(bp::pairs_involving(*shared, std::span<const bp::ProxyId>(moved)).size());
      out = !out;
    }
    st.counters["boxes"] = double(w->boxes.size());
  })->Unit(benchmark::kMillisecond);
}

/// Box i at frame f of the moving scene: its start box shifted by its velocity times a triangle
/// wave of period 128 frames (so the scene stays in place however long the benchmark runs).
collide::Aabb<float> box_at(const World& w, const std::vector<V>& velocity, std::size_t i, std::uint32_t frame) {
  const std::uint32_t phase = frame % 128;
  const float s = float(phase < 64 ? phase : 128 - phase);
  const V d = velocity[i] * s;
  return {w.boxes[i].min() + d, w.boxes[i].max() + d};
}

std::shared_ptr<std::vector<V>> make_velocities(std::size_t n) {
  auto v = std::make_shared<std::vector<V>>();
  std::mt19937 rng{static_cast<unsigned>(n) + 1};
  std::uniform_real_distribution<float> speed(-0.05f, 0.05f);  // units per frame: Box2D's margin is 0.1
  for (std::size_t i = 0; i < n; ++i) v->emplace_back(speed(rng), speed(rng));
  return v;
}

/// Box2D 2.4.1's broadphase as its contact manager drives it: MoveProxy with the displacement
/// for every box, then UpdatePairs, which reports the pairs of the proxies that left their fat
/// boxes (AddPair here only counts them).
struct Box2dBroadPhase {
  b2BroadPhase bp;
  std::vector<int32> proxy;
  std::size_t added = 0;
  void AddPair(void*, void*) { ++added; }
};

template <class B>
void register_events(const std::string& label, const std::shared_ptr<World>& w,
                     const std::shared_ptr<std::vector<V>>& vel) {
  const std::string n = std::to_string(w->boxes.size());
  benchmark::RegisterBenchmark(("broadphase/events/" + label + "/" + n).c_str(), [w, vel](benchmark::State& st) {
    bp::PairTracker<B, float> t(make_structure<B>());
    std::vector<bp::ProxyId> ids;
    for (std::size_t i = 0; i < w->boxes.size(); ++i) ids.push_back(t.add(w->boxes[i], i));
    bp::PairEvents e;
    t.update(e);
    std::uint32_t frame = 0;
    std::size_t events = 0;
    for (auto _ : st) {
      ++frame;
      for (std::size_t i = 0; i < ids.size(); ++i) t.move(ids[i], box_at(*w, *vel, i, frame));
      t.update(e);
      events += e.began.size() + e.ended.size();
    }
    st.counters["boxes"] = double(w->boxes.size());
    st.counters["events_per_frame"] = double(events) / double(std::max<std::uint32_t>(frame, 1));
  })->Unit(benchmark::kMillisecond);
}

void register_box2d_events(const std::shared_ptr<World>& w, const std::shared_ptr<std::vector<V>>& vel) {
  const std::string n = std::to_string(w->boxes.size());
  benchmark::RegisterBenchmark(("broadphase/events/box2d_broadphase/" + n).c_str(), [w, vel](benchmark::State& st) {
    Box2dBroadPhase b;
    for (std::size_t i = 0; i < w->boxes.size(); ++i)
      b.proxy.push_back(b.bp.CreateProxy(to_b2(w->boxes[i]), reinterpret_cast<void*>(i)));
    b.bp.UpdatePairs(&b);
    std::uint32_t frame = 0;
    std::size_t pairs = 0;
    for (auto _ : st) {
      ++frame;
      for (std::size_t i = 0; i < b.proxy.size(); ++i) {
        const b2AABB a = to_b2(box_at(*w, *vel, i, frame));
        const b2AABB was = to_b2(box_at(*w, *vel, i, frame - 1));
        b.bp.MoveProxy(b.proxy[i], a, a.lowerBound - was.lowerBound);
      }
      b.added = 0;
      b.bp.UpdatePairs(&b);
      pairs += b.added;
    }
    st.counters["boxes"] = double(w->boxes.size());
    st.counters["pairs_per_frame"] = double(pairs) / double(std::max<std::uint32_t>(frame, 1));
  })->Unit(benchmark::kMillisecond);
}

/// Cross-check of the pair events: over 200 frames of the moving scene, the pairs current after
/// applying each frame's began and ended to the previous set equal brute force at that frame.
bool check_events(const World& w, const std::vector<V>& vel) {
  bp::PairTracker<bp::DynamicTree<float>, float> t(make_structure<bp::DynamicTree<float>>());
  bp::PairTracker<bp::SweepAndPrune<float>, float> s;
  std::vector<bp::ProxyId> ti, si;
  for (std::size_t i = 0; i < w.boxes.size(); ++i)
    ti.push_back(t.add(w.boxes[i], i)), si.push_back(s.add(w.boxes[i], i));
  std::vector<Pair> current_t, current_s;
  bool ok = true;
  const auto apply = [](auto& tracker, std::vector<Pair>& current) {
    const bp::PairEvents e = tracker.update();
    // No proxy is removed, so slot index == box index.
    const auto key = [](const bp::ProxyPair& p) { return Pair(p.a.index, p.b.index); };
    std::vector<Pair> ended;
    for (const auto& p : e.ended) ended.push_back(key(p));
    std::sort(ended.begin(), ended.end());
    std::vector<Pair> kept;
    std::set_difference(current.begin(), current.end(), ended.begin(), ended.end(), std::back_inserter(kept));
    const bool all_ended_known = kept.size() + ended.size() == current.size();
    for (const auto& p : e.began) kept.push_back(key(p));
    std::sort(kept.begin(), kept.end());
    current = kept;
    return all_ended_known;
  };
  ok = apply(t, current_t) && apply(s, current_s);
  for (std::uint32_t f = 1; f <= 200 && ok; ++f) {
    std::vector<collide::Aabb<float>> now;
    for (std::size_t i = 0; i < w.boxes.size(); ++i) {
      now.push_back(box_at(w, vel, i, f));
      t.move(ti[i], now.back());
      s.move(si[i], now.back());
    }
    ok = apply(t, current_t) && apply(s, current_s);
    if (f % 50 == 0 || f == 1)
      ok = ok && current_t == brute(now) && current_s == current_t;
    else
      ok = ok && current_s == current_t;
  }
  std::printf("check broadphase events N=%-6zu 200 frames, pairs at the end %zu  %s\n", w.boxes.size(),
              current_t.size(), ok ? "OK" : "MISMATCH");
  return ok;
}

/// Cross-check: all structures and Box2D report the same pairs, before and after the move.
bool check_world(const World& w) {
  bool ok = true;
  auto tree = make_structure<bp::DynamicTree<float>>();
  auto sweep = make_structure<bp::SweepAndPrune<float>>();
  auto grid = make_structure<bp::UniformGrid<float>>();
  auto ti = fill(tree, w.boxes), si = fill(sweep, w.boxes), gi = fill(grid, w.boxes);
  Box2dTree b2;
  b2.build(w.boxes);
  std::vector<Pair> b2p;
  b2.all_pairs(b2p);
  std::sort(b2p.begin(), b2p.end());
  bp::DynamicTree<float> batch(0.1f);
  batch.add_batch(w.boxes);
  ok = ok && batch.check_invariants();
  const auto t = as_pairs(tree, tree.pairs());
  ok = ok && t == as_pairs(batch, batch.pairs());
  ok = ok && t == as_pairs(sweep, sweep.pairs()) && t == as_pairs(grid, grid.pairs()) && t == b2p;
  if (w.boxes.size() <= 10000) ok = ok && t == brute(w.boxes);
  // Move 10% and compare the pairs of the moved boxes.
  std::vector<char> mark(w.boxes.size(), 0);
  std::vector<bp::ProxyId> mt, ms, mg;
  for (std::size_t k = 0; k < w.moved.size(); ++k) {
    const std::uint32_t i = w.moved[k];
    mark[i] = 1;
    tree.move(ti[i], w.there[k]);
    sweep.move(si[i], w.there[k]);
    grid.move(gi[i], w.there[k]);
    mt.push_back(ti[i]);
    ms.push_back(si[i]);
    mg.push_back(gi[i]);
  }
  b2.move(w.moved, w.there);
  std::vector<Pair> b2m;
  b2.moved_pairs(w.moved, mark, b2m);
  std::sort(b2m.begin(), b2m.end());
  const auto tm = as_pairs(tree, bp::pairs_involving(tree, std::span<const bp::ProxyId>(mt)));
  ok = ok && tm == as_pairs(sweep, bp::pairs_involving(sweep, std::span<const bp::ProxyId>(ms))) &&
       tm == as_pairs(grid, bp::pairs_involving(grid, std::span<const bp::ProxyId>(mg))) && tm == b2m;
  std::printf("check broadphase N=%-6zu pairs %zu (%.2f overlaps per box), moved-box pairs %zu  %s\n", w.boxes.size(),
              t.size(), 2.0 * double(t.size()) / double(w.boxes.size()), tm.size(), ok ? "OK" : "MISMATCH");
  return ok;
}

}  // namespace

bool register_broadphase() {
  bool ok = true;
  for (const std::size_t n : {std::size_t(1000), std::size_t(10000), std::size_t(100000)}) {
    const auto w = make_world(n);
    ok = check_world(*w) && ok;
    register_structure<bp::DynamicTree<float>>("tree", w);
    benchmark::RegisterBenchmark(("broadphase/build/tree_batch/" + std::to_string(n)).c_str(),
                                 [w](benchmark::State& st) {
                                   for (auto _ : st) {
                                     bp::DynamicTree<float> t(0.1f);
                                     benchmark::DoNotOptimize(t.add_batch(w->boxes).data());
                                   }
                                   st.counters["boxes"] = double(w->boxes.size());
                                 })
        ->Unit(benchmark::kMillisecond);
    register_structure<bp::SweepAndPrune<float>>("sweep", w);
    register_structure<bp::UniformGrid<float>>("grid", w);
    if (n >= 10000) {
      const auto vel = make_velocities(n);
      if (n == 10000) ok = check_events(*w, *vel) && ok;
      register_events<bp::DynamicTree<float>>("tree", w, vel);
      register_events<bp::SweepAndPrune<float>>("sweep", w, vel);
      register_events<bp::UniformGrid<float>>("grid", w, vel);
      register_box2d_events(w, vel);
    }
    const std::string ns = std::to_string(n);
    benchmark::RegisterBenchmark(("broadphase/build/box2d_tree/" + ns).c_str(), [w](benchmark::State& st) {
      for (auto _ : st) {
        Box2dTree b2;
        b2.build(w->boxes);
        benchmark::DoNotOptimize(b2.proxy.data());
      }
      st.counters["boxes"] = double(w->boxes.size());
    })->Unit(benchmark::kMillisecond);
    auto b2 = std::make_shared<Box2dTree>();
    b2->build(w->boxes);
    benchmark::RegisterBenchmark(("broadphase/pairs/box2d_tree/" + ns).c_str(), [w, b2](benchmark::State& st) {
      std::vector<Pair> out;
      for (auto _ : st) {
        out.clear();
        b2->all_pairs(out);
        benchmark::DoNotOptimize(out.data());
      }
      st.counters["boxes"] = double(w->boxes.size());
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("broadphase/move10/box2d_tree/" + ns).c_str(), [w, b2](benchmark::State& st) {
      std::vector<char> mark(w->boxes.size(), 0);
      for (const std::uint32_t i : w->moved) mark[i] = 1;
      std::vector<Pair> out;
      bool there = true;
      for (auto _ : st) {
        out.clear();
        b2->move(w->moved, there ? w->there : w->back);
        b2->moved_pairs(w->moved, mark, out);
        benchmark::DoNotOptimize(out.data());
        there = !there;
      }
      st.counters["boxes"] = double(w->boxes.size());
    })->Unit(benchmark::kMillisecond);
    if (n <= 10000) {
      benchmark::RegisterBenchmark(("broadphase/pairs/brute/" + ns).c_str(), [w](benchmark::State& st) {
        for (auto _ : st) benchmark::DoNotOptimize(brute(w->boxes).size());
        st.counters["boxes"] = double(w->boxes.size());
      })->Unit(benchmark::kMillisecond);
    }
  }
  return ok;
}

}  // namespace bench
