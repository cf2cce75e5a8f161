// Re-entrancy and thread safety of the broadphase structures' const queries: a query or raycast
// made from inside another one's callback (same structure or another) gives the exact answer, and
// many threads querying one structure that nobody modifies get the single-threaded answers; the
// same for a World's contacts and queries, some of them asked from inside its own callbacks.
// Also built with -fsanitize=thread by the broadphase_tsan test (tests/unit/broadphase_tsan).

#include "broadphase_support.hpp"

#include <collide/broadphase.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <thread>
#include <vector>

namespace collide::test {
namespace {

namespace bp = collide::broadphase;

/// Tree margin 0.25, grid cell 1.
template <class S>
S make() {
  return Make<S>::make(ScalarOf<S>(0.25), ScalarOf<S>(1));
}

template <class S>
class BroadphaseReentrant : public ::testing::Test {};
TYPED_TEST_SUITE(BroadphaseReentrant, BroadphaseStructures);

/// A row of n unit boxes, each overlapping its neighbours by half (box i: x in [i/2, i/2 + 1]).
template <class S>
std::vector<bp::ProxyId> add_row(S& s, int n) {
  using T = ScalarOf<S>;
  std::vector<bp::ProxyId> ids;
  for (int i = 0; i < n; ++i) ids.push_back(s.add(Vec2<T>(T(i) / 2, 0), Vec2<T>(T(i) / 2 + 1, 1), std::uint64_t(i)));
  return ids;
}

/// Box i of the row meets boxes i-2 .. i+2 (closed: i +- 2 touch).
int row_neighbours(int i, int n) {
  return std::min(n - 1, i + 2) - std::max(0, i - 2) + 1;
}

TYPED_TEST(BroadphaseReentrant, QueryInsideQueryCallbackIsExact) {
  using T = ScalarOf<TypeParam>;
  const TypeParam s = [] {
    TypeParam m = make<TypeParam>();
    add_row(m, 11);
    return m;
  }();
  const Aabb<T> all(Vec2<T>(-1, -1), Vec2<T>(10, 2));
  int outer = 0, inner = 0, expected_inner = 0;
  s.query(all, [&](bp::ProxyId id) {
    ++outer;
    expected_inner += row_neighbours(int(s.user_data(id)), 11);
    s.query(s.box(id), [&](bp::ProxyId) { ++inner; });
  });
  EXPECT_EQ(outer, 11);
  EXPECT_EQ(inner, expected_inner);
  EXPECT_EQ(inner, 11 + 2 * 10 + 2 * 9);
}

TYPED_TEST(BroadphaseReentrant, RaycastAndQueryNestedBothWaysAreExact) {
  using T = ScalarOf<TypeParam>;
  TypeParam s = make<TypeParam>();
  add_row(s, 11);
  const TypeParam& c = s;
  // Raycast along the row; from each hit, a raycast and a query.
  int outer = 0, inner_rays = 0, inner_queries = 0;
  c.raycast(Vec2<T>(-1, T(0.5)), Vec2<T>(1, 0), T(20), [&](bp::ProxyId id, Calc) {
    ++outer;
    c.raycast(Vec2<T>(-1, T(0.5)), Vec2<T>(1, 0), T(20), [&](bp::ProxyId, Calc) { ++inner_rays; });
    c.query(c.box(id), [&](bp::ProxyId) { ++inner_queries; });
  });
  EXPECT_EQ(outer, 11);
  EXPECT_EQ(inner_rays, 11 * 11);
  EXPECT_EQ(inner_queries, 11 + 2 * 10 + 2 * 9);
  // A query whose callback runs a raycast and a pair walk.
  int pairs_seen = 0, rays = 0;
  c.query(Aabb<T>(Vec2<T>(0, 0), Vec2<T>(1, 1)), [&](bp::ProxyId) {
    c.raycast(Vec2<T>(-1, T(0.5)), Vec2<T>(1, 0), T(20), [&](bp::ProxyId, Calc) { ++rays; });
    c.for_each_pair([&](bp::ProxyId, bp::ProxyId) { ++pairs_seen; });
  });
  EXPECT_EQ(rays, 3 * 11);              // boxes 0, 1, 2 meet [0, 1]^2
  EXPECT_EQ(pairs_seen, 3 * (10 + 9));  // each pair (i, i+1) and (i, i+2) once per outer hit
}

TYPED_TEST(BroadphaseReentrant, QueryInsideAnotherStructuresCallbackIsExact) {
  using T = ScalarOf<TypeParam>;
  TypeParam a = make<TypeParam>(), b = make<TypeParam>();
  add_row(a, 11);
  add_row(b, 11);
  int inner = 0;
  a.query(Aabb<T>(Vec2<T>(-1, -1), Vec2<T>(10, 2)),
          [&](bp::ProxyId id) { b.query(a.box(id), [&](bp::ProxyId) { ++inner; }); });
  EXPECT_EQ(inner, 11 + 2 * 10 + 2 * 9);
}

/// Every answer of a fixed list of queries and rays, as one flat list of user data.
template <class S>
std::vector<std::uint64_t> answers(const S& s, const std::vector<Aabb<ScalarOf<S>>>& qs) {
  using T = ScalarOf<S>;
  std::vector<std::uint64_t> out;
  for (const auto& q : qs) {
    std::vector<std::uint64_t> hits;
    s.query(q, [&](bp::ProxyId id) {
      hits.push_back(s.user_data(id));
      s.query(s.box(id), [&](bp::ProxyId) { hits.push_back(1u << 20); });  // nested as well
    });
    s.raycast(q.min(), Vec2<T>(q.max() - q.min()) * T(4), T(1),
              [&](bp::ProxyId id, Calc) { hits.push_back(s.user_data(id) + (1u << 21)); });
    std::sort(hits.begin(), hits.end());
    out.insert(out.end(), hits.begin(), hits.end());
    out.push_back(~std::uint64_t{0});
  }
  return out;
}

TYPED_TEST(BroadphaseReentrant, ManyThreadsQueryingGetTheSingleThreadedAnswers) {
  using T = ScalarOf<TypeParam>;
  TypeParam s = make<TypeParam>();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> pos(0, 40), size(0.2f, 2.0f);
  std::vector<bp::ProxyId> ids;
  for (int i = 0; i < 1500; ++i) {
    const Vec2<T> lo(T(pos(rng)), T(pos(rng)));
    ids.push_back(s.add(lo, Vec2<T>(lo + Vec2<T>(T(size(rng)), T(size(rng)))), std::uint64_t(i)));
  }
  // Moves and removals last, so no structure is tidied before the threads start.
  for (int i = 0; i < 1500; i += 3) {
    const Vec2<T> lo(T(pos(rng)), T(pos(rng)));
    s.move(ids[std::size_t(i)], lo, Vec2<T>(lo + Vec2<T>(T(1), T(1))));
  }
  for (int i = 1; i < 1500; i += 7) s.remove(ids[std::size_t(i)]);
  std::vector<Aabb<T>> qs;
  for (int i = 0; i < 150; ++i) {
    const Vec2<T> lo(T(pos(rng)), T(pos(rng)));
    qs.emplace_back(lo, Vec2<T>(lo + Vec2<T>(T(size(rng)) * 2, T(size(rng)) * 2)));
  }
  const TypeParam& c = s;
  // Copy first: the reference answers must not tidy the structure the threads then read.
  const TypeParam reference_copy = s;
  const std::vector<std::uint64_t> want = answers(reference_copy, qs);
  ASSERT_GT(want.size(), qs.size() * 2);
  constexpr int kThreads = 4, kRounds = 10;
  std::vector<int> wrong(kThreads, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int r = 0; r < kRounds; ++r) wrong[std::size_t(t)] += answers(c, qs) == want ? 0 : 1;
    });
  }
  for (auto& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(wrong[std::size_t(t)], 0) << "thread " << t;
}

/// Everything a World's const members answer about its bodies: each contact (bodies, id, normal,
/// depth), the bodies at each probe point, those meeting each probe shape, each ray's nearest hit,
/// and for each contact the bodies its first point meets (a query from inside for_each_contact).
std::vector<double> world_answers(const bp::World<float>& w, const std::vector<Vec2<float>>& probes) {
  std::vector<double> out;
  w.for_each_contact([&](const bp::BodyContact<float>& c) {
    out.insert(out.end(), {double(c.a.index), double(c.b.index), double(c.id.index), double(c.contact.normal.x()),
                           double(c.contact.depth)});
    const bp::BodyContact<float>* again = w.find_contact(c.b, c.a);
    out.push_back(again != nullptr && again->id == c.id ? 1 : 0);
    w.query_point(c.contact.points[0], [&](bp::ProxyId id) { out.push_back(double(id.index)); });
  });
  for (const Vec2<float>& p : probes) {
    w.query_point(p, [&](bp::ProxyId id) { out.push_back(double(id.index)); });
    w.query_shape(Circle<float>(p, 1.5f), [&](bp::ProxyId id) { out.push_back(double(id.index)); });
    const auto hit = w.raycast(Ray<float>{p, Vec2<float>(1, 0.5f)}, 10.0f);
    out.push_back(hit ? double(hit->hit.t) : -1.0);
  }
  return out;
}

TEST(WorldThreads, ManyThreadsReadingAWorldGetTheSingleThreadedAnswers) {
  bp::World<float> world(bp::DynamicTree<float>(0.1f), 0.05f);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> pos(0, 30), turn(-3, 3), size(0.3f, 1.2f);
  const Obb<float> crate(Vec2<float>(0, 0), Vec2<float>(1, 0.5f), 0.0f);
  const Capsule<float> stick(Vec2<float>(-1, 0), Vec2<float>(1, 0), 0.3f);
  std::vector<bp::ProxyId> ids;
  for (int i = 0; i < 600; ++i) {
    const Transform<float> x(Vec2<float>(pos(rng), pos(rng)), turn(rng));
    if (i % 3 == 0) {
      ids.push_back(world.add(crate, x));
    } else if (i % 3 == 1) {
      ids.push_back(world.add(stick, x));
    } else {
      ids.push_back(world.add(Circle<float>(Vec2<float>(0, 0), size(rng)), x));
    }
  }
  world.step();
  for (std::size_t i = 0; i < ids.size(); i += 2)
    world.move(ids[i], Transform<float>(Vec2<float>(pos(rng), pos(rng)), turn(rng)));
  world.step();
  std::vector<Vec2<float>> probes;
  for (int i = 0; i < 200; ++i) probes.emplace_back(pos(rng), pos(rng));
  const std::vector<double> want = world_answers(world, probes);
  ASSERT_GT(world.contact_count(), 100u) << "the scene is built to have many contacts";
  constexpr int kThreads = 4, kRounds = 5;
  std::vector<int> wrong(kThreads, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int r = 0; r < kRounds; ++r) wrong[std::size_t(t)] += world_answers(world, probes) == want ? 0 : 1;
    });
  }
  for (auto& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(wrong[std::size_t(t)], 0) << "thread " << t;
}

}  // namespace
}  // namespace collide::test
