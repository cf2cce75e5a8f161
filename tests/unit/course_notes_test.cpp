// The course notes' worked cases, one by one, for float and double. Each value is exactly
// representable, so every expectation is the exact answer, with no tolerance.

#include "support.hpp"

namespace collide::test {
namespace {

template <class T>
class CourseNotes : public ::testing::Test {};
TYPED_TEST_SUITE(CourseNotes, Scalars);

TYPED_TEST(CourseNotes, CircleCircleAroundTheBoundary) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Centres 5 apart (3-4-5): radii summing to exactly 5 touch. A squared-distance test with a
  // strict '<' (or a sqrt that rounds down) fails the touching case.
  const Circle<T> a(V(0, 0), 2);
  EXPECT_TRUE(overlaps(a, Circle<T>(V(3, 4), 3)));
  // 2^-20 either side of the boundary: far above the error bound (about 1e-14 here), so a
  // rounding error this large in the sum of radii or the squared distance would show.
  EXPECT_FALSE(overlaps(a, Circle<T>(V(3, 4), T(3 - 0x1p-20))));
  EXPECT_TRUE(overlaps(a, Circle<T>(V(3, 4), T(3 + 0x1p-20))));
  // Same, moving the centre instead of the radius.
  EXPECT_FALSE(overlaps(a, Circle<T>(V(T(3 + 0x1p-18), 4), 3)));
  EXPECT_TRUE(overlaps(a, Circle<T>(V(T(3 - 0x1p-18), 4), 3)));
  // Concentric, and one inside the other: a test on outlines (CGAL's Circle_2 trap) says false.
  EXPECT_TRUE(overlaps(a, Circle<T>(V(0, 0), T(0.5))));
  EXPECT_TRUE(overlaps(Circle<T>(V(0, 0), T(0.5)), a));
}

TYPED_TEST(CourseNotes, AabbFourNonCollisionCasesOneByOne) {
  using T = TypeParam;
  using V = Vec2<T>;
  // a's min.x (0) differs from its min.y (10) so that comparing against the wrong coordinate
  // (the course notes' `b.max.y < a.min.x` slip) changes the answer in case 4.
  const Aabb<T> a(V(0, 10), V(2, 12));
  // Each b overlaps a on the other axis, so exactly one of the four conditions separates them.
  const Aabb<T> right(V(3, 10), V(5, 12));   // a.max.x < b.min.x
  const Aabb<T> left(V(-5, 10), V(-1, 12));  // b.max.x < a.min.x
  const Aabb<T> above(V(0, 13), V(2, 15));   // a.max.y < b.min.y
  const Aabb<T> below(V(0, 5), V(2, 8));     // b.max.y < a.min.y
  EXPECT_FALSE(overlaps(a, right));
  EXPECT_FALSE(overlaps(a, left));
  EXPECT_FALSE(overlaps(a, above));
  EXPECT_FALSE(overlaps(a, below));
  EXPECT_FALSE(overlaps(below, a));
  // The same four, touching: closed boxes sharing an edge overlap (a strict '<=' slip fails).
  EXPECT_TRUE(overlaps(a, Aabb<T>(V(2, 10), V(5, 12))));
  EXPECT_TRUE(overlaps(a, Aabb<T>(V(-5, 10), V(0, 12))));
  EXPECT_TRUE(overlaps(a, Aabb<T>(V(0, 12), V(2, 15))));
  EXPECT_TRUE(overlaps(a, Aabb<T>(V(0, 5), V(2, 10))));
  // Corner to corner.
  EXPECT_TRUE(overlaps(a, Aabb<T>(V(2, 12), V(3, 13))));
}

TYPED_TEST(CourseNotes, CircleVsAabbUsesTheClosestPoint) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> box(V(0, 0), V(1, 1));
  // Near the corner: the circle's bounding box overlaps the box but the circle does not (the
  // corner is sqrt(2) ~ 1.414 away). A box-vs-box shortcut says true here.
  EXPECT_FALSE(overlaps(Circle<T>(V(2, 2), T(1.375)), box));
  EXPECT_TRUE(overlaps(Circle<T>(V(2, 2), T(1.4375)), box));
  // Touching an edge exactly, and the centre inside the box (clamping gives distance 0).
  EXPECT_TRUE(overlaps(Circle<T>(V(T(1.5), T(0.5)), T(0.5)), box));
  EXPECT_FALSE(overlaps(Circle<T>(V(T(1.5), T(0.5)), T(0.5 - 0x1p-20)), box));
  EXPECT_TRUE(overlaps(Circle<T>(V(T(0.5), T(0.5)), T(0.125)), box));
  // Touching the corner exactly: distance (3, 4) from the corner (1, 1), radius 5.
  EXPECT_TRUE(overlaps(Circle<T>(V(4, 5), 5), box));
  EXPECT_FALSE(overlaps(Circle<T>(V(4, 5), T(5 - 0x1p-18)), box));
}

TYPED_TEST(CourseNotes, PolygonPolygonBySeparatingAxes) {
  using T = TypeParam;
  using V = Vec2<T>;
  const ConvexPolygon<T> a{V(0, 0), V(4, 0), V(0, 4)};
  // Separated only by the axis of a's hypotenuse (x + y = 4): their bounding boxes overlap, and
  // no axis-aligned axis separates them. Skipping the hypotenuse's normal says true.
  EXPECT_FALSE(overlaps(a, ConvexPolygon<T>{V(3, 3), V(5, 3), V(3, 5)}));
  // Separated only by an axis of b (its edge on x + 2y = 9; a reaches 8 along it): none of a's
  // three edge normals separates, so a check of only a's edges says true.
  const ConvexPolygon<T> b{V(1, 4), V(0, 8), V(-2, T(5.5))};
  EXPECT_FALSE(overlaps(a, b));
  EXPECT_FALSE(overlaps(b, a));
  EXPECT_TRUE(overlaps(a, ConvexPolygon<T>{V(4, 0), V(4, 4), V(0, 4)}));  // touching along x + y = 4
  // Vertex of b exactly on a's hypotenuse: touching (orient() == 0 must count as overlapping).
  EXPECT_TRUE(overlaps(a, ConvexPolygon<T>{V(2, 2), V(4, 2), V(2, 4)}));
  EXPECT_TRUE(overlaps(a, ConvexPolygon<T>{V(1, 1), V(4, 2), V(2, 4)}));
  // One inside the other: no edges cross; the test must still say true.
  EXPECT_TRUE(overlaps(a, ConvexPolygon<T>{V(T(0.5), T(0.5)), V(1, T(0.5)), V(T(0.5), 1)}));
}

TYPED_TEST(CourseNotes, AabbResolutionPicksTheShortestOfFourCandidates) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> a(V(0, 0), V(4, 3));
  const Aabb<T> b(V(3, 1), V(10, 9));
  // The four candidate pushes of a: left by a.max.x - b.min.x = 1, right by b.max.x - a.min.x
  // = 10, down by a.max.y - b.min.y = 2, up by b.max.y - a.min.y = 9.
  const V candidates[4] = {V(-1, 0), V(10, 0), V(0, -2), V(0, 9)};
  const Calc lengths[4] = {1, 10, 2, 9};
  for (int i = 0; i < 4; ++i) {
    // Each candidate, lengthened by a hair, separates; shortened by a hair it does not.
    const Calc len = lengths[i];
    const V longer = (candidates[i].template cast<Calc>() * ((len + 0x1p-10) / len)).template cast<T>();
    const V shorter = (candidates[i].template cast<Calc>() * ((len - 0x1p-10) / len)).template cast<T>();
    EXPECT_FALSE(overlaps(translated(a, longer).value(), b)) << i;
    EXPECT_TRUE(overlaps(translated(a, shorter).value(), b)) << i;
  }
  // resolve() picks the shortest (left by 1), plus at most its documented margin (doubled once
  // for the rounding of the cast to T).
  const V v = resolve(a, b);
  EXPECT_LT(v.x(), T(-1));
  EXPECT_GE(double(v.x()), -1 - 2 * resolve_margin(a, b, 1.0, V(1, 0)));
  EXPECT_EQ(v.y(), T(0));
  EXPECT_FALSE(overlaps(translated(a, v).value(), b));
  const auto c = contact(a, b);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->normal, V(1, 0));  // from a toward b
  EXPECT_EQ(c->depth, T(1));
}

}  // namespace
}  // namespace collide::test
