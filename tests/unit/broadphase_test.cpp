// Unit tests of the broadphase structures: pairs, move, remove, filters, the point query and the
// closest hit, each structure's box rule (the tree decides on stored boxes, its fat boxes only add
// candidates; sweep and grid keep their order and cell keys right), and the ray queries at the
// edges of double's range, where the slab test's parameters underflow. Each structure must give
// the exact answer for these boxes, not merely the same answer as the others.

#include "broadphase_support.hpp"

#include <collide/broadphase.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace collide::test {
namespace {

namespace bp = collide::broadphase;
using V = Vec2<double>;

template <class Structure>
std::vector<std::pair<bp::ProxyId, double>> hits(const Structure& s, V origin, V direction, double max_t) {
  std::vector<std::pair<bp::ProxyId, double>> out;
  s.raycast(origin, direction, max_t, [&](bp::ProxyId id, double t) { out.emplace_back(id, t); });
  return out;
}

template <class Structure>
void check_underflowing_slab(Structure s) {
  // The box starts 2^-960 right of the origin; the direction is 2^800 long along x. Moving left,
  // the ray crosses the line x = 2^-960 at t = -2^-1760, which underflows to -0: the slab test
  // used to take that for t = 0 and report a hit although the origin is outside the box.
  const bp::ProxyId id = s.add(V(std::ldexp(1.0, -960), -1), V(1, 1));
  EXPECT_TRUE(hits(s, V(0, 0), V(-std::ldexp(1.0, 800), 0), 1).empty());
  EXPECT_TRUE(hits(s, V(0, 0), V(-std::ldexp(1.0, 800), 0), 0).empty());
  // Moving right it is hit, at t = 2^-1760 rounded up to the smallest subnormal (never 0: the
  // origin is not in the box).
  const auto h = hits(s, V(0, 0), V(std::ldexp(1.0, 800), 0), 1);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0].first, id);
  EXPECT_GT(h[0].second, 0.0);
  EXPECT_LE(h[0].second, std::ldexp(1.0, -1000));
  // From inside the box, and from its boundary: t = 0 (closed boxes).
  EXPECT_EQ(hits(s, V(0.5, 0), V(-std::ldexp(1.0, 800), 0), 1).size(), 1u);
  EXPECT_EQ(hits(s, V(std::ldexp(1.0, -960), 0), V(-std::ldexp(1.0, 800), 0), 1).size(), 1u);
}

TEST(BroadphaseRaycast, UnderflowingSlabParameterKeepsItsSignDynamicTree) {
  check_underflowing_slab(bp::DynamicTree<double>(0.0));
}
TEST(BroadphaseRaycast, UnderflowingSlabParameterKeepsItsSignSweepAndPrune) {
  check_underflowing_slab(bp::SweepAndPrune<double>());
}
TEST(BroadphaseRaycast, UnderflowingSlabParameterKeepsItsSignUniformGrid) {
  check_underflowing_slab(bp::UniformGrid<double>(1.0));
}

/// Tree margin 1 (wide on purpose: small moves stay inside the fat box), grid cell 1.
template <class S>
S make() {
  return Make<S>::make(ScalarOf<S>(1), ScalarOf<S>(1));
}

template <class S>
class BroadphaseUnit : public ::testing::Test {};
TYPED_TEST_SUITE(BroadphaseUnit, BroadphaseStructures);

template <class T>
Aabb<T> box(T x0, T y0, T x1, T y1) {
  return Aabb<T>(Vec2<T>(x0, y0), Vec2<T>(x1, y1));
}

/// Pairs as sorted (user, user) with the lower first.
template <class S>
std::vector<std::pair<std::uint64_t, std::uint64_t>> user_pairs(const S& s) {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> out;
  for (const auto& p : s.pairs()) {
    const auto a = s.user_data(p.a), b = s.user_data(p.b);
    out.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <class S>
std::vector<std::uint64_t> query_users(const S& s, const Aabb<ScalarOf<S>>& q) {
  std::vector<std::uint64_t> out;
  s.query(q, [&](bp::ProxyId id) { out.push_back(s.user_data(id)); });
  std::sort(out.begin(), out.end());
  return out;
}

using UP = std::vector<std::pair<std::uint64_t, std::uint64_t>>;
using U = std::vector<std::uint64_t>;

TYPED_TEST(BroadphaseUnit, PairsAreTheOverlappingStoredBoxesTouchingIncluded) {
  using T = ScalarOf<TypeParam>;
  TypeParam s = make<TypeParam>();
  s.add(box<T>(0, 0, 1, 1), 0);
  s.add(box<T>(1, 0, 2, 1), 1);                      // touches 0 along x = 1
  s.add(box<T>(T(2.5), 0, 3, 1), 2);                 // 0.5 from 1: apart
  s.add(box<T>(T(0.5), T(0.5), T(0.6), T(0.6)), 3);  // inside 0
  s.add(box<T>(1, 1, 4, 4), 4);                      // touches 0 and 1 at corners / edges, 2 along y = 1
  EXPECT_EQ(user_pairs(s), (UP{{0, 1}, {0, 3}, {0, 4}, {1, 4}, {2, 4}}));
  EXPECT_EQ(s.pairs(bp::PairOrder::Sorted).size(), 5u);
}

TYPED_TEST(BroadphaseUnit, MoveStoresTheNewBoxEvenForASmallStep) {
  using T = ScalarOf<TypeParam>;
  TypeParam s = make<TypeParam>();
  const bp::ProxyId a = s.add(box<T>(0, 0, 1, 1), 0);
  s.add(box<T>(T(1.5), 0, T(2.5), 1), 1);
  EXPECT_EQ(user_pairs(s), UP{});
  // 0.5 to the right: within the tree's fat box (margin 1), so the tree's structure stays put,
  // but the stored box, the pairs and the queries must all use the new box.
  s.move(a, box<T>(T(0.5), 0, T(1.5), 1));
  EXPECT_EQ(s.box(a).min().x(), T(0.5));
  EXPECT_EQ(user_pairs(s), (UP{{0, 1}}));
  EXPECT_EQ(query_users(s, box<T>(T(1.5), T(0.5), T(1.5), T(0.5))), (U{0, 1}));
  EXPECT_EQ(query_users(s, box<T>(T(0.2), T(0.5), T(0.3), T(0.5))), U{});
  s.move(a, box<T>(0, 0, 1, 1));
  EXPECT_EQ(user_pairs(s), UP{});
  EXPECT_EQ(query_users(s, box<T>(T(0.2), T(0.5), T(0.3), T(0.5))), (U{0}));
}

TYPED_TEST(BroadphaseUnit, RemoveDropsThePairsAndTheHandle) {
  using T = ScalarOf<TypeParam>;
  TypeParam s = make<TypeParam>();
  const bp::ProxyId a = s.add(box<T>(0, 0, 1, 1), 0);
  const bp::ProxyId b = s.add(box<T>(T(0.5), 0, T(1.5), 1), 1);
  s.add(box<T>(1, 0, 2, 1), 2);
  EXPECT_EQ(user_pairs(s), (UP{{0, 1}, {0, 2}, {1, 2}}));
  s.remove(b);
  EXPECT_EQ(user_pairs(s), (UP{{0, 2}}));
  EXPECT_FALSE(s.contains(b));
  EXPECT_THROW(s.move(b, box<T>(0, 0, 1, 1)), bp::BroadphaseError);
  const bp::ProxyId c = s.add(box<T>(0, 0, 1, 1), 3);  // may reuse b's slot, never its handle
  EXPECT_NE(c, b);
  EXPECT_EQ(user_pairs(s), (UP{{0, 2}, {0, 3}, {2, 3}}));
  s.remove(a);
  EXPECT_EQ(user_pairs(s), (UP{{2, 3}}));
  EXPECT_EQ(s.size(), 2u);
}

/// Many moves that reorder the proxies (long and short), each followed by moving and removing
/// other proxies through their handles: every answer against brute force over the stored boxes.
TYPED_TEST(BroadphaseUnit, MovesAndRemovesThroughReorderedProxiesStayExact) {
  using T = ScalarOf<TypeParam>;
  TypeParam s = make<TypeParam>();
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> coord(-40, 40), size(0, 6), pick(0, 199);
  std::vector<bp::ProxyId> ids;
  std::vector<Aabb<T>> boxes;
  std::vector<bool> live;
  const auto random_box = [&](int range) {
    const T x = T(coord(rng) % range) / 2, y = T(coord(rng) % range) / 2;
    return box<T>(x, y, x + T(size(rng)) / 2, y + T(size(rng)) / 2);
  };
  for (int i = 0; i < 200; ++i) {
    boxes.push_back(random_box(41));
    ids.push_back(s.add(boxes.back(), std::uint64_t(i)));
    live.push_back(true);
  }
  const auto brute = [&] {
    UP out;
    for (std::size_t i = 0; i < boxes.size(); ++i)
      for (std::size_t j = i + 1; j < boxes.size(); ++j)
        if (live[i] && live[j] && bp::boxes_overlap(bp::box_of(boxes[i]), bp::box_of(boxes[j]))) out.emplace_back(i, j);
    return out;
  };
  for (int round = 0; round < 300; ++round) {
    const std::size_t k = std::size_t(pick(rng));
    if (!live[k]) continue;
    if (round % 17 == 16) {
      s.remove(ids[k]);
      live[k] = false;
    } else {
      // Alternate short steps (the sweep shifts its entry) and jumps across the world.
      boxes[k] = round % 2 ? random_box(41) : random_box(3);
      s.move(ids[k], boxes[k]);
    }
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (!live[i]) continue;
      ASSERT_EQ(s.box(ids[i]).min(), boxes[i].min()) << "proxy " << i << " after round " << round;
      ASSERT_EQ(s.box(ids[i]).max(), boxes[i].max()) << "proxy " << i << " after round " << round;
    }
    if (round % 10 == 0) {
      ASSERT_EQ(user_pairs(s), brute()) << "after round " << round;
    }
  }
  EXPECT_EQ(user_pairs(s), brute());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (!live[i]) continue;
    const U hits = query_users(s, boxes[i]);
    ASSERT_TRUE(std::binary_search(hits.begin(), hits.end(), std::uint64_t(i))) << "proxy " << i;
  }
}

TYPED_TEST(BroadphaseUnit, FiltersDecidePairsQueriesAndRays) {
  using T = ScalarOf<TypeParam>;
  TypeParam s = make<TypeParam>();
  const bp::Filter player{1, 0xffffffffu ^ 1u}, bullet{2, 1}, wall{4, 3}, ghost{8, 0};
  s.add(box<T>(0, 0, 2, 2), 0, player);
  s.add(box<T>(1, 1, 3, 3), 1, bullet);
  s.add(box<T>(1, 0, 4, 1), 2, wall);
  s.add(box<T>(0, 0, 4, 4), 3, ghost);
  const bp::ProxyId p4 = s.add(box<T>(0, 0, 1, 1), 4, player);  // players ignore each other
  // All five boxes except the ghost overlap pairwise; bullets meet only players.
  EXPECT_EQ(user_pairs(s), (UP{{0, 1}, {0, 2}, {1, 4}, {2, 4}}));
  U hits;
  s.query(
      box<T>(0, 0, 4, 4), [&](bp::ProxyId id) { hits.push_back(s.user_data(id)); }, bp::Filter{0xffffffffu, 2});
  std::sort(hits.begin(), hits.end());
  EXPECT_EQ(hits, (U{1}));
  std::size_t rays = 0;
  s.raycast(
      Vec2<T>(-1, T(0.5)), Vec2<T>(1, 0), T(10), [&](bp::ProxyId, Calc) { ++rays; }, bp::Filter{0xffffffffu, 1});
  EXPECT_EQ(rays, 2u);  // the two players
  rays = 0;
  s.raycast(
      Vec2<T>(-1, T(0.5)), Vec2<T>(1, 0), T(10), [&](bp::ProxyId, Calc) { ++rays; }, bp::Filter{1, 1});
  EXPECT_EQ(rays, 0u);  // players do not accept category 1
  s.set_filter(p4, wall);
  EXPECT_EQ(user_pairs(s), (UP{{0, 1}, {0, 2}, {0, 4}}));
}

TYPED_TEST(BroadphaseUnit, PointQueryAndClosestHit) {
  using T = ScalarOf<TypeParam>;
  TypeParam s = make<TypeParam>();
  s.add(box<T>(0, 0, 1, 1), 0);
  s.add(box<T>(2, 0, 3, 1), 1);
  s.add(box<T>(T(2.5), 0, 4, 1), 2);
  U at;
  s.query_point(Vec2<T>(T(2.5), 1), [&](bp::ProxyId id) { at.push_back(s.user_data(id)); });
  std::sort(at.begin(), at.end());
  EXPECT_EQ(at, (U{1, 2}));  // a corner and an edge: closed boxes
  EXPECT_THROW(s.query_point(Vec2<T>(std::numeric_limits<T>::quiet_NaN(), 0), [](bp::ProxyId) {}), bp::BroadphaseError);
  const auto hit = s.raycast_closest(Vec2<T>(5, T(0.5)), Vec2<T>(-1, 0), T(10));
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(s.user_data(hit->id), 2u);
  EXPECT_EQ(hit->t, 1.0);
  EXPECT_FALSE(s.raycast_closest(Vec2<T>(5, T(0.5)), Vec2<T>(1, 0), T(10)).has_value());
}

TYPED_TEST(BroadphaseUnit, ForEachPairStopsWhenAsked) {
  using T = ScalarOf<TypeParam>;
  TypeParam s = make<TypeParam>();
  for (int i = 0; i < 20; ++i) s.add(box<T>(0, 0, 1, 1), std::uint64_t(i));
  int seen = 0;
  s.for_each_pair([&](bp::ProxyId, bp::ProxyId) { return ++seen < 7; });
  EXPECT_EQ(seen, 7);
  seen = 0;
  s.for_each_pair([&](bp::ProxyId, bp::ProxyId) { ++seen; });
  EXPECT_EQ(seen, 190);
}

// The tree's rule: leaves hold fat boxes (stored box grown by the margin) so small moves cost
// nothing, but pairs, queries and rays are decided on the stored boxes.
TEST(BroadphaseTreeBoxes, PairsAreNotDecidedOnFatBoxes) {
  bp::DynamicTree<double> t(1.0);
  t.add(box<double>(0, 0, 1, 1), 0);
  t.add(box<double>(1.5, 0, 2.5, 1), 1);  // fat boxes overlap by 1.5
  EXPECT_EQ(user_pairs(t), UP{});
  EXPECT_EQ(query_users(t, box<double>(1.2, 0, 1.3, 1)), U{});
  std::size_t rays = 0;
  t.raycast(Vec2<double>(1.25, -5), Vec2<double>(0, 1), 10.0, [&](bp::ProxyId, Calc) { ++rays; });
  EXPECT_EQ(rays, 0u);
}

TEST(BroadphaseTreeBoxes, FatBoxKeptForSmallMovesAndRebuiltForLargeOnes) {
  bp::DynamicTree<double> t(1.0);
  const bp::ProxyId a = t.add(box<double>(0, 0, 1, 1), 0);
  EXPECT_EQ(t.fat_box(a).min(), Vec2<double>(-1, -1));
  EXPECT_EQ(t.fat_box(a).max(), Vec2<double>(2, 2));
  t.move(a, box<double>(0.5, 0.5, 1.5, 1.5));  // inside the fat box: kept
  EXPECT_EQ(t.fat_box(a).min(), Vec2<double>(-1, -1));
  EXPECT_EQ(t.box(a).min(), Vec2<double>(0.5, 0.5));
  t.move(a, box<double>(5, 5, 6, 6));  // outside: refattened around the new box, stretched ahead
  EXPECT_EQ(t.fat_box(a).min(), Vec2<double>(4, 4));
  EXPECT_EQ(t.fat_box(a).max(), Vec2<double>(9, 9));  // 4 x 4.5 ahead, capped at extent + margin
  t.move(a, box<double>(5.25, 4.5, 6.25, 5.5));       // still inside
  EXPECT_EQ(t.fat_box(a).max(), Vec2<double>(9, 9));
  t.move(a, box<double>(4.5, 2.75, 5.5, 3.75));             // leaves it down and left: stretched that way
  EXPECT_EQ(t.fat_box(a).min(), Vec2<double>(1.5, -0.25));  // 4 x (-0.75, -1.75), capped at -2
  EXPECT_EQ(t.fat_box(a).max(), Vec2<double>(6.5, 4.75));
  EXPECT_TRUE(t.check_invariants());
}

TEST(BroadphaseTreeBoxes, AddBatchFindsTheSamePairsAsAddingOneByOne) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> pos(0, 30), size(0.2f, 2.0f);
  std::vector<Aabb<float>> boxes;
  for (int i = 0; i < 500; ++i) {
    const Vec2<float> lo(pos(rng), pos(rng));
    boxes.emplace_back(lo, Vec2<float>(lo + Vec2<float>(size(rng), size(rng))));
  }
  bp::DynamicTree<float> one(0.1f), batch(0.1f);
  for (std::size_t i = 0; i < boxes.size(); ++i) one.add(boxes[i], i);
  const auto ids = batch.add_batch(boxes);
  ASSERT_EQ(ids.size(), boxes.size());
  EXPECT_TRUE(batch.check_invariants());
  EXPECT_LE(batch.height(), 10);  // top down: balanced (log2 500 < 9)
  for (std::size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(batch.user_data(ids[i]), i);
  EXPECT_EQ(user_pairs(batch), user_pairs(one));
  // Into a non-empty tree, one by one; moves and removals work on batch-built leaves.
  const auto more = batch.add_batch(std::span<const Aabb<float>>(boxes).first(10), 1000);
  EXPECT_EQ(batch.size(), 510u);
  batch.move(ids[0], Aabb<float>(Vec2<float>(100, 100), Vec2<float>(101, 101)));
  batch.remove(more[3]);
  EXPECT_TRUE(batch.check_invariants());
  EXPECT_EQ(query_users(batch, Aabb<float>(Vec2<float>(100, 100), Vec2<float>(100, 100))), (U{0}));
}

// The grid hashes cell (x, y) as two 32-bit halves of one key: a negative y must not spill into
// the x half, or cells (0, -1) and (-1, -1) share a key and pairs reported per cell are lost.
TEST(BroadphaseGridKeys, NegativeCellIndicesKeepTheirOwnCells) {
  for (const double cell : {1.0, 0.25}) {
    bp::UniformGrid<double> g(cell);
    g.add(box<double>(0.2 * cell, -0.8 * cell, 0.4 * cell, -0.6 * cell), 0);  // cell (0, -1)
    g.add(box<double>(0.3 * cell, -0.7 * cell, 0.5 * cell, -0.5 * cell), 1);
    g.add(box<double>(-0.8 * cell, -0.8 * cell, -0.6 * cell, -0.6 * cell), 2);  // cell (-1, -1)
    g.add(box<double>(-0.7 * cell, -0.7 * cell, -0.5 * cell, -0.5 * cell), 3);
    g.add(box<double>(5.2 * cell, -3.8 * cell, 5.4 * cell, -3.6 * cell), 4);  // cell (5, -4)
    g.add(box<double>(5.3 * cell, -3.7 * cell, 5.5 * cell, -3.5 * cell), 5);
    EXPECT_EQ(user_pairs(g), (UP{{0, 1}, {2, 3}, {4, 5}})) << "cell " << cell;
  }
}

}  // namespace
}  // namespace collide::test
