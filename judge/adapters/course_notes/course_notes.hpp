#pragma once
// The course notes' reference code for circles and axis-aligned boxes, as the notes print it:
// a tiny library a student would copy. It is kept as written, slips included, because the judge
// must find them: the box test compares a y with an x, the box resolution returns the vector
// with its sign reversed, and touching circles are called apart (a strict comparison).
// The notes' own contract (their text): shapes are closed, so touching shapes collide, and the
// resolution vector is the shortest translation of the first shape that separates the pair.
// Standalone (no collide): the judge's reproducers include it as it is.

#include <algorithm>
#include <cmath>

namespace course_notes {

struct Vec {
  double x, y;
};

struct Circle {
  Vec c;
  double r;
};

struct Box {
  Vec min, max;
};

inline bool overlaps(const Box& a, const Box& b) {
  return !(a.max.x < b.min.x || b.max.x < a.min.x || a.max.y < b.min.y || b.max.y < a.min.x);
}

inline bool overlaps(const Circle& a, const Circle& b) {
  const double dx = b.c.x - a.c.x, dy = b.c.y - a.c.y, r = a.r + b.r;
  return dx * dx + dy * dy < r * r;
}

// The point of the box closest to the circle's centre, then the distance to it.
inline bool overlaps(const Circle& a, const Box& b) {
  const double qx = std::clamp(a.c.x, b.min.x, b.max.x), qy = std::clamp(a.c.y, b.min.y, b.max.y);
  const double dx = a.c.x - qx, dy = a.c.y - qy;
  return dx * dx + dy * dy <= a.r * a.r;
}

inline bool overlaps(const Box& a, const Circle& b) {
  return overlaps(b, a);
}

// The shortest of the four axis pushes that separate a from b.
inline Vec resolve(const Box& a, const Box& b) {
  const double left = a.max.x - b.min.x, right = b.max.x - a.min.x;
  const double down = a.max.y - b.min.y, up = b.max.y - a.min.y;
  Vec v{-left, 0};
  double best = left;
  if (right < best) best = right, v = Vec{right, 0};
  if (down < best) best = down, v = Vec{0, -down};
  if (up < best) best = up, v = Vec{0, up};
  return Vec{-v.x, -v.y};
}

// Along the line of centres, by the overlap of the radii (any direction when the centres meet).
inline Vec resolve(const Circle& a, const Circle& b) {
  const double dx = a.c.x - b.c.x, dy = a.c.y - b.c.y, d = std::sqrt(dx * dx + dy * dy);
  const double depth = a.r + b.r - d;
  if (d == 0) return Vec{depth, 0};
  return Vec{dx / d * depth, dy / d * depth};
}

// Away from the closest point of the box; a centre inside the box leaves by the nearest face.
inline Vec resolve(const Circle& a, const Box& b) {
  const bool inside = a.c.x >= b.min.x && a.c.x <= b.max.x && a.c.y >= b.min.y && a.c.y <= b.max.y;
  if (inside) {
    const double faces[4] = {a.c.x - b.min.x, b.max.x - a.c.x, a.c.y - b.min.y, b.max.y - a.c.y};
    const int i = static_cast<int>(std::min_element(faces, faces + 4) - faces);
    const double d = faces[i] + a.r;
    const Vec dirs[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    return Vec{dirs[i].x * d, dirs[i].y * d};
  }
  const double qx = std::clamp(a.c.x, b.min.x, b.max.x), qy = std::clamp(a.c.y, b.min.y, b.max.y);
  const double dx = a.c.x - qx, dy = a.c.y - qy, d = std::sqrt(dx * dx + dy * dy);
  const double depth = a.r - d;
  return Vec{dx / d * depth, dy / d * depth};
}

inline Vec resolve(const Box& a, const Circle& b) {
  const Vec v = resolve(b, a);
  return Vec{-v.x, -v.y};
}

}  // namespace course_notes
