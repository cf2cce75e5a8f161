// signed_distance() and closest_points() on hand-computed cases: values for each kind, the sign
// against contains() to the last ulp, NaN and infinite points, tiny and far points; witness
// points of separated, touching, overlapping and crossing pairs in both orders; every registry
// pair against distance(); the placed forms.

#include "support.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace collide::test {
namespace {

template <class T>
class SignedDistance : public ::testing::Test {};
TYPED_TEST_SUITE(SignedDistance, Scalars);

template <class T>
class ClosestPointsTest : public ::testing::Test {};
TYPED_TEST_SUITE(ClosestPointsTest, Scalars);

template <Scalar T>
T up(T x) {
  return std::nextafter(x, std::numeric_limits<T>::infinity());
}
template <Scalar T>
T down(T x) {
  return std::nextafter(x, -std::numeric_limits<T>::infinity());
}

/// Expects signed_distance(s, p) within its documented bound of `exact`.
template <class S, Scalar T>
void expect_signed(const S& s, const Vec2<T>& p, double exact) {
  EXPECT_NEAR(double(signed_distance(s, p)), exact, signed_distance_tolerance(s, p)) << "at " << p.transpose();
}

TYPED_TEST(SignedDistance, EachKindByHand) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> circle(V(0, 0), 5);
  EXPECT_EQ(signed_distance(circle, V(6, 8)), T(5));  // |(6, 8)| = 10, exact
  EXPECT_EQ(signed_distance(circle, V(3, 4)), T(0));  // on the circle
  EXPECT_EQ(signed_distance(circle, V(0, 0)), T(-5));
  EXPECT_EQ(signed_distance(circle, V(1, 0)), T(-4));

  const Aabb<T> box(V(0, 0), V(4, 2));
  EXPECT_EQ(signed_distance(box, V(1, 1)), T(-1));  // a unit from the top and the bottom
  EXPECT_EQ(signed_distance(box, V(2, T(0.5))), T(-0.5));
  EXPECT_EQ(signed_distance(box, V(7, 6)), T(5));  // (3, 4) from the corner (4, 2)
  EXPECT_EQ(signed_distance(box, V(5, 1)), T(1));
  EXPECT_EQ(signed_distance(box, V(4, 1)), T(0));

  // The 45-degree square: sides 1 from its centre, its vertex at (sqrt 2, 0).
  const Obb<T> diamond(V(0, 0), V(1, 1), T(std::numbers::pi / 4));
  expect_signed(diamond, V(0, 0), -1.0);
  expect_signed(diamond, V(3, 0), 3 - std::numbers::sqrt2);
  expect_signed(diamond, V(2, 2), 2 * std::numbers::sqrt2 - 1);

  const Capsule<T> capsule(V(0, 0), V(4, 0), 1);
  EXPECT_EQ(signed_distance(capsule, V(2, 3)), T(2));
  EXPECT_EQ(signed_distance(capsule, V(2, 0)), T(-1));
  EXPECT_EQ(signed_distance(capsule, V(7, 4)), T(4));  // 5 from the end (4, 0)
  EXPECT_EQ(signed_distance(capsule, V(2, 1)), T(0));

  const ConvexPolygon<T> tri{V(0, 0), V(4, 0), V(0, 4)};
  EXPECT_EQ(signed_distance(tri, V(1, 1)), T(-1));
  EXPECT_EQ(signed_distance(tri, V(-3, -4)), T(5));      // from the vertex (0, 0)
  expect_signed(tri, V(4, 4), 2 * std::numbers::sqrt2);  // from the side x + y = 4

  // A compound: a flat box [-1, 1] x [-1/4, 1/4] and a circle of radius 1/2 at the origin. Inside,
  // the depth in the deepest child (the circle's 1/2, not the box's 1/4); outside, the nearest.
  const auto comp = make_kind<ShapeKind::Compound, T>(V(0, 0), 1);
  EXPECT_EQ(signed_distance(comp, V(0, 0)), T(-0.5));
  EXPECT_EQ(signed_distance(comp, V(3, 0)), T(2));
  EXPECT_EQ(signed_distance(Shape<T>(comp), V(3, 0)), T(2));  // the variant lands on the same code
}

TYPED_TEST(SignedDistance, BoundIsTheDocumentedFormula) {
  using T = TypeParam;
  using V = Vec2<T>;
  const double eps = std::numeric_limits<T>::epsilon(), least = std::numeric_limits<T>::denorm_min();
  const Circle<T> circle(V(0, 0), 5);
  const double s = bounds(circle).max().x();  // S: 5, as bounds() rounds it outward
  // (64 * 2^-53 + 4 eps_T) * max(S, |p|_inf) + 2^-500 + denorm_min_T, at |p|_inf = 8 and below S.
  EXPECT_DOUBLE_EQ(signed_distance_tolerance(circle, V(6, 8)), (64 * 0x1p-53 + 4 * eps) * 8 + 0x1p-500 + least);
  EXPECT_DOUBLE_EQ(signed_distance_tolerance(circle, V(1, -2)), (64 * 0x1p-53 + 4 * eps) * s + 0x1p-500 + least);
  // Placed by a move to (16, 0): S about 21 from the placed box, plus the transform's own tolerance.
  const Transform<T> x = Transform<T>::make(V(16, 0), 0).value();
  const double placed = bounds(circle, x).max().x();
  EXPECT_NEAR(placed, 21, 1e-4);
  EXPECT_DOUBLE_EQ(signed_distance_tolerance(circle, x, V(0, 0)),
                   (64 * 0x1p-53 + 4 * eps) * placed + 0x1p-500 + least + transform_tolerance(circle, x));
}

TYPED_TEST(SignedDistance, SignIsContainsToTheUlp) {
  using T = TypeParam;
  using V = Vec2<T>;
  const ConvexPolygon<T> tri{V(0, 0), V(4, 0), V(0, 4)};
  const Circle<T> circle(V(0, 0), 5);
  const Capsule<T> capsule(V(0, 0), V(4, 0), 1);
  const Obb<T> diamond(V(0, 0), V(1, 1), T(std::numbers::pi / 4));
  // Points on each boundary and one ulp to either side: <= 0 exactly when contains().
  const auto check = [](const auto& s, const V& p) {
    for (const V& q : {p, V(p.x(), up(p.y())), V(p.x(), down(p.y())), V(up(p.x()), p.y()), V(down(p.x()), p.y())}) {
      EXPECT_EQ(signed_distance(s, q) <= T(0), contains(s, q)) << q.transpose();
      EXPECT_LE(std::fabs(double(signed_distance(s, q))), signed_distance_tolerance(s, q));
    }
  };
  check(tri, V(2, 2));
  check(circle, V(3, 4));
  check(capsule, V(T(4.6), T(0.8)));  // on the end disk: (0.6, 0.8) from (4, 0)
  check(diamond, V(T(std::numbers::sqrt2), 0));
  const Aabb<T> box(V(0, 0), V(4, 2));
  check(box, V(4, 1));
  check(box, V(4, 2));  // a corner
  check(box, V(T(1.5), 0));
  EXPECT_GT(signed_distance(tri, V(2, up(T(2)))), T(0));  // one ulp beyond the hypotenuse
  EXPECT_LE(signed_distance(tri, V(2, T(2))), T(0));
}

TYPED_TEST(SignedDistance, NanGivesNanInfinityGivesInfinity) {
  using T = TypeParam;
  using V = Vec2<T>;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Aabb<T> box(V(0, 0), V(1, 1));
  EXPECT_TRUE(std::isnan(signed_distance(box, V(nan, 0))));
  EXPECT_TRUE(std::isnan(signed_distance(box, V(inf, nan))));  // NaN wins: no distance at all
  EXPECT_EQ(signed_distance(box, V(inf, 0)), inf);
  EXPECT_EQ(signed_distance(box, V(0, -inf)), inf);
  EXPECT_FALSE(contains(box, V(nan, 0)));  // the same policy as contains(): not held
}

TYPED_TEST(SignedDistance, FarAndTinyPoints) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> unit(V(0, 0), 1);
  // A point at T's largest magnitude: its squares would overflow without the rescaling.
  const T big = std::numeric_limits<T>::max() / 4;
  expect_signed(unit, V(big, 0), double(big) - 1);
  // The same for a polygon and a capsule, whose distances go through their cores: beyond 2^500
  // (double) the squares would overflow without the rescaling.
  const T far = std::is_same_v<T, float> ? T(0x1p120) : T(0x1p600);
  const ConvexPolygon<T> tri{V(0, 0), V(4, 0), V(0, 4)};
  const Capsule<T> capsule(V(0, 0), V(4, 0), 1);
  expect_signed(tri, V(far, 0), double(far) - 4);
  expect_signed(capsule, V(0, -far), double(far) - 1);
  // Beyond T's range the distance is +infinity (sqrt 2 times the largest value).
  const T top = std::numeric_limits<T>::max();
  EXPECT_EQ(signed_distance(unit, V(top, top)), std::numeric_limits<T>::infinity());
  // A tiny circle: relative accuracy, and the least positive T for a point just outside.
  const T tiny = std::is_same_v<T, float> ? T(0x1p-120) : T(0x1p-1000);
  const Circle<T> dot(V(0, 0), tiny);
  EXPECT_EQ(signed_distance(dot, V(3 * tiny, 4 * tiny)), 4 * tiny);
  // A point outside by (sqrt 10 - 3) of the least positive T: the distance rounds to 0, and the
  // least positive T keeps it outside, as contains() says.
  const T least = std::numeric_limits<T>::denorm_min();
  const Circle<T> speck(V(0, 0), 3 * least);
  EXPECT_FALSE(contains(speck, V(3 * least, least)));
  EXPECT_EQ(signed_distance(speck, V(3 * least, least)), least);
  EXPECT_EQ(signed_distance(speck, V(3 * least, 0)), T(0));
}

TYPED_TEST(SignedDistance, PlacedFormIsTheImages) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> box(V(2, -1), V(3, 1));
  // A quarter turn (exact) and a move: the box becomes [9, 11] x [2, 3].
  const Transform<T> x = Transform<T>::make_with_rotation(V(10, 0), V(0, 1)).value();
  EXPECT_EQ(signed_distance(box, x, V(10, T(2.5))), T(-0.5));
  EXPECT_EQ(signed_distance(box, x, V(10, 5)), T(2));
  EXPECT_EQ(signed_distance(box, x, V(10, 5)), signed_distance(Aabb<T>(V(9, 2), V(11, 3)), V(10, 5)));
  EXPECT_EQ(signed_distance(box, Transform<T>(), V(7, 0)), signed_distance(box, V(7, 0)));
  EXPECT_TRUE(std::isnan(signed_distance(box, x, V(std::numeric_limits<T>::quiet_NaN(), 0))));
  // A general turn: within the placed bound, with contains()'s sign.
  const Transform<T> turned = Transform<T>::make(V(0, 0), T(0.5)).value();
  const Circle<T> c(V(3, 0), 1);
  const V centre(T(3 * std::cos(0.5)), T(3 * std::sin(0.5)));
  EXPECT_NEAR(double(signed_distance(c, turned, centre)), -1.0, signed_distance_tolerance(c, turned, centre));
  EXPECT_EQ(signed_distance(c, turned, centre) <= T(0), contains(c, turned, centre));
}

/// Expects a witness pair: the distance, and each point within the bound of the given point.
template <class A, class B, Scalar T>
void expect_witness(const A& a, const B& b, double dist, const Vec2<T>& pa, const Vec2<T>& pb) {
  const ClosestPoints<T> c = closest_points(a, b);
  const double tol = closest_points_tolerance(a, b);
  EXPECT_EQ(c.distance, distance(a, b));
  EXPECT_NEAR(double(c.distance), dist, tol);
  EXPECT_LE((widen(c.point_a) - widen(pa)).norm(), tol) << c.point_a.transpose();
  EXPECT_LE((widen(c.point_b) - widen(pb)).norm(), tol) << c.point_b.transpose();
}

TYPED_TEST(ClosestPointsTest, BoundIsTheDocumentedFormula) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> small(V(0, 0), 1), large(V(5, 0), 2);
  const double s = bounds(large).max().x();  // S: 7, as bounds() rounds it outward
  // 4 rounding_tolerance + 2 eps_T S + 2 denorm_min_T.
  EXPECT_DOUBLE_EQ(closest_points_tolerance(small, large), 4 * rounding_tolerance(small, large) +
                                                               2 * double(std::numeric_limits<T>::epsilon()) * s +
                                                               2 * double(std::numeric_limits<T>::denorm_min()));
  EXPECT_DOUBLE_EQ(closest_points_tolerance(small, Transform<T>(), large, Transform<T>()),
                   closest_points_tolerance(small, large));
}

TYPED_TEST(ClosestPointsTest, SeparatedPairsBothOrders) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> small(V(0, 0), 1), large(V(5, 0), 2);
  expect_witness(small, large, 2.0, V(1, 0), V(3, 0));
  expect_witness(large, small, 2.0, V(3, 0), V(1, 0));

  const Aabb<T> wall(V(2, -1), V(3, 1));
  expect_witness(small, wall, 1.0, V(1, 0), V(2, 0));
  expect_witness(wall, small, 1.0, V(2, 0), V(1, 0));

  // Boxes apart across a diagonal: their nearest corners.
  const Aabb<T> lo(V(0, 0), V(1, 1)), hi(V(3, 5), V(4, 6));
  expect_witness(lo, hi, std::sqrt(20.0), V(1, 1), V(3, 5));
  expect_witness(hi, lo, std::sqrt(20.0), V(3, 5), V(1, 1));

  // The 45-degree square's vertex (sqrt 2, 0) against a circle to its right.
  const Obb<T> diamond(V(0, 0), V(1, 1), T(std::numbers::pi / 4));
  const Circle<T> wheel(V(4, 0), 1);
  expect_witness(diamond, wheel, 3 - std::numbers::sqrt2, V(T(std::numbers::sqrt2), 0), V(3, 0));
  expect_witness(wheel, diamond, 3 - std::numbers::sqrt2, V(3, 0), V(T(std::numbers::sqrt2), 0));

  // A capsule under a triangle whose bottom side is parallel to it: every x in [1, 3] is closest;
  // the two points face each other straight across the gap of 2.
  const Capsule<T> cap(V(0, 0), V(4, 0), 1);
  const ConvexPolygon<T> roof{V(1, 3), V(3, 3), V(2, 5)};
  for (const bool swap : {false, true}) {
    const ClosestPoints<T> c = swap ? closest_points(roof, cap) : closest_points(cap, roof);
    const V on_cap = swap ? c.point_b : c.point_a, on_roof = swap ? c.point_a : c.point_b;
    EXPECT_EQ(c.distance, T(2));
    EXPECT_NEAR(double(on_cap.y()), 1.0, 1e-6);
    EXPECT_NEAR(double(on_roof.y()), 3.0, 1e-6);
    EXPECT_NEAR(double(on_cap.x()), double(on_roof.x()), 1e-6);
    EXPECT_GE(on_roof.x(), T(1));
    EXPECT_LE(on_roof.x(), T(3));
  }

  // A compound answers with its closest child: the circle (radius 1/2) is nearer (0, 3) than the
  // flat box (top at 1/4).
  const auto comp = make_kind<ShapeKind::Compound, T>(V(0, 0), 1);
  const Circle<T> above(V(0, 3), 1);
  expect_witness(comp, above, 1.5, V(0, T(0.5)), V(0, 2));
}

TYPED_TEST(ClosestPointsTest, OverlappingPairsGiveOneCommonPoint) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Touching circles: the point where they touch.
  const Circle<T> left(V(0, 0), 1), right(V(2, 0), 1);
  for (const ClosestPoints<T>& c : {closest_points(left, right), closest_points(right, left)}) {
    EXPECT_EQ(c.distance, T(0));
    EXPECT_EQ(c.point_a, V(1, 0));
    EXPECT_EQ(c.point_b, V(1, 0));
  }
  // Overlapping circles, centres 3 apart with radii 2 and 2: the point dividing the centres'
  // segment in the ratio of the radii, in both orders.
  const Circle<T> a(V(0, 0), 2), b(V(3, 0), 2);
  EXPECT_EQ(closest_points(a, b).point_a, V(T(1.5), 0));
  EXPECT_EQ(closest_points(b, a).point_a, V(T(1.5), 0));
  // A circle whose centre lies outside a box it overlaps: the box's point nearest the centre.
  const Aabb<T> box(V(T(0.5), -1), V(3, 1));
  EXPECT_EQ(closest_points(left, box).point_a, V(T(0.5), 0));
  // Overlapping boxes: a corner of one inside the other.
  const Aabb<T> p(V(0, 0), V(2, 2)), q(V(1, 1), V(3, 3));
  const ClosestPoints<T> c = closest_points(p, q);
  EXPECT_EQ(c.distance, T(0));
  EXPECT_EQ(c.point_a, c.point_b);
  EXPECT_TRUE(contains(p, c.point_a) && contains(q, c.point_a));
  // A plus sign: no corner of either bar lies in the other; the point is where their edges cross.
  const Aabb<T> bar_x(V(-3, -1), V(3, 1)), bar_y(V(-1, -3), V(1, 3));
  for (const ClosestPoints<T>& x : {closest_points(bar_x, bar_y), closest_points(bar_y, bar_x)}) {
    EXPECT_EQ(x.point_a, x.point_b);
    EXPECT_EQ(x.point_a.cwiseAbs(), V(1, 1));
  }
  // A turned square crossing a box: the crossing point lies on both (exactly, up to rounding).
  const Obb<T> turned(V(0, 0), V(2, T(0.25)), T(0.3));
  const Aabb<T> tall(V(T(-0.2), -5), V(T(0.2), 5));
  const ClosestPoints<T> t = closest_points(turned, tall);
  EXPECT_EQ(t.distance, T(0));
  EXPECT_LE(double(signed_distance(turned, t.point_a)), closest_points_tolerance(turned, tall));
  EXPECT_LE(double(signed_distance(tall, t.point_a)), closest_points_tolerance(turned, tall));
}

/// Every registry pair, both orders, apart by a quarter of b's size along x, touching, and
/// overlapping: the distance is distance()'s to the bit, each point within the bound of its shape,
/// and (apart) the two points face each other across the gap along x.
template <ShapeKind KA, ShapeKind KB, Scalar T>
void check_pair_witness() {
  using V = Vec2<T>;
  const T ha = 2, hb = 1;
  for (const T gap : {T(0.25), T(0), T(-0.5)}) {
    const auto a = make_kind<KA, T>(V(0, 0), ha);
    const auto b = make_kind<KB, T>(V(ha + hb + gap, 0), hb);
    SCOPED_TRACE((pair_label<KA, KB>() + " gap " + std::to_string(double(gap))));
    const ClosestPoints<T> c = closest_points(a, b);
    const double tol = closest_points_tolerance(a, b);
    EXPECT_EQ(c.distance, distance(a, b));
    EXPECT_LE(double(signed_distance(a, c.point_a)), tol + signed_distance_tolerance(a, c.point_a));
    EXPECT_LE(double(signed_distance(b, c.point_b)), tol + signed_distance_tolerance(b, c.point_b));
    if (gap > 0) {
      // make_kind's shapes reach x = ha exactly at y = 0 (and b back to its x - hb), so the gap
      // lies along x.
      EXPECT_NEAR(double(c.distance), double(gap), tol);
      EXPECT_NEAR(double(c.point_a.x()), double(ha), tol);
      EXPECT_NEAR(double(c.point_b.x()), double(ha + gap), tol);
      EXPECT_NEAR(double(c.point_a.y()), double(c.point_b.y()), tol);
    } else {
      EXPECT_EQ(c.distance, T(0));
      EXPECT_EQ(c.point_a, c.point_b);
    }
    const ClosestPoints<T> r = closest_points(Shape<T>(b), Shape<T>(a));  // the other order, as variants
    EXPECT_EQ(r.distance, distance(b, a));
    EXPECT_LE(double(signed_distance(a, r.point_b)), tol + signed_distance_tolerance(a, r.point_b));
    EXPECT_LE(double(signed_distance(b, r.point_a)), tol + signed_distance_tolerance(b, r.point_a));
  }
}

TYPED_TEST(ClosestPointsTest, EveryPairAgreesWithDistance) {
  for_each_pair([]<ShapeKind A, ShapeKind B>() {
    check_pair_witness<A, B, TypeParam>();
    if constexpr (A != B) check_pair_witness<B, A, TypeParam>();
  });
}

TYPED_TEST(ClosestPointsTest, PlacedFormIsTheImages) {
  using T = TypeParam;
  using V = Vec2<T>;
  // A unit circle stored at its origin and placed at (10, 0), against a world circle of radius 2
  // at (15, 0): 2 apart, at (11, 0) and (13, 0).
  const Circle<T> local(V(0, 0), 1), world(V(15, 0), 2);
  const Transform<T> x = Transform<T>::make(V(10, 0), 0).value();
  const ClosestPoints<T> c = closest_points(local, x, world, Transform<T>());
  EXPECT_EQ(c.distance, distance(local, x, world, Transform<T>()));
  EXPECT_EQ(c.distance, T(2));
  EXPECT_EQ(c.point_a, V(11, 0));
  EXPECT_EQ(c.point_b, V(13, 0));
  const ClosestPoints<T> r = closest_points(world, Transform<T>(), local, x);
  EXPECT_EQ(r.point_a, V(13, 0));
  EXPECT_EQ(r.point_b, V(11, 0));
  // A box turned by a quarter turn about its own frame's origin: [2, 3] x [-1, 1] becomes
  // [-1, 1] x [2, 3], 1 above a circle of radius 1 at the origin.
  const Aabb<T> box(V(2, -1), V(3, 1));
  const Transform<T> quarter = Transform<T>::make_with_rotation(V(0, 0), V(0, 1)).value();
  const Circle<T> ball(V(0, 0), 1);
  const ClosestPoints<T> d = closest_points(ball, Transform<T>(), box, quarter);
  EXPECT_EQ(d.distance, T(1));
  EXPECT_EQ(d.point_a, V(0, 1));
  EXPECT_EQ(d.point_b, V(0, 2));
  // The identity: the world-space answer, bit for bit.
  const ClosestPoints<T> w = closest_points(ball, Transform<T>(), box, Transform<T>());
  const ClosestPoints<T> v = closest_points(ball, box);
  EXPECT_EQ(w.distance, v.distance);
  EXPECT_EQ(w.point_a, v.point_a);
  EXPECT_EQ(w.point_b, v.point_b);
}

}  // namespace
}  // namespace collide::test
