#pragma once
/// @file mass.hpp
/// Mass properties of every shape: its mass, centroid and rotational inertia, as a rigid body needs
/// them for each of its fixtures.
///
/// Meaning (the one definition): a shape of uniform density rho has
/// - mass = rho * area;
/// - centroid = the centroid of its area (the same for every density);
/// - inertia = rho * (the integral of |x - centroid|^2 over the shape): the rotational inertia
///   about the centroid, the axis out of the plane;
/// - origin_inertia = the same about the origin (0, 0) of the frame the centroid is given in:
///   inertia + mass |centroid|^2.
/// The shape is the point set its stored values define: an OBB is the rectangle center +- hx u
/// +- hy perp(u) with its stored axis u (sides 2 hx |u| and 2 hy |u|, |u| being 1 up to a rounding
/// of T); a capsule is a rectangle 2 r wide along its segment with a half disk at each end. A shape
/// without area (a circle or capsule of radius 0, a flat box) has mass and inertia 0 and its
/// centroid at the middle of its core (the point or the segment).
/// A compound is a body with one fixture per child: its mass properties are the sum of its
/// children's, so children that overlap count twice (the union is not computed). A child placed
/// by a transform keeps its mass and its inertia about its centroid, and its centroid is the
/// transform's exact image of the child's. A compound whose children all lack area has the mean
/// of their centroids as its centroid.
/// A shape placed by a transform x (the forms with a Transform): the centroid is x's exact image
/// of the shape's; mass and inertia are the shape's, to the bit; origin_inertia is about the world
/// origin.
///
/// Computation: in double, from the stored values taken relative to a point of the shape (a vertex,
/// a centre, an end) and scaled by a power of two (exact), so that the error follows the shape's
/// size rather than its distance from the origin and no product underflows or overflows; each
/// output is rounded to T once. An exact move (translated() moving every stored value exactly)
/// leaves mass and inertia unchanged to the bit.
///
/// Error contract (the one definition), with u = 2^-53, eps = T's epsilon, d = T's smallest
/// subnormal, n = the number of vertices (a polygon's, 4 for each other primitive, summed over a
/// compound's children), W = the largest side of bounds(s), L = 0 (for a compound with child
/// transforms, its local_extent()), S = the largest absolute coordinate of bounds(s) (plus
/// |position|_inf of x for the placed forms), and m, I, I_O the exact mass, inertia and origin
/// inertia:
/// - mass within (8 n u + eps) m + d;
/// - each coordinate of the centroid within c + eps S + d, c = 16 n u W + 16 u L + 4 u S;
/// - inertia within i + eps I + d, i = (64 n u W^2 + 32 u W L) m;
/// - origin_inertia within i + 16 n u m S^2 + 4 m S c + (4 u + eps) I_O + d.
/// mass_tolerance() gives these bounds, computed from the computed values taken high by their own
/// error. Errors: a density that is NaN or infinite is Error::NonFinite, one below 0
/// Error::NegativeDensity; a mass, inertia or origin inertia above T's largest finite value is
/// Error::OutOfRange (a float box 2^64 wide, a density of 10^38). A density of 0 gives mass and
/// inertia 0 and the centroid.

#include "collide/bounds.hpp"
#include "collide/compound.hpp"
#include "collide/config.hpp"
#include "collide/error.hpp"
#include "collide/predicates.hpp"
#include "collide/shape_traits.hpp"
#include "collide/shapes.hpp"
#include "collide/transform.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cstdint>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <type_traits>
#include <variant>

namespace collide {

/// The mass properties of a shape of uniform density (see the contract at the top of this file).
template <Scalar T>
struct MassProperties {
  T mass = 0;                          ///< density * area
  Vec2<T> centroid = Vec2<T>::Zero();  ///< the centre of mass: the area's centroid
  T inertia = 0;                       ///< rotational inertia about the centroid
  T origin_inertia = 0;                ///< rotational inertia about the origin: inertia + mass |centroid|^2
};

/// The error bounds of mass_properties(), one per output (the centroid's per coordinate).
struct MassTolerance {
  Calc mass = 0;            ///< of MassProperties::mass
  Calc centroid = 0;        ///< of each coordinate of MassProperties::centroid
  Calc inertia = 0;         ///< of MassProperties::inertia
  Calc origin_inertia = 0;  ///< of MassProperties::origin_inertia
};

namespace detail {

/// x * 2^k rounded once, as std::ldexp: one product when 2^k is a normal double (every call but
/// those of shapes near the range's ends), without ldexp's library call.
inline Calc times_power_of_two(Calc x, int k) noexcept {
  if (k >= -1022 && k <= 1023) [[likely]]
    return x * std::bit_cast<Calc>(std::uint64_t(k + 1023) << 52);
  return std::ldexp(x, k);
}

/// The k with |x| 2^k in [1, 2) (0 for x = 0): the power of two that brings x to unit scale. Read
/// from the exponent field for normal x, as std::ilogb would give it.
inline int unit_shift(Calc x) noexcept {
  const int field = int((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff);
  if (field != 0) [[likely]]
    return 1023 - field;
  return x == 0 ? 0 : -std::ilogb(x);
}

/// A number f * 2^e, f 0 or in [0.5, 1): a mass property while it is assembled, so that products
/// of the density, an area and a squared length can leave double's range before the one rounding
/// to T (a tiny shape's inertia, a huge one's area).
struct Scaled {
  Calc f = 0;
  int e = 0;
};
/// x * 2^e as a Scaled (exact), for a finite x: f and the exponent read from x's bits when x is
/// normal, as std::frexp would give them.
inline Scaled scaled(Calc x, int e = 0) noexcept {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const int field = int((bits >> 52) & 0x7ff);
  if (field != 0) [[likely]]
    return {std::bit_cast<Calc>((bits & 0x800fffffffffffffULL) | (std::uint64_t(1022) << 52)), field - 1022 + e};
  if (x == 0) return {};
  int k = 0;
  const Calc f = std::frexp(x, &k);
  return {f, k + e};
}
/// The product, rounded once.
inline Scaled operator*(const Scaled& a, const Scaled& b) noexcept {
  return scaled(a.f * b.f, a.e + b.e);
}
/// The sum, rounded once (terms below 2^-1074 of the larger are lost).
inline Scaled operator+(const Scaled& a, const Scaled& b) noexcept {
  if (a.f == 0) return b;
  if (b.f == 0) return a;
  const int e = std::max(a.e, b.e);
  return scaled(times_power_of_two(a.f, a.e - e) + times_power_of_two(b.f, b.e - e), e);
}
/// The value in double: infinite above its range, rounded to a subnormal or 0 below it.
inline Calc value_of(const Scaled& s) noexcept {
  return times_power_of_two(s.f, s.e);
}

/// v * 2^k, per coordinate (exact unless the result is subnormal).
inline Vec2c shifted(const Vec2c& v, int k) noexcept {
  return {times_power_of_two(v.x(), k), times_power_of_two(v.y(), k)};
}
/// |v|^2 as a Scaled (v scaled to unit size first: no underflow or overflow).
inline Scaled squared_norm(const Vec2c& v) noexcept {
  const int k = unit_shift(v.cwiseAbs().maxCoeff());
  return scaled(shifted(v, k).squaredNorm(), -2 * k);
}

/// A shape's mass properties at unit density before rounding: its area, its centroid as a stored
/// point (the anchor, exact) plus an offset, and its squared radius of gyration (inertia about the
/// centroid over mass). The offset is held at its own scale so that it keeps its bits for tiny
/// shapes: centroid = anchor + offset 2^-shift.
struct Moments {
  Scaled area;
  Vec2c anchor = Vec2c::Zero();
  Vec2c offset = Vec2c::Zero();
  int shift = 0;
  Scaled gyration;
};

/// The centroid in double: anchor + offset 2^-shift.
inline Vec2c centroid_of(const Moments& m) noexcept {
  return m.anchor + shifted(m.offset, -m.shift);
}

/// Disk of radius r: area pi r^2, gyration r^2 / 2.
template <Scalar T>
Moments moments_of(const Circle<T>& s) noexcept {
  const Scaled r2 = scaled(s.radius()) * scaled(s.radius());
  return {scaled(std::numbers::pi) * r2, widen(s.center()), Vec2c::Zero(), 0, scaled(0.5) * r2};
}

/// Box of sides w: area w.x w.y, gyration (w.x^2 + w.y^2) / 12, anchored at min.
template <Scalar T>
Moments moments_of(const Aabb<T>& s) noexcept {
  const Vec2c lo = widen(s.min()), w = widen(s.max()) - lo;
  const int k = unit_shift(w.maxCoeff());
  const Vec2c wk = shifted(w, k);
  return {scaled(w.x()) * scaled(w.y()), lo, wk * 0.5, k, scaled(wk.squaredNorm() / 12, -2 * k)};
}

/// Rectangle of half sides hx |u| and hy |u|: area 4 hx hy |u|^2, gyration (hx^2 + hy^2) |u|^2 / 3.
template <Scalar T>
Moments moments_of(const Obb<T>& s) noexcept {
  const Calc hx = s.half_extents().x(), hy = s.half_extents().y(), uu = widen(s.axis()).squaredNorm();
  const int k = unit_shift(std::max(hx, hy));
  const Calc ax = times_power_of_two(hx, k), ay = times_power_of_two(hy, k);
  return {scaled(4 * uu) * scaled(hx) * scaled(hy), widen(s.center()), Vec2c::Zero(), 0,
          scaled((ax * ax + ay * ay) * uu / 3, -2 * k)};
}

/// Capsule of radius r around a segment of length l: a rectangle 2r x l and a disk split at its
/// ends. Area r (2 l + pi r); inertia over r about the centroid pi (r^3 / 2 + r l^2 / 4) + 2 r^2 l
/// + l^3 / 6 (the half disks' own inertia moved to their centroids 4r / (3 pi) beyond the ends,
/// then to the middle), so gyration = that / (2 l + pi r). Anchored at a.
template <Scalar T>
Moments moments_of(const Capsule<T>& s) noexcept {
  const Vec2c a = widen(s.a()), d = widen(s.b()) - a;
  const Calc r = s.radius();
  const int k = unit_shift(std::max(d.cwiseAbs().maxCoeff(), r));
  const Vec2c dk = shifted(d, k);
  const Calc rk = times_power_of_two(r, k), lk = dk.norm();
  constexpr Calc pi = std::numbers::pi;
  const Calc across = 2 * lk + pi * rk;
  const Calc turning = pi * (rk * rk * rk / 2 + rk * lk * lk / 4) + 2 * rk * rk * lk + lk * lk * lk / 6;
  const Calc gyration = across > 0 ? turning / across : 0;
  return {scaled(r) * scaled(across, -k), a, dk * 0.5, k, scaled(gyration, -2 * k)};
}

/// Twice the area of the triangle (0, e, f), e and f each given exactly as hi + lo, within 3
/// roundings of its value: Kahan's product difference of the high parts (within 2 roundings of
/// theirs) plus the low parts' cross terms. A triangle thinner than kThinTriangle of its edges'
/// products, where the dropped lo x lo terms could matter, is summed exactly.
inline Calc twice_area(const Vec2c& eh, const Vec2c& el, const Vec2c& fh, const Vec2c& fl) noexcept {
  const Calc w = eh.y() * fh.x();
  const Calc w_error = std::fma(-eh.y(), fh.x(), w);  // exactly w - e.y f.x
  const Calc high = std::fma(eh.x(), fh.y(), -w) + w_error;
  const Calc low = (eh.x() * fl.y() - eh.y() * fl.x()) + (el.x() * fh.y() - el.y() * fh.x());
  const Calc v = high + low;
  if (std::fabs(v) >= kThinTriangle * (std::fabs(eh.x() * fh.y()) + std::fabs(w))) [[likely]]
    return v;
  const Term p[8] = {two_product(eh.x(), fh.y()),  two_product(eh.x(), fl.y()),  two_product(el.x(), fh.y()),
                     two_product(el.x(), fl.y()),  two_product(-eh.y(), fh.x()), two_product(-eh.y(), fl.x()),
                     two_product(-el.y(), fh.x()), two_product(-el.y(), fl.x())};
  const double terms[16] = {p[0].hi, p[0].lo, p[1].hi, p[1].lo, p[2].hi, p[2].lo, p[3].hi, p[3].lo,
                            p[4].hi, p[4].lo, p[5].hi, p[5].lo, p[6].hi, p[6].lo, p[7].hi, p[7].lo};
  return rounded_sum(terms);
}

/// Convex polygon, by a fan of triangles from its first vertex r:
///
///     s   = the power of two that brings the largest |v_k - r| to [2^500, 2^501) (never down:
///           scaling down would drop the low bits of a thin polygon's coordinates)
///     e_k = (v_k - r) 2^s, held exactly as hi + lo (two_sum), and at unit scale u_k = e_k 2^-500
///     for each triangle (r, v_k, v_k+1):
///         w  = twice its area (twice_area: within 3 roundings, however thin)
///         A2 += w;  G += w (u_k + u_k+1);  J += w (u_k.u_k + u_k.u_k+1 + u_k+1.u_k+1)
///     centroid offset = G / (3 A2), gyration = J / (6 A2) - |offset|^2 (about r, then moved)
///
/// Every w is positive and accurate, so the sums lose at most n roundings of their value: the
/// area and centroid are accurate for slivers too, and the gyration loses at most a bounded
/// factor to the move from r to the centroid (the centroid lies within the polygon).
template <Scalar T>
Moments moments_of(const ConvexPolygon<T>& s) noexcept {
  const std::span<const Vec2<T>> v = s.vertices();
  const Vec2c r = widen(v[0]);
  const auto [lo, hi] = PolygonAccess::box(s);
  const Calc reach = std::max((widen(hi) - r).maxCoeff(), (r - widen(lo)).maxCoeff());
  const int k = std::max(0, 500 + unit_shift(reach));
  // 2^k as two factors: k may pass double's largest exponent (a polygon 2^-1000 wide).
  const Calc up1 = times_power_of_two(1, std::min(k, 1000)), up2 = times_power_of_two(1, k - std::min(k, 1000));
  auto edge = [&](std::size_t i, Vec2c& e_hi, Vec2c& e_lo) {
    const Term x = two_sum(Calc(v[i].x()), -r.x()), y = two_sum(Calc(v[i].y()), -r.y());
    e_hi = Vec2c(x.hi * up1 * up2, y.hi * up1 * up2);
    e_lo = Vec2c(x.lo * up1 * up2, y.lo * up1 * up2);
  };
  Calc area2 = 0, turning = 0;
  Vec2c moment = Vec2c::Zero();
  Vec2c e_hi, e_lo, f_hi, f_lo;
  edge(1, e_hi, e_lo);
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    edge(i + 1, f_hi, f_lo);
    const Calc w = twice_area(e_hi, e_lo, f_hi, f_lo);
    const Vec2c eu = e_hi * 0x1p-500, fu = f_hi * 0x1p-500;
    area2 += w;
    moment += w * (eu + fu);
    turning += w * (eu.squaredNorm() + eu.dot(fu) + fu.squaredNorm());
    e_hi = f_hi;
    e_lo = f_lo;
  }
  const Vec2c offset = moment / (3 * area2);
  const Calc gyration = std::max(Calc(0), turning / (6 * area2) - offset.squaredNorm());
  return {scaled(area2 / 2, -2 * k), r, offset, k - 500, scaled(gyration, 2 * (500 - k))};
}

/// A compound's child as the sum sees it: its moments, and its centroid split as anchor + local +
/// offset 2^-shift (offset turned by the child's transform, still at the child's scale).
struct ChildMoments {
  Moments m;
  Vec2c anchor, local, offset;
};

/// Child i of c: without a transform, anchored at its own anchor; with one, anchored at the
/// transform's position, its own anchor turned into the local part.
template <Scalar T>
ChildMoments child_moments(const Compound<T>& c, std::size_t i) {
  ChildMoments k;
  k.m = std::visit([](const auto& p) { return moments_of(p); }, c.children()[i]);
  const Transform<T> x = c.child_transform(i);
  if (x.is_identity()) {
    k.anchor = k.m.anchor;
    k.local = Vec2c::Zero();
    k.offset = k.m.offset;
  } else {
    const Pose pose = x.pose();
    k.anchor = pose.p;
    k.local = pose.rotate(k.m.anchor);
    k.offset = pose.rotate(k.m.offset);
  }
  return k;
}

/// Compound: the children's moments summed, each child's centroid placed by its transform.
///
///     per child i: centroid_i = a_i + l_i + o'_i 2^-shift_i (child_moments)
///     scale: the largest of |a_i - a_0|, |l_i - l_0|, the children's offsets and radii of gyration
///     o_i = (a_i - a_0) + (l_i - l_0) + o'_i 2^-shift_i, at that scale
///     weights w_i = area_i / (the largest area); mean = sum w_i o_i / sum w_i
///     centroid = a_0 + l_0 + mean; gyration = sum w_i (gyration_i + |o_i - mean|^2) / sum w_i
///
/// Three passes, each child's moments computed in each (no allocation, for any number of
/// children); the spread is summed about the mean, not as sum w |o|^2 less the mean's, which
/// would cancel for children far from child 0. The anchors move together under an exact move,
/// and the differences a_i - a_0 with them: mass and inertia keep their bits. Children that all
/// lack area: the mean of their centroids.
template <Scalar T>
Moments moments_of(const Compound<T>& c) {
  const std::size_t count = c.children().size();
  const ChildMoments first = child_moments(c, 0);
  int top_area = INT_MIN, top_size = INT_MIN;
  auto size_exponent = [&](Calc x, int shift) {
    if (x != 0) top_size = std::max(top_size, -unit_shift(x) - shift);
  };
  for (std::size_t i = 0; i < count; ++i) {
    const ChildMoments k = i == 0 ? first : child_moments(c, i);
    if (k.m.area.f != 0) top_area = std::max(top_area, k.m.area.e);
    size_exponent((k.anchor - first.anchor).cwiseAbs().maxCoeff(), 0);
    size_exponent((k.local - first.local).cwiseAbs().maxCoeff(), 0);
    size_exponent(k.offset.cwiseAbs().maxCoeff(), k.m.shift);
    if (k.m.gyration.f != 0) top_size = std::max(top_size, k.m.gyration.e / 2);
  }
  const int shift = top_size == INT_MIN ? 0 : -top_size;
  auto offset_of = [&](const ChildMoments& k) {
    return Vec2c(shifted(k.anchor - first.anchor, shift) + shifted(k.local - first.local, shift) +
                 shifted(k.offset, shift - k.m.shift));
  };
  auto weight_of = [&](const ChildMoments& k) {
    return k.m.area.f == 0 ? Calc(0) : times_power_of_two(k.m.area.f, k.m.area.e - top_area);
  };
  Calc total = 0;
  Vec2c mean = Vec2c::Zero(), plain = Vec2c::Zero();
  for (std::size_t i = 0; i < count; ++i) {
    const ChildMoments k = i == 0 ? first : child_moments(c, i);
    const Vec2c o = offset_of(k);
    total += weight_of(k);
    mean += weight_of(k) * o;
    plain += o;
  }
  Moments out;
  out.anchor = first.anchor;
  out.shift = shift;
  if (total == 0) {
    out.offset = shifted(first.local, shift) + plain / Calc(count);
    return out;
  }
  mean /= total;
  Calc spread = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const ChildMoments k = i == 0 ? first : child_moments(c, i);
    spread += weight_of(k) * (value_of(k.m.gyration * scaled(1, 2 * shift)) + (offset_of(k) - mean).squaredNorm());
  }
  out.offset = shifted(first.local, shift) + mean;
  out.area = scaled(total, top_area);
  out.gyration = scaled(spread / total, -2 * shift);
  return out;
}

/// The moments of any shape (a variant dispatched to its concrete shape).
template <class S>
Moments moments_of_any(const S& s) {
  return visit_shape(s, [](const auto& x) { return moments_of(x); });
}

/// n of the contract: a polygon's vertex count, 4 for each other primitive, summed over children.
template <class S>
std::size_t mass_terms(const S& s) {
  return visit_shape(s, [](const auto& x) -> std::size_t {
    using X = std::remove_cvref_t<decltype(x)>;
    if constexpr (std::is_same_v<X, ConvexPolygon<scalar_of_t<X>>>) {
      return x.size();
    } else if constexpr (is_compound_v<X>) {
      std::size_t n = 0;
      for (const auto& child : x.children()) n += mass_terms(child);
      return n;
    } else {
      return 4;
    }
  });
}

/// L of the contract: a compound's local_extent() when some child has a transform, else 0.
template <class S>
Calc child_placement_extent(const S& s) {
  return visit_shape(s, [](const auto& x) -> Calc {
    if constexpr (is_compound_v<decltype(x)>) {
      return x.has_child_transforms() ? x.local_extent() : 0;
    } else {
      return 0;
    }
  });
}

/// The named error of a density, or nothing when it is valid (finite, >= 0).
template <Scalar T>
std::optional<ShapeError> density_error(T density) noexcept {
  if (!std::isfinite(density)) return ShapeError(Error::NonFinite, -1, "density is NaN or infinite");
  if (density < 0) return ShapeError(Error::NegativeDensity, -1, "density is negative");
  return std::nullopt;
}

/// The outputs of moments m at a valid density, the centroid placed by `body`, each rounded once.
/// Error: OutOfRange when a mass, inertia or origin inertia exceeds T's largest finite value.
template <Scalar T>
Expected<MassProperties<T>> mass_from(const Moments& m, T density, const Pose& body) {
  const Scaled mass = scaled(Calc(density)) * m.area;
  const Scaled inertia = mass * m.gyration;
  Vec2c c = centroid_of(m);
  if (!body.is_identity()) c = body.apply(c);
  const Scaled origin = mass * (m.gyration + squared_norm(c));
  const Calc values[3] = {value_of(mass), value_of(inertia), value_of(origin)};
  for (const Calc x : values) {
    if (!(x <= Calc(std::numeric_limits<T>::max())))
      return ShapeError(Error::OutOfRange, -1, "mass or inertia exceeds the range of T");
  }
  return MassProperties<T>{static_cast<T>(values[0]), c.template cast<T>(), static_cast<T>(values[1]),
                           static_cast<T>(values[2])};
}

/// The bounds of the contract for moments m at a valid density, the centroid placed by `body`;
/// n, w, l, s as there (s with the body's position). The exact values are taken high: the
/// computed ones plus their own bound.
template <Scalar T>
MassTolerance mass_tolerance_of(const Moments& m, T density, const Pose& body, std::size_t n, Calc w, Calc l, Calc s) {
  const Calc u = kUnitRoundoff, eps = std::numeric_limits<T>::epsilon(), d = std::numeric_limits<T>::denorm_min();
  const Calc nu = Calc(n) * u;
  const Calc mass = value_of(scaled(Calc(density)) * m.area) * (1 + 16 * nu);
  const Calc c = 16 * nu * w + 16 * u * l + 4 * u * s;
  const Calc i = (64 * nu * w * w + 32 * u * w * l) * mass;
  const Calc inertia = mass * value_of(m.gyration) + i;
  const Calc reach = body.apply(centroid_of(m)).norm() + 2 * c;  // at least the exact |centroid|
  const Calc origin = inertia + mass * reach * reach;
  MassTolerance out;
  out.mass = (8 * nu + eps) * mass + d;
  out.centroid = c + eps * s + d;
  out.inertia = i + eps * inertia + d;
  out.origin_inertia = i + 16 * nu * mass * s * s + 4 * mass * s * c + (4 * u + eps) * origin + d;
  return out;
}

}  // namespace detail

/// The mass, centroid, inertia about the centroid and inertia about the origin of s with uniform
/// `density` (see the contract at the top of this file: a compound counts overlapping children
/// twice). Errors: NonFinite (density NaN or infinite), NegativeDensity, OutOfRange (a mass or
/// inertia beyond T's range). Never allocates.
template <AnyShape S>
Expected<MassProperties<scalar_of_t<S>>> mass_properties(const S& s, scalar_of_t<S> density = 1) {
  using T = scalar_of_t<S>;
  if (const auto bad = detail::density_error(density)) return *bad;
  return detail::mass_from<T>(detail::moments_of_any(s), density, detail::Pose{});
}

/// mass_properties() of s placed by x: the centroid is x's image of s's, rounded once; mass and
/// inertia are s's, to the bit; origin_inertia is about the world origin.
template <AnyShape S>
Expected<MassProperties<scalar_of_t<S>>> mass_properties(const S& s, const Transform<scalar_of_t<S>>& x,
                                                         scalar_of_t<S> density = 1) {
  using T = scalar_of_t<S>;
  if (const auto bad = detail::density_error(density)) return *bad;
  return detail::mass_from<T>(detail::moments_of_any(s), density, x.pose());
}

/// The error bounds of mass_properties(s, density), per output (see the contract at the top of
/// this file), for a density it accepts.
template <AnyShape S>
MassTolerance mass_tolerance(const S& s, scalar_of_t<S> density = 1) {
  const Aabb<scalar_of_t<S>> box = bounds(s);
  const Calc w = (widen(box.max()) - widen(box.min())).maxCoeff();
  return detail::mass_tolerance_of(detail::moments_of_any(s), density, detail::Pose{}, detail::mass_terms(s), w,
                                   detail::child_placement_extent(s), detail::scale_of(box));
}

/// The error bounds of mass_properties(s, x, density): as mass_tolerance(s, density) with
/// |position|_inf of x added to S.
template <AnyShape S>
MassTolerance mass_tolerance(const S& s, const Transform<scalar_of_t<S>>& x, scalar_of_t<S> density = 1) {
  const Aabb<scalar_of_t<S>> box = bounds(s);
  const Calc w = (widen(box.max()) - widen(box.min())).maxCoeff();
  const Calc reach = detail::scale_of(box) + widen(x.position()).cwiseAbs().maxCoeff();
  return detail::mass_tolerance_of(detail::moments_of_any(s), density, x.pose(), detail::mass_terms(s), w,
                                   detail::child_placement_extent(s), reach);
}

}  // namespace collide
