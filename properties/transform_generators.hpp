#pragma once
/// @file transform_generators.hpp
/// RapidCheck generators of transforms, shared by the transform laws and the cast laws: the
/// identity, exact ones (dyadic positions, quarter turns) and rounded ones (angles, directions
/// that are normalised), at a pair's scale or far away; and compounds given child transforms.

#include "generators.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace collide::props {

/// A transform: the identity, an exact one (dyadic position, a quarter turn), or a rounded one
/// (an angle, or a direction that is normalised), at the pair's scale or far away.
template <Scalar T>
Transform<T> gen_transform(double s) {
  using V = Vec2<T>;
  const int style = *rc::gen::inRange(0, 6);
  const V p(T(grid(-64, 64) * s / 4), T(grid(-64, 64) * s / 4));
  if (style == 0) return Transform<T>();
  if (style == 1) {
    const std::array<V, 4> quarter = {V(1, 0), V(0, 1), V(-1, 0), V(0, -1)};
    return Transform<T>::make_with_rotation(p, quarter[std::size_t(*rc::gen::inRange(0, 4))]).value();
  }
  if (style == 2) return Transform<T>::make(p, T(grid(-64, 64) / 10)).value();
  if (style == 3) {
    const std::vector<V> dirs = {V(3, 4), V(1, 1), V(64, 1), V(-5, 12), V(2, 0)};
    return Transform<T>::make_with_rotation(p, *rc::gen::elementOf(dirs)).value();
  }
  if (style == 4) return Transform<T>::make(V(T(1e6 + grid(-8, 8)), T(-1e6)), T(grid(-64, 64) / 10)).value();
  return Transform<T>::make_translation(V(T(grid(-64, 64) * s / 3), T(grid(-64, 64) * s / 3))).value();
}

/// The scale of a pair (its largest coordinate, at least 2^-20), for transforms at its scale.
template <Scalar T>
double scale_of_pair(const Shape<T>& a, const Shape<T>& b) {
  return std::max({::collide::detail::box_scale(bounds(a)), ::collide::detail::box_scale(bounds(b)), 0x1p-20});
}

/// A compound's children given transforms that keep the world shape (each child moved back by the
/// inverse of a quarter turn about a point: exact), or that move it (a rounded transform).
template <Scalar T>
Shape<T> with_child_transforms(const Shape<T>& s, double scale) {
  const auto* c = std::get_if<Compound<T>>(&s);
  if (c == nullptr || !*rc::gen::arbitrary<bool>()) return s;
  std::vector<typename Compound<T>::Child> kids;
  for (const Primitive<T>& p : c->children()) {
    if (*rc::gen::arbitrary<bool>()) {
      kids.push_back({p, Transform<T>()});
    } else {
      kids.push_back({p, gen_transform<T>(scale / 8)});
    }
  }
  return Compound<T>::make_placed(std::move(kids)).value();
}

}  // namespace collide::props
