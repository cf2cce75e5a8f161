#pragma once
/// @file transform.hpp
/// Exact transforms of stored shapes used by the rotation law and the generators: quarter turns
/// about the origin and mirroring x -> -x (negation and swapping are exact on every value); and
/// the primitives a shape is made of.

#include "collide/collide.hpp"

#include <span>
#include <vector>

namespace collide::laws {

/// The primitives of a shape: a compound's children, or the shape itself.
template <Scalar T>
std::vector<Primitive<T>> primitives_of(const Shape<T>& s) {
  if (const auto* c = std::get_if<Compound<T>>(&s)) return c->children();
  return {std::visit(
      [](const auto& x) -> Primitive<T> {
        using S = std::remove_cvref_t<decltype(x)>;
        if constexpr (std::is_same_v<S, Compound<T>>) {
          return x.children().front();  // unreachable: handled above
        } else {
          return x;
        }
      },
      s)};
}

/// The primitives of a shape, each with its placement in the shape's frame: a compound's children
/// with their child transforms, or the shape itself with the identity. A placed primitive is
/// queried through the transformed overloads (transformed.hpp) and judged by oracle::placed().
template <Scalar T>
std::vector<typename Compound<T>::Child> placed_primitives_of(const Shape<T>& s) {
  std::vector<typename Compound<T>::Child> out;
  if (const auto* c = std::get_if<Compound<T>>(&s)) {
    for (std::size_t i = 0; i < c->children().size(); ++i) out.push_back({c->children()[i], c->child_transform(i)});
    return out;
  }
  for (const Primitive<T>& p : primitives_of(s)) out.push_back({p, Transform<T>()});
  return out;
}

/// Quarter turns (x, y) -> (-y, x), k times, then x -> -x when mirror. Exact.
template <Scalar T>
Vec2<T> turn(const Vec2<T>& p, int quarter_turns, bool mirror) {
  Vec2<T> q = p;
  const int k = ((quarter_turns % 4) + 4) % 4;
  for (int i = 0; i < k; ++i) q = Vec2<T>(-q.y(), q.x());
  if (mirror) q.x() = -q.x();
  return q;
}

/// The shape rotated/mirrored (see laws::rotation); OBBs rebuilt from their axis as input, so that
/// calling this with 0 turns and no mirror gives the canonical form of the same inputs.
/// The primitive turned (see turn()). An OBB is rebuilt through make_with_axis from its stored
/// axis turned, so turned(p, 0, false) is the canonical box of the same inputs.
template <Scalar T>
Primitive<T> turned(const Primitive<T>& p, int k, bool m) {
  return std::visit(
      [&](const auto& s) -> Primitive<T> {
        using S = std::remove_cvref_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Circle<T>>) {
          return Circle<T>(turn(s.center(), k, m), s.radius());
        } else if constexpr (std::is_same_v<S, Aabb<T>>) {
          const Vec2<T> p0 = turn(s.min(), k, m), p1 = turn(s.max(), k, m);
          return Aabb<T>(p0.cwiseMin(p1), p0.cwiseMax(p1));
        } else if constexpr (std::is_same_v<S, Obb<T>>) {
          return Obb<T>::make_with_axis(turn(s.center(), k, m), s.half_extents(), turn(s.axis(), k, m)).value();
        } else if constexpr (std::is_same_v<S, Capsule<T>>) {
          return Capsule<T>(turn(s.a(), k, m), turn(s.b(), k, m), s.radius());
        } else {
          std::vector<Vec2<T>> v;
          for (const Vec2<T>& q : s.vertices()) v.push_back(turn(q, k, m));
          return ConvexPolygon<T>::make(std::span<const Vec2<T>>(v)).value();
        }
      },
      p);
}

/// A child transform turned with its child: x(c) turned is x'(turned c), with x' at the turned
/// position and, under the mirror, the conjugate rotation (quarter turns commute with rotations,
/// a mirror reverses them). Exact: the rotation keeps its length bit for bit.
template <Scalar T>
Transform<T> turned(const Transform<T>& x, int k, bool m) {
  if (x.is_identity()) return x;
  const Vec2<T> q = x.rotation();
  return Transform<T>::make_with_rotation(turn(x.position(), k, m), m ? Vec2<T>(q.x(), -q.y()) : q).value();
}

/// Any shape turned; a compound child by child, each with its child transform.
template <Scalar T>
Shape<T> turned(const Shape<T>& s, int k, bool m) {
  if (const auto* c = std::get_if<Compound<T>>(&s)) {
    std::vector<typename Compound<T>::Child> children;
    for (std::size_t i = 0; i < c->children().size(); ++i)
      children.push_back({turned(c->children()[i], k, m), turned(c->child_transform(i), k, m)});
    return Compound<T>::make_placed(std::move(children)).value();
  }
  return std::visit(
      [&](const auto& x) -> Shape<T> {
        using S = std::remove_cvref_t<decltype(x)>;
        if constexpr (std::is_same_v<S, Compound<T>>) {
          return x;  // handled above
        } else {
          return to_shape(turned(Primitive<T>(x), k, m));
        }
      },
      s);
}

}  // namespace collide::laws
