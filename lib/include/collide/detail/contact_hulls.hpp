#pragma once
/// @file detail/contact_hulls.hpp
/// The contact of two boxes or polygons, and of a capsule with a box or polygon: the separating
/// axis of least penetration over both hulls' faces, each face's depth in closed form where the
/// shapes allow it.

#include "collide/detail/contact_base.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace collide::detail {

/// The least-penetration axis of two boxes with hulls ha and hb (least_penetration_with() on
/// their faces), each face's depth in closed form: along a unit n, (c_a - c_b) . n plus both
/// boxes' half-widths along n. With unit axes u and v = perp(u) (the hulls' normals) and
/// half-lengths X = h_x |w|, Y = h_y |w|, a box's half-width is X |u . n| + Y |v . n|: six dot
/// products in all, where the supports take one per corner and face.
template <class A, class B>
Axis least_penetration_of_boxes(const A& a, const B& b, const Hull& ha, const Hull& hb, Calc tie, Calc stop_below,
                                Rounding rounding) {
  const Rect ka = rect_of(a), kb = rect_of(b);
  const Vec2c ua = ha.normals()[1], ub = hb.normals()[1];  // faces 0..3: -v, u, v, -u (hull_of)
  const auto [xa, ya] = half_lengths(ka, ua);
  const auto [xb, yb] = half_lengths(kb, ub);
  // |u_a . u_b| = |v_a . v_b| and |v_a . u_b| = |u_a . v_b|, bit for bit.
  const Calc cs = std::fabs(ua.dot(ub)), sn = std::fabs(perp(ua).dot(ub));
  const Calc wua = xa + xb * cs + yb * sn, wva = ya + xb * sn + yb * cs;
  const Calc wub = xb + xa * cs + ya * sn, wvb = yb + xa * sn + ya * cs;
  const Vec2c off = ka.c - kb.c;
  const Calc oua = off.dot(ua), ova = off.dot(perp(ua)), oub = off.dot(ub), ovb = off.dot(perp(ub));
  const std::array<Calc, 4> dp{wva - ova, wua + oua, wva + ova, wua - oua};
  const std::array<Calc, 4> dq{wvb + ovb, wub - oub, wvb - ovb, wub + oub};
  return least_penetration_by(
      faces_of(ha), faces_of(hb), [&](const Vec2c&, unsigned i) { return dp[i]; },
      [&](const Vec2c&, unsigned i) { return dq[i]; }, Calc(0), tie, stop_below, rounding);
}

/// The least-penetration axis of a box (shape a, hull hb) and a polygon (hull hp): the box's
/// faces, -v, u, v, -u, take the least and the largest of one pass of the polygon's vertices along
/// u and along v instead of four; along a polygon face's normal n the box, centre c, reaches
/// -c . n + h_x |w| |u . n| + h_y |w| |v . n| (in closed form, as least_penetration_of_boxes()
/// takes it).
template <class A>
Axis least_penetration_of_box_polygon(const A& a, const Hull& hb, const Hull& hp, Calc tie, Calc stop_below,
                                      Rounding rounding) {
  const Core &p = hb.core, &q = hp.core;
  const Calc r = p.radius + q.radius;
  const Vec2c* nb = hb.normals();  // faces 0..3: -v, u, v, -u (hull_of)
  const Vec2c u = nb[1], v = nb[2];
  const Rect k = rect_of(a);
  const HalfLengths half = half_lengths(k, u);
  Calc ulo = std::numeric_limits<Calc>::infinity(), uhi = -ulo, vlo = ulo, vhi = -ulo;
  for (const Vec2c& x : q.pts()) {
    const Calc su = x.dot(u), sv = x.dot(v);
    ulo = std::min(ulo, su);
    uhi = std::max(uhi, su);
    vlo = std::min(vlo, sv);
    vhi = std::max(vhi, sv);
  }
  const std::array<Calc, 4> dp{p[0].dot(nb[0]) + vhi + r, p[1].dot(u) - ulo + r, p[2].dot(v) - vlo + r,
                               p[3].dot(nb[3]) + uhi + r};
  return least_penetration_by(
      faces_of(hb), faces_of(hp), [&](const Vec2c&, unsigned i) { return dp[i]; },
      [&](const Vec2c& m, unsigned i) {
        return (q[i] - k.c).dot(m) + half.x * std::fabs(u.dot(m)) + half.y * std::fabs(v.dot(m)) + r;
      },
      r, tie, stop_below, rounding);
}

/// Two boxes or polygons: the least-penetration axis over both hulls' faces decides when it is
/// clear of the band (all faces deeper: overlapping; one face apart: separated), and its face is
/// the reference face of the contact. Its depth is within 2 ties and its slack of the least, so
/// overlapping is certain above the band plus those. Boxes flat on an axis or thinner than their rounding, polygons of
/// more than 8 vertices and tiny pairs take the generic path. Kept out of line, so that apart_by_boxes() before it
/// inlines into the caller.
template <class A, class B>
[[gnu::noinline]] std::optional<CoreContact> contact_hulls(const A& a, const B& b, Calc speculative,
                                                           Rounding rounding) {
  Hull ha, hb;
  if (!(hull_of(a, ha) && hull_of(b, hb) && std::max(ha.scale, hb.scale) >= kTinyCore))
    return contact_generic(a, b, speculative, rounding);
  const Calc scale = std::max(ha.scale, hb.scale), band = band_of(scale), tie = tie_of(scale);
  Axis ax;
  if constexpr (is_box_v<A> && is_box_v<B>) {
    ax = least_penetration_of_boxes(a, b, ha, hb, tie, -band, rounding);
  } else if constexpr (is_box_v<A>) {
    ax = least_penetration_of_box_polygon(a, ha, hb, tie, -band, rounding);
  } else {
    ax = least_penetration_with(ha.core, faces_of(ha), hb.core, faces_of(hb), tie, -band, rounding);
  }
  const bool overlapping = ax.depth > band + 2 * tie + ax.slack || (!(ax.depth < -band) && decide_exactly(a, b));
  if (overlapping) return contact_from_axis(ha.core, hb.core, ax, speculative, ha.normals(), hb.normals());
  return speculative > 0 ? speculative_contact_cores(ha.core, hb.core, speculative) : std::nullopt;
}

/// The least-penetration axis of a box (shape a, hull ha) and a capsule (hull hc), each face's
/// depth in closed form as least_penetration_of_boxes() takes it: along a unit n the box spans
/// c . n -+ (X |u . n| + Y |v . n|), the capsule's core the least and the largest of its ends'
/// dots. The box's four faces share four dots of the ends; the capsule's two sides, one box
/// half-width.
template <class A>
Axis least_penetration_of_box_capsule(const A& a, const Hull& ha, const Hull& hc, Calc tie, Calc stop_below,
                                      Rounding rounding) {
  const Rect k = rect_of(a);
  const Vec2c u = ha.normals()[1], v = perp(u);  // faces 0..3: -v, u, v, -u (hull_of)
  const auto [x, y] = half_lengths(k, u);
  const Vec2c &e0 = hc.core[0], &e1 = hc.core[1];
  const Calc r = hc.core.radius;
  const Calc cu = k.c.dot(u), cv = k.c.dot(v);
  const Calc au = e0.dot(u), bu = e1.dot(u), av = e0.dot(v), bv = e1.dot(v);
  const std::array<Calc, 4> dp{y - cv + std::max(av, bv) + r, x + cu - std::min(au, bu) + r,
                               y + cv - std::min(av, bv) + r, x - cu + std::max(au, bu) + r};
  const Vec2c n = hc.normals()[0];  // side 1's is -n
  const Calc cn = k.c.dot(n), ext = x * std::fabs(u.dot(n)) + y * std::fabs(v.dot(n));
  const std::array<Calc, 2> dq{ext - cn + e0.dot(n) + r, ext + cn - e1.dot(n) + r};
  return least_penetration_by(
      faces_of(ha), faces_of(hc), [&](const Vec2c&, unsigned i) { return dp[i]; },
      [&](const Vec2c&, unsigned i) { return dq[i]; }, r, tie, stop_below, rounding);
}

/// The least-penetration axis of a capsule (hull hc) and a polygon (hull hp), as
/// least_penetration_with() finds it, bit for bit: the capsule's two sides, n and -n, take the
/// least and the largest of one pass of the polygon's vertices along n instead of two.
inline Axis least_penetration_of_capsule_polygon(const Hull& hc, const Hull& hp, Calc tie, Calc stop_below,
                                                 Rounding rounding) {
  const Core &p = hc.core, &q = hp.core;
  const Calc r = p.radius + q.radius;
  const Vec2c n = hc.normals()[0];  // side 1's is -n
  Calc lo = std::numeric_limits<Calc>::infinity(), hi = -lo;
  for (const Vec2c& x : q.pts()) {
    const Calc s = x.dot(n);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  const std::array<Calc, 2> dp{p[0].dot(n) - lo + r, p[1].dot(hc.normals()[1]) + hi + r};
  return least_penetration_by(
      faces_of(hc), faces_of(hp), [&](const Vec2c&, unsigned i) { return dp[i]; },
      [&](const Vec2c& m, unsigned i) { return q[i].dot(m) + support(p, -m) + r; }, r, tie, stop_below, rounding);
}

/// A capsule and a box or polygon: contact_of_cores() with the faces' normals known (the
/// capsule's sides by one square root, the box's from its axes, the polygon's cached). Kept out of
/// line, as the other specialised pairs are: the dispatch inlines into the caller.
template <class A, class B>
[[gnu::noinline]] std::optional<CoreContact> contact_capsule_hull(const A& a, const B& b, Calc speculative,
                                                                  Rounding rounding) {
  Hull ha, hb;
  if (!(hull_of(a, ha) && hull_of(b, hb))) return contact_generic(a, b, speculative, rounding);
  const Calc points = std::max(ha.scale, hb.scale);
  if constexpr (is_box_v<A>) {
    return contact_of_cores(a, b, ha.core, ha.normals(), hb.core, hb.normals(), points, speculative,
                            [&](Calc tie, Calc stop_below) {
                              return least_penetration_of_box_capsule(a, ha, hb, tie, stop_below, rounding);
                            });
  } else {
    return contact_of_cores(a, b, ha.core, ha.normals(), hb.core, hb.normals(), points, speculative,
                            [&](Calc tie, Calc stop_below) {
                              return least_penetration_of_capsule_polygon(ha, hb, tie, stop_below, rounding);
                            });
  }
}

}  // namespace collide::detail
