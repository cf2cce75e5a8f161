#pragma once
/// @file overlaps.hpp
/// The overlap decision for any two shapes: exact for every pair (decide.hpp), compounds walked
/// child by child behind their cached boxes. A pair that contact()'s own steps decide clear of
/// rounding (detail::overlap_pair) is answered without the exact decision, so that overlaps()
/// costs no more than contact(). Error contract: tolerances.hpp.

#include "collide/compound.hpp"
#include "collide/decide.hpp"
#include "collide/detail/contact_pairs.hpp"
#include "collide/registry.hpp"
#include "collide/shape_traits.hpp"
#include "collide/shapes.hpp"
#include "collide/tolerances.hpp"

#include <type_traits>

namespace collide {

namespace detail {

/// The pair decision for two primitives in either order. A stored float shape met by a double
/// image (a transformed query) is widened first, exactly.
template <PrimitiveShape A, PrimitiveShape B>
bool decide_primitives(const A& a, const B& b) {
  if constexpr (!std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>) {
    if constexpr (std::is_same_v<scalar_of_t<A>, float>) {
      return decide_primitives(widened_shape(a), b);
    } else {
      return decide_primitives(a, widened_shape(b));
    }
  } else if constexpr (static_cast<int>(kind_of_v<A>) <= static_cast<int>(kind_of_v<B>)) {
    return overlap_pair(a, b);
  } else {
    return decide_primitives(b, a);
  }
}

/// The overlap decision for concrete shapes, stored or placed (images, placed compounds).
template <class A, class B>
bool overlaps_concrete(const A& a, const B& b) {
  if constexpr (is_compound_v<A> || is_compound_v<B>) {
    // A hierarchy: the cheap bounding boxes first, then the children.
    if (!decide::aabb_aabb(calc_bounds(a), calc_bounds(b))) return false;
    bool hit = false;
    for_each_primitive(a, [&](const auto& ca) {
      if (hit) return;
      for_each_primitive(b, [&](const auto& cb) { hit = hit || decide_primitives(ca, cb); });
    });
    return hit;
  } else {
    return decide_primitives(a, b);
  }
}

}  // namespace detail

/// True when the closed shapes share at least one point (touching counts).
/// Error: exact for every pair (see the contract at the top of this file).
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>
bool overlaps(const A& a, const B& b) {
  return detail::visit_shapes(a, b, [](const auto& ca, const auto& cb) { return detail::overlaps_concrete(ca, cb); });
}

}  // namespace collide
