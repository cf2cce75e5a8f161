// contains() on hand-computed cases: exact to the last ulp for every kind (contains_tolerance()
// is 0); NaN/inf points; tiny and huge shapes.

#include "support.hpp"

#include <cmath>
#include <limits>

namespace collide::test {
namespace {

template <class T>
class Contains : public ::testing::Test {};
TYPED_TEST_SUITE(Contains, Scalars);

template <Scalar T>
T up(T x) {
  return std::nextafter(x, std::numeric_limits<T>::infinity());
}
template <Scalar T>
T down(T x) {
  return std::nextafter(x, -std::numeric_limits<T>::infinity());
}

TYPED_TEST(Contains, AabbIsExactToTheUlp) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> box(V(0, 0), V(1, 1));
  EXPECT_TRUE(contains(box, V(1, 1)));  // closed: the corner belongs to the box
  EXPECT_TRUE(contains(box, V(0, T(0.5))));
  EXPECT_FALSE(contains(box, V(1, up(T(1)))));         // one ulp out
  EXPECT_FALSE(contains(box, V(down(T(0)), T(0.5))));  // the smallest negative subnormal out
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_FALSE(contains(box, V(nan, T(0.5))));
  EXPECT_FALSE(contains(box, V(inf, inf)));
}

TYPED_TEST(Contains, PolygonIsExactToTheUlp) {
  using T = TypeParam;
  using V = Vec2<T>;
  // On the hypotenuse x + y = 4, and one ulp beyond it: only an exact orient() separates them.
  const ConvexPolygon<T> tri{V(0, 0), V(4, 0), V(0, 4)};
  EXPECT_TRUE(contains(tri, V(2, 2)));
  EXPECT_FALSE(contains(tri, V(2, up(T(2)))));
  EXPECT_TRUE(contains(tri, V(2, down(T(2)))));
  // The same at 2^100 (about 1.3e30): exactness does not depend on scale.
  const T s = T(0x1p100);
  const ConvexPolygon<T> big{V(0, 0), V(4 * s, 0), V(0, 4 * s)};
  EXPECT_TRUE(contains(big, V(2 * s, 2 * s)));
  EXPECT_FALSE(contains(big, V(2 * s, up(T(2 * s)))));
  // A vertex of a skewed triangle, and one ulp outside it along x.
  const ConvexPolygon<T> skew{V(0, 0), V(3, 0), V(0, 7)};
  EXPECT_TRUE(contains(skew, V(3, 0)));
  EXPECT_FALSE(contains(skew, V(up(T(3)), 0)));
}

TYPED_TEST(Contains, RoundShapesAndObb) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> c(V(0, 0), 5);
  EXPECT_TRUE(contains(c, V(3, 4)));  // exactly on the circle (3-4-5)
  EXPECT_FALSE(contains(c, V(3, T(4 + 0x1p-18))));
  EXPECT_TRUE(contains(c, V(3, T(4 - 0x1p-18))));
  const Capsule<T> cap(V(0, 0), V(4, 0), 1);
  EXPECT_TRUE(contains(cap, V(2, 1)));
  EXPECT_FALSE(contains(cap, V(2, T(1 + 0x1p-18))));
  EXPECT_TRUE(contains(cap, V(T(4.6), T(0.8))));  // on the end disk: (0.6, 0.8) from (4, 0)
  EXPECT_FALSE(contains(cap, V(T(4.6 + 0x1p-18), T(0.8))));
  EXPECT_TRUE(contains(cap, V(5, 0)));
  // The 45-degree square: its vertex is at x = sqrt(2) ~ 1.41421.
  const Obb<T> diamond(V(0, 0), V(1, 1), T(std::atan(1.0)));
  EXPECT_TRUE(contains(diamond, V(T(1.40625), 0)));
  EXPECT_FALSE(contains(diamond, V(T(1.421875), 0)));
  EXPECT_FALSE(contains(diamond, V(1, 1)));  // corner of the unturned square: outside
  EXPECT_EQ(contains_tolerance(c, V(3, 4)), 0.0);
}

TYPED_TEST(Contains, RoundShapesAndObbAreExactToTheUlp) {
  using T = TypeParam;
  using V = Vec2<T>;
  for (const T s : {T(1), T(0x1p-60), T(0x1p60), T(0x1p-100), T(0x1p100)}) {
    SCOPED_TRACE(double(s));
    // On the circle (3-4-5), then one ulp out and in.
    const Circle<T> c(V(0, 0), 5 * s);
    EXPECT_TRUE(contains(c, V(3 * s, 4 * s)));
    EXPECT_FALSE(contains(c, V(3 * s, up(4 * s))));
    EXPECT_TRUE(contains(c, V(3 * s, down(4 * s))));
    // On a capsule's end disk, at an offset.
    const T o = T(0x1p20) * s;  // an offset of about 1e6 sizes; o + 7 s stays exact in float
    const Capsule<T> cap(V(o, o), V(o + 4 * s, o), 5 * s);
    EXPECT_TRUE(contains(cap, V(o + 7 * s, o + 4 * s)));
    EXPECT_FALSE(contains(cap, V(up(o + 7 * s), o + 4 * s)));
    EXPECT_TRUE(contains(cap, V(o + 7 * s, down(o + 4 * s))));
    // A turned box: its face midpoint c + h u is exact (h a power of two times s).
    const Obb<T> obb(V(0, 0), V(4 * s, 2 * s), T(0.3));
    const V u = obb.axis();
    const V mid = u * (4 * s);
    EXPECT_TRUE(contains(obb, mid));
    EXPECT_FALSE(contains(obb, V(up(mid.x()), mid.y())));  // u.x > 0: one ulp outward
    EXPECT_TRUE(contains(obb, V(down(mid.x()), mid.y())));
  }
}

TYPED_TEST(Contains, CompoundIsTheUnion) {
  using T = TypeParam;
  using V = Vec2<T>;
  std::vector<Primitive<T>> kids;
  kids.emplace_back(Circle<T>(V(0, 0), 1));
  kids.emplace_back(Aabb<T>(V(3, -1), V(4, 1)));
  const Compound<T> comp(std::move(kids));
  EXPECT_TRUE(contains(comp, V(T(0.5), 0)));
  EXPECT_TRUE(contains(comp, V(4, 1)));
  EXPECT_FALSE(contains(comp, V(2, 0)));  // inside the bounding box, in neither child
  EXPECT_FALSE(contains(comp, V(10, 0)));
  EXPECT_TRUE(contains(Shape<T>(comp), V(T(3.5), 0)));
  EXPECT_TRUE(contains(Primitive<T>(Circle<T>(V(0, 0), 1)), V(1, 0)));
}

TYPED_TEST(Contains, TinyRoundShapesAreRelativeAccurate) {
  using T = TypeParam;
  using V = Vec2<T>;
  // A circle of radius 64 units of denorm_min: the squares of these distances underflow to 0 in
  // double, so without exact rescaling every point within ~2^-537 would count as inside.
  const T d = std::numeric_limits<T>::denorm_min();
  const Circle<T> c(V(0, 0), 64 * d);
  EXPECT_TRUE(contains(c, V(64 * d, 0)));
  EXPECT_TRUE(contains(c, V(0, -63 * d)));
  EXPECT_FALSE(contains(c, V(65 * d, 0)));
  EXPECT_FALSE(contains(c, V(46 * d, 46 * d)));  // 46 * sqrt(2) = 65.05 > 64
  EXPECT_TRUE(contains(c, V(45 * d, 45 * d)));   // 45 * sqrt(2) = 63.6 < 64
  const Capsule<T> cap(V(0, 0), V(0, 128 * d), 8 * d);
  EXPECT_TRUE(contains(cap, V(8 * d, 64 * d)));
  EXPECT_FALSE(contains(cap, V(9 * d, 64 * d)));
}

}  // namespace
}  // namespace collide::test
