// contains(outer, inner) on hand-built cases for every kind of outer (float and double): shapes
// held with room, touching the boundary from inside (counts), poking out by one ulp (does not),
// the same shape twice, compounds as inner shapes, and the refused compound outer. Every expected
// answer is exact: the shapes are chosen so that the exact answer is known in closed form.

#include "support.hpp"

#include <cmath>
#include <limits>

namespace collide::test {
namespace {

/// contains(outer, inner) compiles for this pair.
template <class O, class I>
concept ContainsCompiles = requires(const O& o, const I& i) {
  contains(o, i);
};
// A compound outer is refused at compile time; a compound inner is answered.
static_assert(!ContainsCompiles<Compound<float>, Circle<float>>);
static_assert(!ContainsCompiles<Compound<double>, Compound<double>>);
static_assert(ContainsCompiles<Circle<float>, Compound<float>>);
static_assert(ContainsCompiles<Primitive<double>, Shape<double>>);

template <class T>
class ContainsShape : public ::testing::Test {};
TYPED_TEST_SUITE(ContainsShape, Scalars);

template <Scalar T>
T above(T x) {
  return std::nextafter(x, std::numeric_limits<T>::infinity());
}

TYPED_TEST(ContainsShape, CircleOuter) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> big(V(0, 0), 5);
  EXPECT_TRUE(contains(big, big));                               // itself
  EXPECT_TRUE(contains(big, Circle<T>(V(3, 0), 2)));             // touching inside at (5, 0)
  EXPECT_FALSE(contains(big, Circle<T>(V(3, 0), above(T(2)))));  // one ulp too wide
  EXPECT_TRUE(contains(big, Circle<T>(V(0, 3), 2)));             // touching at (0, 5)
  // A 3-4-5 box corner on the circle: inside; the corner one ulp further out: not.
  EXPECT_TRUE(contains(big, Aabb<T>(V(-3, -4), V(3, 4))));
  EXPECT_FALSE(contains(big, Aabb<T>(V(-3, -4), V(3, above(T(4))))));
  // A capsule whose end discs touch the rim from inside.
  EXPECT_TRUE(contains(big, Capsule<T>(V(-3, 0), V(3, 0), 2)));
  EXPECT_FALSE(contains(big, Capsule<T>(V(-3, 0), V(above(T(3)), 0), 2)));
  // A larger circle never fits, even concentric.
  EXPECT_FALSE(contains(Circle<T>(V(0, 0), 2), big));
}

TYPED_TEST(ContainsShape, BoxOuter) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> box(V(-4, -2), V(4, 2));
  EXPECT_TRUE(contains(box, box));
  EXPECT_TRUE(contains(box, Circle<T>(V(2, 0), 2)));  // touching top, bottom and right
  EXPECT_FALSE(contains(box, Circle<T>(V(above(T(2)), 0), 2)));
  EXPECT_TRUE(contains(box, Capsule<T>(V(-2, 0), V(2, 0), 2)));
  EXPECT_TRUE(contains(box, ConvexPolygon<T>({V(-4, -2), V(4, -2), V(0, 2)})));  // corners on the sides
  EXPECT_FALSE(contains(box, ConvexPolygon<T>({V(-4, -2), V(4, -2), V(0, above(T(2)))})));
  // An OBB turned a quarter, half extents (2, 4) along y and -x: the box itself.
  const Obb<T> turned = Obb<T>::make_with_axis(V(0, 0), V(2, 4), V(0, 1)).value();
  EXPECT_TRUE(contains(box, turned));
  EXPECT_TRUE(contains(turned, box));
  EXPECT_FALSE(contains(box, Aabb<T>(V(-4, -2), V(above(T(4)), 2))));
}

TYPED_TEST(ContainsShape, ObbCapsuleAndPolygonOuter) {
  using T = TypeParam;
  using V = Vec2<T>;
  // An OBB turned a quarter (axis (0, 1), half extents (2, 4)): x in [-4, 4], y in [-2, 2].
  const Obb<T> turned = Obb<T>::make_with_axis(V(0, 0), V(2, 4), V(0, 1)).value();
  EXPECT_TRUE(contains(turned, Circle<T>(V(2, 0), 2)));
  EXPECT_FALSE(contains(turned, Circle<T>(V(above(T(2)), 0), 2)));
  EXPECT_TRUE(contains(turned, ConvexPolygon<T>({V(-4, -2), V(4, -2), V(0, 2)})));
  EXPECT_FALSE(contains(turned, ConvexPolygon<T>({V(-4, -2), V(4, -2), V(0, above(T(2)))})));
  // A diagonal OBB (its axis rounded when normalised): it holds itself exactly, corner on corner,
  // and a copy one ulp longer does not fit.
  const Obb<T> diag = Obb<T>::make_with_axis(V(1, 1), V(3, 1), V(1, 1)).value();
  EXPECT_TRUE(contains(diag, diag));
  EXPECT_TRUE(contains(diag, Obb<T>::make_with_axis(V(1, 1), V(2, 1), V(1, 1)).value()));
  EXPECT_FALSE(contains(diag, Obb<T>::make_with_axis(V(1, 1), V(above(T(3)), 1), V(1, 1)).value()));
  EXPECT_TRUE(contains(diag, Circle<T>(V(1, 1), T(0.5))));
  EXPECT_FALSE(contains(diag, Circle<T>(V(1, 1), T(1.001))));  // wider than the short side
  // A capsule: a circle at one end with the same radius is inside, touching.
  const Capsule<T> cap(V(0, 0), V(6, 0), 2);
  EXPECT_TRUE(contains(cap, Circle<T>(V(6, 0), 2)));
  EXPECT_TRUE(contains(cap, Aabb<T>(V(0, -2), V(6, 2))));  // the rectangle between the ends
  EXPECT_FALSE(contains(cap, Aabb<T>(V(0, -2), V(6, above(T(2))))));
  EXPECT_FALSE(contains(cap, Aabb<T>(V(-2, -2), V(6, 2))));  // a corner past the rounded end
  // A polygon: its own vertices, and a circle touching two of its sides.
  const ConvexPolygon<T> sq({V(0, 0), V(4, 0), V(4, 4), V(0, 4)});
  EXPECT_TRUE(contains(sq, sq));
  EXPECT_TRUE(contains(sq, Circle<T>(V(2, 2), 2)));
  EXPECT_FALSE(contains(sq, Circle<T>(V(2, 2), above(T(2)))));
  EXPECT_TRUE(contains(sq, Capsule<T>(V(1, 1), V(3, 3), 1)));
}

TYPED_TEST(ContainsShape, CompoundsAndVariants) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> box(V(0, 0), V(10, 10));
  const Compound<T> inner(std::vector<Primitive<T>>{Circle<T>(V(2, 2), 2), Aabb<T>(V(5, 5), V(10, 10))});
  EXPECT_TRUE(contains(box, inner));  // every child inside, touching
  const Compound<T> out(std::vector<Primitive<T>>{Circle<T>(V(2, 2), 2), Aabb<T>(V(5, 5), V(10, above(T(10))))});
  EXPECT_FALSE(contains(box, out));  // one child pokes out
  // Through the variants: a primitive outer answers, a compound outer is refused by name.
  EXPECT_TRUE(contains(Primitive<T>(box), Shape<T>(inner)));
  const Expected<bool> via_shape = contains(Shape<T>(box), inner);
  ASSERT_TRUE(via_shape.has_value());
  EXPECT_TRUE(*via_shape);
  const Expected<bool> refused = contains(Shape<T>(inner), Circle<T>(V(2, 2), 1));
  ASSERT_FALSE(refused.has_value());
  EXPECT_EQ(refused.error().code(), Error::CompoundOuter);
  EXPECT_EQ(name(Error::CompoundOuter), "CompoundOuter");
  // Placed children: a child moved by its transform is judged where it is placed.
  const Compound<T> placed =
      Compound<T>::make_placed({{Primitive<T>(Circle<T>(V(0, 0), 2)), Transform<T>(V(8, 8), T(0))}}).value();
  EXPECT_TRUE(contains(box, placed));
  const Compound<T> placed_out =
      Compound<T>::make_placed({{Primitive<T>(Circle<T>(V(0, 0), 2)), Transform<T>(V(9, 8), T(0))}}).value();
  EXPECT_FALSE(contains(box, placed_out));
}

}  // namespace
}  // namespace collide::test
