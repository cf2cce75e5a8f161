// The hot path does not allocate: every query on every pair of kinds (both orders, both scalars,
// concrete and variant arguments, with and without a speculative distance, compounds with and
// without child transforms), every translation and every successful factory of a shape with at
// most 8 vertices. This executable replaces the global operator new and counts the calls
// made while a check runs; a failure names the query and the pair that allocated.
//
// Building a compound owns memory (its children), so compounds are built before counting starts;
// queries on them must still not allocate.

#include "support.hpp"

#include <collide/broadphase.hpp>

#include <atomic>
#include <span>
#include <vector>
#include <cstdlib>
#include <limits>
#include <new>
#include <string>
#include <utility>

namespace {
std::atomic<long> g_allocations{0};
std::atomic<bool> g_counting{false};
}  // namespace

// Out of line: inlined into the standard containers, g++ pairs malloc with the sized delete and
// warns of a mismatch (-Wmismatched-new-delete) that is not there.
__attribute__((noinline)) void* operator new(std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
__attribute__((noinline)) void* operator new[](std::size_t n) {
  return operator new(n);
}
__attribute__((noinline)) void operator delete(void* p) noexcept {
  std::free(p);
}
__attribute__((noinline)) void operator delete[](void* p) noexcept {
  std::free(p);
}
__attribute__((noinline)) void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
__attribute__((noinline)) void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

namespace collide::test {
namespace {

/// Runs f with allocation counting on; returns the number of operator new calls it made.
template <class F>
long allocations_in(F&& f) {
  g_allocations.store(0);
  g_counting.store(true);
  f();
  g_counting.store(false);
  return g_allocations.load();
}

/// Keeps a result alive so that the optimiser cannot drop the call that made it.
template <class V>
void keep(const V& v) {
  asm volatile("" : : "r"(&v) : "memory");
}

template <class T>
class Allocation : public ::testing::Test {};
TYPED_TEST_SUITE(Allocation, Scalars);

/// Every pair query, both orders, on overlapping, touching and separated configurations.
template <ShapeKind KA, ShapeKind KB, Scalar T>
void check_pair_queries() {
  const std::string label = pair_label<KA, KB>();
  for (const T x : {T(0.5), T(2), T(5)}) {
    const auto a = make_kind<KA, T>(Vec2<T>(0, 0), T(1));
    const auto b = make_kind<KB, T>(Vec2<T>(x, T(0.25)), T(1));
    const Shape<T> va(a), vb(b);
    const auto expect_none = [&](const char* query, auto&& f) {
      EXPECT_EQ(0, allocations_in(f)) << query << " " << label << " at x = " << x;
    };
    expect_none("overlaps", [&] {
      keep(overlaps(a, b));
      keep(overlaps(b, a));
      keep(overlaps(va, vb));
    });
    expect_none("contact", [&] {
      keep(contact(a, b));
      keep(contact(b, a));
      keep(contact(va, vb));
    });
    expect_none("speculative contact", [&] {
      keep(contact(a, b, T(0.5)));
      keep(contact(vb, va, T(0.5)));
    });
    expect_none("resolve", [&] {
      keep(resolve(a, b));
      keep(resolve(b, a));
      keep(resolve(va, vb));
    });
    expect_none("distance", [&] {
      keep(distance(a, b));
      keep(distance(va, vb));
    });
    expect_none("tolerances", [&] {
      keep(overlap_tolerance(a, b));
      keep(rounding_tolerance(a, b));
      keep(resolve_margin(a, b, T(1)));
      keep(resolve_margin(a, b, T(1), Vec2<T>(T(0.6), T(0.8))));
    });
    // The same queries on local shapes placed by transforms: a rotated one, a translation, and
    // the identity, in both orders (compounds are imaged child by child, never copied).
    const Transform<T> xa(Vec2<T>(T(0.25), T(-0.5)), T(0.7)), xb(Vec2<T>(T(0.25), T(-0.5)), T(0));
    for (const Transform<T>& x : {xa, xb, Transform<T>()}) {
      expect_none("transformed queries", [&] {
        keep(overlaps(a, x, b, xb));
        keep(overlaps(vb, xb, va, x));
        keep(contact(a, x, b, xb));
        keep(contact(vb, xb, va, x));
        keep(contact(a, x, b, xb, T(0.5)));
        keep(contact(vb, xb, va, x, T(0.5)));
        keep(resolve(a, x, b, xb));
        keep(resolve(vb, xb, va, x));
        keep(distance(a, x, b, xb));
        keep(distance(vb, xb, va, x));
        keep(overlap_tolerance(a, x, b, xb));
        keep(rounding_tolerance(a, x, b, xb));
        keep(resolve_margin(a, x, b, xb, T(1)));
        keep(resolve_margin(a, x, b, xb, T(1), Vec2<T>(T(0.6), T(0.8))));
      });
      expect_none("shape casts", [&] {
        const Vec2<T> v(T(-4), T(1)), still(0, 0);
        keep(shape_cast(a, x, v, b, xb, still, T(2)));
        keep(shape_cast(vb, xb, still, va, x, v, T(2)));
        keep(shape_cast(a, v, b, still, T(2)));
        keep(cast_tolerance(a, x, v, b, xb, still, T(2)));
      });
    }
  }
}

/// The pair queries of a compound whose children carry their own transforms (built before
/// counting: it owns them) against a shape of kind K, both orders, in world space and placed.
template <ShapeKind K, Scalar T>
void check_compound_with_child_transforms() {
  using V = Vec2<T>;
  const std::string label = std::string("compound with child transforms against ") + std::string(name(K));
  std::vector<typename Compound<T>::Child> kids;
  kids.push_back({Obb<T>::make(V(0, 0), V(T(1), T(0.25)), T(0.3)).value(), Transform<T>(V(T(0.5), T(0)), T(0.9))});
  kids.push_back({Circle<T>(V(0, 0), T(0.5)), Transform<T>(V(T(-0.5), T(0.25)), T(0))});
  const Shape<T> c(Compound<T>::make_placed(std::move(kids)).value());
  const Transform<T> turned(V(T(0.25), T(-0.5)), T(0.7));
  for (const T at : {T(0.5), T(2), T(5)}) {
    const Shape<T> other(make_kind<K, T>(V(at, T(0.25)), T(1)));
    EXPECT_EQ(0, allocations_in([&] {
                keep(overlaps(c, other));
                keep(contact(other, c));
                keep(contact(c, other, T(0.5)));
                keep(resolve(c, other));
                keep(distance(other, c));
                keep(overlaps(c, turned, other, Transform<T>()));
                keep(contact(other, Transform<T>(), c, turned));
                keep(contact(c, turned, other, Transform<T>(), T(0.5)));
                keep(resolve(c, turned, other, Transform<T>()));
                keep(distance(other, Transform<T>(), c, turned));
                keep(raycast(c, turned, Ray<T>{V(-10, 0), V(1, 0)}, T(100)));
                keep(contains(c, turned, V(0, 0)));
                keep(bounds(c, turned));
              }))
        << label << " at x = " << at;
  }
}

/// Every single-shape query on a shape of kind K.
template <ShapeKind K, Scalar T>
void check_shape_queries() {
  const std::string label(name(K));
  const auto s = make_kind<K, T>(Vec2<T>(T(1), T(-2)), T(1.5));
  const Shape<T> vs(s);
  const Ray<T> hit{Vec2<T>(T(-10), T(-2)), Vec2<T>(T(1), T(0))};
  const Ray<T> miss{Vec2<T>(T(-10), T(30)), Vec2<T>(T(1), T(0))};
  EXPECT_EQ(0, allocations_in([&] {
              keep(raycast(s, hit, T(100)));
              keep(raycast(s, miss, T(100)));
              keep(raycast(vs, hit, T(100)));
            }))
      << "raycast " << label;
  EXPECT_EQ(0, allocations_in([&] {
              keep(contains(s, Vec2<T>(T(1), T(-2))));
              keep(contains(s, Vec2<T>(T(9), T(9))));
              keep(contains(vs, Vec2<T>(T(1), T(-2))));
            }))
      << "contains " << label;
  EXPECT_EQ(0, allocations_in([&] {
              keep(bounds(s));
              keep(bounds(vs));
            }))
      << "bounds " << label;
  const Transform<T> x(Vec2<T>(T(3), T(1)), T(2.1));
  EXPECT_EQ(0, allocations_in([&] {
              keep(raycast(s, x, hit, T(100)));
              keep(raycast(vs, x, miss, T(100)));
              keep(contains(s, x, Vec2<T>(T(1), T(-2))));
              keep(contains(vs, x, Vec2<T>(T(9), T(9))));
              keep(bounds(s, x));
              keep(bounds(vs, x));
              keep(transform_tolerance(s, x));
              keep(raycast_tolerance(s, x, hit));
            }))
      << "transformed shape queries " << label;
  if constexpr (K != ShapeKind::Compound) {
    // A compound owns its children: moving one builds a new list. Every primitive moves in place.
    EXPECT_EQ(0, allocations_in([&] {
                keep(translated(s, Vec2<T>(T(3), T(0.5))));
                keep(translated(vs, Vec2<T>(T(3), T(0.5))));
              }))
        << "translated " << label;
  }
}

TYPED_TEST(Allocation, NoPairQueryAllocatesForAnyPairInEitherOrder) {
  using T = TypeParam;
  for_each_pair([]<ShapeKind A, ShapeKind B>() { check_pair_queries<A, B, T>(); });
}

TYPED_TEST(Allocation, NoQueryOnACompoundWithChildTransformsAllocates) {
  using T = TypeParam;
  for_each_kind([]<ShapeKind K>() { check_compound_with_child_transforms<K, T>(); });
}

TYPED_TEST(Allocation, NoShapeQueryOrTranslationAllocatesForAnyKind) {
  using T = TypeParam;
  for_each_kind([]<ShapeKind K>() { check_shape_queries<K, T>(); });
}

TYPED_TEST(Allocation, SuccessfulFactoriesDoNotAllocate) {
  using T = TypeParam;
  using V = Vec2<T>;
  const V octagon[] = {V(2, 0), V(1.5, 1.5), V(0, 2), V(-1.5, 1.5), V(-2, 0), V(-1.5, -1.5), V(0, -2), V(1.5, -1.5)};
  // Points whose hull is the octagon above, with interior points and repeats mixed in.
  const V cloud[] = {V(0, 0),  V(2, 0), V(1.5, 1.5),   V(0, 2),  V(0.5, 0.5),  V(-1.5, 1.5),
                     V(-2, 0), V(2, 0), V(-1.5, -1.5), V(0, -2), V(1.5, -1.5), V(-1, 1)};
  EXPECT_EQ(0, allocations_in([&] {
              keep(Circle<T>::make(V(1, 2), T(3)));
              keep(Aabb<T>::make(V(-1, -2), V(3, 4)));
              keep(Obb<T>::make(V(1, 2), V(3, 1), T(0.7)));
              keep(Obb<T>::make_with_axis(V(1, 2), V(3, 1), V(T(0.6), T(0.8))));
              keep(Obb<T>::from_corners(V(0, 0), V(2, 0), V(2, 1), V(0, 1)));
              keep(Capsule<T>::make(V(0, 0), V(3, 1), T(0.5)));
              keep(ConvexPolygon<T>::make(std::span<const V>(octagon)));
              keep(ConvexPolygon<T>::make_hull(std::span<const V>(cloud)));
            }));
  // Transform updates: every factory, and moving one.
  EXPECT_EQ(0, allocations_in([&] {
              const auto x = Transform<T>::make(V(1, 2), T(0.7));
              keep(x);
              keep(Transform<T>::make_with_rotation(V(1, 2), V(3, 4)));
              keep(Transform<T>::make_with_rotation(V(1, 2), V(0, 0)));  // ZeroRotation
              keep(Transform<T>::make_translation(V(5, 6)));
              keep(x->moved(V(1, 1)));
              keep(Transform<T>::make(V(1, 2), std::numeric_limits<T>::quiet_NaN()));  // NonFinite
            }));
}

TYPED_TEST(Allocation, RejectedFactoriesCarryTheirErrorWithoutAllocating) {
  using T = TypeParam;
  using V = Vec2<T>;
  const V reflex[] = {V(0, 0), V(2, 0), V(1, 0.25), V(2, 2), V(0, 2)};
  long count = 0;
  std::string message;
  count = allocations_in([&] {
    const auto bad = ConvexPolygon<T>::make(std::span<const V>(reflex));
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().code(), Error::NonConvex);
    keep(bad);
    const auto neg = Circle<T>::make(V(0, 0), T(-1));
    ASSERT_FALSE(neg);
    EXPECT_EQ(neg.error().code(), Error::NegativeRadius);
    keep(neg);
  });
  EXPECT_EQ(0, count);
  const auto bad = ConvexPolygon<T>::make(std::span<const V>(reflex));
  message = bad.error().what();
  EXPECT_EQ(message, "NonConvex: polygon turns the wrong way (index 2)");
}

TEST(Allocation, CounterSeesAnAllocation) {
  // The counting operator new is live: without this, every check above would pass vacuously.
  EXPECT_EQ(1, allocations_in([] {
              auto* p = new int(3);
              keep(*p);
              delete p;
            }));
}

// Shape casts and time of impact (cast.hpp, time_of_impact.hpp): no allocation for any pair.
template <ShapeKind KA, ShapeKind KB, Scalar T>
void check_pair_casts() {
  using V = Vec2<T>;
  const auto a = make_kind<KA, T>(V(-3, 0), T(1));
  const auto b = make_kind<KB, T>(V(3, 0), T(1));
  const auto local = make_kind<KA, T>(V(0, 0), T(1));  // a compound allocates when built
  Sweep<T> turn;
  turn.c0 = V(-3, 0);
  turn.c1 = V(1, 0);
  turn.a1 = T(1.5);
  const long n = allocations_in([&] {
    keep(shape_cast(a, V(4, 0), b, V(-1, 0), T(1)));
    keep(shape_cast(b, V(0, 1), a, V(0, 0), T(1)));
    keep(time_of_impact(local, turn, b, Sweep<T>{}, T(1)));
  });
  EXPECT_EQ(n, 0) << pair_label<KA, KB>() << ": shape_cast / time_of_impact allocated";
}

TYPED_TEST(Allocation, NoCastOrTimeOfImpactAllocatesForAnyPair) {
  for_each_pair([]<ShapeKind A, ShapeKind B>() { check_pair_casts<A, B, TypeParam>(); });
}

// The narrowphase of a frame allocates only to grow its buffers: after reserve(), and after a
// larger batch, a batch of every kind pair (overlapping and apart) allocates nothing.
TYPED_TEST(Allocation, NarrowphaseAllocatesOnlyToGrowItsBuffers) {
  using T = TypeParam;
  namespace bp = collide::broadphase;
  std::vector<Shape<T>> shapes;
  std::vector<Transform<T>> transforms;
  for (const T x : {T(0), T(1.5), T(9)}) {
    for_each_kind([&]<ShapeKind K>() {
      shapes.emplace_back(make_kind<K, T>(Vec2<T>(0, 0), T(1)));
      transforms.emplace_back(Vec2<T>(x, T(0.25) * T(shapes.size() % 4)), T(0.3) * T(shapes.size()));
    });
  }
  std::vector<bp::ShapePair> pairs;
  for (std::size_t a = 0; a < shapes.size(); ++a) {
    for (std::size_t b = 0; b < shapes.size(); ++b) {
      if (a != b) pairs.push_back({a, b});
    }
  }
  const auto run = [&](bp::Narrowphase<T>& narrow, std::span<const bp::ShapePair> batch) {
    std::size_t contacts = 0;
    narrow.for_each_contact(shapes, transforms, batch,
                            [&](std::size_t, const Contact<T>& c) { contacts += std::size_t(c.count); });
    return contacts;
  };
  bp::Narrowphase<T> reserved;
  reserved.reserve(pairs.size());
  std::size_t contacts = 0;
  EXPECT_EQ(0, allocations_in([&] { contacts = run(reserved, pairs); })) << "after reserve()";
  EXPECT_GT(contacts, 0u) << "no pair met: the batch exercised no contact path";
  bp::Narrowphase<T> grown;
  EXPECT_GT(allocations_in([&] { run(grown, pairs); }), 0) << "the first batch had no buffers to fill";
  EXPECT_EQ(0, allocations_in([&] { run(grown, std::span<const bp::ShapePair>(pairs).first(pairs.size() / 2)); }))
      << "a smaller batch after a larger one";
}

TYPED_TEST(Allocation, WorldMovesAndStepsAllocateNothingOnceItsBuffersHaveGrown) {
  using T = TypeParam;
  namespace bp = collide::broadphase;
  // Bodies of every kind (compounds included) in their own frames, turning on a circle and
  // meeting each other; the motion repeats after 60 frames, so the second round asks nothing of
  // the buffers that the first did not.
  bp::World<T> world(bp::DynamicTree<T>(T(0.1)), T(0.05));
  std::vector<bp::ProxyId> ids;
  for (int copy = 0; copy < 3; ++copy) {
    for_each_kind(
        [&]<ShapeKind K>() { ids.push_back(world.add(make_kind<K, T>(Vec2<T>(0, 0), T(1)), Transform<T>())); });
  }
  const auto frame = [&](int f) {
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const T a = T(0.1) * T((f + int(i) * 7) % 60), r = T(1) + T(i % 5);
      world.move(ids[i], Transform<T>(Vec2<T>(r * std::cos(a), r * std::sin(a)), T(0.3) * T(f % 60)));
    }
    world.step();
    std::size_t points = 0;
    world.for_each_contact([&](const bp::BodyContact<T>& c) { points += std::size_t(c.contact.count); });
    return points;
  };
  std::size_t points = 0;
  for (int f = 0; f < 120; ++f) points += frame(f);
  EXPECT_GT(points, 0u) << "no body met another: the steps computed no contact";
  EXPECT_EQ(0, allocations_in([&] {
              for (int f = 0; f < 120; ++f) frame(f);
            }))
      << "a World's move() and step() allocated in a frame the buffers had already seen";
}

// The character mover: move_and_slide() keeps its planes and path in fixed arrays and visits the
// broadphase's candidates without storing them, so no move allocates, whatever it meets: a
// resting contact and its lift, hits, slides along a floor and into a corner, bodies of every
// kind (compounds included), for a circle and a capsule.
TYPED_TEST(Allocation, MoveAndSlideAllocatesNothing) {
  using T = TypeParam;
  using V = Vec2<T>;
  namespace bp = collide::broadphase;
  bp::World<T> world;
  world.add(Aabb<T>(V(-50, -1), V(50, 0)));  // the floor
  world.add(Aabb<T>(V(6, 0), V(7, 10)));     // a wall
  int slot = 0;
  for_each_kind([&]<ShapeKind K>() {
    world.add(make_kind<K, T>(Vec2<T>(0, 0), T(0.5)), Transform<T>(V(T(-8 + 2 * slot++), T(3)), T(0.3)));
  });
  const Shape<T> ball = Circle<T>(V(0, 0), T(0.5));
  const Shape<T> pill = Capsule<T>(V(0, T(-0.5)), V(0, T(0.5)), T(0.25));
  const std::vector<std::pair<V, V>> moves = {
      {V(0, T(0.5)), V(3, 0)},    // resting on the floor: a lift, then a slide
      {V(0, T(0.75)), V(9, -2)},  // down onto the floor, along it, into the wall's corner
      {V(-9, 5), V(16, -3)},      // among the bodies of every kind
      {V(2, 4), V(-3, T(-0.5))}};
  std::size_t planes = 0;
  const long n = allocations_in([&] {
    for (const Shape<T>* mover : {&ball, &pill}) {
      for (const auto& [start, d] : moves) {
        const bp::MoveResult<T> r = bp::move_and_slide(world, *mover, Transform<T>(start, T(0)), d);
        planes += r.plane_count;
        keep(r);
      }
    }
  });
  EXPECT_EQ(n, 0) << "move_and_slide allocated";
  EXPECT_GE(planes, 8u) << "the moves met too little to exercise the mover";
}

}  // namespace
}  // namespace collide::test
