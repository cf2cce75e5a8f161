// Mass properties: mass_properties() against Box2D 2.4.1's b2CircleShape::ComputeMass and
// b2PolygonShape::ComputeMass (convex hulls, and turned boxes as Box2D polygons), on the same
// shapes, cross-checked before timing.

#include "inputs.hpp"
#include "suites.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace bench {
namespace {

constexpr std::size_t kShapes = 1024;  // shapes per benchmark iteration (fits in L1/L2)

struct MassInputs {
  std::vector<CircleIn> circles;
  std::vector<HullIn> hulls;
  std::vector<ObbIn> boxes;
};

/// The shapes, anywhere in the 100 x 100 world (fixed seed).
const MassInputs& mass_inputs() {
  static const MassInputs in = [] {
    Maker m(41);
    MassInputs out;
    for (std::size_t i = 0; i < kShapes; ++i) {
      const V at(m.uniform(0, 100), m.uniform(0, 100));
      out.circles.push_back(m.circle(at));
      out.hulls.push_back(m.hull(at));
      out.boxes.push_back(m.obb(at));
    }
    return out;
  }();
  return in;
}

/// Box2D's mass data of a shape at unit density (its I is about the origin).
template <class In>
b2MassData box2d_mass(const In& s) {
  b2MassData md;
  s.b.ComputeMass(&md, 1.0f);
  return md;
}

/// The two agree to float's accuracy: mass, centroid, and Box2D's I against origin_inertia (both
/// about the origin), each relatively within 1e-4 (Box2D's float sums lose about 1e-6 here).
bool agrees(const b2MassData& b, const collide::MassProperties<float>& c) {
  auto near = [](double x, double y, double scale) { return std::fabs(x - y) <= 1e-4 * scale; };
  const double reach = std::max(std::fabs(double(b.center.x)), std::fabs(double(b.center.y))) + 1;
  return near(b.mass, c.mass, b.mass) && near(b.center.x, c.centroid.x(), reach) &&
         near(b.center.y, c.centroid.y(), reach) && near(b.I, c.origin_inertia, b.I);
}

template <class In>
bool cross_check(const char* kind, const std::vector<In>& shapes) {
  for (const In& s : shapes) {
    const b2MassData b = box2d_mass(s);
    const auto c = collide::mass_properties(s.c, 1.0f);
    if (!c || !agrees(b, *c)) {
      std::fprintf(stderr, "mass cross-check: %s differs: Box2D mass %g I %g, collide %s\n", kind, double(b.mass),
                   double(b.I), c ? "other values" : c.error().what());
      return false;
    }
  }
  return true;
}

template <class In>
void collide_mass(benchmark::State& state, const std::vector<In>* shapes) {
  for (auto _ : state) {
    for (const In& s : *shapes) {
      const auto m = collide::mass_properties(s.c, 1.0f);
      benchmark::DoNotOptimize(m);
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(shapes->size()));
}

template <class In>
void box2d_mass_bench(benchmark::State& state, const std::vector<In>* shapes) {
  for (auto _ : state) {
    for (const In& s : *shapes) {
      b2MassData md;
      s.b.ComputeMass(&md, 1.0f);
      benchmark::DoNotOptimize(md);
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(shapes->size()));
}

template <class In>
void register_kind(const char* kind, const std::vector<In>& shapes) {
  const std::string base = std::string("mass/") + kind;
  benchmark::RegisterBenchmark((base + "/collide").c_str(), collide_mass<In>, &shapes);
  benchmark::RegisterBenchmark((base + "/box2d").c_str(), box2d_mass_bench<In>, &shapes);
}

}  // namespace

bool register_mass() {
  const MassInputs& in = mass_inputs();
  const bool ok = cross_check("circle", in.circles) && cross_check("polygon", in.hulls) && cross_check("obb", in.boxes);
  register_kind("circle", in.circles);
  register_kind("polygon", in.hulls);
  register_kind("obb", in.boxes);
  return ok;
}

}  // namespace bench
