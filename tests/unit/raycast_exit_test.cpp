// raycast_exit() on hand-computed cases for every kind (float and double): where a ray that
// starts inside leaves, with the outward normal there; a compound left where the union ends, not
// where the first child does; origins outside, rays still inside at max_t, zero directions and
// bad input. Expected exits are exact in closed form; the tolerance is raycast_exit_tolerance().

#include "support.hpp"

#include <cmath>
#include <limits>

namespace collide::test {
namespace {

template <class T>
class RaycastExit : public ::testing::Test {};
TYPED_TEST_SUITE(RaycastExit, Scalars);

template <Scalar T>
Ray<T> ray(T ox, T oy, T dx, T dy) {
  return Ray<T>{Vec2<T>(ox, oy), Vec2<T>(dx, dy)};
}

/// The exit exists, at parameter t (within delta / |direction|), point (within delta), and the
/// normal (within 1e-5: normals are rounded unit vectors).
template <class S, Scalar T>
void expect_exit(const S& s, const Ray<T>& r, T max_t, double t, double px, double py, double nx, double ny) {
  const auto h = raycast_exit(s, r, max_t);
  ASSERT_TRUE(h.has_value()) << "expected an exit at t = " << t;
  const double delta = raycast_exit_tolerance(s, r);
  const double dlen = r.direction.template cast<double>().norm();
  EXPECT_NEAR(double(h->t), t, 2 * delta / dlen);
  EXPECT_NEAR(double(h->point.x()), px, 2 * delta);
  EXPECT_NEAR(double(h->point.y()), py, 2 * delta);
  EXPECT_NEAR(double(h->normal.x()), nx, 1e-5);
  EXPECT_NEAR(double(h->normal.y()), ny, 1e-5);
  EXPECT_GE(h->t, T(0));
  EXPECT_LE(h->t, max_t);
}

TYPED_TEST(RaycastExit, Circle) {
  using T = TypeParam;
  const Circle<T> c(Vec2<T>(0, 0), 5);
  expect_exit(c, ray<T>(0, 0, 1, 0), T(10), 5, 5, 0, 1, 0);
  // t is in units of |direction|.
  expect_exit(c, ray<T>(0, 0, 2, 0), T(10), 2.5, 5, 0, 1, 0);
  // Off-centre chord: from (0, 3) along +x the circle is left at (4, 3) (3-4-5), normal (0.8, 0.6).
  expect_exit(c, ray<T>(0, 3, 1, 0), T(10), 4, 4, 3, 0.8, 0.6);
  // From (-4, 3) the ray crosses the whole chord: 8 long.
  expect_exit(c, ray<T>(-4, 3, 1, 0), T(10), 8, 4, 3, 0.8, 0.6);
  // On the boundary heading out: exit at t = 0 with the normal there.
  expect_exit(c, ray<T>(5, 0, 1, 1), T(10), 0, 5, 0, 1, 0);
  // On the boundary heading in: across the circle.
  expect_exit(c, ray<T>(5, 0, -1, 0), T(20), 10, -5, 0, -1, 0);
}

TYPED_TEST(RaycastExit, BoxesAndPolygon) {
  using T = TypeParam;
  const Aabb<T> box(Vec2<T>(-1, -2), Vec2<T>(3, 2));
  expect_exit(box, ray<T>(0, 0, 1, 0), T(10), 3, 3, 0, 1, 0);
  expect_exit(box, ray<T>(0, 0, 0, -1), T(10), 2, 0, -2, 0, -1);
  expect_exit(box, ray<T>(0, 0, -1, 1), T(10), 1, -1, 1, -1, 0);
  // On a side heading out at a slant: exit at t = 0 through that side, its normal.
  expect_exit(box, ray<T>(3, 0, 1, 1), T(10), 0, 3, 0, 1, 0);
  // The far side reached exactly at max_t: still inside there (the closed box), normal (0, 0).
  const auto at_end = raycast_exit(box, ray<T>(0, 0, 1, 0), T(3));
  ASSERT_TRUE(at_end.has_value());
  EXPECT_EQ(at_end->t, T(3));
  EXPECT_EQ(at_end->normal, Vec2<T>::Zero());
  // An OBB turned a quarter: half extents (2, 1) along y and -x.
  const Obb<T> obb = Obb<T>::make_with_axis(Vec2<T>(0, 0), Vec2<T>(2, 1), Vec2<T>(0, 1)).value();
  expect_exit(obb, ray<T>(0, 0, 1, 0), T(10), 1, 1, 0, 1, 0);
  expect_exit(obb, ray<T>(0, 0, 0, 1), T(10), 2, 0, 2, 0, 1);
  // A triangle, left through its slanted side x + y = 2.
  const ConvexPolygon<T> tri({Vec2<T>(0, 0), Vec2<T>(2, 0), Vec2<T>(0, 2)});
  const double h = std::sqrt(0.5);
  expect_exit(tri, ray<T>(T(0.5), T(0.5), 1, 1), T(10), 0.5, 1, 1, h, h);
  expect_exit(tri, ray<T>(T(0.5), T(0.5), 0, -1), T(10), 0.5, 0.5, 0, 0, -1);
}

TYPED_TEST(RaycastExit, Capsule) {
  using T = TypeParam;
  const Capsule<T> cap(Vec2<T>(0, 0), Vec2<T>(4, 0), 1);
  // Along the axis: out through the far end's cap.
  expect_exit(cap, ray<T>(0, 0, 1, 0), T(10), 5, 5, 0, 1, 0);
  // Across the side.
  expect_exit(cap, ray<T>(2, 0, 0, 1), T(10), 1, 2, 1, 0, 1);
  // From the rectangle out through a cap: at y = 0.6 the cap around (4, 0) ends at x = 4.8.
  expect_exit(cap, ray<T>(1, T(0.6), 1, 0), T(10), 3.8, 4.8, 0.6, 0.8, 0.6);
}

TYPED_TEST(RaycastExit, CompoundLeavesTheUnion) {
  using T = TypeParam;
  // Two overlapping boxes and a circle touching the second one's right side: the ray along +x
  // leaves the first box at x = 2, but the union only at the circle's far side, x = 7.
  const Compound<T> comp(std::vector<Primitive<T>>{Aabb<T>(Vec2<T>(-1, -1), Vec2<T>(2, 1)),
                                                   Aabb<T>(Vec2<T>(1, -1), Vec2<T>(4, 1)),
                                                   Circle<T>(Vec2<T>(5.5, 0), T(1.5))});
  expect_exit(comp, ray<T>(0, 0, 1, 0), T(20), 7, 7, 0, 1, 0);
  // Children listed in another order change nothing.
  const Compound<T> reversed(std::vector<Primitive<T>>{Circle<T>(Vec2<T>(5.5, 0), T(1.5)),
                                                       Aabb<T>(Vec2<T>(1, -1), Vec2<T>(4, 1)),
                                                       Aabb<T>(Vec2<T>(-1, -1), Vec2<T>(2, 1))});
  expect_exit(reversed, ray<T>(0, 0, 1, 0), T(20), 7, 7, 0, 1, 0);
  // A gap stops the ray: a box beyond it is not reached.
  const Compound<T> gap(
      std::vector<Primitive<T>>{Aabb<T>(Vec2<T>(-1, -1), Vec2<T>(2, 1)), Aabb<T>(Vec2<T>(3, -1), Vec2<T>(5, 1))});
  expect_exit(gap, ray<T>(0, 0, 1, 0), T(20), 2, 2, 0, 1, 0);
  // Through the variant as well.
  expect_exit(Shape<T>(comp), ray<T>(0, 0, 1, 0), T(20), 7, 7, 0, 1, 0);
}

TYPED_TEST(RaycastExit, StillInsideOutsideAndBadInput) {
  using T = TypeParam;
  const Circle<T> c(Vec2<T>(0, 0), 5);
  // Still inside at max_t: t = max_t, normal (0, 0).
  const auto stays = raycast_exit(c, ray<T>(0, 0, 1, 0), T(2));
  ASSERT_TRUE(stays.has_value());
  EXPECT_EQ(stays->t, T(2));
  EXPECT_EQ(stays->point, Vec2<T>(2, 0));
  EXPECT_EQ(stays->normal, Vec2<T>::Zero());
  // A zero direction never leaves.
  const auto still = raycast_exit(c, ray<T>(1, 1, 0, 0), T(3));
  ASSERT_TRUE(still.has_value());
  EXPECT_EQ(still->t, T(3));
  EXPECT_EQ(still->normal, Vec2<T>::Zero());
  // Outside, even aimed at the shape: nothing (raycast() answers that).
  EXPECT_FALSE(raycast_exit(c, ray<T>(-6, 0, 1, 0), T(100)).has_value());
  // max_t = 0 from inside: the ray is the origin alone, inside.
  const auto none_long = raycast_exit(c, ray<T>(0, 0, 1, 0), T(0));
  ASSERT_TRUE(none_long.has_value());
  EXPECT_EQ(none_long->t, T(0));
  EXPECT_EQ(none_long->normal, Vec2<T>::Zero());
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_FALSE(raycast_exit(c, ray<T>(0, 0, 1, 0), nan).has_value());
  EXPECT_FALSE(raycast_exit(c, ray<T>(0, 0, 1, 0), inf).has_value());
  EXPECT_FALSE(raycast_exit(c, ray<T>(0, 0, 1, 0), T(-1)).has_value());
  EXPECT_FALSE(raycast_exit(c, ray<T>(0, 0, nan, 0), T(1)).has_value());
  EXPECT_FALSE(raycast_exit(c, ray<T>(nan, 0, 1, 0), T(1)).has_value());
}

TYPED_TEST(RaycastExit, FarAndTinyScales) {
  using T = TypeParam;
  // A tiny circle (squares underflow without the exact rescaling) and a huge box.
  const T tiny = std::is_same_v<T, float> ? T(0x1p-120f) : T(0x1p-480);
  const Circle<T> small(Vec2<T>(0, 0), tiny);
  expect_exit(small, ray<T>(0, 0, 0, 1), T(1), double(tiny), 0, double(tiny), 0, 1);
  const T big = std::is_same_v<T, float> ? T(0x1p120f) : T(0x1p490);
  const Aabb<T> huge(Vec2<T>(-big, -big), Vec2<T>(big, big));
  expect_exit(huge, ray<T>(0, 0, 1, 0), big * 2, double(big), double(big), 0, 1, 0);
}

}  // namespace
}  // namespace collide::test
