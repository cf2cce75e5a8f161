/// Every one of the registry's pairs: the oracle agrees with the library wherever the library's
/// error contract binds (outside the band around the boundary), in both argument orders.

#include "collide/oracle/oracle.hpp"
#include "sample_shapes.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace collide::oracle {
namespace {

struct Tally {
  int judged = 0, overlapping = 0, apart = 0, in_band = 0;
};

template <ShapeKind A, ShapeKind B>
Tally check_pair(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(-2.5, 2.5);
  Tally t;
  for (int i = 0; i < 300; ++i) {
    const auto a = testing::sample_shape<A>(rng, Vec2<double>(pos(rng), pos(rng)), 1.0);
    const auto b = testing::sample_shape<B>(rng, Vec2<double>(0, 0), 1.0);
    // Far from the boundary: 1e-6 is far above overlap_tolerance() at this scale (~1e-14).
    if (oracle::within_band(a, b, 1e-6)) {
      ++t.in_band;
      continue;
    }
    const bool exact = oracle::overlaps(a, b);
    EXPECT_EQ(collide::overlaps(a, b), exact) << name(make_pair(A, B)) << " case " << i;
    EXPECT_EQ(collide::overlaps(b, a), exact) << name(make_pair(A, B)) << " reversed, case " << i;
    EXPECT_EQ(oracle::overlaps(b, a), exact) << "oracle not symmetric: " << name(make_pair(A, B)) << " case " << i;
    // The sign of the reported distance matches the decision.
    const double sd = oracle::approx_signed_distance(a, b);
    EXPECT_EQ(sd <= 0, exact) << name(make_pair(A, B)) << " signed distance " << sd;
    ++t.judged;
    (exact ? t.overlapping : t.apart) += 1;
  }
  return t;
}

TEST(OracleRegistry, EveryPairAgreesWithTheLibraryAwayFromTheBoundary) {
  int pairs = 0;
  for_each_pair([&]<ShapeKind A, ShapeKind B>() {
    const Tally t = check_pair<A, B>(1000 + pair_index(make_pair(A, B)));
    ++pairs;
    // Both outcomes must be exercised, or the agreement above proves little.
    EXPECT_GE(t.overlapping, 30) << name(make_pair(A, B));
    EXPECT_GE(t.apart, 30) << name(make_pair(A, B));
  });
  EXPECT_EQ(pairs, static_cast<int>(kPairCount));
}

TEST(OracleRegistry, FarApartAndCoincidentCentersForEveryPrimitivePair) {
  std::mt19937_64 rng(7);
  for_each_pair([&]<ShapeKind A, ShapeKind B>() {
    if constexpr (A != ShapeKind::Compound && B != ShapeKind::Compound) {
      const auto a = testing::sample_shape<A>(rng, Vec2<double>(0.5, -0.25), 1.0);
      const auto b = testing::sample_shape<B>(rng, Vec2<double>(0.5, -0.25), 1.0);
      // Every primitive sampled here contains its center.
      EXPECT_TRUE(oracle::overlaps(a, b)) << name(make_pair(A, B));
      EXPECT_TRUE(oracle::contains(a, Vec2<double>(0.5, -0.25))) << name(make_pair(A, B));
      const auto far = testing::sample_shape<A>(rng, Vec2<double>(40.0, 3.0), 1.0);
      EXPECT_FALSE(oracle::overlaps(far, b)) << name(make_pair(A, B));
      EXPECT_EQ(oracle::compare_distance(far, b, 30.0), 1) << name(make_pair(A, B));
      EXPECT_EQ(oracle::compare_distance(far, b, 50.0), -1) << name(make_pair(A, B));
      EXPECT_FALSE(collide::overlaps(far, b)) << name(make_pair(A, B));
    }
  });
}

TEST(OracleRegistry, FloatShapesAreJudgedThroughExactWidening) {
  // 0.1f widened is exactly 0.100000001490116119384765625; the circles touch at x = 0.1f.
  const Circle<float> a(Vec2<float>(0.0f, 0.0f), 0.1f);
  const Circle<float> b(Vec2<float>(0.2f, 0.0f), 0.1f);  // 0.2f == 2 * 0.1f exactly
  EXPECT_TRUE(oracle::overlaps(a, b));
  EXPECT_EQ(oracle::compare_distance(a, b, 0.0), 0);
  const Circle<float> c(Vec2<float>(std::nextafter(0.2f, 1.0f), 0.0f), 0.1f);
  EXPECT_FALSE(oracle::overlaps(a, c));
  EXPECT_EQ(oracle::overlaps(Shape<float>(a), Shape<float>(c)), oracle::overlaps(a, c));
}

}  // namespace
}  // namespace collide::oracle
