#pragma once
/// @file ray.hpp
/// A ray and where it meets a shape: the types raycast() and the broadphase structures share.

#include "collide/config.hpp"

namespace collide {

/// A ray: origin + t * direction, t >= 0. direction need not be normalised.
template <Scalar T>
struct Ray {
  Vec2<T> origin;     ///< where the ray starts (t = 0)
  Vec2<T> direction;  ///< the ray's step per unit of t; any length, (0, 0) only tests the origin
};

/// Where a ray first meets a shape.
template <Scalar T>
struct RayHit {
  T t;             ///< ray parameter, in units of |direction|; 0 <= t <= max_t
  Vec2<T> point;   ///< origin + t * direction (rounded)
  Vec2<T> normal;  ///< unit outward normal of the shape at point; -direction/|direction| when t = 0
};

}  // namespace collide
