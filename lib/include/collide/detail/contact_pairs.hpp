#pragma once
/// @file detail/contact_pairs.hpp
/// The contact of two primitives in registry order, deciding presence exactly on the way: the
/// rounded contact computation runs first, and the exact decision (decide.hpp) is asked only when
/// its signed distance lies within the rounding band of touching. Specialised pairs:
///   - circle-circle: analytically;
///   - circle against a box: the centre's coordinates in the box's frame, clamped;
///   - circle against a polygon: the centre's face excesses, then the face of the largest or a
///     vertex at its end;
///   - circle against a capsule: the centre against the segment;
///   - two boxes or polygons: the separating axis of least penetration over both shapes' face
///     normals (taken from the stored axes for boxes, whose depths have a closed form), then
///     reference-face clipping;
///   - a capsule against a box or polygon: the generic steps below on the same known normals.
/// Every other pair (capsule-capsule, boxes flat on an axis, boxes thinner than
/// their corners' rounding, polygons of more than 8 vertices) runs contact_cores()'s steps on the
/// generic cores, their least penetration or closest points deciding outside the band (a face
/// separating the shapes by more than it ends the search); tiny pairs decide exactly first.
/// With a speculative distance, pairs apart by at most it get a speculative contact.

#include "collide/detail/contact_base.hpp"
#include "collide/detail/contact_circle.hpp"
#include "collide/detail/contact_hulls.hpp"

#include <array>
#include <optional>
#include <type_traits>

namespace collide::detail {

/// Whether two primitives in registry order are apart by a cheap test proven at every scale, with
/// no exact step (false when it cannot tell), as contact_pair() tells them before computing
/// anything: a circle beyond a face of an oriented box (told in float for float shapes); two hulls
/// whose rough boxes are apart.
template <class A, class B>
[[gnu::always_inline]] inline bool apart_by_filter(const A& a, const B& b) noexcept {
  using T = scalar_of_t<A>;
  if constexpr (std::is_same_v<A, Circle<T>> && std::is_same_v<B, Obb<T>>) {
    if constexpr (std::is_same_v<T, float>) {
      return circle_beyond_box_in_float(a, b);
    } else {
      const Rect k = rect_of(b);
      const Vec2c c = widen(a.center());
      const Calc scale = rect_scale(c, a.radius(), k);
      return scale >= kTinyCore && circle_beyond_rect(c, a.radius(), k, Calc(0), scale);
    }
  } else if constexpr (is_hull_kind_v<A> && is_hull_kind_v<B>) {
    return apart_by_boxes(a, b, Calc(0));
  } else {
    return false;
  }
}

/// overlap_pair() for a circle and an oriented box that apart_by_filter() did not find apart: the
/// centre in the box's frame, as contact_circle_rect() takes it, where it is clear of the band
/// (beyond a corner, beside a side, or inside, the gap then its depth behind the nearest side),
/// the exact decision otherwise. Kept out of line, as the contact's steps are, so that the filter
/// before it inlines into the caller.
template <Scalar T>
[[gnu::noinline]] bool circle_obb_past_filter(const Circle<T>& a, const Obb<T>& b) {
  const Vec2c c = widen(a.center());
  const Rect k = rect_of(b);
  const Calc scale = rect_scale(c, a.radius(), k);
  if (scale >= kTinyCore && is_proper(b, k)) {
    const CentreInRect f = centre_in_rect<false>(c, a.radius(), k, scale);
    const Calc gap = f.ex > 0 && f.ey > 0   ? norm_of(offset_to_corner(f)) - f.r
                     : f.ex > 0 || f.ey > 0 ? side_gap(f)
                                            : std::max(f.ex, f.ey) * f.len;
    if (gap < -f.band || gap > f.band) return gap < -f.band;
  }
  return decide::pair(a, b);
}

/// The overlap decision of two primitives in registry order, exact: contact_pair()'s own steps
/// where they decide without the exact decision (apart_by_filter(); a circle's centre against a
/// polygon or an oriented box, clear of the band), decide.hpp otherwise. What overlaps() answers.
template <class A, class B>
bool overlap_pair(const A& a, const B& b) {
  using T = scalar_of_t<A>;
  if constexpr (std::is_same_v<A, Circle<T>> && std::is_same_v<B, ConvexPolygon<T>>) {
    if (PolygonAccess::normals(b)) {
      std::array<Calc, ConvexPolygon<T>::kInline> excesses;
      // The contact's own steps: they decide clear of the band and build one point at most.
      return !circle_beyond_a_face(a, b, Calc(0), excesses.data()) &&
             contact_circle_polygon(a, b, excesses.data(), Calc(0)).has_value();
    }
  } else if constexpr (std::is_same_v<A, Circle<T>> && std::is_same_v<B, Obb<T>>) {
    return !apart_by_filter(a, b) && circle_obb_past_filter(a, b);
  } else if constexpr (std::is_same_v<A, Circle<T>> && std::is_same_v<B, Aabb<T>>) {
    // Float pairs apart are told in float first, as contact() tells them; the decision is a clamp
    // and a filtered distance.
    if constexpr (std::is_same_v<T, float>) {
      if (circle_beyond_box_in_float(a, b)) return false;
    }
    return decide::pair(a, b);
  } else if constexpr (std::is_same_v<A, Aabb<T>> && std::is_same_v<B, Aabb<T>>) {
    return decide::pair(a, b);  // four comparisons
  }
  return !apart_by_filter(a, b) && decide::pair(a, b);
}

/// The contact of two primitives in registry order (a's kind <= b's kind): present exactly when
/// they overlap, or, with speculative > 0, when they are apart by at most speculative (rounded).
/// rounding: how far the shapes' values may lie from the shapes they stand for (empty for stored
/// shapes; for images, image_rounding() of both). An image's points carry the rounding of its
/// stored magnitude and position, which may be far larger than the image's own scale, so two faces
/// equally deep in the exact images may differ in the computed ones by more than the tie of their
/// scale; within that rounding the first core's face stays the reference (feature.hpp,
/// least_penetration_by()), and the depth found is within it of the images' least, inside the
/// transformed contract.
template <class A, class B>
std::optional<CoreContact> contact_pair(const A& a, const B& b, Calc speculative, Rounding rounding = {}) {
  constexpr bool circle_a = std::is_same_v<A, Circle<scalar_of_t<A>>>;
  if constexpr ((circle_a || is_hull_kind_v<A>)&&is_hull_kind_v<B>) {
    if constexpr (circle_a && !std::is_same_v<B, ConvexPolygon<scalar_of_t<A>>>) {
      // Float shapes without a speculative distance are told apart in float, at T's own precision.
      if constexpr (std::is_same_v<scalar_of_t<A>, float>) {
        if (!(speculative > 0)) {
          if (circle_beyond_box_in_float(a, b)) return std::nullopt;
          return contact_circle_rect(a, b, speculative);
        }
      }
      const Rect k = rect_of(b);
      const Vec2c c = widen(a.center());
      const Calc scale = rect_scale(c, a.radius(), k);
      if (scale >= kTinyCore && circle_beyond_rect(c, a.radius(), k, speculative, scale)) return std::nullopt;
      return contact_circle_rect(a, b, speculative);
    } else if constexpr (circle_a) {
      if (PolygonAccess::normals(b)) {
        std::array<Calc, ConvexPolygon<scalar_of_t<A>>::kInline> excesses;
        if (circle_beyond_a_face(a, b, speculative, excesses.data())) return std::nullopt;
        return contact_circle_polygon(a, b, excesses.data(), speculative);
      }
    } else {
      if (apart_by_boxes(a, b, speculative)) return std::nullopt;
      return contact_hulls(a, b, speculative, rounding);
    }
  } else if constexpr (circle_a && is_capsule_v<B>) {
    return contact_circle_capsule(a, b, speculative);
  } else if constexpr ((is_capsule_v<A> && is_hull_kind_v<B>) || (is_hull_kind_v<A> && is_capsule_v<B>)) {
    return contact_capsule_hull(a, b, speculative, rounding);
  }
  return contact_generic(a, b, speculative, rounding);
}

}  // namespace collide::detail
