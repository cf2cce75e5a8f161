/// @file scene_walkthrough.cpp
/// The course notes' flow on a small scene: build shapes (one rejected with a named error), the broad
/// check (bounding boxes), the exact overlap test, the contact, resolving the penetration and
/// testing again. Exits non-zero if any step contradicts what it should show.

#include <collide/collide.hpp>

#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace {

using collide::Shape;
using V = collide::Vec2<float>;

struct Object {
  std::string name;
  Shape<float> shape;
};

void print_box(const collide::Aabb<float>& b) {
  std::printf("[%g, %g] x [%g, %g]", b.min().x(), b.max().x(), b.min().y(), b.max().y());
}

int failures = 0;

void expect(bool ok, const char* what) {
  if (!ok) {
    std::printf("  UNEXPECTED: %s\n", what);
    ++failures;
  }
}

}  // namespace

int main() {
  using namespace collide;

  std::printf("1. Shapes (float, closed sets)\n");
  // A capsule player standing on the ground, leaning slightly into a crate turned by 45 degrees.
  std::vector<Object> scene;
  scene.push_back({"player", Capsule<float>(V(0, 0), V(0, 2), 0.5f)});
  scene.push_back({"crate", Obb<float>(V(1.2f, 1.0f), V(0.5f, 0.5f), std::numbers::pi_v<float> / 4)});
  scene.push_back({"coin", Circle<float>(V(0.75f, 2.75f), 0.3f)});
  scene.push_back({"ground", Aabb<float>(V(-3, -1.5f), V(3, -0.5f))});
  scene.push_back({"ramp", ConvexPolygon<float>({V(1.5f, -0.5f), V(3, -0.5f), V(3, 0.5f)})});
  for (const Object& o : scene) {
    std::printf("  %-6s bounds ", o.name.c_str());
    print_box(bounds(o.shape));
    std::printf("\n");
  }
  // Invalid input is refused with a named error, never accepted silently.
  const auto bad = ConvexPolygon<float>::make({V(0, 0), V(2, 0), V(1, 0.5f), V(2, 2), V(0, 2)});
  std::printf("  a dented polygon is rejected: %s\n", bad ? "accepted" : bad.error().what());
  expect(!bad && bad.error().code() == Error::NonConvex, "the dented polygon must be NonConvex");

  std::printf("\n2. Broad check: do the bounding boxes overlap?\n");
  struct Candidate {
    std::size_t i, j;
  };
  std::vector<Candidate> candidates;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    for (std::size_t j = i + 1; j < scene.size(); ++j) {
      const bool near = overlaps(bounds(scene[i].shape), bounds(scene[j].shape));
      std::printf("  %-6s - %-6s %s\n", scene[i].name.c_str(), scene[j].name.c_str(), near ? "yes" : "no");
      if (near) candidates.push_back({i, j});
      // The broad check is conservative: it may pass pairs that do not touch, never miss one.
      if (!near) expect(!overlaps(scene[i].shape, scene[j].shape), "boxes apart but shapes overlap");
    }
  }

  std::printf("\n3. Exact test on the candidates (touching counts as overlapping)\n");
  std::vector<Candidate> hits;
  for (const Candidate& c : candidates) {
    const bool hit = overlaps(scene[c.i].shape, scene[c.j].shape);
    std::printf("  %-6s - %-6s %s\n", scene[c.i].name.c_str(), scene[c.j].name.c_str(),
                hit ? "overlap" : "apart (boxes only)");
    if (hit) hits.push_back(c);
  }
  // Expectations from the scene's geometry, worked out by hand:
  // the crate's left corner reaches x = 1.2 - 0.5 * sqrt(2) ~ 0.493 < 0.5 (the capsule's side);
  // the coin's centre is sqrt(0.75^2 + 0.75^2) ~ 1.06 > 0.8 from the capsule's top point;
  // the capsule's bottom (y = -0.5) and the ramp's base edge lie exactly on the ground's top.
  expect(overlaps(scene[0].shape, scene[1].shape), "player and crate overlap");
  expect(!overlaps(scene[0].shape, scene[2].shape), "player and coin are apart");
  expect(overlaps(scene[0].shape, scene[3].shape), "player touches the ground");
  expect(overlaps(scene[3].shape, scene[4].shape), "ramp touches the ground along an edge");

  std::printf("\n4. Contact of each overlapping pair (normal points from the first to the second)\n");
  for (const Candidate& c : hits) {
    const auto k = contact(scene[c.i].shape, scene[c.j].shape);
    expect(k.has_value(), "contact exists exactly when the shapes overlap");
    if (!k) continue;
    std::printf("  %-6s - %-6s normal (%g, %g), depth %g, points", scene[c.i].name.c_str(), scene[c.j].name.c_str(),
                k->normal.x(), k->normal.y(), k->depth);
    for (int p = 0; p < k->count; ++p) std::printf(" (%g, %g)", k->points[p].x(), k->points[p].y());
    std::printf("\n");
  }

  std::printf("\n5. Resolve: push the player out of the crate, then test again\n");
  const Shape<float>& player = scene[0].shape;
  const Shape<float>& crate = scene[1].shape;
  const V push = resolve(player, crate);
  std::printf("  push (%g, %g)\n", push.x(), push.y());
  const auto moved = translated(player, push);
  expect(moved.has_value(), "the moved player is a valid shape");
  if (moved) {
    const bool still = overlaps(moved.value(), crate);
    std::printf("  player moved by the push vs crate: %s\n", still ? "overlap" : "apart");
    expect(!still, "after resolve the player no longer overlaps the crate");
    std::printf("  distance now %g\n", distance(moved.value(), crate));
  }
  // A pair that does not overlap needs no push.
  const V none = resolve(player, scene[2].shape);
  expect(none.x() == 0 && none.y() == 0, "no push for the coin");

  std::printf("\n%s\n", failures == 0 ? "scene walkthrough: all steps as expected" : "scene walkthrough: FAILED");
  return failures == 0 ? 0 : 1;
}
