// The README's usage example, built and run by ctest so it stays correct.
#include <collide/collide.hpp>

#include <cstdio>

int main() {
  using V = collide::Vec2<float>;

  // Shapes validate their input: make() returns a named error, the constructor throws it.
  const collide::Circle<float> ball(V(0.0f, 0.0f), 1.0f);
  const collide::Obb<float> crate(V(1.5f, 0.0f), V(1.0f, 0.5f), 0.3f);  // centre, half extents, angle
  const auto bad = collide::Circle<float>::make(V(0.0f, 0.0f), -1.0f);
  if (!bad) std::printf("rejected: %s\n", bad.error().what());  // NegativeRadius: ...

  if (collide::overlaps(ball, crate)) {            // closed sets: touching counts
    const auto c = collide::contact(ball, crate);  // present exactly when overlaps() is true
    std::printf("depth %g along (%g, %g)\n", c->depth, c->normal.x(), c->normal.y());
    const V push = collide::resolve(ball, crate);  // move the ball by this to separate
    const auto moved = collide::translated(ball, push).value();
    std::printf("after the push: %s\n", collide::overlaps(moved, crate) ? "overlap" : "apart");
    return collide::overlaps(moved, crate) ? 1 : 0;
  }
  return 1;  // this scene is built to overlap
}
