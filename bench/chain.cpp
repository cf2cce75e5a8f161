// Chains: contact(segment, shape) against Box2D 2.4.1's one-sided edges with ghost vertices
// (b2EdgeShape::SetOneSided, b2CollideEdgeAndCircle / b2CollideEdgeAndPolygon, then
// b2WorldManifold for the normal and points a caller reads), on the same terrain and shapes.
//
// The terrain is one open chain of 1,024 segments 8 long with bumps, listed right to left so its
// front faces up; each shape is paired with the segment under its centre and placed so that
// about half of the pairs touch. Cross-check before timing: on every pair both libraries must
// agree where the answer does not depend on either's conventions (the whole shape over the middle
// of its segment, sunk by more than Box2D's skin and less than a quarter unit): both report a
// contact, with the segment's normal to 1e-4 and the same depth to 1e-4 or, where Box2D's float
// rounding at the pair's coordinates is coarser, 4 ulps of them. Deeper, Box2D may take a
// polygon's face and push the shape through to the edge's back (a polygon sunk 1.08 over
// segment 448 gets the normal (0.04, -0.999), pointing behind the edge, from Box2D; collide
// keeps a shape whose centre is in front on the front).

#include "inputs.hpp"
#include "suites.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace bench {
namespace {

constexpr std::size_t kSegments = 1024;
constexpr std::size_t kPairs = 1024;
constexpr float kLength = 8;  // of a segment along x: most shapes fit over one

struct Terrain {
  collide::Chain<float> chain;
  std::vector<b2EdgeShape> edges;  ///< Box2D's edge i is the chain's segment i, with its ghosts
  std::vector<float> height;       ///< height of the point at x = kLength i, for i in [0, kSegments]
};

template <class In>
struct ChainPair {
  std::size_t segment;
  In shape;
};

struct ChainInputs {
  Terrain terrain;
  std::vector<ChainPair<CircleIn>> circles;
  std::vector<ChainPair<HullIn>> hulls;
};

/// The terrain's points, right to left, with a ghost beyond each end.
Terrain make_terrain(Maker& m) {
  std::vector<float> h(kSegments + 3);
  float y = 0;
  for (float& v : h) {
    y = std::clamp(y + m.uniform(-2.0f, 2.0f), -12.0f, 12.0f);
    v = y;
  }
  // Point j of the chain is at x = kLength (kSegments + 1 - j) (the ghosts beyond both ends).
  std::vector<V> pts;
  for (std::size_t j = 0; j < kSegments + 3; ++j) pts.push_back(V(kLength * (float(kSegments) + 1 - float(j)), h[j]));
  Terrain t{collide::Chain<float>::make(pts, false).value(), {}, {}};
  for (std::size_t i = 0; i < t.chain.size(); ++i) {
    const collide::ChainSegment<float> s = t.chain.segment(i);
    b2EdgeShape e;
    e.SetOneSided(to_b2(s.before()), to_b2(s.a()), to_b2(s.b()), to_b2(s.after()));
    t.edges.push_back(e);
  }
  for (std::size_t x = 0; x <= kSegments; ++x) t.height.push_back(h[kSegments + 1 - x]);
  return t;
}

/// The shape made at the terrain's height under a random x, shifted so that about half touch.
template <class In, class Make>
ChainPair<In> near_terrain(Maker& m, const Terrain& t, Make make) {
  const float u = m.uniform(1.0f, float(kSegments) - 1.0f), x = kLength * u;
  const std::size_t cell = std::size_t(u);
  const float ground = t.height[cell] + (t.height[cell + 1] - t.height[cell]) * (u - float(cell));
  Maker replay = m;  // draws the probe's sizes again, so that the shape placed is the probe lifted
  const In probe = make(m, V(x, 0));
  const collide::Aabb<float> box = collide::bounds(probe.c);
  const float lift = ground - box.min().y() + m.uniform(-0.3f, 0.3f);
  // Segment i runs from x = kLength (kSegments - i) to kLength (kSegments - i - 1).
  return {kSegments - 1 - cell, make(replay, V(x, lift))};
}

const ChainInputs& chain_inputs() {
  static const ChainInputs in = [] {
    Maker m(57);
    ChainInputs out{make_terrain(m), {}, {}};
    for (std::size_t i = 0; i < kPairs; ++i) {
      out.circles.push_back(
          near_terrain<CircleIn>(m, out.terrain, [](Maker& mk, const V& at) { return mk.circle(at); }));
      out.hulls.push_back(near_terrain<HullIn>(m, out.terrain, [](Maker& mk, const V& at) { return mk.hull(at); }));
    }
    return out;
  }();
  return in;
}

void box2d_collide(b2Manifold* m, const b2EdgeShape& e, const b2CircleShape& s) {
  b2CollideEdgeAndCircle(m, &e, b2Transform(b2Vec2(0, 0), b2Rot(0)), &s, b2Transform(b2Vec2(0, 0), b2Rot(0)));
}
void box2d_collide(b2Manifold* m, const b2EdgeShape& e, const b2PolygonShape& s) {
  b2CollideEdgeAndPolygon(m, &e, b2Transform(b2Vec2(0, 0), b2Rot(0)), &s, b2Transform(b2Vec2(0, 0), b2Rot(0)));
}
const b2CircleShape& box2d_shape(const CircleIn& s) {
  return s.b;
}
const b2PolygonShape& box2d_shape(const HullIn& s) {
  return s.b;
}
float box2d_radius(const CircleIn& s) {
  return s.b.m_radius;
}
float box2d_radius(const HullIn&) {
  return 0;
}

/// Whether every point of the shape's core lies over the middle 90 % of the segment.
template <class In>
bool over_the_middle(const collide::ChainSegment<float>& s, const In& shape) {
  const float lo = std::min(s.a().x(), s.b().x()), hi = std::max(s.a().x(), s.b().x());
  const collide::Aabb<float> box = collide::bounds(shape.c);
  return box.min().x() > lo + 0.05f * (hi - lo) && box.max().x() < hi - 0.05f * (hi - lo);
}

template <class In>
bool cross_check(const char* kind, const Terrain& t, const std::vector<ChainPair<In>>& pairs) {
  std::size_t judged = 0;
  for (const ChainPair<In>& p : pairs) {
    const collide::ChainSegment<float> s = t.chain.segment(p.segment);
    const auto c = collide::contact(s, p.shape.c);
    if (!c || c->depth < 0.02f || c->depth > 0.25f || !over_the_middle(s, p.shape)) continue;
    ++judged;
    b2Manifold m;
    box2d_collide(&m, t.edges[p.segment], box2d_shape(p.shape));
    b2WorldManifold w;
    if (m.pointCount > 0) {
      w.Initialize(&m, b2Transform(b2Vec2(0, 0), b2Rot(0)), 0.0f, b2Transform(b2Vec2(0, 0), b2Rot(0)),
                   box2d_radius(p.shape));
    }
    float box2d_depth = 0;
    for (int i = 0; i < m.pointCount; ++i) box2d_depth = std::max(box2d_depth, -w.separations[i]);
    // Box2D computes in float: its depth is good to a few ulps of the pair's coordinates.
    const collide::Aabb<float> box = collide::bounds(p.shape.c);
    const float depth_tol =
        std::max(1e-4f, 4 * std::numeric_limits<float>::epsilon() *
                            std::max(box.max().cwiseAbs().maxCoeff(), box.min().cwiseAbs().maxCoeff()));
    if (m.pointCount == 0 || std::fabs(w.normal.x - c->normal.x()) > 1e-4f ||
        std::fabs(w.normal.y - c->normal.y()) > 1e-4f || std::fabs(box2d_depth - c->depth) > depth_tol) {
      std::fprintf(stderr,
                   "chain cross-check: %s over segment %zu: collide normal (%g, %g) depth %g, Box2D %d points "
                   "normal (%g, %g) depth %g\n",
                   kind, p.segment, double(c->normal.x()), double(c->normal.y()), double(c->depth), m.pointCount,
                   double(w.normal.x), double(w.normal.y), double(box2d_depth));
      return false;
    }
  }
  std::printf("check chain/%s: %zu of %zu pairs judged against Box2D: OK\n", kind, judged, pairs.size());
  return judged >= pairs.size() / 8;  // a check that judged few pairs proves little
}

template <class In>
void collide_chain(benchmark::State& state, const Terrain* t, const std::vector<ChainPair<In>>* pairs) {
  for (auto _ : state) {
    for (const ChainPair<In>& p : *pairs) {
      const auto c = collide::contact(t->chain.segment(p.segment), p.shape.c);
      benchmark::DoNotOptimize(c);
    }
  }
  state.counters["pairs"] = double(pairs->size());
}

template <class In>
void box2d_chain(benchmark::State& state, const Terrain* t, const std::vector<ChainPair<In>>* pairs) {
  for (auto _ : state) {
    for (const ChainPair<In>& p : *pairs) {
      b2Manifold m;
      box2d_collide(&m, t->edges[p.segment], box2d_shape(p.shape));
      b2WorldManifold w;
      if (m.pointCount > 0)
        w.Initialize(&m, b2Transform(b2Vec2(0, 0), b2Rot(0)), 0.0f, b2Transform(b2Vec2(0, 0), b2Rot(0)),
                     box2d_radius(p.shape));
      benchmark::DoNotOptimize(m);
      benchmark::DoNotOptimize(w);
    }
  }
  state.counters["pairs"] = double(pairs->size());
}

template <class In>
void register_kind(const char* kind, const Terrain& t, const std::vector<ChainPair<In>>& pairs) {
  const std::string base = std::string("chain/") + kind;
  benchmark::RegisterBenchmark((base + "/collide").c_str(), collide_chain<In>, &t, &pairs);
  benchmark::RegisterBenchmark((base + "/box2d").c_str(), box2d_chain<In>, &t, &pairs);
}

}  // namespace

bool register_chain() {
  const ChainInputs& in = chain_inputs();
  const bool ok = cross_check("circle", in.terrain, in.circles) && cross_check("polygon", in.terrain, in.hulls);
  register_kind("circle", in.terrain, in.circles);
  register_kind("polygon", in.terrain, in.hulls);
  return ok;
}

}  // namespace bench
