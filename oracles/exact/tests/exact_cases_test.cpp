/// Hand-made cases whose answers follow from exact arithmetic on the stored values, including
/// touching cases that rounded double arithmetic gets wrong, and the CGAL traps the oracle avoids.

#include "collide/oracle/oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace collide::oracle {
namespace {

using V = Vec2<double>;

double next_up(double x) {
  return std::nextafter(x, std::numeric_limits<double>::infinity());
}
double next_down(double x) {
  return std::nextafter(x, -std::numeric_limits<double>::infinity());
}

ConvexPolygon<double> square(double x0, double y0, double side) {
  return ConvexPolygon<double>({V(x0, y0), V(x0 + side, y0), V(x0 + side, y0 + side), V(x0, y0 + side)});
}

TEST(OracleExact, CirclesApartByLessThanTheRoundingOfTheirRadii) {
  // r = 1 + (2^-52 - 2^-60) rounds to 1 + 2^-52 = the center distance, so rounded arithmetic sees
  // them touching; exactly, the gap is 2^-60.
  const Circle<double> a(V(0, 0), 1.0);
  const Circle<double> b(V(1.0 + 0x1p-52, 0), 0x1p-52 - 0x1p-60);
  const double d = 1.0 + 0x1p-52, r = 1.0 + (0x1p-52 - 0x1p-60);
  ASSERT_LE(d * d, r * r);  // the rounded test says "overlap"
  EXPECT_FALSE(oracle::overlaps(a, b));
  EXPECT_EQ(oracle::compare_distance(a, b, 0x1p-60), 0);
  EXPECT_EQ(oracle::compare_distance(a, b, 0x1p-61), 1);
  EXPECT_EQ(oracle::compare_distance(a, b, 0x1p-59), -1);
  EXPECT_TRUE(oracle::within_band(a, b, 0x1p-60));
  EXPECT_FALSE(oracle::within_band(a, b, 0x1p-61));
  EXPECT_FALSE(oracle::separates(a, b, V(0x1p-60, 0)));  // moved onto b: touching
  EXPECT_TRUE(oracle::separates(a, b, V(0x1p-61, 0)));
  EXPECT_TRUE(oracle::separates(a, b, V(0, 0)));
}

TEST(OracleExact, DecimalValuesAreTheirExactBinaryValues) {
  // 0.1 + 0.2 as exact binary values exceeds the double 0.3: circles of radii 0.1 and 0.2 at
  // distance 0.3 overlap by about 2.8e-17, although neither sum nor distance shows it in double.
  const Circle<double> a(V(0, 0), 0.1), b(V(0.3, 0), 0.2);
  EXPECT_TRUE(oracle::overlaps(a, b));
  EXPECT_EQ(oracle::compare_depth(a, b, 0.0), 1);
  EXPECT_EQ(oracle::compare_depth(a, b, 1e-16), -1);
  EXPECT_EQ(oracle::compare_depth(a, b, 0x1p-55), 0);  // the depth is exactly 2^-55
  // 0.1 + 0.2 rounds up to 0.30000000000000004 while the exact sum lies just below that double:
  // at that distance the circles are apart, by less than one ulp.
  const Circle<double> c(V(0.30000000000000004, 0), 0.2);
  EXPECT_FALSE(oracle::overlaps(a, c));
  EXPECT_EQ(oracle::compare_distance(a, c, 0x1p-53), -1);
  EXPECT_EQ(oracle::compare_distance(a, c, 0x1p-55), 0);  // the gap is exactly 2^-55
}

TEST(OracleExact, ObbUsesItsStoredAxisExactly) {
  // axis (3, 4) is stored as (0.6, 0.8) rounded: |u| is not exactly 1. The exact box is still
  // center +- hx*u +- hy*v, so c + u is the midpoint of an edge (on the boundary).
  const Obb<double> box = Obb<double>::make_with_axis(V(0, 0), V(1, 2), V(3, 4)).value();
  const V u = box.axis(), v(-u.y(), u.x());
  // Exactly, |u|^2 = 1 + 4.4e-17: projecting c + u on a unit-length axis would put it outside.
  EXPECT_TRUE(oracle::contains(box, u));
  EXPECT_TRUE(oracle::contains(box, V(-u)));
  EXPECT_TRUE(oracle::contains(box, V(2 * v)));
  EXPECT_TRUE(oracle::contains(box, V(-2 * v)));
  EXPECT_FALSE(oracle::contains(box, V(next_up(u.x()), next_up(u.y()))));
  EXPECT_FALSE(oracle::contains(box, V(2 * v.x() * (1 + 0x1p-40), 2 * v.y() * (1 + 0x1p-40))));
  EXPECT_EQ(oracle::compare_boundary_distance(box, u, 0.0), 0);
  // A circle of radius 0 at the edge midpoint touches; a point circle one ulp out does not.
  EXPECT_TRUE(oracle::overlaps(box, Circle<double>(u, 0.0)));
  EXPECT_FALSE(oracle::overlaps(box, Circle<double>(V(next_up(u.x()), next_up(u.y())), 0.0)));
  // An AABB whose corner is exactly c + u.
  EXPECT_TRUE(oracle::overlaps(box, Aabb<double>(u, u + V(1, 1))));
}

TEST(OracleExact, CircleInsideCircleOverlaps) {
  // CGAL's do_intersect(Circle_2, Circle_2) tests outlines and returns false here.
  const Circle<double> big(V(0, 0), 10.0), small(V(1, 1), 0.5);
  EXPECT_TRUE(oracle::overlaps(big, small));
  EXPECT_TRUE(oracle::overlaps(small, big));
  EXPECT_EQ(oracle::compare_depth(big, small, 10.5 - std::sqrt(2.0) + 1e-9), -1);
  EXPECT_EQ(oracle::compare_depth(big, small, 10.5 - std::sqrt(2.0) - 1e-9), 1);
}

TEST(OracleExact, CircleAndBoxContainingOneAnother) {
  // do_intersect(Circle_2, Iso_rectangle_2) also tests the outline.
  const Circle<double> c(V(0, 0), 1.0);
  EXPECT_TRUE(oracle::overlaps(c, Aabb<double>(V(-0.1, -0.1), V(0.1, 0.1))));
  EXPECT_TRUE(oracle::overlaps(c, Aabb<double>(V(-5, -5), V(5, 5))));
}

TEST(OracleExact, SquaresSharingOnlyAnEdgeOrAVertexOverlap) {
  // Regularised Boolean operations report no intersection for these.
  EXPECT_TRUE(oracle::overlaps(square(0, 0, 1), square(1, 0, 1)));    // shared edge
  EXPECT_TRUE(oracle::overlaps(square(0, 0, 1), square(1, 1, 1)));    // shared vertex
  EXPECT_TRUE(oracle::overlaps(square(0, 0, 1), square(1, 0.5, 1)));  // partly shared edge
  EXPECT_FALSE(oracle::overlaps(square(0, 0, 1), square(next_up(1.0), 1, 1)));
  EXPECT_TRUE(oracle::overlaps(Aabb<double>(V(0, 0), V(1, 1)), Aabb<double>(V(1, 1), V(2, 2))));
  EXPECT_TRUE(oracle::overlaps(Aabb<double>(V(0, 0), V(1, 1)), square(1, 0, 1)));
  // Vertex of a diamond exactly on a square's edge.
  const ConvexPolygon<double> diamond({V(1, 0.5), V(1.5, 0), V(2, 0.5), V(1.5, 1)});
  EXPECT_TRUE(oracle::overlaps(square(0, 0, 1), diamond));
  EXPECT_EQ(oracle::compare_distance(square(0, 0, 1), diamond, 0.0), 0);
}

TEST(OracleExact, CrossingPolygonsWithNoVertexInsideTheOther) {
  // Two triangles forming a six-pointed star: only edges cross.
  const ConvexPolygon<double> up({V(0, 0), V(6, 0), V(3, 5)});
  const ConvexPolygon<double> down({V(0, 3.5), V(3, -1.5), V(6, 3.5)});
  EXPECT_TRUE(oracle::overlaps(up, down));
}

TEST(OracleExact, SegmentThroughABoxCornerOnTheDiagonal) {
  // The points (t, t) for t = 0.1, 0.2, 0.3 (as doubles) are exactly collinear.
  const V p(0.1, 0.1), q(0.3, 0.3);
  EXPECT_TRUE(oracle::segment_meets(Aabb<double>(V(-1, 0.2), V(0.2, 1)), p, q));
  EXPECT_FALSE(oracle::segment_meets(Aabb<double>(V(-1, 0.2), V(next_down(0.2), 1)), p, q));
  EXPECT_TRUE(oracle::segment_meets(Circle<double>(V(0.2, 0.2), 0.0), p, q));
  EXPECT_TRUE(oracle::segment_meets(Circle<double>(V(5, 5), 1.0), V(5, 5), V(5, 5)));  // degenerate segment
  // Capsule of radius 0 is the segment itself: the midpoint (0.5, 0.25) is on it, one ulp off is not.
  const Capsule<double> seg(V(0, 0), V(1, 0.5), 0.0);
  EXPECT_TRUE(oracle::contains(seg, V(0.5, 0.25)));
  EXPECT_FALSE(oracle::contains(seg, V(0.5, next_up(0.25))));
}

TEST(OracleExact, CapsulesTouchingAtTheirRims) {
  // Parallel capsules 2 apart with radii 1: touching; a hair further, not.
  const Capsule<double> a(V(0, 0), V(4, 0), 1.0);
  EXPECT_TRUE(oracle::overlaps(a, Capsule<double>(V(1, 2), V(3, 2), 1.0)));
  EXPECT_FALSE(oracle::overlaps(a, Capsule<double>(V(1, next_up(2.0)), V(3, next_up(2.0)), 1.0)));
  // End cap against end cap along a 3-4-5 diagonal.
  EXPECT_TRUE(oracle::overlaps(a, Capsule<double>(V(7, 4), V(9, 9), 4.0)));
  EXPECT_FALSE(oracle::overlaps(a, Capsule<double>(V(7, 4), V(9, 9), next_down(4.0))));
}

TEST(OracleExact, InsideBoxUsesExactExtremes) {
  const Aabb<double> box(V(0, 0), V(1, 1));
  EXPECT_TRUE(oracle::inside_box(Circle<double>(V(0.5, 0.5), 0.5), box));
  EXPECT_FALSE(oracle::inside_box(Circle<double>(V(0.5, 0.5), next_up(0.5)), box));
  // 0.1 + 0.2 > 0.3 exactly: a circle at 0.1 of radius 0.2 reaches past 0.3 (as a double).
  EXPECT_FALSE(oracle::inside_box(Circle<double>(V(0.1, 0.5), 0.2), Aabb<double>(V(-1, 0), V(0.3, 1))));
  EXPECT_TRUE(oracle::inside_box(Capsule<double>(V(0.25, 0.25), V(0.75, 0.75), 0.25), box));
  EXPECT_TRUE(oracle::inside_box(box, box));
  EXPECT_FALSE(oracle::inside_box(Obb<double>(V(0.5, 0.5), V(0.5, 0.5), 0.3), box));
  EXPECT_TRUE(oracle::inside_box(
      Compound<double>({Circle<double>(V(0.2, 0.2), 0.1), Aabb<double>(V(0.5, 0.5), V(1, 1))}), box));
  EXPECT_FALSE(oracle::inside_box(
      Compound<double>({Circle<double>(V(0.2, 0.2), 0.1), Aabb<double>(V(0.5, 0.5), V(1, 2))}), box));
}

TEST(OracleExact, BoundaryDistanceInsideAndOutside) {
  const ConvexPolygon<double> sq = square(0, 0, 4);
  EXPECT_EQ(oracle::compare_boundary_distance(sq, V(1, 2), 1.0), 0);  // inside: nearest edge x = 0
  EXPECT_EQ(oracle::compare_boundary_distance(sq, V(1, 2), 0.5), 1);
  EXPECT_EQ(oracle::compare_boundary_distance(sq, V(6, 2), 2.0), 0);  // outside
  EXPECT_EQ(oracle::compare_boundary_distance(sq, V(7, 8), 5.0), 0);  // outside, 3-4-5 to the corner
  EXPECT_EQ(oracle::compare_boundary_distance(sq, V(4, 1), 0.0), 0);  // on the boundary
  const Circle<double> c(V(0, 0), 2.0);
  EXPECT_EQ(oracle::compare_boundary_distance(c, V(0.5, 0), 1.5), 0);
  EXPECT_EQ(oracle::compare_boundary_distance(c, V(0, 0), 2.0), 0);
  EXPECT_EQ(oracle::compare_boundary_distance(c, V(3, 4), 3.0), 0);
  const Capsule<double> cap(V(0, 0), V(4, 0), 1.0);
  EXPECT_EQ(oracle::compare_boundary_distance(cap, V(2, 0.25), 0.75), 0);  // in the rim
  EXPECT_EQ(oracle::compare_boundary_distance(cap, V(2, 0), 1.0), 0);      // on the core
  // Rounded box: an AABB core has radius 0, so its interior depth is the edge distance.
  EXPECT_EQ(oracle::compare_boundary_distance(Aabb<double>(V(0, 0), V(2, 6)), V(1.5, 3), 0.5), 0);
  const Compound<double> two({Circle<double>(V(0, 0), 1.0), Circle<double>(V(10, 0), 1.0)});
  EXPECT_EQ(oracle::compare_boundary_distance(two, V(5, 0), 4.0), 0);
  EXPECT_THROW(oracle::compare_boundary_distance(two, V(0, 0), 1.0), Unsupported);
}

TEST(OracleExact, SeparatesTranslatesExactly) {
  const Aabb<double> a(V(0, 0), V(1, 1)), b(V(2, 0), V(3, 1));
  EXPECT_FALSE(oracle::separates(a, b, V(1, 0)));  // touching after the move
  EXPECT_TRUE(oracle::separates(a, b, V(next_down(1.0), 0)));
  // 0.1 + 0.2 is not rounded: a moved by 0.2 from 0.1 ends just beyond the double 0.3.
  const Circle<double> p(V(0.1, 0), 0.0);
  const Aabb<double> wall(V(-1, -1), V(0.3, 1));
  EXPECT_TRUE(oracle::separates(p, wall, V(0.2, 0)));
  EXPECT_FALSE(oracle::separates(p, wall, V(0.19, 0)));
  EXPECT_TRUE(oracle::separates(Compound<double>({Circle<double>(V(0, 0), 1.0), Circle<double>(V(5, 0), 1.0)}),
                                Circle<double>(V(10, 0), 1.0), V(0, 5)));
}

TEST(OracleExact, ApproximateSignedDistance) {
  const Circle<double> a(V(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(oracle::approx_signed_distance(a, Circle<double>(V(3, 4), 1.0)), 3.0);
  EXPECT_DOUBLE_EQ(oracle::approx_signed_distance(a, Circle<double>(V(1, 0), 1.0)), -1.0);
  EXPECT_DOUBLE_EQ(oracle::approx_signed_distance(square(0, 0, 2), square(1, 0.5, 2)), -1.0);
  EXPECT_DOUBLE_EQ(oracle::approx_signed_distance(square(0, 0, 2), square(5, 6, 2)), 5.0);
  const Compound<double> two({Circle<double>(V(0, 0), 1.0), Circle<double>(V(10, 0), 1.0)});
  EXPECT_DOUBLE_EQ(oracle::approx_signed_distance(two, Circle<double>(V(5, 0), 1.0)), 3.0);
  const double overlapping = oracle::approx_signed_distance(two, Circle<double>(V(10.5, 0), 1.0));
  EXPECT_EQ(overlapping, 0.0);
  EXPECT_TRUE(std::signbit(overlapping));
}

TEST(OracleExact, NonFiniteArgumentsAreRejectedByName) {
  const Circle<double> a(V(0, 0), 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(oracle::compare_distance(a, a, nan), InvalidInput);
  EXPECT_THROW(oracle::compare_depth(a, a, inf), InvalidInput);
  EXPECT_THROW(oracle::within_band(a, a, nan), InvalidInput);
  EXPECT_THROW(oracle::contains(a, V(nan, 0)), InvalidInput);
  EXPECT_THROW(oracle::separates(a, a, V(0, inf)), InvalidInput);
  EXPECT_THROW(oracle::segment_meets(a, V(0, 0), V(inf, 0)), InvalidInput);
  EXPECT_THROW(oracle::compare_boundary_distance(a, V(0, 0), -inf), InvalidInput);
}

TEST(OracleExact, ExtremeMagnitudesFallBackToRationals) {
  // Values at the ends of the library's range.
  const double big = 0x1p+500;
  const Circle<double> a(V(big, 0), big), b(V(-big, 0), big);
  EXPECT_TRUE(oracle::overlaps(a, b));  // touching at the origin
  EXPECT_EQ(oracle::compare_distance(a, b, 0.0), 0);
  EXPECT_FALSE(oracle::overlaps(a, Circle<double>(V(-big, 0), next_down(big))));
  // Fourth powers of 2^500 overflow double intervals (inf - inf): the exact pass decides.
  const Capsule<double> bar(V(-big, 0), V(big, 0), 0.0);
  EXPECT_TRUE(oracle::overlaps(bar, Circle<double>(V(0, big / 2), big / 2)));
  EXPECT_FALSE(oracle::overlaps(bar, Circle<double>(V(0, next_up(big / 2)), big / 2)));
  // Tiny values: products are subnormal; the intervals stay conservative.
  const double tiny = 0x1p-520;
  EXPECT_TRUE(oracle::overlaps(Circle<double>(V(0, 0), tiny), Circle<double>(V(3 * tiny, 4 * tiny), 4 * tiny)));
  EXPECT_FALSE(oracle::overlaps(Circle<double>(V(0, 0), tiny), Circle<double>(V(3 * tiny, 4 * tiny), 3.5 * tiny)));
}

}  // namespace
}  // namespace collide::oracle
