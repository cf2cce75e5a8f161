// Uses the installed collide the way a game would; every expected value is worked out by hand.
#include <collide/collide.hpp>

#include <cmath>
#include <cstdio>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what);
  if (!ok) ++failures;
}

}  // namespace

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

  std::printf("%s\n", failures == 0 ? "consumer: all checks passed" : "consumer: FAILED");
  return failures == 0 ? 0 : 1;
}
