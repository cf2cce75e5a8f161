// Bounding boxes are conservative at 1e30 and at subnormal scales, for every kind (driven by the
// registry). "Conservative" is checked exactly: each box side is compared with the exact extreme
// coordinate of the stored shape by an exact sign of a sum of products, so a box that is one ulp
// too small fails (the pad/outward-rounding step of bounds_from_calc is what this pins down).

#include "support.hpp"

#include <cmath>
#include <limits>

namespace collide::test {
namespace {

template <class T>
class Scale : public ::testing::Test {};
TYPED_TEST_SUITE(Scale, Scalars);

/// Exact sign of p0 + q0 * q1 + r0 * r1 + s0 * s1 (doubles). Values are first scaled by 2^k
/// (k applied to the first factor of each product and to p0) so that no product underflows.
int exact_sign(double p0, double q0, double q1, double r0, double r1, double s0, double s1) {
  const double m = std::max({std::fabs(p0), std::fabs(q0), std::fabs(r0), std::fabs(s0)});
  const int k = (m > 0 && m < 0x1p-400) ? 600 : 0;
  auto sc = [k](double x) { return std::ldexp(x, k); };
  const detail::Term q = detail::two_product(sc(q0), q1), r = detail::two_product(sc(r0), r1),
                     s = detail::two_product(sc(s0), s1);
  const double terms[7] = {sc(p0), q.hi, q.lo, r.hi, r.lo, s.hi, s.lo};
  return detail::exact_sign_of_sum(terms);
}

/// lo <= (c - sum of |extents|) and (c + sum) <= hi on one axis, exactly.
/// Extents are given as products e_i * f_i (f_i >= 0).
void expect_covers(double lo, double hi, double c, double e1, double f1, double e2, double f2) {
  // lo - c + e1 f1 + e2 f2 <= 0
  EXPECT_LE(exact_sign(lo, c, -1.0, e1, f1, e2, f2), 0) << "low side " << lo << " vs centre " << c;
  // c + e1 f1 + e2 f2 - hi <= 0
  EXPECT_LE(exact_sign(-hi, c, 1.0, e1, f1, e2, f2), 0) << "high side " << hi << " vs centre " << c;
}

template <Scalar T>
void expect_conservative(const Aabb<T>& b, const Circle<T>& s) {
  for (int i = 0; i < 2; ++i) expect_covers(b.min()[i], b.max()[i], s.center()[i], s.radius(), 1.0, 0.0, 0.0);
}
template <Scalar T>
void expect_conservative(const Aabb<T>& b, const Aabb<T>& s) {
  EXPECT_TRUE(b.min().x() <= s.min().x() && b.min().y() <= s.min().y());
  EXPECT_TRUE(s.max().x() <= b.max().x() && s.max().y() <= b.max().y());
}
template <Scalar T>
void expect_conservative(const Aabb<T>& b, const Obb<T>& s) {
  // Extreme x: c.x + hx |u.x| + hy |v.x|, v = perp(u) = (-u.y, u.x); likewise for y.
  const double ux = std::fabs(double(s.axis().x())), uy = std::fabs(double(s.axis().y()));
  expect_covers(b.min().x(), b.max().x(), s.center().x(), s.half_extents().x(), ux, s.half_extents().y(), uy);
  expect_covers(b.min().y(), b.max().y(), s.center().y(), s.half_extents().x(), uy, s.half_extents().y(), ux);
}
template <Scalar T>
void expect_conservative(const Aabb<T>& b, const Capsule<T>& s) {
  for (int i = 0; i < 2; ++i) {
    expect_covers(b.min()[i], b.max()[i], s.a()[i], s.radius(), 1.0, 0.0, 0.0);
    expect_covers(b.min()[i], b.max()[i], s.b()[i], s.radius(), 1.0, 0.0, 0.0);
  }
}
template <Scalar T>
void expect_conservative(const Aabb<T>& b, const ConvexPolygon<T>& s) {
  for (const Vec2<T>& p : s.vertices()) {
    EXPECT_TRUE(b.min().x() <= p.x() && p.x() <= b.max().x() && b.min().y() <= p.y() && p.y() <= b.max().y());
  }
}
template <Scalar T>
void expect_conservative(const Aabb<T>& b, const Compound<T>& s) {
  for (const Primitive<T>& c : s.children()) std::visit([&](const auto& x) { expect_conservative(b, x); }, c);
}

/// Not too loose either: each side within 16 ulps of T at the shape's scale (+ 4 subnormal units).
template <Scalar T, class S>
void expect_tight(const Aabb<T>& b, const S& s, double width_x, double width_y) {
  const double sc = detail::scale_of(b);
  const double slack =
      16 * double(std::numeric_limits<T>::epsilon()) * sc + 4 * double(std::numeric_limits<T>::denorm_min());
  EXPECT_LE(double(b.max().x()) - double(b.min().x()), width_x + 2 * slack);
  EXPECT_LE(double(b.max().y()) - double(b.min().y()), width_y + 2 * slack);
  static_cast<void>(s);
}

template <Scalar T>
std::vector<T> odd_scales() {
  // Non-dyadic factors so that c +- r rounds: 1e30, normal-but-tiny, and subnormal.
  if constexpr (std::is_same_v<T, float>) {
    return {T(1e30), T(-3e35), T(1e-36), T(3e-41), T(7e-45)};
  } else {
    return {1e30, -3e145, 1e-300, 3e-310, 5e-322};
  }
}

TYPED_TEST(Scale, BoundsConservativeForEveryKind) {
  using T = TypeParam;
  for (T s : odd_scales<T>()) {
    SCOPED_TRACE(std::to_string(double(s)));
    const Vec2<T> c(T(1.2345678) * s, T(-0.7654321) * s);
    const T h = std::fabs(T(0.3141592) * s);
    for_each_kind([&]<ShapeKind K>() {
      SCOPED_TRACE(std::string(name(K)));
      const auto shape = make_kind<K, T>(c, h);
      expect_conservative(bounds(shape), shape);
      if constexpr (K == ShapeKind::Aabb) {  // an AABB is its own bounds, exactly
        EXPECT_EQ(bounds(shape).min(), shape.min());
        EXPECT_EQ(bounds(shape).max(), shape.max());
      }
      expect_conservative(bounds(Shape<T>(shape)), shape);
    });
    // Turned and tilted shapes, whose extremes are sums of products.
    const Obb<T> obb(c, Vec2<T>(h, h / 2), T(0.3));
    expect_conservative(bounds(obb), obb);
    expect_tight(bounds(obb), obb, 2 * (double(h) * std::cos(0.3) + double(h) / 2 * std::sin(0.3)),
                 2 * (double(h) * std::sin(0.3) + double(h) / 2 * std::cos(0.3)));
    const Capsule<T> cap(c, Vec2<T>(c.x() + h, c.y() + T(0.7) * h), h / 3);
    expect_conservative(bounds(cap), cap);
    const Circle<T> circle(c, h);
    expect_tight(bounds(circle), circle, 2 * double(h), 2 * double(h));
  }
}

TYPED_TEST(Scale, OverlapTolerancesStayFiniteAndSmallAtTheLimit) {
  using T = TypeParam;
  // Shapes at max_magnitude with radius max_magnitude: boxes reach 2x the limit, squares of the
  // differences reach 16x its square; nothing may overflow to inf or NaN.
  const T m = max_magnitude<T>();
  const Circle<T> a(Vec2<T>(m, m), m), b(Vec2<T>(-m, -m), m);
  EXPECT_FALSE(overlaps(a, b));             // centres 2 sqrt(2) m apart, radii sum 2 m
  EXPECT_EQ(overlap_tolerance(a, b), 0.0);  // decisions are exact
  const Calc tol = rounding_tolerance(a, b);
  EXPECT_TRUE(std::isfinite(tol));
  EXPECT_LT(tol, 1e-12 * double(m));
  const T gap = distance(a, b);
  EXPECT_NEAR(double(gap), (2 * std::sqrt(2.0) - 2) * double(m), 1e-5 * double(m));
  const Capsule<T> cap(Vec2<T>(-m, m), Vec2<T>(m, -m), m);
  EXPECT_TRUE(overlaps(cap, a));
  const auto c = contact(cap, a);
  ASSERT_TRUE(c.has_value());
  EXPECT_TRUE(c->normal.allFinite());
  EXPECT_TRUE(std::isfinite(double(c->depth)));
  const Vec2<T> v = resolve(cap, a);
  EXPECT_TRUE(v.allFinite());
  const Obb<T> obb(Vec2<T>(m, -m), Vec2<T>(m, m), T(0.5));
  EXPECT_TRUE(overlaps(obb, cap));
  EXPECT_TRUE(std::isfinite(double(distance(obb, b))));
}

TYPED_TEST(Scale, DecisionsAreExactAtTheExtremes) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Exactly touching at the largest magnitude and at the smallest (subnormal) one, then one ulp
  // apart: the squares of these differences overflow or underflow in the computation type.
  const T m = max_magnitude<T>();
  const T tiny = std::numeric_limits<T>::denorm_min();
  for (const T s : {T(m / 8), T(tiny)}) {
    SCOPED_TRACE(double(s));
    const Circle<T> a(V(0, 0), 2 * s), b(V(3 * s, 4 * s), 3 * s);
    EXPECT_TRUE(overlaps(a, b));
    EXPECT_FALSE(overlaps(a, Circle<T>(V(3 * s, std::nextafter(4 * s, m)), 3 * s)));
    const Capsule<T> cap(V(-5 * s, 0), V(-5 * s, -4 * s), 3 * s);  // 5 s away, radii 2 s + 3 s
    EXPECT_TRUE(overlaps(a, cap));
    EXPECT_FALSE(overlaps(a, Capsule<T>(V(std::nextafter(-5 * s, -m), 0), V(-5 * s, -4 * s), 3 * s)));
    const Obb<T> box(V(4 * s, 0), V(2 * s, 2 * s), T(0));
    EXPECT_TRUE(overlaps(a, box));  // touching at (2 s, 0)
    EXPECT_FALSE(overlaps(a, Obb<T>(V(std::nextafter(4 * s, m), 0), V(2 * s, 2 * s), T(0))));
  }
}

TYPED_TEST(Scale, ThinBoxCollapsedByRoundingIsASegment) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Half height 2^-40 at y = 2^30: the corners' y = 2^30 +- 2^-40 round to 2^30 in double, so the
  // computed corners coincide in pairs. Treated as a flat 4-gon, separating axes taken from its
  // (parallel) edges cannot separate it from another flat box on the same line: these two boxes,
  // 1 apart along x (far above the error bound, ~8e-6 here), would be reported as overlapping.
  const Obb<T> a(V(0, T(0x1p30)), V(1, T(0x1p-40)), T(0));
  const Obb<T> b(V(3, T(0x1p30)), V(1, T(0x1p-40)), T(0));
  EXPECT_FALSE(overlaps(a, b));
  EXPECT_TRUE(overlaps(a, Obb<T>(V(2, T(0x1p30)), V(1, T(0x1p-40)), T(0))));  // touching at x = 1
  EXPECT_TRUE(contains(a, V(T(0.5), T(0x1p30))));
  EXPECT_NEAR(double(distance(a, b)), 1.0, 1e-5);
  const auto hit = raycast(a, Ray<T>{V(-5, T(0x1p30)), V(1, 0)}, T(100));
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(double(hit->t), 4.0, 1e-4);
}

TYPED_TEST(Scale, NeedleBoxAtTheOriginCollapsedByRoundingIsASegment) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Half extents 2^100 x 2^-60 along the diagonal, centred at the origin: each corner's 2^-60 part
  // is lost next to 2^100 u, so the four computed corners coincide in pairs. The thin-box check
  // compared the short side with |centre| (0 here) instead of |centre| + the long side, kept the
  // 4-gon with its duplicate corners, and none of its edges separated a segment lying on the same
  // diagonal beyond the needle's end: 2^102 away, it was reported overlapping (found by the fuzz
  // target overlap_oracle, case agreement-aabb_obb-double-a5c12c69).
  const Obb<T> needle = Obb<T>::make_with_axis(V(0, 0), V(T(0x1p100), T(0x1p-60)), V(1, 1)).value();
  const Aabb<T> far(V(-T(0x1p102), -T(0x1p102)), V(-T(0x1p102), 0));  // lower end on the diagonal
  EXPECT_FALSE(overlaps(needle, far));
  EXPECT_FALSE(overlaps(far, needle));
  EXPECT_GT(double(distance(needle, far)), 0x1p100);
  const Aabb<T> on_needle(V(-T(0x1p99), -T(0x1p99)), V(-T(0x1p99), 0));  // lower end on the needle
  EXPECT_TRUE(overlaps(needle, on_needle));
}

}  // namespace
}  // namespace collide::test
