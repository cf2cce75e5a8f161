// The broadphase structures' ray queries at the edges of double's range, where the slab test's
// parameters underflow. Every structure must give the exact answer for these boxes, not merely
// the same answer as the others (the fuzz target compares them with each other).

#include <collide/broadphase.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

namespace collide::test {
namespace {

namespace bp = collide::broadphase;
using V = Vec2<double>;

template <class Structure>
std::vector<std::pair<bp::ProxyId, double>> hits(const Structure& s, V origin, V direction, double max_t) {
  std::vector<std::pair<bp::ProxyId, double>> out;
  s.raycast(origin, direction, max_t, [&](bp::ProxyId id, double t) { out.emplace_back(id, t); });
  return out;
}

template <class Structure>
void check_underflowing_slab(Structure s) {
  // The box starts 2^-960 right of the origin; the direction is 2^800 long along x. Moving left,
  // the ray crosses the line x = 2^-960 at t = -2^-1760, which underflows to -0: the slab test
  // used to take that for t = 0 and report a hit although the origin is outside the box.
  const bp::ProxyId id = s.add(V(std::ldexp(1.0, -960), -1), V(1, 1));
  EXPECT_TRUE(hits(s, V(0, 0), V(-std::ldexp(1.0, 800), 0), 1).empty());
  EXPECT_TRUE(hits(s, V(0, 0), V(-std::ldexp(1.0, 800), 0), 0).empty());
  // Moving right it is hit, at t = 2^-1760 rounded up to the smallest subnormal (never 0: the
  // origin is not in the box).
  const auto h = hits(s, V(0, 0), V(std::ldexp(1.0, 800), 0), 1);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0].first, id);
  EXPECT_GT(h[0].second, 0.0);
  EXPECT_LE(h[0].second, std::ldexp(1.0, -1000));
  // From inside the box, and from its boundary: t = 0 (closed boxes).
  EXPECT_EQ(hits(s, V(0.5, 0), V(-std::ldexp(1.0, 800), 0), 1).size(), 1u);
  EXPECT_EQ(hits(s, V(std::ldexp(1.0, -960), 0), V(-std::ldexp(1.0, 800), 0), 1).size(), 1u);
}

TEST(BroadphaseRaycast, UnderflowingSlabParameterKeepsItsSignDynamicTree) {
  check_underflowing_slab(bp::DynamicTree<double>(0.0));
}
TEST(BroadphaseRaycast, UnderflowingSlabParameterKeepsItsSignSweepAndPrune) {
  check_underflowing_slab(bp::SweepAndPrune<double>());
}
TEST(BroadphaseRaycast, UnderflowingSlabParameterKeepsItsSignUniformGrid) {
  check_underflowing_slab(bp::UniformGrid<double>(1.0));
}

}  // namespace
}  // namespace collide::test
