// orient() and the polygon validation built on it, where naive floating point fails:
// near-collinear points, subnormal coordinates (products underflow), and values so large that
// the filter's products overflow.

#include "support.hpp"

#include <cmath>
#include <limits>

namespace collide::test {
namespace {

Vec2c v(double x, double y) { return Vec2c(x, y); }

TEST(Orient, NearCollinearIsExact) {
  // det = 1 - (1 + 2^-52) = -2^-52: below the filter's bound, decided by the exact expansion.
  EXPECT_EQ(orient(v(0, 0), v(1, 1), v(1 + 0x1p-52, 1)), -1);
  EXPECT_EQ(orient(v(0, 0), v(1, 1), v(1, 1 + 0x1p-52)), 1);
  EXPECT_EQ(orient(v(0, 0), v(1, 1), v(3, 3)), 0);
  // The classic failure: points on the line y = x far from the origin, perturbed by one ulp.
  const double x = 0.5 + 0x1p-53 * 3;
  EXPECT_EQ(orient(v(12, 12), v(24, 24), v(x, 0.5)), -1);  // right of the line, not collinear
  EXPECT_EQ(orient(v(12, 12), v(24, 24), v(0.5, x)), 1);
  // Antisymmetry under swapping two points, to the bit.
  EXPECT_EQ(orient(v(24, 24), v(12, 12), v(x, 0.5)), 1);
}

TEST(Orient, SubnormalCoordinatesDoNotUnderflow) {
  const double d = std::numeric_limits<double>::denorm_min();
  // Products of subnormals underflow to 0 in double: without rescaling every triple of subnormal
  // points would be reported collinear.
  EXPECT_EQ(orient(v(0, 0), v(3 * d, d), v(6 * d, 3 * d)), 1);  // det = 9 d^2 - 6 d^2 > 0
  EXPECT_EQ(orient(v(0, 0), v(3 * d, d), v(6 * d, d)), -1);     // det = 3 d^2 - 6 d^2 < 0
  EXPECT_EQ(orient(v(0, 0), v(3 * d, d), v(6 * d, 2 * d)), 0);  // exactly collinear
  // Mixed: one normal and two subnormal coordinates in the same call.
  EXPECT_EQ(orient(v(0x1p-1000, 0), v(0, d), v(0, 0)), 1);
  EXPECT_EQ(orient(v(0x1p-1000, 0), v(0, 0), v(0, d)), -1);
}

TEST(Orient, HugeCoordinates) {
  const double h = 0x1p500;
  EXPECT_EQ(orient(v(h, h), v(-h, -h), v(h - 0x1p448, h)), -1);
  EXPECT_EQ(orient(v(h, h), v(-h, -h), v(h / 2, h / 2)), 0);
  // Beyond the shapes' range the filter's products overflow; the rescaled expansion still answers.
  const double big = 1e308;
  EXPECT_EQ(orient(v(-big, -big), v(big, big), v(0, 1)), 1);
  EXPECT_EQ(orient(v(-big, -big), v(big, big), v(1, 0)), -1);
  EXPECT_EQ(orient(v(-big, -big), v(big, big), v(0, 0)), 0);
}

template <class T>
class TinyPolygons : public ::testing::Test {};
TYPED_TEST_SUITE(TinyPolygons, Scalars);

TYPED_TEST(TinyPolygons, SubnormalPolygonsAreValidAndExact) {
  using T = TypeParam;
  using V = Vec2<T>;
  const T d = std::numeric_limits<T>::denorm_min();
  // A diamond of half diagonal 4 units of denorm_min: every turn's determinant underflows
  // unless orient() rescales, and validation would reject it as Collinear.
  const auto poly = ConvexPolygon<T>::make({V(4 * d, 0), V(0, 4 * d), V(-4 * d, 0), V(0, -4 * d)});
  ASSERT_TRUE(poly.has_value()) << poly.error().what();
  // A spike at that scale is still NonConvex (compared by signs, not an underflowing dot product).
  const auto spike = ConvexPolygon<T>::make({V(0, 0), V(2 * d, 0), V(d, 0), V(d, d)});
  ASSERT_FALSE(spike.has_value());
  EXPECT_EQ(spike.error().code(), Error::NonConvex);
  EXPECT_EQ(spike.error().index(), 1);
  // Exact decisions at that scale: a diamond 1 unit away along x does not touch, 0 units does.
  const ConvexPolygon<T> a = poly.value();
  const ConvexPolygon<T> far{V(9 * d, 0), V(5 * d, 4 * d), V(5 * d, -4 * d)};
  const ConvexPolygon<T> touch{V(8 * d, 0), V(4 * d, 4 * d), V(4 * d, -4 * d)};
  EXPECT_FALSE(overlaps(a, far));
  EXPECT_TRUE(overlaps(a, touch));
  EXPECT_FALSE(overlaps(a, Aabb<T>(V(3 * d, 2 * d), V(8 * d, 8 * d))));  // the corner (3d, 2d)
  EXPECT_TRUE(overlaps(a, Aabb<T>(V(2 * d, 2 * d), V(8 * d, 8 * d))));   // on the edge x + y = 4d
}

}  // namespace
}  // namespace collide::test
