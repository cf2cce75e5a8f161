#pragma once
/// @file sample_shapes.hpp
/// Random shapes of every kind around a given center, for the registry-driven agreement tests.

#include "collide/collide.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace collide::oracle::testing {

/// A random shape of kind K roughly within `size` of `center` (every kind, compounds included).
template <ShapeKind K>
ShapeOf<K, double> sample_shape(std::mt19937_64& rng, const Vec2<double>& center, double size) {
  std::uniform_real_distribution<double> unit(0.25, 1.0), angle(0.0, 6.283185307179586);
  const Vec2<double> c = center;
  if constexpr (K == ShapeKind::Circle) {
    return Circle<double>(c, size * unit(rng));
  } else if constexpr (K == ShapeKind::Aabb) {
    const Vec2<double> h(size * unit(rng), size * unit(rng));
    return Aabb<double>(c - h, c + h);
  } else if constexpr (K == ShapeKind::Obb) {
    return Obb<double>(c, Vec2<double>(size * unit(rng), size * unit(rng)), angle(rng));
  } else if constexpr (K == ShapeKind::Capsule) {
    const double a = angle(rng), l = size * unit(rng) * 0.7;
    const Vec2<double> d(l * std::cos(a), l * std::sin(a));
    return Capsule<double>(c - d, c + d, size * unit(rng) * 0.4);
  } else if constexpr (K == ShapeKind::Polygon) {
    std::vector<Vec2<double>> pts;
    const int n = 3 + static_cast<int>(rng() % 6);
    const double phase = angle(rng);
    for (int i = 0; i < n; ++i) {
      const double a = phase + 6.283185307179586 * i / n, r = size * unit(rng);
      pts.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a));
    }
    return ConvexPolygon<double>::make_hull(pts).value();
  } else {
    std::vector<Primitive<double>> children;
    const int n = 1 + static_cast<int>(rng() % 3);
    std::uniform_real_distribution<double> off(-0.5 * size, 0.5 * size);
    for (int i = 0; i < n; ++i) {
      const Vec2<double> cc = c + Vec2<double>(off(rng), off(rng));
      switch (rng() % 5) {
        case 0:
          children.emplace_back(sample_shape<ShapeKind::Circle>(rng, cc, 0.5 * size));
          break;
        case 1:
          children.emplace_back(sample_shape<ShapeKind::Aabb>(rng, cc, 0.5 * size));
          break;
        case 2:
          children.emplace_back(sample_shape<ShapeKind::Obb>(rng, cc, 0.5 * size));
          break;
        case 3:
          children.emplace_back(sample_shape<ShapeKind::Capsule>(rng, cc, 0.5 * size));
          break;
        default:
          children.emplace_back(sample_shape<ShapeKind::Polygon>(rng, cc, 0.5 * size));
          break;
      }
    }
    return Compound<double>(std::move(children));
  }
}

}  // namespace collide::oracle::testing
