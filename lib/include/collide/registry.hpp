#pragma once
/// @file registry.hpp
/// The one registry of shape kinds and pairs. The library's dispatch, the oracle, the property
/// generators and the fuzz decoders all iterate these lists; none keeps its own pair table.
///
/// Adding a shape kind: add it to ShapeKind, kKinds, kind names, KindTraits, KindOf and the Shape
/// variant (in kind order; the static_asserts below stop the build when these disagree), and give
/// it a codec (oracles/laws codec.hpp); every consumer that misses the new kind then fails to
/// compile. README.md, "Adding a kind or a law", lists the rest file by file.

#include "collide/compound.hpp"
#include "collide/shapes.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace collide {

/// Shape kinds, in the order of the Shape variant's alternatives.
enum class ShapeKind : std::uint8_t { Circle, Aabb, Obb, Capsule, Polygon, Compound };

/// Number of shape kinds.
inline constexpr std::size_t kKindCount = 6;
/// Every kind, in ShapeKind order.
inline constexpr std::array<ShapeKind, kKindCount> kKinds = {
    ShapeKind::Circle, ShapeKind::Aabb, ShapeKind::Obb, ShapeKind::Capsule, ShapeKind::Polygon, ShapeKind::Compound};

/// Lower-case name used in reports, case files and command lines: circle, aabb, obb, capsule,
/// polygon, compound.
constexpr std::string_view name(ShapeKind k) noexcept {
  constexpr std::array<std::string_view, kKindCount> names = {"circle",  "aabb",    "obb",
                                                              "capsule", "polygon", "compound"};
  return names[static_cast<std::size_t>(k)];
}

/// The kind named `s` (as name(ShapeKind) spells it), or nullopt.
constexpr std::optional<ShapeKind> kind_from_name(std::string_view s) noexcept {
  for (ShapeKind k : kKinds) {
    if (name(k) == s) return k;
  }
  return std::nullopt;
}

/// An unordered pair of kinds, stored with first <= second.
struct KindPair {
  ShapeKind first;   ///< the kind that comes first in ShapeKind order
  ShapeKind second;  ///< the other kind (equal to first for a pair of one kind)
  /// Same kinds in the same slots.
  friend constexpr bool operator==(const KindPair&, const KindPair&) = default;
};

/// Number of unordered pairs of kinds (21).
inline constexpr std::size_t kPairCount = kKindCount * (kKindCount + 1) / 2;

/// All 21 unordered pairs, in row order: (circle, circle), (circle, aabb), ..., (compound, compound).
inline constexpr std::array<KindPair, kPairCount> kPairs = [] {
  std::array<KindPair, kPairCount> out{};
  std::size_t n = 0;
  for (std::size_t i = 0; i < kKindCount; ++i) {
    for (std::size_t j = i; j < kKindCount; ++j) out[n++] = {kKinds[i], kKinds[j]};
  }
  return out;
}();

/// "circle_aabb" style name of a pair (first kind, underscore, second kind).
inline std::string name(KindPair p) {
  return std::string(name(p.first)) + "_" + std::string(name(p.second));
}

/// Position of a pair in kPairs.
constexpr std::size_t pair_index(KindPair p) noexcept {
  for (std::size_t i = 0; i < kPairCount; ++i) {
    if (kPairs[i] == p) return i;
  }
  return kPairCount;
}

/// The unordered pair of a and b, stored in ShapeKind order.
constexpr KindPair make_pair(ShapeKind a, ShapeKind b) noexcept {
  return static_cast<int>(a) <= static_cast<int>(b) ? KindPair{a, b} : KindPair{b, a};
}

/// Kind -> shape type, as `type`.
template <ShapeKind K, Scalar T>
struct KindTraits;
/// @cond COLLIDE_SPECIALISATIONS
template <Scalar T>
struct KindTraits<ShapeKind::Circle, T> {
  using type = Circle<T>;
};
template <Scalar T>
struct KindTraits<ShapeKind::Aabb, T> {
  using type = Aabb<T>;
};
template <Scalar T>
struct KindTraits<ShapeKind::Obb, T> {
  using type = Obb<T>;
};
template <Scalar T>
struct KindTraits<ShapeKind::Capsule, T> {
  using type = Capsule<T>;
};
template <Scalar T>
struct KindTraits<ShapeKind::Polygon, T> {
  using type = ConvexPolygon<T>;
};
template <Scalar T>
struct KindTraits<ShapeKind::Compound, T> {
  using type = Compound<T>;
};
/// @endcond

/// The shape type of kind K with scalar T, e.g. ShapeOf<ShapeKind::Circle, float> = Circle<float>.
template <ShapeKind K, Scalar T>
using ShapeOf = typename KindTraits<K, T>::type;

/// Any shape. The alternative index equals the ShapeKind.
template <Scalar T>
using Shape = std::variant<Circle<T>, Aabb<T>, Obb<T>, Capsule<T>, ConvexPolygon<T>, Compound<T>>;

/// Shape type -> kind, as `value`.
template <class S>
struct KindOf;
/// @cond COLLIDE_SPECIALISATIONS
template <Scalar T>
struct KindOf<Circle<T>> {
  static constexpr ShapeKind value = ShapeKind::Circle;
};
template <Scalar T>
struct KindOf<Aabb<T>> {
  static constexpr ShapeKind value = ShapeKind::Aabb;
};
template <Scalar T>
struct KindOf<Obb<T>> {
  static constexpr ShapeKind value = ShapeKind::Obb;
};
template <Scalar T>
struct KindOf<Capsule<T>> {
  static constexpr ShapeKind value = ShapeKind::Capsule;
};
template <Scalar T>
struct KindOf<ConvexPolygon<T>> {
  static constexpr ShapeKind value = ShapeKind::Polygon;
};
template <Scalar T>
struct KindOf<Compound<T>> {
  static constexpr ShapeKind value = ShapeKind::Compound;
};
/// @endcond

/// The kind of shape type S.
template <class S>
inline constexpr ShapeKind kind_of_v = KindOf<S>::value;

/// The kind of the shape a variant holds.
template <Scalar T>
constexpr ShapeKind kind(const Shape<T>& s) noexcept {
  return static_cast<ShapeKind>(s.index());
}
/// The kind of the primitive a variant holds.
template <Scalar T>
constexpr ShapeKind kind(const Primitive<T>& s) noexcept {
  return static_cast<ShapeKind>(s.index());
}

/// @cond COLLIDE_REGISTRY_CHECKS
namespace detail {
/// Whether kKinds lists every ShapeKind once in enum order and variant V's alternative I is the
/// shape type of kind I, for every alternative, with scalar T.
template <class V, Scalar T>
consteval bool alternatives_follow_kinds() {
  return []<std::size_t... I>(std::index_sequence<I...>) {
    return ((static_cast<std::size_t>(kKinds[I]) == I) && ...) &&
           (std::is_same_v<std::variant_alternative_t<I, V>, ShapeOf<kKinds[I], T>> && ...) &&
           ((kind_of_v<std::variant_alternative_t<I, V>> == kKinds[I]) && ...);
  }
  (std::make_index_sequence<std::variant_size_v<V>>{});
}
}  // namespace detail
/// @endcond

// The registry and the variants agree: one alternative per kind, in ShapeKind order, and the
// primitives are every kind but the compound, which comes last.
static_assert(std::variant_size_v<Shape<float>> == kKindCount, "Shape needs one alternative per kind");
static_assert(std::variant_size_v<Primitive<float>> + 1 == kKindCount && kKinds.back() == ShapeKind::Compound,
              "Primitive is every kind but the compound, which is the last kind");
static_assert(detail::alternatives_follow_kinds<Shape<float>, float>() &&
                  detail::alternatives_follow_kinds<Shape<double>, double>(),
              "Shape's alternatives must follow ShapeKind order (kKinds, KindTraits, KindOf)");
static_assert(detail::alternatives_follow_kinds<Primitive<float>, float>() &&
                  detail::alternatives_follow_kinds<Primitive<double>, double>(),
              "Primitive's alternatives must follow ShapeKind order");
static_assert(name(kKinds.back()) == "compound" && kind_from_name("circle") == ShapeKind::Circle,
              "kind names follow ShapeKind order");

/// Calls `f.template operator()<K>()` for every kind, in order.
template <class F>
constexpr void for_each_kind(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f.template operator()<kKinds[I]>(), ...);
  }
  (std::make_index_sequence<kKindCount>{});
}

/// Calls `f.template operator()<A, B>()` for every unordered pair (A <= B), in kPairs order.
template <class F>
constexpr void for_each_pair(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f.template operator()<kPairs[I].first, kPairs[I].second>(), ...);
  }
  (std::make_index_sequence<kPairCount>{});
}

/// Calls `f.template operator()<K>()` for the kind known only at run time; returns its result.
template <class F>
constexpr decltype(auto) visit_kind(ShapeKind k, F&& f) {
  switch (k) {
    case ShapeKind::Circle:
      return f.template operator()<ShapeKind::Circle>();
    case ShapeKind::Aabb:
      return f.template operator()<ShapeKind::Aabb>();
    case ShapeKind::Obb:
      return f.template operator()<ShapeKind::Obb>();
    case ShapeKind::Capsule:
      return f.template operator()<ShapeKind::Capsule>();
    case ShapeKind::Polygon:
      return f.template operator()<ShapeKind::Polygon>();
    case ShapeKind::Compound:
      break;
  }
  return f.template operator()<ShapeKind::Compound>();
}

/// Upcast a primitive to a Shape.
template <Scalar T>
Shape<T> to_shape(const Primitive<T>& p) {
  return std::visit([](const auto& s) { return Shape<T>(s); }, p);
}

}  // namespace collide

namespace collide {

/// The same shape with double storage. Exact: every float converts to double without rounding,
/// so the widened shape is the same point set (the oracle judges float shapes through this).
inline Circle<double> widened(const Circle<float>& s) {
  return Circle<double>(s.center().cast<double>(), s.radius());
}
/// The same shape with double storage (exact: the same point set).
inline Aabb<double> widened(const Aabb<float>& s) {
  return Aabb<double>(s.min().cast<double>(), s.max().cast<double>());
}
/// The same shape with double storage (exact: the same point set).
inline Obb<double> widened(const Obb<float>& s) {
  return detail::ObbAccess::with_axis_of<double>(s.center().cast<double>(), s.half_extents().cast<double>(), s).value();
}
/// The same shape with double storage (exact: the same point set).
inline Capsule<double> widened(const Capsule<float>& s) {
  return Capsule<double>(s.a().cast<double>(), s.b().cast<double>(), s.radius());
}
/// The same shape with double storage (exact: the same point set).
inline ConvexPolygon<double> widened(const ConvexPolygon<float>& s) {
  std::vector<Vec2<double>> v;
  for (const Vec2<float>& p : s.vertices()) v.push_back(p.cast<double>());
  return ConvexPolygon<double>(std::span<const Vec2<double>>(v));
}
/// The same shape with double storage (exact: the same point set).
inline Compound<double> widened(const Compound<float>& s) {
  std::vector<Compound<double>::Child> c;
  for (std::size_t i = 0; i < s.children().size(); ++i) {
    std::visit([&](const auto& x) { c.push_back({widened(x), s.child_transform(i).widened()}); }, s.children()[i]);
  }
  return Compound<double>::make_placed(std::move(c)).value();
}
/// The same shape with double storage (exact: the same point set).
inline Shape<double> widened(const Shape<float>& s) {
  return std::visit([](const auto& x) { return Shape<double>(widened(x)); }, s);
}
/// Identity for double shapes, so generic code can widen any shape.
template <class S>
requires std::is_same_v<S, Shape<double>>
const S& widened(const S& s) {
  return s;
}

}  // namespace collide
