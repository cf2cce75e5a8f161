#pragma once
/// @file broadphase/world.hpp
/// The lecture's hierarchy end to end over a list of shapes: a broadphase on the shapes'
/// conservative bounding boxes proposes pairs, the exact pair decisions (overlaps, contact) settle them.

#include "collide/broadphase/tree.hpp"
#include "collide/queries.hpp"
#include "collide/raycast.hpp"
#include "collide/registry.hpp"

#include <algorithm>
#include <optional>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace collide::broadphase {

/// Two shapes of the input list, by index, a < b.
struct ShapePair {
  std::size_t a;
  std::size_t b;
  friend constexpr bool operator==(const ShapePair&, const ShapePair&) = default;
  friend constexpr auto operator<=>(const ShapePair&, const ShapePair&) = default;
};

/// A contact between shapes a < b of the input list (normal points from a toward b).
template <Scalar T>
struct ShapeContact {
  std::size_t a;
  std::size_t b;
  Contact<T> contact;
};

/// Every pair of shapes that overlaps(), sorted by (a, b). Same answer as testing all pairs:
/// bounds() never shrinks a shape, and the broadphase reports every pair of touching boxes.
/// BP is DynamicTree<T> (default), SweepAndPrune<T> or UniformGrid<T>, built by `make_bp`.
template <Scalar T, class BP = DynamicTree<T>>
std::vector<ShapePair> find_overlapping_shapes(std::span<const Shape<T>> shapes, BP bp = BP()) {
  for (std::size_t i = 0; i < shapes.size(); ++i) bp.add(bounds(shapes[i]), i);
  std::vector<ShapePair> out;
  for (const ProxyPair& p : bp.pairs()) {
    std::size_t a = bp.user_data(p.a), b = bp.user_data(p.b);
    if (a > b) std::swap(a, b);
    if (overlaps(shapes[a], shapes[b])) out.push_back({a, b});
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Every contact between overlapping shapes, sorted by (a, b); contact(a, b) exists exactly
/// when overlaps(a, b), so the pairs are those of find_overlapping_shapes().
template <Scalar T, class BP = DynamicTree<T>>
std::vector<ShapeContact<T>> find_contacts(std::span<const Shape<T>> shapes, BP bp = BP()) {
  std::vector<ShapeContact<T>> out;
  for (const ShapePair& p : find_overlapping_shapes<T, BP>(shapes, std::move(bp))) {
    if (auto c = contact(shapes[p.a], shapes[p.b])) out.push_back({p.a, p.b, *c});
  }
  return out;
}

/// The first shape a ray meets: index into the input list and the hit.
template <Scalar T>
struct ShapeHit {
  std::size_t index;
  RayHit<T> hit;
};

/// The nearest hit of origin + t direction, t in [0, max_t], over the shapes (ties: lowest
/// index), or nothing. The broadphase proposes the shapes whose bounding boxes the segment meets;
/// collide::raycast settles each. Errors: BadRay (NaN/inf ray, negative max_t).
template <Scalar T, class BP = DynamicTree<T>>
std::optional<ShapeHit<T>> raycast_shapes(std::span<const Shape<T>> shapes, const Ray<T>& ray, T max_t,
                                          BP bp = BP()) {
  // Boxes padded by 16 eps_T of their scale: a hit that collide::raycast reports within its own
  // rounding tolerance just outside a shape must still find that shape's box.
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const Aabb<T> b = bounds(shapes[i]);
    const T scale = std::max(b.min().cwiseAbs().maxCoeff(), b.max().cwiseAbs().maxCoeff());
    const T pad = T(16) * std::numeric_limits<T>::epsilon() * scale + std::numeric_limits<T>::min();
    const Expected<Aabb<T>> padded =
        Aabb<T>::make((b.min().array() - pad).matrix(), (b.max().array() + pad).matrix());
    bp.add(padded ? padded.value() : b, i);
  }
  std::optional<ShapeHit<T>> best;
  bp.raycast(ray, max_t, [&](ProxyId id, Calc) {
    const std::size_t i = bp.user_data(id);
    const auto h = raycast(shapes[i], ray, max_t);
    if (h && (!best || h->t < best->hit.t || (h->t == best->hit.t && i < best->index))) best = ShapeHit<T>{i, *h};
  });
  return best;
}

}  // namespace collide::broadphase
