// raycast() on hand-computed cases for every kind (float and double), the documented edge cases
// (start inside, zero direction, NaN/inf, max_t bounds) and far/huge/tiny inputs that must not
// crash or produce NaN. Each expected hit is exact in closed form; the tolerance used is
// raycast_tolerance(), so a check fails only on an error larger than the documented bound.

#include "support.hpp"

#include <cmath>
#include <limits>

namespace collide::test {
namespace {

template <class T>
class Raycast : public ::testing::Test {};
TYPED_TEST_SUITE(Raycast, Scalars);

/// The hit exists, at parameter t (within delta / |direction|), point (within delta), and the
/// normal (within 1e-5: normals are rounded unit vectors).
template <class S, Scalar T>
void expect_hit(const S& s, const Ray<T>& ray, T max_t, double t, double px, double py, double nx, double ny) {
  const auto h = raycast(s, ray, max_t);
  ASSERT_TRUE(h.has_value()) << "expected a hit at t = " << t;
  const double delta = raycast_tolerance(s, ray);
  const double dlen = ray.direction.template cast<double>().norm();
  EXPECT_NEAR(double(h->t), t, 2 * delta / dlen);
  EXPECT_NEAR(double(h->point.x()), px, 2 * delta);
  EXPECT_NEAR(double(h->point.y()), py, 2 * delta);
  EXPECT_NEAR(double(h->normal.x()), nx, 1e-5);
  EXPECT_NEAR(double(h->normal.y()), ny, 1e-5);
  EXPECT_GE(h->t, T(0));
  EXPECT_LE(h->t, max_t);
}

template <Scalar T>
Ray<T> ray(T ox, T oy, T dx, T dy) {
  return Ray<T>{Vec2<T>(ox, oy), Vec2<T>(dx, dy)};
}

TYPED_TEST(Raycast, Circle) {
  using T = TypeParam;
  const Circle<T> c(Vec2<T>(0, 0), 1);
  expect_hit(c, ray<T>(-3, 0, 1, 0), T(10), 2, -1, 0, -1, 0);
  // t is in units of |direction|: a direction twice as long halves t (same point).
  expect_hit(c, ray<T>(-3, 0, 2, 0), T(10), 1, -1, 0, -1, 0);
  // Off-centre: the line y = 0.6 meets the circle at x = -0.8 (3-4-5), normal (-0.8, 0.6).
  expect_hit(c, ray<T>(-3, T(0.6), 1, 0), T(10), 2.2, -0.8, 0.6, -0.8, 0.6);
  // max_t is inclusive (closed): exactly reaching the surface hits; stopping short misses.
  expect_hit(c, ray<T>(-3, 0, 1, 0), T(2), 2, -1, 0, -1, 0);
  EXPECT_FALSE(raycast(c, ray<T>(-3, 0, 1, 0), T(1.9375)).has_value());
  // Pointing away, and passing by 2^-10 above the top (not within the error bound).
  EXPECT_FALSE(raycast(c, ray<T>(-3, 0, -1, 0), T(100)).has_value());
  EXPECT_FALSE(raycast(c, ray<T>(-3, T(1 + 0x1p-10), 1, 0), T(100)).has_value());
}

TYPED_TEST(Raycast, StartInsideZeroDirectionAndNonFinite) {
  using T = TypeParam;
  const Circle<T> c(Vec2<T>(0, 0), 1);
  // Inside: t = 0, normal = -direction normalised.
  expect_hit(c, ray<T>(0, T(0.5), 0, 3), T(1), 0, 0, 0.5, 0, -1);
  // On the boundary counts as inside (closed set).
  expect_hit(c, ray<T>(1, 0, 1, 0), T(1), 0, 1, 0, -1, 0);
  // Zero direction: a hit at t = 0 only when the origin is in the shape.
  const auto in = raycast(c, ray<T>(T(0.5), 0, 0, 0), T(1));
  ASSERT_TRUE(in.has_value());
  EXPECT_EQ(in->t, T(0));
  EXPECT_FALSE(raycast(c, ray<T>(2, 0, 0, 0), T(1)).has_value());
  // NaN / inf anywhere, or max_t < 0: no hit (documented), never a NaN hit.
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_FALSE(raycast(c, ray<T>(nan, 0, 1, 0), T(10)).has_value());
  EXPECT_FALSE(raycast(c, ray<T>(-3, 0, inf, 0), T(10)).has_value());
  EXPECT_FALSE(raycast(c, ray<T>(-3, 0, 1, nan), T(10)).has_value());
  EXPECT_FALSE(raycast(c, ray<T>(-3, 0, 1, 0), inf).has_value());
  EXPECT_FALSE(raycast(c, ray<T>(-3, 0, 1, 0), nan).has_value());
  EXPECT_FALSE(raycast(c, ray<T>(0, 0, 1, 0), T(-1)).has_value());  // even from inside
}

TYPED_TEST(Raycast, BoxesAndPolygons) {
  using T = TypeParam;
  const Aabb<T> box(Vec2<T>(1, -1), Vec2<T>(2, 1));
  expect_hit(box, ray<T>(0, 0, 1, 0), T(10), 1, 1, 0, -1, 0);
  expect_hit(box, ray<T>(T(1.5), 5, 0, -1), T(10), 4, 1.5, 1, 0, 1);
  // Grazing along the top edge y = 1: the closed box is hit where the edge begins.
  expect_hit(box, ray<T>(0, 1, 1, 0), T(10), 1, 1, 1, -1, 0);
  EXPECT_FALSE(raycast(box, ray<T>(0, T(1 + 0x1p-10), 1, 0), T(10)).has_value());
  // Hypotenuse x + y = 4 of a triangle, hit at (2, 2) from (4, 4).
  const ConvexPolygon<T> tri{Vec2<T>(0, 0), Vec2<T>(4, 0), Vec2<T>(0, 4)};
  const double r = std::sqrt(0.5);
  expect_hit(tri, ray<T>(4, 4, -1, -1), T(10), 2, 2, 2, r, r);
  // A ray along the line of an edge but beyond its end misses.
  EXPECT_FALSE(raycast(tri, ray<T>(5, 0, 1, 0), T(10)).has_value());
  // The 45-degree box: its vertex (-sqrt 2, 0) is hit first from the left.
  const Obb<T> diamond(Vec2<T>(0, 0), Vec2<T>(1, 1), T(std::atan(1.0)));
  const auto h = raycast(diamond, ray<T>(-5, 0, 1, 0), T(10));
  ASSERT_TRUE(h.has_value());
  EXPECT_NEAR(double(h->t), 5 - std::sqrt(2.0), (std::is_same_v<T, float> ? 1e-5 : 1e-12));
  // Hitting a face of the turned box: from (-5, -5) along (1, 1) to the face at distance 1.
  expect_hit(diamond, ray<T>(-5, -5, 1, 1), T(10), 5 - r, -r, -r, -r, -r);
}

// A needle from (0, 0) to (1, 1) whose other corner is 2^-60 along the x axis: the side from
// (2^-60, 0) to (1, 1) has direction (1 - 2^-60, 1), which rounds to (1, 1), so the two long sides
// become exactly parallel half-planes and their intersection a strip running on past (1, 1).
// Clipping against the half-planes alone reported a hit at (2, 2), outside the needle (found by
// the contact_raycast fuzz target with a 1.6e11-long needle in a compound).
TYPED_TEST(Raycast, NeedlePolygonIsNotHitPastItsSharpCorner) {
  using T = TypeParam;
  const ConvexPolygon<T> needle{Vec2<T>(0, 0), Vec2<T>(T(0x1p-60), 0), Vec2<T>(1, 1)};
  EXPECT_FALSE(raycast(needle, ray<T>(1, 0, 1, 2), T(10)).has_value());
  EXPECT_FALSE(raycast(needle, ray<T>(3, 0, -1, 2), T(10)).has_value());
  // Across the needle it is still hit, from both sides.
  const double r = std::sqrt(0.5);
  expect_hit(needle, ray<T>(T(0.5), 2, 0, -1), T(10), 1.5, 0.5, 0.5, -r, r);
  expect_hit(needle, ray<T>(T(0.5), -2, 0, 1), T(10), 2.5, 0.5, 0.5, r, -r);
}

TYPED_TEST(Raycast, Capsule) {
  using T = TypeParam;
  const Capsule<T> cap(Vec2<T>(0, 0), Vec2<T>(4, 0), 1);
  expect_hit(cap, ray<T>(2, 5, 0, -1), T(10), 4, 2, 1, 0, 1);    // the flat side
  expect_hit(cap, ray<T>(-5, 0, 1, 0), T(10), 4, -1, 0, -1, 0);  // the round end
  // The round end off-axis: line y = 0.6 meets the end disk at x = 4.8, normal (0.8, 0.6).
  expect_hit(cap, ray<T>(10, T(0.6), -1, 0), T(10), 5.2, 4.8, 0.6, 0.8, 0.6);
  // Zero radius: a segment, hit where the ray crosses it.
  const Capsule<T> seg(Vec2<T>(0, -1), Vec2<T>(0, 1), 0);
  expect_hit(seg, ray<T>(-2, T(0.5), 1, 0), T(10), 2, 0, 0.5, -1, 0);
  EXPECT_FALSE(raycast(seg, ray<T>(-2, 2, 1, 0), T(10)).has_value());
}

/// A ray reaching a capsule exactly where its round end meets its flat side: the rectangle
/// between the end disks is entered through its end and its side at once, and rounding made the
/// end (inside the capsule) the entering face. The normal must be the surface's, (0, 1).
TYPED_TEST(Raycast, CapsuleHitWhereTheEndMeetsTheSideHasTheSurfaceNormal) {
  using T = TypeParam;
  const T m = T(1048576);  // 2^20
  const Capsule<T> cap(Vec2<T>(-5 * m, -9 * m), Vec2<T>(-11 * m, -9 * m), m);
  // (1, -6) + t (-9, -3) reaches the top of the end disk, (-5, -8), at t = 2/3 (in units of m).
  expect_hit(cap, ray<T>(m, -6 * m, -9 * m, -3 * m), T(1), 2.0 / 3.0, -5.0 * m, -8.0 * m, 0, 1);
}

TYPED_TEST(Raycast, CompoundNearestChild) {
  using T = TypeParam;
  std::vector<Primitive<T>> kids;
  kids.emplace_back(Circle<T>(Vec2<T>(0, 0), 1));
  kids.emplace_back(Aabb<T>(Vec2<T>(3, -1), Vec2<T>(4, 1)));
  const Compound<T> comp(std::move(kids));
  expect_hit(comp, ray<T>(10, 0, -1, 0), T(100), 6, 4, 0, 1, 0);  // box child first
  expect_hit(comp, ray<T>(2, 0, 1, 0), T(100), 1, 3, 0, -1, 0);
  expect_hit(comp, ray<T>(2, 0, -1, 0), T(100), 1, 1, 0, 1, 0);         // circle child
  EXPECT_FALSE(raycast(comp, ray<T>(2, 5, 1, 0), T(100)).has_value());  // bounds early-out
  const std::vector<Shape<T>> whole = {comp};
  expect_hit(whole[0], ray<T>(10, 0, -1, 0), T(100), 6, 4, 0, 1, 0);  // variant dispatch
}

TYPED_TEST(Raycast, FarHugeAndTinyInputsStayFinite) {
  using T = TypeParam;
  const T big = std::numeric_limits<T>::max();
  const Circle<T> c(Vec2<T>(0, 0), 1);
  // Origin at the largest finite value: squares would overflow without the box clip.
  const auto far = raycast(c, ray<T>(-big, 0, 1, 0), big);
  ASSERT_TRUE(far.has_value());
  EXPECT_TRUE(std::isfinite(double(far->t)));
  EXPECT_NEAR(double(far->point.x()), -1.0, raycast_tolerance(c, ray<T>(-big, 0, 1, 0)));
  // Largest direction: |direction| overflows if computed naively; t is then tiny but finite.
  const auto huge_dir = raycast(c, ray<T>(-3, 0, big, big), T(1));
  EXPECT_FALSE(huge_dir.has_value());  // the diagonal from (-3, 0) passes 2.1 from the centre
  const auto huge_dir2 = raycast(c, ray<T>(-3, 0, big, 0), T(1));
  ASSERT_TRUE(huge_dir2.has_value());
  EXPECT_TRUE(std::isfinite(double(huge_dir2->t)));
  EXPECT_NEAR(double(huge_dir2->point.x()), -1.0, 1e-5);
  // Tiny shape and subnormal direction: distances square to zero unless rescaled, which would
  // report the origin (256 units of denorm_min away) as inside. The surface is 192 units away.
  const T tiny = std::numeric_limits<T>::denorm_min();
  const Circle<T> small(Vec2<T>(0, 0), tiny * 64);
  const auto h = raycast(small, ray<T>(-256 * tiny, 0, tiny, 0), big);
  ASSERT_TRUE(h.has_value());
  EXPECT_NEAR(double(h->t), 192.0, 1.0);
  EXPECT_NEAR(double(h->normal.x()), -1.0, 1e-5);
  // A subnormal direction cannot reach a shape 1 away within t <= max(): no hit.
  EXPECT_FALSE(raycast(Circle<T>(Vec2<T>(0, 0), 1), ray<T>(-2, 0, tiny, 0), big).has_value());
}

/// A float ray along a 5.9 x 10^34 direction meeting a circle 4.8 x 10^-9 away: the hit's t,
/// 58.88 denorm_min, is subnormal in float. Rounded to nearest it became 59 denorm_min, 9.6 x 10^-12
/// past the entry along the ray, and the ray point at t lay that deep inside the circle, beyond
/// raycast_tolerance(). The contract says no ray point before t is deeper than that: the point at
/// t itself (computed in double) must be no deeper either.
TEST(RaycastRegression, SubnormalHitTimeStopsShortOfTheSurface) {
  using V = Vec2<float>;
  const Circle<float> c = *Circle<float>::make(V(0x1.6d04a8p-21f, -0x1.812a9ep-74f), 0x1.6a6a6ap-21f);
  const Ray<float> r{V(0x1.a9a8p-136f, 0x1.6a6a62p-63f), V(0x1.6a11d8p+115f, 0x1.cb08p-134f)};
  const auto h = raycast(c, r, 0x1.fep-142f);
  ASSERT_TRUE(h.has_value());
  ASSERT_GT(h->t, 0.0f);
  const Vec2c at = widen(r.origin) + widen(r.direction) * double(h->t);
  const double depth = double(c.radius()) - (at - widen(c.center())).norm();
  EXPECT_LE(depth, raycast_tolerance(c, r)) << "the ray point at t lies inside the circle";
}

}  // namespace
}  // namespace collide::test
