// Shape casts and time of impact: the cases games complain about (a bullet through a thin wall,
// a box sliding along flat ground, casts that start in contact, no motion), every pair of kinds
// against a contact time known exactly, and the motion of time_of_impact() with rotation.

#include "support.hpp"

#include <collide/cast.hpp>
#include <collide/time_of_impact.hpp>

#include <cmath>
#include <limits>
#include <numbers>

namespace collide::test {
namespace {

template <class T>
class Cast : public ::testing::Test {};
TYPED_TEST_SUITE(Cast, Scalars);

/// a moved by v (rounded to T), or a itself when the move is not representable.
template <class S, Scalar T>
S moved_by(const S& a, const Vec2<T>& v) {
  return translated(a, v).value();
}

/// The shapes at time t of the cast, widened to double and moved there (each move rounded once
/// in double: far below the cast's target separation).
template <class S>
auto as_double(const S& s) {
  if constexpr (std::is_same_v<scalar_of_t<S>, double>) {
    return s;
  } else {
    return widened(s);
  }
}

template <class A, class B, Scalar T>
bool overlap_at(const A& a, const Vec2<T>& va, const B& b, const Vec2<T>& vb, double t) {
  return overlaps(moved_by(as_double(a), Vec2<double>(widen(va) * t)),
                  moved_by(as_double(b), Vec2<double>(widen(vb) * t)));
}

TYPED_TEST(Cast, BulletDoesNotTunnelThroughThinWall) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> bullet(V(-10, 0), T(0.0625));
  const Aabb<T> wall(V(0, -5), V(T(0.0078125), 5));
  const V v(2000, 0);  // 20 units per frame at t in [0, 1]: the wall is 1/2560 of a frame thick
  const CastResult<T> r = shape_cast(bullet, v, wall, V(0, 0), T(1));
  ASSERT_EQ(r.outcome, CastOutcome::Hit);
  const double exact = (10 - 0.0625) / 2000.0;  // the first contact
  EXPECT_LE(double(r.t), exact);
  EXPECT_GE(double(r.t), exact - cast_tolerance(bullet, v, wall, V(0, 0), T(1)) / 2000.0);
  EXPECT_NEAR(double(r.normal.x()), 1.0, 1e-6);
  EXPECT_NEAR(double(r.normal.y()), 0.0, 1e-6);
  EXPECT_NEAR(double(r.point.x()), 0.0, 1e-3);
  // Stepping by whole frames would have missed: the bullet is apart from the wall at both ends.
  EXPECT_FALSE(overlaps(bullet, wall));
  EXPECT_FALSE(overlap_at(bullet, v, wall, V(0, 0), 1.0));
  EXPECT_FALSE(overlap_at(bullet, v, wall, V(0, 0), double(r.t)));
}

TYPED_TEST(Cast, CircleGrazingACornerReachesItsDiscInOneStep) {
  using T = TypeParam;
  using V = Vec2<T>;
  // The circle passes the box's top-left corner 0.25 below the height where it would clear it:
  // the face step brings it level with the left face, beside the corner, and the corner's disc
  // is then one step away, where steps along the closest points' direction shrink geometrically.
  const Aabb<T> box(V(-1, -1), V(1, 1));
  const Circle<T> ball(V(-5, T(1.25)), T(0.5));
  const V v(10, 0);
  const CastResult<T> r = shape_cast(ball, v, box, V(0, 0), T(1));
  ASSERT_EQ(r.outcome, CastOutcome::Hit);
  EXPECT_LE(r.iterations, 1);
  const double exact = (4 - std::sqrt(0.1875)) / 10;  // |centre - corner| = 0.5
  EXPECT_LE(double(r.t), exact);
  // The gap closes at 10 * 0.866 per unit time there: within the tolerance, t is that close.
  EXPECT_GE(double(r.t), exact - cast_tolerance(ball, v, box, V(0, 0), T(1)) / 8);
  EXPECT_NEAR(double(r.normal.x()), std::sqrt(0.75), 1e-5);
  EXPECT_NEAR(double(r.normal.y()), -0.5, 1e-5);
  EXPECT_FALSE(overlap_at(ball, v, box, V(0, 0), double(r.t)));
}

TYPED_TEST(Cast, BoxSlidingAlongFlatGroundHasAnAnswer) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> ground(V(-50, -1), V(50, 0));
  const V slide(5, 0);
  // Resting on the ground (touching): t = 0, normal from the box down into the ground.
  const Obb<T> box = Obb<T>::make_with_axis(V(0, T(0.5)), V(T(0.5), T(0.5)), V(1, 0)).value();
  const CastResult<T> touching = shape_cast(box, slide, ground, V(0, 0), T(1));
  ASSERT_EQ(touching.outcome, CastOutcome::Hit);
  EXPECT_EQ(touching.t, T(0));
  EXPECT_NEAR(double(touching.normal.y()), -1.0, 1e-6);
  EXPECT_TRUE(std::isfinite(touching.point.x()) && std::isfinite(touching.point.y()));
  // Hovering just above it, sliding parallel: a miss, found in one step.
  const Obb<T> hover = Obb<T>::make_with_axis(V(0, T(0.5009765625)), V(T(0.5), T(0.5)), V(1, 0)).value();
  const CastResult<T> parallel = shape_cast(hover, slide, ground, V(0, 0), T(1));
  EXPECT_EQ(parallel.outcome, CastOutcome::Miss);
  EXPECT_EQ(parallel.t, T(1));
  EXPECT_LE(parallel.iterations, 2);
  // Sinking slowly while sliding: hits when the gap closes (0.0009765625 at 0.01 per unit time).
  const CastResult<T> sinking = shape_cast(hover, V(5, T(-0.01)), ground, V(0, 0), T(1));
  ASSERT_EQ(sinking.outcome, CastOutcome::Hit);
  EXPECT_LE(double(sinking.t), 0.09765625);
  EXPECT_GE(double(sinking.t), 0.0976);
  EXPECT_NEAR(double(sinking.normal.y()), -1.0, 1e-6);
}

TYPED_TEST(Cast, StartingInContactHitsAtZeroWithTheContactNormal) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> a(V(0, 0), 1);
  const Circle<T> touching(V(2, 0), 1), deep(V(T(0.5), 0), 1);
  for (const Circle<T>& b : {touching, deep}) {
    for (const V& va : {V(1, 0), V(-1, 0), V(0, 0)}) {
      const CastResult<T> r = shape_cast(a, va, b, V(0, 0), T(1));
      ASSERT_EQ(r.outcome, CastOutcome::Hit);
      EXPECT_EQ(r.t, T(0));
      const auto c = contact(a, b);
      ASSERT_TRUE(c.has_value());
      EXPECT_EQ(r.normal, c->normal);
      EXPECT_EQ(r.point, c->points[0]);
    }
  }
}

TYPED_TEST(Cast, ZeroRelativeVelocity) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Capsule<T> a(V(0, 0), V(1, 0), T(0.25));
  const ConvexPolygon<T> b{V(3, 0), V(4, 0), V(3, 1)};
  // Both still, and both moving together: apart for ever.
  for (const V& v : {V(0, 0), V(7, -3)}) {
    const CastResult<T> r = shape_cast(a, v, b, v, T(10));
    EXPECT_EQ(r.outcome, CastOutcome::Miss);
    EXPECT_EQ(r.t, T(10));
  }
  const CastResult<T> still = shape_cast(a, V(0, 0), a, V(0, 0), T(10));
  EXPECT_EQ(still.outcome, CastOutcome::Hit);
  EXPECT_EQ(still.t, T(0));
}

TYPED_TEST(Cast, BadInputIsNamed) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> a(V(0, 0), 1), b(V(5, 0), 1);
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_EQ(shape_cast(a, V(nan, 0), b, V(0, 0), T(1)).outcome, CastOutcome::InvalidInput);
  EXPECT_EQ(shape_cast(a, V(0, 0), b, V(0, inf), T(1)).outcome, CastOutcome::InvalidInput);
  EXPECT_EQ(shape_cast(a, V(1, 0), b, V(0, 0), T(-1)).outcome, CastOutcome::InvalidInput);
  EXPECT_EQ(shape_cast(a, V(1, 0), b, V(0, 0), inf).outcome, CastOutcome::InvalidInput);
  EXPECT_EQ(shape_cast(a, V(max_magnitude<T>(), 0), b, V(0, 0), T(4)).outcome, CastOutcome::InvalidInput);
  Sweep<T> bad;
  bad.a1 = nan;
  EXPECT_EQ(time_of_impact(a, bad, b, Sweep<T>{}, T(1)).outcome, CastOutcome::InvalidInput);
  EXPECT_EQ(time_of_impact(a, Sweep<T>{}, b, Sweep<T>{}, T(2)).outcome, CastOutcome::InvalidInput);
}

/// Every pair: shapes of half width h, centres 8h apart on the x axis, closing at speed 3 each
/// way; the extreme points sit on the axis, so the first contact is exactly at (8h - 2h) / 6.
template <ShapeKind KA, ShapeKind KB, Scalar T>
void check_pair_contact_time() {
  using V = Vec2<T>;
  const T h = T(0.75);
  const auto a = make_kind<KA, T>(V(-4 * h, 1), h);
  const auto b = make_kind<KB, T>(V(4 * h, 1), h);
  const V va(3, 0), vb(-3, 0);
  const double exact = 6 * double(h) / 6.0;
  const std::string label = pair_label<KA, KB>();
  const CastResult<T> r = shape_cast(a, va, b, vb, T(4));
  ASSERT_EQ(r.outcome, CastOutcome::Hit) << label;
  EXPECT_LE(double(r.t), exact) << label;
  EXPECT_GE(double(r.t), exact - cast_tolerance(a, va, b, vb, T(4)) / 6.0) << label;
  EXPECT_NEAR(double(r.normal.x()), 1.0, 1e-6) << label;
  EXPECT_FALSE(overlap_at(a, va, b, vb, double(r.t))) << label;
  // Swapped: the same time to the bit and the reversed normal.
  const CastResult<T> s = shape_cast(b, vb, a, va, T(4));
  EXPECT_EQ(s.t, r.t) << label;
  EXPECT_EQ(s.normal, Vec2<T>(-r.normal)) << label;
  // Only the relative motion matters.
  const CastResult<T> rel = shape_cast(a, V(va - vb), b, V(0, 0), T(4));
  EXPECT_EQ(rel.t, r.t) << label;
  // Stopping short of the contact is a miss.
  EXPECT_EQ(shape_cast(a, va, b, vb, T(0.5) * T(exact)).outcome, CastOutcome::Miss) << label;
}

TYPED_TEST(Cast, EveryPairMeetsAtTheKnownTime) {
  using T = TypeParam;
  for_each_pair([]<ShapeKind A, ShapeKind B>() {
    check_pair_contact_time<A, B, T>();
    check_pair_contact_time<B, A, T>();
  });
}

TYPED_TEST(Cast, SpinningStickHitsWhatItsTranslationMisses) {
  using T = TypeParam;
  using V = Vec2<T>;
  // A stick of half length 2 turning a quarter turn about its centre; a small ball at (0, 1.5).
  const Obb<T> stick = Obb<T>::make_with_axis(V(0, 0), V(2, T(0.05)), V(1, 0)).value();
  const Circle<T> ball(V(0, T(1.5)), T(0.1));
  Sweep<T> turn;
  turn.a1 = T(std::numbers::pi / 2);
  Sweep<T> still;
  const CastResult<T> r = time_of_impact(stick, turn, ball, still, T(1));
  ASSERT_EQ(r.outcome, CastOutcome::Hit);
  // The stick's upper edge reaches the ball's lowest point when sin(angle) ~ (1.4 - 0.05) / 2...
  // roughly; the exact check: at t the posed stick is apart from the ball, at a slightly later
  // time it is not.
  auto stick_at = [&](double s) {
    const SweepPose p = sweep_pose(turn, s);
    return Obb<double>::make_with_axis(p.position, Vec2<double>(2, double(T(0.05))), p.rotation).value();
  };
  const Circle<double> ball_d(Vec2<double>(0, double(T(1.5))), double(T(0.1)));
  EXPECT_FALSE(overlaps(stick_at(double(r.t)), ball_d));
  EXPECT_TRUE(overlaps(stick_at(std::min(1.0, double(r.t) + 1e-3)), ball_d));
  EXPECT_GT(r.t, T(0.5));
  // Without the rotation the stick never reaches the ball.
  EXPECT_EQ(time_of_impact(stick, still, ball, still, T(1)).outcome, CastOutcome::Miss);
  // The swapped query: same time, reversed normal.
  const CastResult<T> s = time_of_impact(ball, still, stick, turn, T(1));
  EXPECT_EQ(s.t, r.t);
  EXPECT_EQ(s.normal, Vec2<T>(-r.normal));
}

TYPED_TEST(Cast, TimeOfImpactWithoutRotationAgreesWithTheCast) {
  using T = TypeParam;
  using V = Vec2<T>;
  const ConvexPolygon<T> tri{V(0, 0), V(1, 0), V(0, 1)};
  const Aabb<T> wall(V(5, -3), V(6, 3));
  Sweep<T> move;
  move.c1 = V(8, 0);
  const CastResult<T> toi = time_of_impact(tri, move, wall, Sweep<T>{}, T(1));
  const CastResult<T> cast = shape_cast(tri, V(8, 0), wall, V(0, 0), T(1));
  ASSERT_EQ(toi.outcome, CastOutcome::Hit);
  ASSERT_EQ(cast.outcome, CastOutcome::Hit);
  EXPECT_LE(double(toi.t), 0.5);
  EXPECT_LE(double(cast.t), 0.5);
  EXPECT_NEAR(double(toi.t), 0.5, 1e-5);
  EXPECT_NEAR(double(cast.t), 0.5, 1e-5);
}

TYPED_TEST(Cast, TimeOfImpactOfBodiesThatDoNotTurnReachesACornerDiscInOneStep) {
  using T = TypeParam;
  using V = Vec2<T>;
  // The ball of CircleGrazingACornerReachesItsDiscInOneStep, its body held at a fixed angle
  // (a1 == a0) with its centre of rotation off the ball's, passing the top-left corner of a box
  // that comes toward it: neither body turns, so the pair is a translation and the corner's disc
  // is one step away, where the bounds for turning bodies shrink their steps geometrically.
  const Circle<T> ball(V(0, 0), T(0.5));
  const Aabb<T> box(V(-1, -1), V(1, 1));
  const T angle = T(0.75);
  const Sweep<T> sa{V(T(0.25), T(-0.125)), V(T(-4.75), T(1.375)), V(T(3.25), T(1.375)), angle, angle};
  const Sweep<T> sb{V(0, 0), V(3, 0), V(1, 0), T(0), T(0)};
  // The ball's centre: the body's centre minus the turned local centre, moving by (8, 0); the
  // box's top-left corner starts at (2, 1) and moves by (-2, 0).
  const SweepPose start = sweep_pose(sa, 0);
  const double cx = start.position.x(), cy = start.position.y();
  const double exact = (2 - cx - std::sqrt(0.25 - (cy - 1) * (cy - 1))) / 10;  // first contact
  for (const bool swapped : {false, true}) {
    const CastResult<T> r = swapped ? time_of_impact(box, sb, ball, sa, T(1)) : time_of_impact(ball, sa, box, sb, T(1));
    ASSERT_EQ(r.outcome, CastOutcome::Hit);
    EXPECT_LE(r.iterations, 1);
    EXPECT_LE(double(r.t), exact);
    EXPECT_GE(double(r.t), exact - toi_tolerance(ball, sa, box, sb, T(1)) / 8);
    // At the corner: the normal from the ball's centre to it, the point on it, both at t.
    const Vec2<double> centre(cx + 8 * double(r.t), cy), corner(2 - 2 * double(r.t), 1);
    const Vec2<double> n = (corner - centre).normalized() * (swapped ? -1.0 : 1.0);
    EXPECT_NEAR(double(r.normal.x()), n.x(), 1e-5);
    EXPECT_NEAR(double(r.normal.y()), n.y(), 1e-5);
    EXPECT_NEAR(double(r.point.x()), corner.x(), 1e-5);
    EXPECT_NEAR(double(r.point.y()), corner.y(), 1e-5);
  }
}

TYPED_TEST(Cast, TimeOfImpactOfABodyHeldTurnedStepsByItsTurnedFaces) {
  using T = TypeParam;
  using V = Vec2<T>;
  // A box held at 0.6 rad (a1 == a0) moves along its own turned axis u into a still ball on that
  // axis: its face +u meets the ball head-on. That face, turned to the pose, bounds the first step
  // to the contact exactly, so the hit takes no second step and its normal is u.
  const Aabb<T> box(V(-1, T(-0.5)), V(1, T(0.5)));
  const Circle<T> ball(V(0, 0), T(0.25));
  const T angle = T(0.6);
  const Vec2<double> u(std::cos(double(angle)), std::sin(double(angle)));
  const Sweep<T> sa{V(0, 0), V(0, 0), V(T(4 * u.x()), T(4 * u.y())), angle, angle};
  const Sweep<T> sb{V(0, 0), V(T(3 * u.x()), T(3 * u.y())), V(T(3 * u.x()), T(3 * u.y())), T(0), T(0)};
  for (const bool swapped : {false, true}) {
    const CastResult<T> r = swapped ? time_of_impact(ball, sb, box, sa, T(1)) : time_of_impact(box, sa, ball, sb, T(1));
    ASSERT_EQ(r.outcome, CastOutcome::Hit);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_NEAR(double(r.t), 1.75 / 4, 1e-5);
    const Vec2<double> n = widen(r.normal) * (swapped ? -1.0 : 1.0);
    EXPECT_NEAR(n.x(), u.x(), 1e-5);
    EXPECT_NEAR(n.y(), u.y(), 1e-5);
  }
}

}  // namespace
}  // namespace collide::test

namespace collide::test {
namespace {

// Regressions found by the cast property suite.

/// Distance from p to s moved by v * t (in double).
template <class S>
double distance_at(const Vec2<double>& p, const S& s, const Vec2<double>& v, double t) {
  return distance(Circle<double>(p, 0), translated(s, Vec2<double>(v * t)).value());
}

TYPED_TEST(Cast, PlacedBulletStopsAtTheTurnedWall) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Stored in local frames: a wall lying along x, turned upright by a quarter turn and placed at
  // x = 10 (world x in [9.75, 10.25]); a ball at its local origin, placed at (-10, 0) by a
  // rounded rotation (which does not move its centre).
  const Aabb<T> wall(V(-5, T(-0.25)), V(5, T(0.25)));
  const Circle<T> ball(V(0, 0), T(0.5));
  const Transform<T> xw = Transform<T>::make_with_rotation(V(10, 0), V(0, 1)).value();
  const Transform<T> xb(V(-10, 0), T(0.7));
  const V v(100, 0), still(0, 0);
  const CastResult<T> r = shape_cast(ball, xb, v, wall, xw, still, T(1));
  ASSERT_EQ(r.outcome, CastOutcome::Hit);
  const double exact = (9.75 - (-10 + 0.5)) / 100;
  const double eps = cast_tolerance(ball, xb, v, wall, xw, still, T(1));
  EXPECT_LE(double(r.t), exact);
  EXPECT_GE(double(r.t), exact - eps / 100);
  EXPECT_NEAR(double(r.normal.x()), 1.0, 1e-6);
  EXPECT_NEAR(double(r.point.x()), 9.75, 1e-3);
  // The same shapes built in world space meet at the same time, within both tolerances.
  const Aabb<T> world_wall(V(T(9.75), -5), V(T(10.25), 5));
  const Circle<T> world_ball(V(-10, 0), T(0.5));
  const CastResult<T> w = shape_cast(world_ball, v, world_wall, still, T(1));
  ASSERT_EQ(w.outcome, CastOutcome::Hit);
  EXPECT_NEAR(double(w.t), double(r.t), (eps + cast_tolerance(world_ball, v, world_wall, still, T(1))) / 100);
  // Swapped, and seen as relative motion: the same t to the bit, the normal reversed.
  const CastResult<T> s = shape_cast(wall, xw, still, ball, xb, v, T(1));
  EXPECT_EQ(s.t, r.t);
  EXPECT_EQ(s.normal, V(-r.normal));
  const CastResult<T> rel = shape_cast(ball, xb, V(v - V(3, 0)), wall, xw, V(-3, 0), T(1));
  EXPECT_EQ(rel.t, r.t);
  // Stopping short is a miss; starting against the wall is a hit at t = 0.
  EXPECT_EQ(shape_cast(ball, xb, v, wall, xw, still, T(0.125)).outcome, CastOutcome::Miss);
  const Transform<T> against = Transform<T>::make_translation(V(T(9.25), 3)).value();
  const CastResult<T> start = shape_cast(ball, against, v, wall, xw, still, T(1));
  EXPECT_EQ(start.outcome, CastOutcome::Hit);
  EXPECT_EQ(start.t, T(0));
}

TYPED_TEST(Cast, IdentityTransformsAreTheWorldSpaceCast) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Capsule<T> a(V(0, 0), V(1, 0), T(0.25));
  const ConvexPolygon<T> b{V(3, 0), V(4, 0), V(3, 1)};
  const Transform<T> id;
  for (const V& va : {V(3, 0), V(3, T(0.5)), V(0, 1)}) {
    const CastResult<T> w = shape_cast(a, va, b, V(0, 0), T(2));
    const CastResult<T> p = shape_cast(a, id, va, b, id, V(0, 0), T(2));
    EXPECT_EQ(p.outcome, w.outcome);
    EXPECT_EQ(p.t, w.t);
    EXPECT_EQ(p.normal, w.normal);
    EXPECT_EQ(p.point, w.point);
    EXPECT_EQ(cast_tolerance(a, id, va, b, id, V(0, 0), T(2)), cast_tolerance(a, va, b, V(0, 0), T(2)));
  }
}

TYPED_TEST(Cast, PlacedCompoundWithChildTransformsMeetsAtTheKnownTime) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Two unit squares, each stored at its own origin and placed by a child transform at x = -1
  // and x = +1 (one turned a quarter): the compound spans x in [-1.5, 1.5], y in [-0.5, 0.5].
  // The body turns it upright (y in [8.5, 11.5] at (0, 10)); a ball below it rises.
  using C = Compound<T>;
  const Aabb<T> square(V(T(-0.5), T(-0.5)), V(T(0.5), T(0.5)));
  const C body = C::make_placed({{square, Transform<T>::make_translation(V(-1, 0)).value()},
                                 {square, Transform<T>::make_with_rotation(V(1, 0), V(0, 1)).value()}})
                     .value();
  const Transform<T> xc = Transform<T>::make_with_rotation(V(0, 10), V(0, 1)).value();
  const Circle<T> ball(V(0, 0), T(0.25));
  const V up(0, 4), still(0, 0);
  const Transform<T> id;
  const CastResult<T> r = shape_cast(ball, id, up, body, xc, still, T(4));
  ASSERT_EQ(r.outcome, CastOutcome::Hit);
  const double exact = (10 - 1.5 - 0.25) / 4;
  EXPECT_LE(double(r.t), exact);
  EXPECT_GE(double(r.t), exact - cast_tolerance(ball, id, up, body, xc, still, T(4)) / 4);
  EXPECT_NEAR(double(r.normal.y()), 1.0, 1e-6);
  // Aimed beside it (x = 0.875: the compound's half width 0.5 plus the radius is 0.75): a miss.
  const Transform<T> beside = Transform<T>::make_translation(V(T(0.875), 0)).value();
  EXPECT_EQ(shape_cast(ball, beside, up, body, xc, still, T(4)).outcome, CastOutcome::Miss);
}

TYPED_TEST(Cast, LeavingAnOverlapIsNoHitWhenTheStartIsNotAStop) {
  using T = TypeParam;
  using V = Vec2<T>;
  CastOptions leave;
  leave.stop_at_overlap = false;
  // A ball 0.1 inside the right face of a box, depth 0.6 along x: contact()'s normal is -x (from
  // the ball toward the box).
  const Circle<T> ball(V(T(1.9), 1), T(0.5));
  const Aabb<T> box(V(0, 0), V(2, 2));
  ASSERT_TRUE(overlaps(ball, box));
  // Moving out along +x: the default stops at t = 0; leaving, the pair never begins to touch again.
  EXPECT_EQ(shape_cast(ball, V(1, 0), box, V(0, 0), T(1)).t, T(0));
  const CastResult<T> out = shape_cast(ball, V(1, 0), box, V(0, 0), T(1), leave);
  EXPECT_EQ(out.outcome, CastOutcome::Miss);
  EXPECT_EQ(out.t, T(1));
  // Sliding along the face (n . w = 0) leaves too; moving deeper (n . w > 0) still hits at t = 0
  // with contact()'s normal, as without the option.
  EXPECT_EQ(shape_cast(ball, V(0, 1), box, V(0, 0), T(1), leave).outcome, CastOutcome::Miss);
  const CastResult<T> in = shape_cast(ball, V(-1, 0), box, V(0, 0), T(1), leave);
  const CastResult<T> stop = shape_cast(ball, V(-1, 0), box, V(0, 0), T(1));
  ASSERT_EQ(in.outcome, CastOutcome::Hit);
  EXPECT_EQ(in.t, T(0));
  EXPECT_EQ(in.normal, stop.normal);
  EXPECT_EQ(in.point, stop.point);
  // Only the relative motion counts: the box moving -x carries the ball out as well.
  EXPECT_EQ(shape_cast(ball, V(0, 0), box, V(-1, 0), T(1), leave).outcome, CastOutcome::Miss);
}

TYPED_TEST(Cast, LeavingAnOverlapStillMeetsWhatLiesAhead) {
  using T = TypeParam;
  using V = Vec2<T>;
  CastOptions leave;
  leave.stop_at_overlap = false;
  // A compound of a floor the ball starts in and a wall ahead, the ball rising out of the floor
  // toward the wall: the floor is left out and the wall is met at its own first contact.
  const Circle<T> ball(V(0, T(0.25)), T(0.5));
  const Compound<T> level = Compound<T>::make({Aabb<T>(V(-8, -1), V(8, 0)), Aabb<T>(V(-8, 4), V(8, 5))}).value();
  const V v(0, 2);
  ASSERT_EQ(shape_cast(ball, v, level, V(0, 0), T(4)).t, T(0));
  const CastResult<T> r = shape_cast(ball, v, level, V(0, 0), T(4), leave);
  ASSERT_EQ(r.outcome, CastOutcome::Hit);
  const double exact = (4 - 0.5 - 0.25) / 2.0;  // the ball's top reaches y = 4
  const double eps = cast_tolerance(ball, v, level, V(0, 0), T(4));
  EXPECT_LE(double(r.t), exact);
  EXPECT_GE(double(r.t), exact - eps / 2);
  EXPECT_NEAR(double(r.normal.y()), 1.0, 1e-6);
  // Without an overlap at the start the option changes nothing, bit for bit.
  const Circle<T> clear(V(0, 2), T(0.5));
  const CastResult<T> a = shape_cast(clear, v, level, V(0, 0), T(4), leave);
  const CastResult<T> b = shape_cast(clear, v, level, V(0, 0), T(4));
  EXPECT_EQ(a.outcome, b.outcome);
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.normal, b.normal);
  EXPECT_EQ(a.point, b.point);
}

TEST(CastRegression, StepAxisFromClosestPointsLosesSeparationAlongASliver) {
  using V = Vec2<double>;
  // At a gap of 5e-7, 1e6 from the origin, the closest points' direction is off by 2e-4 rad and
  // the sliver (128 long) showed a negative separation along it: the cast stopped 16 tolerances
  // short. The face normal of the sliver's edge separates by the gap.
  const Circle<double> a(V(999856.125, -1000013), 0);
  const ConvexPolygon<double> b{V(999728, -1000016), V(999792, -1000015), V(999856, -1000013)};
  const V va(-64.125, -1.6666666666278616);
  const CastResult<double> r = shape_cast(a, va, b, V(0, 0), 0.25);
  ASSERT_EQ(r.outcome, CastOutcome::Hit);
  const double eps = cast_tolerance(a, va, b, V(0, 0), 0.25);
  EXPECT_LE(distance(translated(a, V(va * r.t)).value(), b), eps);
  EXPECT_FALSE(overlaps(translated(a, V(va * r.t)).value(), b));
}

TEST(CastRegression, SlidingPastALongSliverStepsByTheGapUntilTheIterationLimit) {
  // A small quadrilateral drifting along a sliver 2000 long, a few target separations off it:
  // rounding leaves the closest points' direction separating by no more than the target, so each
  // step is the gap over |w|, and after kCastMaxIterations of them the cast stops undecided, at a
  // time up to which the two are apart, in either order.
  using V = Vec2<double>;
  const auto a = ConvexPolygon<double>::make(
                     {V(-0x1.e9df70f795615p+9, -0x1.b4cd2b17431d4p+6), V(-0x1.e9db734ff5461p+9, -0x1.b4cf5533dc097p+6),
                      V(-0x1.e9db2e0c62288p+9, -0x1.b4af67f6db2f6p+6), V(-0x1.e9df2bb40243cp+9, -0x1.b4ad3dda42433p+6)})
                     .value();
  const auto b = ConvexPolygon<double>::make(
                     {V(-0x1.e9dae8c8cea17p+9, -0x1.b48f7ab9da8e8p+6), V(-0x1.e9d6eb212e863p+9, -0x1.b491a4d6737abp+6),
                      V(-0x1.5f4fc4e623c8ep+9, 0x1.f12f42e6ee24p+11), V(-0x1.5f53c28dc3e42p+9, 0x1.f12f5437d2eb6p+11)})
                     .value();
  const V w(0x1.7992f95c93e5ap-9, 0x1.5c147ad139a48p-5);
  const double max_t = 0x1p+16;
  const CastResult<double> r = shape_cast(a, w, b, V(0, 0), max_t);
  ASSERT_EQ(r.outcome, CastOutcome::IterationLimit);
  EXPECT_EQ(r.iterations, kCastMaxIterations);
  EXPECT_GT(r.t, max_t / 8);
  EXPECT_EQ(shape_cast(b, V(0, 0), a, w, max_t).t, r.t);
  // The first step (the faces') ends at t = 8295.68221, where the closest points' direction no
  // longer separates by more than the target: the gap bound carries each step after it, which
  // all move t on.
  EXPECT_GT(r.t, 8295.6823);
  for (int i = 0; i <= 256; ++i) {
    const double s = r.t * i / 256;
    EXPECT_FALSE(overlaps(moved_by(a, V(w * s)), b)) << "at s = " << s;
  }
}

TEST(CastRegression, HitPointAlongTheClosestPointsNotTheFaceNormal) {
  using V = Vec2<double>;
  // A circle of radius 6 reaching the end of a vertical segment: the face normal (1, 0) separates
  // as well as the gap, but the circle's surface point lies along the closest points' direction.
  const Circle<double> a(V(-67108858.0234375, -54525964.5), 6);
  const Aabb<double> b(V(-67108852, -54525963), V(-67108852, -54525962));
  const V va(0.18750000000000044, 12.000000000000028), vb(0, 0);
  const CastResult<double> r = shape_cast(a, va, b, vb, 0.25);
  ASSERT_EQ(r.outcome, CastOutcome::Hit);
  const double eps = cast_tolerance(a, va, b, vb, 0.25);
  EXPECT_LE(distance_at(r.point, a, va, r.t), 2 * eps);
  EXPECT_LE(distance_at(r.point, b, vb, r.t), 2 * eps);
}

// The sweeps below are written {local centre, centre at 0, centre at 1, angle at 0, angle at 1}.

/// time_of_impact(a, sa, b, sb, 1) hits within 16 steps (a quarter of the limit), and the shapes,
/// posed as the sweeps say at t, are apart and within twice the tolerance.
template <class A, class B, Scalar T>
void expect_prompt_hit(const A& a, const Sweep<T>& sa, const B& b, const Sweep<T>& sb) {
  const CastResult<T> r = time_of_impact(a, sa, b, sb, T(1));
  ASSERT_EQ(r.outcome, CastOutcome::Hit) << "iterations " << r.iterations;
  EXPECT_LE(r.iterations, 16);
  auto at = [&](const Sweep<T>& s) {
    const SweepPose p = sweep_pose(s, Calc(r.t));
    return Transform<double>::make_with_rotation(p.position, p.rotation).value();
  };
  EXPECT_FALSE(overlaps(as_double(a), at(sa), as_double(b), at(sb)));
  EXPECT_LE(distance(as_double(a), at(sa), as_double(b), at(sb)), 2 * toi_tolerance(a, sa, b, sb, T(1)));
}

TEST(TimeOfImpact, BodyWhirledPastTheOtherStopsAtTheIterationLimitApartSoFar) {
  // A speck of a box whirled about the origin 145 turns per unit time, 14 from it, while another
  // small box drifts beside its orbit: every step is bounded by the whirl's speed, and after
  // kCastMaxIterations of them the query stops undecided, at a time up to which the two are apart.
  using V = Vec2<double>;
  const Obb<double> drifting = Obb<double>::make_with_axis(V(-0x1.a3115325cccp+0, -0x1.c4fce933c86e5p+3),
                                                           V(0x1.0925805914abfp-23, 0x1.2fba5d9d59f1ep-22),
                                                           V(-0x1.363984abbda92p-2, 0x1.e7f04dc3d17f9p-1))
                                   .value();
  const Obb<double> speck = Obb<double>::make_with_axis(V(-0x1.a311621ef846ep+0, -0x1.c4fcea528c0a1p+3),
                                                        V(0x1.77e27b3f8df7fp-34, 0x1.da87749a3c972p-34),
                                                        V(0x1.fbf2953434d7dp-1, 0x1.01294c84f68bp-3))
                                .value();
  const V c0 = drifting.center();
  const Sweep<double> drift{c0, c0, V(-0x1.a311533453492p+0, -0x1.c4fce934de9e8p+3), 0, 0};
  const Sweep<double> whirl{V(0, 0), V(0, 0), V(0, 0), 0, 0x1.c9616cfae23f4p+9};
  for (const bool swapped : {false, true}) {
    const CastResult<double> r =
        swapped ? time_of_impact(speck, whirl, drifting, drift) : time_of_impact(drifting, drift, speck, whirl);
    ASSERT_EQ(r.outcome, CastOutcome::IterationLimit);
    EXPECT_EQ(r.iterations, kCastMaxIterations);
    ASSERT_GT(r.t, 0.0);
    // Apart at every sampled pose up to t.
    for (int i = 0; i <= 512; ++i) {
      const double s = r.t * i / 512;
      const SweepPose pa = sweep_pose(drift, s), pb = sweep_pose(whirl, s);
      const auto xa = Transform<double>::make_with_rotation(pa.position, pa.rotation);
      const auto xb = Transform<double>::make_with_rotation(pb.position, pb.rotation);
      ASSERT_TRUE(xa && xb);
      EXPECT_FALSE(overlaps(drifting, *xa, speck, *xb)) << "at s = " << s;
    }
  }
}

TEST(TimeOfImpact, CornerBehindTheSupportThatTurnsFasterBoundsTheStep) {
  // A box turning 0.65 rad as it passes a still ball: the corner that first touches the ball lies
  // behind the support along the closest points when a step is taken, and outruns it. A bound from
  // the support's rate alone steps over the contact and calls the motion a miss.
  using V = Vec2<double>;
  const Circle<double> ball(V(-0x1.60247560ff62ep-1, -0x1.eed93c814cd88p-4), 0x1.7419b4ba9efa5p-1);
  const Aabb<double> box =
      Aabb<double>::make(V(-0x1.8ecf3416a18b4p-2, 0x1.26a1d06bfc048p-2), V(0x1.4ba98a7e40df4p-3, 0x1.4be3d2945f77p+0))
          .value();
  const V c_ball(0x1.e6f5ea4c465e1p+0, -0x1.d5986c7d05c95p+0);
  const Sweep<double> still{V(0x1.0ce3547307815p-2, 0x1.a2de905d1f274p-3), c_ball, c_ball, -0x1.5181f81fdf726p+0,
                            -0x1.5181f81fdf726p+0};
  const Sweep<double> turn{V(-0x1.b366803e5a581p-4, -0x1.4505fa3e4648dp-7),
                           V(0x1.075d85d059c3ep+1, 0x1.f73bc128a5708p-1),
                           V(0x1.eb01839611ba8p-2, -0x1.7f4e876afb874p-1), 0x1.300a122a27fd2p+1, 0x1.b9bb5b260d1dap+0};
  expect_prompt_hit(ball, still, box, turn);
  expect_prompt_hit(box, turn, ball, still);
}

TEST(CastRegression, CornerBehindTheSupportButFasterDoesNotHoldEveryStepBack) {
  // A box turning 0.8 rad in place towards a still ball: a corner just behind the support along
  // the closest points closes much faster than the support. Charging every point near the support
  // with the fastest near rate makes each step a small fraction of the gap, and the query ends at
  // the iteration limit; each point's own lag and rate bound the step.
  using V = Vec2<double>;
  const Aabb<double> box =
      Aabb<double>::make(V(0x1.bbe4a3f5d044p-5, -0x1.6f3e18a45b6a4p-3), V(0x1.3e98905b07e48p-2, 0x1.4b486fbff999cp-2))
          .value();
  const Circle<double> ball(V(0x1.a5ea132a1e0d2p-1, 0x1.9ce5df04fea48p-3), 0x1.7f50eeed38107p-1);
  const V c_box(0x1.274904b6ccf1cp-1, 0x1.0dcbcf4a63df8p-2), c_ball(0x1.b5aa8996e805cp-1, 0x1.10c29b9792252p-1);
  const Sweep<double> turn{V(0x1.ca09e2956fdd3p-4, -0x1.11f085069a10bp-2), c_box, c_box, 0x1.f922bd556789p-2,
                           -0x1.872cf88746698p-3};
  const Sweep<double> still{V(0x1.fd0aeeb55d4d5p-3, 0x1.16346a6a6a7ep-4), c_ball, c_ball, -0.0, 0.0};
  expect_prompt_hit(box, turn, ball, still);
  expect_prompt_hit(ball, still, box, turn);
}

TEST(CastRegression, TurningBoxPassingACapsuleConvergesInFloat) {
  // An OBB turning a radian while it crosses a capsule's path, in float: the same slow steps.
  using V = Vec2<float>;
  const Obb<float> box(V(-0x1.eb76cep-3f, -0x1.0dcb22p-1f), V(0x1.83d05p-1f, 0x1.d2a9a2p-1f), 0x1.6b2028p+1f);
  const Capsule<float> capsule =
      Capsule<float>::make(V(0x1.286fbap-2f, 0x1.eb2346p-1f), V(-0x1.c8d2ccp-3f, 0x1.a24bap-4f), 0x1.8cd2e8p-3f)
          .value();
  const Sweep<float> turn{V(-0x1.98da0ep-3f, -0x1.8a80b6p-3f), V(0x1.05741cp+1f, -0x1.bd49e8p-1f),
                          V(-0x1.dbbbe6p+0f, -0x1.78f24ap+1f), -0x1.4c840ep+1f, -0x1.cd8f74p+0f};
  const Sweep<float> slide{V(-0x1.16891p-2f, 0x1.903bb6p-3f), V(-0x1.0f3028p+0f, -0x1.73656ep-1f),
                           V(-0x1.e1f4b4p-1f, -0x1.e8c90ap-1f), 0x1.25344ap-2f, 0x1.25344ap-2f};
  expect_prompt_hit(box, turn, capsule, slide);
  expect_prompt_hit(capsule, slide, box, turn);
}

}  // namespace

TEST(CastRegression, TouchingStartOverAnEmptyIntervalIsAHitNotAMiss) {
  using V = Vec2<double>;
  // Over [0, 0] a pair that no face separates is not yet proven apart: the faces' bound alone
  // must not declare the miss (the fuzz corpus's sliver touching a point circle, as a box).
  const Aabb<double> a(V(0, 0), V(1, 1));
  const Circle<double> b(V(1.5, 0.5), 0.5);
  const CastResult<double> r = shape_cast(a, V(0, 0), b, V(0, 0), 0.0);
  ASSERT_EQ(r.outcome, CastOutcome::Hit);
  EXPECT_EQ(r.t, 0.0);
  const CastResult<double> s = shape_cast(b, V(3, 0), a, V(0, 0), 0.0);
  ASSERT_EQ(s.outcome, CastOutcome::Hit);
  EXPECT_EQ(s.t, 0.0);
}

}  // namespace collide::test
