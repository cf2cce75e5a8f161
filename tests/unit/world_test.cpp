// Unit tests of the World's bodies and of what makes a full world cheap: bodies placed by
// transforms and moved without their shapes, contacts with their ids and speculative distance,
// the one policy for NaN points and rays, the pair map behind the contacts, the tree's rebuild
// and the pair tracker's bulk update (the paths a world of more than a thousand new bodies takes,
// which the property suites' small worlds never reach).

#include <collide/broadphase.hpp>
#include <collide/collide.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace collide::test {
namespace {

namespace bp = collide::broadphase;
using V = Vec2<float>;
using X = Transform<float>;

X at(float x, float y, float angle = 0) {
  return X::make(V(x, y), angle).value();
}

TEST(World, ABodyMovedByATransformGetsThePlacedContact) {
  bp::World<float> world;
  const Obb<float> crate(V(0, 0), V(1, 0.5f), 0.0f);
  const Capsule<float> stick(V(-1, 0), V(1, 0), 0.25f);
  const bp::ProxyId a = world.add(crate, at(0, 0), 1);
  const bp::ProxyId b = world.add(stick, at(5, 0), 2);
  EXPECT_TRUE(world.step().began.empty()) << "bodies 5 apart are not in contact";

  world.move(b, at(1.5f, 0.5f, 0.7f));
  const bp::PairEvents& e = world.step();
  ASSERT_EQ(e.began.size(), 1u) << "the stick turned into the crate: one contact begins";
  const bp::BodyContact<float>* c = world.find_contact(a, b);
  ASSERT_NE(c, nullptr);
  const auto want = contact(crate, at(0, 0), stick, at(1.5f, 0.5f, 0.7f));
  ASSERT_TRUE(want.has_value());
  EXPECT_EQ(c->contact.normal, want->normal) << "the World's manifold is contact() of the placed shapes";
  EXPECT_EQ(c->contact.depth, want->depth);
  EXPECT_EQ(c->contact.count, want->count);
  EXPECT_EQ(world.transform(b), at(1.5f, 0.5f, 0.7f));
  EXPECT_TRUE(std::holds_alternative<Capsule<float>>(world.shape(b))) << "the shape is kept in its own frame";
}

TEST(World, AContactKeepsItsIdWhileItLastsAndANewContactGetsANewOne) {
  bp::World<float> world;
  const Circle<float> ball(V(0, 0), 1);
  const bp::ProxyId a = world.add(ball, at(0, 0));
  const bp::ProxyId b = world.add(ball, at(1.5f, 0));
  world.step();
  const bp::ContactId first = world.find_contact(a, b)->id;
  world.move(b, at(1.0f, 0.5f));
  EXPECT_TRUE(world.step().began.empty());
  EXPECT_EQ(world.find_contact(a, b)->id, first) << "moved but still touching: the same contact";
  world.move(b, at(3, 0));
  EXPECT_EQ(world.step().ended.size(), 1u);
  EXPECT_EQ(world.find_contact(a, b), nullptr);
  world.move(b, at(2, 0));  // touching counts
  EXPECT_EQ(world.step().began.size(), 1u);
  const bp::ContactId second = world.find_contact(a, b)->id;
  EXPECT_NE(second, first) << "a contact that begins again is a new contact: a solver must not warm-start it";
  EXPECT_EQ(second.index, first.index) << "its slot is reused";
  EXPECT_LT(second.index, world.contact_capacity());
}

TEST(World, SpeculativeContactsReachBodiesApartByAtMostTheDistance) {
  bp::World<float> world(bp::DynamicTree<float>(0.1f), 0.5f);
  const Aabb<float> ground(V(-10, -1), V(10, 0));
  const Circle<float> ball(V(0, 0), 1);
  const bp::ProxyId g = world.add(ground);
  const bp::ProxyId b = world.add(ball, at(0, 1.25f));  // 0.25 above the ground
  world.step();
  const bp::BodyContact<float>* c = world.find_contact(g, b);
  ASSERT_NE(c, nullptr) << "0.25 apart is within the speculative 0.5";
  EXPECT_NEAR(c->contact.separations[0], 0.25f, 1e-6f) << "a speculative point's separation is the gap";
  world.move(b, at(0, 1.75f));  // 0.75 apart
  EXPECT_EQ(world.step().ended.size(), 1u);
  world.move(b, at(0, 1.5f));  // exactly 0.5 apart: the closed bound
  EXPECT_EQ(world.step().began.size(), 1u);
}

TEST(World, BadSpeculativeDistanceIsANamedError) {
  for (const float d : {-1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    try {
      bp::World<float> world(bp::DynamicTree<float>(), d);
      ADD_FAILURE() << "speculative distance " << d << " accepted";
    } catch (const bp::BroadphaseError& e) {
      EXPECT_EQ(e.code(), bp::BroadphaseErrc::BadMargin);
    }
  }
}

TEST(World, ANanOrInfinitePointOrRayMeetsNoBodyAsContainsAndRaycastSay) {
  bp::World<float> world;
  world.add(Aabb<float>(V(-1e30f, -1e30f), V(1e30f, 1e30f)));  // holds every finite point
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (const V& p : {V(nan, 0), V(0, nan), V(inf, 0), V(-inf, inf)}) {
    int found = 0;
    world.query_point(p, [&](bp::ProxyId) { ++found; });
    EXPECT_EQ(found, 0) << "the World's point query answers as contains()";
    EXPECT_FALSE(contains(world.shape(bp::ProxyId{0, 0}), p));
    const Ray<float> ray{p, V(1, 0)};
    EXPECT_FALSE(world.raycast(ray, 1.0f).has_value()) << "the World's ray answers as raycast()";
    EXPECT_FALSE(raycast(world.shape(bp::ProxyId{0, 0}), ray, 1.0f).has_value());
  }
  EXPECT_FALSE(world.raycast(Ray<float>{V(0, 0), V(nan, 1)}, 1.0f).has_value());
  EXPECT_FALSE(world.raycast(Ray<float>{V(0, 0), V(1, 0)}, -1.0f).has_value());
  EXPECT_FALSE(world.raycast(Ray<float>{V(0, 0), V(1, 0)}, nan).has_value());
  int found = 0;
  world.query_point(V(0, 0), [&](bp::ProxyId) { ++found; });
  EXPECT_EQ(found, 1) << "a finite point inside is found";
}

TEST(World, StaleHandlesAreNamed) {
  bp::World<float> world;
  const bp::ProxyId a = world.add(Circle<float>(V(0, 0), 1));
  world.remove(a);
  EXPECT_THROW(world.move(a, at(1, 1)), bp::BroadphaseError);
  EXPECT_THROW(static_cast<void>(world.transform(a)), bp::BroadphaseError);
  EXPECT_THROW(static_cast<void>(world.shape(a)), bp::BroadphaseError);
  EXPECT_EQ(world.find_contact(a, a), nullptr);
}

TEST(PairMap, AgreesWithAnOrderedMapThroughInsertsAndErases) {
  collide::detail::PairMap map;
  std::map<std::uint64_t, std::uint32_t> model;
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> slot(0, 300);
  for (int step = 0; step < 200000; ++step) {
    const std::uint64_t k = collide::detail::pair_key(slot(rng), slot(rng));
    const auto it = model.find(k);
    if (it == model.end()) {
      const std::uint32_t v = std::uint32_t(step);
      map.insert(k, v);
      model.emplace(k, v);
    } else if (step % 3 == 0) {
      std::uint32_t v = 0;
      ASSERT_TRUE(map.erase(k, &v));
      ASSERT_EQ(v, it->second);
      model.erase(it);
    }
    ASSERT_EQ(map.size(), model.size());
  }
  for (std::uint32_t a = 0; a <= 300; ++a)
    for (std::uint32_t b = a; b <= 300; ++b) {
      const std::uint64_t k = collide::detail::pair_key(b, a);
      const auto it = model.find(k);
      const std::uint32_t* v = map.find(k);
      ASSERT_EQ(v != nullptr, it != model.end()) << "pair " << a << ", " << b;
      if (v) {
        ASSERT_EQ(*v, it->second);
      }
    }
}

std::vector<Aabb<float>> random_boxes(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  const float extent = std::sqrt(2.0f * float(n));
  std::uniform_real_distribution<float> pos(0, extent), size(0.5f, 1.5f);
  std::vector<Aabb<float>> out;
  for (std::size_t i = 0; i < n; ++i) {
    const V lo(pos(rng), pos(rng));
    out.emplace_back(lo, lo + V(size(rng), size(rng)));
  }
  return out;
}

TEST(DynamicTreeRebuild, KeepsHandlesBoxesAndEveryAnswer) {
  bp::DynamicTree<float> tree(0.1f);
  const std::vector<Aabb<float>> boxes = random_boxes(3000, 3);
  std::vector<bp::ProxyId> ids;
  for (std::size_t i = 0; i < boxes.size(); ++i) ids.push_back(tree.add(boxes[i], i));
  for (std::size_t i = 0; i < ids.size(); i += 3) tree.remove(ids[i]);
  const auto before = tree.pairs(bp::PairOrder::Sorted);
  std::vector<Aabb<float>> fat;
  for (std::size_t i = 1; i < ids.size(); i += 3) fat.push_back(tree.fat_box(ids[i]));
  const int height = tree.height();
  tree.rebuild();
  EXPECT_TRUE(tree.check_invariants());
  EXPECT_EQ(tree.pairs(bp::PairOrder::Sorted), before);
  for (std::size_t i = 1, k = 0; i < ids.size(); i += 3, ++k) {
    EXPECT_EQ(tree.fat_box(ids[i]).min(), fat[k].min()) << "fat boxes are kept";
    EXPECT_EQ(tree.box(ids[i]).min(), boxes[i].min());
  }
  EXPECT_LE(tree.height(), height) << "a median build is no taller than one-by-one insertion";
  // The rebuilt tree keeps working: moves and removals through old handles.
  for (std::size_t i = 1; i < ids.size(); i += 3) tree.move(ids[i], boxes[(i + 7) % boxes.size()]);
  for (std::size_t i = 2; i < ids.size(); i += 6) tree.remove(ids[i]);
  EXPECT_TRUE(tree.check_invariants());
  bp::SweepAndPrune<float> sweep;
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (tree.contains(ids[i])) sweep.add(tree.box(ids[i]), i);
  std::vector<std::pair<std::uint64_t, std::uint64_t>> got, want;
  tree.for_each_pair(
      [&](bp::ProxyId a, bp::ProxyId b) { got.emplace_back(std::minmax(tree.user_data(a), tree.user_data(b))); });
  sweep.for_each_pair(
      [&](bp::ProxyId a, bp::ProxyId b) { want.emplace_back(std::minmax(sweep.user_data(a), sweep.user_data(b))); });
  std::sort(got.begin(), got.end());
  std::sort(want.begin(), want.end());
  EXPECT_EQ(got, want);
}

/// The pair events of a tracker, as sorted pairs of user data.
template <class Tracker>
std::pair<std::vector<std::pair<std::uint64_t, std::uint64_t>>, std::vector<std::pair<std::uint64_t, std::uint64_t>>>
sorted_events(Tracker& t, const std::map<bp::ProxyId, std::uint64_t>& user) {
  const bp::PairEvents e = t.update();
  std::pair<std::vector<std::pair<std::uint64_t, std::uint64_t>>, std::vector<std::pair<std::uint64_t, std::uint64_t>>>
      out;
  for (const auto& p : e.began) out.first.emplace_back(std::minmax(user.at(p.a), user.at(p.b)));
  for (const auto& p : e.ended) out.second.emplace_back(std::minmax(user.at(p.a), user.at(p.b)));
  std::sort(out.first.begin(), out.first.end());
  std::sort(out.second.begin(), out.second.end());
  return out;
}

TEST(PairTrackerBulk, ATreeTrackerRebuiltAndRefilledInBulkReportsWhatSweepAndPruneDoes) {
  // Thousands of proxies added or moved between two updates take the tree tracker's bulk paths
  // (a rebuild, one walk of every fat pair); sort and sweep has none, so it is the reference.
  bp::PairTracker<bp::DynamicTree<float>, float> tree{bp::DynamicTree<float>(0.1f)};
  bp::PairTracker<bp::SweepAndPrune<float>, float> sweep;
  std::map<bp::ProxyId, std::uint64_t> tree_user, sweep_user;
  std::vector<bp::ProxyId> tree_id, sweep_id;
  std::vector<Aabb<float>> boxes = random_boxes(4000, 11);
  const auto add = [&](std::size_t i) {
    tree_id.push_back(tree.add(boxes[i], i));
    sweep_id.push_back(sweep.add(boxes[i], i));
    tree_user[tree_id.back()] = i;
    sweep_user[sweep_id.back()] = i;
  };
  for (std::size_t i = 0; i < 3000; ++i) add(i);
  auto t = sorted_events(tree, tree_user), s = sorted_events(sweep, sweep_user);
  EXPECT_EQ(t, s);
  EXPECT_GT(t.first.size(), 1000u) << "the scene has many pairs";
  const std::vector<Aabb<float>> elsewhere = random_boxes(4000, 12);
  for (std::size_t i = 0; i < 3000; i += 2) {  // half of them move far: new fat boxes in bulk
    tree.move(tree_id[i], elsewhere[i]);
    sweep.move(sweep_id[i], elsewhere[i]);
  }
  for (std::size_t i = 1; i < 3000; i += 10) {
    tree.remove(tree_id[i]);
    sweep.remove(sweep_id[i]);
  }
  for (std::size_t i = 3000; i < 4000; ++i) add(i);
  t = sorted_events(tree, tree_user);
  s = sorted_events(sweep, sweep_user);
  EXPECT_EQ(t, s);
  EXPECT_FALSE(t.second.empty());
  EXPECT_EQ(tree.structure().pairs(bp::PairOrder::Sorted).size(),
            sweep.structure().pairs(bp::PairOrder::Sorted).size());
  EXPECT_TRUE(tree.structure().check_invariants());
}

}  // namespace
}  // namespace collide::test
