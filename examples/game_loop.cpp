/// @file game_loop.cpp
/// A game loop with collide: thirty moving, spinning bodies of every primitive kind in a walled
/// arena. Each body's shape is built once in its own frame; each frame moves the bodies by new
/// transforms, lets the persistent World compute their contacts and report the contacts that
/// began and ended, and pushes bodies out of each other and out of the walls with resolve(). At
/// the end it checks the World against all pairs, and writes the last frame as an SVG picture
/// (game_loop.svg, or the path in argv[1]). Exits non-zero if any check fails.

#include <collide/broadphase.hpp>
#include <collide/collide.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

namespace {

using T = float;
using V = collide::Vec2<T>;
using collide::Shape;
using collide::broadphase::ProxyId;

constexpr T kArena = 20;      // the walls' inner faces are at +-kArena
constexpr T kDt = T(1) / 60;  // seconds per frame
constexpr int kFrames = 600;
constexpr std::uint32_t kWallGroup = 1, kBodyGroup = 2;

/// A moving body: its kind, size, where it is and how it moves.
struct Body {
  collide::ShapeKind kind;
  T size;
  V position;
  T angle;
  V velocity;
  T spin;  // radians per second
  ProxyId id;
};

/// The body's shape in world space at its current position and angle (for the picture).
Shape<T> world_shape(const Body& b) {
  const V axis(std::cos(b.angle), std::sin(b.angle));
  switch (b.kind) {
    case collide::ShapeKind::Circle:
      return collide::Circle<T>(b.position, b.size);
    case collide::ShapeKind::Obb:
      return collide::Obb<T>(b.position, V(b.size, b.size / 2), b.angle);
    case collide::ShapeKind::Capsule:
      return collide::Capsule<T>(b.position - axis * b.size, b.position + axis * b.size, b.size / 2);
    default: {
      // A regular polygon of 3 to 8 sides, chosen by its size.
      const int n = 3 + int(b.size * 10) % 6;
      std::vector<V> v;
      for (int k = 0; k < n; ++k) {
        const T a = b.angle + T(2) * std::numbers::pi_v<T> * T(k) / T(n);
        v.push_back(b.position + V(std::cos(a), std::sin(a)) * b.size);
      }
      return collide::ConvexPolygon<T>(std::span<const V>(v));
    }
  }
}

/// The body's shape in its own frame, built once.
Shape<T> local_shape(const Body& b) {
  Body at_origin = b;
  at_origin.position = V(0, 0);
  at_origin.angle = 0;
  return world_shape(at_origin);
}

/// The body's pose: where its frame is and how it is turned.
collide::Transform<T> pose(const Body& b) {
  return collide::Transform<T>::make(b.position, b.angle).value();
}

/// Deterministic pseudo-random numbers in [0, 1), so every run is the same scene.
struct Random {
  std::uint32_t state = 12345;
  T next() {
    state = state * 1664525u + 1013904223u;
    return T(state >> 8) / T(1 << 24);
  }
};

int failures = 0;
void expect(bool ok, const char* what) {
  if (!ok) {
    std::printf("  UNEXPECTED: %s\n", what);
    ++failures;
  }
}

/// The last frame as an SVG picture: walls grey, bodies blue, contact points red with their normals.
void write_svg(const char* path, const std::vector<Shape<T>>& walls, const std::vector<Body>& bodies,
               const std::vector<std::pair<V, V>>& contacts) {
  std::FILE* f = std::fopen(path, "w");
  if (!f) {
    std::printf("  cannot write %s\n", path);
    ++failures;
    return;
  }
  const T scale = 12, half = kArena + 2;
  auto x = [&](T v) { return (v + half) * scale; };
  auto y = [&](T v) { return (half - v) * scale; };
  std::fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\">\n", double(2 * half * scale),
               double(2 * half * scale));
  auto draw = [&](const Shape<T>& s, const char* fill) {
    std::visit(
        [&](const auto& shape) {
          using S = std::remove_cvref_t<decltype(shape)>;
          if constexpr (std::is_same_v<S, collide::Circle<T>>) {
            std::fprintf(f, "<circle cx=\"%g\" cy=\"%g\" r=\"%g\" fill=\"%s\"/>\n", double(x(shape.center().x())),
                         double(y(shape.center().y())), double(shape.radius() * scale), fill);
          } else if constexpr (std::is_same_v<S, collide::Aabb<T>>) {
            std::fprintf(f, "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"%s\"/>\n",
                         double(x(shape.min().x())), double(y(shape.max().y())),
                         double((shape.max().x() - shape.min().x()) * scale),
                         double((shape.max().y() - shape.min().y()) * scale), fill);
          } else if constexpr (std::is_same_v<S, collide::Capsule<T>>) {
            std::fprintf(f,
                         "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"%s\" stroke-width=\"%g\" "
                         "stroke-linecap=\"round\"/>\n",
                         double(x(shape.a().x())), double(y(shape.a().y())), double(x(shape.b().x())),
                         double(y(shape.b().y())), fill, double(2 * shape.radius() * scale));
          } else if constexpr (std::is_same_v<S, collide::Obb<T>> || std::is_same_v<S, collide::ConvexPolygon<T>>) {
            std::vector<V> corners;
            if constexpr (std::is_same_v<S, collide::Obb<T>>) {
              const V u = shape.axis(), v(-u.y(), u.x()), h = shape.half_extents();
              for (const auto& [su, sv] : {std::pair{1, 1}, {-1, 1}, {-1, -1}, {1, -1}})
                corners.push_back(shape.center() + u * (T(su) * h.x()) + v * (T(sv) * h.y()));
            } else {
              corners.assign(shape.vertices().begin(), shape.vertices().end());
            }
            std::fprintf(f, "<polygon fill=\"%s\" points=\"", fill);
            for (const V& p : corners) std::fprintf(f, "%g,%g ", double(x(p.x())), double(y(p.y())));
            std::fprintf(f, "\"/>\n");
          }
        },
        s);
  };
  for (const Shape<T>& w : walls) draw(w, "#888888");
  for (const Body& b : bodies) draw(world_shape(b), "#4a7fc1");
  for (const auto& [p, n] : contacts) {
    std::fprintf(f, "<circle cx=\"%g\" cy=\"%g\" r=\"3\" fill=\"#d03030\"/>\n", double(x(p.x())), double(y(p.y())));
    std::fprintf(f, "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#d03030\" stroke-width=\"1.5\"/>\n",
                 double(x(p.x())), double(y(p.y())), double(x(p.x() + n.x())), double(y(p.y() + n.y())));
  }
  std::fprintf(f, "</svg>\n");
  std::fclose(f);
}

}  // namespace

int main(int argc, char** argv) {
  const char* picture = argc > 1 ? argv[1] : "game_loop.svg";
  collide::broadphase::World<T> world;

  // Static walls: they pair with bodies only (mask), never with each other.
  const T k = kArena;
  const std::vector<Shape<T>> walls = {
      collide::Aabb<T>(V(-k - 1, -k - 1), V(k + 1, -k)), collide::Aabb<T>(V(-k - 1, k), V(k + 1, k + 1)),
      collide::Aabb<T>(V(-k - 1, -k), V(-k, k)), collide::Aabb<T>(V(k, -k), V(k + 1, k))};
  std::vector<ProxyId> wall_ids;
  for (const Shape<T>& w : walls)
    wall_ids.push_back(world.add(w, 0, collide::broadphase::Filter{kWallGroup, kBodyGroup}));

  // Moving bodies on a grid, every primitive kind, with random speeds and spins: each body's
  // shape is given once, in its own frame, with the transform that places it.
  Random rng;
  std::vector<Body> bodies;
  const collide::ShapeKind kinds[] = {collide::ShapeKind::Circle, collide::ShapeKind::Obb, collide::ShapeKind::Capsule,
                                      collide::ShapeKind::Polygon};
  for (int i = 0; i < 30; ++i) {
    Body b{kinds[i % 4],
           T(0.6) + rng.next(),
           V(T(-15 + 6 * (i % 6)), T(-12 + 6 * (i / 6))),
           0,
           V(rng.next() * 16 - 8, rng.next() * 16 - 8),
           rng.next() * 4 - 2,
           ProxyId{}};
    b.id = world.add(local_shape(b), pose(b), std::uint64_t(i),
                     collide::broadphase::Filter{kBodyGroup, kWallGroup | kBodyGroup});
    bodies.push_back(b);
  }
  auto body_of = [&](ProxyId id) -> Body* {
    const std::uint64_t user = world.user_data(id);
    for (const ProxyId& w : wall_ids)
      if (w == id) return nullptr;
    return &bodies[std::size_t(user)];
  };

  long began = 0, ended = 0, contact_pairs = 0, contact_points = 0, pushes_left_overlapping = 0;
  std::vector<std::pair<V, V>> last_contacts;
  for (int frame = 0; frame < kFrames; ++frame) {
    // 1. Move: integrate, then give the World each body's new transform (no shape is rebuilt).
    for (Body& b : bodies) {
      b.position += b.velocity * kDt;
      b.angle += b.spin * kDt;
      world.move(b.id, pose(b));
    }
    // 2. The broadphase and the contacts of the placed shapes: those that began and ended.
    const collide::broadphase::PairEvents& events = world.step();
    began += long(events.began.size());
    ended += long(events.ended.size());

    // On the last frame, the World's contacts must be exactly the overlapping pairs its filters
    // allow, found by testing all pairs, each with the manifold contact() gives for that pair.
    if (frame == kFrames - 1) {
      std::set<std::pair<std::uint32_t, std::uint32_t>> reported, all_pairs;
      world.for_each_contact([&](const collide::broadphase::BodyContact<T>& c) {
        reported.insert(std::minmax(c.a.index, c.b.index));
        const auto again =
            collide::contact(world.shape(c.a), world.transform(c.a), world.shape(c.b), world.transform(c.b));
        expect(again && again->normal == c.contact.normal && again->depth == c.contact.depth,
               "a World contact is the pair's contact()");
      });
      std::vector<ProxyId> every(wall_ids);
      for (const Body& b : bodies) every.push_back(b.id);
      for (std::size_t i = 0; i < every.size(); ++i)
        for (std::size_t j = i + 1; j < every.size(); ++j) {
          const bool both_walls = i < walls.size() && j < walls.size();
          if (!both_walls && collide::overlaps(world.shape(every[i]), world.transform(every[i]), world.shape(every[j]),
                                               world.transform(every[j])))
            all_pairs.insert(std::minmax(every[i].index, every[j].index));
        }
      expect(reported == all_pairs, "the World's contacts are exactly the overlapping pairs");
      expect(long(reported.size()) == began - ended, "contacts now = contacts begun - contacts ended");
      last_contacts.clear();
    }

    // 3. Contacts and resolution: every contact the step found; bodies are pushed apart (half
    //    each) and out of walls (all of it), and bounce off along the contact normal. A push moves
    //    a body after the step, so the push is asked of the bodies where they are now.
    world.for_each_contact([&](const collide::broadphase::BodyContact<T>& c) {
      ProxyId ia = c.a, ib = c.b;
      V n = c.contact.normal;  // from a toward b
      Body* a = body_of(ia);
      Body* b = body_of(ib);
      if (!a) std::swap(a, b), std::swap(ia, ib), n = -n;  // a is always a body
      ++contact_pairs;
      contact_points += c.contact.count;
      if (frame == kFrames - 1)
        for (int p = 0; p < c.contact.count; ++p) last_contacts.emplace_back(c.contact.points[std::size_t(p)], n);
      const Shape<T>& sa = world.shape(ia);
      const Shape<T>& sb = world.shape(ib);
      const collide::Transform<T> xa = pose(*a), xb = b ? pose(*b) : world.transform(ib);
      if (!collide::overlaps(sa, xa, sb, xb)) return;  // apart again after an earlier push this frame
      const V push = collide::resolve(sa, xa, sb, xb);
      const auto moved = xa.moved(push);
      if (moved && collide::overlaps(sa, *moved, sb, xb)) ++pushes_left_overlapping;
      if (b) {
        a->position += push / 2;
        b->position -= push / 2;
        const T approach = (a->velocity - b->velocity).dot(n);
        if (approach > 0) {
          a->velocity -= n * approach;
          b->velocity += n * approach;
        }
      } else {
        a->position += push;
        const T approach = a->velocity.dot(n);
        if (approach > 0) a->velocity -= n * (2 * approach);
      }
    });
  }

  bool inside = true;
  for (const Body& b : bodies) inside = inside && std::fabs(b.position.x()) < k && std::fabs(b.position.y()) < k;
  expect(inside, "no body left the arena");
  expect(pushes_left_overlapping == 0, "every push separates the pair it resolves");
  expect(began > 0 && ended > 0, "contacts began and ended during the run");

  std::printf(
      "%d frames, %zu bodies and %zu walls: %ld contacts began, %ld ended; %ld contacts resolved "
      "(%ld points)\n",
      kFrames, bodies.size(), walls.size(), began, ended, contact_pairs, contact_points);
  write_svg(picture, walls, bodies, last_contacts);
  std::printf("picture of the last frame: %s\n", picture);
  std::printf("%s\n", failures == 0 ? "game loop: all checks passed" : "game loop: FAILED");
  return failures == 0 ? 0 : 1;
}
