#pragma once
/// @file shapes.hpp
/// The six shapes. Each is a plain value type whose stored values always satisfy its invariants:
/// the only ways in are the factory `make(...)` (returns Expected, never throws) and a constructor
/// with the same arguments (throws ShapeError). Every shape is a closed set.

#include "collide/config.hpp"
#include "collide/error.hpp"
#include "collide/predicates.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace collide {

namespace detail {

/// Rejects NaN, infinities and magnitudes above max_magnitude<T>().
template <Scalar T>
inline bool check_value(T v, long index, ShapeError* out) noexcept {
  if (!std::isfinite(v)) {
    *out = ShapeError(Error::NonFinite, index, "value is NaN or infinite");
    return false;
  }
  if (std::fabs(v) > max_magnitude<T>()) {
    *out = ShapeError(Error::OutOfRange, index, "magnitude exceeds max_magnitude()");
    return false;
  }
  return true;
}

/// True when every value is finite and within max_magnitude<T>() (check_values() without the error).
template <Scalar T>
inline bool values_in_range(std::initializer_list<T> values) noexcept {
  // On the magnitudes' bits: one compare for all values, and NaN's bits lie above every finite value's.
  using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
  constexpr Bits sign = Bits(1) << (8 * sizeof(T) - 1);
  Bits m = 0;
  for (T v : values) m = std::max(m, Bits(std::bit_cast<Bits>(v) & ~sign));
  return m <= std::bit_cast<Bits>(max_magnitude<T>());
}

template <Scalar T>
inline bool check_values(std::initializer_list<T> values, ShapeError* out) noexcept {
  long i = 0;
  for (T v : values) {
    if (!check_value(v, i++, out)) return false;
  }
  return true;
}

inline ShapeError placeholder_error();
/// The error check_values() names for values that values_in_range() rejects.
template <Scalar T>
ShapeError range_error(std::initializer_list<T> values) {
  ShapeError e = placeholder_error();
  check_values<T>(values, &e);
  return e;
}

/// v / |v| for a finite v, or nullopt for the zero vector. v is first scaled by a power of two
/// (exact) so that its larger coordinate lies in [1, 2): subnormal or huge directions normalise
/// as accurately as ordinary ones, and the result is unit within a few roundings of double.
inline std::optional<Vec2c> normalized(const Vec2c& v) noexcept {
  const Calc m = std::max(std::fabs(v.x()), std::fabs(v.y()));
  if (!(m > 0)) return std::nullopt;
  const int e = std::ilogb(m);
  const Vec2c w(std::scalbn(v.x(), -e), std::scalbn(v.y(), -e));
  return Vec2c(w / std::hypot(w.x(), w.y()));
}

/// The unit outward normal of a counter-clockwise polygon's edge from a to b, computed in double
/// (one square root; an edge whose squared length would underflow or overflow is scaled first).
inline Vec2c edge_normal(const Vec2c& a, const Vec2c& b) noexcept {
  const Vec2c d = b - a;
  const Calc dd = d.squaredNorm();
  if (dd > kUnderflowMargin && dd < kOverflowMargin) [[likely]]
    return Vec2c(d.y(), -d.x()) / std::sqrt(dd);
  return normalized(Vec2c(d.y(), -d.x())).value_or(Vec2c::Zero());
}

/// How far each vertex of a counter-clockwise, strictly convex polygon may move (independently,
/// in any direction) with every turn still strictly left, or 0 when not computed (a coordinate
/// beyond [2^-200, 2^200], where the products below could underflow or overflow). Per vertex b
/// between its neighbours a and c: b's distance h from the line ac over 1 + |t| + |1 - t| (t: b's
/// projection along ac; moving a and c by e moves the line at b by at most (|t| + |1 - t|) e), and
/// |c - a| (which keeps the line's turn small), each taken low by norms of ac that bound its length
/// (no square root). A quarter of the least covers the roundings and the line's turn.
template <class At>
Calc turn_margin(std::size_t n, At&& at) noexcept {
  Calc scale = 0, m = std::numeric_limits<Calc>::infinity();
  for (std::size_t k = 0; k < n; ++k) scale = std::max(scale, at(k).cwiseAbs().maxCoeff());
  if (!(scale >= 0x1p-200 && scale <= 0x1p200)) return 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2c a = at(k), b = at(next_index(k, n)), c = at(next_index(next_index(k, n), n));
    const Vec2c ac = c - a, ab = b - a;
    const Calc len2 = ac.squaredNorm(), along = ab.dot(ac), cross = ab.x() * ac.y() - ab.y() * ac.x();
    // h / (1 + |t| + |1 - t|) >= cross / |ac|_1 * len2 / (len2 + |along| + |len2 - along|).
    const Calc spread = len2 + std::fabs(along) + std::fabs(len2 - along);
    m = std::min({m, cross * len2 / (ac.cwiseAbs().sum() * spread), ac.cwiseAbs().maxCoeff()});
  }
  return m > 0 ? m / 4 : 0;
}

struct Unchecked {};
struct ObbAccess;
struct PolygonAccess;
struct AabbAccess;
struct ShapeAccess;

inline ShapeError placeholder_error() {
  return ShapeError(Error::NonFinite, -1, "");
}

/// A list that keeps up to N elements inline and moves to the heap only beyond that, so that
/// factories of shapes with a few vertices do not allocate.
template <class V, std::size_t N>
class SmallList {
 public:
  std::size_t size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }
  V* data() noexcept { return size_ > N || !heap_.empty() ? heap_.data() : inline_.data(); }
  const V* data() const noexcept { return size_ > N || !heap_.empty() ? heap_.data() : inline_.data(); }
  V& operator[](std::size_t i) noexcept { return data()[i]; }
  const V& operator[](std::size_t i) const noexcept { return data()[i]; }
  V& front() noexcept { return data()[0]; }
  V& back() noexcept { return data()[size_ - 1]; }
  V* begin() noexcept { return data(); }
  V* end() noexcept { return data() + size_; }
  const V* begin() const noexcept { return data(); }
  const V* end() const noexcept { return data() + size_; }
  void push_back(const V& v) {
    if (heap_.empty() && size_ == N) heap_.assign(inline_.begin(), inline_.end());
    if (!heap_.empty()) {
      if (heap_.size() == size_)
        heap_.push_back(v);
      else
        heap_[size_] = v;
    } else {
      inline_[size_] = v;
    }
    ++size_;
  }
  void pop_back() noexcept { --size_; }
  void erase_at(std::size_t i) noexcept {
    std::move(begin() + i + 1, end(), begin() + i);
    --size_;
  }
  void resize_down(std::size_t n) noexcept { size_ = std::min(size_, n); }
  std::span<const V> span() const noexcept { return {data(), size_}; }

 private:
  std::array<V, N> inline_{};
  std::vector<V> heap_;
  std::size_t size_ = 0;
};

}  // namespace detail

/// Circle: every point within `radius` of `center`. radius >= 0 (0 is a point).
template <Scalar T>
class Circle {
 public:
  /// Errors: NonFinite, OutOfRange (index 0..2 = center.x, center.y, radius), NegativeRadius.
  static Expected<Circle> make(const Vec2<T>& center, T radius) noexcept {
    ShapeError e = detail::placeholder_error();
    if (!detail::check_values<T>({center.x(), center.y(), radius}, &e)) return e;
    if (radius < T(0)) return ShapeError(Error::NegativeRadius, -1, "circle radius is negative");
    return Circle(detail::Unchecked{}, center, radius);
  }
  /// As make(), throwing the ShapeError.
  Circle(const Vec2<T>& center, T radius) : Circle(make(center, radius).value()) {}

  /// Centre.
  const Vec2<T>& center() const noexcept { return center_; }
  /// Radius, >= 0.
  T radius() const noexcept { return radius_; }

 private:
  friend struct detail::ShapeAccess;
  Circle(detail::Unchecked, const Vec2<T>& c, T r) : center_(c), radius_(r) {}
  Vec2<T> center_;
  T radius_;
};

/// Axis-aligned box [min.x, max.x] x [min.y, max.y]. min == max on an axis is allowed (a segment or
/// a point).
template <Scalar T>
class Aabb {
 public:
  /// Errors: NonFinite, OutOfRange (index 0..3 = min.x, min.y, max.x, max.y), MinGreaterThanMax
  /// (index = axis).
  static Expected<Aabb> make(const Vec2<T>& min, const Vec2<T>& max) noexcept {
    ShapeError e = detail::placeholder_error();
    if (!detail::check_values<T>({min.x(), min.y(), max.x(), max.y()}, &e)) return e;
    for (int axis = 0; axis < 2; ++axis) {
      if (min[axis] > max[axis]) return ShapeError(Error::MinGreaterThanMax, axis, "AABB min exceeds max");
    }
    return Aabb(detail::Unchecked{}, min, max);
  }
  /// As make(), throwing the ShapeError.
  Aabb(const Vec2<T>& min, const Vec2<T>& max) : Aabb(make(min, max).value()) {}

  /// Lower-left corner (min <= max on each axis).
  const Vec2<T>& min() const noexcept { return min_; }
  /// Upper-right corner.
  const Vec2<T>& max() const noexcept { return max_; }

 private:
  template <Scalar U>
  friend Aabb<U> bounds_from_calc(const Vec2c&, const Vec2c&) noexcept;
  friend struct detail::AabbAccess;
  friend struct detail::ShapeAccess;
  Aabb(detail::Unchecked, const Vec2<T>& lo, const Vec2<T>& hi) : min_(lo), max_(hi) {}
  Vec2<T> min_;
  Vec2<T> max_;
};

/// Oriented box: the set center + s*hx*u + t*hy*v for s, t in [-1, 1], where u = axis() and
/// v = perp(u) = (-u.y, u.x). The exact shape is the one these stored values define; u is the unit
/// vector rounded to T, so |u| differs from 1 by at most one rounding.
template <Scalar T>
class Obb {
 public:
  /// Rotation given as an angle in radians (counter-clockwise from +x).
  /// Errors: NonFinite, OutOfRange (index 0..4 = center.x, center.y, hx, hy, angle), NegativeExtent.
  static Expected<Obb> make(const Vec2<T>& center, const Vec2<T>& half_extents, T angle) noexcept {
    ShapeError e = detail::placeholder_error();
    if (!detail::check_values<T>({center.x(), center.y(), half_extents.x(), half_extents.y(), angle}, &e)) return e;
    const Vec2<T> axis(static_cast<T>(std::cos(static_cast<Calc>(angle))),
                       static_cast<T>(std::sin(static_cast<Calc>(angle))));
    return make_with_axis(center, half_extents, axis);
  }
  /// Rotation given as the direction of the box's local x axis (any length > 0; normalised).
  /// An axis that is already a unit vector rounded to T (| |axis|^2 - 1 | <= 4 eps_T) is stored
  /// bit for bit, so make_with_axis(c, h, obb.axis()) rebuilds exactly the same box.
  /// Errors: NonFinite, OutOfRange, NegativeExtent, ZeroAxis.
  static Expected<Obb> make_with_axis(const Vec2<T>& center, const Vec2<T>& half_extents,
                                      const Vec2<T>& axis) noexcept {
    ShapeError e = detail::placeholder_error();
    if (!detail::check_values<T>({center.x(), center.y(), half_extents.x(), half_extents.y(), axis.x(), axis.y()}, &e))
      return e;
    if (half_extents.x() < T(0) || half_extents.y() < T(0))
      return ShapeError(Error::NegativeExtent, half_extents.x() < T(0) ? 0 : 1, "OBB half extent is negative");
    const Vec2c a = widen(axis);
    if (std::fabs(a.squaredNorm() - 1) <= 4 * Calc(std::numeric_limits<T>::epsilon()))
      return Obb(detail::Unchecked{}, center, half_extents, axis);
    const std::optional<Vec2c> u = detail::normalized(a);
    if (!u) return ShapeError(Error::ZeroAxis, -1, "OBB axis is the zero vector");
    return Obb(detail::Unchecked{}, center, half_extents, u->template cast<T>());
  }
  /// The course notes' form: four corners in order around the rectangle (either winding).
  /// They must form a rectangle up to rounding: |p0 + p2 - p1 - p3| <= 16 eps_T S and
  /// |(p1 - p0) . (p3 - p0)| <= 16 eps_T S (|p1 - p0| + |p3 - p0|), S = largest |coordinate|.
  /// Errors: NonFinite, OutOfRange (index = 2 * corner + axis), NotARectangle.
  static Expected<Obb> from_corners(const Vec2<T>& p0, const Vec2<T>& p1, const Vec2<T>& p2,
                                    const Vec2<T>& p3) noexcept {
    ShapeError e = detail::placeholder_error();
    if (!detail::check_values<T>({p0.x(), p0.y(), p1.x(), p1.y(), p2.x(), p2.y(), p3.x(), p3.y()}, &e)) return e;
    const Vec2c q0 = widen(p0), q1 = widen(p1), q2 = widen(p2), q3 = widen(p3);
    const Calc scale = std::max(
        {q0.cwiseAbs().maxCoeff(), q1.cwiseAbs().maxCoeff(), q2.cwiseAbs().maxCoeff(), q3.cwiseAbs().maxCoeff()});
    const Calc tol = 16 * Calc(std::numeric_limits<T>::epsilon()) * scale;
    const Vec2c e1 = q1 - q0, e2 = q3 - q0;
    if ((q0 + q2 - q1 - q3).cwiseAbs().maxCoeff() > 2 * tol)
      return ShapeError(Error::NotARectangle, -1, "corners do not form a parallelogram");
    const Calc l1 = e1.norm(), l2 = e2.norm();
    if (std::fabs(e1.dot(e2)) > tol * (l1 + l2))
      return ShapeError(Error::NotARectangle, -1, "corners do not meet at right angles");
    Vec2c u(1, 0);
    if (l1 > 0) {
      u = e1 / l1;
    } else if (l2 > 0) {
      u = -perp(e2 / l2);
    }
    const Vec2c c = (q0 + q2) * 0.5;
    const Vec2<T> half(static_cast<T>(l1 * 0.5), static_cast<T>(l2 * 0.5));
    return Obb(detail::Unchecked{}, c.template cast<T>(), half, u.template cast<T>());
  }
  /// As make(center, half_extents, angle), throwing the ShapeError.
  Obb(const Vec2<T>& center, const Vec2<T>& half_extents, T angle) : Obb(make(center, half_extents, angle).value()) {}

  /// Centre.
  const Vec2<T>& center() const noexcept { return center_; }
  /// Half extents along the local x axis (axis()) and the local y axis (axis() turned +90 degrees), >= 0.
  const Vec2<T>& half_extents() const noexcept { return half_; }
  /// Unit direction of the local x axis (rounded to T).
  const Vec2<T>& axis() const noexcept { return axis_; }

 private:
  friend struct detail::ObbAccess;
  friend struct detail::ShapeAccess;
  Obb(detail::Unchecked, const Vec2<T>& c, const Vec2<T>& h, const Vec2<T>& u) : center_(c), half_(h), axis_(u) {}
  Vec2<T> center_;
  Vec2<T> half_;
  Vec2<T> axis_;
};

namespace detail {
/// Builds an OBB keeping a stored axis bit for bit (for exact widening and translation): only
/// the new center and extents are validated.
struct ObbAccess {
  template <Scalar T, Scalar U>
  static Expected<Obb<T>> with_axis_of(const Vec2<T>& center, const Vec2<T>& half, const Obb<U>& from) {
    ShapeError e = placeholder_error();
    if (!check_values<T>({center.x(), center.y(), half.x(), half.y()}, &e)) return e;
    if (half.x() < T(0) || half.y() < T(0)) return ShapeError(Error::NegativeExtent, -1, "OBB half extent is negative");
    return Obb<T>(Unchecked{}, center, half, from.axis().template cast<T>());
  }
};
}  // namespace detail

namespace detail {
/// Builds a box without validation, for bounding boxes computed from valid shapes: those may
/// exceed max_magnitude<T>() by a few times (a circle at 2^500 with radius 2^500), and must not
/// make an otherwise valid shape fail. Precondition: finite, lo <= hi.
struct AabbAccess {
  template <Scalar T>
  static Aabb<T> unchecked(const Vec2<T>& lo, const Vec2<T>& hi) noexcept {
    return Aabb<T>(Unchecked{}, lo, hi);
  }
};
}  // namespace detail

/// Capsule: every point within `radius` of the segment [a, b]. a == b is a circle.
template <Scalar T>
class Capsule {
 public:
  /// Errors: NonFinite, OutOfRange (index 0..4 = a.x, a.y, b.x, b.y, radius), NegativeRadius.
  static Expected<Capsule> make(const Vec2<T>& a, const Vec2<T>& b, T radius) noexcept {
    ShapeError e = detail::placeholder_error();
    if (!detail::check_values<T>({a.x(), a.y(), b.x(), b.y(), radius}, &e)) return e;
    if (radius < T(0)) return ShapeError(Error::NegativeRadius, -1, "capsule radius is negative");
    return Capsule(detail::Unchecked{}, a, b, radius);
  }
  /// As make(), throwing the ShapeError.
  Capsule(const Vec2<T>& a, const Vec2<T>& b, T radius) : Capsule(make(a, b, radius).value()) {}

  /// First end of the core segment.
  const Vec2<T>& a() const noexcept { return a_; }
  /// Second end of the core segment (may equal a(): the capsule is then a circle).
  const Vec2<T>& b() const noexcept { return b_; }
  /// Radius around the segment, >= 0.
  T radius() const noexcept { return radius_; }

 private:
  friend struct detail::ShapeAccess;
  Capsule(detail::Unchecked, const Vec2<T>& a, const Vec2<T>& b, T r) : a_(a), b_(b), radius_(r) {}
  Vec2<T> a_;
  Vec2<T> b_;
  T radius_;
};

namespace detail {
/// Points on a convex hull, inline for the hulls of up to 16 points.
template <Scalar T>
using HullPoints = SmallList<Vec2<T>, 32>;

/// The convex hull of finite points, counter-clockwise from the lexicographically smallest
/// (monotone chain on the exact orient(); points on the hull's edges dropped); fewer than 3
/// points when they are all on one line. `distinct` gets the number of distinct points.
template <Scalar T>
HullPoints<T> hull_points(std::span<const Vec2<T>> points, std::size_t& distinct) {
  SmallList<Vec2<T>, 16> p;
  for (const Vec2<T>& q : points) p.push_back(q);
  std::sort(p.begin(), p.end(),
            [](const Vec2<T>& a, const Vec2<T>& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  p.resize_down(std::size_t(std::unique(p.begin(), p.end()) - p.begin()));
  distinct = p.size();
  HullPoints<T> h;
  if (p.size() < 3) return h;
  for (std::size_t i = 0; i < 2 * p.size(); ++i) h.push_back(Vec2<T>::Zero());
  std::size_t k = 0;
  auto turn = [&](std::size_t i, const Vec2<T>& c) { return orient(widen(h[i - 2]), widen(h[i - 1]), widen(c)); };
  for (const Vec2<T>& q : p) {
    while (k >= 2 && turn(k, q) <= 0) --k;
    h[k++] = q;
  }
  const std::size_t lower = k + 1;
  for (std::size_t i = p.size() - 1; i-- > 0;) {
    while (k >= lower && turn(k, p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize_down(k - 1);
  return h;
}
}  // namespace detail

/// Convex polygon with vertices stored counter-clockwise, no two consecutive equal, no three
/// consecutive collinear. Up to kInline vertices are stored without a heap allocation.
template <Scalar T>
class ConvexPolygon {
 public:
  /// Polygons of up to this many vertices are stored without a heap allocation.
  static constexpr std::size_t kInline = 8;

  /// Accepts either winding (normalised to counter-clockwise). Repeated consecutive vertices are
  /// merged; a vertex collinear with its neighbours and lying between them is dropped. Decisions
  /// use the exact orient() predicate.
  /// Errors: NonFinite, OutOfRange (index = 2 * vertex + axis), TooFewVertices (< 3 distinct),
  /// Collinear (no area), NonConvex (index = the input vertex where the boundary turns the wrong
  /// way, doubles back, or completes a second turn).
  static Expected<ConvexPolygon> make(std::span<const Vec2<T>> vertices) {
    ShapeError e = detail::placeholder_error();
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      if (!detail::check_value(vertices[i].x(), long(2 * i), &e)) return e;
      if (!detail::check_value(vertices[i].y(), long(2 * i + 1), &e)) return e;
    }
    // Merge repeats, remembering each kept vertex's input index for error messages.
    detail::SmallList<std::size_t, 2 * kInline> idx;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      if (idx.empty() || vertices[idx.back()] != vertices[i]) idx.push_back(i);
    }
    while (idx.size() > 1 && vertices[idx.front()] == vertices[idx.back()]) idx.pop_back();
    if (idx.size() < 3) return ShapeError(Error::TooFewVertices, -1, "polygon has fewer than 3 distinct vertices");
    auto at = [&](std::size_t k) { return widen(vertices[idx[k % idx.size()]]); };
    // Winding: the sign of the signed area (so that a NonConvex index names a reflex vertex of a
    // simple polygon, not the first turn), else the sign of the first non-zero turn. Only a
    // preference: every turn is then checked exactly.
    int winding = 0;
    for (std::size_t k = 0; k < idx.size() && winding == 0; ++k) winding = orient(at(k), at(k + 1), at(k + 2));
    if (winding == 0) return ShapeError(Error::Collinear, -1, "polygon vertices are all collinear");
    {
      // Tiny polygons are scaled up by 2^600 (exact) so that the cross products do not underflow.
      Calc m = 0;
      for (std::size_t k = 0; k < idx.size(); ++k) m = std::max(m, at(k).cwiseAbs().maxCoeff());
      const int sc = m < kTinyCore ? 600 : 0;
      const Vec2c o = at(0);
      auto rel = [&](std::size_t k) {
        const Vec2c d = at(k) - o;
        return Vec2c(std::ldexp(d.x(), sc), std::ldexp(d.y(), sc));
      };
      Calc area2 = 0;
      for (std::size_t k = 1; k + 1 < idx.size(); ++k) area2 += cross(rel(k), rel(k + 1));
      if (std::isfinite(area2) && area2 != 0) winding = area2 > 0 ? 1 : -1;
    }
    if (winding < 0) std::reverse(idx.begin(), idx.end());
    // Drop straight-through collinear vertices; reject wrong turns and doublings-back.
    bool changed = true;
    while (changed && idx.size() >= 3) {
      changed = false;
      for (std::size_t k = 0; k < idx.size(); ++k) {
        const Vec2c p = at(k + idx.size() - 1), q = at(k), r = at(k + 1);
        const int o = orient(p, q, r);
        if (o < 0) return ShapeError(Error::NonConvex, long(idx[k]), "polygon turns the wrong way");
        if (o == 0) {
          // Collinear: it doubles back iff a coordinate of the two steps has opposite signs
          // (compared by sign, not by a dot product, which underflows for tiny coordinates).
          auto opposite = [](Calc s1, Calc s2) { return (s1 < 0 && s2 > 0) || (s1 > 0 && s2 < 0); };
          if (opposite(q.x() - p.x(), r.x() - q.x()) || opposite(q.y() - p.y(), r.y() - q.y()))
            return ShapeError(Error::NonConvex, long(idx[k]), "polygon doubles back");
          idx.erase_at(k);
          changed = true;
          break;
        }
      }
    }
    if (idx.size() < 3) return ShapeError(Error::Collinear, -1, "polygon vertices are all collinear");
    // All turns are left turns; the boundary must go round exactly once. Count the edges that
    // cross from the lower half-plane of directions into the upper one.
    auto upper = [](const Vec2c& d) { return d.y() > 0 || (d.y() == 0 && d.x() > 0); };
    std::size_t crossings = 0;
    for (std::size_t k = 0; k < idx.size(); ++k) {
      const bool u0 = upper(at(k + 1) - at(k));
      const bool u1 = upper(at(k + 2) - at(k + 1));
      if (!u0 && u1) {
        if (++crossings > 1)
          return ShapeError(Error::NonConvex, long(idx[(k + 1) % idx.size()]), "polygon winds more than once");
      }
    }
    ConvexPolygon poly;
    poly.size_ = idx.size();
    if (poly.size_ > kInline) poly.heap_.resize(poly.size_);
    Vec2<T>* out = poly.size_ > kInline ? poly.heap_.data() : poly.inline_.data();
    for (std::size_t k = 0; k < idx.size(); ++k) out[k] = vertices[idx[k]];
    poly.cache_box();
    poly.cache_normals();
    return poly;
  }
  /// Convex hull of any point set (monotone chain on the exact orient(); collinear points on the
  /// hull's edges are dropped). Errors: NonFinite, OutOfRange, TooFewVertices, Collinear.
  static Expected<ConvexPolygon> make_hull(std::span<const Vec2<T>> points) {
    ShapeError e = detail::placeholder_error();
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!detail::check_value(points[i].x(), long(2 * i), &e)) return e;
      if (!detail::check_value(points[i].y(), long(2 * i + 1), &e)) return e;
    }
    std::size_t distinct = 0;
    const detail::HullPoints<T> h = detail::hull_points(points, distinct);
    if (distinct < 3) return ShapeError(Error::TooFewVertices, -1, "fewer than 3 distinct points");
    if (h.size() < 3) return ShapeError(Error::Collinear, -1, "points are all collinear");
    return make(h.span());
  }
  /// As make(std::span), from a braced list.
  static Expected<ConvexPolygon> make(std::initializer_list<Vec2<T>> vertices) {
    return make(std::span<const Vec2<T>>(vertices.begin(), vertices.size()));
  }
  /// As make(), throwing the ShapeError.
  explicit ConvexPolygon(std::span<const Vec2<T>> vertices) : ConvexPolygon(make(vertices).value()) {}
  /// As make(), from a braced list, throwing the ShapeError.
  ConvexPolygon(std::initializer_list<Vec2<T>> vertices) : ConvexPolygon(make(vertices).value()) {}

  /// Counter-clockwise vertices.
  std::span<const Vec2<T>> vertices() const noexcept {
    return {size_ > kInline ? heap_.data() : inline_.data(), size_};
  }
  /// Number of vertices, >= 3.
  std::size_t size() const noexcept { return size_; }
  /// Vertex i, counter-clockwise. Precondition: i < size().
  const Vec2<T>& operator[](std::size_t i) const noexcept { return vertices()[i]; }

 private:
  friend struct detail::ShapeAccess;
  friend struct detail::PolygonAccess;
  ConvexPolygon() = default;
  /// The box of the vertices, so that a pair of boxes apart is told without reading them.
  void cache_box() noexcept {
    lo_ = hi_ = vertices()[0];
    for (const Vec2<T>& p : vertices()) {
      lo_ = lo_.cwiseMin(p);
      hi_ = hi_.cwiseMax(p);
    }
  }
  /// Every edge's unit outward normal, for the contact paths, and the turn margin, for images
  /// (polygons of at most kInline vertices).
  void cache_normals() noexcept {
    if (size_ > kInline) return;
    for (std::size_t k = 0; k < size_; ++k)
      normals_[k] = detail::edge_normal(widen(inline_[k]), widen(inline_[detail::next_index(k, size_)]));
    normals_cached_ = true;
    turn_margin_ = detail::turn_margin(size_, [&](std::size_t k) { return widen(inline_[k]); });
  }
  std::array<Vec2<T>, kInline> inline_{};
  std::vector<Vec2<T>> heap_;
  std::size_t size_ = 0;
  Vec2<T> lo_ = Vec2<T>::Zero(), hi_ = Vec2<T>::Zero();  ///< the smallest and largest coordinates of the vertices
  std::array<Vec2c, kInline> normals_{};
  bool normals_cached_ = false;
  Calc turn_margin_ = 0;  ///< detail::turn_margin() of the vertices, or 0 (not computed)
};

namespace detail {
/// A polygon's cached unit edge normals, or nullptr when it has none (more than kInline vertices,
/// or an image of a polygon that has none). A polygon made by the factories caches
/// detail::edge_normal of each edge, bit for bit; an image keeps its stored polygon's, turned by
/// the image's rotation.
struct PolygonAccess {
  template <Scalar T>
  static const Vec2c* normals(const ConvexPolygon<T>& s) noexcept {
    return s.normals_cached_ ? s.normals_.data() : nullptr;
  }
  /// The smallest and largest coordinates of the polygon's vertices (cached by every polygon).
  template <Scalar T>
  static std::pair<Vec2<T>, Vec2<T>> box(const ConvexPolygon<T>& s) noexcept {
    return {s.lo_, s.hi_};
  }
  /// The largest absolute coordinate of the polygon's vertices: that of a corner of their box.
  template <Scalar T>
  static Calc largest_coordinate(const ConvexPolygon<T>& s) noexcept {
    return std::max(widen(s.lo_).cwiseAbs().maxCoeff(), widen(s.hi_).cwiseAbs().maxCoeff());
  }
  /// The polygon's cached turn_margin(), or 0 when it has none.
  template <Scalar T>
  static Calc turn_margin(const ConvexPolygon<T>& s) noexcept {
    return s.turn_margin_;
  }
};

/// Builds shapes from values already known valid (images, exact widenings).
struct ShapeAccess {
  template <Scalar T>
  static Circle<T> circle(const Vec2<T>& c, T r) noexcept {
    return Circle<T>(Unchecked{}, c, r);
  }
  template <Scalar T>
  static Aabb<T> aabb(const Vec2<T>& lo, const Vec2<T>& hi) noexcept {
    return Aabb<T>(Unchecked{}, lo, hi);
  }
  template <Scalar T>
  static Obb<T> obb(const Vec2<T>& c, const Vec2<T>& h, const Vec2<T>& u) noexcept {
    return Obb<T>(Unchecked{}, c, h, u);
  }
  template <Scalar T>
  static Capsule<T> capsule(const Vec2<T>& a, const Vec2<T>& b, T r) noexcept {
    return Capsule<T>(Unchecked{}, a, b, r);
  }
  /// A polygon of n >= 1 vertices, vertex k = at(k) (called once for each k, in order), with its
  /// box; allocates only beyond kInline vertices.
  template <Scalar T, class At>
  static ConvexPolygon<T> polygon(std::size_t n, At&& at) {
    ConvexPolygon<T> poly;
    poly.size_ = n;
    if (n > ConvexPolygon<T>::kInline) poly.heap_.resize(n);
    Vec2<T>* out = n > ConvexPolygon<T>::kInline ? poly.heap_.data() : poly.inline_.data();
    Vec2<T> lo = at(0), hi = lo;
    out[0] = lo;
    for (std::size_t k = 1; k < n; ++k) {
      const Vec2<T> v = at(k);
      out[k] = v;
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    poly.lo_ = lo;
    poly.hi_ = hi;
    return poly;
  }
  /// Caches normal(k) as edge k's unit outward normal (a polygon of at most kInline vertices).
  template <Scalar T, class Normal>
  static void cache_normals(ConvexPolygon<T>& poly, Normal&& normal) noexcept {
    for (std::size_t k = 0; k < poly.size_; ++k) poly.normals_[k] = normal(k);
    poly.normals_cached_ = true;
  }
};
}  // namespace detail

/// One child of a compound: any shape but a compound.
template <Scalar T>
using Primitive = std::variant<Circle<T>, Aabb<T>, Obb<T>, Capsule<T>, ConvexPolygon<T>>;

/// The union of a non-empty list of primitives, with a cached conservative bounding box checked
/// before any child (the bounding-box early-out). Defined in compound.hpp.
template <Scalar T>
class Compound;

}  // namespace collide
