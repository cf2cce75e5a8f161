#pragma once
/// @file shape_traits.hpp
/// Compile-time facts about shape types: the scalar of any shape, the concepts every query is
/// constrained by (a primitive, a concrete shape, a variant, any of them), and the two ways of
/// walking a shape (the concrete shape inside a variant; the primitives of a compound).

#include "collide/compound.hpp"
#include "collide/registry.hpp"
#include "collide/shapes.hpp"

#include <type_traits>
#include <variant>

namespace collide {

/// Shape type -> its scalar (float or double), as `type`; for the six shapes and their variants.
template <class S>
struct ScalarOf;
/// @cond COLLIDE_SPECIALISATIONS
template <Scalar T>
struct ScalarOf<Circle<T>> {
  using type = T;
};
template <Scalar T>
struct ScalarOf<Aabb<T>> {
  using type = T;
};
template <Scalar T>
struct ScalarOf<Obb<T>> {
  using type = T;
};
template <Scalar T>
struct ScalarOf<Capsule<T>> {
  using type = T;
};
template <Scalar T>
struct ScalarOf<ConvexPolygon<T>> {
  using type = T;
};
template <Scalar T>
struct ScalarOf<Compound<T>> {
  using type = T;
};
template <Scalar T, class... Rest>
struct ScalarOf<std::variant<Circle<T>, Rest...>> {
  using type = T;
};
/// @endcond

/// The scalar (float or double) of any shape type.
template <class S>
using scalar_of_t = typename ScalarOf<std::remove_cvref_t<S>>::type;

template <class S>
concept PrimitiveShape = requires {
  typename ScalarOf<S>::type;
}
&&(std::is_same_v<S, Circle<scalar_of_t<S>>> || std::is_same_v<S, Aabb<scalar_of_t<S>>> ||
   std::is_same_v<S, Obb<scalar_of_t<S>>> || std::is_same_v<S, Capsule<scalar_of_t<S>>> ||
   std::is_same_v<S, ConvexPolygon<scalar_of_t<S>>>);

template <class S>
concept ConcreteShape = PrimitiveShape<S> ||
    (requires { typename ScalarOf<S>::type; } && std::is_same_v<S, Compound<scalar_of_t<S>>>);

template <class S>
concept VariantShape = requires {
  typename ScalarOf<S>::type;
}
&&(std::is_same_v<S, Shape<scalar_of_t<S>>> || std::is_same_v<S, Primitive<scalar_of_t<S>>>);

/// Any of the six shapes, Primitive<T> or Shape<T>.
template <class S>
concept AnyShape = ConcreteShape<std::remove_cvref_t<S>> || VariantShape<std::remove_cvref_t<S>>;

namespace detail {

/// Calls f with the concrete shape held by s.
template <class S, class F>
decltype(auto) visit_shape(const S& s, F&& f) {
  if constexpr (VariantShape<S>) {
    return std::visit(f, s);
  } else {
    return f(s);
  }
}

/// Calls f with the concrete shapes held by a and b. Two variants take one dispatch on the pair of
/// kinds rather than one per shape: in a stream of mixed pairs each dispatch is an indirect jump
/// that the branch predictor mostly misses.
template <class A, class B, class F>
decltype(auto) visit_shapes(const A& a, const B& b, F&& f) {
  if constexpr (VariantShape<A> && VariantShape<B>) {
    return std::visit(f, a, b);
  } else {
    return visit_shape(a, [&](const auto& ca) { return visit_shape(b, [&](const auto& cb) { return f(ca, cb); }); });
  }
}

template <class S>
struct IsCompound : std::false_type {};
template <Scalar T>
struct IsCompound<Compound<T>> : std::true_type {};
template <Scalar T>
struct IsCompound<PlacedCompound<T>> : std::true_type {};

/// A compound, local or placed by a body transform.
template <class S>
inline constexpr bool is_compound_v = IsCompound<std::remove_cvref_t<S>>::value;

/// The placement of child i of c under `body`: composed with the child's own transform, if any.
template <Scalar T>
Pose child_pose(const Compound<T>& c, std::size_t i, const Pose& body) {
  return c.has_child_transforms() ? compose(body, c.child_transform(i).pose()) : body;
}

/// Calls f with the image of child i of c under `body` composed with the child's own transform
/// (always an image in double, even of the identity: one set of placed types).
template <Scalar T, class F>
void visit_child(const Compound<T>& c, std::size_t i, const Pose& body, F&& f) {
  const Pose x = child_pose(c, i, body);
  std::visit([&](const auto& p) { with_image(p, x, f); }, c.children()[i]);
}

/// name_stored_features() (detail/image.hpp) for the child of compound c that one side of `contact`
/// names, when it is a polygon imaged under `body` composed with its own transform: a contact's
/// points all come from one child pair.
template <Scalar T, class C>
void name_child_features(const Compound<T>& c, const Pose& body, C& contact, bool side_b) {
  const std::size_t i = side_b ? contact.ids[0].child_b : contact.ids[0].child_a;
  if (const auto* poly = std::get_if<ConvexPolygon<T>>(&c.children()[i]))
    name_stored_features(*poly, child_pose(c, i, body), contact, side_b);
}
/// As above for a shape met in contact_concrete(): a compound visited through its children's
/// images (placed, or with child transforms). Nothing for the others.
template <Scalar T, class C>
void name_child_features(const PlacedCompound<T>& s, C& contact, bool side_b) {
  name_child_features(*s.compound, s.pose, contact, side_b);
}
/// @copydoc name_child_features(const PlacedCompound<T>&, C&, bool)
template <Scalar T, class C>
void name_child_features(const Compound<T>& s, C& contact, bool side_b) {
  if (s.has_child_transforms()) name_child_features(s, Pose{}, contact, side_b);
}
/// @copydoc name_child_features(const PlacedCompound<T>&, C&, bool)
template <class S, class C>
void name_child_features(const S&, C&, bool) noexcept {}

/// Calls f with each primitive of s (s itself, or each child of a compound, placed: a compound
/// with child transforms is visited through its children's images).
template <class S, class F>
void for_each_primitive(const S& s, F&& f) {
  if constexpr (std::is_same_v<S, Compound<scalar_of_t<S>>>) {
    if (!s.has_child_transforms()) {
      for (const auto& child : s.children()) std::visit(f, child);
    } else {
      for (std::size_t i = 0; i < s.children().size(); ++i) visit_child(s, i, Pose{}, f);
    }
  } else {
    f(s);
  }
}
/// @cond COLLIDE_SPECIALISATIONS
template <Scalar T, class F>
void for_each_primitive(const PlacedCompound<T>& s, F&& f) {
  for (std::size_t i = 0; i < s.compound->children().size(); ++i) visit_child(*s.compound, i, s.pose, f);
}
/// @endcond

}  // namespace detail

/// Conservative bounding box of any shape (see compound.hpp for the per-shape overloads).
template <class S>
requires VariantShape<S> Aabb<scalar_of_t<S>> bounds(const S& s) {
  return std::visit([](const auto& x) { return bounds(x); }, s);
}

}  // namespace collide
