#pragma once
/// @file detail/placement.hpp
/// Shapes and compounds posed by transforms, as the transformed queries see them: a concrete
/// shape's image (a compound placed, never copied), its box, how far it may round, and the
/// renaming of a re-hulled image's features back to the stored numbering.

#include "collide/compound.hpp"
#include "collide/detail/image.hpp"
#include "collide/shape_traits.hpp"
#include "collide/tolerances.hpp"
#include "collide/transform.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace collide {

namespace detail {

/// The local magnitude L of transform_tolerance().
template <class S>
Calc local_extent(const S& s) {
  if constexpr (is_compound_v<S>) {
    return s.local_extent();
  } else {
    return scale_of(bounds(s));
  }
}

/// Calls f with the concrete shape s placed by x, always in double: a primitive's image (exact for
/// the identity), or a compound seen through its placement. Imaging even the identity keeps one
/// set of placed types (the five primitives in double and the placed compound) whatever the
/// kinds, so a transformed query instantiates what a world-space query in double does; the
/// queries take the world-space path when both transforms are identities.
template <class S, Scalar T, class F>
decltype(auto) with_placed(const S& s, const Transform<T>& x, F&& f) {
  if constexpr (is_compound_v<S>) {
    return f(placed(s, x.pose()));
  } else {
    return with_image(s, x.pose(), f);
  }
}

/// name_stored_features() for a concrete shape s placed by x as `image`: only a polygon imaged as a
/// hull (fewer vertices: a vertex whose mapped turn is not left is not one of the hull's) or as a
/// segment numbers its features its own way. A compound's children are renamed where their contact
/// is found.
template <class S, class Image, Scalar T, class C>
void name_placed_features(const S& s, const Image& image, const Transform<T>& x, C& c, bool side_b) {
  if constexpr (std::is_same_v<S, ConvexPolygon<T>>) {
    if constexpr (std::is_same_v<Image, ConvexPolygon<Calc>>) {
      if (image.size() == s.size()) [[likely]]
        return;
    }
    name_stored_features(s, x.pose(), c, side_b);
  }
}

/// The box of s's computed image under x, before any padding (a compound's: its placed box).
template <class S, Scalar T>
Aabb<Calc> placed_box(const S& s, const Transform<T>& x) {
  if constexpr (is_compound_v<S>) {
    return calc_bounds(placed(s, x.pose()));
  } else {
    return image_box(s, x.pose());
  }
}

/// transform_tolerance() of a concrete shape under x, not the identity.
template <class S, Scalar T>
Calc image_tolerance_of(const S& s, const Transform<T>& x) {
  return image_tolerance(x.pose(), local_extent(s));
}

/// At least local_extent(s), from the stored values alone (their magnitudes plus the radius or
/// half extents; a polygon's cached largest coordinate): the bounding box's outward rounding costs
/// more than a contact's tie needs.
template <class S>
Calc rough_extent(const S& s) noexcept {
  using T = scalar_of_t<S>;
  if constexpr (is_compound_v<S>) {
    return s.local_extent();
  } else if constexpr (std::is_same_v<S, Circle<T>>) {
    return widen(s.center()).cwiseAbs().maxCoeff() + Calc(s.radius());
  } else if constexpr (std::is_same_v<S, Aabb<T>>) {
    return std::max(widen(s.min()).cwiseAbs().maxCoeff(), widen(s.max()).cwiseAbs().maxCoeff());
  } else if constexpr (std::is_same_v<S, Obb<T>>) {
    return widen(s.center()).cwiseAbs().maxCoeff() + Calc(s.half_extents().x()) + Calc(s.half_extents().y());
  } else if constexpr (std::is_same_v<S, Capsule<T>>) {
    return std::max(widen(s.a()).cwiseAbs().maxCoeff(), widen(s.b()).cwiseAbs().maxCoeff()) + Calc(s.radius());
  } else {
    return PolygonAccess::largest_coordinate(s);
  }
}

/// Whether a concrete shape may have faces (every kind but the circle; a compound's children may):
/// only a pair of such shapes can tie two faces for the reference (contact_pair()'s rounding).
template <class S>
constexpr bool has_faces(const S&) noexcept {
  return !std::is_same_v<S, Circle<float>> && !std::is_same_v<S, Circle<double>>;
}

/// Whether the image of the concrete shape s under x may round at a magnitude beyond the image's
/// own: under a turn the products R(q) v round at |v|, and a compound's children are images of
/// their child transforms. Under a translation each image point v + p rounds once, well within the
/// tie of the image's own scale.
template <class S, Scalar T>
bool rounds_beyond_image(const S& s, const Transform<T>& x) noexcept {
  if constexpr (is_compound_v<S>) {
    if (s.has_child_transforms()) return true;
  }
  return x.rotation() != Vec2<T>(T(1), T(0));
}

/// How far the computed image of the concrete shape s under x may lie from the exact image, as
/// transform_tolerance() bounds it but from rough_extent() (and not 0 for the identity):
/// contact_pair()'s rounding.
template <class S, Scalar T>
Calc image_rounding(const S& s, const Transform<T>& x) noexcept {
  return image_tolerance(x.pose(), rough_extent(s));
}

/// Calls f(a placed, b placed) for two concrete shapes.
template <class A, class B, Scalar T, class F>
decltype(auto) with_placed_both(const A& a, const Transform<T>& xa, const B& b, const Transform<T>& xb, F&& f) {
  return with_placed(a, xa,
                     [&](const auto& pa) { return with_placed(b, xb, [&](const auto& pb) { return f(pa, pb); }); });
}

/// Calls f(a placed, b placed) for any two shapes (variants visited first).
template <class A, class B, Scalar T, class F>
decltype(auto) with_placed_pair(const A& a, const Transform<T>& xa, const B& b, const Transform<T>& xb, F&& f) {
  return visit_shapes(a, b, [&](const auto& ca, const auto& cb) { return with_placed_both(ca, xa, cb, xb, f); });
}

}  // namespace detail

}  // namespace collide
