#pragma once
/// @file compiled.hpp
/// The public queries on Shape<float> and Shape<double>, compiled once into the library
/// collide::compiled rather than in every translation unit that calls them.
///
/// A file that includes this header (it includes collide.hpp) and whose target links
/// collide::compiled sees the queries listed below as explicit instantiation declarations
/// (`extern template`): calling them on Shape<T>, T = float or double, then parses the headers but
/// instantiates and optimises none of their code; the linker takes the copies in the library.
/// Calls on concrete kinds (Circle<T>, ...) and every other template are instantiated in the
/// caller as with collide::collide alone. The answers are the same: one source, compiled with the
/// flags the library was built with (a caller's own flags, such as -ffast-math, do not reach
/// these queries).
///
/// The list is one macro per group, so that the declarations here and the definitions in the
/// library (lib/src/queries.cpp.in) cannot drift apart: `extern` here, nothing there.

#include "collide/collide.hpp"

/// The world-space queries on Shape<T>: overlaps, contact (plain and speculative), distance,
/// closest points, resolve, contains, signed distance and raycast. `EXTERN` is `extern` (a
/// declaration) or empty (a definition).
#define COLLIDE_COMPILED_WORLD_QUERIES(EXTERN, T)                                                             \
  EXTERN template bool overlaps<Shape<T>, Shape<T>>(const Shape<T>&, const Shape<T>&);                        \
  EXTERN template std::optional<Contact<T>> contact<Shape<T>, Shape<T>>(const Shape<T>&, const Shape<T>&);    \
  EXTERN template std::optional<Contact<T>> contact<Shape<T>, Shape<T>>(const Shape<T>&, const Shape<T>&, T); \
  EXTERN template T distance<Shape<T>, Shape<T>>(const Shape<T>&, const Shape<T>&);                           \
  EXTERN template ClosestPoints<T> closest_points<Shape<T>, Shape<T>>(const Shape<T>&, const Shape<T>&);      \
  EXTERN template Vec2<T> resolve<Shape<T>, Shape<T>>(const Shape<T>&, const Shape<T>&);                      \
  EXTERN template bool contains<Shape<T>>(const Shape<T>&, const Vec2<T>&);                                   \
  EXTERN template T signed_distance<Shape<T>>(const Shape<T>&, const Vec2<T>&);                               \
  EXTERN template std::optional<RayHit<T>> raycast<Shape<T>>(const Shape<T>&, const Ray<T>&, T);

/// The same queries on shapes placed by transforms (transformed.hpp), and bounds(s, x).
#define COLLIDE_COMPILED_PLACED_QUERIES(EXTERN, T)                                                                    \
  EXTERN template bool overlaps<Shape<T>, Shape<T>>(const Shape<T>&, const Transform<T>&, const Shape<T>&,            \
                                                    const Transform<T>&);                                             \
  EXTERN template std::optional<Contact<T>> contact<Shape<T>, Shape<T>>(const Shape<T>&, const Transform<T>&,         \
                                                                        const Shape<T>&, const Transform<T>&);        \
  EXTERN template std::optional<Contact<T>> contact<Shape<T>, Shape<T>, T>(                                           \
      const Shape<T>&, const Transform<T>&, const Shape<T>&, const Transform<T>&, const T&);                          \
  EXTERN template T distance<Shape<T>, Shape<T>>(const Shape<T>&, const Transform<T>&, const Shape<T>&,               \
                                                 const Transform<T>&);                                                \
  EXTERN template Vec2<T> resolve<Shape<T>, Shape<T>>(const Shape<T>&, const Transform<T>&, const Shape<T>&,          \
                                                      const Transform<T>&);                                           \
  EXTERN template ClosestPoints<T> closest_points<Shape<T>, Shape<T>>(const Shape<T>&, const Transform<T>&,           \
                                                                      const Shape<T>&, const Transform<T>&);          \
  EXTERN template bool contains<Shape<T>>(const Shape<T>&, const Transform<T>&, const Vec2<T>&);                      \
  EXTERN template T signed_distance<Shape<T>>(const Shape<T>&, const Transform<T>&, const Vec2<T>&);                  \
  EXTERN template std::optional<RayHit<T>> raycast<Shape<T>>(const Shape<T>&, const Transform<T>&, const Ray<T>&, T); \
  EXTERN template Aabb<T> bounds<Shape<T>>(const Shape<T>&, const Transform<T>&);

/// The queries on moving shapes: shape_cast (world and placed) and time_of_impact.
#define COLLIDE_COMPILED_MOVING_QUERIES(EXTERN, T)                                                                    \
  EXTERN template CastResult<T> shape_cast<Shape<T>, Shape<T>>(const Shape<T>&, const Vec2<T>&, const Shape<T>&,      \
                                                               const Vec2<T>&, T, const CastOptions&);                \
  EXTERN template CastResult<T> shape_cast<Shape<T>, Shape<T>>(const Shape<T>&, const Transform<T>&, const Vec2<T>&,  \
                                                               const Shape<T>&, const Transform<T>&, const Vec2<T>&,  \
                                                               T, const CastOptions&);                                \
  EXTERN template CastResult<T> time_of_impact<Shape<T>, Shape<T>>(const Shape<T>&, const Sweep<T>&, const Shape<T>&, \
                                                                   const Sweep<T>&, T);

namespace collide {

COLLIDE_COMPILED_WORLD_QUERIES(extern, float)
COLLIDE_COMPILED_WORLD_QUERIES(extern, double)
COLLIDE_COMPILED_PLACED_QUERIES(extern, float)
COLLIDE_COMPILED_PLACED_QUERIES(extern, double)
COLLIDE_COMPILED_MOVING_QUERIES(extern, float)
COLLIDE_COMPILED_MOVING_QUERIES(extern, double)

}  // namespace collide
