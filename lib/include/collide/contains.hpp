#pragma once
/// @file contains.hpp
/// Containment: does a closed shape hold a point, or a whole other shape?
///
/// Error contract: exact for every kind. The answer is the exact answer for the stored values
/// and point (the same exact signs as overlaps(), see decide.hpp); contains_tolerance() is 0,
/// except for a compound with child transforms: its children are imaged (transformed.hpp), so
/// points within its placement_tolerance() of a child's boundary may be answered either way.
///
/// contains(outer, inner): inner is a subset of outer, both closed (touching from inside counts).
/// - outer a primitive (every kind but the compound, or a Primitive<T>), inner any shape: exact.
///   outer is convex, so it holds inner exactly when it holds inner's extreme discs (a circle;
///   a capsule's end discs; the corners of a box, OBB or polygon; every child of a compound),
///   each decided by exact signs (detail/contains_shape.hpp). An inner compound with child
///   transforms is judged on its children's images, as contains(s, p) is: exact for those images,
///   so within placement_tolerance(inner) of the exact answer.
/// - outer a compound: refused. A union of children can hold a shape that no child holds alone,
///   and that is not decided: Compound<T> as outer does not compile, and a Shape<T> outer returns
///   Expected<bool> with Error::CompoundOuter when it holds a compound.

#include "collide/detail/contains_point.hpp"
#include "collide/detail/contains_shape.hpp"
#include "collide/error.hpp"
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

/// True when the closed shape inner lies wholly in the closed convex primitive outer (touching
/// from inside counts). Exact for every pair of kinds; an inner compound with child transforms
/// within placement_tolerance(inner) (see the contract at the top of this file).
template <AnyShape O, AnyShape I>
requires(PrimitiveShape<O> || std::is_same_v<O, Primitive<scalar_of_t<O>>>) &&
    std::is_same_v<scalar_of_t<O>, scalar_of_t<I>> bool contains(const O& outer, const I& inner) {
  return detail::visit_shape(outer, [&](const auto& o) {
    return detail::visit_shape(inner, [&](const auto& i) { return detail::primitive_holds(o, i); });
  });
}

/// contains(outer, inner) for a variant outer: the answer for a primitive, Error::CompoundOuter
/// for a compound (containment in a union of children is not decided).
template <Scalar T, AnyShape I>
requires std::is_same_v<T, scalar_of_t<I>> Expected<bool> contains(const Shape<T>& outer, const I& inner) {
  return std::visit(
      [&](const auto& o) -> Expected<bool> {
        if constexpr (detail::is_compound_v<decltype(o)>) {
          return ShapeError(Error::CompoundOuter, -1, "containment in a compound is not decided");
        } else {
          return contains(o, inner);
        }
      },
      outer);
}

/// A compound outer does not compile: a union of children can hold a shape that no child holds
/// alone, and containment in a union is not decided.
template <Scalar T, AnyShape I>
bool contains(const Compound<T>& outer, const I& inner) = delete;

}  // namespace collide
