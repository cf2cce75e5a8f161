// Uses the installed collide::compiled the way a game would: the queries on Shape<T> come from
// the library (collide/compiled.hpp declares them extern; run_consumer.cmake checks that this
// file's object defines none of them). Every expected value is worked out by hand.
#include <collide/compiled.hpp>

#include <cmath>
#include <cstdio>

#include "check.hpp"

using consumer::check;
using consumer::failures;

int main() {
  using V = collide::Vec2<double>;
  using Shape = collide::Shape<double>;
  using Transform = collide::Transform<double>;

  // The unit circle, a box [1.5, 3] x [-1, 1] 0.5 to its right, and a circle of radius 1 at (1.5, 0).
  const Shape circle = collide::Circle<double>(V(0, 0), 1.0);
  const Shape box = collide::Aabb<double>(V(1.5, -1), V(3, 1));
  const Shape near = collide::Circle<double>(V(1.5, 0), 1.0);

  check(!collide::overlaps(circle, box), "the circle and the box 0.5 to its right do not overlap");
  check(std::fabs(collide::distance(circle, box) - 0.5) < 1e-12, "their distance is 0.5");
  const auto c = collide::contact(circle, near);
  check(c.has_value() && std::fabs(c->depth - 0.5) < 1e-12 && std::fabs(c->normal.x() - 1) < 1e-12,
        "circles 1.5 apart with radii 1 touch 0.5 deep along +x");
  const auto speculative = collide::contact(circle, box, 1.0);
  check(speculative.has_value() && speculative->depth == 0, "a speculative contact reaches the box 0.5 away");
  check(collide::resolve(circle, near).x() <= -0.5, "resolve pushes the circle along -x by >= 0.5");
  check(collide::contains(box, V(2, 0)) && !collide::contains(box, V(0, 0)), "the box contains (2, 0), not (0, 0)");
  const auto hit = collide::raycast(box, collide::Ray<double>{V(-10, 0), V(1, 0)}, 100.0);
  check(hit.has_value() && std::fabs(hit->t - 11.5) < 1e-12 && std::fabs(hit->normal.x() + 1) < 1e-12,
        "a ray along +x from (-10, 0) meets the box at t = 11.5, normal (-1, 0)");

  // Placed by transforms: the box moved 1 to the left overlaps the circle, 1 to the right is 1.5 away.
  const Transform here;
  const Transform left = Transform::make_translation(V(-1, 0)).value();
  const Transform right = Transform::make_translation(V(1, 0)).value();
  check(collide::overlaps(circle, here, box, left), "the box moved 1 to the left overlaps the circle");
  check(std::fabs(collide::distance(circle, here, box, right) - 1.5) < 1e-12, "moved 1 to the right it is 1.5 away");
  const auto placed = collide::contact(circle, here, box, left);
  check(placed.has_value() && std::fabs(placed->depth - 0.5) < 1e-12, "and then 0.5 deep");
  // Conservative: the image's box [2.5, 4] x [-1, 1] padded by transform_tolerance(box, right), a few ulps.
  const collide::Aabb<double> moved = collide::bounds(box, right);
  check(moved.min().x() <= 2.5 && moved.min().x() > 2.5 - 1e-12 && moved.max().x() >= 4 && moved.max().x() < 4 + 1e-12,
        "the moved box's bounds hold [2.5, 4] along x, padded by at most 1e-12");

  // Moving: the circle at speed 1 along +x meets the box at t = 0.5, by a cast and by a sweep.
  const auto cast = collide::shape_cast(circle, V(1, 0), box, V(0, 0), 1.0);
  check(cast.hit() && std::fabs(cast.t - 0.5) < 1e-6, "a cast along +x meets the box at t = 0.5");
  collide::Sweep<double> moving, still;
  moving.c1 = V(1, 0);
  const auto toi = collide::time_of_impact(circle, moving, box, still, 1.0);
  check(toi.hit() && std::fabs(toi.t - 0.5) < 1e-6, "a sweep along +x meets the box at t = 0.5");

  // float: the same library holds the float queries.
  using Vf = collide::Vec2<float>;
  const collide::Shape<float> small = collide::Circle<float>(Vf(0, 0), 1.0f);
  const collide::Shape<float> touching = collide::Circle<float>(Vf(2, 0), 1.0f);
  check(collide::overlaps(small, touching), "float circles exactly touching overlap");

  std::printf("%s\n", failures == 0 ? "all passed" : "FAILED");
  return failures == 0 ? 0 : 1;
}
