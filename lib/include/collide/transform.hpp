#pragma once
/// @file transform.hpp
/// Transform<T>: where a body is and how it is turned. Shapes are stored in their body's local
/// frame; a transform places them in the world without rebuilding or re-validating them.
///
/// Meaning (the one definition): a transform with stored position p and rotation q = (c, s) maps
/// a local point x to the world point R(q) x + p, R(q) = [[c, -s], [s, c]], evaluated exactly.
/// A shape with a transform is the exact image of its stored local values: its defining points
/// (centres, corners, segment ends, vertices) are mapped, its radii and half extents are kept,
/// and an OBB's axis is turned by R(q). The stored q is a unit vector rounded to T, so |q| may
/// differ from 1 by about one rounding of T; the exact image uses q as stored.

#include "collide/config.hpp"
#include "collide/error.hpp"
#include "collide/predicates.hpp"
#include "collide/shapes.hpp"

#include <cmath>
#include <limits>
#include <optional>

namespace collide {

namespace detail {

/// A placement in the computation type: x -> R(q) x + p, each coordinate computed as
/// (q.x * x.x - q.y * x.y) + p.x (and likewise for y), the order every image uses.
struct Pose {
  Vec2c p = Vec2c::Zero();  ///< position
  Vec2c q = Vec2c(1, 0);    ///< rotation (cos, sin), as stored (|q| = 1 up to one rounding)

  /// R(q) v.
  Vec2c rotate(const Vec2c& v) const noexcept { return {q.x() * v.x() - q.y() * v.y(), q.y() * v.x() + q.x() * v.y()}; }
  /// R(q) x + p.
  Vec2c apply(const Vec2c& x) const noexcept {
    const Vec2c r = rotate(x);
    return {r.x() + p.x(), r.y() + p.y()};
  }
  /// The pose identity: nothing to compute.
  bool is_identity() const noexcept { return p.x() == 0 && p.y() == 0 && q.x() == 1 && q.y() == 0; }
};

/// outer after inner (a compound child placed in its body): x -> outer(inner(x)), rounded.
inline Pose compose(const Pose& outer, const Pose& inner) noexcept {
  return Pose{outer.apply(inner.p), outer.rotate(inner.q)};
}

}  // namespace detail

/// A rigid placement: position plus rotation stored as (cosine, sine). Plain value, no allocation.
template <Scalar T>
class Transform {
 public:
  /// The identity: position (0, 0), rotation (1, 0). World-space queries mean this transform.
  constexpr Transform() noexcept : p_(Vec2<T>::Zero()), q_(T(1), T(0)) {}

  /// Position and counter-clockwise angle in radians; q = (cos angle, sin angle) computed by T's
  /// own cos and sin (each within one unit in the last place of T, so |q|^2 is within 4 eps_T of
  /// 1). q is what the transform means: the exact image uses it as stored.
  /// Errors: NonFinite, OutOfRange (index 0, 1 = position, 2 = angle).
  static Expected<Transform> make(const Vec2<T>& position, T angle) noexcept {
    if (!detail::values_in_range<T>({position.x(), position.y(), angle})) [[unlikely]]
      return detail::range_error<T>({position.x(), position.y(), angle});
    return Transform(position, Vec2<T>(std::cos(angle), std::sin(angle)));
  }

  /// Position and rotation given as a direction (the image of the local x axis). A vector whose
  /// squared length is within 4 eps_T of 1 is stored bit for bit, so make_with_rotation(p,
  /// x.rotation()) rebuilds the same transform; any other non-zero vector is normalised (in
  /// double, then rounded to T) rather than rejected, as Obb::make_with_axis does.
  /// Errors: NonFinite, OutOfRange (index 0, 1 = position, 2, 3 = rotation), ZeroRotation.
  static Expected<Transform> make_with_rotation(const Vec2<T>& position, const Vec2<T>& rotation) noexcept {
    if (!detail::values_in_range<T>({position.x(), position.y(), rotation.x(), rotation.y()})) [[unlikely]]
      return detail::range_error<T>({position.x(), position.y(), rotation.x(), rotation.y()});
    const Vec2c r = widen(rotation);
    if (std::fabs(r.squaredNorm() - 1) <= 4 * Calc(std::numeric_limits<T>::epsilon()))
      return Transform(position, rotation);
    const std::optional<Vec2c> u = detail::normalized(r);
    if (!u) return ShapeError(Error::ZeroRotation, -1, "transform rotation is the zero vector");
    return Transform(position, u->template cast<T>());
  }

  /// A pure translation (rotation (1, 0)). Errors: NonFinite, OutOfRange (index 0, 1).
  static Expected<Transform> make_translation(const Vec2<T>& position) noexcept {
    return make_with_rotation(position, Vec2<T>(T(1), T(0)));
  }

  /// The same transform moved by v: position + v rounded to T, rotation kept bit for bit (a body
  /// moving between frames). Errors: NonFinite, OutOfRange (index 0, 1).
  Expected<Transform> moved(const Vec2<T>& v) const noexcept {
    const Vec2<T> p = p_ + v;
    if (!detail::values_in_range<T>({p.x(), p.y()})) [[unlikely]]
      return detail::range_error<T>({p.x(), p.y()});
    return Transform(p, q_);
  }

  /// As make(), throwing the ShapeError.
  Transform(const Vec2<T>& position, T angle) : Transform(make(position, angle).value()) {}

  /// The stored position p (the image of the local origin).
  const Vec2<T>& position() const noexcept { return p_; }
  /// The stored rotation q = (cos, sin): |q| is 1 up to one rounding of T.
  const Vec2<T>& rotation() const noexcept { return q_; }

  /// R(q) x + p for a local point, computed in Calc (double): each coordinate is within
  /// 2^-52 (|p| + |c x| + |s y|) of the exact image, and exact when every product and the sum
  /// are representable (exact translations, quarter turns of representable values).
  Vec2c apply(const Vec2c& x) const noexcept { return pose().apply(x); }
  /// R(q) v for a local direction, computed in Calc.
  Vec2c rotate(const Vec2c& v) const noexcept { return pose().rotate(v); }
  /// The transpose R(q)^T v (the inverse rotation when |q| = 1), computed in Calc.
  Vec2c unrotate(const Vec2c& v) const noexcept {
    const Calc c = q_.x(), s = q_.y();
    return {c * v.x() + s * v.y(), -s * v.x() + c * v.y()};
  }

  /// True for position (0, 0) and rotation (1, 0): queries then use the stored shape itself.
  bool is_identity() const noexcept { return pose().is_identity(); }
  /// The stored values in the computation type.
  detail::Pose pose() const noexcept { return detail::Pose{widen(p_), widen(q_)}; }

  /// The same transform with double values, bit for bit (exact: every float is a double).
  Transform<double> widened() const noexcept { return Transform<double>(widen(p_), widen(q_)); }

  /// Same stored values.
  friend bool operator==(const Transform& a, const Transform& b) noexcept { return a.p_ == b.p_ && a.q_ == b.q_; }

 private:
  template <Scalar U>
  friend class Transform;
  Transform(const Vec2<T>& p, const Vec2<T>& q) noexcept : p_(p), q_(q) {}
  Vec2<T> p_;
  Vec2<T> q_;
};

}  // namespace collide
