#pragma once
/// @file contains.hpp
/// Point containment: does a closed shape hold a point?
///
/// Error contract: exact for every kind. The answer is the exact answer for the stored values
/// and point (the same exact signs as overlaps(), see decide.hpp); contains_tolerance() is 0,
/// except for a compound with child transforms: its children are imaged (transformed.hpp), so
/// points within its placement_tolerance() of a child's boundary may be answered either way.

#include "collide/detail/contains_point.hpp"
#include "collide/shape_traits.hpp"
#include "collide/tolerances.hpp"

#include <cmath>

namespace collide {

/// True when p lies in the closed shape (boundary included). p may be any value: NaN gives false
/// (comparisons with NaN fail), infinities give false for every bounded shape.
/// Error: exact for every kind; within contains_tolerance() for a compound with child transforms.
template <AnyShape S>
bool contains(const S& s, const Vec2<scalar_of_t<S>>& p) {
  const Vec2c q = widen(p);
  if (!std::isfinite(q.x()) || !std::isfinite(q.y())) return false;
  return detail::visit_shape(s, [&](const auto& x) { return detail::contains_concrete(x, q); });
}

/// The error bound of contains(s, p): the distance from the boundary within which the answer
/// may differ from the exact one. 0 for stored shapes, every kind being decided exactly;
/// placement_tolerance(s) for a compound with child transforms (its children's images round).
template <AnyShape S>
Calc contains_tolerance(const S& s, const Vec2<scalar_of_t<S>>&) noexcept {
  return placement_tolerance(s);
}

}  // namespace collide
