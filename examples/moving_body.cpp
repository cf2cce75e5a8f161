// A moving, rotating body updated by its transform each frame: a paddle (a box with a round cap,
// one compound in its own frame) spins while it sweeps across a row of resting balls. The shapes
// are built once; each frame only the transform changes. Each ball the paddle touches is pushed
// out by resolve() in world space, and the program checks that every push separates.

#include <collide/collide.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
  using V = collide::Vec2<float>;
  using Xf = collide::Transform<float>;
  using Child = collide::Compound<float>::Child;

  // The paddle in its own frame: a 4 x 0.5 bar, and a round cap placed at its right end.
  const auto paddle = collide::Compound<float>::make_placed(
                          std::vector<Child>{{collide::Aabb<float>(V(-2.0f, -0.25f), V(2.0f, 0.25f)), Xf()},
                                             {collide::Circle<float>(V(0.0f, 0.0f), 0.5f),
                                              Xf::make_translation(V(2.0f, 0.0f)).value()}})
                          .value();
  // The balls are world-space shapes (the identity transform).
  std::vector<collide::Circle<float>> balls;
  for (int i = 0; i < 8; ++i) balls.emplace_back(V(-7.0f + 2.0f * float(i), 0.0f), 0.4f);

  int pushes = 0, failures = 0;
  const float dt = 1.0f / 60.0f;
  for (int frame = 0; frame < 240; ++frame) {
    // 1. The body's transform for this frame: position and angle, nothing rebuilt.
    const float t = float(frame) * dt;
    const auto body = Xf::make(V(-8.0f + 4.0f * t, 0.5f * std::sin(3.0f * t)), 2.0f * t);
    if (!body) return 1;
    // 2. Every ball the paddle touches is pushed out of it.
    for (collide::Circle<float>& ball : balls) {
      if (!collide::overlaps(ball, Xf(), paddle, *body)) continue;
      const auto c = collide::contact(ball, Xf(), paddle, *body);  // world normal, depth, points
      const V push = collide::resolve(ball, Xf(), paddle, *body);
      ball = collide::translated(ball, push).value();
      ++pushes;
      if (!c || collide::overlaps(ball, Xf(), paddle, *body)) ++failures;
    }
  }
  const auto box = collide::bounds(paddle, Xf::make(V(0.0f, 0.0f), 0.5f).value());
  std::printf("%d pushes, %d failures; paddle box at 0.5 rad: (%g, %g) .. (%g, %g)\n", pushes, failures,
              double(box.min().x()), double(box.min().y()), double(box.max().x()), double(box.max().y()));
  return pushes > 0 && failures == 0 ? 0 : 1;
}
