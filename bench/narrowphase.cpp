// Per-pair benchmarks: boolean overlap and contact/manifold, collide against Box2D 2.4.1 (and a
// naive inline formula for circles and AABBs), on the same pairs, cross-checked before timing.

#include "inputs.hpp"
#include "suites.hpp"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace bench {
namespace {

constexpr std::size_t kPairs = 1024;  // pairs per benchmark iteration (fits in L1/L2)

b2Transform identity() {
  b2Transform xf;
  xf.SetIdentity();
  return xf;
}
const b2Transform kXf = identity();

// ---- Box2D boolean overlap (b2TestOverlap, skins 0) ----------------------------------------
inline bool b2_overlap(const AabbIn& a, const AabbIn& b) {
  return b2TestOverlap(a.b, b.b);
}
inline bool b2_overlap(const CircleIn& a, const AabbIn& b) {
  return b2TestOverlap(&a.b, 0, &b.p, 0, kXf, kXf);
}
template <class A, class B>
inline bool b2_overlap(const A& a, const B& b) {
  return b2TestOverlap(&a.b, 0, &b.b, 0, kXf, kXf);
}

// ---- Box2D manifold functions; pointCount > 0 means overlap. Depth for the cross-check. -----
struct B2Contact {
  bool hit;
  float depth;
  b2Vec2 normal;  // from A toward B
};
inline B2Contact from_manifold(const b2Manifold& m, const b2Shape& sa, const b2Shape& sb, bool flip) {
  if (m.pointCount == 0) return {false, 0, {0, 0}};
  b2WorldManifold wm;
  wm.Initialize(&m, kXf, sa.m_radius, kXf, sb.m_radius);
  float sep = wm.separations[0];
  for (int i = 1; i < m.pointCount; ++i) sep = std::min(sep, wm.separations[i]);
  return {true, -sep, flip ? -wm.normal : wm.normal};
}
// The shape Box2D's manifold functions take (an AABB as its polygon form).
inline const b2CircleShape& b2_shape(const CircleIn& s) {
  return s.b;
}
inline const b2PolygonShape& b2_shape(const AabbIn& s) {
  return s.p;
}
inline const b2PolygonShape& b2_shape(const ObbIn& s) {
  return s.b;
}
inline const b2PolygonShape& b2_shape(const HullIn& s) {
  return s.b;
}
// The manifold function of a pair; a circle against a polygon is asked polygon first.
inline void b2_collide(b2Manifold* m, const b2CircleShape& a, const b2CircleShape& b) {
  b2CollideCircles(m, &a, kXf, &b, kXf);
}
inline void b2_collide(b2Manifold* m, const b2CircleShape& a, const b2PolygonShape& b) {
  b2CollidePolygonAndCircle(m, &b, kXf, &a, kXf);
}
inline void b2_collide(b2Manifold* m, const b2PolygonShape& a, const b2PolygonShape& b) {
  b2CollidePolygons(m, &a, kXf, &b, kXf);
}
template <class A, class B>
requires requires(b2Manifold* m, const A& a, const B& b) {
  b2_collide(m, b2_shape(a), b2_shape(b));
}
std::optional<B2Contact> b2_manifold(const A& a, const B& b) {
  b2Manifold m;
  b2_collide(&m, b2_shape(a), b2_shape(b));
  constexpr bool polygon_first = std::is_same_v<A, CircleIn> && !std::is_same_v<B, CircleIn>;
  if constexpr (polygon_first) return from_manifold(m, b2_shape(b), b2_shape(a), true);
  return from_manifold(m, b2_shape(a), b2_shape(b), false);
}
// Manifold call without the world-manifold post-processing, for timing. The manifold is kept
// whole, as contact()'s result is in the contact benchmarks: a solver reads every field.
template <class A, class B>
requires requires(b2Manifold* m, const A& a, const B& b) {
  b2_collide(m, b2_shape(a), b2_shape(b));
}
int b2_manifold_points(const A& a, const B& b) {
  b2Manifold m;
  b2_collide(&m, b2_shape(a), b2_shape(b));
  benchmark::DoNotOptimize(m);
  return m.pointCount;
}
template <class A, class B>
constexpr bool manifold_exists() {
  return requires(const A& a, const B& b) {
    { b2_manifold_points(a, b) } -> std::same_as<int>;
  };
}

// ---- Naive inline formulas (the floor for the simplest pairs) -----------------------------
inline bool naive(const CircleIn& a, const CircleIn& b) {
  const float dx = b.c.center().x() - a.c.center().x(), dy = b.c.center().y() - a.c.center().y();
  const float r = a.c.radius() + b.c.radius();
  return dx * dx + dy * dy <= r * r;
}
inline bool naive(const AabbIn& a, const AabbIn& b) {
  // Branchless: the four comparisons combined without short-circuit jumps.
  return (int(a.c.min().x() <= b.c.max().x()) & int(b.c.min().x() <= a.c.max().x()) &
          int(a.c.min().y() <= b.c.max().y()) & int(b.c.min().y() <= a.c.max().y())) != 0;
}
template <class A, class B>
constexpr bool naive_exists() {
  return requires(const A& a, const B& b) {
    naive(a, b);
  };
}

/// The floor of a world-space contact of two circles: the fields contact() returns (normal, depth,
/// the point midway, its separation and feature id), in float, with one square root and one
/// division and no exact decision, so an answer within rounding of touching is a guess. Box2D's
/// b2CollideCircles returns a local manifold and leaves the square root to b2WorldManifold.
inline std::optional<collide::Contact<float>> naive_contact(const CircleIn& a, const CircleIn& b) {
  const V ca = a.c.center(), d = b.c.center() - ca;
  const float ra = a.c.radius(), r = ra + b.c.radius(), d2 = d.squaredNorm();
  if (d2 > r * r) return std::nullopt;
  const float dist = std::sqrt(d2), depth = r - dist;
  const V n = dist > 0 ? V(d / dist) : V(1, 0);
  return collide::Contact<float>{n, depth, 1, {V(ca + n * (ra - 0.5f * depth)), V(0, 0)}, {}, {-depth, 0}};
}
template <class A, class B>
constexpr bool naive_contact_exists() {
  return requires(const A& a, const B& b) {
    naive_contact(a, b);
  };
}

template <class A, class B>
struct Set {
  std::string pair;  // registry name, e.g. "circle_obb"
  Placement placement;
  std::vector<A> a;
  std::vector<B> b;
  double overlap_rate = 0;
};

/// Cross-check on every pair before timing. Decisions may differ only within `band` of touching
/// (Box2D: float GJK with a 10 eps tolerance, float polygon corners); depths of overlapping
/// pairs must agree within depth_tol (Box2D's polygon clipper prefers a face within 0.0005).
template <class A, class B>
bool cross_check(Set<A, B>& s) {
  constexpr double band = 1e-3, depth_tol = 2e-3;
  long hits = 0, bad = 0, boundary = 0, depth_bad = 0, b2_manifold_checked = 0, exact_calls = 0;
  std::uint64_t exact_signs = 0;
  for (std::size_t i = 0; i < s.a.size(); ++i) {
    const A& a = s.a[i];
    const B& b = s.b[i];
    const std::uint64_t before = collide::detail::exact_evaluations;
    const bool c = collide::overlaps(a.c, b.c);
    exact_signs += collide::detail::exact_evaluations - before;
    exact_calls += collide::detail::exact_evaluations != before;
    const auto ct = collide::contact(a.c, b.c);
    if (ct.has_value() != c) ++bad;
    hits += c;
    const double gap = collide::distance(a.c, b.c);
    const double depth = ct ? double(ct->depth) : 0.0;
    const bool near_boundary = (c && depth <= band) || (!c && gap <= band);
    auto compare = [&](bool other) {
      if (other == c) return;
      if (near_boundary) {
        ++boundary;
      } else {
        ++bad;
        if (bad < 5)
          std::fprintf(stderr, "  %s/%s pair %zu: collide %d, peer %d, gap %g, depth %g\n", s.pair.c_str(),
                       name(s.placement), i, c, other, gap, depth);
      }
    };
    compare(b2_overlap(a, b));
    if constexpr (naive_exists<A, B>()) compare(naive(a, b));
    if constexpr (naive_contact_exists<A, B>()) {
      const auto n = naive_contact(a, b);
      compare(n.has_value());
      if (n && ct && std::fabs(double(n->depth) - depth) > depth_tol) ++depth_bad;
    }
    if constexpr (manifold_exists<A, B>()) {
      const auto m = b2_manifold(a, b);
      compare(m->hit);
      if (m->hit && c) {
        ++b2_manifold_checked;
        if (std::fabs(double(m->depth) - depth) > depth_tol) {
          ++depth_bad;
          if (depth_bad < 5)
            std::fprintf(stderr, "  %s/%s pair %zu: depth collide %g, Box2D %g\n", s.pair.c_str(), name(s.placement), i,
                         depth, double(m->depth));
        }
      }
    }
  }
  s.overlap_rate = double(hits) / double(s.a.size());
  std::printf(
      "check %-16s %-8s overlap %5.1f%%  filter decided %6.2f%% (exact signs %llu)  "
      "boundary-band disagreements %ld  contacts compared %ld  %s\n",
      s.pair.c_str(), name(s.placement), 100 * s.overlap_rate,
      100.0 * double(long(s.a.size()) - exact_calls) / double(s.a.size()), (unsigned long long)exact_signs, boundary,
      b2_manifold_checked, bad == 0 && depth_bad == 0 ? "OK" : "MISMATCH");
  return bad == 0 && depth_bad == 0;
}

template <class A, class B, class F>
void run_pairs(benchmark::State& st, const Set<A, B>& s, F f) {
  for (auto _ : st) {
    int n = 0;
    for (std::size_t i = 0; i < s.a.size(); ++i) n += f(s.a[i], s.b[i]);
    benchmark::DoNotOptimize(n);
  }
  st.counters["pairs"] = double(s.a.size());
  st.counters["overlap_rate"] = s.overlap_rate;
}

template <class A, class B>
void register_set(const std::shared_ptr<Set<A, B>>& s) {
  const std::string tail = s->pair + "/" + name(s->placement);
  benchmark::RegisterBenchmark(("overlap/" + tail + "/collide").c_str(), [s](benchmark::State& st) {
    run_pairs(st, *s, [](const A& a, const B& b) { return int(collide::overlaps(a.c, b.c)); });
  });
  benchmark::RegisterBenchmark(("overlap/" + tail + "/box2d_test_overlap").c_str(), [s](benchmark::State& st) {
    run_pairs(st, *s, [](const A& a, const B& b) { return int(b2_overlap(a, b)); });
  });
  if constexpr (manifold_exists<A, B>()) {
    benchmark::RegisterBenchmark(("overlap/" + tail + "/box2d_manifold").c_str(), [s](benchmark::State& st) {
      run_pairs(st, *s, [](const A& a, const B& b) { return int(b2_manifold_points(a, b) > 0); });
    });
    benchmark::RegisterBenchmark(("contact/" + tail + "/collide").c_str(), [s](benchmark::State& st) {
      run_pairs(st, *s, [](const A& a, const B& b) {
        // The whole contact is kept: a solver reads every field, and a count alone would let the
        // compiler drop the rounding of the others, which Box2D's manifold function cannot skip.
        const auto c = collide::contact(a.c, b.c);
        benchmark::DoNotOptimize(c);
        return c ? c->count : 0;
      });
    });
    benchmark::RegisterBenchmark(("contact/" + tail + "/box2d_manifold").c_str(), [s](benchmark::State& st) {
      run_pairs(st, *s, [](const A& a, const B& b) { return b2_manifold_points(a, b); });
    });
  }
  if constexpr (naive_exists<A, B>()) {
    benchmark::RegisterBenchmark(("overlap/" + tail + "/naive").c_str(), [s](benchmark::State& st) {
      run_pairs(st, *s, [](const A& a, const B& b) { return int(naive(a, b)); });
    });
  }
  if constexpr (naive_contact_exists<A, B>()) {
    benchmark::RegisterBenchmark(("contact/" + tail + "/naive").c_str(), [s](benchmark::State& st) {
      run_pairs(st, *s, [](const A& a, const B& b) {
        const auto c = naive_contact(a, b);
        benchmark::DoNotOptimize(c);
        return c ? c->count : 0;
      });
    });
  }
}

template <class A, class B, class MA, class MB>
bool add_pair(collide::ShapeKind ka, collide::ShapeKind kb, float near_scale, MA ma, MB mb, unsigned seed) {
  bool ok = true;
  for (const Placement p : {Placement::Random, Placement::Near}) {
    auto s = std::make_shared<Set<A, B>>();
    s->pair = collide::name(collide::make_pair(ka, kb));
    s->placement = p;
    Maker maker(seed + (p == Placement::Near ? 1000u : 0u));
    maker.pairs(
        kPairs, p, near_scale, [&](const V& at) { return (maker.*ma)(at); },
        [&](const V& at) { return (maker.*mb)(at); }, s->a, s->b);
    ok = cross_check(*s) && ok;
    register_set(s);
  }
  return ok;
}

/// Exactly touching pairs: every decision takes the exact path, so these time its cost.
template <class A, class F>
bool add_touching(collide::ShapeKind k, F fill, unsigned seed) {
  auto s = std::make_shared<Set<A, A>>();
  s->pair = collide::name(collide::make_pair(k, k));
  s->placement = Placement::Touching;
  Maker maker(seed);
  (maker.*fill)(kPairs, s->a, s->b);
  const bool ok = cross_check(*s) && s->overlap_rate == 1.0;
  const std::string tail = s->pair + "/" + name(s->placement);
  benchmark::RegisterBenchmark(("overlap/" + tail + "/collide").c_str(), [s](benchmark::State& st) {
    run_pairs(st, *s, [](const A& a, const A& b) { return int(collide::overlaps(a.c, b.c)); });
  });
  if constexpr (naive_exists<A, A>()) {
    benchmark::RegisterBenchmark(("overlap/" + tail + "/naive").c_str(), [s](benchmark::State& st) {
      run_pairs(st, *s, [](const A& a, const A& b) { return int(naive(a, b)); });
    });
  }
  return ok;
}

}  // namespace

bool register_narrowphase() {
  using K = collide::ShapeKind;
  bool ok = true;
  ok = add_pair<CircleIn, CircleIn>(K::Circle, K::Circle, 2.0f, &Maker::circle, &Maker::circle, 1) && ok;
  ok = add_pair<AabbIn, AabbIn>(K::Aabb, K::Aabb, 1.7f, &Maker::aabb, &Maker::aabb, 2) && ok;
  ok = add_pair<ObbIn, ObbIn>(K::Obb, K::Obb, 1.6f, &Maker::obb, &Maker::obb, 3) && ok;
  ok = add_pair<CircleIn, ObbIn>(K::Circle, K::Obb, 1.8f, &Maker::circle, &Maker::obb, 4) && ok;
  ok = add_pair<CircleIn, AabbIn>(K::Circle, K::Aabb, 1.8f, &Maker::circle, &Maker::aabb, 9) && ok;
  ok = add_pair<CircleIn, HullIn>(K::Circle, K::Polygon, 1.5f, &Maker::circle, &Maker::hull, 10) && ok;
  ok = add_pair<CapsuleIn, CapsuleIn>(K::Capsule, K::Capsule, 1.4f, &Maker::capsule, &Maker::capsule, 5) && ok;
  ok = add_pair<HullIn, HullIn>(K::Polygon, K::Polygon, 1.3f, &Maker::hull, &Maker::hull, 6) && ok;
  ok = add_touching<CircleIn>(K::Circle, &Maker::touching_circles, 7) && ok;
  ok = add_touching<ObbIn>(K::Obb, &Maker::touching_boxes, 8) && ok;
  return ok;
}

}  // namespace bench
