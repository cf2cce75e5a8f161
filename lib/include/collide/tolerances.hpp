#pragma once
/// @file tolerances.hpp
/// The error bounds of the pair queries (overlaps, contact, resolve, distance, contains, raycast),
/// and the conservative double box they start from.
///
/// Every function accepts any shape type: the six concrete shapes, Primitive<T> or Shape<T>, in
/// either order, with one scalar. Concrete types dispatch at compile time; variants dispatch by
/// std::visit (no virtual call). Reversed argument orders call the same decision, so
/// overlaps(a, b) == overlaps(b, a) holds to the bit.
///
/// Error contract (the one definition; README and the oracle properties refer to it):
/// - S(a, b) = the largest absolute coordinate of bounds(a) and bounds(b).
/// - overlaps(a, b) is exact for every pair and both scalars: it equals the exact answer for the
///   stored values, touching included (decide.hpp); overlap_tolerance(a, b) = 0 (except for
///   compounds with child transforms, below).
/// - rounding_tolerance(a, b) = 64 * 2^-53 * S + 2^-500 is the error unit of the rounded outputs
///   (contact depth, normal and points, distance, resolution margin).
/// - contact(a, b) exists exactly when overlaps(a, b) is true.
/// - Tiny shapes (every value below 2^-400) have their rounded outputs computed on exactly
///   rescaled cores, so those are relative-accurate; the 2^-500 floor is a bound.
/// - contains() is exact for every kind (contains.hpp); raycast() states its bound in raycast.hpp.
/// - signed_distance(s, p) (distance.hpp) has the sign of contains(s, p) and is within
///   signed_distance_tolerance(s, p) of the exact signed distance; closest_points(a, b) has
///   distance()'s distance and its points within closest_points_tolerance(a, b) of their shapes.
/// - Shapes placed by transforms (transformed.hpp, every query with a Transform per shape): the
///   exact shape is the exact image of the stored values; the identity computes nothing and
///   gives these answers. Otherwise the image is rounded in double within transform_tolerance(s,
///   x) = 16 * 2^-53 * (|position|_inf + 2 L) + 2^-1070 (L the local magnitude; 0 for the
///   identity), exact for exact translations and quarter turns: overlaps() is exact outside a
///   band of the two transform_tolerance()s, and rounded outputs add them to their bound. A
///   compound whose children carry transforms is placed the same way in world space
///   (placement_tolerance(), included in overlap_tolerance() and rounding_tolerance()).

#include "collide/compound.hpp"
#include "collide/shape_traits.hpp"
#include "collide/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide {

namespace detail {

/// A shape's conservative box with double values (exact for a float box).
template <class S>
Aabb<Calc> calc_bounds(const S& s) {
  const auto b = bounds(s);
  return ShapeAccess::aabb<Calc>(widen(b.min()), widen(b.max()));
}

/// signed_distance_tolerance() without the placement term, for a shape with this bounding box.
template <Scalar T>
Calc point_distance_tolerance(const Aabb<T>& box, const Vec2<T>& p) {
  const Calc m = std::max(scale_of(box), widen(p).cwiseAbs().maxCoeff());
  return (kOverlapErrorFactor * kUnitRoundoff + 4 * Calc(std::numeric_limits<T>::epsilon())) * m + kAbsoluteFloor +
         Calc(std::numeric_limits<T>::denorm_min());
}

/// closest_points_tolerance() for the error unit `unit` of a pair whose boxes reach magnitude s:
/// 4 units (distance()'s bound) plus the rounding of two points to T.
template <Scalar T>
Calc witness_tolerance(Calc unit, Calc s) {
  return 4 * unit + 2 * Calc(std::numeric_limits<T>::epsilon()) * s + 2 * Calc(std::numeric_limits<T>::denorm_min());
}

}  // namespace detail

/// The error bound of the placement of s in the world (see the contract at the top of this file):
/// 0 for a stored shape and for a compound whose children are all placed by the identity;
/// transform_tolerance(c, identity) for a compound with child transforms.
template <AnyShape S>
Calc placement_tolerance(const S& s) noexcept {
  return detail::visit_shape(s, [](const auto& x) -> Calc {
    if constexpr (detail::is_compound_v<decltype(x)>) {
      return x.has_child_transforms() ? detail::image_tolerance(detail::Pose{}, x.local_extent()) : 0;
    } else {
      return 0;
    }
  });
}

/// The error unit of this pair's rounded outputs (contact depth, normal and points, distance,
/// resolution margin): 64 * 2^-53 * S + 2^-500, where S is the largest absolute coordinate of
/// either bounding box, plus the placement tolerance of compounds with child transforms. Each
/// query states its bound as a multiple of it.
template <AnyShape A, AnyShape B>
Calc rounding_tolerance(const A& a, const B& b) {
  const Calc s = std::max(detail::scale_of(bounds(a)), detail::scale_of(bounds(b)));
  return kOverlapErrorFactor * kUnitRoundoff * s + kAbsoluteFloor + placement_tolerance(a) + placement_tolerance(b);
}

/// The error bound of closest_points(a, b): each witness point lies within it of its shape, and
/// the distance between the two points within it of the distance returned. 4 rounding_tolerance(a,
/// b) + 2 eps_T S + 2 denorm_min_T (S as in rounding_tolerance(): the points' rounding to T).
template <AnyShape A, AnyShape B>
Calc closest_points_tolerance(const A& a, const B& b) {
  const Calc s = std::max(detail::scale_of(bounds(a)), detail::scale_of(bounds(b)));
  return detail::witness_tolerance<scalar_of_t<A>>(rounding_tolerance(a, b), s);
}

/// The error bound of signed_distance(s, p): (64 * 2^-53 + 4 eps_T) * max(S, |p|_inf) + 2^-500 +
/// denorm_min_T, S the largest absolute coordinate of bounds(s), plus placement_tolerance(s) for a
/// compound with child transforms. The answer is within it of the exact signed distance (for a
/// finite p whose distance T can hold).
template <AnyShape S>
Calc signed_distance_tolerance(const S& s, const Vec2<scalar_of_t<S>>& p) {
  return detail::point_distance_tolerance(bounds(s), p) + placement_tolerance(s);
}

/// The error bound of overlaps() for this pair: the width of the band of exact signed distance
/// around touching inside which an answer may differ from the exact one. 0 for stored shapes,
/// every pair being decided exactly; the placement tolerance of a compound with child transforms.
template <AnyShape A, AnyShape B>
Calc overlap_tolerance(const A& a, const B& b) noexcept {
  return placement_tolerance(a) + placement_tolerance(b);
}

}  // namespace collide
