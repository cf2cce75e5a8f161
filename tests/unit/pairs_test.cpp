// Every pair of the registry, both argument orders, both scalars, at several scales: separated,
// exactly touching, just separated / just overlapping (by 2^-18 of the size; exact decisions),
// overlapping, one containing the other, coincident. Then contact, resolve and distance on the
// same configurations. The pairs come from for_each_pair and the shapes from make_kind, so a new
// kind or pair is covered without editing this file.

#include "support.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>

namespace collide::test {
namespace {

/// The scales every pair is checked at: ordinary, 1e18 and 1e30-ish (powers of two keep every
/// coordinate exact), a quarter of max_magnitude (squares of differences near the overflow
/// limit of the computation), and tiny (subnormal double; near-subnormal float).
template <Scalar T>
std::vector<T> scales() {
  if constexpr (std::is_same_v<T, float>) {
    return {T(1), T(0x1p60), T(0x1p100), max_magnitude<T>() / 4, T(0x1p-100), T(0x1p-120)};
  } else {
    return {T(1), T(0x1p60), T(0x1p100), max_magnitude<T>() / 4, T(0x1p-900), T(0x1p-1040)};
  }
}

/// One configuration: B of extent hb centred at (x, 0), A of extent ha at the origin.
/// `gap` is the exact signed distance (gap > 0 separated, 0 touching, < 0 overlapping along x).
template <ShapeKind KA, ShapeKind KB, Scalar T>
void check_config(T ha, T hb, T x, T gap, bool contained) {
  const auto a = make_kind<KA, T>(Vec2<T>(0, 0), ha);
  const auto b = make_kind<KB, T>(Vec2<T>(x, 0), hb);
  const bool ab = overlaps(a, b);
  const bool ba = overlaps(b, a);
  // Reversed orders call the same decision: any asymmetry means a pair table disagrees with
  // itself (e.g. a reversed-argument slip in decide.hpp).
  EXPECT_EQ(ab, ba);
  // Variant dispatch must land on the same decision as the concrete call.
  EXPECT_EQ(ab, overlaps(Shape<T>(a), Shape<T>(b)));
  // Every pair is decided exactly: the answer is the exact one, touching included.
  EXPECT_EQ(overlap_tolerance(a, b), 0.0);
  const bool expected = contained || !(gap > 0);
  EXPECT_EQ(ab, expected) << "gap " << gap;
  // Depths and distances are rounded outputs, bounded by rounding_tolerance.
  const Calc tol = rounding_tolerance(a, b);
  // contact() exists exactly when overlaps() is true (same decision underneath).
  EXPECT_EQ(contact(a, b).has_value(), ab);
  EXPECT_EQ(contact(b, a).has_value(), ab);
  if (!ab) {
    EXPECT_EQ(resolve(a, b), Vec2<T>::Zero());
    // The gap along x is the true distance here (every point of A has x <= ha, every point of B
    // x >= ha + gap, and (ha, 0), (ha + gap, 0) belong to them). A failure is a wrong closest pair.
    if (gap > 0 && std::fabs(Calc(gap)) > 8 * tol) {
      EXPECT_NEAR(Calc(distance(a, b)), Calc(gap), 8 * tol + 4 * Calc(std::numeric_limits<T>::epsilon()) * gap);
    }
    return;
  }
  EXPECT_EQ(distance(a, b), T(0));
  const auto c = contact(a, b);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->normal.template cast<Calc>().norm(), 1.0, 1e-6);  // a unit normal (rounded to T)
  EXPECT_GE(c->depth, T(0));
  // Resolve then re-test: moving a by resolve(a, b) must separate (strictly, after rounding to T).
  const Vec2<T> v = resolve(a, b);
  const auto moved = translated(a, v);
  ASSERT_TRUE(moved.has_value());
  EXPECT_FALSE(overlaps(moved.value(), b)) << "resolve " << v.transpose();
  if (gap <= 0 && !contained && std::fabs(Calc(gap)) > 8 * tol) {
    // Pushing a by |gap| along -x separates, so the minimum translation is at most that:
    // a longer push means the least-penetration axis was missed.
    const Calc margin = 256 * resolve_margin(a, b, -Calc(gap), c->normal);
    EXPECT_LE(Calc(c->depth), -Calc(gap) + 8 * tol);
    EXPECT_LE(v.template cast<Calc>().norm(), -Calc(gap) + margin);
    // And |resolve| is the contact depth plus a margin, no more.
    EXPECT_NEAR(v.template cast<Calc>().norm(), Calc(c->depth), margin);
  }
}

template <ShapeKind KA, ShapeKind KB, Scalar T>
void check_pair_at(T s) {
  const T ha = s, hb = s / 2;
  const T near = s * T(0x1p-18);  // far below the shapes' size
  SCOPED_TRACE((pair_label<KA, KB>() + " scale " + std::to_string(double(s))));
  {
    SCOPED_TRACE("separated");
    check_config<KA, KB, T>(ha, hb, ha + hb + hb / 2, hb / 2, false);
  }
  {
    SCOPED_TRACE("just separated");
    check_config<KA, KB, T>(ha, hb, ha + hb + near, near, false);
  }
  {
    SCOPED_TRACE("exactly touching");
    check_config<KA, KB, T>(ha, hb, ha + hb, T(0), false);
  }
  {
    SCOPED_TRACE("just overlapping");
    check_config<KA, KB, T>(ha, hb, ha + hb - near, -near, false);
  }
  {
    SCOPED_TRACE("one ulp apart");
    const T x = std::nextafter(ha + hb, std::numeric_limits<T>::infinity());
    check_config<KA, KB, T>(ha, hb, x, x - (ha + hb), false);
  }
  {
    SCOPED_TRACE("one ulp overlapping");
    const T x = std::nextafter(ha + hb, T(0));
    check_config<KA, KB, T>(ha, hb, x, x - (ha + hb), false);
  }
  {
    SCOPED_TRACE("overlapping");
    check_config<KA, KB, T>(ha, hb, ha + hb / 2, -hb / 2, false);
  }
  {
    SCOPED_TRACE("b inside a");
    check_config<KA, KB, T>(ha, ha / 8, T(0), T(0), true);
  }
  {
    SCOPED_TRACE("a inside b");
    check_config<KA, KB, T>(ha / 8, ha, T(0), T(0), true);
  }
  {
    SCOPED_TRACE("coincident");
    check_config<KA, KB, T>(ha, ha, T(0), T(0), true);
  }
}

/// One test per registry pair and scalar (named e.g. PairsDouble.circle_aabb), both argument
/// orders, every scale. Registered from for_each_pair so the list cannot drift from the registry.
template <Scalar T>
class PairTest : public ::testing::Test {
 public:
  explicit PairTest(void (*body)()) : body_(body) {}
  void TestBody() override { body_(); }

 private:
  void (*body_)();
};

template <ShapeKind A, ShapeKind B, Scalar T>
void run_pair() {
  for (T s : scales<T>()) {
    check_pair_at<A, B, T>(s);
    if constexpr (A != B) check_pair_at<B, A, T>(s);
  }
}

template <Scalar T>
int register_pairs(const char* suite) {
  int n = 0;
  for_each_pair([&]<ShapeKind A, ShapeKind B>() {
    ++n;
    ::testing::RegisterTest(suite, pair_label<A, B>().c_str(), nullptr, nullptr, __FILE__, __LINE__,
                            []() -> ::testing::Test* { return new PairTest<T>(&run_pair<A, B, T>); });
  });
  return n;
}

const int kRegisteredFloat = register_pairs<float>("PairsFloat");
const int kRegisteredDouble = register_pairs<double>("PairsDouble");

// A zero-length capsule (a point core) against a segment capsule: the point's distance to the
// segment decides, not only the distances between endpoints.
TEST(Pairs, PointCapsuleMeetsSegmentCapsuleBySegmentDistance) {
  using V = Vec2<double>;
  const Capsule<double> seg(V(-10, 0), V(10, 0), 1);
  const Capsule<double> dot(V(0, 3), V(0, 3), 2);  // 3 above the segment's middle, radii 1 + 2
  EXPECT_TRUE(overlaps(seg, dot));
  EXPECT_TRUE(overlaps(dot, seg));
  EXPECT_FALSE(overlaps(seg, Capsule<double>(V(0, std::nextafter(3.0, 4.0)), V(0, std::nextafter(3.0, 4.0)), 2)));
}

// A box whose face lies on a turned box's rightmost corner, within the rounding of that box's
// computed bounding box: the rounded box can end an ulp short of the exact corner, and the pair,
// overlapping exactly, must keep its contact (the test of boxes apart allows for that rounding).
TEST(Pairs, BoxOnATurnedBoxCornerBeyondItsRoundedBoundsHasAContact) {
  using V = Vec2<double>;
  int beyond = 0;
  for (int k = 1; k <= 4000 && beyond < 20; ++k) {
    const Obb<double> turned =
        Obb<double>::make(V(0, k * 0.37), V(1.3 + k * 1e-3, 0.7 + k * 3e-4), 0.3 + k * 1e-3).value();
    const double hi = detail::rough_box(turned).hi.x(),
                 lo = std::nextafter(hi, std::numeric_limits<double>::infinity());
    const Aabb<double> box(V(lo, turned.center().y() - 16), V(lo + 1, turned.center().y() + 16));
    if (!overlaps(turned, box)) continue;  // the rounded bound was not short of the corner
    ++beyond;
    EXPECT_TRUE(contact(turned, box).has_value()) << "k = " << k;
    EXPECT_TRUE(contact(box, turned).has_value()) << "k = " << k;
  }
  // Configurations where the rounding falls short exist, or the test proves nothing.
  EXPECT_GT(beyond, 0);
}

// Float circles just within reach of a turned box's face, where the box's stored axis (rounded
// from a unit vector) is longer than 1. The reach is the radius, or the radius plus a speculative
// distance. Measured in units of the axis' length, the excess over the face exceeds the reach for
// circles within reach by less than reach * (|axis| - 1), and those must keep their contact (the
// test of a circle beyond a box's face scales its reach by the axis' length). A speculative
// decision is on the rounded gap, so only gaps short of the distance by more than the rounding
// tolerance are asked about.
void check_circles_within_reach_of_a_turned_box_face(double speculative) {
  using V = Vec2<float>;
  const Obb<float> box = Obb<float>::make_with_axis(V(0, 0), V(2, 1), V(3, 4)).value();
  const Vec2c w = widen(box.axis());
  const double len = w.norm();
  ASSERT_GT(len, 1.0) << "the stored axis must be longer than 1 for this test to mean anything";
  const Vec2c u = w / len, v(-u.y(), u.x());
  int asked = 0, stretched = 0;
  for (int k = 0; k < 4000; ++k) {
    const float r = 0.5f + float(k) * 1e-3f;
    const double t = (double(k % 200) / 100 - 1) * 0.9;  // along the face, inside its ends
    const Vec2c centre = w * 2.0 + v * (t * len) + u * (double(r) + speculative);
    const Circle<float> circle(centre.cast<float>(), r);
    if (speculative == 0) {
      const bool overlapping = overlaps(circle, box);
      EXPECT_EQ(contact(circle, box).has_value(), overlapping) << "k = " << k;
      EXPECT_EQ(contact(box, circle).has_value(), overlapping) << "k = " << k;
      if (!overlapping) continue;
    } else {
      const double gap = distance(circle, box);
      if (!(gap < speculative - 4 * rounding_tolerance(circle, box))) continue;
      EXPECT_TRUE(contact(circle, box, speculative).has_value()) << "k = " << k << ", gap " << gap;
      EXPECT_TRUE(contact(box, circle, speculative).has_value()) << "k = " << k << ", gap " << gap;
    }
    ++asked;
    // The centre's distance beyond the face line (the rounded centre's, in double).
    const double excess = widen(circle.center()).dot(u) - 2 * len;
    if (excess > (double(r) + speculative) / len + 1e-12) ++stretched;
  }
  EXPECT_GT(asked, 0) << "no circle fell within reach";
  EXPECT_GT(stretched, 0) << "no circle fell between reach / |axis| and the reach";
}
TEST(Pairs, CircleJustInsideATurnedBoxFaceHasAContact) {
  check_circles_within_reach_of_a_turned_box_face(0);
}
TEST(Pairs, CircleJustWithinSpeculativeReachOfATurnedBoxFaceHasAContact) {
  check_circles_within_reach_of_a_turned_box_face(0.25);
}

// Circles straddling a turned box's face by about a rounding, at scales from 2^-100 to 2^100: a
// pair the quick test before the contact tells apart must be apart exactly (float shapes are told
// apart in float, double shapes in double). Some of the overlapping ones have a computed excess
// over the face beyond the radius; those keep their contact only through the test's allowance for
// rounding (the float test's margin, the double test's band).
template <Scalar T>
void check_circles_at_a_turned_box_face() {
  using V = Vec2<T>;
  int saved_by_allowance = 0, apart = 0;
  for (const T s : {T(1), T(0x1p40), T(0x1p-40), T(0x1p100), T(0x1p-100)}) {
    const Obb<T> box = Obb<T>::make(V(3 * s, -5 * s), V(2 * s, s), T(0.9)).value();
    const Vec2c c = widen(box.center()), w = widen(box.axis());
    const double len = w.norm();
    const Vec2c u = w / len, v(-u.y(), u.x());
    for (int k = 0; k < 2000; ++k) {
      const T r = s * (T(0.5) + T(k) * T(1e-3));
      const double t = (double(k % 200) / 100 - 1) * 0.9;  // along the face, inside its ends
      const Vec2c centre = c + u * (2.0 * double(s) * len + double(r)) + v * (t * double(s) * len);
      const Circle<T> circle(centre.cast<T>(), r);
      const bool overlapping = overlaps(circle, box);
      EXPECT_EQ(contact(circle, box).has_value(), overlapping) << "scale " << s << ", k = " << k;
      EXPECT_EQ(contact(box, circle).has_value(), overlapping) << "scale " << s << ", k = " << k;
      apart += !overlapping;
      // The excess over the face times |axis|, computed in T as the quick tests compute it.
      const T dx = circle.center().x() - box.center().x(), dy = circle.center().y() - box.center().y();
      const T wx = box.axis().x(), wy = box.axis().y();
      const T excess = std::fabs(dx * wx + dy * wy) - box.half_extents().x() * (wx * wx + wy * wy);
      if (overlapping && excess > r * std::max(wx * wx + wy * wy, T(1))) ++saved_by_allowance;
    }
  }
  EXPECT_GT(apart, 0) << "no circle fell beyond the face: the placements miss the boundary";
  EXPECT_GT(saved_by_allowance, 0) << "no overlapping circle had a computed excess beyond its radius";
}
TEST(Pairs, FloatCircleAtATurnedBoxFaceIsToldApartOnlyWhenApart) {
  check_circles_at_a_turned_box_face<float>();
}
TEST(Pairs, DoubleCircleAtATurnedBoxFaceIsToldApartOnlyWhenApart) {
  check_circles_at_a_turned_box_face<double>();
}

// Circle against circle and circle against a box have their common cases written out twice: in
// one straight line, and among the general steps that handle every case. Both must give the same
// contact to the bit. Near pairs (over a quarter of them overlapping) at scales from 2^-100 to 2^100,
// with and without a speculative distance, in both scalars; a failure names the pair whose two
// paths disagree.
bool same_bits(const std::optional<detail::CoreContact>& x, const std::optional<detail::CoreContact>& y) {
  if (x.has_value() != y.has_value()) return false;
  if (!x) return true;
  const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  bool same = bits(x->normal.x()) == bits(y->normal.x()) && bits(x->normal.y()) == bits(y->normal.y()) &&
              bits(x->depth) == bits(y->depth) && x->count == y->count && x->overlapping == y->overlapping;
  for (std::size_t i = 0; i < 2; ++i) {
    same = same && bits(x->points[i].x()) == bits(y->points[i].x()) &&
           bits(x->points[i].y()) == bits(y->points[i].y()) && bits(x->separations[i]) == bits(y->separations[i]) &&
           x->ids[i] == y->ids[i];
  }
  return same;
}

template <Scalar T>
void check_common_circle_paths() {
  using V = Vec2<T>;
  std::mt19937 rng(52);
  const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  int pairs = 0, overlapping = 0;
  for (const T s : {T(1), T(0x1p40), T(0x1p-40), T(0x1p100), T(0x1p-100)}) {
    for (int k = 0; k < 3000; ++k) {
      const V at(T(uniform(-3, 3) * s), T(uniform(-3, 3) * s));
      const V near = at + V(T(uniform(-3, 3) * s), T(uniform(-3, 3) * s));
      const Circle<T> a(at, T(uniform(0.2, 2) * s));
      const Circle<T> b(near, T(uniform(0.2, 2) * s));
      const Aabb<T> box = Aabb<T>::make(near - V(T(uniform(0.2, 2) * s), T(uniform(0.2, 2) * s)), near).value();
      const Obb<T> turned = Obb<T>::make(near, V(T(uniform(0.2, 2) * s), T(uniform(0.2, 2) * s)),
                                         k % 8 == 0 ? T(1.5707963267948966) : T(uniform(-3.2, 3.2)))
                                .value();
      const double speculative = k % 3 == 0 ? uniform(0, 1) * double(s) : 0;
      const Vec2c d = widen(b.center()) - widen(a.center());
      const int sign = detail::filtered_sign_dist2(d.x(), d.y(), Calc(a.radius()) + Calc(b.radius()));
      const auto circles = detail::contact_circles(a, b, sign, speculative);
      EXPECT_TRUE(same_bits(circles, detail::contact_circles_in_general(a, b, sign, speculative)))
          << "scale " << s << ", pair " << k << ", speculative " << speculative;
      const auto with_box = detail::contact_circle_rect(a, box, speculative);
      EXPECT_TRUE(same_bits(with_box, detail::contact_circle_rect_in_general(a, box, speculative)))
          << "scale " << s << ", pair " << k << " (AABB), speculative " << speculative;
      const auto with_turned = detail::contact_circle_rect(a, turned, speculative);
      EXPECT_TRUE(same_bits(with_turned, detail::contact_circle_rect_in_general(a, turned, speculative)))
          << "scale " << s << ", pair " << k << " (OBB), speculative " << speculative;
      pairs += 3;
      for (const auto* c : {&circles, &with_box, &with_turned}) overlapping += *c && (*c)->overlapping;
    }
  }
  // Pairs overlapping by more than the band take the straight line: most of the overlapping ones.
  EXPECT_GT(overlapping, pairs / 4) << "too few overlapping pairs: the common paths are hardly asked";
}
TEST(Pairs, FloatCirclesTakeTheSameContactOnTheCommonPathsAsInGeneral) {
  check_common_circle_paths<float>();
}
TEST(Pairs, DoubleCirclesTakeTheSameContactOnTheCommonPathsAsInGeneral) {
  check_common_circle_paths<double>();
}

// The registration covered the whole registry (a for_each_pair that skipped pairs would show).
TEST(Pairs, EveryRegistryPairIsRegistered) {
  EXPECT_EQ(kRegisteredFloat, int(kPairCount));
  EXPECT_EQ(kRegisteredDouble, int(kPairCount));
  EXPECT_EQ(kPairCount, 21u);
}

}  // namespace
}  // namespace collide::test
