// Unit tests of move_and_slide() (collide/broadphase/mover.hpp) on scenes whose answers are
// worked out by hand. Most use a skin of 1/64 (exact in float), so the stopping places are exact
// dyadic numbers: a circle of radius 1 moving right stops when its radius grown by the inflation
// (the skin, or half the gap to what it slides along) touches the wall.
//
// The scene: a wall [3, 4] x [-10, 10] (body 0) and a floor [-100, 100] x [-1, 0] (body 1).

#include "support.hpp"

#include <collide/broadphase.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace collide::test {
namespace {

namespace bp = collide::broadphase;

template <class T>
class Mover : public ::testing::Test {};
TYPED_TEST_SUITE(Mover, Scalars);

/// The wall-and-floor world, and the helpers every test uses.
template <Scalar T>
struct Scene {
  using V = Vec2<T>;
  bp::World<T> world;
  bp::ProxyId wall, floor;
  bp::MoveOptions<T> options;
  Scene() {
    wall = world.add(Aabb<T>(V(3, -10), V(4, 10)));
    floor = world.add(Aabb<T>(V(-100, -1), V(100, 0)));
    options.skin = T(1) / 64;
  }
  /// A circle of radius r centred at the origin of its frame.
  static Shape<T> ball(T r = 1) { return Circle<T>(V(0, 0), r); }
  static Transform<T> at(T x, T y) { return Transform<T>::make_translation(V(x, y)).value(); }
  bp::MoveResult<T> move(const Shape<T>& mover, T x, T y, V d) const {
    return bp::move_and_slide(world, mover, at(x, y), d, options);
  }
};

/// How far an answer may be from the worked one: the casts' tolerance (a hit may come up to a few
/// 2^-45 of the scene's scale, 100, early) and the rounding of T.
template <Scalar T>
double near() {
  return std::is_same_v<T, float> ? 1e-5 : 1e-10;
}

template <Scalar T>
void expect_at(const bp::MoveResult<T>& r, double x, double y) {
  EXPECT_NEAR(double(r.transform.position().x()), x, near<T>());
  EXPECT_NEAR(double(r.transform.position().y()), y, near<T>());
}

TYPED_TEST(Mover, HeadOnIntoAWallStopsASkinInFrontOfIt) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  // Centre at x = 3 - (1 + 1/64) = 1.984375 when the inflated circle touches the wall's face.
  const auto r = s.move(s.ball(), 0, 5, V(5, 0));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Blocked);
  expect_at(r, 1.984375, 5);
  EXPECT_LE(double(r.transform.position().x()), 1.984375 + r.rounding) << "never past the inflated contact";
  ASSERT_EQ(r.plane_count, 1u);
  EXPECT_EQ(r.planes[0].body, s.wall);
  EXPECT_FALSE(r.planes[0].resting);
  EXPECT_NEAR(double(r.planes[0].normal.x()), 1, near<T>());
  EXPECT_NEAR(double(r.planes[0].normal.y()), 0, near<T>());
  EXPECT_NEAR(double(r.planes[0].point.x()), 3, near<T>()) << "where the grown circle meets the face";
  EXPECT_EQ(r.path_count, 2u) << "one leg, which ends at the hit";
  EXPECT_EQ(r.skin, 1.0 / 64);
  EXPECT_EQ(r.displacement, V(r.transform.position() - V(0, 5)));
}

TYPED_TEST(Mover, AtAnAngleIntoAWallSlidesAlongItByTheTangentialPart) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  // Hit at t = 1.984375 / 5 = 0.396875, at y = 5 + 2 t = 5.79375; the rest (3.015625, 1.20625)
  // loses its part along the wall's normal and goes on up by 1.20625: y = 7, the whole 2.
  const auto r = s.move(s.ball(), 0, 5, V(5, 2));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Completed);
  expect_at(r, 1.984375, 7);
  ASSERT_EQ(r.path_count, 3u);
  EXPECT_NEAR(double(r.path[1].y()), 5.79375, near<T>());
  ASSERT_EQ(r.plane_count, 1u);
  EXPECT_EQ(r.planes[0].body, s.wall);
}

TYPED_TEST(Mover, OneIterationStopsAtTheFirstHitWithDisplacementLeft) {
  using T = TypeParam;
  using V = Vec2<T>;
  Scene<T> s;
  s.options.max_iterations = 1;
  const auto r = s.move(s.ball(), 0, 5, V(5, 2));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::IterationLimit);
  expect_at(r, 1.984375, 5.79375);
}

TYPED_TEST(Mover, RestingOnTheFloorLiftsBySkinAndSlidesTheRest) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  // Touching the floor: a resting contact. The move lifts off it by the skin (1/64), which it
  // spends from its length, and slides the rest: x = 1.5 - 1/64, y = 1 + 1/64.
  const auto r = s.move(s.ball(), 0, 1, V(T(1.5), 0));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Completed);
  expect_at(r, 1.484375, 1.015625);
  ASSERT_EQ(r.plane_count, 1u);
  EXPECT_TRUE(r.planes[0].resting);
  EXPECT_EQ(r.planes[0].body, s.floor);
  EXPECT_NEAR(double(r.planes[0].normal.y()), -1, near<T>()) << "from the mover toward the floor";
  EXPECT_EQ(r.path_count, 3u) << "start, lift, slide";
}

TYPED_TEST(Mover, JustAboveTheFloorItMovesByExactlyTheDisplacement) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  // Half a unit above the floor: no resting contact; the floor is cast with an inflation of at
  // most half the gap, and a motion parallel to it never meets it.
  const auto r = s.move(s.ball(), 0, T(1.5), V(T(1.5), 0));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Completed);
  EXPECT_EQ(r.transform.position(), V(T(1.5), T(1.5)));
  EXPECT_EQ(r.plane_count, 0u);
}

TYPED_TEST(Mover, SlidesOverTheSeamsOfARowOfFlushTiles) {
  using T = TypeParam;
  using V = Vec2<T>;
  bp::World<T> world;
  for (int i = -4; i < 12; ++i) world.add(Aabb<T>(V(T(i), -1), V(T(i + 1), 0)));
  bp::MoveOptions<T> options;
  options.skin = T(1) / 64;
  // A circle touching tile [0, 1] (its neighbours' corners are 0.118 away): lift 1/64, then six
  // tiles' worth of seams without a hit.
  const auto r = bp::move_and_slide(world, Shape<T>(Circle<T>(V(0, 0), 1)), Scene<T>::at(T(0.5), 1), V(6, 0), options);
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Completed);
  expect_at(r, 6.484375, 1.015625);
  ASSERT_EQ(r.plane_count, 1u) << "the resting contact only: no seam was hit";
  // A level capsule resting on two tiles at once, moving left across five seams.
  const auto c = bp::move_and_slide(world, Shape<T>(Capsule<T>(V(T(-0.5), 0), V(T(0.5), 0), T(0.5))),
                                    Scene<T>::at(1, T(0.5)), V(-3, 0), options);
  EXPECT_EQ(c.outcome, bp::MoveOutcome::Completed);
  expect_at(c, -1.984375, 0.515625);
  ASSERT_EQ(c.plane_count, 2u) << "two resting contacts, no hit";
  EXPECT_TRUE(c.planes[0].resting && c.planes[1].resting);
}

TYPED_TEST(Mover, PressingIntoTheFloorIsBlockedAndMovesNothing) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  const auto r = s.move(s.ball(), 0, 1, V(0, -1));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Blocked);
  EXPECT_EQ(r.transform, Scene<T>::at(0, 1));
  EXPECT_EQ(r.path_count, 1u);
  EXPECT_EQ(r.displacement, V(0, 0));
}

TYPED_TEST(Mover, FallingOntoTheFloorStopsASkinAboveIt) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  const auto r = s.move(s.ball(), 0, 3, V(0, -5));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Blocked);
  expect_at(r, 0, 1.015625);
}

TYPED_TEST(Mover, IntoTheCornerItSlidesAlongTheFloorThenStopsAtTheWall) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  // The floor first, at t = (3 - 1.015625) / 5 = 0.396875 and x = 1.5875; then along it, 1/64
  // above it, with an inflation of that gap less the margin m (a few roundings, below 1e-4): the
  // wall stops the centre at x = 3 - 1 - (1/64 - m), and both planes together leave no way on.
  const auto r = s.move(s.ball(), 0, 3, V(4, -5));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Blocked);
  EXPECT_NEAR(double(r.transform.position().y()), 1.015625, near<T>());
  EXPECT_GE(double(r.transform.position().x()), 1.984375 - near<T>());
  EXPECT_LE(double(r.transform.position().x()), 1.984375 + 1e-4);
  ASSERT_EQ(r.plane_count, 2u);
  EXPECT_EQ(r.planes[0].body, s.floor);
  EXPECT_EQ(r.planes[1].body, s.wall);
  EXPECT_NEAR(double(r.path[1].x()), 1.5875, near<T>());
}

TYPED_TEST(Mover, AnUprightCapsuleStopsAtTheWallByItsRadius) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  const Shape<T> capsule = Capsule<T>(V(0, T(-0.5)), V(0, T(0.5)), T(0.5));
  const auto r = s.move(capsule, 0, 5, V(5, 0));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Blocked);
  expect_at(r, 2.484375, 5);
  // Turned a quarter turn by its transform (lying level), the same capsule stops 0.5 earlier.
  const Transform<T> level = Transform<T>::make_with_rotation(V(0, 5), V(0, 1)).value();
  const auto l = bp::move_and_slide(s.world, capsule, level, V(5, 0), s.options);
  expect_at(l, 1.984375, 5);
  EXPECT_EQ(l.transform.rotation(), V(0, 1)) << "the rotation is kept bit for bit";
}

TYPED_TEST(Mover, AThinWallStopsAFastMoverInsteadOfLettingItThrough) {
  using T = TypeParam;
  using V = Vec2<T>;
  bp::World<T> world;
  world.add(Aabb<T>(V(0, -5), V(T(0.01), 5)));
  const auto r = bp::move_and_slide(world, Shape<T>(Circle<T>(V(0, 0), T(0.1))), Scene<T>::at(-10, 0), V(20, 0));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Blocked);
  const double x = double(r.transform.position().x());
  EXPECT_LT(x, -0.1) << "in front of the wall";
  EXPECT_GT(x, -0.1 - r.skin - 1e-5) << "a skin in front of it, up to the cast's tolerance";
  EXPECT_GT(r.skin, 0);
  // 64 rho, rho = 4 eps_T (10.1 + 20): about 9e-4 in float; in double the cast tolerance leads.
  const double few_roundings = std::is_same_v<T, float> ? 1e-3 : 1e-9;
  EXPECT_LT(r.skin, few_roundings) << "the automatic skin is a few hundred roundings";
}

TYPED_TEST(Mover, TheAutomaticSkinLiftsARestingMoverByNoMoreThanIt) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  const auto r = bp::move_and_slide(s.world, s.ball(), Scene<T>::at(0, 1), V(T(1.5), 0));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Completed);
  const double rise = double(r.transform.position().y()) - 1;
  EXPECT_GT(rise, 0) << "lifted off the floor it touched";
  EXPECT_LE(rise, r.skin + 3 * r.rounding);
  EXPECT_NEAR(double(r.transform.position().x()), 1.5, r.skin + 3 * r.rounding);
}

TYPED_TEST(Mover, IgnoredAndFilteredBodiesDoNotBlock) {
  using T = TypeParam;
  using V = Vec2<T>;
  bp::World<T> world;
  const bp::ProxyId self = world.add(Shape<T>(Circle<T>(V(0, 0), 1)), Scene<T>::at(-10, 5));  // the character's body
  world.add(Aabb<T>(V(-7, 0), V(-6, 10)), 0, bp::Filter{2, 0xffffffffu});                     // a trigger zone
  const bp::ProxyId wall = world.add(Aabb<T>(V(3, -10), V(4, 10)));
  const Shape<T> ball = Circle<T>(V(0, 0), 1);
  bp::MoveOptions<T> options;
  options.skin = T(1) / 64;
  options.filter = bp::Filter{1, 1};  // bodies of category 1 block
  const std::vector<bp::ProxyId> own{self};
  options.ignore = own;
  const auto r = bp::move_and_slide(world, ball, Scene<T>::at(-10, 5), V(20, 0), options);
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Blocked);
  expect_at(r, 1.984375, 5);
  ASSERT_EQ(r.plane_count, 1u);
  EXPECT_EQ(r.planes[0].body, wall);
  // Not ignored, its own body (the same circle, overlapping it wholly) is a resting contact whose
  // normal, (1, 0) for coincident centres, takes the whole displacement.
  options.ignore = {};
  const auto stuck = bp::move_and_slide(world, ball, Scene<T>::at(-10, 5), V(20, 0), options);
  EXPECT_EQ(stuck.outcome, bp::MoveOutcome::Blocked);
  EXPECT_EQ(stuck.transform.position(), V(-10, 5));
  ASSERT_EQ(stuck.plane_count, 1u);
  EXPECT_EQ(stuck.planes[0].body, self);
  EXPECT_TRUE(stuck.planes[0].resting);
}

TYPED_TEST(Mover, StartingDeepInABodyItIsNotPushedOutButNeverGoesDeeper) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  // Half sunk into the floor: a resting contact. The lift (1/64) goes across the displacement
  // d = (1.5, -0.25), |d| = sqrt(2.3125), along (0.25, 1.5) / |d|, and does not get it out; the
  // rest, |d| - 1/64 along d, loses its part into the floor: never down.
  const auto r = s.move(s.ball(), 0, T(0.5), V(T(1.5), T(-0.25)));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Completed);
  const double len = std::sqrt(2.3125), lift = 1.0 / 64;
  expect_at(r, (lift * 0.25 + (len - lift) * 1.5) / len, 0.5 + lift * 1.5 / len);
  EXPECT_TRUE(overlaps(s.ball(), r.transform, Shape<T>(Aabb<T>(V(-100, -1), V(100, 0))), Transform<T>()));
}

TYPED_TEST(Mover, NoDisplacementMovesNothing) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Scene<T> s;
  const auto r = s.move(s.ball(), 0, 5, V(0, 0));
  EXPECT_EQ(r.outcome, bp::MoveOutcome::Completed);
  EXPECT_EQ(r.transform, Scene<T>::at(0, 5));
  EXPECT_EQ(r.path_count, 1u);
  EXPECT_EQ(r.positions().size(), 1u);
  EXPECT_TRUE(r.contacts().empty());
}

TYPED_TEST(Mover, BadInputIsNamedAndMovesNothing) {
  using T = TypeParam;
  using V = Vec2<T>;
  Scene<T> s;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const auto refused = [&](const bp::MoveResult<T>& r, bp::MoveOutcome why) {
    EXPECT_EQ(r.outcome, why);
    EXPECT_EQ(r.transform, Scene<T>::at(0, 5));
    EXPECT_EQ(r.displacement, V(0, 0));
    EXPECT_EQ(r.path_count, 1u);
    EXPECT_EQ(r.plane_count, 0u);
  };
  refused(s.move(s.ball(), 0, 5, V(nan, 0)), bp::MoveOutcome::InvalidInput);
  refused(s.move(s.ball(), 0, 5, V(0, inf)), bp::MoveOutcome::InvalidInput);
  refused(s.move(s.ball(), 0, 5, V(max_magnitude<T>(), 0)), bp::MoveOutcome::InvalidInput);
  refused(s.move(Aabb<T>(V(-1, -1), V(1, 1)), 0, 5, V(1, 0)), bp::MoveOutcome::UnsupportedMover);
  refused(s.move(make_kind<ShapeKind::Compound, T>(V(0, 0), 1), 0, 5, V(1, 0)), bp::MoveOutcome::UnsupportedMover);
  for (const int n : {0, bp::kMoveMaxIterations + 1}) {
    s.options.max_iterations = n;
    refused(s.move(s.ball(), 0, 5, V(1, 0)), bp::MoveOutcome::InvalidInput);
  }
  s.options.max_iterations = bp::kMoveMaxIterations;
  for (const T skin : {T(-1), nan, inf}) {
    s.options.skin = skin;
    refused(s.move(s.ball(), 0, 5, V(1, 0)), bp::MoveOutcome::InvalidInput);
  }
  EXPECT_EQ(bp::name(bp::MoveOutcome::InvalidInput), "InvalidInput");
  EXPECT_EQ(bp::name(bp::MoveOutcome::UnsupportedMover), "UnsupportedMover");
  EXPECT_EQ(bp::name(bp::MoveOutcome::Completed), "Completed");
}

}  // namespace
}  // namespace collide::test
