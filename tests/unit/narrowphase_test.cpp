// Narrowphase::for_each_contact: the same contacts as contact() pair by pair, bit for bit, each
// reported once, in the documented order; bad lists refused before anything is reported.

#include "support.hpp"

#include <collide/broadphase.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

namespace collide::test {
namespace {

namespace bp = collide::broadphase;

template <class T>
class NarrowphaseTest : public ::testing::Test {};
TYPED_TEST_SUITE(NarrowphaseTest, Scalars);

/// A crowd of every kind (the registry's makers, sizes 0.5 to 2) placed at random in a 12 x 12
/// square under random turns, and every pair of it: about a tenth of the pairs meet.
template <Scalar T>
struct Crowd {
  std::vector<Shape<T>> shapes;
  std::vector<Transform<T>> transforms;
  std::vector<bp::ShapePair> pairs;

  explicit Crowd(unsigned seed, std::size_t per_kind = 6) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> place(-6, 6), turn(-3.2, 3.2), size(0.5, 2);
    for (std::size_t i = 0; i < per_kind; ++i) {
      for_each_kind([&]<ShapeKind K>() {
        shapes.emplace_back(make_kind<K, T>(Vec2<T>(0, 0), T(size(rng))));
        transforms.push_back(Transform<T>::make(Vec2<T>(T(place(rng)), T(place(rng))), T(turn(rng))).value());
      });
    }
    for (std::size_t a = 0; a < shapes.size(); ++a) {
      for (std::size_t b = 0; b < shapes.size(); ++b) {
        if (a != b) pairs.push_back({a, b});
      }
    }
  }
};

/// Bit-for-bit equality of two contacts: every field a solver reads.
template <Scalar T>
::testing::AssertionResult same_contact(const Contact<T>& got, const Contact<T>& want) {
  const auto bits = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof(x)) == 0; };
  bool same = got.count == want.count && bits(got.normal, want.normal) && bits(got.depth, want.depth);
  for (int k = 0; k < want.count && same; ++k) {
    same = bits(got.points[k], want.points[k]) && got.ids[k] == want.ids[k] &&
           bits(got.separations[k], want.separations[k]);
  }
  if (same) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "normal (" << got.normal.x() << ", " << got.normal.y() << ") depth "
                                       << got.depth << " count " << got.count << ", contact() gave normal ("
                                       << want.normal.x() << ", " << want.normal.y() << ") depth " << want.depth
                                       << " count " << want.count;
}

/// Runs the batch on the crowd and checks it against contact() pair by pair: a pair is reported
/// exactly when contact() is present, once, with contact()'s value; the calls come grouped by
/// kind pair in registry order, and by index within a kind pair.
template <Scalar T>
void expect_batch_matches_single(const Crowd<T>& crowd, bp::Narrowphase<T>& narrow, T speculative) {
  std::vector<int> seen(crowd.pairs.size(), 0);
  std::vector<std::optional<Contact<T>>> got(crowd.pairs.size());
  std::size_t last_run = 0, last_index = 0, calls = 0;
  narrow.for_each_contact(
      crowd.shapes, crowd.transforms, crowd.pairs,
      [&](std::size_t i, const Contact<T>& c) {
        ASSERT_LT(i, crowd.pairs.size());
        const bp::ShapePair& p = crowd.pairs[i];
        const std::size_t run = crowd.shapes[p.a].index() * kKindCount + crowd.shapes[p.b].index();
        if (calls > 0) {
          EXPECT_TRUE(run > last_run || (run == last_run && i > last_index))
              << "pair " << i << " (kind pair " << run << ") came after pair " << last_index << " (kind pair "
              << last_run << "): not grouped by kind pair, or out of order within one";
        }
        last_run = run;
        last_index = i;
        ++calls;
        ++seen[i];
        got[i] = c;
      },
      speculative);
  std::size_t present = 0;
  for (std::size_t i = 0; i < crowd.pairs.size(); ++i) {
    const bp::ShapePair& p = crowd.pairs[i];
    const auto want =
        contact(crowd.shapes[p.a], crowd.transforms[p.a], crowd.shapes[p.b], crowd.transforms[p.b], speculative);
    const std::string what = "pair " + std::to_string(i) + " (shapes " + std::to_string(p.a) + ", " +
                             std::to_string(p.b) + "), speculative " + std::to_string(double(speculative));
    if (!want) {
      EXPECT_EQ(0, seen[i]) << what << ": reported, but contact() has none";
      continue;
    }
    ++present;
    ASSERT_EQ(1, seen[i]) << what << ": contact() has one, reported " << seen[i] << " times";
    EXPECT_TRUE(same_contact(*got[i], *want)) << what;
  }
  // The crowd must exercise both answers, or the comparison above proves little.
  EXPECT_GT(present, crowd.pairs.size() / 20) << "too few pairs in contact";
  EXPECT_LT(present, crowd.pairs.size() / 2) << "too few pairs apart";
}

TYPED_TEST(NarrowphaseTest, ReportsExactlyWhatContactGivesPairByPair) {
  using T = TypeParam;
  bp::Narrowphase<T> narrow;
  for (const unsigned seed : {1u, 2u, 3u}) {
    const Crowd<T> crowd(seed);
    expect_batch_matches_single(crowd, narrow, T(0));
  }
}

TYPED_TEST(NarrowphaseTest, PassesTheSpeculativeDistanceOn) {
  using T = TypeParam;
  bp::Narrowphase<T> narrow;
  const Crowd<T> crowd(4);
  expect_batch_matches_single(crowd, narrow, T(0.75));
}

TYPED_TEST(NarrowphaseTest, ReusesItsBuffersAcrossBatchesOfAnySize) {
  using T = TypeParam;
  bp::Narrowphase<T> narrow;
  Crowd<T> crowd(5);
  expect_batch_matches_single(crowd, narrow, T(0));
  const std::size_t grown = narrow.capacity();
  EXPECT_GE(grown, crowd.pairs.size());
  // A smaller batch after a larger one: the stale tail of the buffers must not be read.
  crowd.pairs.resize(crowd.pairs.size() / 3);
  expect_batch_matches_single(crowd, narrow, T(0));
  EXPECT_EQ(grown, narrow.capacity());
}

TYPED_TEST(NarrowphaseTest, NoPairsReportNothing) {
  using T = TypeParam;
  bp::Narrowphase<T> narrow;
  const Crowd<T> crowd(6);
  int calls = 0;
  narrow.for_each_contact(crowd.shapes, crowd.transforms, {}, [&](std::size_t, const Contact<T>&) { ++calls; });
  EXPECT_EQ(0, calls);
}

TYPED_TEST(NarrowphaseTest, RefusesAPairBeyondTheListBeforeReportingAnything) {
  using T = TypeParam;
  bp::Narrowphase<T> narrow;
  Crowd<T> crowd(7);
  const std::size_t n = crowd.shapes.size();
  for (const bp::ShapePair bad : {bp::ShapePair{0, n}, bp::ShapePair{n, 0}, bp::ShapePair{n + 5, n + 9}}) {
    std::vector<bp::ShapePair> pairs = crowd.pairs;
    pairs.push_back(bad);  // last, so that every good pair before it would be reported first
    int calls = 0;
    try {
      narrow.for_each_contact(crowd.shapes, crowd.transforms, pairs, [&](std::size_t, const Contact<T>&) { ++calls; });
      ADD_FAILURE() << "pair (" << bad.a << ", " << bad.b << ") of a list of " << n << " accepted";
    } catch (const bp::BroadphaseError& e) {
      EXPECT_EQ(bp::BroadphaseErrc::BadPair, e.code()) << e.what();
    }
    EXPECT_EQ(0, calls) << "contacts reported before the bad pair was refused";
  }
  // The refusal left nothing behind: the same Narrowphase answers the good list.
  expect_batch_matches_single(crowd, narrow, T(0));
}

TYPED_TEST(NarrowphaseTest, RefusesTransformsThatDoNotMatchTheShapes) {
  using T = TypeParam;
  bp::Narrowphase<T> narrow;
  Crowd<T> crowd(8);
  crowd.transforms.pop_back();
  try {
    narrow.for_each_contact(crowd.shapes, crowd.transforms, crowd.pairs, [](std::size_t, const Contact<T>&) {});
    ADD_FAILURE() << crowd.shapes.size() << " shapes with " << crowd.transforms.size() << " transforms accepted";
  } catch (const bp::BroadphaseError& e) {
    EXPECT_EQ(bp::BroadphaseErrc::BadPair, e.code()) << e.what();
  }
}

TYPED_TEST(NarrowphaseTest, AnExceptionFromTheCallbackLeavesItUsable) {
  using T = TypeParam;
  bp::Narrowphase<T> narrow;
  const Crowd<T> crowd(9);
  int calls = 0;
  EXPECT_THROW(narrow.for_each_contact(crowd.shapes, crowd.transforms, crowd.pairs,
                                       [&](std::size_t, const Contact<T>&) {
                                         if (++calls == 3) throw std::runtime_error("stop");
                                       }),
               std::runtime_error);
  EXPECT_EQ(3, calls);
  expect_batch_matches_single(crowd, narrow, T(0));
}

TYPED_TEST(NarrowphaseTest, RefusesACallFromItsOwnCallbackButNotFromAnothers) {
  using T = TypeParam;
  bp::Narrowphase<T> narrow, other;
  const Crowd<T> crowd(10);
  int refused = 0, inner = 0;
  bool first = true;
  narrow.for_each_contact(crowd.shapes, crowd.transforms, crowd.pairs, [&](std::size_t, const Contact<T>&) {
    if (!first) return;
    first = false;
    try {
      narrow.for_each_contact(crowd.shapes, crowd.transforms, crowd.pairs, [](std::size_t, const Contact<T>&) {});
    } catch (const bp::BroadphaseError& e) {
      EXPECT_EQ(bp::BroadphaseErrc::Reentered, e.code()) << e.what();
      ++refused;
    }
    other.for_each_contact(crowd.shapes, crowd.transforms, crowd.pairs,
                           [&](std::size_t, const Contact<T>&) { ++inner; });
  });
  EXPECT_EQ(1, refused) << "a nested call on the running Narrowphase was accepted";
  EXPECT_GT(inner, 0) << "a second Narrowphase inside the callback reported nothing";
  // The refused call and the finished batch left it usable.
  expect_batch_matches_single(crowd, narrow, T(0));
}

}  // namespace
}  // namespace collide::test
