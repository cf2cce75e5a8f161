/// compare_depth on depths computed by hand, and within_band for primitives and compounds.

#include "collide/oracle/oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace collide::oracle {
namespace {

using V = Vec2<double>;

/// depth(a, b) == len exactly: equal at len, above and below one step away.
template <class A, class B>
void expect_depth(const A& a, const B& b, double len, double step = 1e-12) {
  EXPECT_EQ(oracle::compare_depth(a, b, len), 0) << len;
  EXPECT_EQ(oracle::compare_depth(a, b, len - step), 1) << len;
  EXPECT_EQ(oracle::compare_depth(a, b, len + step), -1) << len;
  EXPECT_EQ(oracle::compare_depth(b, a, len), 0) << "reversed " << len;
}

TEST(OracleDepth, Circles) {
  expect_depth(Circle<double>(V(0, 0), 1.0), Circle<double>(V(1, 0), 1.0), 1.0);
  expect_depth(Circle<double>(V(0, 0), 1.0), Circle<double>(V(3, 4), 4.5), 0.5);
  expect_depth(Circle<double>(V(2, 2), 1.0), Circle<double>(V(2, 2), 0.25), 1.25);  // same center
}

TEST(OracleDepth, IrrationalDepthIsBracketed) {
  // depth = 2 - sqrt(2): never equal to a double.
  const Circle<double> a(V(0, 0), 1.0), b(V(1, 1), 1.0);
  const double approx = 2.0 - std::sqrt(2.0);
  EXPECT_NE(oracle::compare_depth(a, b, approx), 0);
  EXPECT_EQ(oracle::compare_depth(a, b, approx - 1e-15), 1);
  EXPECT_EQ(oracle::compare_depth(a, b, approx + 1e-15), -1);
}

TEST(OracleDepth, Boxes) {
  // [0,2]^2 against [1.5,3.5]x[0,2]: the x overlap 0.5 is the least push.
  expect_depth(Aabb<double>(V(0, 0), V(2, 2)), Aabb<double>(V(1.5, 0), V(3.5, 2)), 0.5);
  // Touching boxes: depth 0.
  expect_depth(Aabb<double>(V(0, 0), V(2, 2)), Aabb<double>(V(2, 1), V(3, 3)), 0.0);
  // Small box inside a big one: the big box slides left until its right side (10) reaches the
  // small box's left side (8).
  expect_depth(Aabb<double>(V(0, 0), V(10, 10)), Aabb<double>(V(8, 4), V(9, 6)), 2.0);
}

TEST(OracleDepth, CircleAgainstBox) {
  // Center outside the box: r - distance to the box.
  expect_depth(Circle<double>(V(0, 0), 1.0), Aabb<double>(V(0.5, -1), V(3, 1)), 0.5);
  // Center inside the box: distance to the nearest side + r.
  expect_depth(Circle<double>(V(0, 0), 0.5), Aabb<double>(V(-1, -2), V(3, 2)), 1.5);
  // Rotated box (axis (0, 1): exact unit), center inside.
  expect_depth(Circle<double>(V(0, 0), 0.5), Obb<double>::make_with_axis(V(0, 0), V(3, 1), V(0, 1)).value(), 1.5);
}

TEST(OracleDepth, CapsulesAndPolygons) {
  expect_depth(Capsule<double>(V(0, 0), V(4, 0), 1.0), Circle<double>(V(2, 1.5), 1.0), 0.5);
  // Point (radius-0 circle) inside a right triangle: nearest edges are the legs, at 1.
  const ConvexPolygon<double> tri({V(0, 0), V(4, 0), V(0, 4)});
  expect_depth(Circle<double>(V(1, 1), 0.0), tri, 1.0);
  // Crossing capsules (an X): the cores' difference is the square [-1,1]^2 around the origin, so
  // depth = 1 + the radii 0.25 + 0.25.
  expect_depth(Capsule<double>(V(-1, 0), V(1, 0), 0.25), Capsule<double>(V(0, -1), V(0, 1), 0.25), 1.5);
  // Apart: depth 0.
  expect_depth(Capsule<double>(V(0, 0), V(1, 0), 0.5), Capsule<double>(V(0, 3), V(1, 3), 0.5), 0.0);
}

TEST(OracleDepth, CompoundsOfSeveralChildrenAreUnsupported) {
  const Compound<double> c({Circle<double>(V(0, 0), 1.0), Circle<double>(V(5, 0), 1.0)});
  EXPECT_THROW(oracle::compare_depth(c, Circle<double>(V(0, 0), 1.0), 1.0), Unsupported);
  EXPECT_THROW(oracle::compare_depth(Circle<double>(V(0, 0), 1.0), c, 1.0), Unsupported);
}

TEST(OracleDepth, ACompoundOfOneChildIsThatChildPlacedByItsTransform) {
  // A unit circle moved to (0.5, 0) by its child transform, then the body turned a quarter and
  // moved by (1, 0): its centre is at (1, 0.5), so a unit circle at (1, 2) overlaps it 0.5 deep.
  using Child = Compound<double>::Child;
  const Compound<double> c =
      Compound<double>::make_placed(
          {Child{Circle<double>(V(0, 0), 1.0), Transform<double>::make_translation(V(0.5, 0)).value()}})
          .value();
  const oracle::Placed placed(Shape<double>(c), V(1, 0), V(0, 1));
  const Circle<double> other(V(1, 2), 1.0);
  EXPECT_EQ(oracle::compare_depth(placed, other, 0.5), 0);
  EXPECT_EQ(oracle::compare_depth(other, placed, 0.25), 1);
  EXPECT_EQ(oracle::compare_boundary_distance(placed, V(1, 0.5), 1.0), 0);  // its centre, 1 from the boundary
  EXPECT_NEAR(oracle::approx_signed_distance(placed, other), -0.5, 1e-12);
}

TEST(OracleBand, PrimitivesUseTheSignedDistance) {
  const Circle<double> a(V(0, 0), 1.0);
  const Circle<double> apart(V(3, 0), 1.0);   // gap 1
  const Circle<double> deep(V(1.5, 0), 1.0);  // depth 0.5
  EXPECT_TRUE(oracle::within_band(a, apart, 1.0));
  EXPECT_FALSE(oracle::within_band(a, apart, 0.999));
  EXPECT_TRUE(oracle::within_band(a, deep, 0.5));
  EXPECT_FALSE(oracle::within_band(a, deep, 0.499));
  EXPECT_TRUE(oracle::within_band(a, Circle<double>(V(2, 0), 1.0), 0.0));  // touching: sigma = 0
}

TEST(OracleBand, CompoundWithNoOverlappingChildUsesTheSmallestGap) {
  const Compound<double> two({Circle<double>(V(0, 0), 1.0), Circle<double>(V(10, 0), 1.0)});
  const Circle<double> c(V(3, 0), 1.0);  // gaps 1 and 5
  EXPECT_TRUE(oracle::within_band(two, c, 1.0));
  EXPECT_FALSE(oracle::within_band(two, c, 0.99));
  EXPECT_TRUE(oracle::within_band(c, two, 1.0));
}

TEST(OracleBand, CompoundWithOverlapsNeedsEveryOverlappingChildShallow) {
  const Compound<double> two({Circle<double>(V(0, 0), 1.0), Circle<double>(V(10, 0), 1.0)});
  // Overlaps the second child by 0.5; the first child's gap (9.5) does not matter.
  const Circle<double> c(V(11.5, 0), 1.0);
  EXPECT_TRUE(oracle::within_band(two, c, 0.5));
  EXPECT_FALSE(oracle::within_band(two, c, 0.49));
  // A capsule overlapping both children, by 0.5 and by 0.2: all must be within the band.
  const Capsule<double> bar(V(1.5, 0), V(8.2, 0), 1.0);
  EXPECT_FALSE(oracle::within_band(two, bar, 0.3));
  EXPECT_TRUE(oracle::within_band(two, bar, 0.5));
  EXPECT_TRUE(oracle::within_band(bar, two, 0.5));
  // Two compounds.
  const Compound<double> other({Circle<double>(V(1.5, 0), 1.0), Aabb<double>(V(20, 20), V(21, 21))});
  EXPECT_TRUE(oracle::within_band(two, other, 0.5));
  EXPECT_FALSE(oracle::within_band(two, other, 0.4));
}

TEST(OraclePassesDeeper, ABoxCrossedAlongItsMiddleIsAsDeepAsItsHalfHeight) {
  const Aabb<double> box(V(0, 0), V(4, 1));
  EXPECT_TRUE(oracle::passes_deeper(box, V(-1, 0.5), V(5, 0.5), 0.499));
  EXPECT_FALSE(oracle::passes_deeper(box, V(-1, 0.5), V(5, 0.5), 0.5));
  // Stopping 0.25 inside: the deepest point is the end.
  EXPECT_TRUE(oracle::passes_deeper(box, V(-1, 0.5), V(0.25, 0.5), 0.2499));
  EXPECT_FALSE(oracle::passes_deeper(box, V(-1, 0.5), V(0.25, 0.5), 0.25));
  // One point: its own depth.
  EXPECT_TRUE(oracle::passes_deeper(box, V(2, 0.3), V(2, 0.3), 0.29));
  EXPECT_FALSE(oracle::passes_deeper(box, V(2, 0.3), V(2, 0.3), 0.3));
  EXPECT_FALSE(oracle::passes_deeper(box, V(-1, 2), V(5, 2), 0.0));  // apart
}

TEST(OraclePassesDeeper, AThinSlabCrossedIsNeverDeeperThanHalfItsThickness) {
  const Obb<double> slab = Obb<double>::make_with_axis(V(0, 0), V(1e22, 1e6), V(0.6, 0.8)).value();
  EXPECT_FALSE(oracle::passes_deeper(slab, V(-3e7, -4e6), V(3e7, 4e6), 1e6));
  EXPECT_TRUE(oracle::passes_deeper(slab, V(-3e7, -4e6), V(3e7, 4e6), 0.99e6));
}

TEST(OraclePassesDeeper, DisksAndCapsulesAreDeepNearTheirCores) {
  const Circle<double> disk(V(0, 0), 1.0);
  EXPECT_TRUE(oracle::passes_deeper(disk, V(-2, 0.6), V(2, 0.6), 0.399));
  EXPECT_FALSE(oracle::passes_deeper(disk, V(-2, 0.6), V(2, 0.6), 0.4));
  const Capsule<double> bar(V(0, 0), V(4, 0), 1.0);
  EXPECT_TRUE(oracle::passes_deeper(bar, V(2, -3), V(2, 3), 0.999));
  EXPECT_FALSE(oracle::passes_deeper(bar, V(2, -3), V(2, 3), 1.0));
  EXPECT_FALSE(oracle::passes_deeper(bar, V(5.5, -3), V(5.5, 3), 0.0));  // past the end: outside
}

TEST(OraclePassesDeeper, APolygonsDepthIsItsLeastDistanceToAnEdgeLine) {
  // Inradius 2 - sqrt(2), at (r, r): never equal to a double.
  const ConvexPolygon<double> tri({V(0, 0), V(2, 0), V(0, 2)});
  const double r = 2.0 - std::sqrt(2.0);
  EXPECT_TRUE(oracle::passes_deeper(tri, V(-1, r), V(3, r), r - 1e-12));
  EXPECT_FALSE(oracle::passes_deeper(tri, V(-1, r), V(3, r), r + 1e-12));
  // Through a vertex only: depth 0 there.
  EXPECT_FALSE(oracle::passes_deeper(tri, V(-1, 3), V(1, 1), 0.0));
  EXPECT_TRUE(oracle::passes_deeper(tri, V(-1, 3), V(1, 0.9), 0.0));
}

TEST(OraclePassesDeeper, PlacedShapesAndCompoundsAnswerChildByChild) {
  // Two unit boxes side by side: together 2 wide, but each child is only 0.5 deep.
  const Compound<double> two({Aabb<double>(V(0, 0), V(1, 1)), Aabb<double>(V(1, 0), V(2, 1))});
  EXPECT_FALSE(oracle::passes_deeper(two, V(-1, 0.5), V(3, 0.5), 0.5));
  EXPECT_TRUE(oracle::passes_deeper(two, V(1.5, 0.5), V(1.5, 0.5), 0.49));
  // The box [0, 4] x [0, 1] turned a quarter and moved by (10, 0): [9, 10] x [0, 4].
  const Placed turned =
      oracle::placed(Aabb<double>(V(0, 0), V(4, 1)), Transform<double>::make_with_rotation(V(10, 0), V(0, 1)).value());
  EXPECT_TRUE(oracle::passes_deeper(turned, V(9.5, -1), V(9.5, 5), 0.49));
  EXPECT_FALSE(oracle::passes_deeper(turned, V(9.5, -1), V(9.5, 5), 0.5));
  EXPECT_FALSE(oracle::passes_deeper(turned, V(0.5, -1), V(0.5, 5), 0.0));  // where it was
}

}  // namespace
}  // namespace collide::oracle
