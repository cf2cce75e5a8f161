#pragma once
/// @file distance.hpp
/// The gap between two shapes. Error contract: tolerances.hpp.

#include "collide/detail/convex_core.hpp"
#include "collide/overlaps.hpp"
#include "collide/shape_traits.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>

namespace collide {

namespace detail {

/// distance() in T, for concrete shapes stored or placed.
template <Scalar T, class A, class B>
T distance_as(const A& ca, const B& cb) {
  if (overlaps_concrete(ca, cb)) return T(0);
  Calc best = std::numeric_limits<Calc>::infinity();
  for_each_primitive(ca, [&](const auto& pa) {
    for_each_primitive(cb, [&](const auto& pb) { best = std::min(best, core_gap(core_of(pa), core_of(pb))); });
  });
  // Separated (decided exactly): a gap that rounds to zero is reported as the least positive T.
  const T gap = static_cast<T>(std::max(Calc(0), best));
  return gap > T(0) ? gap : std::numeric_limits<T>::denorm_min();
}

}  // namespace detail

/// Euclidean distance between the closed shapes: 0 exactly when they overlap, otherwise the gap,
/// at least the smallest positive T (a separated pair whose gap rounds to 0 is not reported as
/// touching). Error: a rounded result, within a few rounding_tolerance(a, b) of the exact gap.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> scalar_of_t<A> distance(const A& a, const B& b) {
  using T = scalar_of_t<A>;
  return detail::visit_shapes(a, b, [](const auto& ca, const auto& cb) { return detail::distance_as<T>(ca, cb); });
}

}  // namespace collide
