// The game loop, side by side: N mixed moving bodies (circles, boxes, spinning boxes, spinning
// capsules, spinning 3-8-gons), 600 frames. Each frame, for both libraries on identical motion:
//   1. transforms: each body's pose made from its position and angle;
//   2. broadphase: each body's bounding box under its pose moved in a dynamic tree, then the pairs
//      of overlapping boxes found, each once, by each library's own means (collide: the tree's
//      for_each_pair; Box2D: a tree query per body, as its b2BroadPhase does for moved proxies);
//      collide's loop runs a second time on sort and sweep, the structure that suits many
//      similar bodies moving coherently;
//   3. narrowphase: a contact manifold for every candidate pair.
// The update of phase 2 (each body's box under its new pose, moved in the tree) is also counted
// on its own (update_ms): it is what a World's move() costs. A fourth loop runs the documented
// World loop: world.move(id, pose) per body (update_ms, its broadphase_ms), then world.step(),
// which finds the pairs and computes every contact of a moved body (step_ms).
// collide: local shapes with Transform<float>, DynamicTree, Narrowphase (contact(a, xa, b, xb) of
// every pair, run kind pair by kind pair). Box2D 2.4.1:
// b2Shape with b2Transform, b2DynamicTree, b2Collide* (polygon skin radius 0, capsules as 2-gons
// with a radius, as Box2D v3 treats them). The motion itself (integration, bouncing off the
// walls) is outside the timed phases. Counters: milliseconds of this thread's CPU time per frame
// of each phase. Box2D's b2Collide* return local manifolds; its loop also times, outside the frame,
// a second narrowphase that turns each manifold with points into world points, normal and
// separations (b2WorldManifold::Initialize), which contact() returns (narrowphase_world_ms).

#include "collide/broadphase.hpp"
#include "collide/collide.hpp"
#include "suites.hpp"

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#include <ctime>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <type_traits>
#include <utility>
#include <vector>

namespace bench {
namespace {

namespace bp = collide::broadphase;
using Tree = bp::DynamicTree<float>;
using V = collide::Vec2<float>;
/// This thread's CPU time: on a shared machine wall time would count other processes' work.
struct Clock {
  using time_point = double;  // seconds
  static time_point now() noexcept {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
  }
};
constexpr int kFrames = 600;
constexpr float kStep = 1.0f / 60.0f;

enum class Body { Circle, Box, SpinningBox, Capsule, Polygon };

/// The scene: each body's local shape (both libraries' forms) and its motion.
struct Scene {
  std::vector<collide::Shape<float>> shapes;
  std::vector<std::unique_ptr<b2Shape>> b2shapes;
  std::vector<V> position, velocity;
  std::vector<float> angle, spin;
  float side = 0;
};

b2Vec2 to_b2(const V& v) {
  return {v.x(), v.y()};
}

/// A regular-ish n-gon of radius about r, counter-clockwise.
std::vector<V> polygon_vertices(int n, float r, std::mt19937& rng) {
  std::uniform_real_distribution<float> jitter(0.85f, 1.0f);
  std::vector<V> v;
  for (int i = 0; i < n; ++i) {
    const float a = 2 * std::numbers::pi_v<float> * float(i) / float(n);
    const float k = r * jitter(rng);
    v.emplace_back(k * std::cos(a), k * std::sin(a));
  }
  return v;
}

std::shared_ptr<Scene> make_scene(std::size_t n) {
  auto s = std::make_shared<Scene>();
  std::mt19937 rng{static_cast<unsigned>(n) + 17};
  // About 1.6 area units per body: a body touches one or two others at a time.
  s->side = std::sqrt(1.6f * float(n));
  std::uniform_real_distribution<float> pos(1, s->side - 1), vel(-2, 2), size(0.2f, 0.45f), turn(-3, 3);
  std::uniform_int_distribution<int> kind(0, 4), sides(3, 8);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<Body>(kind(rng));
    const float r = size(rng);
    s->position.emplace_back(pos(rng), pos(rng));
    s->velocity.emplace_back(vel(rng), vel(rng));
    s->angle.push_back(0);
    s->spin.push_back(k == Body::Circle || k == Body::Box ? 0.0f : turn(rng));
    switch (k) {
      case Body::Circle: {
        s->shapes.emplace_back(collide::Circle<float>(V(0, 0), r));
        auto c = std::make_unique<b2CircleShape>();
        c->m_radius = r;
        s->b2shapes.push_back(std::move(c));
        break;
      }
      case Body::Box:
      case Body::SpinningBox: {
        const V h(r, 0.6f * r);
        if (k == Body::Box) {
          s->shapes.emplace_back(collide::Aabb<float>(-h, h));
        } else {
          s->shapes.emplace_back(collide::Obb<float>(V(0, 0), h, 0.0f));
        }
        auto b = std::make_unique<b2PolygonShape>();
        b->SetAsBox(h.x(), h.y());
        b->m_radius = 0;
        s->b2shapes.push_back(std::move(b));
        break;
      }
      case Body::Capsule: {
        const float rad = 0.4f * r;
        s->shapes.emplace_back(collide::Capsule<float>(V(-r, 0), V(r, 0), rad));
        auto b = std::make_unique<b2PolygonShape>();
        b->m_count = 2;
        b->m_vertices[0].Set(-r, 0);
        b->m_vertices[1].Set(r, 0);
        b->m_normals[0].Set(0, -1);
        b->m_normals[1].Set(0, 1);
        b->m_centroid.SetZero();
        b->m_radius = rad;
        s->b2shapes.push_back(std::move(b));
        break;
      }
      case Body::Polygon: {
        const std::vector<V> v = polygon_vertices(sides(rng), r, rng);
        s->shapes.emplace_back(collide::ConvexPolygon<float>(v));
        std::vector<b2Vec2> w;
        for (const V& p : v) w.push_back(to_b2(p));
        auto b = std::make_unique<b2PolygonShape>();
        b->Set(w.data(), int32(w.size()));
        b->m_radius = 0;
        s->b2shapes.push_back(std::move(b));
        break;
      }
    }
  }
  return s;
}

/// One frame of motion: integrate, bounce off the walls of the square.
void advance(std::vector<V>& p, std::vector<V>& v, std::vector<float>& a, const Scene& s) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    p[i] += kStep * v[i];
    a[i] += kStep * s.spin[i];
    for (int d = 0; d < 2; ++d) {
      if ((p[i][d] < 1 && v[i][d] < 0) || (p[i][d] > s.side - 1 && v[i][d] > 0)) v[i][d] = -v[i][d];
    }
  }
}

template <class Broadphase>
Broadphase make_broadphase() {
  if constexpr (std::is_same_v<Broadphase, Tree>) {
    return Broadphase(0.1f);  // Box2D 2.4.1's b2_aabbMargin
  } else {
    return Broadphase();
  }
}

/// Per-frame milliseconds of each phase, and what the loop found (for the cross-check).
struct Timings {
  double transforms = 0, broadphase = 0, narrowphase = 0;
  double update = 0;             ///< the part of broadphase (all of it, for the World) that moves the boxes
  double step = 0;               ///< the World only: world.step(), pairs and contacts
  double narrowphase_world = 0;  ///< Box2D only: b2Collide* and b2WorldManifold::Initialize, not in the frame
  std::size_t candidates = 0, contacts = 0, points = 0;
};

double ms(Clock::time_point a, Clock::time_point b) {
  return 1e3 * (b - a);
}

/// collide's loop over a broadphase structure: the dynamic tree (fat boxes, moved by move_fat) or
/// sort and sweep (exact boxes).
template <class Broadphase>
Timings run_collide(const Scene& s, int frames = kFrames) {
  const std::size_t n = s.shapes.size();
  std::vector<V> p = s.position, v = s.velocity;
  std::vector<float> a = s.angle;
  std::vector<collide::Transform<float>> xf(n);
  std::vector<collide::Aabb<float>> box(n, collide::Aabb<float>(V(0, 0), V(0, 0)));
  Broadphase tree = make_broadphase<Broadphase>();
  std::vector<bp::ProxyId> id(n);
  for (std::size_t i = 0; i < n; ++i) {
    xf[i] = collide::Transform<float>::make(p[i], a[i]).value();
    id[i] = tree.add(collide::bounds(s.shapes[i], xf[i]), i);
  }
  std::vector<bp::ShapePair> pairs;
  bp::Narrowphase<float> narrowphase;
  Timings t;
  for (int frame = 0; frame < frames; ++frame) {
    advance(p, v, a, s);
    const auto t0 = Clock::now();
    for (std::size_t i = 0; i < n; ++i) xf[i] = *collide::Transform<float>::make(p[i], a[i]);
    const auto t1 = Clock::now();
    for (std::size_t i = 0; i < n; ++i) {
      box[i] = collide::bounds(s.shapes[i], xf[i]);
      if constexpr (std::is_same_v<Broadphase, Tree>) {
        tree.move_fat(id[i], box[i]);
      } else {
        tree.move(id[i], box[i]);
      }
    }
    const auto t_update = Clock::now();
    pairs.clear();
    tree.for_each_pair([&](bp::ProxyId x, bp::ProxyId y) {
      const std::size_t i = tree.user_data(x), j = tree.user_data(y);
      pairs.push_back({std::min(i, j), std::max(i, j)});
    });
    const auto t2 = Clock::now();
    narrowphase.for_each_contact(s.shapes, xf, pairs, [&](std::size_t, const collide::Contact<float>& c) {
      benchmark::DoNotOptimize(c);  // every field, as a solver reads them (Box2D's manifold too)
      ++t.contacts;
      t.points += std::size_t(c.count);
    });
    const auto t3 = Clock::now();
    t.transforms += ms(t0, t1);
    t.update += ms(t1, t_update);
    t.broadphase += ms(t1, t2);
    t.narrowphase += ms(t2, t3);
    t.candidates += pairs.size();
  }
  return t;
}

/// The documented World loop: local shapes added once with their poses, moved by new poses each
/// frame, step() for the pairs and the contacts, every contact read as a solver would.
Timings run_world(const Scene& s, int frames = kFrames) {
  const std::size_t n = s.shapes.size();
  std::vector<V> p = s.position, v = s.velocity;
  std::vector<float> a = s.angle;
  std::vector<collide::Transform<float>> xf(n);
  bp::World<float> world(Tree(0.1f));
  std::vector<bp::ProxyId> id(n);
  for (std::size_t i = 0; i < n; ++i) id[i] = world.add(s.shapes[i], *collide::Transform<float>::make(p[i], a[i]), i);
  world.step();
  Timings t;
  for (int frame = 0; frame < frames; ++frame) {
    advance(p, v, a, s);
    const auto t0 = Clock::now();
    for (std::size_t i = 0; i < n; ++i) xf[i] = *collide::Transform<float>::make(p[i], a[i]);
    const auto t1 = Clock::now();
    for (std::size_t i = 0; i < n; ++i) world.move(id[i], xf[i]);
    const auto t2 = Clock::now();
    world.step();
    world.for_each_contact([&](const bp::BodyContact<float>& c) {
      benchmark::DoNotOptimize(c);
      ++t.contacts;
      t.points += std::size_t(c.contact.count);
    });
    const auto t3 = Clock::now();
    t.transforms += ms(t0, t1);
    t.update += ms(t1, t2);
    t.broadphase += ms(t1, t2);
    t.step += ms(t2, t3);
  }
  return t;
}

/// Box2D's b2Collide* for a pair of its shapes (circles and polygons: all this scene has).
void collide_b2(b2Manifold& m, const b2Shape* a, const b2Transform& xa, const b2Shape* b, const b2Transform& xb) {
  const bool ca = a->GetType() == b2Shape::e_circle, cb = b->GetType() == b2Shape::e_circle;
  if (ca && cb) {
    b2CollideCircles(&m, static_cast<const b2CircleShape*>(a), xa, static_cast<const b2CircleShape*>(b), xb);
  } else if (cb) {
    b2CollidePolygonAndCircle(&m, static_cast<const b2PolygonShape*>(a), xa, static_cast<const b2CircleShape*>(b), xb);
  } else if (ca) {
    b2CollidePolygonAndCircle(&m, static_cast<const b2PolygonShape*>(b), xb, static_cast<const b2CircleShape*>(a), xa);
  } else {
    b2CollidePolygons(&m, static_cast<const b2PolygonShape*>(a), xa, static_cast<const b2PolygonShape*>(b), xb);
  }
}

/// Box2D's tree query callback: pairs (lower index first) whose boxes overlap, from one body's box
/// (the tree answers by fat boxes; the pair is kept when the bodies' own boxes overlap).
struct B2Query {
  const b2DynamicTree* tree = nullptr;
  const std::vector<b2AABB>* box = nullptr;
  std::uint32_t self = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>>* out = nullptr;
  bool QueryCallback(int32 proxy) {
    const auto j = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(tree->GetUserData(proxy)));
    if (j > self && b2TestOverlap((*box)[self], (*box)[j])) out->emplace_back(self, j);
    return true;
  }
};

Timings run_box2d(const Scene& s, int frames = kFrames) {
  const std::size_t n = s.shapes.size();
  std::vector<V> p = s.position, v = s.velocity;
  std::vector<float> a = s.angle;
  std::vector<b2Transform> xf(n);
  std::vector<b2AABB> box(n);
  b2DynamicTree tree;
  std::vector<int32> id(n);
  for (std::size_t i = 0; i < n; ++i) {
    xf[i].Set(to_b2(p[i]), a[i]);
    s.b2shapes[i]->ComputeAABB(&box[i], xf[i], 0);
    id[i] = tree.CreateProxy(box[i], reinterpret_cast<void*>(i));
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  B2Query q{&tree, &box, 0, &pairs};
  Timings t;
  for (int frame = 0; frame < frames; ++frame) {
    advance(p, v, a, s);
    const auto t0 = Clock::now();
    for (std::size_t i = 0; i < n; ++i) xf[i].Set(to_b2(p[i]), a[i]);
    const auto t1 = Clock::now();
    for (std::size_t i = 0; i < n; ++i) {
      b2AABB old = box[i];
      s.b2shapes[i]->ComputeAABB(&box[i], xf[i], 0);
      tree.MoveProxy(id[i], box[i], box[i].GetCenter() - old.GetCenter());
    }
    const auto t_update = Clock::now();
    pairs.clear();
    for (std::size_t i = 0; i < n; ++i) {
      q.self = std::uint32_t(i);
      tree.Query(&q, box[i]);
    }
    const auto t2 = Clock::now();
    for (const auto& [i, j] : pairs) {
      b2Manifold m;
      collide_b2(m, s.b2shapes[i].get(), xf[i], s.b2shapes[j].get(), xf[j]);
      benchmark::DoNotOptimize(m);
      if (m.pointCount > 0) {
        ++t.contacts;
        t.points += std::size_t(m.pointCount);
      }
    }
    const auto t3 = Clock::now();
    // The same pairs again, each manifold with points also turned into world points, normal and
    // separations (what contact() returns, and what Box2D's solver computes for each contact).
    for (const auto& [i, j] : pairs) {
      b2Manifold m;
      collide_b2(m, s.b2shapes[i].get(), xf[i], s.b2shapes[j].get(), xf[j]);
      if (m.pointCount > 0) {
        b2WorldManifold w;
        w.Initialize(&m, xf[i], s.b2shapes[i]->m_radius, xf[j], s.b2shapes[j]->m_radius);
        benchmark::DoNotOptimize(w);
      }
    }
    const auto t4 = Clock::now();
    t.transforms += ms(t0, t1);
    t.update += ms(t1, t_update);
    t.broadphase += ms(t1, t2);
    t.narrowphase += ms(t2, t3);
    t.narrowphase_world += ms(t3, t4);
    t.candidates += pairs.size();
  }
  return t;
}

void report(benchmark::State& state, const Timings& t) {
  state.counters["transforms_ms"] = t.transforms / kFrames;
  if (t.step == 0) state.counters["broadphase_ms"] = t.broadphase / kFrames;    // the World's: update_ms, step_ms
  if (t.step == 0) state.counters["narrowphase_ms"] = t.narrowphase / kFrames;  // the World's is inside its step
  if (t.narrowphase_world > 0) state.counters["narrowphase_world_ms"] = t.narrowphase_world / kFrames;
  state.counters["update_ms"] = t.update / kFrames;
  if (t.step > 0) state.counters["step_ms"] = t.step / kFrames;
  state.counters["frame_ms"] = (t.transforms + t.broadphase + t.narrowphase + t.step) / kFrames;
  state.counters["contacts_per_frame"] = double(t.contacts) / kFrames;
  state.counters["points_per_frame"] = double(t.points) / kFrames;
  state.SetIterationTime((t.transforms + t.broadphase + t.narrowphase + t.step) / 1e3);
}

}  // namespace

bool register_game_loop() {
  bool agreed = true;
  for (const std::size_t n : {std::size_t(2000), std::size_t(10000)}) {
    const std::shared_ptr<Scene> scene = make_scene(n);
    // Cross-check on the first 30 frames: the two libraries find nearly the same contacts (a
    // pair touching within rounding may go either way; Box2D's tree pads boxes differently).
    const Timings c = run_collide<Tree>(*scene, 30), b = run_box2d(*scene, 30);
    const Timings sweep = run_collide<bp::SweepAndPrune<float>>(*scene, 30);
    const Timings world = run_world(*scene, 30);
    if (world.contacts != c.contacts || world.points != c.points) {
      std::fprintf(stderr, "game_loop/%zu: the World found %zu contacts and %zu points, the Narrowphase %zu and %zu\n",
                   n, world.contacts, world.points, c.contacts, c.points);
      agreed = false;
    }
    if (sweep.candidates != c.candidates || sweep.contacts != c.contacts) {
      std::fprintf(stderr, "game_loop/%zu: sort and sweep found %zu pairs and %zu contacts, the tree %zu and %zu\n", n,
                   sweep.candidates, sweep.contacts, c.candidates, c.contacts);
      agreed = false;
    }
    const double diff = std::fabs(double(c.contacts) - double(b.contacts));
    if (c.contacts == 0 || diff > 0.01 * double(b.contacts)) {
      std::fprintf(stderr, "game_loop/%zu: collide found %zu contacts in 30 frames, Box2D %zu\n", n, c.contacts,
                   b.contacts);
      agreed = false;
    }
    std::fprintf(stderr, "check game_loop/%zu: contacts in 30 frames collide %zu Box2D %zu, points %zu / %zu\n", n,
                 c.contacts, b.contacts, c.points, b.points);
    benchmark::RegisterBenchmark(("game_loop/collide/" + std::to_string(n)).c_str(),
                                 [scene](benchmark::State& st) {
                                   for (auto _ : st) report(st, run_collide<Tree>(*scene));
                                 })
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("game_loop/collide_sweep/" + std::to_string(n)).c_str(),
                                 [scene](benchmark::State& st) {
                                   for (auto _ : st) report(st, run_collide<bp::SweepAndPrune<float>>(*scene));
                                 })
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("game_loop/collide_world/" + std::to_string(n)).c_str(),
                                 [scene](benchmark::State& st) {
                                   for (auto _ : st) report(st, run_world(*scene));
                                 })
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("game_loop/box2d/" + std::to_string(n)).c_str(),
                                 [scene](benchmark::State& st) {
                                   for (auto _ : st) report(st, run_box2d(*scene));
                                 })
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
  return agreed;
}

}  // namespace bench
