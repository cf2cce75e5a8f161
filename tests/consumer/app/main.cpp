// Uses the installed collide the way a game would; every expected value is worked out by hand.
#include <collide/broadphase.hpp>
#include <collide/collide.hpp>

#include <cmath>
#include <cstdio>

#include "check.hpp"

using consumer::check;
using consumer::failures;

int main() {
  using collide::Vec2;
  using V = Vec2<double>;

  // Centres 1.5 apart, radii 1 + 1: they overlap by 0.5 along +x.
  const collide::Circle<double> a(V(0, 0), 1.0);
  const collide::Circle<double> b(V(1.5, 0), 1.0);
  check(collide::overlaps(a, b), "circles 1.5 apart with radii 1 overlap");
  const auto c = collide::contact(a, b);
  check(c.has_value() && std::fabs(c->depth - 0.5) < 1e-12, "their contact depth is 0.5");
  check(c.has_value() && std::fabs(c->normal.x() - 1) < 1e-12 && std::fabs(c->normal.y()) < 1e-12,
        "their contact normal is (1, 0)");

  // Closed sets: centres exactly 2 apart touch; a little further they do not.
  check(collide::overlaps(a, collide::Circle<double>(V(2, 0), 1.0)), "touching circles overlap");
  check(!collide::overlaps(a, collide::Circle<double>(V(2.001, 0), 1.0)), "circles 0.001 apart do not");

  // A box and a triangle sharing only the corner (1, 1): touching, decided exactly.
  const collide::Aabb<double> box(V(0, 0), V(1, 1));
  const collide::ConvexPolygon<double> tri({V(1, 1), V(2, 1), V(1, 2)});
  check(collide::overlaps(box, tri), "box and triangle sharing a corner overlap");
  const collide::ConvexPolygon<double> tri_moved({V(1 + 0x1p-40, 1), V(2, 1), V(1 + 0x1p-40, 2)});
  check(!collide::overlaps(box, tri_moved), "moved 2^-40 to the right, they do not");

  // The gap from the unit circle to the box [3, 4] x [-1, 1] is 3 - 1 = 2.
  const double gap = collide::distance(a, collide::Aabb<double>(V(3, -1), V(4, 1)));
  check(std::fabs(gap - 2) < 1e-12, "distance from the unit circle to a box at x = 3 is 2");

  // Resolving pushes a out of b along -x by at least the depth, and then they are apart.
  const V push = collide::resolve(a, b);
  check(push.x() <= -0.5 && std::fabs(push.y()) < 1e-12, "resolve pushes a along -x by >= 0.5");
  const auto moved = collide::translated(a, push);
  check(moved.has_value() && !collide::overlaps(moved.value(), b), "after the push they are apart");

  // Bad input gets a named error.
  const auto bad = collide::Circle<double>::make(V(0, 0), -1.0);
  check(!bad && bad.error().code() == collide::Error::NegativeRadius, "a negative radius is rejected");

  // A persistent world: two overlapping bodies begin a contact; moving one away ends it.
  collide::broadphase::World<double> world;
  const auto first = world.add(a, 1);
  const auto second = world.add(b, 2);
  const auto& began = world.step();
  check(began.began.size() == 1 && began.ended.empty(), "two overlapping bodies begin one contact");
  world.move(second, collide::Circle<double>(V(5, 0), 1.0));
  const auto& ended = world.step();
  check(ended.ended.size() == 1 && ended.began.empty(), "moving one away ends it");
  int at_origin = 0;
  world.query_point(V(0, 0), [&](collide::broadphase::ProxyId id) { at_origin += id == first ? 1 : 100; });
  check(at_origin == 1, "the point (0, 0) lies in the first body only");
  const auto hit = world.raycast(collide::Ray<double>{V(-10, 0), V(1, 0)}, 100.0);
  check(hit.has_value() && hit->body == first && std::fabs(hit->hit.t - 9) < 1e-12,
        "a ray along +x meets the first body at t = 9");

  // The three structures give the same pairs.
  collide::broadphase::DynamicTree<float> tree;
  collide::broadphase::SweepAndPrune<float> sweep;
  collide::broadphase::UniformGrid<float> grid(2.0f);
  for (int i = 0; i < 20; ++i) {
    const collide::Aabb<float> box(collide::Vec2<float>(float(i), 0.0f), collide::Vec2<float>(float(i) + 1.5f, 1.0f));
    tree.add(box, std::uint64_t(i));
    sweep.add(box, std::uint64_t(i));
    grid.add(box, std::uint64_t(i));
  }
  const auto order = collide::broadphase::PairOrder::Sorted;
  check(tree.pairs(order) == sweep.pairs(order) && tree.pairs(order) == grid.pairs(order) &&
            tree.pairs(order).size() == 19,
        "tree, sweep and grid find the same 19 pairs of 20 boxes in a row");

  std::printf("%s\n", failures == 0 ? "consumer: all checks passed" : "consumer: FAILED");
  return failures == 0 ? 0 : 1;
}
