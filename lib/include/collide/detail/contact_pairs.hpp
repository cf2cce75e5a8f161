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

/// Whether two primitives in registry order are apart by more than `speculative` by a cheap test
/// proven at every scale, with no exact step (false when it cannot tell): a float circle beyond a
/// float box's face told in float; a circle beyond a box's face; a circle beyond a face of a
/// polygon with cached normals (which leaves every face's excess in `excesses`, when given, for
/// contact_circle_polygon()); two hulls whose rough boxes are apart. contact_pair() ends on it
/// before computing anything, and overlaps() asks it before the exact decision.
template <class A, class B>
bool apart_by_filter(const A& a, const B& b, Calc speculative, Calc* excesses = nullptr) noexcept {
  using T = scalar_of_t<A>;
  if constexpr (std::is_same_v<A, Circle<T>> && is_hull_kind_v<B> && !std::is_same_v<B, ConvexPolygon<T>>) {
    // Float shapes without a speculative distance are told apart in float, at T's own precision.
    if constexpr (std::is_same_v<T, float>) {
      if (!(speculative > 0)) return circle_beyond_box_in_float(a, b);
    }
    const Rect k = rect_of(b);
    const Vec2c c = widen(a.center());
    const Calc scale = rect_scale(c, a.radius(), k);
    return scale >= kTinyCore && circle_beyond_rect(c, a.radius(), k, speculative, scale);
  } else if constexpr (std::is_same_v<A, Circle<T>> && std::is_same_v<B, ConvexPolygon<T>>) {
    if (!PolygonAccess::normals(b)) return false;
    std::array<Calc, ConvexPolygon<T>::kInline> own;
    return circle_beyond_a_face(a, b, speculative, excesses ? excesses : own.data());
  } else if constexpr (is_hull_kind_v<A> && is_hull_kind_v<B>) {
    return apart_by_boxes(a, b, speculative);
  } else {
    return false;
  }
}

/// overlap_pair() for a circle and a polygon with cached normals, or an oriented box, that
/// apart_by_filter() did not find apart (excesses: the polygon's, as it computed them): the
/// centre's steps of contact_circle_polygon() or contact_circle_rect() where they are clear of the
/// band, the exact decision otherwise. Kept out of line, as the contact's steps are, so that the
/// filter before it inlines into the caller.
template <Scalar T, class B>
[[gnu::noinline]] bool circle_overlaps_past_filter(const Circle<T>& a, const B& b, const Calc* excesses) {
  if constexpr (std::is_same_v<B, ConvexPolygon<T>>) {
    const CentreAgainstPolygon l = centre_against_polygon(a, b, excesses);
    if (!l.generic && (l.gap < -l.band || l.gap > l.band)) return l.gap < -l.band;
  } else {
    // The centre in the box's frame: beyond a corner, beside a side, or inside (the gap is then
    // its depth behind the nearest side).
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
      if (circle_beyond_a_face(a, b, Calc(0), excesses.data())) return false;
      return circle_overlaps_past_filter(a, b, excesses.data());
    }
  } else if constexpr (std::is_same_v<A, Circle<T>> && std::is_same_v<B, Obb<T>>) {
    return !apart_by_filter(a, b, Calc(0)) && circle_overlaps_past_filter(a, b, nullptr);
  }
  return !apart_by_filter(a, b, Calc(0)) && decide::pair(a, b);
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
      if (apart_by_filter(a, b, speculative)) return std::nullopt;
      return contact_circle_rect(a, b, speculative);
    } else if constexpr (circle_a) {
      if (PolygonAccess::normals(b)) {
        std::array<Calc, ConvexPolygon<scalar_of_t<A>>::kInline> excesses;
        if (apart_by_filter(a, b, speculative, excesses.data())) return std::nullopt;
        return contact_circle_polygon(a, b, excesses.data(), speculative);
      }
    } else {
      if (apart_by_filter(a, b, speculative)) return std::nullopt;
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
