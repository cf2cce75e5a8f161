// Transforms: the factories' named errors, local shapes placed by transforms against the same
// shapes built in world space, compounds whose children carry transforms, the resolution margin
// from the moved shape's own coordinates (the ground box), and the list helpers deducing T.

#include "support.hpp"

#include <collide/broadphase.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace collide::test {
namespace {

template <class T>
class Transforms : public ::testing::Test {};
TYPED_TEST_SUITE(Transforms, Scalars);

TYPED_TEST(Transforms, FactoriesNameEveryBadValue) {
  using T = TypeParam;
  using V = Vec2<T>;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const T huge = T(max_magnitude<T>() * T(2));
  EXPECT_EQ(Transform<T>::make(V(nan, 0), T(0)).error().code(), Error::NonFinite);
  EXPECT_EQ(Transform<T>::make(V(0, 0), inf).error().index(), 2);
  EXPECT_EQ(Transform<T>::make(V(0, huge), T(0)).error().code(), Error::OutOfRange);
  EXPECT_EQ(Transform<T>::make_with_rotation(V(0, 0), V(0, 0)).error().code(), Error::ZeroRotation);
  EXPECT_EQ(Transform<T>::make_with_rotation(V(0, 0), V(nan, 1)).error().index(), 2);
  EXPECT_EQ(Transform<T>::make_with_rotation(V(0, 0), V(1, huge)).error().code(), Error::OutOfRange);
  EXPECT_EQ(Transform<T>::make_translation(V(inf, 0)).error().code(), Error::NonFinite);
  const auto far = Transform<T>::make_translation(V(max_magnitude<T>(), 0)).value();
  EXPECT_EQ(far.moved(V(max_magnitude<T>(), 0)).error().code(), Error::OutOfRange);
}

TYPED_TEST(Transforms, UnitRotationKeptOtherVectorsNormalised) {
  using T = TypeParam;
  using V = Vec2<T>;
  const auto turned = Transform<T>::make(V(1, 2), T(0.3)).value();
  // A stored rotation is a unit vector up to rounding: rebuilding from it keeps it bit for bit.
  EXPECT_EQ(Transform<T>::make_with_rotation(V(1, 2), turned.rotation()).value(), turned);
  const auto scaled = Transform<T>::make_with_rotation(V(0, 0), V(3, 4)).value();
  EXPECT_EQ(scaled.rotation(), V(T(0.6), T(0.8)));
  const auto tiny = Transform<T>::make_with_rotation(V(0, 0), V(std::numeric_limits<T>::denorm_min(), 0)).value();
  EXPECT_EQ(tiny.rotation(), V(1, 0));
  EXPECT_TRUE(Transform<T>().is_identity());
  EXPECT_FALSE(scaled.is_identity());
}

TYPED_TEST(Transforms, SubnormalRotationNormalisedAlongItsDirection) {
  using T = TypeParam;
  using V = Vec2<T>;
  // (211, 1) units of the smallest subnormal: normalised after an exact scaling by a power of
  // two, not from its few significant bits (which gave (1, 0.0047393), |q|^2 - 1 = 2.2e-5).
  const T d = std::numeric_limits<T>::denorm_min();
  const auto x = Transform<T>::make_with_rotation(V(0, 0), V(T(211) * d, d)).value();
  const Vec2c unit = Vec2c(211, 1).normalized();
  EXPECT_LE((widen(x.rotation()) - unit).cwiseAbs().maxCoeff(), 2 * double(std::numeric_limits<T>::epsilon()));
  EXPECT_LE(std::fabs(widen(x.rotation()).squaredNorm() - 1), 4 * double(std::numeric_limits<T>::epsilon()));
}

TYPED_TEST(Transforms, QuarterTurnsAndTranslationsGiveTheWorldAnswers) {
  using T = TypeParam;
  using V = Vec2<T>;
  // A box and a polygon touching at x = 1; turned a quarter and moved by (8, -4) they touch at
  // y = 1 - 4. Every mapped value is exact, so the answers are those of the moved world shapes.
  const Aabb<T> box(V(-1, -1), V(1, 1));
  const ConvexPolygon<T> tri{V(1, 0), V(3, -1), V(3, 1)};
  const auto x = Transform<T>::make_with_rotation(V(8, -4), V(0, 1)).value();
  const Aabb<T> box_w(V(7, -5), V(9, -3));
  const ConvexPolygon<T> tri_w{V(8, -3), V(9, -1), V(7, -1)};
  EXPECT_TRUE(overlaps(box, x, tri, x));
  EXPECT_EQ(overlaps(box, x, tri, x), overlaps(box_w, tri_w));
  EXPECT_EQ(distance(box, x, tri, x), distance(box_w, tri_w));
  const Aabb<T> bb = bounds(box, x);  // padded by the transform's bound, never smaller
  EXPECT_TRUE(bb.min().x() <= T(7) && bb.min().y() <= T(-5) && bb.max().x() >= T(9) && bb.max().y() >= T(-3));
  EXPECT_LT((widen(bb.max()) - Vec2c(9, -3)).norm(), 1e-5);
  // One ulp apart, still decided exactly.
  const auto apart = Transform<T>::make_with_rotation(V(8, std::nextafter(T(-4), T(0))), V(0, 1)).value();
  EXPECT_FALSE(overlaps(box, x, tri, apart));
  EXPECT_TRUE(contains(tri, x, V(8, -3)));
  EXPECT_FALSE(contains(tri, x, V(8, std::nextafter(T(-3), T(-4)))));
}

TYPED_TEST(Transforms, RotatedShapesMatchTheirBuiltImages) {
  using T = TypeParam;
  using V = Vec2<T>;
  const auto x = Transform<T>::make(V(2, 1), T(0.5)).value();
  const Capsule<T> cap(V(-1, 0), V(1, 0), T(0.25));
  const Vec2c a = x.apply(Vec2c(-1, 0)), b = x.apply(Vec2c(1, 0));
  const Capsule<T> cap_w(a.template cast<T>(), b.template cast<T>(), T(0.25));
  const Circle<T> probe(V(2, 2), T(0.5));
  EXPECT_EQ(overlaps(cap, x, probe, Transform<T>()), overlaps(cap_w, probe));
  const T d = distance(cap, x, probe, Transform<T>()), dw = distance(cap_w, probe);
  EXPECT_NEAR(double(d), double(dw), 1e-5);
  // An AABB turned by a general angle is an OBB.
  const Aabb<T> box(V(-1, -0.5), V(1, 0.5));
  const Obb<T> obb_w = Obb<T>::make_with_axis(V(2, 1), V(1, 0.5), x.rotation()).value();
  const auto c = contact(box, x, probe, Transform<T>()), cw = contact(obb_w, probe);
  ASSERT_EQ(bool(c), bool(cw));
  if (c) {
    EXPECT_NEAR(double(c->depth), double(cw->depth), 1e-5);
  }
  // The placed shape's box holds its image.
  const Aabb<T> bb = bounds(box, x);
  for (const Vec2c& corner : {Vec2c(-1, -0.5), Vec2c(1, -0.5), Vec2c(1, 0.5), Vec2c(-1, 0.5)}) {
    const Vec2c w = x.apply(corner);
    EXPECT_TRUE(w.x() >= bb.min().x() && w.x() <= bb.max().x() && w.y() >= bb.min().y() && w.y() <= bb.max().y());
  }
  // A ray along +x at the body's height hits the turned box.
  const auto hit = raycast(box, x, Ray<T>{V(-5, 1), V(1, 0)}, T(100));
  ASSERT_TRUE(hit);
  EXPECT_GT(hit->t, T(5));
}

// Polygons the turn-margin tests use: a square, a thin triangle whose middle vertex projects far
// beyond its neighbours' segment (t = 3: there moving the neighbours shifts their line most), a
// needle, and random hulls of 3 to 8 points.
template <Scalar T>
std::vector<ConvexPolygon<T>> turn_margin_polygons() {
  using V = Vec2<T>;
  std::vector<ConvexPolygon<T>> out;
  out.push_back(ConvexPolygon<T>{V(-1, -1), V(1, -1), V(1, 1), V(-1, 1)});
  out.push_back(ConvexPolygon<T>{V(0, 0), V(3, T(-0.125)), V(1, 0)});
  out.push_back(ConvexPolygon<T>{V(0, 0), V(64, 0), V(32, T(0x1p-12))});
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<T> coord(-4, 4);
  while (out.size() < 60) {
    std::vector<V> pts(3 + rng() % 6);
    for (V& p : pts) p = V(coord(rng), coord(rng));
    if (auto poly = ConvexPolygon<T>::make_hull(pts); poly && poly->size() <= ConvexPolygon<T>::kInline)
      out.push_back(*poly);
  }
  return out;
}

// turn_margin(): each vertex moved by (just under) the margin, the two ends of a turn the way
// that shifts their line most toward the middle vertex and the middle vertex toward that line,
// still turns strictly left. A margin of the least height, ignoring how far the line shifts at
// the middle vertex's projection, fails on the thin triangle.
TYPED_TEST(Transforms, TurnMarginKeepsEveryTurnLeftUnderTheWorstMoves) {
  using T = TypeParam;
  for (const ConvexPolygon<T>& poly : turn_margin_polygons<T>()) {
    const Calc m = detail::PolygonAccess::turn_margin(poly);
    ASSERT_GT(m, 0);
    const std::size_t n = poly.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2c a = widen(poly[k]), b = widen(poly[(k + 1) % n]), c = widen(poly[(k + 2) % n]);
      const Vec2c ac = c - a, left = Vec2c(-ac.y(), ac.x()) / ac.norm();  // toward the side away from b
      const Calc t = (b - a).dot(ac) / ac.squaredNorm(), e = 0.999 * m;
      const Vec2c a2 = a - left * (t < 1 ? e : -e), c2 = c - left * (t > 0 ? e : -e), b2 = b + left * e;
      EXPECT_GT(orient(a2, b2, c2), 0) << "turn " << k << " of a polygon of " << n << " vertices, margin " << m;
    }
  }
}

// A polygon's image skips testing its turns only when the margin proves them left: the image
// keeps every mapped vertex exactly when all the mapped turns are left, and is the rounded hull
// otherwise. Poses far from the origin flatten the needle; near it the margin decides.
TYPED_TEST(Transforms, PolygonImageTestsItsTurnsWhenRoundingMayFlattenThem) {
  using T = TypeParam;
  std::mt19937 rng(1202);
  std::uniform_real_distribution<T> angle(-3, 3);
  int proven = 0, flattened = 0;
  for (const ConvexPolygon<T>& poly : turn_margin_polygons<T>()) {
    for (int shift : {0, 20, 40, 60, 90}) {
      const T far = std::ldexp(T(1), shift);
      const Transform<T> x = Transform<T>::make(Vec2<T>(far, -far / 3), angle(rng)).value();
      const detail::Pose pose = x.pose();
      const std::size_t n = poly.size();
      std::vector<Vec2c> mapped;
      for (std::size_t k = 0; k < n; ++k) mapped.push_back(detail::image_point(pose, widen(poly[k])));
      bool left = true;
      for (std::size_t k = 0; k < n; ++k)
        left = left && orient(mapped[k], mapped[(k + 1) % n], mapped[(k + 2) % n]) > 0;
      Calc local = 0;
      for (const Vec2<T>& v : poly.vertices()) local = std::max(local, widen(v).cwiseAbs().maxCoeff());
      proven += detail::PolygonAccess::turn_margin(poly) > detail::image_tolerance(pose, local);
      flattened += !left;
      detail::with_image(poly, pose, [&](const auto& img) {
        if constexpr (std::is_same_v<std::decay_t<decltype(img)>, ConvexPolygon<Calc>>) {
          if (left) {
            ASSERT_EQ(img.size(), n);
            for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(img[k], mapped[k]);
          } else {
            const auto hull = ConvexPolygon<Calc>::make_hull(mapped);
            ASSERT_TRUE(hull.has_value());
            ASSERT_EQ(img.size(), hull->size());
            for (std::size_t k = 0; k < img.size(); ++k) EXPECT_EQ(img[k], (*hull)[k]);
          }
        } else {
          EXPECT_FALSE(left) << "a polygon whose mapped turns are all left became a segment";
          EXPECT_FALSE(ConvexPolygon<Calc>::make_hull(mapped).has_value()) << "a segment where a hull exists";
        }
      });
    }
  }
  EXPECT_GT(proven, 100) << "the margin should spare most images their turn tests";
  EXPECT_GT(flattened, 0) << "some pose should flatten the needle, or this test checks nothing";
}

/// The stored edge of `poly` (placed by translation p) nearest the point v, its images computed in
/// double as with_image() maps them.
std::size_t nearest_stored_edge(const ConvexPolygon<float>& poly, const Vec2<float>& p, const Vec2c& v) {
  std::size_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Vec2c a = widen(poly[k]) + widen(p), b = widen(poly[(k + 1) % poly.size()]) + widen(p);
    const Vec2c d = b - a;
    const double t = std::clamp((v - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const double dist = (v - (a + d * t)).norm();
    if (dist < best_d) {
      best_d = dist;
      best = k;
    }
  }
  return best;
}

/// A float polygon at 6.5 x 10^35 translated by 8.7 x 10^32: the translation rounds three vertices
/// of its top face onto one line, so its image is the hull of the rounded vertices, numbered its
/// own way. A circle touches the left face (stored edge 5). The point must name that edge, placed
/// directly, as a compound's child with that translation, and as a placed compound's child; the
/// hull's own number for that face names the top face, 5 x 10^35 away.
TEST(TransformRegression, RehulledPolygonImageNamesTheStoredPolygonsFeatures) {
  using V = Vec2<float>;
  const ConvexPolygon<float> poly =
      *ConvexPolygon<float>::make({V(-0x1.f5f672p+118f, -0x1.f46df6p+118f), V(-0x1.14f8dp+40f, -0x1.f5f7f6p+118f),
                                   V(0x1.78761p+53f, -0x1.f9f78ap+39f), V(0x1.ac8acp+47f, 0x1.ab417ap+47f),
                                   V(-0x1.e463f4p+116f, 0x1.ab3ac2p+47f), V(-0x1.f5f5f4p+118f, 0x1.a3be8cp+45f)});
  const V p(0x1.606064p-31f, 0x1.562642p+109f);
  const Transform<float> x = *Transform<float>::make_translation(p);
  const Circle<float> ball = *Circle<float>::make(V(-0x1.f598p+118f, 0x1.51555p-128f), 0x1.0cp-134f);
  const Compound<float> child = *Compound<float>::make_placed({{Primitive<float>(poly), x}});
  const Compound<float> body({Primitive<float>(poly)});
  const std::array<std::optional<Contact<float>>, 3> contacts = {
      contact(poly, x, ball, Transform<float>()), contact(child, ball), contact(body, x, ball, Transform<float>())};
  for (std::size_t way = 0; way < contacts.size(); ++way) {
    const auto& c = contacts[way];
    ASSERT_TRUE(c.has_value()) << "way " << way;
    for (int i = 0; i < c->count; ++i) {
      const FeatureId& id = c->ids[std::size_t(i)];
      const Vec2c surface =
          widen(c->points[std::size_t(i)]) - widen(c->normal) * (double(c->separations[std::size_t(i)]) / 2);
      ASSERT_EQ(id.kind_a, FeatureKind::Edge) << "way " << way;
      EXPECT_EQ(id.index_a, nearest_stored_edge(poly, p, surface)) << "way " << way << ", point " << i;
    }
  }
}

/// A float polygon at 6.5 x 10^35 turned and translated so that two of its vertices round 10^28
/// apart and the hull of the rounded vertices drops one of them. Against a polygon whose face is
/// the reference face, the hull's incident edge is clipped back to near the origin, and that point
/// keeps the id of the dropped vertex's neighbour on the hull. It must name a stored vertex whose
/// edges pass through the point (a vertex feature spans its two edges), not the hull vertex's own
/// stored vertex, 6.5 x 10^35 away.
TEST(TransformRegression, RehulledPolygonImageNamesAClippedVertexByItsEdges) {
  using V = Vec2<float>;
  const ConvexPolygon<float> a = *ConvexPolygon<float>::make(
      {V(-0x1.f5f5f6p+118f, -0x1.1dc3aep+39f), V(-0x1.f5f5f4p+118f, -0x1.f5f5f6p+118f),
       V(0x1.c13874p+39f, -0x1.f5f5f4p+118f), V(0x1.aeaeaep+99f, -0x1.1dc3aep+39f), V(-0x1.f5f5f4p+118f, 0)});
  const Transform<float> xa =
      *Transform<float>::make_with_rotation(V(0x1.c13874p+39f, -0x1.1dc3aep+39f), V(0x1.afffe8p-1f, -0x1.12cf42p-1f));
  const ConvexPolygon<float> b =
      *ConvexPolygon<float>::make({V(-0x1.f5f5cp+117f, 0x1.f5f628p+117f), V(0x1.b2606p-31f, 0x1.545412p-43f),
                                   V(0x1.f5f628p+117f, -0x1.f5f5cp+117f), V(0x1.f5f694p+117f, 0x1.f5f628p+117f)});
  const Transform<float> xb = *Transform<float>::make_translation(V(0x1.add454p-43f, 0x1.545454p-43f));
  const auto c = contact(a, xa, b, xb);
  ASSERT_TRUE(c.has_value());
  const detail::Pose pose = xa.pose();
  const std::size_t n = a.size();
  int vertices = 0;
  for (int i = 0; i < c->count; ++i) {
    const FeatureId& id = c->ids[std::size_t(i)];
    if (id.kind_a != FeatureKind::Vertex) continue;
    ++vertices;
    const Vec2c surface =
        widen(c->points[std::size_t(i)]) - widen(c->normal) * (double(c->separations[std::size_t(i)]) / 2);
    double reach = std::numeric_limits<double>::infinity();
    for (const std::size_t e : {std::size_t(id.index_a), (id.index_a + n - 1) % n}) {
      const Vec2c p = detail::image_point(pose, widen(a[e])), q = detail::image_point(pose, widen(a[(e + 1) % n]));
      const Vec2c d = q - p;
      const double t = std::clamp((surface - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
      reach = std::min(reach, (surface - (p + d * t)).norm());
    }
    EXPECT_LT(reach, 1e31) << "point " << i << " names vertex " << int(id.index_a);
  }
  EXPECT_GT(vertices, 0) << "no point names a vertex of a: the clipped point this pins is gone";
}

/// A float triangle 10^-5 high translated to y = 2^40, where the float translation's image rounds
/// its apex onto its base: the image is the segment between the base's ends. A circle beyond the
/// left end touches it, and the point must name that end's stored vertex (2), not the segment's
/// first end (0).
TEST(TransformRegression, FlattenedPolygonImageNamesTheStoredVertexAtItsEnd) {
  using V = Vec2<float>;
  const ConvexPolygon<float> tri = *ConvexPolygon<float>::make({V(1024, 0), V(512, 1e-5f), V(0, 0)});
  ASSERT_EQ(tri[2], V(0, 0));
  const Transform<float> x = *Transform<float>::make_translation(V(0, 0x1p40f));
  const auto c = contact(tri, x, *Circle<float>::make(V(-50, 0x1p40f), 100), Transform<float>());
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 1);
  EXPECT_EQ(c->ids[0].kind_a, FeatureKind::Vertex);
  EXPECT_EQ(c->ids[0].index_a, 2);
}

/// A triangle 2.4 x 10^103 wide placed at y = 1.2 x 10^123, where its image flattens onto the
/// segment from its vertices 0 and 2 (rounded onto one point) to vertex 1. A box's face clips it
/// into two points, and both named vertex 1: each clipped point lies on vertex 1's two edges, and
/// the nearest-edges rule looked among every stored vertex. Each end names a stored vertex at that
/// end, so the two points name two features.
TEST(TransformRegression, FlattenedPolygonImageNamesEachEndByItsOwnVertices) {
  using V = Vec2<double>;
  const ConvexPolygon<double> tri = *ConvexPolygon<double>::make({V(-0x1.13889b0c7cdf5p+334, -0x1.2250d05fd3551p+332),
                                                                  V(0x1.5ee5510d9bf5ap+343, -0x1.2250d05fd3551p+332),
                                                                  V(-0x1.13889b0c7cdf5p+334, 0x1.518d67a7acee7p+343)});
  const Transform<double> xa = *Transform<double>::make_with_rotation(V(0x1.f1f1f1f1f1f1fp-526, 0x1.d8d1f1f1f1f1fp+408),
                                                                      V(1, 0x1.6daa85519322fp-66));
  const Obb<double> box = *Obb<double>::make_with_axis(V(-0x1.8782d9430d3ffp+391, -0x1.9c83e793be72p+389),
                                                       V(0x1.98fcd74597d8dp+406, 0x1.97d58cd8f8d74p+390),
                                                       V(0x1.6a09e667f3bcdp-1, 0x1.6a09e667f3bcdp-1));
  const Transform<double> xb = *Transform<double>::make_with_rotation(V(0x1.f1f1f1f1f1f1fp-526, 0x1.d8d1f1f1f1f2p+408),
                                                                      V(-0x1.6a09e667f3bc7p-1, -0x1.6a09e667f3bd1p-1));
  const auto c = contact(tri, xa, box, xb);
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->count, 2);
  EXPECT_NE(c->ids[0], c->ids[1]);
  EXPECT_NE(c->ids[0].index_a, c->ids[1].index_a);
}

/// A polygon with vertices at 2^500 (the largest magnitude) placed by a translation of 2^449 and a
/// tiny rotation: its bottom face's three vertices round onto one line, and one image vertex lies
/// at 2^500 + 2^449, beyond the magnitude the factories accept. The image is the hull of the
/// rounded vertices all the same (not the segment along its diagonal, 2^500 / sqrt(2) from the
/// origin): the distance to a point at the origin is that of the bottom face's middle vertex, 2^449.
TEST(TransformRegression, PolygonImageBeyondTheLargestMagnitudeIsStillItsHull) {
  using V = Vec2<double>;
  const ConvexPolygon<double> poly =
      *ConvexPolygon<double>::make({V(-0x1.6a6a63affb001p-405, 0x1.6a6a6a6a6a6a6p+11), V(0, 0),
                                    V(0x1p+500, -0x1.ffffffffffffep-1), V(0x1.1799a9ae4b004p-80, 0x1p+500)});
  const V p(0, 0x1.0000081p+449);
  const Transform<double> x = *Transform<double>::make_with_rotation(p, V(1, 0x1.ba3df57c0943p-319));
  const Circle<double> dot = *Circle<double>::make(V(0x0.0008e8e8e8ep-1022, 0), 0);
  const Compound<double> child = *Compound<double>::make_placed({{Primitive<double>(poly), x}});
  for (const double d : {distance(poly, x, dot, Transform<double>()), distance(child, dot)})
    EXPECT_NEAR(d, p.y(), 1e-6 * p.y());
}

/// A 13-unit AABB and a triangle 0.094 wide at its centre, both stored near (-10^6, 10^6) and
/// placed near the origin by one rotation: the box's bottom face and the triangle's top face lie
/// on one axis and are exactly as deep, so a's face is the reference (feature.hpp) wherever b
/// slides a little. The images' points round at their stored magnitude, 10^6, not at the world's
/// 2 10^4, which moved the two faces' computed depths 10^-10 apart, beyond the tie of the world
/// scale: b's face took over at one position in eight. A failure names a position whose reference
/// face is another.
TEST(TransformRegression, FacesEquallyDeepInPlacedImagesKeepAsFaceAsTheReference) {
  using V = Vec2<double>;
  const Aabb<double> box = *Aabb<double>::make(V(-0x1.e85p+19, 0x1.e8486p+19), V(-0x1.e84e6p+19, 0x1.e84ap+19));
  const Transform<double> x = *Transform<double>::make_with_rotation(V(0x1.e847p+19, -0x1.e848p+19),
                                                                     V(0x1.ffed789fc7a41p-1, -0x1.137a9c2cb3e7ep-6));
  const std::array<V, 3> triangle{V(-0x1.e84f2ep+19, 0x1.e849305555555p+19), V(-0x1.e84f31p+19, 0x1.e849305555555p+19),
                                  V(-0x1.e84f31p+19, 0x1.e8492f5555555p+19)};
  for (int k = -100; k <= 100; ++k) {
    const V t = V(3, 4) * (k * 0x1p-17);
    const ConvexPolygon<double> b = *ConvexPolygon<double>::make({triangle[0] + t, triangle[1] + t, triangle[2] + t});
    const std::optional<Contact<double>> c = contact(box, x, b, x);
    ASSERT_TRUE(c) << "b moved by " << k << " steps";
    ASSERT_EQ(c->count, 2) << "b moved by " << k << " steps";
    for (int i = 0; i < 2; ++i) {
      const FeatureId& id = c->ids[std::size_t(i)];
      EXPECT_TRUE(id.kind_a == FeatureKind::Edge && id.index_a == 0 && id.kind_b == FeatureKind::Vertex)
          << "b moved by " << k << " steps: point " << i << " names a's "
          << (id.kind_a == FeatureKind::Edge ? "edge " : "vertex ") << int(id.index_a) << " and b's "
          << (id.kind_b == FeatureKind::Edge ? "edge " : "vertex ") << int(id.index_b);
    }
  }
}

/// A float compound of a circle and an AABB, each with a child transform, placed by the rotation
/// (0, 0.99999994), whose squared length is within float's 4 eps of 1 and is stored as given: it
/// scales positions by |q| but not the circle's radius. The compound's world box was the image of
/// its local box, scaled with it, and fell 1.5 10^-8 short of the circle's image at the top. A
/// failure names the side of the box that misses the circle.
TEST(TransformRegression, PlacedCompoundBoxUnderARotationStoredAsGivenHoldsItsCircle) {
  using V = Vec2<float>;
  const Circle<float> circle = *Circle<float>::make(V(-0x1.d5efa2p-1f, -0x1.f1252ap-1f), 0.5f);
  const Transform<float> tc =
      *Transform<float>::make_with_rotation(V(-0x1.6af7ccp+0f, -0x1.f1252ap-1f), V(0x1p-148f, 1));
  const Aabb<float> box = *Aabb<float>::make(V(-0x1.6af7dp+0f, -0x1.789294p+0f), V(-0x1.abdf44p-2f, -0x1.e24a54p-2f));
  const Transform<float> tb = *Transform<float>::make_with_rotation(V(-0x1.abdf44p-2f, -0x1.f1252ap-1f), V(0, -1));
  const Compound<float> body =
      *Compound<float>::make_placed({{Primitive<float>(circle), tc}, {Primitive<float>(box), tb}});
  const Transform<float> x = *Transform<float>::make_with_rotation(V(0x1p-149f, 0x1.7ep-142f), V(0, 0x1.fffffep-1f));
  ASSERT_EQ(x.rotation().y(), 0x1.fffffep-1f);  // stored as given
  // The circle's exact image centre, in double (each product and sum exact up to 10^-16).
  const Vec2c local = Vec2c(0x1p-148 * double(circle.center().x()) - double(circle.center().y()),
                            double(circle.center().x()) + 0x1p-148 * double(circle.center().y())) +
                      widen(tc.position());
  const Vec2c centre(-double(x.rotation().y()) * local.y() + double(x.position().x()),
                     double(x.rotation().y()) * local.x() + double(x.position().y()));
  for (const Aabb<float>& b : {bounds(Shape<float>(body), x), bounds(body, x)}) {
    EXPECT_LE(double(b.min().x()), centre.x() - 0.5 + 1e-12) << "left";
    EXPECT_GE(double(b.max().x()), centre.x() + 0.5 - 1e-12) << "right";
    EXPECT_LE(double(b.min().y()), centre.y() - 0.5 + 1e-12) << "bottom";
    EXPECT_GE(double(b.max().y()), centre.y() + 0.5 - 1e-12) << "top";
  }
}

// A circle against a polygon turned by a general rotation is computed in the polygon's frame
// (detail/contact_local.hpp), not on the images. Its answer must be the images' answer: present
// exactly when the imaged pair's contact is (both are exact on the computed images), the same
// features, and values within a few rounding units of T. Half the circles are sized to touch the
// polygon up to a hair (the local band then leaves most to the images); positions reach 1e4, where
// the images' own rounding exceeds the local computation's. A failure names a local decision that
// the images contradict, or a local value off the imaged one.
TYPED_TEST(Transforms, CirclePolygonInThePolygonsFrameIsTheImagesAnswer) {
  using T = TypeParam;
  using V = Vec2<T>;
  const std::vector<ConvexPolygon<T>> polygons = turn_margin_polygons<T>();
  std::mt19937 rng(20261204);
  std::uniform_real_distribution<T> unit(-1, 1), angle(-4, 4), radius(T(0.05), T(2));
  long decided = 0, present = 0, cases = 0;
  for (int i = 0; i < 20000; ++i) {
    const ConvexPolygon<T>& poly = polygons[std::size_t(i) % polygons.size()];
    const T scale = T(std::pow(10.0, double(i % 6) - 1));
    const auto xb = Transform<T>::make(V(unit(rng) * scale, unit(rng) * scale), angle(rng)).value();
    const auto xa = Transform<T>::make(xb.position() + V(unit(rng) * 6, unit(rng) * 6), angle(rng)).value();
    Circle<T> circle(V(unit(rng), unit(rng)), radius(rng));
    if (i % 2 == 1) {
      // Within a few of the images' rounding units of touching (double radii can get there).
      const T gap = distance(circle, xa, poly, xb);
      const T touching = circle.radius() + gap + T(4 * transform_tolerance(poly, xb) * unit(rng));
      if (!(touching > 0)) continue;
      circle = Circle<T>(circle.center(), touching);
    }
    ++cases;
    const detail::LocalContact local = detail::contact_local(circle, xa.pose(), poly, xb.pose(), 0.0);
    decided += local.decided;
    const auto imaged = detail::with_placed_pair(
        circle, xa, poly, xb, [](const auto& pa, const auto& pb) { return detail::contact_as<T>(pa, pb); });
    const auto c = contact(circle, xa, poly, xb), swapped = contact(poly, xb, circle, xa);
    ASSERT_EQ(bool(c), bool(imaged)) << "case " << i << ": presence differs from the images'";
    ASSERT_EQ(bool(swapped), bool(c)) << "case " << i;
    if (!c) continue;
    ++present;
    EXPECT_EQ(swapped->normal, (-c->normal).eval()) << "case " << i << ": not symmetric";
    EXPECT_EQ(swapped->ids[0], c->ids[0].swapped()) << "case " << i;
    const double unit_error = rounding_tolerance(circle, xa, poly, xb);
    const double eps = double(std::numeric_limits<T>::epsilon());
    EXPECT_EQ(c->ids[0], imaged->ids[0]) << "case " << i << ": another feature than the images'";
    EXPECT_LE((widen(c->normal) - widen(imaged->normal)).norm(), 4 * eps) << "case " << i;
    EXPECT_LE(std::fabs(double(c->depth) - double(imaged->depth)), 4 * unit_error + 2 * eps * double(imaged->depth))
        << "case " << i;
    const Vec2c p = widen(c->points[0]), q = widen(imaged->points[0]);
    EXPECT_LE((p - q).norm(), 4 * unit_error + 2 * eps * q.norm()) << "case " << i;
  }
  // The local path must carry most pairs, or this test would judge the images against themselves.
  EXPECT_GT(decided, cases * 6 / 10);
  EXPECT_GT(present, cases / 3);
}

TYPED_TEST(Transforms, CompoundChildrenCarryTheirTransforms) {
  using T = TypeParam;
  using V = Vec2<T>;
  using Child = typename Compound<T>::Child;
  // Two circles of radius 1 placed at x = -3 and x = +3 in the body's frame.
  const Compound<T> body =
      Compound<T>::make_placed(
          std::vector<Child>{{Circle<T>(V(0, 0), 1), Transform<T>::make_translation(V(-3, 0)).value()},
                             {Circle<T>(V(0, 0), 1), Transform<T>::make_translation(V(3, 0)).value()}})
          .value();
  EXPECT_TRUE(body.has_child_transforms());
  EXPECT_LE(body.bounds().min().x(), T(-4));
  EXPECT_GT(body.bounds().min().x(), T(-4.001));
  const Circle<T> probe(V(3, 1.5), T(0.5));
  EXPECT_TRUE(overlaps(body, probe));  // touches the right child at (3, 1)
  EXPECT_FALSE(overlaps(body, Circle<T>(V(0, 0), T(1.5))));
  // Turned half a turn about the origin of its frame, the body is the same point set.
  const auto half = Transform<T>::make_with_rotation(V(0, 0), V(-1, 0)).value();
  EXPECT_TRUE(overlaps(body, half, probe, Transform<T>()));
  // Turned a quarter, its children sit at y = -3 and y = +3.
  const auto quarter = Transform<T>::make_with_rotation(V(0, 0), V(0, 1)).value();
  EXPECT_FALSE(overlaps(body, quarter, probe, Transform<T>()));
  EXPECT_TRUE(contains(body, quarter, V(0, 4)));
  const V push = resolve(probe, Transform<T>(), body, quarter);
  EXPECT_EQ(push, V(0, 0));
  const V out = resolve(Circle<T>(V(0.5, 3), 1), Transform<T>(), body, quarter);
  EXPECT_FALSE(overlaps(translated(Circle<T>(V(0.5, 3), 1), out).value(), Transform<T>(), body, quarter));
  // Moving the compound moves the children's transforms.
  const Compound<T> moved = translated(body, V(10, 0)).value();
  EXPECT_EQ(moved.child_transform(1).position(), V(13, 0));
  EXPECT_TRUE(overlaps(moved, Circle<T>(V(13, 1.5), T(0.5))));
}

/// The gap a float or double ball of radius 0.5, sunk 0.1 into a ground box of half-width w
/// (top face y = 0), is left with after resolve(): the margin depends on the ball's own
/// coordinates and the depth, not on w.
template <Scalar T, class Ground>
double ground_gap(const Ground& ground) {
  const Circle<T> ball(Vec2<T>(0, T(0.4)), T(0.5));
  const Vec2<T> push = resolve(ball, ground);
  const Circle<T> after = translated(ball, push).value();
  EXPECT_FALSE(overlaps(after, ground)) << "the pushed ball still overlaps (exact decision)";
  return double(after.center().y()) - 0.5;  // exact: the top face is y = 0
}

TYPED_TEST(Transforms, GroundBoxLeavesTheBallWithinTheMarginOfItsOwnScale) {
  using T = TypeParam;
  using V = Vec2<T>;
  for (const T w : {T(10), T(1e3), T(1e5)}) {
    const Aabb<T> box(V(-w, -1), V(w, 0));
    const Obb<T> obb = Obb<T>::make_with_axis(V(0, T(-0.5)), V(w, T(0.5)), V(1, 0)).value();
    for (const double gap : {ground_gap<T>(box), ground_gap<T>(obb)}) {
      EXPECT_GT(gap, 0) << "half-width " << w;
      EXPECT_LE(gap, 1e-5) << "half-width " << w;
      // The documented margin, for the ball against this ground pushed up, bounds the gap.
      EXPECT_LE(gap, 2 * resolve_margin(Circle<T>(V(0, T(0.4)), T(0.5)), box, 0.1, V(0, -1))) << "half-width " << w;
    }
  }
}

/// A float ball of radius 0.5 sunk 0.01 into a ground box (top face y = 0) far along the ground,
/// stored there or placed there by a translation. The push is along y, which a move rounds at the
/// ball's own magnitude (about 1); x, across the push, is not moved at all, so the margin must not
/// grow with it. A gap above 1e-5 at x = 1e5 (or above twice the documented margin further out)
/// means the margin grew with the coordinate across the push.
TEST(TransformRegression, FloatBallFarAlongTheGroundRestsOnIt) {
  using V = Vec2<float>;
  for (const float x : {1e5f, 1e6f, 1e7f}) {
    const Aabb<float> ground(V(x - 10, -1), V(x + 10, 0));
    const Circle<float> ball(V(x, 0.49f), 0.5f);
    const V push = resolve(ball, ground);
    EXPECT_EQ(push.x(), 0.0f) << "x = " << x;
    const Circle<float> after = translated(ball, push).value();
    EXPECT_FALSE(overlaps(after, ground)) << "x = " << x << ": the pushed ball still overlaps";
    const double gap = double(after.center().y()) - 0.5;  // exact
    EXPECT_GT(gap, 0) << "x = " << x;
    EXPECT_LE(gap, 2 * resolve_margin(ball, ground, 0.01, V(0, -1))) << "x = " << x;
    if (x == 1e5f) {
      EXPECT_LE(gap, 1e-5) << "x = " << x;
    }

    // The same ball stored at x = 0 and placed at x by its transform, whose position a move rounds.
    const Circle<float> local(V(0, 0.49f), 0.5f);
    const Transform<float> at = Transform<float>::make_translation(V(x, 0)).value();
    const V placed_push = resolve(local, at, ground, Transform<float>());
    const Transform<float> moved = at.moved(placed_push).value();
    EXPECT_FALSE(overlaps(local, moved, ground, Transform<float>())) << "x = " << x << ": still overlapping";
    const double placed_gap = double(moved.position().y()) + 0.49 - 0.5;  // exact
    EXPECT_GT(placed_gap, 0) << "x = " << x;
    EXPECT_LE(placed_gap, 2 * resolve_margin(local, at, ground, Transform<float>(), 0.01, V(0, -1))) << "x = " << x;
    if (x == 1e5f) {
      EXPECT_LE(placed_gap, 1e-5) << "x = " << x;
    }
  }
}

TYPED_TEST(Transforms, ListHelpersDeduceTheScalar) {
  using T = TypeParam;
  using V = Vec2<T>;
  const std::vector<Shape<T>> shapes = {Circle<T>(V(0, 0), 1), Aabb<T>(V(1, -1), V(3, 1)), Circle<T>(V(9, 9), 1)};
  const auto pairs = broadphase::find_overlapping_shapes(shapes);
  ASSERT_EQ(pairs.size(), 1u);
  const auto contacts = broadphase::find_contacts(shapes);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].b, 1u);
  const auto hit = broadphase::raycast_shapes(shapes, Ray<T>{V(9, 0), V(0, 1)}, T(100));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->index, 2u);
  const std::array<Shape<T>, 2> fixed = {shapes[0], shapes[1]};
  EXPECT_EQ(broadphase::find_contacts(fixed).size(), 1u);
}

}  // namespace
}  // namespace collide::test
