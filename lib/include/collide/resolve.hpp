#pragma once
/// @file resolve.hpp
/// The shortest push that separates two shapes, and its margin. Error contract: tolerances.hpp.

#include "collide/compound.hpp"
#include "collide/detail/contact_cores.hpp"
#include "collide/detail/convex_core.hpp"
#include "collide/overlaps.hpp"
#include "collide/shape_traits.hpp"
#include "collide/shapes.hpp"
#include "collide/tolerances.hpp"
#include "collide/translate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <variant>

namespace collide {

namespace detail {

/// h(n) = max over the dilated core of x . n, for unit n.
inline Calc dilated_support(const Core& c, const Vec2c& n) {
  return support(c, n) + c.radius;
}

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
template <class A, class B>
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

/// Whether a, moved by v and rounded to T as translated() would, still overlaps b; nullopt when
/// the move has no representation in T (translated() would return an error). A compound is
/// judged child by child, so that no moved copy of it is built (which would allocate).
template <ConcreteShape A, class B>
std::optional<bool> moved_overlaps(const A& a, const Vec2<scalar_of_t<A>>& v, const B& b) {
  if constexpr (is_compound_v<A>) {
    const auto& kids = a.children();
    bool representable = true;
    for (std::size_t i = 0; i < kids.size(); ++i) {
      if (a.child_transform(i).is_identity()) {
        std::visit([&](const auto& c) { representable = representable && bool(translated(c, v)); }, kids[i]);
      } else {
        representable = representable && bool(a.child_transform(i).moved(v));
      }
    }
    if (!representable) return std::nullopt;
    bool any = false;
    for (std::size_t i = 0; i < kids.size() && !any; ++i) {
      if (a.child_transform(i).is_identity()) {
        std::visit([&](const auto& c) { any = overlaps_concrete(translated(c, v).value(), b); }, kids[i]);
      } else {
        const Pose x = a.child_transform(i).moved(v)->pose();
        std::visit(
            [&](const auto& c) { any = with_image(c, x, [&](const auto& img) { return overlaps_concrete(img, b); }); },
            kids[i]);
      }
    }
    return any;
  } else {
    const auto moved = translated(a, v);
    if (!moved) return std::nullopt;
    return overlaps_concrete(moved.value(), b);
  }
}

/// The margin formula with its magnitudes given: s_pair the computation's scale (the largest
/// coordinate the depth was computed from), s_along the moved shape's stored magnitudes along the
/// push (moved_along(): what rounding them to T can shift it by along the push, over eps_T / 2).
template <Scalar T>
Calc margin_of(Calc s_pair, Calc s_along, Calc depth) noexcept {
  return 4 * kOverlapErrorFactor * kUnitRoundoff * s_pair +
         8 * Calc(std::numeric_limits<T>::epsilon()) * (s_along + depth) + 16 * kSmallestDouble +
         2 * Calc(std::numeric_limits<T>::denorm_min());
}

/// The largest absolute coordinate of a box per axis (x, y).
template <class T>
Vec2c axis_scale(const Aabb<T>& b) noexcept {
  return widen(b.min()).cwiseAbs().cwiseMax(widen(b.max()).cwiseAbs());
}

/// The largest stored magnitude per axis (x, y) that moving s rounds to T: its box's coordinates
/// and, for a compound, the position of each child placed by a transform (a move shifts that
/// position).
template <AnyShape S>
Vec2c moved_scale(const S& s) {
  return visit_shape(s, [](const auto& c) {
    Vec2c m = axis_scale(bounds(c));
    if constexpr (is_compound_v<decltype(c)>) {
      for (std::size_t i = 0; c.has_child_transforms() && i < c.children().size(); ++i) {
        m = m.cwiseMax(Vec2c(widen(c.child_transform(i).position()).cwiseAbs()));
      }
    }
    return m;
  });
}

/// |n_x| S_x + |n_y| S_y for the push direction n and the per-axis magnitudes S = moved_scale():
/// a move by v rounds a coordinate on axis i by at most eps_T / 2 |c_i + v_i|, and not at all when
/// v_i = 0, which shifts the moved shape along n by at most |n_x| err_x + |n_y| err_y. Each |n_i|
/// is taken at most 1, so the sum never exceeds S_x + S_y (the bound over all directions).
inline Calc moved_along(const Vec2c& scale, const Vec2c& n) noexcept {
  return std::min(std::fabs(n.x()), Calc(1)) * scale.x() + std::min(std::fabs(n.y()), Calc(1)) * scale.y();
}

}  // namespace detail

/// The margin resolve() adds beyond the computed depth when it pushes a along -normal, from the
/// magnitudes that round: 4 * 64 * 2^-53 * S (four times the relative part of rounding_tolerance:
/// the depth is computed in double from both shapes' coordinates, S as in rounding_tolerance), plus
/// 8 eps_T (|n_x| S_x + |n_y| S_y + depth), n = normal, where S_x and S_y are the largest absolute
/// x and y coordinates of bounds(a) alone, or of a compound child's position when larger
/// (detail::moved_scale()): moving a rounds each coordinate on axis i to T within eps_T / 2 of its
/// moved magnitude (at most S_i + |n_i| (depth + margin)) and leaves an axis the push does not move
/// exact, so a shifts along the push by at most the sum of |n_i| times that. The term grows with
/// a's coordinates along the push, not across it, and not with b's extent. Plus 16 subnormal
/// units of double and two of T for rounding near zero (a push along a diagonal moves each
/// coordinate by a whole unit: sqrt(2) units in all), plus 2 placement_tolerance of each shape (a
/// compound with child transforms is imaged once for the depth and once for the test). No 2^-500
/// floor: tiny shapes are decided after exact rescaling, so their depths are relative-accurate,
/// and a push of 2^-500 would collapse a subnormal polygon.
///
/// normal: the unit push direction, as contact(a, b) returns it. resolve() evaluates this with
/// its own normal in double, which the normal rounded to T matches within a relative eps_T.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Calc resolve_margin(const A& a, const B& b, Calc depth,
                                                                            const Vec2<scalar_of_t<A>>& normal) {
  using T = scalar_of_t<A>;
  const Calc along = detail::moved_along(detail::moved_scale(a), widen(normal));
  const Calc s = std::max(detail::scale_of(bounds(a)), detail::scale_of(bounds(b)));
  return detail::margin_of<T>(s, along, depth) + 2 * (placement_tolerance(a) + placement_tolerance(b));
}

/// resolve_margin(a, b, depth, normal) for the worst direction: S_x + S_y in place of
/// |n_x| S_x + |n_y| S_y, so at least the margin of every push direction.
template <AnyShape A, AnyShape B>
Calc resolve_margin(const A& a, const B& b, Calc depth) {
  using T = scalar_of_t<A>;
  const Calc along = detail::moved_along(detail::moved_scale(a), Vec2c(1, 1));
  const Calc s = std::max(detail::scale_of(bounds(a)), detail::scale_of(bounds(b)));
  return detail::margin_of<T>(s, along, depth) + 2 * (placement_tolerance(a) + placement_tolerance(b));
}

namespace detail {

/// resolve() on concrete shapes, stored or placed: the push in T. s_moved is the largest stored
/// magnitude of a per axis that a move rounds; extra is added to the margin (the placements' bound);
/// still_overlaps(v) tests a moved by v (nullopt when the move has no representation in T).
template <Scalar T, class A, class B, class Moved>
Vec2<T> resolve_as(const A& ca, const B& cb, const Vec2c& s_moved, Calc extra, Moved&& still_overlaps) {
  if (!overlaps_concrete(ca, cb)) return Vec2<T>::Zero();
  const Calc s_pair = std::max(scale_of(bounds(ca)), scale_of(bounds(cb)));
  constexpr bool compound = is_compound_v<A> || is_compound_v<B>;
  // A push is at most about the shapes' extent, 2 S. The shadows are across the push, so the
  // rounding of a move counts in every direction here (s_pair, not moved_along()).
  const Calc shadow_tol = margin_of<T>(s_pair, s_pair, 2 * s_pair) + extra;
  Vec2c best_n(1, 0);
  Calc best_t = std::numeric_limits<Calc>::infinity();
  for_each_primitive(ca, [&](const auto& pa) {
    for_each_primitive(cb, [&](const auto& pb) {
      if (!decide_primitives(pa, pb)) return;
      const CoreContact c = contact_cores(core_of(pa), core_of(pb));
      const Calc t = compound ? push_along(ca, cb, c.normal, shadow_tol) : c.depth;
      if (t < best_t) {
        best_t = t;
        best_n = c.normal;
      }
    });
  });
  const Calc along = moved_along(s_moved, best_n);
  Calc margin = margin_of<T>(s_pair, along, best_t) + extra;
  Vec2<T> v = round_toward_zero<T>(-best_n * (best_t + margin));
  // The moved shape is tested: for subnormal shapes of very different sizes the rounded depth
  // can fall short by more than the margin.
  for (int attempt = 0; attempt < 8; ++attempt) {
    const std::optional<bool> still = still_overlaps(v);
    if (!still || !*still) break;
    margin *= 2;
    v = round_toward_zero<T>(-best_n * (best_t + margin));
  }
  return v;
}

}  // namespace detail

/// Minimum translation of a that separates it from b (the shortest push,
/// as the course notes resolve penetration, generalised to every pair): zero if they do not overlap; otherwise -normal
/// * (depth + margin), so a moved by it no longer overlaps b, strictly (margin: resolve_margin(a, b, depth, normal),
/// which grows with a's coordinates along the push only; doubled up to 8
/// times while the moved shape, rounded to T, still tests as overlapping: for subnormal shapes of very different
/// sizes the rounded depth can fall short of the margin).
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
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Vec2<scalar_of_t<A>> resolve(const A& a, const B& b) {
  using T = scalar_of_t<A>;
  return detail::visit_shapes(a, b, [&](const auto& ca, const auto& cb) -> Vec2<T> {
    const Calc extra = 2 * (placement_tolerance(ca) + placement_tolerance(cb));
    return detail::resolve_as<T>(ca, cb, detail::moved_scale(ca), extra,
                                 [&](const Vec2<T>& v) { return detail::moved_overlaps(ca, v, cb); });
  });
}

}  // namespace collide
