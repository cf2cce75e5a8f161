#pragma once
/// @file raycast.hpp
/// Ray casts: the first point of a closed shape along a ray.
///
/// Semantics: the ray is origin + t * direction for t >= 0; t is in units of |direction| (a
/// direction of length 2 halves every t). raycast() returns the smallest t in [0, max_t] at which
/// the ray meets the closed shape, the point there and the shape's unit outward normal there.
/// - A ray starting inside or on the shape hits at t = 0 with normal = -direction / |direction|.
/// - A zero direction hits (t = 0, normal = (0, 0)) exactly when the origin is in the shape.
/// - A NaN or infinite coordinate in the ray, a NaN or infinite max_t, or max_t < 0: no hit.
///
/// Error contract (delta = raycast_tolerance(shape, ray)
///   = (64 * 2^-53 + 4 eps_T) * M + 2^-500 + denorm_min_T, M = max(S, |origin|_inf),
///   S = largest absolute coordinate of bounds(shape)):
/// - a returned point lies within delta of the shape (within delta of its boundary unless t = 0),
///   and |origin + t * direction - point| <= delta + (4 eps_T t + denorm_min_T) |direction| (t is
///   rounded to T toward 0, and underflows to 0 for a hit 1e-60 along a 1e33 direction);
/// - no ray point with parameter in [0, t) is deeper than delta inside the shape;
/// - no hit means no ray point with parameter in [0, max_t] is deeper than delta inside the shape.
/// So rays passing within delta of the shape (grazing, or ending within delta of it) may hit or
/// miss; all others are decided as for the exact shape. For AABBs and polygons the t = 0 decision
/// (origin inside) is exact. Normals are rounded unit vectors.

#include "collide/compound.hpp"
#include "collide/detail/contains_point.hpp"
#include "collide/detail/convex_core.hpp"
#include "collide/ray.hpp"
#include "collide/shape_traits.hpp"
#include "collide/tolerances.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

namespace collide {

namespace detail {

/// The ray in the computation type with a unit direction; s is the distance along it.
struct UnitRay {
  Vec2c o;
  Vec2c u;
  Calc s_max;  ///< max_t * |direction| (may be +inf after overflow: a bound only)
  Calc pad;    ///< absolute padding of early-out boxes, a fraction of the error bound
};

struct UnitRayHit {
  Calc s;
  Vec2c normal;
  int face = -1;  ///< the half-plane entered (ray_half_planes), -1 otherwise
};

inline bool closer(const std::optional<UnitRayHit>& h, const std::optional<UnitRayHit>& best) {
  return h && (!best || h->s < best->s);
}

/// Where the ray is inside a box: distances along it.
struct Span {
  Calc enter;
  Calc exit;
};

/// The part of the ray (within s_max) inside the padded box, or nothing if it misses.
inline std::optional<Span> ray_box_span(const Vec2c& lo, const Vec2c& hi, const UnitRay& r) noexcept {
  Calc enter = 0, exit = r.s_max;
  for (int i = 0; i < 2; ++i) {
    const Calc l = lo[i] - r.pad, h = hi[i] + r.pad;
    if (r.u[i] == 0) {
      if (r.o[i] < l || r.o[i] > h) return std::nullopt;
      continue;
    }
    Calc t1 = (l - r.o[i]) / r.u[i], t2 = (h - r.o[i]) / r.u[i];
    if (t1 > t2) std::swap(t1, t2);
    enter = std::max(enter, t1);
    exit = std::min(exit, t2);
  }
  if (!(enter <= exit)) return std::nullopt;
  return Span{enter, exit};
}

/// Ray against a disk (centre c, radius r >= 0). Robust form: the perpendicular offset is computed
/// directly rather than as a difference of squares, so grazing rays lose no precision.
inline std::optional<UnitRayHit> ray_disk(const Vec2c& c, Calc r, const UnitRay& ray) noexcept {
  const Vec2c m = ray.o - c;
  const Calc b = m.dot(ray.u);
  const Calc r2 = r * r;
  if (m.squaredNorm() <= r2) {
    return UnitRayHit{0, m != Vec2c::Zero() ? unit_of(m) : Vec2c(-ray.u)};
  }
  if (b > 0) return std::nullopt;  // outside and moving away
  const Vec2c h = m - ray.u * b;
  const Calc h2 = h.squaredNorm();
  if (h2 > r2) return std::nullopt;
  const Calc s = std::max(Calc(0), -b - std::sqrt(r2 - h2));
  const Vec2c n = ray.o + ray.u * s - c;
  return UnitRayHit{s, n != Vec2c::Zero() ? unit_of(n) : Vec2c(-ray.u)};
}

/// Cyrus-Beck clipping against half-planes n_i . x <= n_i . p_i (outward normals, any length).
/// `plane(i, n, p)` fills the i-th half-plane. A ray starting inside gets s = 0 and the normal of
/// the face it is closest to leaving through backwards (the entering face), else -u.
template <class Plane>
std::optional<UnitRayHit> ray_half_planes(std::size_t count, Plane&& plane, const UnitRay& ray) {
  Calc enter = -std::numeric_limits<Calc>::infinity(), exit = std::numeric_limits<Calc>::infinity();
  Vec2c enter_n = -ray.u;
  int enter_face = -1;
  for (std::size_t i = 0; i < count; ++i) {
    Vec2c n, p;
    plane(i, n, p);
    const Calc num = n.dot(ray.o - p);  // > 0: origin outside this half-plane
    const Calc den = n.dot(ray.u);
    if (den == 0) {
      if (num > 0) return std::nullopt;
      continue;
    }
    const Calc s = -num / den;
    if (den < 0) {
      if (s > enter) {
        enter = s;
        enter_n = n;
        enter_face = int(i);
      }
    } else {
      exit = std::min(exit, s);
    }
  }
  if (!(enter <= exit) || exit < 0 || enter > ray.s_max) return std::nullopt;
  return UnitRayHit{std::max(Calc(0), enter), enter_n != Vec2c::Zero() ? unit_of(enter_n) : Vec2c(-ray.u), enter_face};
}

/// Ray against a closed segment [a, b] (zero thickness).
inline std::optional<UnitRayHit> ray_segment(const Vec2c& a, const Vec2c& b, const UnitRay& ray) noexcept {
  const Vec2c w = b - a, ao = a - ray.o;
  const Calc den = cross(ray.u, w);
  if (den == 0) {
    if (cross(ao, ray.u) != 0) return std::nullopt;  // parallel, off the line
    const Calc sa = ao.dot(ray.u), sb = (b - ray.o).dot(ray.u);
    if (std::max(sa, sb) < 0) return std::nullopt;
    return UnitRayHit{std::max(Calc(0), std::min(sa, sb)), Vec2c(-ray.u)};
  }
  const Calc s = cross(ao, w) / den;
  const Calc v = cross(ao, ray.u) / den;
  if (s < 0 || v < 0 || v > 1) return std::nullopt;
  Vec2c n = perp(w);
  if (n.dot(ray.u) > 0) n = -n;
  return UnitRayHit{s, n != Vec2c::Zero() ? unit_of(n) : Vec2c(-ray.u)};
}

/// Ray against a dilated core (point + r, segment + r, or convex polygon + 0).
inline std::optional<UnitRayHit> ray_core(const Core& c, const UnitRay& ray) {
  if (c.size() == 1) return ray_disk(c[0], c.radius, ray);
  if (c.size() == 2) {
    if (!(c.radius > 0)) return ray_segment(c[0], c[1], ray);
    // Capsule: the union of the two end disks and the rectangle between them; the first hit of a
    // union is the nearest first hit. On ties the disk wins (its normal is the true one).
    std::optional<UnitRayHit> best = ray_disk(c[0], c.radius, ray);
    const std::optional<UnitRayHit> hb = ray_disk(c[1], c.radius, ray);
    if (closer(hb, best)) best = hb;
    const Vec2c w = c[1] - c[0];
    if (w != Vec2c::Zero()) {
      const Vec2c t = unit_of(w), n = perp(t);
      const Vec2c ap = c[0] + n * c.radius, am = c[0] - n * c.radius;
      const auto plane = [&](std::size_t i, Vec2c& nn, Vec2c& p) {
        switch (i) {
          case 0:
            nn = n;
            p = ap;
            break;
          case 1:
            nn = -n;
            p = am;
            break;
          case 2:
            nn = t;
            p = c[1];
            break;
          default:
            nn = -t;
            p = c[0];
            break;
        }
      };
      std::optional<UnitRayHit> hr = ray_half_planes(4, plane, ray);
      // Entered through an end of the rectangle (its tie with that end's disk lost to rounding):
      // the point lies on the disk, and the disk's normal is the surface's (an end is inside).
      if (hr && hr->face >= 2 && hr->s > 0) {
        const Vec2c m = ray.o + ray.u * hr->s - (hr->face == 2 ? c[1] : c[0]);
        if (m != Vec2c::Zero()) hr->normal = unit_of(m);
      }
      if (hr && (!best || hr->s < best->s)) best = hr;
    }
    return best;
  }
  const std::size_t n = c.size();
  const auto plane = [&](std::size_t i, Vec2c& nn, Vec2c& p) {
    const Vec2c e = c[next_index(i, n)] - c[i];
    nn = Vec2c(e.y(), -e.x());
    p = c[i];
  };
  return ray_half_planes(n, plane, ray);
}

/// One primitive: early-out on its bounding box, then start the exact-shape cast from the box
/// entry so that every later product is at the shape's scale (a far origin cannot overflow).
/// The cast also ends at the box exit: the rounded half-planes of a polygon with a very sharp
/// corner (two sides at an angle below their rounding) bound a region reaching far past that
/// corner, and the box is what cuts it off.
template <PrimitiveShape P>
std::optional<UnitRayHit> ray_primitive(const P& shape, const UnitRay& ray) {
  const Aabb<scalar_of_t<P>> box = bounds(shape);
  const std::optional<Span> span = ray_box_span(widen(box.min()), widen(box.max()), ray);
  if (!span) return std::nullopt;
  const Calc entry = span->enter;  // >= 0
  UnitRay local = ray;
  local.o = ray.o + ray.u * entry;
  local.s_max = span->exit - entry;
  const Core core = core_of(shape);
  Core origin;
  origin.push(local.o);
  std::optional<UnitRayHit> h;
  if (const int k = tiny_scale(core, origin); k != 0) {
    // Tiny shape and origin: rescale exactly so that squares do not underflow.
    UnitRay scaled_ray = local;
    scaled_ray.o = Vec2c(std::ldexp(local.o.x(), k), std::ldexp(local.o.y(), k));
    scaled_ray.s_max = std::ldexp(local.s_max, k);
    h = ray_core(scaled(core, k), scaled_ray);
    if (h) h->s = std::ldexp(h->s, -k);
  } else {
    h = ray_core(core, local);
  }
  if (!h || !(h->s <= local.s_max)) return std::nullopt;
  h->s += entry;
  return h;
}

template <class S>
std::optional<UnitRayHit> ray_concrete(const S& shape, const UnitRay& ray) {
  if constexpr (is_compound_v<S>) {
    const Aabb<Calc> box = calc_bounds(shape);
    if (!ray_box_span(box.min(), box.max(), ray)) return std::nullopt;
    std::optional<UnitRayHit> best;
    for_each_primitive(shape, [&](const auto& x) {
      const std::optional<UnitRayHit> h = ray_primitive(x, ray);
      if (closer(h, best)) best = h;
    });
    return best;
  } else {
    return ray_primitive(shape, ray);
  }
}

/// raycast_tolerance() without the placement term, for a shape with this bounding box.
template <Scalar T>
Calc ray_tolerance(const Aabb<T>& box, const Ray<T>& ray) {
  const Calc m = std::max(scale_of(box), widen(ray.origin).cwiseAbs().maxCoeff());
  return (kOverlapErrorFactor * kUnitRoundoff + 4 * Calc(std::numeric_limits<T>::epsilon())) * m + kAbsoluteFloor +
         Calc(std::numeric_limits<T>::denorm_min());
}

}  // namespace detail

/// The error bound delta of raycast() (see the contract at the top of this file):
/// (64 * 2^-53 + 4 eps_T) * max(S, |origin|_inf) + 2^-500 + denorm_min_T.
template <AnyShape S>
Calc raycast_tolerance(const S& shape, const Ray<scalar_of_t<S>>& ray) {
  return detail::ray_tolerance<scalar_of_t<S>>(bounds(shape), ray) + placement_tolerance(shape);
}

namespace detail {

/// raycast() with its result in T, for a shape stored or placed (images, placed compounds).
template <Scalar T, class S>
std::optional<RayHit<T>> raycast_as(const S& shape, const Ray<T>& ray, T max_t) {
  const Vec2c o = widen(ray.origin), d = widen(ray.direction);
  const Calc tmax = max_t;
  if (!o.allFinite() || !d.allFinite() || !std::isfinite(tmax) || tmax < 0) return std::nullopt;
  const bool inside = visit_shape(shape, [&](const auto& x) { return contains_concrete(x, o); });
  const Calc dm = d.cwiseAbs().maxCoeff();
  if (dm == 0) {
    if (!inside) return std::nullopt;
    return RayHit<T>{T(0), ray.origin, Vec2<T>::Zero()};
  }
  // Unit direction without overflow: scale by a power of two first (exact), then normalise.
  int e = 0;
  static_cast<void>(std::frexp(dm, &e));
  const Vec2c ds(std::ldexp(d.x(), -e), std::ldexp(d.y(), -e));
  const Calc len_s = ds.norm();  // |d| = len_s * 2^e
  const Vec2c u = ds / len_s;
  if (inside) return RayHit<T>{T(0), ray.origin, Vec2<T>((-u).template cast<T>())};

  UnitRay r{o, u, std::ldexp(tmax * len_s, e), 0};
  const Calc m = std::max(scale_of(calc_bounds(shape)), o.cwiseAbs().maxCoeff());
  r.pad = 4 * kUnitRoundoff * m + 16 * kSmallestDouble;  // no 2^-500 floor: tiny shapes are rescaled
  const std::optional<UnitRayHit> h = visit_shape(shape, [&](const auto& x) { return ray_concrete(x, r); });
  if (!h) return std::nullopt;
  // t = s / |d| = s / len_s * 2^-e, ordered so that neither step overflows (len_s is in [0.5, 1.5)).
  const Calc t = e > 0 ? std::ldexp(h->s, -e) / len_s : std::ldexp(h->s / len_s, -e);
  if (!(t <= tmax)) return std::nullopt;
  const Vec2c point = o + u * h->s;
  // t rounded toward 0, so that no ray point before it is deeper than the hit: rounded to nearest,
  // a subnormal t may land a whole denorm_min * |direction| past it.
  T rounded = static_cast<T>(t);
  if (Calc(rounded) > t) rounded = std::nextafter(rounded, T(0));
  return RayHit<T>{rounded, point.template cast<T>(), h->normal.template cast<T>()};
}

}  // namespace detail

/// First point of the closed shape along the ray with 0 <= t <= max_t, or nothing.
/// t is in units of |direction|. NaN/inf anywhere in the ray or max_t, or max_t < 0: nothing.
/// Compounds: bounding-box early-out, then the nearest child hit.
/// Error: see raycast_tolerance() and the contract at the top of raycast.hpp.
template <AnyShape S>
std::optional<RayHit<scalar_of_t<S>>> raycast(const S& shape, const Ray<scalar_of_t<S>>& ray, scalar_of_t<S> max_t) {
  return detail::raycast_as<scalar_of_t<S>>(shape, ray, max_t);
}

}  // namespace collide
