// Mass properties: hand-checked values for every kind (unit square, unit circle, a capsule as a
// rectangle and a disk split at its ends, compounds with overlapping and placed children), the
// placed form, shapes without area, and the named errors of bad densities and overflow.

#include "support.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace collide::test {
namespace {

template <class T>
class Mass : public ::testing::Test {};
TYPED_TEST_SUITE(Mass, Scalars);

constexpr double kPi = std::numbers::pi;

/// Every output within its bound of the exact values (mass, centroid, inertia about the centroid).
template <Scalar T>
void expect_mass(const MassProperties<T>& got, const MassTolerance& tol, double mass, Vec2<double> centroid,
                 double inertia) {
  EXPECT_NEAR(double(got.mass), mass, tol.mass);
  EXPECT_NEAR(double(got.centroid.x()), centroid.x(), tol.centroid);
  EXPECT_NEAR(double(got.centroid.y()), centroid.y(), tol.centroid);
  EXPECT_NEAR(double(got.inertia), inertia, tol.inertia);
  EXPECT_NEAR(double(got.origin_inertia), inertia + mass * centroid.squaredNorm(), tol.origin_inertia);
}

TYPED_TEST(Mass, UnitSquareOfEveryBoxKind) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Side 1: inertia about the centre m (1^2 + 1^2) / 12 = 1/6; about the origin 1/6 + 1 * |(1/2, 1/2)|^2.
  const Aabb<T> box(V(0, 0), V(1, 1));
  const ConvexPolygon<T> poly({V(0, 0), V(1, 0), V(1, 1), V(0, 1)});
  const Obb<T> obb = Obb<T>::make_with_axis(V(T(0.5), T(0.5)), V(T(0.5), T(0.5)), V(1, 0)).value();
  expect_mass(mass_properties(box).value(), mass_tolerance(box), 1, {0.5, 0.5}, 1.0 / 6);
  expect_mass(mass_properties(poly).value(), mass_tolerance(poly), 1, {0.5, 0.5}, 1.0 / 6);
  expect_mass(mass_properties(obb).value(), mass_tolerance(obb), 1, {0.5, 0.5}, 1.0 / 6);
  EXPECT_NEAR(mass_properties(box).value().origin_inertia, 2.0 / 3, 1e-6);
  // Density 3 scales mass and inertia, not the centroid.
  expect_mass(mass_properties(poly, T(3)).value(), mass_tolerance(poly, T(3)), 3, {0.5, 0.5}, 0.5);
  // The same square turned 45 degrees as an OBB: its stored axis u is a unit vector rounded to T,
  // so its sides are |u| long: mass |u|^2 and inertia |u|^2 (|u|^2 + |u|^2) / 12.
  const Obb<T> turned(V(2, 3), V(T(0.5), T(0.5)), T(kPi / 4));
  const double uu = Vec2<double>(turned.axis().template cast<double>()).squaredNorm();
  expect_mass(mass_properties(turned).value(), mass_tolerance(turned), uu, {2, 3}, uu * uu / 6);
}

TYPED_TEST(Mass, UnitCircleAndACapsuleAsRectangleAndDisk) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Unit disk: mass pi, inertia pi / 2 about its centre; at (2, 0), pi / 2 + pi 2^2 about the origin.
  const Circle<T> disk(V(2, 0), 1);
  const auto d = mass_properties(disk).value();
  expect_mass(d, mass_tolerance(disk), kPi, {2, 0}, kPi / 2);
  EXPECT_NEAR(d.origin_inertia, kPi / 2 + 4 * kPi, 1e-5);
  // Capsule from (0, 0) to (2, 0), radius 1: the rectangle [0, 2] x [-1, 1] (mass 4, inertia
  // 4 (2^2 + 2^2) / 12 = 8/3) plus the unit disk split at the ends. The disk's halves have their
  // centroids 4 / (3 pi) beyond the ends, so moving them 1 out from the middle adds pi 1^2 plus
  // 2 (pi / 2) (2 * 1 * 4 / (3 pi)) = 8/3 to the disk's own pi / 2.
  const Capsule<T> cap(V(0, 0), V(2, 0), 1);
  const double inertia = 8.0 / 3 + (kPi / 2 + kPi + 8.0 / 3);
  expect_mass(mass_properties(cap).value(), mass_tolerance(cap), 4 + kPi, {1, 0}, inertia);
  // Turned and moved, a capsule keeps its mass and its inertia about its centroid: (10, 10) to
  // (11.5, 12) is 2.5 long, as (0, 0) to (2.5, 0) is.
  const Capsule<T> slanted(V(10, 10), V(T(11.5), 12), 1), straight(V(0, 0), V(T(2.5), 0), 1);
  const auto s = mass_properties(straight).value();
  expect_mass(mass_properties(slanted).value(), mass_tolerance(slanted), s.mass, {10.75, 11}, s.inertia);
}

TYPED_TEST(Mass, CompoundSumsItsChildrenOverlapsCountTwice) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Two unit squares 2 apart: centroid between them, inertia 2 (1/6) + 2 * 1^2 (parallel axes).
  const Compound<T> pair({Primitive<T>(Aabb<T>(V(0, 0), V(1, 1))), Primitive<T>(Aabb<T>(V(2, 0), V(3, 1)))});
  expect_mass(mass_properties(pair).value(), mass_tolerance(pair), 2, {1.5, 0.5}, 2.0 / 6 + 2);
  // The same square twice: a body with two fixtures, mass 2, not the union's 1.
  const Compound<T> twice({Primitive<T>(Aabb<T>(V(0, 0), V(1, 1))), Primitive<T>(Aabb<T>(V(0, 0), V(1, 1)))});
  expect_mass(mass_properties(twice).value(), mass_tolerance(twice), 2, {0.5, 0.5}, 2.0 / 6);
  // A disk and a square placed by a quarter turn at (3, 0): the square's centroid is the image of
  // its own (0.5, 0) -> (3, 0.5); the disk (mass pi at the origin) pulls the centroid toward it.
  const Compound<T> placed = Compound<T>::make_placed({{Circle<T>(V(0, 0), 1), Transform<T>()},
                                                       {Aabb<T>(V(0, T(-0.5)), V(1, T(0.5))),
                                                        Transform<T>::make_with_rotation(V(3, 0), V(0, 1)).value()}})
                                 .value();
  const double m = kPi + 1, cx = 3 / m, cy = 0.5 / m;
  const double spread = kPi * (cx * cx + cy * cy) + ((3 - cx) * (3 - cx) + (0.5 - cy) * (0.5 - cy));
  expect_mass(mass_properties(placed).value(), mass_tolerance(placed), m, {cx, cy}, kPi / 2 + 1.0 / 6 + spread);
}

TYPED_TEST(Mass, PlacedFormMovesTheCentroidAndKeepsMassAndInertia) {
  using T = TypeParam;
  using V = Vec2<T>;
  const ConvexPolygon<T> tri({V(0, 0), V(3, 0), V(0, 3)});                             // centroid (1, 1), area 9/2
  const Transform<T> x = Transform<T>::make_with_rotation(V(10, 0), V(0, 1)).value();  // (u, v) -> (10 - v, u)
  const auto world = mass_properties(tri).value(), there = mass_properties(tri, x).value();
  EXPECT_EQ(there.mass, world.mass);
  EXPECT_EQ(there.inertia, world.inertia);
  const MassTolerance tol = mass_tolerance(tri, x);
  // Triangle about its centroid: area (|e|^2 + |f|^2 - e.f) / 18 with e, f two of its sides
  // from one vertex: (9/2) (9 + 9 - 0) / 18 = 9/2.
  expect_mass(there, tol, 4.5, {9, 1}, 4.5);
}

TYPED_TEST(Mass, FarFromTheOriginTheErrorFollowsTheSize) {
  using T = TypeParam;
  using V = Vec2<T>;
  // A unit square 2^20 out: computed from its first vertex, its inertia keeps its digits.
  const T far = T(0x1p20);
  const ConvexPolygon<T> poly({V(far, far), V(far + 1, far), V(far + 1, far + 1), V(far, far + 1)});
  const auto p = mass_properties(poly).value();
  const MassTolerance tol = mass_tolerance(poly);
  EXPECT_NEAR(double(p.inertia), 1.0 / 6, tol.inertia);
  EXPECT_LT(tol.inertia, 1e-6);  // eps_T times the squared distance would be 2^40 eps_T
  EXPECT_NEAR(double(p.centroid.x()), double(far) + 0.5, tol.centroid);
  // An exact move keeps mass and inertia to the bit.
  const ConvexPolygon<T> moved = translated(poly, V(-far, T(3 * 1024))).value();
  EXPECT_EQ(mass_properties(moved).value().mass, p.mass);
  EXPECT_EQ(mass_properties(moved).value().inertia, p.inertia);
}

TYPED_TEST(Mass, ShapesWithoutAreaWeighNothingAndKeepTheirMiddle) {
  using T = TypeParam;
  using V = Vec2<T>;
  const auto point = mass_properties(Circle<T>(V(2, 5), 0)).value();
  EXPECT_EQ(point.mass, T(0));
  EXPECT_EQ(point.inertia, T(0));
  EXPECT_EQ(point.centroid, V(2, 5));
  const auto segment = mass_properties(Capsule<T>(V(0, 0), V(4, 2), 0)).value();
  EXPECT_EQ(segment.mass, T(0));
  EXPECT_EQ(segment.centroid, V(2, 1));
  const auto flat = mass_properties(Aabb<T>(V(1, 1), V(3, 1))).value();
  EXPECT_EQ(flat.mass, T(0));
  EXPECT_EQ(flat.centroid, V(2, 1));
  // A compound of points: the mean of their centroids; with one square, the square's alone.
  const Compound<T> points({Primitive<T>(Circle<T>(V(0, 0), 0)), Primitive<T>(Circle<T>(V(4, 2), 0))});
  EXPECT_EQ(mass_properties(points).value().centroid, V(2, 1));
  const Compound<T> with_square({Primitive<T>(Circle<T>(V(0, 0), 0)), Primitive<T>(Aabb<T>(V(4, 2), V(5, 3)))});
  EXPECT_EQ(mass_properties(with_square).value().centroid, V(T(4.5), T(2.5)));
  // Density 0: no mass, no inertia, the centroid still.
  const auto none = mass_properties(Aabb<T>(V(0, 0), V(2, 2)), T(0)).value();
  EXPECT_EQ(none.mass, T(0));
  EXPECT_EQ(none.origin_inertia, T(0));
  EXPECT_EQ(none.centroid, V(1, 1));
}

TYPED_TEST(Mass, BadDensitiesAndOverflowAreNamedErrors) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> disk(V(0, 0), 1);
  const Transform<T> x = Transform<T>::make_translation(V(1, 2)).value();
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_EQ(mass_properties(disk, nan).error().code(), Error::NonFinite);
  EXPECT_EQ(mass_properties(disk, inf).error().code(), Error::NonFinite);
  EXPECT_EQ(mass_properties(disk, x, -inf).error().code(), Error::NonFinite);
  EXPECT_EQ(mass_properties(disk, T(-1)).error().code(), Error::NegativeDensity);
  EXPECT_EQ(mass_properties(disk, x, -std::numeric_limits<T>::denorm_min()).error().code(), Error::NegativeDensity);
  EXPECT_EQ(name(Error::NegativeDensity), "NegativeDensity");
  EXPECT_STREQ(mass_properties(disk, T(-1)).error().what(), "NegativeDensity: density is negative");
  // A mass beyond T's largest value: OutOfRange, never infinity.
  const T top = std::numeric_limits<T>::max();
  EXPECT_EQ(mass_properties(disk, top).error().code(), Error::OutOfRange);
  const T wide = max_magnitude<T>();
  EXPECT_EQ(mass_properties(Aabb<T>(V(-wide, -wide), V(wide, wide))).error().code(), Error::OutOfRange);
  // Only the origin's inertia passes the range: still OutOfRange, placed there.
  const Transform<T> away = Transform<T>::make_translation(V(wide, 0)).value();
  EXPECT_TRUE(mass_properties(Circle<T>(V(0, 0), 1), top / 8).has_value());
  EXPECT_EQ(mass_properties(Circle<T>(V(0, 0), 1), away, top / 8).error().code(), Error::OutOfRange);
}

}  // namespace
}  // namespace collide::test
