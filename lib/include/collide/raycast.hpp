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
///
/// raycast_exit() answers the other question for a ray that starts inside: where it leaves.
/// - Origin in the closed shape (the exact contains()): the exit is the largest t in [0, max_t]
///   such that every ray point with parameter in [0, t] lies in the shape, with the shape's unit
///   outward normal there. A compound is the union of its children: the exit is where the ray
///   leaves the union, not where it leaves the child it started in. A ray that is still inside at
///   max_t (a zero direction included) exits at t = max_t with normal (0, 0).
/// - Origin outside the shape, or a NaN or infinite ray or max_t, or max_t < 0: nothing. (To pass
///   through a shape from outside, raycast() to the entry, then raycast_exit() from a point
///   inside.)
///
/// Error contract of raycast_exit() (delta = raycast_exit_tolerance(shape, ray), the same formula
/// as raycast_tolerance()): t is in [0, max_t]; |origin + t * direction - point| obeys raycast()'s
/// bound; no ray point with parameter in [0, t] is farther than delta outside the shape (a gap
/// in a compound narrower than 2 delta may be crossed); for normal != (0, 0) the point is not
/// deeper than delta inside the shape, so the reported exit is neither before nor after the exact
/// one except where the ray runs within delta of the boundary; and the normal is outward there.

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

/// A ray's finite, nonzero direction d as u * len_s * 2^e, u of unit length and len_s in
/// [0.5, 1.5): scaled by a power of two first (exact), then normalised, so nothing overflows.
struct ScaledDirection {
  Vec2c u;
  Calc len_s = 0;
  int e = 0;
  explicit ScaledDirection(const Vec2c& d) noexcept {
    static_cast<void>(std::frexp(d.cwiseAbs().maxCoeff(), &e));
    const Vec2c ds(std::ldexp(d.x(), -e), std::ldexp(d.y(), -e));
    len_s = ds.norm();
    u = ds / len_s;
  }
  /// The distance along u at ray parameter t: t |d|.
  Calc distance(Calc t) const noexcept { return std::ldexp(t * len_s, e); }
  /// The ray parameter t = s / |d| at distance s along u, ordered so that neither step
  /// overflows.
  Calc time(Calc s) const noexcept { return e > 0 ? std::ldexp(s, -e) / len_s : std::ldexp(s / len_s, -e); }
};

/// A ray parameter in T rounded toward 0, so that the ray up to it stays before the point it
/// names: rounded to nearest, a subnormal t may land a whole denorm_min * |direction| past it.
template <Scalar T>
T toward_zero(Calc t) noexcept {
  T rounded = static_cast<T>(t);
  if (Calc(rounded) > t) rounded = std::nextafter(rounded, T(0));
  return rounded;
}

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
  const ScaledDirection dir(d);
  if (inside) return RayHit<T>{T(0), ray.origin, Vec2<T>((-dir.u).template cast<T>())};

  UnitRay r{o, dir.u, dir.distance(tmax), 0};
  const Calc m = std::max(scale_of(calc_bounds(shape)), o.cwiseAbs().maxCoeff());
  r.pad = 4 * kUnitRoundoff * m + 16 * kSmallestDouble;  // no 2^-500 floor: tiny shapes are rescaled
  const std::optional<UnitRayHit> h = visit_shape(shape, [&](const auto& x) { return ray_concrete(x, r); });
  if (!h) return std::nullopt;
  const Calc t = dir.time(h->s);
  if (!(t <= tmax)) return std::nullopt;
  const Vec2c point = o + dir.u * h->s;
  // No ray point before the hit's t is deeper than the hit.
  return RayHit<T>{toward_zero<T>(t), point.template cast<T>(), h->normal.template cast<T>()};
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

namespace detail {

/// The stretch of the ray's line inside one convex piece, as distances along the unit ray (enter
/// may be negative), and the unit outward normal where the line leaves the piece.
struct LineSpan {
  Calc enter;
  Calc exit;
  Vec2c exit_normal;
  int face = -1;  ///< the half-plane left (half_planes_span), -1 otherwise
};

/// The line against a disk (centre c, radius r >= 0); the exit is computed from the perpendicular
/// offset h, as in ray_disk(), so that a chord near the rim loses no precision.
inline std::optional<LineSpan> disk_span(const Vec2c& c, Calc r, const UnitRay& ray) noexcept {
  const Vec2c m = ray.o - c;
  const Calc b = m.dot(ray.u);
  const Vec2c h = m - ray.u * b;
  const Calc h2 = h.squaredNorm(), r2 = r * r;
  if (h2 > r2) return std::nullopt;
  const Calc root = std::sqrt(r2 - h2);
  const Vec2c n = h + ray.u * root;  // the exit point, from the centre
  return LineSpan{-b - root, root - b, n != Vec2c::Zero() ? unit_of(n) : Vec2c(ray.u)};
}

/// The line against half-planes n_i . x <= n_i . p_i (outward normals, any length), as in
/// ray_half_planes(): the exit is the nearest face the line leaves through.
template <class Plane>
std::optional<LineSpan> half_planes_span(std::size_t count, Plane&& plane, const UnitRay& ray) {
  Calc enter = -std::numeric_limits<Calc>::infinity(), exit = std::numeric_limits<Calc>::infinity();
  Vec2c exit_n = ray.u;
  int exit_face = -1;
  for (std::size_t i = 0; i < count; ++i) {
    Vec2c n, p;
    plane(i, n, p);
    const Calc num = n.dot(ray.o - p);
    const Calc den = n.dot(ray.u);
    if (den == 0) {
      if (num > 0) return std::nullopt;  // parallel, outside this face
      continue;
    }
    const Calc s = -num / den;
    if (den < 0) {
      enter = std::max(enter, s);
    } else if (s < exit) {
      exit = s;
      exit_n = n;
      exit_face = int(i);
    }
  }
  if (!(enter <= exit) || !std::isfinite(exit)) return std::nullopt;
  return LineSpan{enter, exit, exit_n != Vec2c::Zero() ? unit_of(exit_n) : Vec2c(ray.u), exit_face};
}

/// The line against a closed segment [a, b] (zero thickness): along it (parallel within the
/// direction's rounding, and on its line within the pad), the stretch between its ends; across
/// it, the one crossing point, left through the side the ray heads to.
inline std::optional<LineSpan> segment_span(const Vec2c& a, const Vec2c& b, const UnitRay& ray) noexcept {
  const Vec2c w = b - a, ao = a - ray.o;
  const Calc den = cross(ray.u, w);
  const Calc wl = w.cwiseAbs().sum();
  if (std::fabs(den) <= 8 * kUnitRoundoff * wl) {
    if (std::fabs(cross(ao, ray.u)) > ray.pad) return std::nullopt;
    const Calc sa = ao.dot(ray.u), sb = (b - ray.o).dot(ray.u);
    const Vec2c along = sb >= sa ? unit_of(w) : unit_of(Vec2c(-w));
    return LineSpan{std::min(sa, sb), std::max(sa, sb), along};
  }
  const Calc s = cross(ao, w) / den;
  const Calc v = cross(ao, ray.u) / den;
  if (v < 0 || v > 1) return std::nullopt;
  Vec2c n = perp(w);
  if (n.dot(ray.u) < 0) n = -n;
  return LineSpan{s, s, unit_of(n)};
}

/// The wider of two spans of pieces of one convex shape (their union is the shape's span); on a
/// tie of exits the first keeps its normal.
inline std::optional<LineSpan> span_union(std::optional<LineSpan> a, const std::optional<LineSpan>& b) noexcept {
  if (!a) return b;
  if (!b) return a;
  a->enter = std::min(a->enter, b->enter);
  if (b->exit > a->exit) {
    a->exit = b->exit;
    a->exit_normal = b->exit_normal;
    a->face = b->face;
  }
  return a;
}

/// The line against a dilated core (point + r, segment + r, or convex polygon + 0).
inline std::optional<LineSpan> core_span(const Core& c, const UnitRay& ray) {
  if (c.size() == 1) return disk_span(c[0], c.radius, ray);
  if (c.size() == 2) {
    if (!(c.radius > 0)) return segment_span(c[0], c[1], ray);
    // Capsule: its span is the union of its end disks' and its rectangle's (each a convex piece
    // of it). A rectangle left through an end face was left on that end's disk (its normal).
    std::optional<LineSpan> best = span_union(disk_span(c[0], c.radius, ray), disk_span(c[1], c.radius, ray));
    const Vec2c t = unit_of(Vec2c(c[1] - c[0])), n = perp(t);
    const auto plane = [&](std::size_t i, Vec2c& nn, Vec2c& p) {
      nn = i == 0 ? n : i == 1 ? Vec2c(-n) : i == 2 ? t : Vec2c(-t);
      p = i == 0 ? Vec2c(c[0] + n * c.radius) : i == 1 ? Vec2c(c[0] - n * c.radius) : i == 2 ? c[1] : c[0];
    };
    std::optional<LineSpan> rect = half_planes_span(4, plane, ray);
    if (rect && rect->face >= 2) {
      const Vec2c m = ray.o + ray.u * rect->exit - (rect->face == 2 ? c[1] : c[0]);
      if (m != Vec2c::Zero()) rect->exit_normal = unit_of(m);
    }
    return span_union(best, rect);
  }
  const std::size_t n = c.size();
  const auto plane = [&](std::size_t i, Vec2c& nn, Vec2c& p) {
    const Vec2c e = c[next_index(i, n)] - c[i];
    nn = Vec2c(e.y(), -e.x());
    p = c[i];
  };
  return half_planes_span(n, plane, ray);
}

/// One primitive's span along the ray, cut to its bounding box's span within [0, s_max] (nothing
/// when the ray misses the box), its exit +infinity when the ray ends inside it: the cast starts
/// at the box entry, so products stay at the shape's scale, and tiny shapes are rescaled exactly,
/// as in ray_primitive().
template <PrimitiveShape P>
std::optional<LineSpan> primitive_span(const P& shape, const UnitRay& ray) {
  const Aabb<scalar_of_t<P>> box = bounds(shape);
  const std::optional<Span> span = ray_box_span(widen(box.min()), widen(box.max()), ray);
  if (!span) return std::nullopt;
  const Calc entry = span->enter;
  UnitRay local = ray;
  local.o = ray.o + ray.u * entry;
  local.s_max = span->exit - entry;
  const Core core = core_of(shape);
  Core origin;
  origin.push(local.o);
  std::optional<LineSpan> h;
  if (const int k = tiny_scale(core, origin); k != 0) {
    UnitRay scaled_ray = local;
    scaled_ray.o = Vec2c(std::ldexp(local.o.x(), k), std::ldexp(local.o.y(), k));
    scaled_ray.s_max = std::ldexp(local.s_max, k);
    scaled_ray.pad = std::ldexp(local.pad, k);
    h = core_span(scaled(core, k), scaled_ray);
    if (h) {
      h->enter = std::ldexp(h->enter, -k);
      h->exit = std::ldexp(h->exit, -k);
    }
  } else {
    h = core_span(core, local);
  }
  if (!h) return std::nullopt;
  h->enter += entry;
  if (span->exit == ray.s_max && !(h->exit < local.s_max)) {
    h->exit = std::numeric_limits<Calc>::infinity();  // still inside where the ray ends
  } else {
    h->exit = std::min(h->exit, local.s_max) + entry;  // the box ends any rounded sliver
  }
  return h;
}

/// Where a ray starting in the shape leaves it: the end of the chain of spans that starts at 0,
/// each span joining it when it begins no later than `join` past the chain's end (children that
/// touch or overlap along the ray). For a primitive this is its one span. Each pass recomputes
/// the children's spans rather than keeping them, so that the query does not allocate.
template <class S>
LineSpan exit_concrete(const S& shape, const UnitRay& ray, Calc join) {
  // Seeded by the spans holding the origin, even one left right there (an origin on the
  // boundary heading out leaves at 0 through that span's face).
  LineSpan out{0, -std::numeric_limits<Calc>::infinity(), ray.u};
  for (bool grew = true; grew;) {
    grew = false;
    for_each_primitive(shape, [&](const auto& x) {
      const std::optional<LineSpan> h = primitive_span(x, ray);
      if (h && h->enter <= std::max(out.exit, Calc(0)) + join && h->exit >= -join && h->exit > out.exit) {
        out.exit = h->exit;
        out.exit_normal = h->exit_normal;
        grew = true;
      }
    });
  }
  return out;
}

/// raycast_exit() with its result in T, for a stored shape.
template <Scalar T, class S>
std::optional<RayHit<T>> raycast_exit_as(const S& shape, const Ray<T>& ray, T max_t) {
  const Vec2c o = widen(ray.origin), d = widen(ray.direction);
  const Calc tmax = max_t;
  if (!o.allFinite() || !d.allFinite() || !std::isfinite(tmax) || tmax < 0) return std::nullopt;
  if (!visit_shape(shape, [&](const auto& x) { return contains_concrete(x, o); })) return std::nullopt;
  const auto stays = [&] { return RayHit<T>{max_t, Vec2<T>((o + d * tmax).template cast<T>()), Vec2<T>::Zero()}; };
  const Calc dm = d.cwiseAbs().maxCoeff();
  if (dm == 0) return stays();
  const ScaledDirection dir(d);
  UnitRay r{o, dir.u, dir.distance(tmax), 0};
  const Calc m = std::max(scale_of(calc_bounds(shape)), o.cwiseAbs().maxCoeff());
  r.pad = 4 * kUnitRoundoff * m + 16 * kSmallestDouble;
  // Children that touch along the ray join across their spans' rounding (a few pads), well
  // within the bound.
  const LineSpan h = visit_shape(shape, [&](const auto& x) { return exit_concrete(x, r, 4 * r.pad); });
  if (!(h.exit < r.s_max)) return stays();
  const Calc s = std::max(Calc(0), h.exit);
  const Calc t = dir.time(s);
  if (!(t < tmax)) return stays();
  const Vec2c point = o + dir.u * s;
  // The ray up to the exit's t stays in the shape.
  return RayHit<T>{toward_zero<T>(t), point.template cast<T>(), h.exit_normal.template cast<T>()};
}

}  // namespace detail

/// The error bound delta of raycast_exit() (see the contract at the top of this file): the same
/// formula as raycast_tolerance().
template <AnyShape S>
Calc raycast_exit_tolerance(const S& shape, const Ray<scalar_of_t<S>>& ray) {
  return raycast_tolerance(shape, ray);
}

/// Where a ray starting in the closed shape leaves it: the largest t in [0, max_t] with the whole
/// ray up to t in the shape, the point there and the unit outward normal; t = max_t with normal
/// (0, 0) when the ray is still inside at max_t. A compound is left where the ray leaves the union
/// of its children. Nothing for an origin outside the shape, and for NaN or infinite values or
/// max_t < 0. Error: see raycast_exit_tolerance() and the contract at the top of raycast.hpp.
template <AnyShape S>
std::optional<RayHit<scalar_of_t<S>>> raycast_exit(const S& shape, const Ray<scalar_of_t<S>>& ray,
                                                   scalar_of_t<S> max_t) {
  return detail::raycast_exit_as<scalar_of_t<S>>(shape, ray, max_t);
}

}  // namespace collide
