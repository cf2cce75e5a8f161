#pragma once
// Shared helpers of the unit tests: the two scalars, and a per-kind shape maker driven by the
// registry so that every per-pair test covers all 21 pairs without a hand-written pair table.

#include <collide/collide.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace collide::test {

using Scalars = ::testing::Types<float, double>;

/// A shape of kind K whose extent along x is exactly [c.x - h, c.x + h], and whose points at
/// x = c.x +- h include (c.x +- h, c.y). Every coordinate is c + (a dyadic multiple of h), so for
/// dyadic c and h every stored value is exact and shapes built h_a + h_b apart touch exactly.
///   circle: radius h. aabb: the square of half side h. obb: the same square, axis (1, 0).
///   capsule: vertical segment of half length h/2, radius h. polygon: the diamond of half
///   diagonal h. compound: a flat AABB [-h, h] x [-h/4, h/4] plus a circle of radius h/2.
template <ShapeKind K, Scalar T>
ShapeOf<K, T> make_kind(const Vec2<T>& c, T h) {
  using V = Vec2<T>;
  if constexpr (K == ShapeKind::Circle) {
    return Circle<T>(c, h);
  } else if constexpr (K == ShapeKind::Aabb) {
    return Aabb<T>(V(c.x() - h, c.y() - h), V(c.x() + h, c.y() + h));
  } else if constexpr (K == ShapeKind::Obb) {
    return Obb<T>::make_with_axis(c, V(h, h), V(1, 0)).value();
  } else if constexpr (K == ShapeKind::Capsule) {
    return Capsule<T>(V(c.x(), c.y() - h / 2), V(c.x(), c.y() + h / 2), h);
  } else if constexpr (K == ShapeKind::Polygon) {
    return ConvexPolygon<T>{V(c.x() + h, c.y()), V(c.x(), c.y() + h), V(c.x() - h, c.y()), V(c.x(), c.y() - h)};
  } else {
    std::vector<Primitive<T>> kids;
    kids.emplace_back(Aabb<T>(V(c.x() - h, c.y() - h / 4), V(c.x() + h, c.y() + h / 4)));
    kids.emplace_back(Circle<T>(c, h / 2));
    return Compound<T>(std::move(kids));
  }
}

/// Kinds decided by exact predicates only (comparisons and orient()).
constexpr bool exact_kind(ShapeKind k) {
  return k == ShapeKind::Aabb || k == ShapeKind::Polygon;
}

template <ShapeKind A, ShapeKind B>
std::string pair_label() {
  return name(KindPair{A, B});
}

}  // namespace collide::test
