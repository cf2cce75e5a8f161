#pragma once
/// @file compound.hpp
/// Compound, which caches the box of its children, and a compound placed by a pose.

#include "collide/bounds.hpp"
#include "collide/detail/image.hpp"
#include "collide/shapes.hpp"
#include "collide/transform.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace collide {

namespace detail {

/// The box of primitive s's computed image under x, before any padding.
template <class P>
Aabb<Calc> image_box(const P& s, const Pose& x) {
  return with_image(s, x, [](const auto& img) { return bounds(img); });
}
/// A polygon's: the box of its mapped vertices, which holds whatever its image is (their hull, or
/// two of them) without building that image.
template <Scalar T>
Aabb<Calc> image_box(const ConvexPolygon<T>& s, const Pose& x) {
  Vec2c lo = image_point(x, widen(s[0])), hi = lo;
  for (std::size_t k = 1; k < s.size(); ++k) {
    const Vec2c p = image_point(x, widen(s[k]));
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return AabbAccess::unchecked<Calc>(lo, hi);
}

/// Conservative box, in T, of the image of primitive s under x, an image whose points are within
/// tol of the exact image's: the rounded image's box padded by tol and rounded outward.
template <Scalar T, class P>
Aabb<T> placed_bounds(const P& s, const Pose& x, Calc tol) {
  const Aabb<Calc> b = image_box(s, x);
  return bounds_from_calc<T>((b.min().array() - tol).matrix(), (b.max().array() + tol).matrix());
}

}  // namespace detail

/// A body made of several shapes (a "list of geometries"): the union of its children, each placed
/// in the body's frame by its own transform (the identity unless given), with a cached bounding box
/// that every query checks before looking at any child.
template <Scalar T>
class Compound {
 public:
  /// One child and its placement in the compound's frame.
  struct Child {
    Primitive<T> shape;      ///< the child in its own local frame
    Transform<T> transform;  ///< where the child sits in the compound's frame (identity by default)
  };

  /// Children placed where their values say (every child transform the identity).
  /// Errors: EmptyCompound. Children are valid by construction.
  static Expected<Compound> make(std::vector<Primitive<T>> children) {
    if (children.empty()) return ShapeError(Error::EmptyCompound, -1, "compound has no children");
    Vec2<T> lo = collide::bounds(children[0]).min(), hi = collide::bounds(children[0]).max();
    Calc extent = 0;
    for (const Primitive<T>& c : children) {
      const Aabb<T> b = collide::bounds(c);
      lo = lo.cwiseMin(b.min());
      hi = hi.cwiseMax(b.max());
      extent = std::max(extent, 2 * detail::scale_of(b));
    }
    // Unchecked: children's boxes may exceed max_magnitude<T>() (see AabbAccess).
    return Compound(std::move(children), {}, detail::AabbAccess::unchecked<T>(lo, hi), extent);
  }
  /// Children with their own transforms (the image of each child under its transform, as a
  /// transformed query defines it). Errors: EmptyCompound. Allocates (the compound owns its children).
  static Expected<Compound> make_placed(std::vector<Child> children) {
    if (children.empty()) return ShapeError(Error::EmptyCompound, -1, "compound has no children");
    bool placed = false;
    for (const Child& c : children) placed = placed || !c.transform.is_identity();
    std::vector<Primitive<T>> shapes;
    shapes.reserve(children.size());
    for (Child& c : children) shapes.push_back(std::move(c.shape));
    if (!placed) return make(std::move(shapes));
    std::vector<Transform<T>> xf;
    xf.reserve(children.size());
    Calc extent = 0;
    std::optional<Aabb<T>> box;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      xf.push_back(children[i].transform);
      const detail::Pose x = children[i].transform.pose();
      const Calc local = std::visit([](const auto& s) { return detail::scale_of(collide::bounds(s)); }, shapes[i]);
      extent = std::max(extent, x.p.cwiseAbs().maxCoeff() + 2 * local);
      const Aabb<T> b = std::visit(
          [&](const auto& s) { return detail::placed_bounds<T>(s, x, detail::image_tolerance(x, local)); }, shapes[i]);
      box = box ? detail::AabbAccess::unchecked<T>(box->min().cwiseMin(b.min()), box->max().cwiseMax(b.max())) : b;
    }
    return Compound(std::move(shapes), std::move(xf), *box, extent);
  }
  /// As make(), throwing the ShapeError.
  explicit Compound(std::vector<Primitive<T>> children) : Compound(make(std::move(children)).value()) {}

  /// The children, in the order given, each in its own local frame (see child_transform()).
  const std::vector<Primitive<T>>& children() const noexcept { return children_; }
  /// Where child i sits in the compound's frame: the identity unless given. Precondition:
  /// i < children().size().
  Transform<T> child_transform(std::size_t i) const noexcept {
    return transforms_.empty() ? Transform<T>() : transforms_[i];
  }
  /// True when some child has a transform other than the identity.
  bool has_child_transforms() const noexcept { return !transforms_.empty(); }
  /// Cached conservative bounding box of all children (placed), in the compound's frame.
  const Aabb<T>& bounds() const noexcept { return bounds_; }
  /// The local magnitude L of transform_tolerance(): the largest over the children of
  /// |child position|_inf + 2 * (largest absolute coordinate of the child's own box).
  Calc local_extent() const noexcept { return extent_; }

 private:
  Compound(std::vector<Primitive<T>> c, std::vector<Transform<T>> x, const Aabb<T>& b, Calc extent)
      : children_(std::move(c)), transforms_(std::move(x)), bounds_(b), extent_(extent) {}
  std::vector<Primitive<T>> children_;
  std::vector<Transform<T>> transforms_{};  // empty when every child is placed by the identity
  Aabb<T> bounds_;
  Calc extent_ = 0;
};

/// The compound's cached box (the union of its children's boxes).
template <Scalar T>
Aabb<T> bounds(const Compound<T>& s) noexcept {
  return s.bounds();
}

}  // namespace collide

namespace collide::detail {

/// A compound placed by a body pose, as queries see it: nothing is copied; each child is imaged
/// under the body pose composed with its own transform when visited.
template <Scalar T>
struct PlacedCompound {
  const Compound<T>* compound;  ///< the local compound
  Pose pose;                    ///< the body's placement
  Aabb<Calc> box;               ///< conservative world box (the local box's image, padded)
};

/// The compound under x with its world box: the image of its local box, padded. A rotation
/// stored as given scales positions by |q| but not radii and half extents, so the image of the
/// local box falls short of the children's images by up to ||q| - 1| L <= |q^2 - 1| L (plus the
/// rounding of q^2); that is padded too.
template <Scalar T>
PlacedCompound<T> placed(const Compound<T>& c, const Pose& x) {
  const Aabb<T>& b = c.bounds();
  const Calc local = c.local_extent();
  const Calc tol = image_tolerance(x, local) + (std::fabs(x.q.squaredNorm() - 1) + 4 * kUnitRoundoff) * local;
  const Aabb<Calc> box = placed_bounds<Calc>(ShapeAccess::aabb<Calc>(widen(b.min()), widen(b.max())), x, tol);
  return PlacedCompound<T>{&c, x, box};
}

/// The world box of a placed compound.
template <Scalar T>
const Aabb<Calc>& bounds(const PlacedCompound<T>& s) noexcept {
  return s.box;
}

}  // namespace collide::detail
