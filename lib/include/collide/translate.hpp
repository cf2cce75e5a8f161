#pragma once
/// @file translate.hpp
/// translated(): a shape moved by a vector, rebuilt through its factory so that the moved shape
/// satisfies every invariant (or the factory's named error says why it cannot).

#include "collide/compound.hpp"
#include "collide/shape_traits.hpp"
#include "collide/shapes.hpp"

#include <optional>
#include <utility>
#include <variant>
#include <vector>

namespace collide {

/// The shape moved by v: every stored point coordinate plus v, rounded to T. Errors: those of the
/// shape's factory (NonFinite, OutOfRange when the move leaves the representable range).
template <Scalar T>
Expected<Circle<T>> translated(const Circle<T>& s, const Vec2<T>& v) {
  return Circle<T>::make(s.center() + v, s.radius());
}
/// The shape moved by v, rounded to T. Errors: NonFinite, OutOfRange (as its factory names them).
template <Scalar T>
Expected<Aabb<T>> translated(const Aabb<T>& s, const Vec2<T>& v) {
  return Aabb<T>::make(s.min() + v, s.max() + v);
}
/// The box moved by v: its centre plus v rounded to T, its axis and half extents unchanged.
/// Errors: NonFinite, OutOfRange.
template <Scalar T>
Expected<Obb<T>> translated(const Obb<T>& s, const Vec2<T>& v) {
  // Keep the stored axis bit for bit: renormalising would rotate the box by rounding.
  return detail::ObbAccess::with_axis_of<T>(Vec2<T>(s.center() + v), s.half_extents(), s);
}
/// The shape moved by v, rounded to T. Errors: NonFinite, OutOfRange (as its factory names them).
template <Scalar T>
Expected<Capsule<T>> translated(const Capsule<T>& s, const Vec2<T>& v) {
  return Capsule<T>::make(s.a() + v, s.b() + v, s.radius());
}
/// Rounding the moved vertices to T can break exact convexity; the result is then the convex hull
/// of the moved vertices (it can only lose vertices that became reflex or collinear).
template <Scalar T>
Expected<ConvexPolygon<T>> translated(const ConvexPolygon<T>& s, const Vec2<T>& v) {
  detail::SmallList<Vec2<T>, ConvexPolygon<T>::kInline> moved;
  for (const Vec2<T>& p : s.vertices()) moved.push_back(p + v);
  Expected<ConvexPolygon<T>> r = ConvexPolygon<T>::make(moved.span());
  if (r || (r.error().code() != Error::NonConvex && r.error().code() != Error::Collinear &&
            r.error().code() != Error::TooFewVertices)) {
    return r;
  }
  return ConvexPolygon<T>::make_hull(moved.span());
}
/// Every child moved by v (allocates: the compound owns its children): a child placed by the
/// identity has its values moved, any other child its transform's position. Errors: the first
/// child's error, as that child's factory (or Transform::moved) names it.
template <Scalar T>
Expected<Compound<T>> translated(const Compound<T>& s, const Vec2<T>& v) {
  std::vector<typename Compound<T>::Child> moved;
  moved.reserve(s.children().size());
  for (std::size_t i = 0; i < s.children().size(); ++i) {
    const Transform<T> x = s.child_transform(i);
    if (!x.is_identity()) {
      const Expected<Transform<T>> mx = x.moved(v);
      if (!mx) return mx.error();
      moved.push_back({s.children()[i], *mx});
      continue;
    }
    std::optional<ShapeError> err;
    std::visit(
        [&](const auto& c) {
          auto m = translated(c, v);
          if (m) {
            moved.push_back({Primitive<T>(std::move(m).value()), x});
          } else {
            err = m.error();
          }
        },
        s.children()[i]);
    if (err) return *err;
  }
  return Compound<T>::make_placed(std::move(moved));
}
/// A variant translated: same alternative, moved by v. Errors: those of the shape's factory
/// (NonFinite, OutOfRange when the move leaves the representable range; Collinear when rounding
/// collapses a thin polygon).
template <class S>
requires VariantShape<S> Expected<S> translated(const S& s, const Vec2<scalar_of_t<S>>& v) {
  return std::visit(
      [&](const auto& x) -> Expected<S> {
        auto m = translated(x, v);
        if (!m) return m.error();
        return S(std::move(m).value());
      },
      s);
}

}  // namespace collide
