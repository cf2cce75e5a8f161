// orient() and the polygon validation built on it, where naive floating point fails:
// near-collinear points, subnormal coordinates (products underflow), and values so large that
// the filter's products overflow.

#include "support.hpp"

#include <cmath>
#include <limits>

namespace collide::test {
namespace {

Vec2c v(double x, double y) {
  return Vec2c(x, y);
}

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

// Coordinates 2^263 and subnormal in one orientation test: the scaled expansion would lose the
// products of the smallest coordinates, so these are evaluated in exact binary arithmetic. The
// pair is apart (the exact oracle's answer on a fuzz corpus input).
TEST(Orient, CoordinatesSpreadBeyondTheExpansionRangeAreExact) {
  using V = Vec2<double>;
  const ConvexPolygon<double> a{V(-0x1.050505050505p+262, 0x0.0001p-1022), V(-0x1.a828p+227, 0x0.000000000505p-1022),
                                V(0, 0x0.0008d0401505p-1022), V(-0x1.41414p+240, 0x1.050505050505p+262),
                                V(-0x1.050505050505p+262, 0x1.0bfdap+257)};
  const ConvexPolygon<double> b{V(0, 0), V(0x1.050505050505p-1018, 0), V(0x1.050505050505p+263, 0x1.0003f5050505p+257),
                                V(0x1.050505050505p+263, 0x1.050505050505p+262),
                                V(0x1.050505050505p-1018, 0x1.0003feep+257)};
  EXPECT_FALSE(overlaps(a, b));
  EXPECT_FALSE(overlaps(b, a));
  // Magnitudes 2^501 and 2^-1074 in one call: collinear (0), one unit off (+1), and a determinant
  // of exactly -t^2 = -2^-2148, which no double holds.
  const double t = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(orient(Vec2c(0, 0), Vec2c(0x1p500, t), Vec2c(0x1p501, 2 * t)), 0);
  EXPECT_EQ(orient(Vec2c(0, 0), Vec2c(0x1p500, t), Vec2c(0x1p501, 3 * t)), 1);
  EXPECT_EQ(orient(Vec2c(t, 0), Vec2c(0x1p500, t), Vec2c(0x1p501, 2 * t)), -1);
}

// ---------------------------------------------------------------------------------------------
// The exact number type and the filter behind every decision.

using detail::Bounded;
using detail::Exact;

/// (a + b)^2 - a^2 - 2ab - b^2 + e in number type N.
template <class N>
N expanded_square(double a, double b, double e) {
  const N x(a), y(b);
  return (x + y) * (x + y) - x * x - N(2.0) * x * y - y * y + N(e);
}

TEST(Exact, SumsKeepEveryBit) {
  // 2^500 + 2^-1074 - 2^500 is the smallest subnormal, not 0.
  const Exact big(0x1p500), tiny(std::numeric_limits<double>::denorm_min());
  EXPECT_EQ((big + tiny - big).sign(), 1);
  EXPECT_EQ((big - tiny - big).sign(), -1);
  EXPECT_EQ((big - big).sign(), 0);
  EXPECT_EQ((tiny - big).sign(), -1);
  EXPECT_EQ((-(tiny - big)).sign(), 1);
}

TEST(Exact, PolynomialIdentitiesAcrossTheRange) {
  // Degree-2 identities with terms 2^-1074 .. 2^501 apart: exact zero, and the sign of a
  // perturbation far below every term's rounding.
  const double values[] = {1.0, 0.1, -3.75e-200, 2.5e150, 0x1p500, -0x1p-1074, 0x1.fffffffffffffp-1022, 1e-300};
  for (double a : values) {
    for (double b : values) {
      EXPECT_EQ(expanded_square<Exact>(a, b, 0).sign(), 0) << a << " " << b;
      EXPECT_EQ(expanded_square<Exact>(a, b, 0x1p-1074).sign(), 1) << a << " " << b;
      EXPECT_EQ(expanded_square<Exact>(a, b, -0x1p-1074).sign(), -1) << a << " " << b;
    }
  }
  // A degree-6 product of extremes: (2^501 - 2^-1074)^6 > 0, and its difference from 2^3006 < 0.
  const Exact x = Exact(0x1p500) + Exact(0x1p500) - Exact(0x1p-1074);
  const Exact x6 = x * x * x * x * x * x;
  const Exact p = Exact(0x1p501) * Exact(0x1p501) * Exact(0x1p501) * Exact(0x1p501) * Exact(0x1p501) * Exact(0x1p501);
  EXPECT_EQ(x6.sign(), 1);
  EXPECT_EQ((x6 - p).sign(), -1);
}

TEST(Bounded, CertainSignsAreTheExactSigns) {
  // Where the running bound claims a sign, it is the exact sign; where the answer is 0 or below
  // the rounding, it claims none.
  const double values[] = {1.0, 0.1, -3.75e-200, 2.5e150, 0x1p500, -0x1p-1074, 1e-300, -7.0, 1e-17};
  int certain = 0;
  for (double a : values) {
    for (double b : values) {
      for (double e : {0.0, 1e-300, -1.0, 3.0, 0x1p-1074}) {
        const int s = expanded_square<Bounded>(a, b, e).certain_sign();
        const int x = expanded_square<Exact>(a, b, e).sign();
        if (s != 2) {
          ++certain;
          EXPECT_EQ(s, x) << a << " " << b << " " << e;
        }
        if (x == 0) {
          EXPECT_EQ(s, 2);
        }
      }
    }
  }
  EXPECT_GT(certain, 0);
}

}  // namespace
}  // namespace collide::test
