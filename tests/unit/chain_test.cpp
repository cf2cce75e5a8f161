// Unit tests of chains (collide/chain.hpp): their named errors, the one-sided rule, the corner
// arcs, and the scene a game cares about: shapes sliding over a row of tiles. Built as separate
// boxes, the tiles give sideways normals at their seams (ghost collisions); built as one chain,
// none. The per-box count is asserted too: a scene that provoked no ghost would prove nothing.

#include "support.hpp"

#include <collide/broadphase.hpp>
#include <collide/chain.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace collide::test {
namespace {

template <class T>
class Chains : public ::testing::Test {};
TYPED_TEST_SUITE(Chains, Scalars);

/// Whether a normal is the floor's (0, 1) up to T's rounding: anything else is a ghost.
template <Scalar T>
bool is_up(const Vec2<T>& n) {
  return std::fabs(double(n.x())) <= 1e-5 && double(n.y()) > 0;
}

TYPED_TEST(Chains, NamedErrors) {
  using T = TypeParam;
  using V = Vec2<T>;
  const std::vector<V> three = {V(0, 0), V(1, 0), V(2, 0)};
  EXPECT_EQ(Chain<T>::make(three, false).error().code(), Error::TooFewVertices);
  EXPECT_EQ(Chain<T>::make(std::vector<V>{V(0, 0), V(1, 0)}, true).error().code(), Error::TooFewVertices);
  const std::vector<V> repeated = {V(0, 0), V(1, 0), V(1, 0), V(2, 0)};
  const auto zero = Chain<T>::make(repeated, false);
  ASSERT_FALSE(zero);
  EXPECT_EQ(zero.error().code(), Error::ZeroLengthSegment);
  EXPECT_EQ(zero.error().index(), 1);
  const std::vector<V> folded = {V(0, 0), V(1, 0), V(2, 0), V(1.5, 0), V(3, 1)};
  const auto fold = Chain<T>::make(folded, false);
  ASSERT_FALSE(fold);
  EXPECT_EQ(fold.error().code(), Error::FoldedChain);
  EXPECT_EQ(fold.error().index(), 2);
  const std::vector<V> nan = {V(0, 0), V(1, 0), V(std::nan(""), 0), V(2, 0)};
  EXPECT_EQ(Chain<T>::make(nan, false).error().code(), Error::NonFinite);
  EXPECT_EQ(Chain<T>::make(nan, false).error().index(), 4);
  // A loop's closing segment counts: the last point may not repeat the first.
  const std::vector<V> closed = {V(0, 0), V(1, 0), V(1, 1), V(0, 0)};
  EXPECT_EQ(Chain<T>::make(closed, true).error().code(), Error::ZeroLengthSegment);
  EXPECT_EQ(ChainSegment<T>::make(V(0, 0), V(1, 0), V(2, 0), V(2, 0)).error().code(), Error::ZeroLengthSegment);
  EXPECT_EQ(ChainSegment<T>::make(V(2, 0), V(1, 0), V(2, 0), V(3, 0)).error().code(), Error::FoldedChain);
  EXPECT_EQ(name(Error::ZeroLengthSegment), "ZeroLengthSegment");
  EXPECT_EQ(name(Error::FoldedChain), "FoldedChain");
}

TYPED_TEST(Chains, SegmentsAndGhosts) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Open: the first and last points are ghosts; a floor runs right to left to face up.
  const Chain<T> open({V(3, 0), V(2, 0), V(1, 0), V(0, 0), V(-1, 0)}, false);
  ASSERT_EQ(open.size(), 2u);
  EXPECT_EQ(open.segment(0).before(), V(3, 0));
  EXPECT_EQ(open.segment(0).a(), V(2, 0));
  EXPECT_EQ(open.segment(1).after(), V(-1, 0));
  EXPECT_TRUE(open.segment(0).owns_start_corner());
  EXPECT_FALSE(open.segment(1).owns_start_corner());
  const Chain<T> loop({V(0, 0), V(1, 0), V(1, 1)}, true);
  ASSERT_EQ(loop.size(), 3u);
  EXPECT_EQ(loop.segment(0).before(), V(1, 1));
  EXPECT_EQ(loop.segment(2).a(), V(1, 1));
  EXPECT_EQ(loop.segment(2).b(), V(0, 0));
  EXPECT_EQ(loop.segment(2).after(), V(1, 0));
  EXPECT_FALSE(loop.segment(0).owns_start_corner());
}

TYPED_TEST(Chains, FrontFaceContact) {
  using T = TypeParam;
  using V = Vec2<T>;
  const ChainSegment<T> floor(V(3, 0), V(2, 0), V(-2, 0), V(-3, 0));
  // A box sunk 1/4 into the floor: two points on the front, normal up, ids edge 0 and the box's
  // bottom corners (vertex 0 = min, vertex 1 = (max.x, min.y)).
  const auto c = contact(floor, Aabb<T>(V(-1, T(-0.25)), V(1, 1)));
  ASSERT_TRUE(c);
  EXPECT_TRUE(is_up(c->normal));
  EXPECT_NEAR(double(c->depth), 0.25, 1e-6);
  ASSERT_EQ(c->count, 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(double(c->separations[std::size_t(i)]), -0.25, 1e-6);
    EXPECT_NEAR(double(c->points[std::size_t(i)].y()), -0.125, 1e-6);
  }
  // Behind the front (the centre below the line): no contact, though the shapes overlap.
  EXPECT_FALSE(contact(floor, Aabb<T>(V(-1, -1), V(1, T(0.25)))));
  EXPECT_TRUE(overlaps(floor.as_capsule(), Aabb<T>(V(-1, -1), V(1, T(0.25)))));
  // Touching counts; apart does not, unless within the speculative distance.
  EXPECT_TRUE(contact(floor, Circle<T>(V(0, 1), 1)));
  EXPECT_FALSE(contact(floor, Circle<T>(V(0, T(1.5)), 1)));
  const auto spec = contact(floor, Circle<T>(V(0, T(1.5)), 1), T(1));
  ASSERT_TRUE(spec);
  EXPECT_NEAR(double(spec->separations[0]), 0.5, 1e-6);
  EXPECT_EQ(spec->depth, T(0));
}

TYPED_TEST(Chains, CompoundAnswersWithItsDeepestChild) {
  using T = TypeParam;
  using V = Vec2<T>;
  const ChainSegment<T> floor(V(3, 0), V(2, 0), V(-2, 0), V(-3, 0));
  // Two boxes of one compound over the floor, the second sunk deeper: its contact, naming it, in
  // either order of the children. A contact of the shallower box would let the deeper sink on.
  const Aabb<T> shallow(V(-1, T(-0.125)), V(0, 1)), deep(V(T(0.5), T(-0.375)), V(T(1.5), 1));
  for (const bool deep_first : {false, true}) {
    std::vector<Primitive<T>> kids;
    kids.emplace_back(deep_first ? deep : shallow);
    kids.emplace_back(deep_first ? shallow : deep);
    const auto c = contact(floor, Shape<T>(Compound<T>(std::move(kids))));
    ASSERT_TRUE(c);
    EXPECT_TRUE(is_up(c->normal));
    EXPECT_NEAR(double(c->depth), 0.375, 1e-6) << "deep box first: " << deep_first;
    for (int i = 0; i < c->count; ++i) EXPECT_EQ(c->ids[std::size_t(i)].child_b, deep_first ? 0 : 1);
  }
}

TYPED_TEST(Chains, CapsuleMeetsTheFrontWithItsSide) {
  using T = TypeParam;
  using V = Vec2<T>;
  const ChainSegment<T> floor(V(3, 0), V(2, 0), V(-2, 0), V(-3, 0));
  // A capsule lying flat, sunk 0.05: its bottom side gives two points, one under each end, each
  // naming the end it comes from; a point from its top side would float 0.45 above the floor.
  const auto c = contact(floor, Capsule<T>(V(-1, T(0.2)), V(1, T(0.2)), T(0.25)));
  ASSERT_TRUE(c);
  ASSERT_EQ(c->count, 2);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(double(c->separations[i]), -0.05, 1e-6);
    EXPECT_NEAR(double(c->points[i].y()), -0.025, 1e-6);
    EXPECT_NEAR(double(c->points[i].x()), i == 0 ? -1.0 : 1.0, 1e-6);
    EXPECT_EQ(c->ids[i].index_b, i);
  }
}

TYPED_TEST(Chains, TiltedCapsulePointsLieOnItsSurface) {
  using T = TypeParam;
  using V = Vec2<T>;
  // The laws' counterexample of a first version, which pushed the capsule's core points straight
  // down by its radius: for a tilted capsule those lie inside it, not on its surface. Each point's
  // end on the capsule (point + normal * separation / 2) must lie one radius from its core.
  const ChainSegment<T> floor(V(3, 0), V(2, 0), V(-2, 0), V(-3, 0));
  const Capsule<T> tilted(V(-1, T(0.2)), V(1, T(0.6)), T(0.25));
  const auto c = contact(floor, tilted, T(1));  // within reach: the far end's point is kept too
  ASSERT_TRUE(c);
  ASSERT_EQ(c->count, 2);
  for (std::size_t i = 0; i < 2; ++i) {
    const Vec2c on_shape = widen(c->points[i]) + widen(c->normal) * (double(c->separations[i]) / 2);
    const Vec2c a = widen(tilted.a()), d = widen(tilted.b()) - a;
    const double t = std::clamp((on_shape - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    EXPECT_NEAR((a + d * t - on_shape).norm(), 0.25, 1e-5) << "point " << i;
  }
  EXPECT_NEAR(double(c->depth), 0.05, 1e-5);  // its lowest point, under the lower end
}

TYPED_TEST(Chains, SpeculativeContactsAlongTheChain) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Chain<T> floor({V(5, 0), V(4, 0), V(0, 0), V(-4, 0), V(-5, 0)}, false);
  // A ball half a unit above the floor: a speculative contact within reach, none without.
  const Circle<T> ball(V(2, T(1.5)), 1);
  std::vector<std::size_t> hit;
  for_each_contact(floor, ball, T(1), [&](std::size_t i, const Contact<T>& c) {
    hit.push_back(i);
    EXPECT_TRUE(is_up(c.normal));
    EXPECT_NEAR(double(c.separations[0]), 0.5, 1e-6);
  });
  EXPECT_EQ(hit, std::vector<std::size_t>{0});
  int touching = 0;
  for_each_contact(floor, ball, T(0), [&](std::size_t, const Contact<T>&) { ++touching; });
  EXPECT_EQ(touching, 0);
}

TYPED_TEST(Chains, ConvexCornerBelongsToOneSegment) {
  using T = TypeParam;
  using V = Vec2<T>;
  // A hill: the floor rises from the right, turns at (0, 0) (a left turn: convex) and falls.
  const Chain<T> hill({V(4, -4), V(2, -2), V(0, 0), V(-2, -2), V(-4, -4)}, false);
  ASSERT_EQ(hill.size(), 2u);
  // A circle right above the summit touches the corner: one contact, the normal straight up,
  // inside the arc between the two faces' normals.
  int contacts = 0;
  for_each_contact(hill, Circle<T>(V(0, T(0.9)), 1), T(0), [&](std::size_t i, const Contact<T>& c) {
    ++contacts;
    EXPECT_EQ(i, 0u);  // the arc belongs to the segment ending there
    EXPECT_NEAR(double(c.normal.x()), 0, 1e-6);
    EXPECT_NEAR(double(c.normal.y()), 1, 1e-6);
  });
  EXPECT_EQ(contacts, 1);
}

TYPED_TEST(Chains, ConcaveValleyGivesEachFaceItsNormal) {
  using T = TypeParam;
  using V = Vec2<T>;
  // A valley (right turn at the bottom: concave): a box pressed in touches both faces, each
  // along its own normal, never along the box's sides.
  const Chain<T> valley({V(4, 4), V(2, 2), V(0, 0), V(-2, 2), V(-4, 4)}, false);
  const T r = T(std::sqrt(0.5));
  std::vector<Vec2<T>> normals;
  for_each_contact(valley, Aabb<T>(V(-1, T(0.5)), V(1, 2)), T(0),
                   [&](std::size_t, const Contact<T>& c) { normals.push_back(c.normal); });
  ASSERT_EQ(normals.size(), 2u);
  EXPECT_NEAR(double(normals[0].x()), -r, 1e-6);
  EXPECT_NEAR(double(normals[0].y()), r, 1e-6);
  EXPECT_NEAR(double(normals[1].x()), r, 1e-6);
  EXPECT_NEAR(double(normals[1].y()), r, 1e-6);
}

TYPED_TEST(Chains, LoopIsHitFromOutsideOnly) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Chain<T> square({V(0, 0), V(4, 0), V(4, 4), V(0, 4)}, true);  // counter-clockwise
  int outside = 0, inside = 0;
  for_each_contact(square, Circle<T>(V(5, 2), T(1.5)), T(0), [&](std::size_t i, const Contact<T>& c) {
    ++outside;
    EXPECT_EQ(i, 1u);
    EXPECT_NEAR(double(c.normal.x()), 1, 1e-6);
  });
  for_each_contact(square, Circle<T>(V(3, 2), T(1.5)), T(0), [&](std::size_t, const Contact<T>&) { ++inside; });
  EXPECT_EQ(outside, 1);
  EXPECT_EQ(inside, 0);
}

/// One shape sliding over a row of unit tiles from x = 0 to 20: 1,000 steps of 0.0173 (not a
/// divisor of the tile width, so the seams are met at many phases), sunk into the floor by a
/// depth that varies from step to step as a solver leaves it (0 to 0.02). Returns the share of
/// contacts whose normal is not the floor's.
template <Scalar T, class MakeShape, class Contacts>
double ghost_share(MakeShape make_shape, Contacts contacts_of) {
  long contacts = 0, ghosts = 0, steps_held = 0;
  for (int step = 0; step < 1000; ++step) {
    const double x = 1.5 + 0.0173 * step;
    const double sink = 0.02 * double((step * 7) % 11) / 10;
    const long before = contacts;
    contacts_of(make_shape(T(x), T(-sink)), [&](const Contact<T>& c) {
      ++contacts;
      if (!is_up(c.normal)) ++ghosts;
    });
    if (contacts > before) ++steps_held;
  }
  EXPECT_EQ(steps_held, 1000);  // the floor held the shape at every step
  return double(ghosts) / double(contacts);
}

TYPED_TEST(Chains, SlidingOverTilesGivesNoGhostNormals) {
  using T = TypeParam;
  using V = Vec2<T>;
  std::vector<Aabb<T>> tiles;
  std::vector<V> points = {V(21, 0)};  // ghost continuing the floor
  for (int i = 20; i >= 0; --i) points.push_back(V(T(i), 0));
  points.push_back(V(-1, 0));  // ghost
  for (int i = 0; i < 20; ++i) tiles.emplace_back(V(T(i), -1), V(T(i + 1), 0));
  const Chain<T> floor = Chain<T>::make(points, false).value();
  // The shapes, each with its lowest point at height `bottom`.
  const auto box = [](T x, T bottom) { return Aabb<T>(V(x - T(0.5), bottom), V(x + T(0.5), bottom + 1)); };
  const auto obb = [](T x, T bottom) {
    return Obb<T>::make_with_axis(V(x, bottom + T(0.25)), V(T(0.5), T(0.25)), V(1, 0)).value();
  };
  const auto capsule = [](T x, T bottom) {
    return Capsule<T>(V(x - T(0.4), bottom + T(0.3)), V(x + T(0.4), bottom + T(0.3)), T(0.3));
  };
  const auto circle = [](T x, T bottom) { return Circle<T>(V(x, bottom + T(0.5)), T(0.5)); };
  const auto on_chain = [&](const auto& s, const auto& report) {
    for_each_contact(floor, s, T(0), [&](std::size_t, const Contact<T>& c) { report(c); });
  };
  const auto on_tiles = [&](const auto& s, const auto& report) {
    for (const Aabb<T>& t : tiles) {
      if (const auto c = contact(t, s)) report(*c);
    }
  };
  const double chain_box = ghost_share<T>(box, on_chain), tiles_box = ghost_share<T>(box, on_tiles);
  const double chain_obb = ghost_share<T>(obb, on_chain), tiles_obb = ghost_share<T>(obb, on_tiles);
  const double chain_capsule = ghost_share<T>(capsule, on_chain), tiles_capsule = ghost_share<T>(capsule, on_tiles);
  const double chain_circle = ghost_share<T>(circle, on_chain);
  std::printf(
      "ghost normals, chain / separate tiles: box %.3f / %.3f, obb %.3f / %.3f, capsule %.3f / %.3f, "
      "circle %.3f\n",
      chain_box, tiles_box, chain_obb, tiles_obb, chain_capsule, tiles_capsule, chain_circle);
  EXPECT_EQ(chain_box, 0);
  EXPECT_EQ(chain_obb, 0);
  EXPECT_EQ(chain_capsule, 0);
  EXPECT_EQ(chain_circle, 0);
  // The same slides over separate tiles catch their seams: the scene provokes ghosts.
  EXPECT_GT(tiles_box, 0);
  EXPECT_GT(tiles_obb, 0);
  EXPECT_GT(tiles_capsule, 0);
}

/// A floor of 20 unit tiles as one chain, running right to left (its front faces up), with a flat
/// ghost at each end.
template <Scalar T>
Chain<T> tile_floor() {
  std::vector<Vec2<T>> points = {Vec2<T>(21, 0)};
  for (int i = 20; i >= 0; --i) points.push_back(Vec2<T>(T(i), 0));
  points.push_back(Vec2<T>(-1, 0));
  return Chain<T>::make(points, false).value();
}

/// A box body (in its own frame, added before the floor, so its contacts are seen from it: normal
/// down) slid 1,000 steps over the floor by transforms, as ghost_share() slides it; the floor is
/// the tile chain, or 20 separate tile bodies. Returns the ghost contacts; expects contact at
/// every step, and none between chain segments.
template <Scalar T>
long world_slide_ghosts(bool chain) {
  using V = Vec2<T>;
  namespace bp = collide::broadphase;
  bp::World<T> world;
  const Shape<T> box = Obb<T>::make_with_axis(V(0, 0), V(T(0.5), T(0.25)), V(1, 0)).value();
  const bp::ProxyId body = world.add(box, Transform<T>::make_translation(V(T(1.5), T(0.24))).value());
  if (chain) {
    world.add(tile_floor<T>());
  } else {
    for (int i = 0; i < 20; ++i) world.add(Shape<T>(Aabb<T>(V(T(i), -1), V(T(i + 1), 0))));
  }
  long contacts = 0, ghosts = 0;
  for (int step = 0; step < 1000; ++step) {
    const double sink = 0.02 * double((step * 7) % 11) / 10;
    world.move(body, Transform<T>::make_translation(V(T(1.5 + 0.0173 * step), T(0.25 - sink))).value());
    world.step();
    long now = 0;
    world.for_each_contact([&](const bp::BodyContact<T>& c) {
      if (c.a != body) {
        EXPECT_FALSE(chain) << "two chain segments touched";  // separate tiles touch their neighbours
        return;
      }
      ++now;
      if (!is_up(Vec2<T>(-c.contact.normal))) ++ghosts;
    });
    EXPECT_GE(now, 1);
    contacts += now;
  }
  std::printf("World slide over %s: %ld contacts, %ld ghost normals\n", chain ? "a chain" : "separate tiles", contacts,
              ghosts);
  return ghosts;
}

TYPED_TEST(Chains, WorldBodiesSlideOverAChainWithoutGhosts) {
  using T = TypeParam;
  using V = Vec2<T>;
  namespace bp = collide::broadphase;
  EXPECT_EQ(world_slide_ghosts<T>(true), 0);
  EXPECT_GT(world_slide_ghosts<T>(false), 0);  // the slide provokes ghosts where the floor has seams
  bp::World<T> world;
  const bp::ProxyId body = world.add(Shape<T>(Circle<T>(V(3, 3), 1)));
  const std::vector<bp::ProxyId> floor = world.add(tile_floor<T>());
  ASSERT_EQ(floor.size(), 20u);
  ASSERT_NE(world.chain_segment(floor[3]), nullptr);
  EXPECT_EQ(world.chain_segment(body), nullptr);
  // A segment stays where it was added; set_shape() makes it an ordinary body.
  try {
    world.move(floor[0], Transform<T>::make_translation(V(0, 1)).value());
    ADD_FAILURE() << "a chain segment moved";
  } catch (const bp::BroadphaseError& e) {
    EXPECT_EQ(e.code(), bp::BroadphaseErrc::ChainMoved);
  }
  world.set_shape(floor[0], Shape<T>(Circle<T>(V(50, 50), 1)), Transform<T>());
  EXPECT_EQ(world.chain_segment(floor[0]), nullptr);
  // The queries meet a segment as the two-sided segment it is.
  int found = 0;
  world.query_point(V(T(10.5), 0), [&](bp::ProxyId id) { found += world.chain_segment(id) != nullptr; });
  EXPECT_EQ(found, 1);
}

TYPED_TEST(Chains, WorldChainAddedFirstAndCompoundBodies) {
  using T = TypeParam;
  using V = Vec2<T>;
  namespace bp = collide::broadphase;
  bp::World<T> world;
  world.add(tile_floor<T>());
  // A compound of two balls, turned by a quarter: each child meets the floor on its own.
  std::vector<Primitive<T>> kids;
  kids.emplace_back(Circle<T>(V(0, T(-0.5)), T(0.5)));
  kids.emplace_back(Circle<T>(V(0, T(0.5)), T(0.5)));
  const Shape<T> pair = Compound<T>(std::move(kids));
  const bp::ProxyId body = world.add(pair, Transform<T>::make_with_rotation(V(T(5.5), T(0.45)), V(0, 1)).value());
  world.step();
  int contacts = 0;
  world.for_each_contact([&](const bp::BodyContact<T>& c) {
    ++contacts;
    EXPECT_EQ(c.b, body);  // the chain came first: seen from the floor, normal up
    EXPECT_TRUE(is_up(c.contact.normal));
    EXPECT_NEAR(double(c.contact.depth), 0.05, 1e-5);
  });
  EXPECT_GE(contacts, 1);
  // The same body placed by the transform meets the chain's own contact() in world space.
  const auto direct =
      contact(tile_floor<T>().segment(14), pair, Transform<T>::make_with_rotation(V(T(5.5), T(0.45)), V(0, 1)).value());
  ASSERT_TRUE(direct);
  EXPECT_TRUE(is_up(direct->normal));
}

}  // namespace
}  // namespace collide::test
