#pragma once
/// @file queries.hpp
/// Pair queries: overlaps, contact, resolve, distance, and their error contract.
///
/// Every function accepts any shape type: the six concrete shapes, Primitive<T> or Shape<T>, in
/// either order, with one scalar. Concrete types dispatch at compile time; variants dispatch by
/// std::visit (no virtual call). Reversed argument orders call the same decision, so
/// overlaps(a, b) == overlaps(b, a) holds to the bit.
///
/// Error contract (the one definition; README and the oracle properties refer to it):
/// - S(a, b) = the largest absolute coordinate of bounds(a) and bounds(b).
/// - overlaps(a, b) is exact for every pair and both scalars: it equals the exact answer for the
///   stored values, touching included (decide.hpp); overlap_tolerance(a, b) = 0.
/// - rounding_tolerance(a, b) = 64 * 2^-53 * S + 2^-500 is the error unit of the rounded outputs
///   (contact depth, normal and points, distance, resolution margin).
/// - contact(a, b) exists exactly when overlaps(a, b) is true.
/// - Tiny shapes (every value below 2^-400) have their rounded outputs computed on exactly
///   rescaled cores, so those are relative-accurate; the 2^-500 floor is a bound.
/// - contains() is exact for every kind (contains.hpp); raycast() states its bound in raycast.hpp.

#include "collide/compound.hpp"
#include "collide/decide.hpp"
#include "collide/detail/core.hpp"
#include "collide/registry.hpp"
#include "collide/shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>
#include <vector>

namespace collide {

// ---------------------------------------------------------------------------------------------
// Shape type traits.

template <class S>
struct ScalarOf;
template <Scalar T> struct ScalarOf<Circle<T>> { using type = T; };
template <Scalar T> struct ScalarOf<Aabb<T>> { using type = T; };
template <Scalar T> struct ScalarOf<Obb<T>> { using type = T; };
template <Scalar T> struct ScalarOf<Capsule<T>> { using type = T; };
template <Scalar T> struct ScalarOf<ConvexPolygon<T>> { using type = T; };
template <Scalar T> struct ScalarOf<Compound<T>> { using type = T; };
template <Scalar T, class... Rest>
struct ScalarOf<std::variant<Circle<T>, Rest...>> {
  using type = T;
};

/// The scalar (float or double) of any shape type.
template <class S>
using scalar_of_t = typename ScalarOf<std::remove_cvref_t<S>>::type;

template <class S>
concept PrimitiveShape = requires { typename ScalarOf<S>::type; } &&
    (std::is_same_v<S, Circle<scalar_of_t<S>>> || std::is_same_v<S, Aabb<scalar_of_t<S>>> ||
     std::is_same_v<S, Obb<scalar_of_t<S>>> || std::is_same_v<S, Capsule<scalar_of_t<S>>> ||
     std::is_same_v<S, ConvexPolygon<scalar_of_t<S>>>);

template <class S>
concept ConcreteShape = PrimitiveShape<S> || (requires { typename ScalarOf<S>::type; } &&
                                              std::is_same_v<S, Compound<scalar_of_t<S>>>);

template <class S>
concept VariantShape = requires { typename ScalarOf<S>::type; } &&
    (std::is_same_v<S, Shape<scalar_of_t<S>>> || std::is_same_v<S, Primitive<scalar_of_t<S>>>);

/// Any of the six shapes, Primitive<T> or Shape<T>.
template <class S>
concept AnyShape = ConcreteShape<std::remove_cvref_t<S>> || VariantShape<std::remove_cvref_t<S>>;

namespace detail {

/// Calls f with the concrete shape held by s.
template <class S, class F>
decltype(auto) visit_shape(const S& s, F&& f) {
  if constexpr (VariantShape<S>) {
    return std::visit(f, s);
  } else {
    return f(s);
  }
}

/// Calls f with each primitive of s (s itself, or each child of a compound).
template <class S, class F>
void for_each_primitive(const S& s, F&& f) {
  if constexpr (std::is_same_v<S, Compound<scalar_of_t<S>>>) {
    for (const auto& child : s.children()) std::visit(f, child);
  } else {
    f(s);
  }
}

template <class S>
inline constexpr bool is_compound_v = std::is_same_v<S, Compound<scalar_of_t<S>>>;

/// The pair decision for two primitives in either order.
template <PrimitiveShape A, PrimitiveShape B>
bool decide_primitives(const A& a, const B& b) {
  if constexpr (static_cast<int>(kind_of_v<A>) <= static_cast<int>(kind_of_v<B>)) {
    return decide::pair(a, b);
  } else {
    return decide::pair(b, a);
  }
}

template <ConcreteShape A, ConcreteShape B>
bool overlaps_concrete(const A& a, const B& b) {
  if constexpr (is_compound_v<A> || is_compound_v<B>) {
    // The lecture's hierarchy: the cheap bounding boxes first, then the children.
    if (!decide::aabb_aabb(bounds(a), bounds(b))) return false;
    bool hit = false;
    for_each_primitive(a, [&](const auto& ca) {
      if (hit) return;
      for_each_primitive(b, [&](const auto& cb) { hit = hit || decide_primitives(ca, cb); });
    });
    return hit;
  } else {
    return decide_primitives(a, b);
  }
}

}  // namespace detail

/// Conservative bounding box of any shape (see compound.hpp for the per-shape overloads).
template <class S>
  requires VariantShape<S>
Aabb<scalar_of_t<S>> bounds(const S& s) {
  return std::visit([](const auto& x) { return bounds(x); }, s);
}

/// True when the closed shapes share at least one point (touching counts).
/// Error: exact for every pair (see the contract at the top of this file).
template <AnyShape A, AnyShape B>
  requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>
bool overlaps(const A& a, const B& b) {
  return detail::visit_shape(a, [&](const auto& ca) {
    return detail::visit_shape(b, [&](const auto& cb) { return detail::overlaps_concrete(ca, cb); });
  });
}

/// The error unit of this pair's rounded outputs (contact depth, normal and points, distance,
/// resolution margin): 64 * 2^-53 * S + 2^-500, where S is the largest absolute coordinate of
/// either bounding box. Each query states its bound as a multiple of it.
template <AnyShape A, AnyShape B>
Calc rounding_tolerance(const A& a, const B& b) {
  const Calc s = std::max(detail::scale_of(bounds(a)), detail::scale_of(bounds(b)));
  return kOverlapErrorFactor * 0x1p-53 * s + kAbsoluteFloor;
}

/// The error bound of overlaps() for this pair: 0, since every pair is decided exactly (the band
/// of exact signed distance around touching inside which an answer could differ is empty).
template <AnyShape A, AnyShape B>
Calc overlap_tolerance(const A&, const B&) noexcept {
  return 0;
}

// ---------------------------------------------------------------------------------------------
// Contact.

/// Where two overlapping shapes touch.
template <Scalar T>
struct Contact {
  Vec2<T> normal;  ///< unit vector pointing from a toward b (a moves along -normal to separate)
  T depth;         ///< penetration depth along normal, >= 0 (0 when only touching)
  int count;       ///< number of valid entries in points: 1 or 2
  std::array<Vec2<T>, 2> points;  ///< contact points, midway between the two surfaces
};

namespace detail {

struct ContactC {
  Vec2c normal = Vec2c(1, 0);
  Calc depth = 0;
  int count = 0;
  std::array<Vec2c, 2> points{};
};

/// Contact of two dilated cores known to overlap.
///
///   if the cores are disjoint: normal = closest-point direction, depth = R - distance
///   else: least-penetration face (SAT over both cores' faces); the other core's most
///         anti-parallel face (or its point) is clipped to the reference face's side planes,
///         keeping up to two points within reach of the radii.
inline ContactC contact_cores_at_scale(const Core& p, const Core& q) {
  ContactC out;
  const Calc r = p.radius + q.radius;
  if (!cores_intersect(p, q)) {
    const Closest cl = closest_points(p, q);
    const Calc d = norm_of(cl.on_q - cl.on_p);
    // A gap at the level of rounding (a point that misses a segment through it only because the
    // segment's ends were rounded) has no reliable direction: take the separating axes instead.
    Calc scale = 0;
    for (const Vec2c& x : p.pts()) scale = std::max(scale, x.cwiseAbs().maxCoeff());
    for (const Vec2c& x : q.pts()) scale = std::max(scale, x.cwiseAbs().maxCoeff());
    if (d > kOverlapErrorFactor * 0x1p-53 * scale) {
      out.normal = unit_of(cl.on_q - cl.on_p);
      out.depth = std::max(Calc(0), r - d);
      const Vec2c sp = cl.on_p + out.normal * p.radius, sq = cl.on_q - out.normal * q.radius;
      out.points[0] = (sp + sq) * 0.5;
      out.count = 1;
      return out;
    }
  }
  const Axis ax = least_penetration(p, q);
  out.normal = ax.normal;
  out.depth = std::max(Calc(0), ax.depth);
  if (ax.owner < 0) {
    out.points[0] = (p[0] + q[0]) * 0.5;
    out.count = 1;
    return out;
  }
  const Core& ref = ax.owner == 0 ? p : q;
  const Core& inc = ax.owner == 0 ? q : p;
  const Vec2c nr = ax.owner == 0 ? ax.normal : Vec2c(-ax.normal);
  Vec2c r1, r2;
  if (ref.size() == 2) {
    r1 = ax.face == 0 ? ref[0] : ref[1];
    r2 = ax.face == 0 ? ref[1] : ref[0];
  } else {
    r1 = ref[ax.face];
    r2 = ref[(ax.face + 1) % ref.size()];
  }
  const Vec2c tangent = r2 - r1;
  const Calc len2 = tangent.squaredNorm();
  std::array<Vec2c, 2> ip{};
  int icount = 0;
  if (inc.size() == 1) {
    ip[0] = inc[0];
    icount = 1;
  } else if (inc.size() == 2) {
    ip = {inc[0], inc[1]};
    icount = 2;
  } else {
    std::size_t best = 0;
    Calc best_dot = std::numeric_limits<Calc>::infinity();
    for (std::size_t j = 0; j < inc.size(); ++j) {
      const Vec2c e = inc[(j + 1) % inc.size()] - inc[j];
      const Calc dot = Vec2c(e.y(), -e.x()).dot(nr) / std::max(e.norm(), Calc(1e-300));
      if (dot < best_dot) {
        best_dot = dot;
        best = j;
      }
    }
    // Among faces as anti-parallel as the best up to rounding (a polygon side split by a vertex
    // one ulp off the line), take the one that spans most of the reference face: the other may
    // lie beside it entirely, and clipping would then find nothing.
    Calc best_span = -std::numeric_limits<Calc>::infinity();
    for (std::size_t j = 0; j < inc.size(); ++j) {
      const Vec2c a0 = inc[j], a1 = inc[(j + 1) % inc.size()];
      const Vec2c e = a1 - a0;
      if (Vec2c(e.y(), -e.x()).dot(nr) / std::max(e.norm(), Calc(1e-300)) > best_dot + 0x1p-40) continue;
      const Calc t0 = (a0 - r1).dot(tangent), t1 = (a1 - r1).dot(tangent);
      const Calc span = std::min(std::max(t0, t1), len2) - std::max(std::min(t0, t1), Calc(0));
      if (span > best_span) {
        best_span = span;
        best = j;
      }
    }
    ip = {inc[best], inc[(best + 1) % inc.size()]};
    icount = 2;
  }
  const Calc inc_len2 = icount == 2 ? (ip[1] - ip[0]).squaredNorm() : 0;
  // Clipping an incident face 2^20 times longer than the reference face moves its ends by ulps of
  // the long face, more than the short face is long: skip it and take the witness below.
  const bool ref_tiny = inc_len2 > 0x1p40 * len2;
  bool missed = ref_tiny;
  if (icount == 2 && len2 > 0 && !missed) {
    // Clip the incident segment to 0 <= (x - r1) . tangent <= len2.
    for (int side = 0; side < 2 && !missed; ++side) {
      const Calc lim = side == 0 ? 0 : len2;
      const Calc sgn = side == 0 ? 1 : -1;
      const Calc d0 = sgn * ((ip[0] - r1).dot(tangent) - lim), d1 = sgn * ((ip[1] - r1).dot(tangent) - lim);
      missed = d0 < 0 && d1 < 0;
      if (missed) break;
      if (d0 < 0) ip[0] = ip[0] + (ip[1] - ip[0]) * (d0 / (d0 - d1));
      if (d1 < 0) ip[1] = ip[1] + (ip[0] - ip[1]) * (d1 / (d1 - d0));
    }
  }
  const Calc reach = ref.radius + inc.radius;
  for (int i = 0; i < icount && !missed; ++i) {
    const Calc s = (ip[i] - r1).dot(nr);
    if (s <= reach) out.points[out.count++] = ip[i] + nr * ((ref.radius - s - inc.radius) * 0.5);
  }
  if (out.count == 2 && out.points[0] == out.points[1]) out.count = 1;
  if (out.count == 0) {
    // Clipping found nothing (the incident face misses a short reference face) or was not
    // trusted (a 1e24 incident edge against a 1e-37 box side). The witness is the candidate
    // nearest to both dilated cores: the incident core's deepest vertex moved halfway to the
    // reference surface, the reference face's midpoint moved halfway to the incident surface,
    // or a vertex of either core (often inside the other, when the shapes differ in size by
    // orders of magnitude).
    auto excess = [](const Vec2c& x, const Core& c) {
      Core pt;
      pt.push(x);
      if (cores_intersect(pt, c)) return Calc(0);
      const Closest cl = closest_points(pt, c);
      return std::max(Calc(0), norm_of(cl.on_q - cl.on_p) - c.radius);
    };
    Calc best = std::numeric_limits<Calc>::infinity();
    auto consider_witness = [&](const Vec2c& x) {
      const Calc e = std::max(excess(x, p), excess(x, q));
      if (e < best) {
        best = e;
        out.points[0] = x;
      }
    };
    std::size_t k = 0;
    for (std::size_t j = 1; j < inc.size(); ++j) {
      if ((inc[j] - r1).dot(nr) < (inc[k] - r1).dot(nr)) k = j;
    }
    const Calc s = (inc[k] - r1).dot(nr);
    consider_witness(inc[k] + nr * ((ref.radius - s - inc.radius) * 0.5));
    consider_witness((r1 + r2) * 0.5 + nr * (ref.radius - out.depth * 0.5));
    for (const Vec2c& x : p.pts()) consider_witness(x);
    for (const Vec2c& x : q.pts()) consider_witness(x);
    out.count = 1;
  }
  return out;
}

/// contact_cores_at_scale() after exact rescaling of tiny cores (see detail::tiny_scale).
inline ContactC contact_cores(const Core& p, const Core& q) {
  const int k = tiny_scale(p, q);
  if (k == 0) return contact_cores_at_scale(p, q);
  ContactC c = contact_cores_at_scale(scaled(p, k), scaled(q, k));
  c.depth = std::ldexp(c.depth, -k);
  for (Vec2c& pt : c.points) pt = Vec2c(std::ldexp(pt.x(), -k), std::ldexp(pt.y(), -k));
  return c;
}

/// Distance between two dilated cores that do not overlap (rescaled when tiny).
inline Calc core_gap(const Core& p, const Core& q) {
  const int k = tiny_scale(p, q);
  if (k == 0) return std::sqrt(closest_points(p, q).dist2) - p.radius - q.radius;
  const Core ps = scaled(p, k), qs = scaled(q, k);
  return std::ldexp(std::sqrt(closest_points(ps, qs).dist2) - ps.radius - qs.radius, -k);
}

template <Scalar T>
Contact<T> to_scalar(const ContactC& c) {
  Contact<T> out{};
  out.normal = c.normal.template cast<T>();
  out.depth = static_cast<T>(c.depth);
  out.count = c.count;
  for (int i = 0; i < 2; ++i) out.points[i] = c.points[i].template cast<T>();
  return out;
}

template <ConcreteShape A, ConcreteShape B>
std::optional<ContactC> contact_concrete(const A& a, const B& b) {
  if (!overlaps_concrete(a, b)) return std::nullopt;
  std::optional<ContactC> best;
  for_each_primitive(a, [&](const auto& ca) {
    for_each_primitive(b, [&](const auto& cb) {
      if (!decide_primitives(ca, cb)) return;
      const ContactC c = contact_cores(core_of(ca), core_of(cb));
      if (!best || c.depth > best->depth) best = c;
    });
  });
  return best;
}

}  // namespace detail

/// Contact of two shapes: present exactly when overlaps(a, b). For a compound, the deepest contact
/// among its overlapping child pairs. Coincident circle centres give normal (1, 0).
/// Error: normal and depth are rounded results (depth within a few rounding_tolerance of exact).
template <AnyShape A, AnyShape B>
  requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>
std::optional<Contact<scalar_of_t<A>>> contact(const A& a, const B& b) {
  using T = scalar_of_t<A>;
  const std::optional<detail::ContactC> c = detail::visit_shape(a, [&](const auto& ca) {
    return detail::visit_shape(b, [&](const auto& cb) { return detail::contact_concrete(ca, cb); });
  });
  if (!c) return std::nullopt;
  return detail::to_scalar<T>(*c);
}

// ---------------------------------------------------------------------------------------------
// Translation.

template <Scalar T>
Expected<Circle<T>> translated(const Circle<T>& s, const Vec2<T>& v) {
  return Circle<T>::make(s.center() + v, s.radius());
}
template <Scalar T>
Expected<Aabb<T>> translated(const Aabb<T>& s, const Vec2<T>& v) {
  return Aabb<T>::make(s.min() + v, s.max() + v);
}
template <Scalar T>
Expected<Obb<T>> translated(const Obb<T>& s, const Vec2<T>& v) {
  // Keep the stored axis bit for bit: renormalising would rotate the box by rounding.
  return detail::ObbAccess::with_axis_of<T>(Vec2<T>(s.center() + v), s.half_extents(), s);
}
template <Scalar T>
Expected<Capsule<T>> translated(const Capsule<T>& s, const Vec2<T>& v) {
  return Capsule<T>::make(s.a() + v, s.b() + v, s.radius());
}
/// Rounding the moved vertices to T can break exact convexity; the result is then the convex hull
/// of the moved vertices (it can only lose vertices that became reflex or collinear).
template <Scalar T>
Expected<ConvexPolygon<T>> translated(const ConvexPolygon<T>& s, const Vec2<T>& v) {
  std::vector<Vec2<T>> moved;
  moved.reserve(s.size());
  for (const Vec2<T>& p : s.vertices()) moved.push_back(p + v);
  Expected<ConvexPolygon<T>> r = ConvexPolygon<T>::make(moved);
  if (r || (r.error().code() != Error::NonConvex && r.error().code() != Error::Collinear &&
            r.error().code() != Error::TooFewVertices)) {
    return r;
  }
  return ConvexPolygon<T>::make_hull(moved);
}
template <Scalar T>
Expected<Compound<T>> translated(const Compound<T>& s, const Vec2<T>& v) {
  std::vector<Primitive<T>> moved;
  moved.reserve(s.children().size());
  for (const Primitive<T>& c : s.children()) {
    std::optional<ShapeError> err;
    std::visit(
        [&](const auto& x) {
          auto m = translated(x, v);
          if (m) {
            moved.emplace_back(std::move(m).value());
          } else {
            err = m.error();
          }
        },
        c);
    if (err) return *err;
  }
  return Compound<T>::make(std::move(moved));
}
/// A variant translated: same alternative, moved by v. Errors: those of the shape's factory
/// (NonFinite, OutOfRange when the move leaves the representable range; Collinear when rounding
/// collapses a thin polygon).
template <class S>
  requires VariantShape<S>
Expected<S> translated(const S& s, const Vec2<scalar_of_t<S>>& v) {
  return std::visit(
      [&](const auto& x) -> Expected<S> {
        auto m = translated(x, v);
        if (!m) return m.error();
        return S(std::move(m).value());
      },
      s);
}

// ---------------------------------------------------------------------------------------------
// Resolution.

namespace detail {

/// h(n) = max over the dilated core of x . n, for unit n.
inline Calc dilated_support(const Core& c, const Vec2c& n) { return support(c, n) + c.radius; }

/// v rounded to T with each component's magnitude rounded down, so |result| <= |v|: the push
/// never exceeds depth + margin because of the final rounding.
template <Scalar T>
Vec2<T> round_toward_zero(const Vec2c& v) noexcept {
  Vec2<T> out;
  for (int i = 0; i < 2; ++i) {
    T f = static_cast<T>(v[i]);
    if (std::fabs(static_cast<Calc>(f)) > std::fabs(v[i])) f = std::nextafter(f, T(0));
    out[i] = f;
  }
  return out;
}

/// Push along -n that separates every pair of children that would meet while a slides along -n:
///   t(n) = max over child pairs whose shadows across n overlap (within tol) of  h_a(n) + h_b(-n)
/// (the support gap; for one convex pair along its least-penetration axis it equals the depth).
/// tol covers the rounding of the supports, of n and of a + v to T: shadows that miss by less
/// may still meet. (Without it, a needle lying on a capsule child's own line, 1e-9 from a circle
/// child, was pushed out of the circle and onto the capsule.)
template <ConcreteShape A, ConcreteShape B>
Calc push_along(const A& a, const B& b, const Vec2c& n, Calc tol) {
  const Vec2c side = perp(n);
  Calc t = 0;
  for_each_primitive(a, [&](const auto& ca) {
    const Core pa = core_of(ca);
    for_each_primitive(b, [&](const auto& cb) {
      const Core pb = core_of(cb);
      const bool shadows_meet = dilated_support(pa, side) + tol >= -dilated_support(pb, -side) &&
                                dilated_support(pb, side) + tol >= -dilated_support(pa, -side);
      if (shadows_meet) t = std::max(t, dilated_support(pa, n) + dilated_support(pb, -n));
    });
  });
  return t;
}

}  // namespace detail

/// The margin resolve() adds beyond the computed depth: 4 * 64 * 2^-53 * S (four times the
/// relative part of rounding_tolerance), plus 8 eps_T (S + depth), which covers rounding a's moved
/// coordinates to T, plus 16 subnormal units of double and two of T for rounding near zero (a
/// push along a diagonal moves each coordinate by a whole unit: sqrt(2) units in all).
/// It has no 2^-500 floor: tiny shapes are decided after exact rescaling, so their depths are
/// relative-accurate, and a push of 2^-500 would collapse a subnormal polygon.
template <AnyShape A, AnyShape B>
Calc resolve_margin(const A& a, const B& b, Calc depth) {
  using T = scalar_of_t<A>;
  const Calc s = std::max(detail::scale_of(bounds(a)), detail::scale_of(bounds(b)));
  return 4 * kOverlapErrorFactor * 0x1p-53 * s + 8 * Calc(std::numeric_limits<T>::epsilon()) * (s + depth) +
         16 * 0x1p-1074 + 2 * Calc(std::numeric_limits<T>::denorm_min());
}

/// Minimum translation of a that separates it from b (the lecture's shortest-push rule,
/// generalised): zero if they do not overlap; otherwise -normal * (depth + margin), so a moved by
/// it no longer overlaps b, strictly (margin: resolve_margin(); doubled up to 8 times if the moved
/// shape still tests as overlapping after rounding to T).
///
/// Minimal for the 15 pairs of primitives (depth is the least penetration over the Minkowski
/// difference's faces). For compounds the push is the smallest among the child contacts'
/// directions, each long enough to clear every child it would meet on the way.
///
/// Caveat: a + v may have no representation in T: beyond max_magnitude(), or a polygon (or
/// compound child) thin next to |v| whose vertices round onto one line. translated(a, v) then
/// returns that named error (OutOfRange, Collinear, TooFewVertices); v still separates the exact,
/// unrounded a + v.
template <AnyShape A, AnyShape B>
  requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>
Vec2<scalar_of_t<A>> resolve(const A& a, const B& b) {
  using T = scalar_of_t<A>;
  return detail::visit_shape(a, [&](const auto& ca) {
    return detail::visit_shape(b, [&](const auto& cb) -> Vec2<T> {
      if (!detail::overlaps_concrete(ca, cb)) return Vec2<T>::Zero();
      // A push is at most about the shapes' extent, 2 S.
      const Calc scale = std::max(detail::scale_of(bounds(ca)), detail::scale_of(bounds(cb)));
      const Calc shadow_tol = resolve_margin(ca, cb, 2 * scale);
      Vec2c best_n(1, 0);
      Calc best_t = std::numeric_limits<Calc>::infinity();
      detail::for_each_primitive(ca, [&](const auto& pa) {
        detail::for_each_primitive(cb, [&](const auto& pb) {
          if (!detail::decide_primitives(pa, pb)) return;
          const detail::ContactC c = detail::contact_cores(detail::core_of(pa), detail::core_of(pb));
          const Calc t = detail::is_compound_v<std::remove_cvref_t<decltype(ca)>> ||
                                 detail::is_compound_v<std::remove_cvref_t<decltype(cb)>>
                             ? detail::push_along(ca, cb, c.normal, shadow_tol)
                             : c.depth;
          if (t < best_t) {
            best_t = t;
            best_n = c.normal;
          }
        });
      });
      Calc margin = resolve_margin(ca, cb, best_t);
      Vec2<T> v = detail::round_toward_zero<T>(-best_n * (best_t + margin));
      for (int attempt = 0; attempt < 8; ++attempt) {
        const auto moved = translated(ca, v);
        if (!moved || !detail::overlaps_concrete(moved.value(), cb)) break;
        margin *= 2;
        v = detail::round_toward_zero<T>(-best_n * (best_t + margin));
      }
      return v;
    });
  });
}

// ---------------------------------------------------------------------------------------------
// Distance.

/// Euclidean distance between the closed shapes: 0 when they overlap, otherwise the gap.
/// Error: a rounded result, within a few rounding_tolerance(a, b) of the exact gap.
template <AnyShape A, AnyShape B>
  requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>
scalar_of_t<A> distance(const A& a, const B& b) {
  using T = scalar_of_t<A>;
  return detail::visit_shape(a, [&](const auto& ca) {
    return detail::visit_shape(b, [&](const auto& cb) -> T {
      if (detail::overlaps_concrete(ca, cb)) return T(0);
      Calc best = std::numeric_limits<Calc>::infinity();
      detail::for_each_primitive(ca, [&](const auto& pa) {
        detail::for_each_primitive(cb, [&](const auto& pb) {
          best = std::min(best, detail::core_gap(detail::core_of(pa), detail::core_of(pb)));
        });
      });
      // Separated (decided exactly): a gap that rounds to zero is reported as the least positive T.
      const T gap = static_cast<T>(std::max(Calc(0), best));
      return gap > T(0) ? gap : std::numeric_limits<T>::denorm_min();
    });
  });
}

}  // namespace collide
