// Distances against Box2D 2.4.1's b2Distance (GJK, radii included: distance, pointA, pointB), on
// the same inputs, cross-checked before timing:
//   - closest_points() and distance() of pairs, against b2Distance of the two shapes' proxies;
//   - signed_distance() of points near each kind, against b2Distance of the shape and a one-vertex
//     proxy (unsigned: 0 inside), and contains() against b2Shape::TestPoint (not for a capsule:
//     Box2D's edge has no area to test).
// Box2D's proxies are built once, before timing, as a game keeps them with its shapes.

#include "inputs.hpp"
#include "suites.hpp"

#include <benchmark/benchmark.h>
#include <box2d/b2_distance.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace bench {
namespace {

constexpr std::size_t kPairs = 1024;  // pairs (or points) per benchmark iteration

// Box2D's distance agrees within its float GJK's tolerance, and decides touching within it.
constexpr double kDistanceTolerance = 2e-3;

b2Transform identity() {
  b2Transform xf;
  xf.SetIdentity();
  return xf;
}

// The Box2D shape of each input (an AABB as its polygon form).
const b2Shape& b2_of(const CircleIn& s) {
  return s.b;
}
const b2Shape& b2_of(const AabbIn& s) {
  return s.p;
}
const b2Shape& b2_of(const ObbIn& s) {
  return s.b;
}
const b2Shape& b2_of(const CapsuleIn& s) {
  return s.b;
}
const b2Shape& b2_of(const HullIn& s) {
  return s.b;
}

b2DistanceOutput b2_distance(const b2DistanceInput& in) {
  b2SimplexCache cache;
  cache.count = 0;
  b2DistanceOutput out;
  b2Distance(&out, &cache, &in);
  return out;
}

template <class A, class B>
struct PairSet {
  std::string name;  // e.g. "circle_obb/near"
  std::vector<A> a;
  std::vector<B> b;
  std::vector<b2DistanceInput> b2;  // refers to a and b, which stay put once filled
};

/// Distances and overlap must agree with Box2D's within its tolerance; collide's witness points
/// must realise its distance (|point_b - point_a| = distance, one point when overlapping).
template <class A, class B>
bool check_pairs(const PairSet<A, B>& s) {
  long bad = 0, apart = 0;
  for (std::size_t i = 0; i < s.a.size(); ++i) {
    const collide::ClosestPoints<float> c = collide::closest_points(s.a[i].c, s.b[i].c);
    const b2DistanceOutput o = b2_distance(s.b2[i]);
    const double tol = collide::closest_points_tolerance(s.a[i].c, s.b[i].c);
    const double apart_by = (c.point_b.cast<double>() - c.point_a.cast<double>()).norm();
    const bool ok = c.distance == collide::distance(s.a[i].c, s.b[i].c) &&
                    std::fabs(double(c.distance) - double(o.distance)) <= kDistanceTolerance &&
                    (c.distance == 0 ? c.point_a == c.point_b : std::fabs(apart_by - double(c.distance)) <= tol);
    apart += c.distance > 0;
    if (!ok && ++bad < 5)
      std::fprintf(stderr, "  %s pair %zu: collide %g, Box2D %g\n", s.name.c_str(), i, double(c.distance),
                   double(o.distance));
  }
  std::printf("check distance %-24s apart %5.1f%%  %s\n", s.name.c_str(), 100.0 * double(apart) / double(s.a.size()),
              bad == 0 ? "OK" : "MISMATCH");
  return bad == 0;
}

template <class A, class B, class F>
void time_pairs(benchmark::State& st, const PairSet<A, B>& s, F f) {
  for (auto _ : st) {
    for (std::size_t i = 0; i < s.a.size(); ++i) f(i);
  }
  st.counters["pairs"] = double(s.a.size());
}

template <class A, class B, class MA, class MB>
bool add_pairs(collide::ShapeKind ka, collide::ShapeKind kb, float near_scale, MA ma, MB mb, unsigned seed) {
  bool ok = true;
  for (const Placement p : {Placement::Random, Placement::Near}) {
    auto s = std::make_shared<PairSet<A, B>>();
    s->name = collide::name(collide::make_pair(ka, kb)) + "/" + name(p);
    Maker maker(seed + (p == Placement::Near ? 1000u : 0u));
    maker.pairs(
        kPairs, p, near_scale, [&](const V& at) { return (maker.*ma)(at); },
        [&](const V& at) { return (maker.*mb)(at); }, s->a, s->b);
    for (std::size_t i = 0; i < s->a.size(); ++i) {
      b2DistanceInput in;
      in.proxyA.Set(&b2_of(s->a[i]), 0);
      in.proxyB.Set(&b2_of(s->b[i]), 0);
      in.transformA = identity();
      in.transformB = identity();
      in.useRadii = true;
      s->b2.push_back(in);
    }
    ok = check_pairs(*s) && ok;
    benchmark::RegisterBenchmark(("distance/" + s->name + "/closest_points").c_str(), [s](benchmark::State& st) {
      time_pairs(st, *s,
                 [&](std::size_t i) { benchmark::DoNotOptimize(collide::closest_points(s->a[i].c, s->b[i].c)); });
    });
    benchmark::RegisterBenchmark(("distance/" + s->name + "/distance").c_str(), [s](benchmark::State& st) {
      time_pairs(st, *s, [&](std::size_t i) { benchmark::DoNotOptimize(collide::distance(s->a[i].c, s->b[i].c)); });
    });
    benchmark::RegisterBenchmark(("distance/" + s->name + "/box2d_distance").c_str(), [s](benchmark::State& st) {
      time_pairs(st, *s, [&](std::size_t i) { benchmark::DoNotOptimize(b2_distance(s->b2[i])); });
    });
  }
  return ok;
}

template <class A>
struct PointSet {
  std::string name;  // e.g. "obb/near"
  std::vector<A> s;
  std::vector<V> p;
  std::vector<b2Vec2> b2_point;     // the same points for Box2D
  std::vector<b2DistanceInput> b2;  // the shape's proxy and the point's (refers to s and b2_point)
};

/// Whether Box2D's TestPoint answers for the shape's area: not for an edge, whose radius it ignores.
template <class A>
constexpr bool b2_has_area() {
  return !std::is_same_v<A, CapsuleIn>;
}

/// signed_distance() against Box2D's unsigned distance: equal outside (within its tolerance),
/// 0 from Box2D where collide's is <= 0; the sign is contains()'s and TestPoint's (within the band).
template <class A>
bool check_points(const PointSet<A>& s) {
  long bad = 0, inside = 0;
  for (std::size_t i = 0; i < s.s.size(); ++i) {
    const float d = collide::signed_distance(s.s[i].c, s.p[i]);
    const b2DistanceOutput o = b2_distance(s.b2[i]);
    const bool in = collide::contains(s.s[i].c, s.p[i]);
    const bool b2_in = b2_has_area<A>() ? b2_of(s.s[i]).TestPoint(identity(), s.b2_point[i]) : in;
    inside += in;
    const bool ok = (d <= 0) == in && std::fabs(double(std::max(d, 0.0f)) - double(o.distance)) <= kDistanceTolerance &&
                    (in == b2_in || std::fabs(double(d)) <= kDistanceTolerance);
    if (!ok && ++bad < 5)
      std::fprintf(stderr, "  %s point %zu: signed distance %g, Box2D %g\n", s.name.c_str(), i, double(d),
                   double(o.distance));
  }
  std::printf("check signed distance %-15s inside %5.1f%%  %s\n", s.name.c_str(),
              100.0 * double(inside) / double(s.s.size()), bad == 0 ? "OK" : "MISMATCH");
  return bad == 0;
}

template <class A, class F>
void time_points(benchmark::State& st, const PointSet<A>& s, F f) {
  for (auto _ : st) {
    for (std::size_t i = 0; i < s.s.size(); ++i) f(i);
  }
  st.counters["pairs"] = double(s.s.size());
}

/// Points around each shape: from its centre up to twice its size in any direction, denser near
/// the centre (the distance drawn uniformly), so that about a third lie inside.
template <class A, class M>
bool add_points(collide::ShapeKind k, M make, unsigned seed) {
  auto s = std::make_shared<PointSet<A>>();
  s->name = std::string(collide::name(k)) + "/near";
  Maker maker(seed);
  for (std::size_t i = 0; i < kPairs; ++i) {
    const V at(maker.uniform(0, 100), maker.uniform(0, 100));
    s->s.push_back((maker.*make)(at));
    const float reach = 2 * Maker::extent(s->s.back()) * maker.uniform(0, 1);
    const float angle = maker.uniform(0, 6.2831853f);
    s->p.push_back(at + V(reach * std::cos(angle), reach * std::sin(angle)));
    s->b2_point.push_back(to_b2(s->p.back()));
  }
  for (std::size_t i = 0; i < kPairs; ++i) {
    b2DistanceInput in;
    in.proxyA.Set(&b2_of(s->s[i]), 0);
    in.proxyB.Set(&s->b2_point[i], 1, 0.0f);
    in.transformA = identity();
    in.transformB = identity();
    in.useRadii = true;
    s->b2.push_back(in);
  }
  const bool ok = check_points(*s);
  benchmark::RegisterBenchmark(("point/" + s->name + "/signed_distance").c_str(), [s](benchmark::State& st) {
    time_points(st, *s, [&](std::size_t i) { benchmark::DoNotOptimize(collide::signed_distance(s->s[i].c, s->p[i])); });
  });
  benchmark::RegisterBenchmark(("point/" + s->name + "/contains").c_str(), [s](benchmark::State& st) {
    time_points(st, *s, [&](std::size_t i) { benchmark::DoNotOptimize(collide::contains(s->s[i].c, s->p[i])); });
  });
  benchmark::RegisterBenchmark(("point/" + s->name + "/box2d_distance").c_str(), [s](benchmark::State& st) {
    time_points(st, *s, [&](std::size_t i) { benchmark::DoNotOptimize(b2_distance(s->b2[i])); });
  });
  if constexpr (b2_has_area<A>()) {
    benchmark::RegisterBenchmark(("point/" + s->name + "/box2d_test_point").c_str(), [s](benchmark::State& st) {
      const b2Transform xf = identity();
      time_points(st, *s,
                  [&](std::size_t i) { benchmark::DoNotOptimize(b2_of(s->s[i]).TestPoint(xf, s->b2_point[i])); });
    });
  }
  return ok;
}

}  // namespace

bool register_distance() {
  using K = collide::ShapeKind;
  bool ok = true;
  ok = add_pairs<CircleIn, CircleIn>(K::Circle, K::Circle, 2.0f, &Maker::circle, &Maker::circle, 21) && ok;
  ok = add_pairs<AabbIn, AabbIn>(K::Aabb, K::Aabb, 1.7f, &Maker::aabb, &Maker::aabb, 22) && ok;
  ok = add_pairs<ObbIn, ObbIn>(K::Obb, K::Obb, 1.6f, &Maker::obb, &Maker::obb, 23) && ok;
  ok = add_pairs<CircleIn, ObbIn>(K::Circle, K::Obb, 1.8f, &Maker::circle, &Maker::obb, 24) && ok;
  ok = add_pairs<CircleIn, HullIn>(K::Circle, K::Polygon, 1.5f, &Maker::circle, &Maker::hull, 25) && ok;
  ok = add_pairs<CapsuleIn, CapsuleIn>(K::Capsule, K::Capsule, 1.4f, &Maker::capsule, &Maker::capsule, 26) && ok;
  ok = add_pairs<CapsuleIn, HullIn>(K::Capsule, K::Polygon, 1.4f, &Maker::capsule, &Maker::hull, 27) && ok;
  ok = add_pairs<HullIn, HullIn>(K::Polygon, K::Polygon, 1.3f, &Maker::hull, &Maker::hull, 28) && ok;
  ok = add_points<CircleIn>(K::Circle, &Maker::circle, 31) && ok;
  ok = add_points<AabbIn>(K::Aabb, &Maker::aabb, 32) && ok;
  ok = add_points<ObbIn>(K::Obb, &Maker::obb, 33) && ok;
  ok = add_points<CapsuleIn>(K::Capsule, &Maker::capsule, 34) && ok;
  ok = add_points<HullIn>(K::Polygon, &Maker::hull, 35) && ok;
  return ok;
}

}  // namespace bench
