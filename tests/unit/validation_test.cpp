// Every validation error of every factory, by name and index, for float and double; and the
// throwing constructors. A failure means bad input would slip into a shape (and later into a
// query as NaN, an inverted box or a reflex polygon) or be reported under the wrong name/index.

#include "support.hpp"

#include <limits>
#include <string>

namespace collide::test {
namespace {

template <class T>
class Validation : public ::testing::Test {};
TYPED_TEST_SUITE(Validation, Scalars);

template <class E>
void expect_error(const E& r, Error code, long index) {
  ASSERT_FALSE(r.has_value()) << "accepted bad input, expected " << name(code);
  EXPECT_EQ(r.error().code(), code) << "got " << name(r.error().code()) << ": " << r.error().what();
  EXPECT_EQ(r.error().index(), index) << r.error().what();
  // The message starts with the stable error name.
  EXPECT_EQ(std::string(r.error().what()).rfind(std::string(name(code)), 0), 0u) << r.error().what();
}

template <Scalar T>
constexpr T nan_v() {
  return std::numeric_limits<T>::quiet_NaN();
}
template <Scalar T>
constexpr T inf_v() {
  return std::numeric_limits<T>::infinity();
}
/// Finite but above max_magnitude<T>() (2^125 for float, 2^500 for double).
template <Scalar T>
constexpr T too_big() {
  return max_magnitude<T>() * T(2);
}

TYPED_TEST(Validation, Circle) {
  using T = TypeParam;
  using V = Vec2<T>;
  expect_error(Circle<T>::make(V(nan_v<T>(), 0), 1), Error::NonFinite, 0);
  expect_error(Circle<T>::make(V(0, inf_v<T>()), 1), Error::NonFinite, 1);
  expect_error(Circle<T>::make(V(0, 0), -inf_v<T>()), Error::NonFinite, 2);
  expect_error(Circle<T>::make(V(0, too_big<T>()), 1), Error::OutOfRange, 1);
  expect_error(Circle<T>::make(V(0, 0), too_big<T>()), Error::OutOfRange, 2);
  expect_error(Circle<T>::make(V(0, 0), T(-1)), Error::NegativeRadius, -1);
  // Smallest negative radius: a sign test, not a "< -epsilon" test.
  expect_error(Circle<T>::make(V(0, 0), -std::numeric_limits<T>::denorm_min()), Error::NegativeRadius, -1);
  // Boundary values are valid: radius 0, magnitude exactly max_magnitude, subnormal.
  EXPECT_TRUE(Circle<T>::make(V(0, 0), T(0)).has_value());
  EXPECT_TRUE(Circle<T>::make(V(max_magnitude<T>(), -max_magnitude<T>()), max_magnitude<T>()).has_value());
  EXPECT_TRUE(
      Circle<T>::make(V(std::numeric_limits<T>::denorm_min(), 0), std::numeric_limits<T>::denorm_min()).has_value());
  EXPECT_THROW(Circle<T>(V(0, 0), T(-1)), ShapeError);
}

TYPED_TEST(Validation, Aabb) {
  using T = TypeParam;
  using V = Vec2<T>;
  expect_error(Aabb<T>::make(V(nan_v<T>(), 0), V(1, 1)), Error::NonFinite, 0);
  expect_error(Aabb<T>::make(V(0, 0), V(1, nan_v<T>())), Error::NonFinite, 3);
  expect_error(Aabb<T>::make(V(0, 0), V(too_big<T>(), 1)), Error::OutOfRange, 2);
  expect_error(Aabb<T>::make(V(1, 0), V(0, 1)), Error::MinGreaterThanMax, 0);
  expect_error(Aabb<T>::make(V(0, 1), V(1, 0)), Error::MinGreaterThanMax, 1);
  EXPECT_TRUE(Aabb<T>::make(V(1, 1), V(1, 1)).has_value());  // a point is a valid (closed) box
  EXPECT_THROW(Aabb<T>(V(1, 0), V(0, 1)), ShapeError);
}

TYPED_TEST(Validation, Obb) {
  using T = TypeParam;
  using V = Vec2<T>;
  expect_error(Obb<T>::make(V(0, 0), V(1, 1), nan_v<T>()), Error::NonFinite, 4);
  expect_error(Obb<T>::make(V(0, 0), V(inf_v<T>(), 1), T(0)), Error::NonFinite, 2);
  expect_error(Obb<T>::make(V(too_big<T>(), 0), V(1, 1), T(0)), Error::OutOfRange, 0);
  expect_error(Obb<T>::make(V(0, 0), V(-1, 1), T(0)), Error::NegativeExtent, 0);
  expect_error(Obb<T>::make(V(0, 0), V(1, -1), T(0)), Error::NegativeExtent, 1);
  expect_error(Obb<T>::make_with_axis(V(0, 0), V(1, 1), V(0, 0)), Error::ZeroAxis, -1);
  expect_error(Obb<T>::make_with_axis(V(0, 0), V(1, 1), V(0, nan_v<T>())), Error::NonFinite, 5);
  // A subnormal axis is a direction, not zero: hypot in double must not underflow it away.
  EXPECT_TRUE(Obb<T>::make_with_axis(V(0, 0), V(1, 1), V(std::numeric_limits<T>::denorm_min(), 0)).has_value());
  EXPECT_THROW(Obb<T>(V(0, 0), V(-1, 1), T(0)), ShapeError);
}

TYPED_TEST(Validation, ObbFromCorners) {
  using T = TypeParam;
  using V = Vec2<T>;
  expect_error(Obb<T>::from_corners(V(0, 0), V(2, 0), V(2, nan_v<T>()), V(0, 1)), Error::NonFinite, 5);
  expect_error(Obb<T>::from_corners(V(0, 0), V(2, 0), V(2, 1), V(0, too_big<T>())), Error::OutOfRange, 7);
  // A parallelogram that is not a rectangle, and a quadrilateral that is not a parallelogram.
  expect_error(Obb<T>::from_corners(V(0, 0), V(2, 0), V(3, 1), V(1, 1)), Error::NotARectangle, -1);
  expect_error(Obb<T>::from_corners(V(0, 0), V(2, 0), V(2, 1), V(0, 2)), Error::NotARectangle, -1);
  // A rotated rectangle (3-4-5 edges, exact) in either winding is accepted, with half extents 2.5, 5.
  for (bool reverse : {false, true}) {
    const V p0(0, 0), p1(4, 3), p2(-2, 11), p3(-6, 8);
    const auto r = reverse ? Obb<T>::from_corners(p3, p2, p1, p0) : Obb<T>::from_corners(p0, p1, p2, p3);
    ASSERT_TRUE(r.has_value());
    const V c = r.value().center();
    EXPECT_NEAR(double(c.x()), -1.0, 1e-6);
    EXPECT_NEAR(double(c.y()), 5.5, 1e-6);
  }
}

TYPED_TEST(Validation, Capsule) {
  using T = TypeParam;
  using V = Vec2<T>;
  expect_error(Capsule<T>::make(V(0, 0), V(nan_v<T>(), 0), 1), Error::NonFinite, 2);
  expect_error(Capsule<T>::make(V(0, 0), V(1, 0), too_big<T>()), Error::OutOfRange, 4);
  expect_error(Capsule<T>::make(V(0, 0), V(1, 0), T(-0.5)), Error::NegativeRadius, -1);
  EXPECT_TRUE(Capsule<T>::make(V(0, 0), V(0, 0), T(1)).has_value());  // a == b is a circle
  EXPECT_THROW(Capsule<T>(V(0, 0), V(1, 0), T(-1)), ShapeError);
}

TYPED_TEST(Validation, Polygon) {
  using T = TypeParam;
  using V = Vec2<T>;
  expect_error(ConvexPolygon<T>::make({V(0, 0), V(1, 0), V(0, inf_v<T>())}), Error::NonFinite, 5);
  expect_error(ConvexPolygon<T>::make({V(0, 0), V(too_big<T>(), 0), V(0, 1)}), Error::OutOfRange, 2);
  expect_error(ConvexPolygon<T>::make({V(0, 0), V(1, 1)}), Error::TooFewVertices, -1);
  // Repeats merge (including last == first), leaving two distinct vertices.
  expect_error(ConvexPolygon<T>::make({V(0, 0), V(1, 1), V(1, 1), V(0, 0)}), Error::TooFewVertices, -1);
  expect_error(ConvexPolygon<T>::make({V(0, 0), V(1, 1), V(3, 3)}), Error::Collinear, -1);
  // Reflex vertex: input index 3 in both windings (given clockwise it is still input vertex 1).
  expect_error(ConvexPolygon<T>::make({V(0, 0), V(4, 0), V(4, 4), V(2, 1), V(0, 4)}), Error::NonConvex, 3);
  expect_error(ConvexPolygon<T>::make({V(0, 4), V(2, 1), V(4, 4), V(4, 0), V(0, 0)}), Error::NonConvex, 1);
  // Doubling back along a line at input vertex 1 (the spike (0,0) -> (2,0) -> (1,0)).
  expect_error(ConvexPolygon<T>::make({V(0, 0), V(2, 0), V(1, 0), V(1, 1)}), Error::NonConvex, 1);
  // A pentagram: every turn is to the same side but the boundary goes round twice.
  {
    const auto r = ConvexPolygon<T>::make({V(0, 10), V(6, -8), V(-10, 3), V(10, 3), V(-6, -8)});
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().code(), Error::NonConvex);
    EXPECT_GE(r.error().index(), 0);
    EXPECT_LT(r.error().index(), 5);
  }
  // Accepted: clockwise input is re-wound; a straight-through collinear vertex is dropped.
  {
    const auto r = ConvexPolygon<T>::make({V(0, 0), V(0, 2), V(2, 2), V(2, 1), V(2, 0)});
    ASSERT_TRUE(r.has_value());
    EXPECT_EQ(r.value().size(), 4u);
    const auto v = r.value().vertices();
    for (std::size_t i = 0; i < v.size(); ++i) {
      EXPECT_GT(orient(widen(v[i]), widen(v[(i + 1) % v.size()]), widen(v[(i + 2) % v.size()])), 0);
    }
  }
  EXPECT_THROW((ConvexPolygon<T>{V(0, 0), V(1, 1), V(2, 2)}), ShapeError);
}

TYPED_TEST(Validation, PolygonHull) {
  using T = TypeParam;
  using V = Vec2<T>;
  const std::vector<V> nan_pts = {V(0, 0), V(1, 0), V(nan_v<T>(), 1)};
  expect_error(ConvexPolygon<T>::make_hull(nan_pts), Error::NonFinite, 4);
  const std::vector<V> two = {V(0, 0), V(1, 0), V(0, 0), V(1, 0)};
  expect_error(ConvexPolygon<T>::make_hull(two), Error::TooFewVertices, -1);
  const std::vector<V> line = {V(0, 0), V(2, 2), V(1, 1), V(3, 3)};
  expect_error(ConvexPolygon<T>::make_hull(line), Error::Collinear, -1);
  // Interior and edge points are dropped: the hull of a square's corners, centre and edge midpoint.
  const std::vector<V> pts = {V(1, 1), V(0, 0), V(2, 0), V(2, 2), V(0, 2), V(1, 0)};
  const auto r = ConvexPolygon<T>::make_hull(pts);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r.value().size(), 4u);
}

TYPED_TEST(Validation, Compound) {
  using T = TypeParam;
  expect_error(Compound<T>::make({}), Error::EmptyCompound, -1);
  EXPECT_THROW(Compound<T>(std::vector<Primitive<T>>{}), ShapeError);
  // A valid compound whose bounding box exceeds max_magnitude (child at the limit with a radius at
  // the limit) must be accepted, not rejected by its own cached box.
  const T m = max_magnitude<T>();
  std::vector<Primitive<T>> kids;
  kids.emplace_back(Circle<T>(Vec2<T>(m, m), m));
  const auto r = Compound<T>::make(std::move(kids));
  ASSERT_TRUE(r.has_value());
  EXPECT_GE(double(r.value().bounds().max().x()), 2.0 * double(m));
}

TYPED_TEST(Validation, TranslatedReportsOutOfRange) {
  using T = TypeParam;
  using V = Vec2<T>;
  const T m = max_magnitude<T>();
  const auto r = translated(Circle<T>(V(m, 0), 1), V(m, 0));
  expect_error(r, Error::OutOfRange, 0);
}

TYPED_TEST(Validation, ExpectedGivesItsValueLikeAPointerOrAFallback) {
  using T = TypeParam;
  using V = Vec2<T>;
  const auto good = Circle<T>::make(V(1, 2), T(3));
  ASSERT_TRUE(good);
  EXPECT_EQ((*good).radius(), T(3));
  EXPECT_EQ(good->center(), V(1, 2));
  const Circle<T> fallback(V(0, 0), T(7));
  EXPECT_EQ(good.value_or(fallback).radius(), T(3));
  const auto bad = Circle<T>::make(V(1, 2), T(-3));
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.value_or(fallback).radius(), T(7));
  EXPECT_EQ(Circle<T>::make(V(1, 2), T(-3)).value_or(fallback).radius(), T(7));
  EXPECT_THROW((void)*bad, std::bad_variant_access);
}

TEST(ShapeErrorMessage, NamesTheErrorAndIndexAndIsCutToItsBuffer) {
  const ShapeError e(Error::NonConvex, 12, "polygon turns the wrong way");
  EXPECT_STREQ(e.what(), "NonConvex: polygon turns the wrong way (index 12)");
  const ShapeError none(Error::EmptyCompound, -1, "compound has no children");
  EXPECT_STREQ(none.what(), "EmptyCompound: compound has no children");
  const std::string long_text(500, 'x');
  const ShapeError cut(Error::Collinear, 3, long_text);
  const std::string_view m = cut.what();
  EXPECT_LT(m.size(), long_text.size());
  EXPECT_EQ(m.substr(0, 11), "Collinear: ");
}

TEST(ErrorNames, AreStable) {
  EXPECT_EQ(name(Error::NonFinite), "NonFinite");
  EXPECT_EQ(name(Error::OutOfRange), "OutOfRange");
  EXPECT_EQ(name(Error::NegativeRadius), "NegativeRadius");
  EXPECT_EQ(name(Error::NegativeExtent), "NegativeExtent");
  EXPECT_EQ(name(Error::MinGreaterThanMax), "MinGreaterThanMax");
  EXPECT_EQ(name(Error::ZeroAxis), "ZeroAxis");
  EXPECT_EQ(name(Error::TooFewVertices), "TooFewVertices");
  EXPECT_EQ(name(Error::Collinear), "Collinear");
  EXPECT_EQ(name(Error::NonConvex), "NonConvex");
  EXPECT_EQ(name(Error::NotARectangle), "NotARectangle");
  EXPECT_EQ(name(Error::EmptyCompound), "EmptyCompound");
  EXPECT_EQ(name(Error::ZeroRotation), "ZeroRotation");
}

}  // namespace
}  // namespace collide::test
