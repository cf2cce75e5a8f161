// Contact manifolds on hand-computed cases (float and double): feature ids, per-point
// separations, speculative contacts and compound child ids.

#include "support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace collide::test {
namespace {

template <class T>
class Manifolds : public ::testing::Test {};
TYPED_TEST_SUITE(Manifolds, Scalars);

template <Scalar T>
double tol() {
  return std::is_same_v<T, float> ? 1e-5 : 1e-12;
}

FeatureId face_on_a(unsigned face, unsigned vertex) {
  return {0, 0, std::uint8_t(face), std::uint8_t(vertex), FeatureKind::Edge, FeatureKind::Vertex};
}

/// A 2 x 1 box resting 0.25 deep on a 4 x 2 box: the top face of a (edge 2) is the reference
/// face, b's bottom face (vertices 0 and 1) is incident, both points 0.25 deep.
TYPED_TEST(Manifolds, BoxRestingOnBoxHasTwoPointsWithFaceIds) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> ground(V(-2, -2), V(2, 0));
  const Aabb<T> crate(V(-1, T(-0.25)), V(1, T(0.75)));
  const auto c = contact(ground, crate);
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 2);
  EXPECT_NEAR(double(c->normal.y()), 1.0, tol<T>());
  EXPECT_NEAR(double(c->depth), 0.25, tol<T>());
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(double(c->separations[std::size_t(i)]), -0.25, tol<T>());
    EXPECT_NEAR(double(c->points[std::size_t(i)].y()), -0.125, tol<T>());
  }
  const FeatureId want[2] = {face_on_a(2, 0), face_on_a(2, 1)};
  EXPECT_TRUE(std::is_permutation(c->ids.begin(), c->ids.end(), std::begin(want)));
  // The other order: equally deep faces go to the first shape, so the crate's bottom (edge 0) is
  // the reference face and the ground's top corners (vertices 2 and 3) are clipped to it.
  const auto r = contact(crate, ground);
  ASSERT_TRUE(r.has_value());
  ASSERT_EQ(r->count, 2);
  EXPECT_NEAR(double(r->normal.y()), -1.0, tol<T>());
  const FeatureId other[2] = {face_on_a(0, 2), face_on_a(0, 3)};
  EXPECT_TRUE(std::is_permutation(r->ids.begin(), r->ids.end(), std::begin(other)));
}

/// A polygon whose bottom side is split by a vertex 10^-7 below the line of its ends, resting on
/// a box's top face: its two bottom faces are equally anti-parallel to that face up to rounding.
/// The flatter one, on the right, is the more anti-parallel in the last bits, but the box's face
/// ends under it; the left one lies over the face along all its length, spans more of it, and
/// is the incident face: its two ends are the points, with its vertices' ids.
TYPED_TEST(Manifolds, OfFacesEquallyAntiParallelTheOneSpanningMoreIsIncident) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> ground(V(-3, -1), V(T(0.5), 0));
  const ConvexPolygon<T> crate({V(-1, 0), V(0, T(-1e-7)), V(2, 0), V(2, 1), V(-1, 1)});
  const auto c = contact(ground, crate);
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 2);
  EXPECT_NEAR(double(c->normal.y()), 1.0, tol<T>());
  const FeatureId want[2] = {face_on_a(2, 0), face_on_a(2, 1)};
  EXPECT_TRUE(std::is_permutation(c->ids.begin(), c->ids.end(), std::begin(want)))
      << "the incident face must be the left one, over the ground's face, not the flatter one past its end";
  std::array<double, 2> xs{double(c->points[0].x()), double(c->points[1].x())};
  std::sort(xs.begin(), xs.end());
  EXPECT_NEAR(xs[0], -1.0, tol<T>());
  EXPECT_NEAR(xs[1], 0.0, tol<T>());
}

/// The crate slid sideways and sunk deeper keeps the same reference and incident features, so
/// the same ids; tilted, its points separate unevenly.
TYPED_TEST(Manifolds, IdsStayWhileTheFeaturesStay) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> ground(V(-2, -2), V(2, 0));
  const auto first = contact(ground, Aabb<T>(V(-1, T(-0.25)), V(1, T(0.75))));
  const auto moved = contact(ground, Aabb<T>(V(T(-0.5), T(-0.375)), V(T(1.5), T(0.625))));
  ASSERT_TRUE(first && moved);
  ASSERT_EQ(moved->count, 2);
  EXPECT_TRUE(std::is_permutation(first->ids.begin(), first->ids.end(), moved->ids.begin()));
  const Obb<T> tilted(V(0, T(0.3)), V(1, T(0.5)), T(0.1));
  const auto t = contact(ground, tilted);
  ASSERT_TRUE(t.has_value());
  ASSERT_EQ(t->count, 2);
  // Bottom corners at y = 0.3 -+ sin(0.1) - 0.5 cos(0.1): both below the ground's top, 2 sin(0.1) apart.
  const double lo = 0.3 - std::sin(0.1) - 0.5 * std::cos(0.1), hi = 0.3 + std::sin(0.1) - 0.5 * std::cos(0.1);
  const double s0 = double(t->separations[0]), s1 = double(t->separations[1]);
  EXPECT_NEAR(std::min(s0, s1), lo, 1e-5);
  EXPECT_NEAR(std::max(s0, s1), hi, 1e-5);
}

/// Two boxes stacked with parallel faces at 200 angles: the two faces are equally deep up to
/// rounding, and the first box keeps the reference face while the second moves by a few ulps
/// either way (without the face order tie, 16 of the 200 pairs changed owner and ids).
TYPED_TEST(Manifolds, ParallelFacesKeepTheirOwnerUnderTinyMotions) {
  using T = TypeParam;
  using V = Vec2<T>;
  for (int i = 0; i < 200; ++i) {
    const double th = 0.01 + 0.0137 * i;
    const V u(T(std::cos(th)), T(std::sin(th))), v(-u.y(), u.x());
    const Obb<T> a = Obb<T>::make_with_axis(V(0, 0), V(T(1.5), T(0.5)), u).value();
    const V at = v * T(0.9) + u * T(0.3), step = (u + v) * T(4e-6);
    const auto ids = [&](const V& c) {
      const auto k = contact(a, Obb<T>::make_with_axis(c, V(1, T(0.5)), u).value());
      EXPECT_TRUE(k.has_value());
      EXPECT_EQ(k->count, 2);
      return std::array<FeatureId, 2>{k->ids[0], k->ids[1]};
    };
    const auto here = ids(at);
    EXPECT_EQ(here[0].kind_a, FeatureKind::Edge) << "angle " << th;
    EXPECT_EQ(here, ids(at + step)) << "angle " << th;
    EXPECT_EQ(here, ids(at - step)) << "angle " << th;
  }
}

/// Circles 1 apart with radii summing to 2: one point, separation -1 (Vertex 0 on both).
TYPED_TEST(Manifolds, CirclesHaveOnePointWithVertexIds) {
  using T = TypeParam;
  using V = Vec2<T>;
  const auto c = contact(Circle<T>(V(0, 0), 1), Circle<T>(V(0, 1), 1));
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 1);
  EXPECT_NEAR(double(c->separations[0]), -1.0, tol<T>());
  EXPECT_EQ(c->ids[0], FeatureId{});
  EXPECT_NEAR(double(c->points[0].y()), 0.5, tol<T>());
}

/// A circle beside a box's right face (edge 1), and above its top-right corner (vertex 2).
TYPED_TEST(Manifolds, CircleAgainstBoxNamesTheFaceOrCorner) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> box(V(-1, -1), V(1, 1));
  const auto face = contact(Circle<T>(V(T(1.5), 0), 1), box);
  ASSERT_TRUE(face.has_value());
  EXPECT_NEAR(double(face->separations[0]), -0.5, tol<T>());
  EXPECT_EQ(face->ids[0].kind_b, FeatureKind::Edge);
  EXPECT_EQ(face->ids[0].index_b, 1);
  const auto corner = contact(Circle<T>(V(T(1.5), T(1.5)), 1), box);
  ASSERT_TRUE(corner.has_value());
  EXPECT_NEAR(double(corner->separations[0]), std::sqrt(0.5) - 1, tol<T>());
  EXPECT_EQ(corner->ids[0].kind_b, FeatureKind::Vertex);
  EXPECT_EQ(corner->ids[0].index_b, 2);
}

/// Shapes 0.5 apart: no contact, a speculative one from 0.5 on with separation 0.5 and depth 0;
/// a negative or NaN speculative distance is none.
TYPED_TEST(Manifolds, SpeculativeContactOfShapesApart) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Circle<T> a(V(0, 0), 1);
  const Aabb<T> b(V(T(1.5), -1), V(3, 1));
  EXPECT_FALSE(contact(a, b).has_value());
  EXPECT_FALSE(contact(a, b, T(0.25)).has_value());
  EXPECT_FALSE(contact(a, b, T(-1)).has_value());
  EXPECT_FALSE(contact(a, b, std::numeric_limits<T>::quiet_NaN()).has_value());
  EXPECT_FALSE(overlaps(a, b));
  const auto c = contact(a, b, T(0.75));
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->count, 1);
  EXPECT_EQ(double(c->depth), 0.0);
  EXPECT_NEAR(double(c->separations[0]), 0.5, tol<T>());
  EXPECT_NEAR(double(c->normal.x()), 1.0, tol<T>());
  EXPECT_NEAR(double(c->points[0].x()), 1.25, tol<T>());
  // Two boxes 0.5 apart likewise.
  const auto boxes = contact(Aabb<T>(V(-1, -1), V(1, 1)), b, T(1));
  ASSERT_TRUE(boxes.has_value());
  EXPECT_NEAR(double(boxes->separations[0]), 0.5, tol<T>());
}

/// An overlapping pair keeps contact(a, b)'s normal and depth with a speculative distance, and a
/// tilted box's far corner, apart by less than it, becomes a second point.
TYPED_TEST(Manifolds, SpeculativeDistanceAddsNearPoints) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> ground(V(-2, -2), V(2, 0));
  const Obb<T> tilted(V(0, T(0.55)), V(1, T(0.5)), T(0.1));  // one bottom corner below 0, one above
  const auto plain = contact(ground, tilted);
  const auto spec = contact(ground, tilted, T(0.5));
  ASSERT_TRUE(plain && spec);
  EXPECT_EQ(plain->count, 1);
  EXPECT_EQ(spec->count, 2);
  EXPECT_EQ(spec->normal, plain->normal);
  EXPECT_EQ(spec->depth, plain->depth);
  EXPECT_GT(double(std::max(spec->separations[0], spec->separations[1])), 0.0);
}

/// A capsule resting on the ground with only its radius sunk in (its segment above the ground):
/// a point under each end, as under a box, so that a solver does not rock it about one end. The
/// ids name the ground's top face (edge 2) and the capsule's ends (vertices 0 and 1). Tilted so
/// that one end lifts clear, one point; a speculative distance reaching the other end adds it.
TYPED_TEST(Manifolds, CapsuleRestingOnABoxHasAPointUnderEachEnd) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> ground(V(-4, -2), V(4, 0));
  const auto c = contact(ground, Capsule<T>(V(-1, T(0.375)), V(1, T(0.375)), T(0.5)));
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 2);
  EXPECT_NEAR(double(c->normal.y()), 1.0, tol<T>());
  EXPECT_NEAR(double(c->depth), 0.125, tol<T>());
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(double(c->separations[i]), -0.125, tol<T>());
    EXPECT_NEAR(double(c->points[i].y()), -0.0625, tol<T>());
  }
  EXPECT_NEAR(std::fabs(double(c->points[0].x() - c->points[1].x())), 2.0, tol<T>());
  const FeatureId want[2] = {face_on_a(2, 0), face_on_a(2, 1)};
  EXPECT_TRUE(std::is_permutation(c->ids.begin(), c->ids.end(), std::begin(want)));
  // The same capsule placed by a transform.
  const auto placed = contact(ground, Transform<T>(), Capsule<T>(V(-1, 0), V(1, 0), T(0.5)),
                              Transform<T>::make(V(0, T(0.375)), 0).value());
  ASSERT_TRUE(placed.has_value());
  EXPECT_EQ(placed->count, 2);
  // Ends at y = 0.375 and 0.75: at the right end's x the capsule's surface is its flat side, lower
  // than the end's own circle: 0.75 - 0.5 sqrt(1 + (0.375 / 2)^2) above the ground.
  const Capsule<T> tilted(V(-1, T(0.375)), V(1, T(0.75)), T(0.5));
  const auto one = contact(ground, tilted);
  ASSERT_TRUE(one.has_value());
  ASSERT_EQ(one->count, 1);
  EXPECT_EQ(one->ids[0], face_on_a(2, 0));
  const auto two = contact(ground, tilted, T(0.5));
  ASSERT_TRUE(two.has_value());
  ASSERT_EQ(two->count, 2);
  EXPECT_NEAR(double(std::max(two->separations[0], two->separations[1])), 0.75 - 0.5 * std::sqrt(1 + 0.1875 * 0.1875),
              tol<T>());
}

/// A capsule beyond a box's corner, 0.3 from both face lines but 0.3 sqrt(2) = 0.42 from the
/// corner, with radius 0.35: no face line separates them by the radius, yet they are apart. Its
/// nearest end lies beside both faces, so their separations are not the distance. Moved 0.4 left,
/// its end is over the top face and it rests 0.05 deep on it: a point at each end of the part of
/// its segment over the face (x = 0.9 and 1).
TYPED_TEST(Manifolds, CapsuleBeyondABoxCornerWithinItsRadiusOfBothFaceLinesIsApart) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> box(V(-1, -1), V(1, 1));
  const Capsule<T> beyond(V(T(1.3), T(1.3)), V(T(3.3), T(1.3)), T(0.35));
  EXPECT_FALSE(overlaps(box, beyond));
  EXPECT_FALSE(contact(box, beyond).has_value());
  const auto over = contact(box, Capsule<T>(V(T(0.9), T(1.3)), V(T(2.9), T(1.3)), T(0.35)));
  ASSERT_TRUE(over.has_value());
  ASSERT_EQ(over->count, 2);
  EXPECT_NEAR(double(over->normal.y()), 1.0, tol<T>());
  for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(double(over->separations[i]), -0.05, 1e-6);
  EXPECT_NEAR(double(std::min(over->points[0].x(), over->points[1].x())), 0.9, 1e-6);
  EXPECT_NEAR(double(std::max(over->points[0].x(), over->points[1].x())), 1.0, 1e-6);
  const FeatureId want[2] = {face_on_a(2, 0), face_on_a(2, 1)};
  EXPECT_TRUE(std::is_permutation(over->ids.begin(), over->ids.end(), std::begin(want)));
}

/// A crate hovering 0.25 over the ground, within the speculative distance: a point under each
/// bottom corner, both 0.25 apart, with the ids it has when it rests on the ground
/// (BoxRestingOnBoxHasTwoPointsWithFaceIds), so that a solver keeps its impulses as it lands.
/// Beside a corner of the ground, the closest features are two vertices: one point.
TYPED_TEST(Manifolds, CrateHoveringWithinTheSpeculativeDistanceHasTwoPoints) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Aabb<T> ground(V(-2, -2), V(2, 0));
  const auto c = contact(ground, Aabb<T>(V(-1, T(0.25)), V(1, T(1.25))), T(0.5));
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 2);
  EXPECT_EQ(double(c->depth), 0.0);
  EXPECT_NEAR(double(c->normal.y()), 1.0, tol<T>());
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(double(c->separations[i]), 0.25, tol<T>());
    EXPECT_NEAR(double(c->points[i].y()), 0.125, tol<T>());
  }
  const FeatureId want[2] = {face_on_a(2, 0), face_on_a(2, 1)};
  EXPECT_TRUE(std::is_permutation(c->ids.begin(), c->ids.end(), std::begin(want)));
  const auto corner = contact(ground, Aabb<T>(V(T(2.25), T(0.25)), V(T(3.25), T(1.25))), T(0.5));
  ASSERT_TRUE(corner.has_value());
  ASSERT_EQ(corner->count, 1);
  EXPECT_EQ(corner->ids[0].kind_a, FeatureKind::Vertex);
  EXPECT_EQ(corner->ids[0].kind_b, FeatureKind::Vertex);
}

/// A capsule whose segment starts on a box's corner (up to rounding) and leaves it along a face's
/// normal: the clipped segment lies on the side plane, rounding clips all of it, and the point
/// comes from the witness candidates. It must be the midway one, half the depth inside the box
/// from the corner, not the corner itself (on the box's surface, the whole depth inside the capsule).
TEST(ManifoldRegression, CapsuleEndOnABoxCornerAlongItsFaceNormalGetsAMidwayPoint) {
  using V = Vec2<double>;
  const Obb<double> box = *Obb<double>::make_with_axis(V(-0x1.6p+9, 0x1.cp+8), V(0x1.8p+7, 0x1p+7),
                                                       V(0x1.3333333333333p-1, 0x1.999999999999ap-1));
  const V start(-0x1.e666666666666p+8, 0x1.0666666666668p+9);  // the box's corner c + hx u - hy v, to rounding
  const Capsule<double> capsule = *Capsule<double>::make(start, start + V(256, -192), 64);  // along -v
  for (const bool swapped : {false, true}) {
    const auto c = swapped ? contact(capsule, box) : contact(box, capsule);
    ASSERT_TRUE(c.has_value());
    ASSERT_EQ(c->count, 1);
    const V n = swapped ? V(-c->normal) : c->normal;  // from the box toward the capsule
    EXPECT_NEAR(n.x(), 0.8, 1e-12);
    EXPECT_NEAR(n.y(), -0.6, 1e-12);
    EXPECT_NEAR(c->depth, 64.0, 1e-9);
    EXPECT_NEAR(c->separations[0], -64.0, 1e-9);
    const V midway = start - n * 32.0;
    EXPECT_NEAR((c->points[0] - midway).norm(), 0.0, 1e-9) << "point " << c->points[0].transpose();
  }
}

/// A circle centred on the end of a flat box (a segment): moved off along the normal either way,
/// its closest feature is the end vertex; centred on it, the contact comes from the segment's face
/// but must name the same vertex, so that the id does not change as the circle moves through.
TEST(ManifoldRegression, CircleCentredOnTheEndOfAFlatBoxNamesTheEndVertex) {
  using V = Vec2<double>;
  const Obb<double> flat = *Obb<double>::make_with_axis(V(0x1.3333333333334p+1, -0x1.1cccccccccccdp+4), V(0, 3),
                                                        V(0x1.3333333333333p-1, 0x1.999999999999ap-1));
  const V end(0, -16);  // c + 3 perp(u), computed exactly
  const V off = V(0.6, 0.8) * 0x1p-14;
  const auto at = contact(flat, *Circle<double>::make(end, 1));
  ASSERT_TRUE(at.has_value());
  EXPECT_EQ(at->ids[0].kind_a, FeatureKind::Vertex);
  for (const double k : {-1.0, 1.0}) {
    const auto moved = contact(flat, *Circle<double>::make(end + off * k, 1));
    ASSERT_TRUE(moved.has_value());
    EXPECT_EQ(moved->ids[0], at->ids[0]) << "moved by " << k << " x " << off.transpose();
  }
}

/// A small square at 45 degrees to a large box's face: its two faces toward the box are equally
/// anti-parallel and span the reference face equally, up to rounding at 10^7. The first must stay
/// the incident face, at the square and moved either way, so that the points keep their ids.
TEST(ManifoldRegression, SquareAt45DegreesToTheReferenceFaceKeepsItsIncidentFace) {
  using V = Vec2<double>;
  const Obb<double> big = *Obb<double>::make_with_axis(V(8437440, -7291456), V(3145728, 4194304),
                                                       V(-0x1.6a09e667f3bccp-1, 0x1.6a09e667f3bccp-1));
  const auto square = [](const V& at) { return *Obb<double>::make_with_axis(at, V(16384, 16384), V(-1, 0)); };
  const V at(12631744, -7291456);
  const auto c = contact(big, square(at));
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 2);
  for (const double k : {-1.0, 1.0}) {
    const auto moved = contact(big, square(at + V(48, 64) * k));
    ASSERT_TRUE(moved.has_value());
    ASSERT_EQ(moved->count, 2);
    EXPECT_EQ(moved->ids[0], c->ids[0]) << "moved by " << k << " x (48, 64)";
    EXPECT_EQ(moved->ids[1], c->ids[1]) << "moved by " << k << " x (48, 64)";
  }
}

/// A capsule whose segment ends on the end of a flat box (a segment) and leaves it beside the
/// box's face, outside its side plane: rounding puts that end just outside too, clipping finds
/// nothing, and the point comes from the witness candidates. It must be the end moved midway
/// between the surfaces, not the end itself (inside both shapes, but a radius from the capsule's
/// surface along the normal).
TEST(ManifoldRegression, CapsuleEndingOnTheEndOfAFlatBoxGetsAMidwayPoint) {
  using V = Vec2<double>;
  const Obb<double> flat =
      *Obb<double>::make_with_axis(V(16, -3), V(0, 1), V(-0.38461538461538464, -0.92307692307692313));
  const V end(15.076923076923077, -2.615384615384615);  // c - v, to rounding
  const Capsule<double> capsule = *Capsule<double>::make(V(7.0769230769230766, -2.615384615384615), end, 1);
  for (const bool swapped : {false, true}) {
    const auto c = swapped ? contact(capsule, flat) : contact(flat, capsule);
    ASSERT_TRUE(c.has_value());
    ASSERT_EQ(c->count, 1);
    const V n = swapped ? V(-c->normal) : c->normal;  // from the box toward the capsule: -u
    EXPECT_NEAR(n.x(), -0.38461538461538464, 1e-12);
    EXPECT_NEAR(n.y(), -0.92307692307692313, 1e-12);
    EXPECT_NEAR(c->separations[0], -1.0, 1e-12);
    EXPECT_NEAR((c->points[0] - (end - n * 0.5)).norm(), 0.0, 1e-12) << "point " << c->points[0].transpose();
  }
}

/// A box 1.5 x 10^-8 across inside one a thousand times larger, both turned by (0.6, 0.8) and
/// placed 1.6 x 10^-4 from the origin: the small box's face is the reference face, and the large
/// box's face, clipped to its span 5.7 x 10^-6 away, must end at the small box's corners. The
/// direction of the face's rounded ends is off by their rounding over its length (10^-12), which
/// put the clipped ends, and the small box's surface points, 7 x 10^-18 beyond its corners (the
/// bound is 4 x 10^-18); the face's normal is not.
TEST(ManifoldRegression, ShortReferenceFaceFarFromTheOriginClipsAlongItsNormal) {
  using V = Vec2<double>;
  const Transform<double> x =
      *Transform<double>::make_with_rotation(V(-0x1.4000000000005p-13, -0x1.f400000000008p-15), V(0.6, 0.8));
  const Aabb<double> small(V(0x1.fep-20, -0x1.008p-18), V(0x1.01p-19, -0x1.ffp-19));
  const Obb<double> large = *Obb<double>::make_with_axis(V(0x1p-19, -0x1p-18), V(0x1.8p-18, 0x1p-17), V(0, -1));
  const auto c = contact(small, x, large, x);
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 2);
  // The small box's corners in the world, in long double (exact enough here).
  using L = long double;
  const L q0 = x.rotation().x(), q1 = x.rotation().y(), px = x.position().x(), py = x.position().y();
  const L xs[2] = {small.min().x(), small.max().x()}, ys[2] = {small.min().y(), small.max().y()};
  for (int i = 0; i < 2; ++i) {
    const L sx = L(c->points[std::size_t(i)].x()) - L(c->normal.x()) * L(c->separations[std::size_t(i)]) / 2;
    const L sy = L(c->points[std::size_t(i)].y()) - L(c->normal.y()) * L(c->separations[std::size_t(i)]) / 2;
    L nearest = 1;
    for (const L cx : xs) {
      for (const L cy : ys) {
        const L wx = q0 * cx - q1 * cy + px, wy = q1 * cx + q0 * cy + py;
        nearest = std::min(nearest, std::hypot(sx - wx, sy - wy));
      }
    }
    EXPECT_LE(double(nearest), 1e-19) << "point " << i << ": the small box's surface point is off its corner";
  }
}

/// A short segment lying on a long one, both at 2 x 10^7 along (3, 4): both clipped ends are at
/// separation 0, up to rounding, and both must stay points at the segment and moved along the line
/// either way (one end rounded out of reach dropped its point, a different one at each position).
TEST(ManifoldRegression, SegmentLyingOnALongSegmentKeepsBothEnds) {
  using V = Vec2<double>;
  const Capsule<double> a = *Capsule<double>::make(V(-15777472, -17777216), V(-22068928, -26165824), 0);
  const auto b = [](const V& at) { return *Capsule<double>::make(at, at + V(-98304, -131072), 0); };
  const V at(-18874048, -21905984);
  for (const double k : {-1.0, 0.0, 1.0}) {
    const auto c = contact(a, b(at + V(24, 32) * k));
    ASSERT_TRUE(c.has_value());
    ASSERT_EQ(c->count, 2) << "moved by " << k << " x (24, 32)";
    EXPECT_EQ(c->ids[0].index_b, 0);
    EXPECT_EQ(c->ids[1].index_b, 1);
    for (int i = 0; i < 2; ++i) EXPECT_LE(std::fabs(c->separations[std::size_t(i)]), 1e-8);
  }
}

/// A capsule lying along a box's bottom face, 0.125 deep, its end exactly below the box's corner,
/// then 1.9 x 10^-5 either way along (3, 4): the faces are parallel and equally deep, and the
/// box's face must stay the reference face throughout, in the box's frame and placed by a turned
/// transform. At the corner the closest points are two vertices, and a contact found from them
/// must still name the box's face.
TEST(ManifoldRegression, CapsuleEndBelowABoxCornerKeepsTheBoxFace) {
  using V = Vec2<double>;
  const Obb<double> box = *Obb<double>::make_with_axis(V(-2, -0.125), V(3, 1), V(-1, 0));
  const Transform<double> x = *Transform<double>::make_with_rotation(V(-0x1.f400000000008p+5, -0x1.0400000000004p+6),
                                                                     V(-0x1.f1216dba340c9p-1, -0x1.e9fb8d64830e3p-3));
  for (const double k : {-1.0, 0.0, 1.0}) {
    const V t = V(0x1.8p-17, 0x1p-16) * k;
    const Capsule<double> capsule = *Capsule<double>::make(V(1, -2) + t, V(0, -2) + t, 1);
    for (const bool placed : {false, true}) {
      const auto c = placed ? contact(box, x, capsule, x) : contact(box, capsule);
      ASSERT_TRUE(c.has_value());
      ASSERT_EQ(c->count, 2) << "moved by " << k << " x t, placed " << placed;
      EXPECT_EQ(c->ids[0], face_on_a(2, 0)) << "moved by " << k << " x t, placed " << placed;
      EXPECT_EQ(c->ids[1], face_on_a(2, 1)) << "moved by " << k << " x t, placed " << placed;
    }
  }
}

/// A capsule's end level with a box's corner, beside the box's right face (the offset is
/// perpendicular to that face): the closest points are the two vertices, and the point names them.
/// A face through a closest vertex counts only beside a face of the other core (parallel faces);
/// the capsule's side is not parallel here, and naming the box's side would change the id at this
/// one configuration as the capsule moves past the corner.
TEST(ManifoldRegression, CapsuleEndLevelWithABoxCornerNamesTheCorner) {
  using V = Vec2<double>;
  const Aabb<double> box(V(0, 0), V(2, 2));
  const auto c = contact(box, *Capsule<double>::make(V(3, 2), V(4, 3), 1.5));
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 1);
  EXPECT_EQ(c->ids[0], (FeatureId{0, 0, 2, 0, FeatureKind::Vertex, FeatureKind::Vertex}));
}

/// A box's corner level with a capsule's end, inside its end cap, both placed at 1.7 x 10^7, then
/// b moved by -+(3, 4) x 2^-17: moved one way the corner lies beyond the end, the other way beside
/// the capsule's side, whose face then clips the box's top face (two points, the faces nearly
/// parallel). At the level configuration the side's face clipped the box's top face so that its far
/// corner's clipped end landed exactly on the near corner. The deepest point must name the near
/// corner (vertex 3) in all three, the level configuration's one point included, not the far
/// corner whose end was carried onto it.
TEST(ManifoldRegression, CornerLevelWithACapsuleEndKeepsItsIdThroughTheLevel) {
  using V = Vec2<double>;
  const Obb<double> a = *Obb<double>::make_with_axis(V(0x1.e849789d89d8ap+19, -0x1.e83e98ec4ec4fp+19), V(6, 2),
                                                     V(0x1.d89d89d89d89ep-1, -0x1.89d89d89d89d9p-2));
  const Transform<double> x = *Transform<double>::make_with_rotation(V(-0x1.e84a42762763p+23, 0x1.f78c9489d89e2p+22),
                                                                     V(-0x1.ff207e2b9cbb6p-1, -0x1.de33739e82d32p-5));
  for (const double k : {-1.0, 0.0, 1.0}) {
    const V t = V(0x1.8p-16, 0x1p-15) * k;
    const Capsule<double> b =
        *Capsule<double>::make(V(0x1.e848ep+19, -0x1.e83ep+19) + t, V(0x1.e848cp+19, -0x1.e83ep+19) + t, 1);
    const auto c = contact(a, x, b, x);
    ASSERT_TRUE(c.has_value());
    if (k == 0) {
      ASSERT_EQ(c->count, 1) << "at the level configuration";
    }
    const std::size_t deepest = c->count == 2 && c->separations[1] < c->separations[0] ? 1 : 0;
    EXPECT_EQ(c->ids[deepest].kind_a, FeatureKind::Vertex) << "moved by " << k << " x t";
    EXPECT_EQ(c->ids[deepest].index_a, 3) << "moved by " << k << " x t";
  }
}

/// Step 5 on its own, with the reference face given (the box's top face; the full contact of these
/// shapes takes another face, of least penetration): the incident face runs from a vertex beyond the
/// face's left side plane to a vertex exactly on it, so clipping carries the first end onto the
/// second. The one point lies at the second vertex, unclipped, and must name it (vertex 1), not the
/// vertex clipping moved there (0): as the incident face slides right, that vertex keeps the point.
TEST(ManifoldRegression, ClippedEndCarriedOntoTheOtherNamesTheVertexThere) {
  using V = Vec2<double>;
  const Aabb<double> box(V(0, 0), V(2, 2));
  const ConvexPolygon<double> wedge = *ConvexPolygon<double>::make({V(-1, 1.95), V(0, 1.9), V(3, 2.5), V(-1, 3)});
  detail::Axis top;
  top.normal = Vec2c(0, 1);
  top.depth = 0.1;
  top.owner = 0;
  top.face = 2;
  const detail::CoreContact c = detail::contact_from_axis(detail::core_of(box), detail::core_of(wedge), top);
  ASSERT_EQ(c.count, 1);
  EXPECT_EQ(c.points[0].x(), 0.0);
  EXPECT_EQ(c.ids[0].kind_b, FeatureKind::Vertex);
  EXPECT_EQ(c.ids[0].index_b, 1);
}

/// Parallel capsules 6.6 x 10^-6 apart with faces shorter than that (one point, along the
/// points' direction), their top ends level, then 3.6 x 10^-11 either way along (3, 4): every
/// pair of points on the common span is closest, and the point must name both sides, not the
/// ends rounding picked (two vertices at level ends, an end and a side otherwise).
TEST(ManifoldRegression, ParallelSegmentsCloserThanTheirLengthNameBothSides) {
  using V = Vec2<double>;
  const Capsule<double> a = *Capsule<double>::make(V(-0x1.48p-18, -0x1.2p-17), V(-0x1.48p-18, -0x1.ep-17), 0x1p-18);
  const Transform<double> x = *Transform<double>::make_with_rotation(V(-0x1.0a00000000004p-13, -0x1.db00000000008p-13),
                                                                     V(0x1.dfc2d59376aeep-2, 0x1.c4542b2ba24d7p-1));
  for (const double k : {-1.0, 0.0, 1.0}) {
    const V t = V(0x1.8p-36, 0x1p-35) * k;
    const Capsule<double> b =
        *Capsule<double>::make(V(-0x1.8p-17, -0x1.2p-17) + t, V(-0x1.8p-17, -0x1.4p-17) + t, 0x1.8p-19);
    for (const bool placed : {false, true}) {
      const auto c = placed ? contact(a, x, b, x) : contact(a, b);
      ASSERT_TRUE(c.has_value());
      ASSERT_EQ(c->count, 1) << "moved by " << k << " x t, placed " << placed;
      EXPECT_EQ(c->ids[0].kind_a, FeatureKind::Edge) << "moved by " << k << " x t, placed " << placed;
      EXPECT_EQ(c->ids[0].kind_b, FeatureKind::Edge) << "moved by " << k << " x t, placed " << placed;
    }
  }
}

/// A circle whose centre lies beside a segment (a zero-radius capsule), just past the foot of its
/// end: the foot a + d t rounds by up to an ulp of a, which made the end look closer than the
/// segment, and the normal became the direction to the end, across the segment. Pushed along that,
/// the circle stays overlapping the segment's far part. The normal must be the segment's
/// perpendicular, and a moved by -normal * (depth + margin) must clear b. Two cases: a segment
/// leaning 1.8 x 10^-5 from the y axis at 10^-178, and one leaning 3.9 x 10^-3 at 10^-52 (in a
/// compound, and alone).
TEST(ManifoldRegression, CircleBesideASegmentNearItsEndTakesTheSegmentsNormal) {
  using V = Vec2<double>;
  const std::array<std::pair<Circle<double>, Capsule<double>>, 2> pairs = {{
      {*Circle<double>::make(V(0x1.b1b1b1b1b1b1bp-590, 0x1.b1b1b1b1b1b1bp-590), 0x1.b1b1b1b1b1b1bp-590),
       *Capsule<double>::make(V(0x1.b1b1b1b1d1b1bp-590, 0x1.b1b1b1b1b1b1bp-590),
                              V(0x1.b1b1b1b1b1b1cp-590, 0x1.b1b1ccccccccdp-590), 0)},
      {*Circle<double>::make(V(0x1.5353535350c35p-172, 0x1.5353530353536p-172), 0x1.535353635p-172),
       *Capsule<double>::make(V(0x1.5353535353535p-172, 0x1.5353530353536p-172),
                              V(0x1.5353500003535p-172, 0x1.5350035353535p-172), 0)},
  }};
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto& [ball, segment] = pairs[k];
    const Compound<double> in_compound({Primitive<double>(ball)});
    for (const auto& c : {contact(ball, segment), contact(in_compound, segment)}) {
      ASSERT_TRUE(c.has_value()) << "pair " << k;
      const Vec2c d = widen(segment.b()) - widen(segment.a());
      EXPECT_NEAR(std::fabs(c->normal.dot(d.normalized())), 0.0, 1e-9) << "pair " << k << ": not across the segment";
      const Vec2<double> push = -c->normal * (c->depth + resolve_margin(ball, segment, c->depth, c->normal));
      const Circle<double> moved = *Circle<double>::make(ball.center() + push, ball.radius());
      EXPECT_FALSE(overlaps(moved, segment)) << "pair " << k << ": still overlapping after the push";
    }
    const Circle<double> resolved = *Circle<double>::make(ball.center() + resolve(ball, segment), ball.radius());
    EXPECT_FALSE(overlaps(resolved, segment)) << "pair " << k << ": resolve() leaves them overlapping";
  }
}

/// How far a's surface point of c's first point lies from the feature of polygon a it names (a
/// vertex: the nearer of its two edges).
template <Scalar T>
double reach_of_named_feature(const ConvexPolygon<T>& a, const Contact<T>& c) {
  const FeatureId& id = c.ids[0];
  const Vec2c surface = widen(c.points[0]) - widen(c.normal) * (double(c.separations[0]) / 2);
  const std::size_t n = a.size();
  const auto edge_distance = [&](std::size_t e) {
    const Vec2c p = widen(a[e]), d = widen(a[(e + 1) % n]) - p;
    const double t = std::clamp((surface - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (surface - (p + d * t)).norm();
  };
  return id.kind_a == FeatureKind::Edge ? edge_distance(id.index_a)
                                        : std::min(edge_distance(id.index_a), edge_distance((id.index_a + n - 1) % n));
}

/// A polygon whose edges 1 and 2 are parallel to within 10^-16 (a corner at a subnormal vertex),
/// touched by a segment beyond edge 1's end, at edge 2, 3 x 10^-11 past the corner. The faces tie
/// for the least depth and edge 1, the first, is the reference face; clipping keeps nothing of the
/// segment, and the witness point, on edge 2, was named by edge 1, 3 x 10^-11 away. The point must
/// name a feature it lies on: a's edge 2, or the corner (a vertex spans its two edges).
TEST(ManifoldRegression, WitnessBeyondTheReferenceFaceNamesTheFacesEnd) {
  using V = Vec2<double>;
  const ConvexPolygon<double> a = *ConvexPolygon<double>::make(
      {V(-0x1.b1b03396c351ap-14, -0x1.c3206bfb5f617p-16), V(0x1.7e217c9e6p-30, -0x1.c3206bfb5f617p-16),
       V(0x0.000000035p-1022, 0x0.00023272dp-1022), V(-0x1.b1b03396c351ap-14, 0x1.fffe3cdfa8d96p+0)});
  const Transform<double> xa = *Transform<double>::make_with_rotation(
      V(-0x1.e8e254031588ep-791, -0x1.e8e8e8e8e8e8fp-791), V(1, 0x1.11b08ce6de5cp-446));
  const Capsule<double> b =
      *Capsule<double>::make(V(0x1.ffffa71e33cfep-32, 0x1.0aac619bea75ep-35),
                             V(-0x1.c3c730c06206p-50, 0x1.0aac619bea75ep-35), 0x1.0001062008e8ep-1007);
  const Transform<double> xb = *Transform<double>::make_translation(V(0x0.000000035p-1022, 0x0.0000023272dp-1022));
  const auto c = contact(a, xa, b, xb);
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 1);
  const FeatureId& id = c->ids[0];
  EXPECT_LT(reach_of_named_feature(a, *c), 1e-15)
      << "a's " << (id.kind_a == FeatureKind::Edge ? "edge " : "vertex ") << int(id.index_a);
}

/// A polygon whose edges 0, 1 and 2 are collinear up to rounding (tilts of 10^-26 and 10^-51 at
/// 10^23), with a capsule deep inside it beside edge 2, 2.8 x 10^23 along. The three faces tie
/// for the least depth and edge 0, 0.015 long, is the reference face; clipping keeps nothing, and
/// the witness, past edge 0's end, was named by that end's vertex, 2.8 x 10^23 away. The point
/// must name the face it lies along: edge 2, within the rounding of the point (10^17).
TEST(ManifoldRegression, WitnessPastFacesContinuingTheReferenceFaceNamesTheOneItLiesOn) {
  using V = Vec2<float>;
  const ConvexPolygon<float> a = *ConvexPolygon<float>::make(
      {V(-0x1.252524p-90f, -0x1.deb9fap-7f), V(0.0f, -0x1.252524p-89f), V(0.0f, 0x1.e043dap+21f),
       V(-0x1.252524p-90f, 0x1.d2a88ep+78f), V(-0x1.b9fb0cp+97f, 0x1.bcb8ccp+98f)});
  const Capsule<float> b =
      *Capsule<float>::make(V(-0x1.deba2ap+41f, 0x1.e043dap+77f), V(-0x1.deba1p+42f, 0x1.e043dap+77f), 0x1.e0445cp+21f);
  const auto c = contact(a, b);
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 1);
  const FeatureId& id = c->ids[0];
  EXPECT_LT(reach_of_named_feature(a, *c), 1e17)
      << "a's " << (id.kind_a == FeatureKind::Edge ? "edge " : "vertex ") << int(id.index_a);
}

/// A capsule whose segment starts at a box's top-left corner and runs left along the line of its
/// top face, both placed by one rotation. Clipping keeps nothing (the segment lies beyond the
/// face), and its two ends are equally deep up to rounding: the far one, 7 past the corner, came
/// out an ulp deeper, and the point moved from it lay 7 off the box, so the box's corner itself
/// was taken, which puts the box's surface point 0.5 off the box. The point must lie midway
/// between the surfaces, at the corner moved half the depth into the box, and each surface point
/// on its shape.
TEST(ManifoldRegression, EndsEquallyDeepBeyondAFaceTakeTheOneAtTheFace) {
  using V = Vec2<double>;
  const Obb<double> a = *Obb<double>::make_with_axis(V(-12, -12), V(7, 1), V(1, 0));
  const Capsule<double> b = *Capsule<double>::make(V(-19, -11), V(-26, -11), 1);
  const Transform<double> x = *Transform<double>::make_with_rotation(V(-0x1.cb00000000007p+6, -0x1.b000000000007p+8),
                                                                     V(0x1.fc82bbd1e4ca1p-1, -0x1.dd62b2f352a2cp-4));
  const auto c = contact(a, x, b, x);
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 1);
  EXPECT_NEAR(c->depth, 1.0, 1e-12);
  const auto local = [&](const Vec2c& w) { return x.unrotate(w - widen(x.position())); };
  const Vec2c point = local(widen(c->points[0]));
  EXPECT_NEAR(point.x(), -19.0, 1e-12);
  EXPECT_NEAR(point.y(), -11.5, 1e-12);
  const Vec2c half = x.unrotate(widen(c->normal)) * (c->separations[0] / 2);
  const Vec2c on_a = point - half, on_b = point + half;
  const Vec2c outside(std::max({-19.0 - on_a.x(), on_a.x() + 5.0, 0.0}),
                      std::max({-13.0 - on_a.y(), on_a.y() + 11.0, 0.0}));
  const double inside = std::min({on_a.x() + 19.0, -5.0 - on_a.x(), on_a.y() + 13.0, -11.0 - on_a.y()});
  EXPECT_LT(outside.norm() + std::max(inside, 0.0), 1e-12) << "a's surface point off the box";
  const double along = std::clamp(-(on_b.x() + 19.0) / 7.0, 0.0, 1.0);
  EXPECT_NEAR((on_b - Vec2c(-19 - 7 * along, -11)).norm(), 1.0, 1e-12) << "b's surface point off the capsule";
}

/// A float polygon whose right side runs through a vertex 1.8 x 10^-14 off the line of its two
/// faces there (edges 1 and 2, 10^28 long), and a circle 2.3 x 10^20 inside, beside edge 2. The
/// two faces tie for the least depth up to rounding, and edge 1, the first, was kept as the
/// reference face though the centre projects 1.1 x 10^28 beyond its end: the point named a face
/// that far from it. The point must name a feature it lies on: edge 2, or the vertex between.
TEST(ManifoldRegression, CircleDeepInsideBesideATiedFaceNamesTheFaceItLiesOn) {
  using V = Vec2<float>;
  const ConvexPolygon<float> a = *ConvexPolygon<float>::make(
      {V(-0x1.70dfdp+86f, -0x1.acd7e8p+95f), V(0x1.58p-127f, -0x1.acd7e8p+95f), V(0x1.42addep-46f, -0x1.24efd8p+93f),
       V(0, 0x1.f33afep+95f), V(-0x1.70dfdp+86f, 0x1.f33b04p+95f)});
  const Circle<float> b = *Circle<float>::make(V(0x1.aeaap+47f, 0x1.aeaeaep+47f), 0x1.aeb2aep+47f);
  const Transform<float> xb = *Transform<float>::make_translation(V(-0x1.93eaaep+67f, 0x1.aeaeaep+47f));
  for (const bool placed : {false, true}) {
    const Circle<float> world =
        *Circle<float>::make(V(-0x1.93eaaep+67f + 0x1.aeaap+47f, 0x1.aeaeaep+48f), 0x1.aeb2aep+47f);
    const auto c = placed ? contact(a, Transform<float>(), b, xb) : contact(a, world);
    ASSERT_TRUE(c.has_value()) << "placed " << placed;
    ASSERT_EQ(c->count, 1);
    const FeatureId& id = c->ids[0];
    EXPECT_LT(reach_of_named_feature(a, *c), 1e23)
        << "placed " << placed << ": a's " << (id.kind_a == FeatureKind::Edge ? "edge " : "vertex ") << int(id.index_a);
  }
}

/// Two child pairs of compounds overlapping equally deep up to rounding: a speculative distance
/// adds a point apart to one of them, and the pair contact(a, b) chose must still win (the tie
/// between child pairs is measured at their deepest points, which the added point is not).
TEST(ManifoldRegression, SpeculativeDistanceKeepsTheChildPairOfAnOverlappingCompound) {
  using V = Vec2<float>;
  const Obb<float> tilted = *Obb<float>::make_with_axis(V(0x1.eec4fp-19f, -0x1.5d89d8p-17f), V(0x1p-19f, 0x1.4p-18f),
                                                        V(-0x1.89d89ep-2f, -0x1.d89d8ap-1f));
  const Compound<float> a({Primitive<float>(tilted)});
  const Capsule<float> dot = *Capsule<float>::make(V(0x1.6p-17f, -0x1.6p-17f), V(0x1.6p-17f, -0x1.6p-17f), 0x1.8p-19f);
  const Aabb<float> box = *Aabb<float>::make(V(-0x1p-17f, 0), V(-0x1.4p-18f, 0x1.8p-18f));
  const Transform<float> at = *Transform<float>::make_translation(V(0x1p-16f, -0x1p-16f));
  const Compound<float> b =
      *Compound<float>::make_placed({{Primitive<float>(dot), Transform<float>()}, {Primitive<float>(box), at}});
  const auto plain = contact(a, b);
  ASSERT_TRUE(plain.has_value());
  for (int k = -22; k <= -12; ++k) {
    const auto spec = contact(a, b, std::ldexp(1.0f, k));
    ASSERT_TRUE(spec.has_value());
    EXPECT_EQ(spec->normal, plain->normal) << "speculative 2^" << k;
    EXPECT_EQ(spec->depth, plain->depth) << "speculative 2^" << k;
    EXPECT_EQ(spec->ids[0].child_b, plain->ids[0].child_b) << "speculative 2^" << k;
  }
}

/// A triangle 10^-307 wide and 7.6 x 10^78 tall, its sharp vertex at 0.0078 above a circle
/// whose top reaches 1.6 x 10^63 above the origin: the centre lies on the line of a long face,
/// rounded to an excess of 0, 7.6 x 10^78 below the vertex. The depth is the vertex's (about
/// 1.6 x 10^63), not the radius the centre's excess behind that face would give.
TEST(ManifoldRegression, CircleFarBelowASharpVertexGetsTheVertexDepth) {
  using V = Vec2<double>;
  const ConvexPolygon<double> spike = *ConvexPolygon<double>::make(std::vector<V>{
      V(0, 0x1.05000008p+262), V(0x1.ff000ea00005p-1020, 0x1.000000001p-7), V(0x0.00000c08p-1022, 0x1.05000008p+262)});
  const Circle<double> ball(V(0, -0x1.0504fffffffffp+262), 0x1.0505p+262);
  const auto c = contact(spike, ball);
  ASSERT_TRUE(c.has_value());
  EXPECT_LT(c->depth, 1e66);        // within the error bound of the exact 1.6 x 10^63, 8 x 64 x 2^-53 x 7.6 x 10^78
  EXPECT_LT(c->normal.y(), -0.99);  // from the spike down toward the ball
}

/// A polygon with three faces on its left side (two of them below 10^-6 long) tied up to
/// rounding for a circle beside them: the circle lies beside the long one, 2.4 x 10^26 away
/// with a radius of 2.8 x 10^26, beyond the ends of the short face the tie picked first, whose
/// neighbours alone would put the closest point at the origin and the pair apart.
TEST(ManifoldRegression, CircleBesideARunOfTinyFacesFindsTheFaceBeyondThem) {
  using V = Vec2<float>;
  const ConvexPolygon<float> p = *ConvexPolygon<float>::make(
      std::vector<V>{V(-0x1.fp-144f, 0x1.f8p-144f), V(0, -0x1.c4c2d6p-22f), V(0x1.d6d6d6p+87f, -0x1.08p-143f),
                     V(0x1.626262p-31f, 0x1.fdc2fp+86f), V(-0x1.fp-144f, 0x1.04p-143f)});
  const Circle<float> ball(V(-0x1.8be2b4p+87f, 0x1.fdc2fp+86f), 0x1.d6d6d6p+87f);
  ASSERT_TRUE(overlaps(p, ball));
  const auto c = contact(p, ball);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->depth, 0x1.d6d6d6p+87f - 0x1.8be2b4p+87f, 1e20f);
  EXPECT_EQ(c->normal.x(), -1.0f);
  EXPECT_EQ(c->ids[0].kind_b, FeatureKind::Vertex);  // the circle's centre
  // The long left face, or its top vertex: the centre is level with it, and the closest point
  // lies 10^-9 below it, far within rounding at 10^26.
  EXPECT_EQ(c->ids[0].index_a, 3);
}

/// A compound's ids name the child pair that produced the contact.
TYPED_TEST(Manifolds, CompoundIdsNameTheChildren) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Compound<T> body({Primitive<T>(Circle<T>(V(-5, 0), 1)), Primitive<T>(Aabb<T>(V(4, -1), V(6, 1)))});
  const auto c = contact(Circle<T>(V(T(6.5), 0), 1), body);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->ids[0].child_a, 0);
  EXPECT_EQ(c->ids[0].child_b, 1);
  EXPECT_EQ(c->ids[0].index_b, 1);  // the box's right face
}

/// A polygon 3 long and 10^-245 thick, turned 45 degrees, and a circle of radius 3 whose centre
/// lies 2.715 off its line: the closest-point search named the sliver's far side, whose outward
/// normal points away from the centre, and its normal gave a depth of r + 2.715 with the normal
/// reversed. The depth is r less the centre's distance to the line y = x, and the normal points
/// from the centre toward the polygon.
TEST(ManifoldRegression, CircleBesideASliverFacesItsNearSide) {
  using V = Vec2<double>;
  const Circle<double> circle = *Circle<double>::make(V(-0x1.046bb2c88d37p+0, -0x1.693fe507c3863p+1), 3);
  const Transform<double> xa = *Transform<double>::make_with_rotation(V(0x1p-1011, 0), V(0, 1));
  const ConvexPolygon<double> sliver = *ConvexPolygon<double>::make(
      {V(3, 0x1.d0d0d0d16a1b2p-815), V(0x1.d0d0d0d0d0d0dp-815, 0x1.d0d0d0d0d0d12p-815),
       V(0x1.d0d0d0d0d0d0dp-815, 0x1.d0d0d0d0d0d0dp-815), V(0x1.7fffe7fffffffp+1, 0x1.d0d0d0d16a1b1p-815)});
  const Transform<double> xb = *Transform<double>::make_with_rotation(V(0x1.d0d0d0d0d0d0dp-815, 0x1.d0d0d0d0d0d0dp-815),
                                                                      V(0x1.6a09e667f3bccp-1, 0x1.6a09e667f3bccp-1));
  const std::optional<Contact<double>> c = contact(circle, xa, sliver, xb);
  ASSERT_TRUE(c);
  const V centre = xa.apply(circle.center());
  const double off_line = (centre.x() - centre.y()) / std::sqrt(2.0);
  EXPECT_NEAR(c->depth, 3 - off_line, 1e-12);
  EXPECT_LT(c->normal.dot(V(centre.x() - centre.y(), centre.y() - centre.x())), 0) << "normal away from the polygon";
}

}  // namespace
}  // namespace collide::test
