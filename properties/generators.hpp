#pragma once
/// @file generators.hpp
/// RapidCheck generators for shapes and pairs, aimed at the hard region.
///
/// Coordinates come from small integers times a power of two (exact dyadic values that shrink
/// toward 0): RapidCheck's own double generator never produces the values that matter here.
/// A pair is placed on purpose: separated, exactly touching along an axis (extreme points
/// aligned), a circle touching a face of the other shape, turned faces included (up to the
/// rounding of its centre), touching nudged by a few ulps either way, overlapping, or one shape
/// shrunk inside the other; then the pair is turned by quarter turns. Shapes are sometimes tiny
/// (2^-20) or huge (2^20), sometimes far from the origin (about 1e6) or, on request, far across
/// the axis they meet along (up to 1e7 in float, 1e15 in double), slivers (zero width, zero
/// radius, thin triangles) and near-parallel edges (axes like (64, 1)). The kind of each shape is
/// chosen through the registry (visit_kind).

#include "collide/collide.hpp"
#include "collide/laws/codec.hpp"
#include "collide/laws/transform.hpp"

#include <rapidcheck.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

namespace collide::props {

/// Integer in [lo, hi] mapped to a double (exact).
inline double grid(int lo, int hi) {
  return double(*rc::gen::inRange(lo, hi + 1));
}

/// A primitive of kind K at the given scale (coordinates = small integers * scale), built in T.
template <ShapeKind K, Scalar T>
Primitive<T> gen_primitive(double s) {
  using V = Vec2<T>;
  auto p = [&](int lo, int hi) { return V(T(grid(lo, hi) * s), T(grid(lo, hi) * s)); };
  if constexpr (K == ShapeKind::Circle) {
    return Circle<T>(p(-16, 16), T(grid(0, 16) * s));
  } else if constexpr (K == ShapeKind::Aabb) {
    const V lo = p(-16, 16);
    const bool sliver = *rc::gen::inRange(0, 8) == 0;
    const V size(T(grid(sliver ? 0 : 1, 16) * s), T(grid(1, 16) * s));
    return Aabb<T>(lo, V(lo + size));
  } else if constexpr (K == ShapeKind::Obb) {
    // Axis-aligned half the time (exact corners, exact touching), else rotated, some nearly.
    const std::vector<V> axes = {V(1, 0), V(0, 1), V(1, 0),  V(0, 1),   V(-1, 0), V(0, -1),
                                 V(3, 4), V(1, 1), V(64, 1), V(-1, 64), V(5, -12)};
    const V axis = *rc::gen::elementOf(axes);
    return Obb<T>::make_with_axis(p(-16, 16), V(T(grid(0, 8) * s), T(grid(1, 8) * s)), axis).value();
  } else if constexpr (K == ShapeKind::Capsule) {
    const V a = p(-16, 16);
    const bool point = *rc::gen::inRange(0, 4) == 0;
    const V b = point ? a : V(a + p(-8, 8));
    return Capsule<T>(a, b, T(grid(0, 8) * s));
  } else if constexpr (K == ShapeKind::Polygon) {
    const int style = *rc::gen::inRange(0, 4);
    std::vector<V> pts;
    const V o = p(-16, 16);
    if (style == 0) {
      // Sliver triangle: nearly collinear.
      pts = {o, V(o + V(T(64 * s), T(1 * s))), V(o + V(T(128 * s), T(3 * s)))};
    } else if (style == 1) {
      // Axis-aligned rectangle (also an AABB).
      const V size(T(grid(1, 16) * s), T(grid(1, 16) * s));
      pts = {o, V(o.x() + size.x(), o.y()), V(o + size), V(o.x(), o.y() + size.y())};
    } else {
      const int n = *rc::gen::inRange(3, 9);
      for (int i = 0; i < n; ++i) pts.push_back(V(o + p(-12, 12)));
    }
    auto hull = ConvexPolygon<T>::make_hull(pts);
    if (hull) return hull.value();
    // All collinear (or rounded flat): a right triangle at o.
    return ConvexPolygon<T>({o, V(o + V(T(4 * s), 0)), V(o + V(0, T(4 * s)))});
  } else {
    static_assert(K != ShapeKind::Compound, "compound children are primitives");
    return Circle<T>(V(0, 0), T(0));
  }
}

/// A primitive of a kind chosen among the five, through the registry.
template <Scalar T>
Primitive<T> gen_any_primitive(double s) {
  const auto k = static_cast<ShapeKind>(*rc::gen::inRange(0, int(kKindCount) - 1));
  return visit_kind(k, [&]<ShapeKind K>() -> Primitive<T> {
    if constexpr (K == ShapeKind::Compound) {
      return gen_primitive<ShapeKind::Circle, T>(s);
    } else {
      return gen_primitive<K, T>(s);
    }
  });
}

/// A transform: the identity, an exact one (dyadic position, a quarter turn), or a rounded one
/// (an angle, or a direction that is normalised), at scale s or far away.
template <Scalar T>
Transform<T> gen_transform(double s) {
  using V = Vec2<T>;
  const int style = *rc::gen::inRange(0, 6);
  const V p(T(grid(-64, 64) * s / 4), T(grid(-64, 64) * s / 4));
  if (style == 0) return Transform<T>();
  if (style == 1) {
    const std::array<V, 4> quarter = {V(1, 0), V(0, 1), V(-1, 0), V(0, -1)};
    return Transform<T>::make_with_rotation(p, quarter[std::size_t(*rc::gen::inRange(0, 4))]).value();
  }
  if (style == 2) return Transform<T>::make(p, T(grid(-64, 64) / 10)).value();
  if (style == 3) {
    const std::vector<V> dirs = {V(3, 4), V(1, 1), V(64, 1), V(-5, 12), V(2, 0)};
    return Transform<T>::make_with_rotation(p, *rc::gen::elementOf(dirs)).value();
  }
  if (style == 4) return Transform<T>::make(V(T(1e6 + grid(-8, 8)), T(-1e6)), T(grid(-64, 64) / 10)).value();
  return Transform<T>::make_translation(V(T(grid(-64, 64) * s / 3), T(grid(-64, 64) * s / 3))).value();
}

/// The size of a pair (the larger side of the box around both, at least 2^-20), for transforms
/// that keep a pair far from the origin where it is.
template <Scalar T>
double size_of_pair(const Shape<T>& a, const Shape<T>& b) {
  const Aabb<T> ba = bounds(a), bb = bounds(b);
  const Vec2c lo = widen(ba.min()).cwiseMin(widen(bb.min())), hi = widen(ba.max()).cwiseMax(widen(bb.max()));
  return std::max((hi - lo).maxCoeff(), 0x1p-20);
}

/// The scale of a pair (its largest coordinate, at least 2^-20), for transforms at its scale.
template <Scalar T>
double scale_of_pair(const Shape<T>& a, const Shape<T>& b) {
  return std::max({::collide::detail::scale_of(bounds(a)), ::collide::detail::scale_of(bounds(b)), 0x1p-20});
}

/// p moved by t when no moved value rounds (every position coordinate plus t exact in double and
/// in T, the other values unchanged), else nothing.
template <Scalar T>
std::optional<Primitive<T>> moved_exactly(const Primitive<T>& p, const Vec2<T>& t) {
  const Expected<Primitive<T>> m = translated(p, t);
  if (!m) return std::nullopt;
  const laws::ShapeData d0 = laws::to_data(to_shape(p)), d1 = laws::to_data(to_shape(*m));
  if (d0.values.size() != d1.values.size()) return std::nullopt;
  const laws::KindCodec codec = laws::codec_of(d0.kind);
  for (std::size_t i = 0; i < d0.values.size(); ++i) {
    const laws::Role role = codec.fields[i % codec.fields.size()].role;
    const double shift = role == laws::Role::X ? double(t.x()) : role == laws::Role::Y ? double(t.y()) : 0.0;
    const double sum = d0.values[i] + shift;
    const double back = sum - shift;  // two-sum: the sum is exact when both differences vanish
    if (back != d0.values[i] || sum - back != shift || sum != d1.values[i]) return std::nullopt;
  }
  return *m;
}

/// Child c of a compound placed by an exact transform that keeps it where it is: the child stored
/// turned back by a quarter turn about a dyadic point p, placed by (p, that quarter turn), so the
/// image is c again, exactly. c itself with the identity when a value would round.
template <Scalar T>
typename Compound<T>::Child in_place_child(const Primitive<T>& c, double s) {
  using V = Vec2<T>;
  const V p(T(grid(-64, 64) * s / 4), T(grid(-64, 64) * s / 4));
  const int k = *rc::gen::inRange(0, 4);
  const std::array<V, 4> quarter = {V(1, 0), V(0, 1), V(-1, 0), V(0, -1)};
  const std::optional<Primitive<T>> shifted = moved_exactly(c, V(-p));
  if (!shifted) return {c, Transform<T>()};
  return {laws::turned(*shifted, -k, false), Transform<T>::make_with_rotation(p, quarter[std::size_t(k)]).value()};
}

/// A compound's children given transforms, sometimes (other shapes unchanged; a compound that has
/// child transforms already is kept): per child the identity, an exact transform that keeps the
/// child's world shape (in_place_child), or a rounded or exact one that moves it (gen_transform at
/// an eighth of the scale).
template <Scalar T>
Shape<T> with_child_transforms(const Shape<T>& s, double scale) {
  const auto* c = std::get_if<Compound<T>>(&s);
  if (c == nullptr || c->has_child_transforms() || !*rc::gen::arbitrary<bool>()) return s;
  std::vector<typename Compound<T>::Child> kids;
  for (const Primitive<T>& p : c->children()) {
    const int style = *rc::gen::inRange(0, 3);
    if (style == 0) {
      kids.push_back({p, Transform<T>()});
    } else if (style == 1) {
      kids.push_back(in_place_child(p, scale));
    } else {
      kids.push_back({p, gen_transform<T>(scale / 8)});
    }
  }
  return Compound<T>::make_placed(std::move(kids)).value();
}

/// A shape of kind K at scale s. A compound has 1 to 3 children of any primitive kind, sometimes
/// with child transforms (with_child_transforms).
template <ShapeKind K, Scalar T>
Shape<T> gen_shape(double s) {
  if constexpr (K == ShapeKind::Compound) {
    const int n = *rc::gen::inRange(1, 4);
    std::vector<Primitive<T>> children;
    for (int i = 0; i < n; ++i) children.push_back(gen_any_primitive<T>(s));
    return with_child_transforms(Shape<T>(Compound<T>(std::move(children))), s);
  } else {
    return to_shape(gen_primitive<K, T>(s));
  }
}

/// Shape of a kind known at run time (dispatched through the registry).
template <Scalar T>
Shape<T> gen_shape_of(ShapeKind k, double s) {
  return visit_kind(k, [&]<ShapeKind K>() { return gen_shape<K, T>(s); });
}

/// The core of child i of a compound as placed by its child transform (its image, rounded to
/// double unless the transform is exact).
template <Scalar T>
::collide::detail::Core placed_core(const Compound<T>& c, std::size_t i) {
  ::collide::detail::Core core;
  ::collide::detail::visit_child(c, i, ::collide::detail::Pose{},
                                 [&](const auto& img) { core = ::collide::detail::core_of(img); });
  return core;
}

/// Extreme point of a core in direction +x (sign = +1) or -x (sign = -1).
inline Vec2c extreme_x(const ::collide::detail::Core& core, int sign) {
  Vec2c best = core[0];
  for (const Vec2c& q : core.pts()) {
    if (sign * q.x() > sign * best.x()) best = q;
  }
  return {best.x() + sign * core.radius, best.y()};
}

/// Extreme point of a shape in direction +x (sign = +1) or -x (sign = -1): x and a y where the
/// shape reaches it. Exact for everything but rotated OBBs (rounded corners).
template <Scalar T>
Vec2c extreme_x(const Primitive<T>& p, int sign) {
  return extreme_x(std::visit([](const auto& s) { return ::collide::detail::core_of(s); }, p), sign);
}

template <Scalar T>
Vec2c extreme_x(const Shape<T>& s, int sign) {
  if (const auto* c = std::get_if<Compound<T>>(&s)) {
    Vec2c best = extreme_x(placed_core(*c, 0), sign);
    for (std::size_t i = 0; i < c->children().size(); ++i) {
      const Vec2c q = extreme_x(placed_core(*c, i), sign);
      if (sign * q.x() > sign * best.x()) best = q;
    }
    return best;
  }
  return std::visit(
      [&](const auto& x) -> Vec2c {
        using S = std::remove_cvref_t<decltype(x)>;
        if constexpr (std::is_same_v<S, Compound<T>>) {
          return {};
        } else {
          return extreme_x(Primitive<T>(x), sign);
        }
      },
      s);
}

/// The core of a shape's first primitive (a compound's first child, placed).
template <Scalar T>
::collide::detail::Core first_core(const Shape<T>& s) {
  if (const auto* c = std::get_if<Compound<T>>(&s)) return placed_core(*c, 0);
  return std::visit([](const auto& x) { return ::collide::detail::core_of(x); }, laws::primitives_of(s).front());
}

/// A point inside the shape (a core vertex average of its first primitive).
template <Scalar T>
Vec2c inner_point(const Shape<T>& s) {
  const ::collide::detail::Core core = first_core(s);
  Vec2c m = Vec2c::Zero();
  for (const Vec2c& q : core.pts()) m += q;
  return m / double(core.size());
}

/// s moved by t, or s itself when the move is rejected (out of range, collapsed sliver).
template <Scalar T>
Shape<T> moved(const Shape<T>& s, const Vec2<T>& t) {
  auto m = translated(s, t);
  return m ? m.value() : s;
}

/// ulp of T at magnitude m.
template <Scalar T>
T ulp_at(double m) {
  const T x = T(std::fabs(m));
  return std::nextafter(x, std::numeric_limits<T>::infinity()) - x;
}

/// How the second shape is placed against the first.
enum class Placement { Separated, Touching, Nudged, Overlapping, Contained };

/// The move that takes a circle's centre to the point of radius_sum beyond a face of a core (one
/// of the library's faces, for_each_face, at one of the eighths along it): touching a turned face
/// up to the rounding of the centre to T, which no alignment of extreme points reaches (a turned
/// box's extreme points are corners). nullopt for a core without a face.
template <Scalar T>
std::optional<Vec2<T>> toward_face(const ::collide::detail::Core& core, const Vec2c& centre, double radius_sum) {
  std::vector<std::pair<Vec2c, unsigned>> faces;
  ::collide::detail::for_each_face(core, [&](const Vec2c& n, unsigned i) { faces.emplace_back(n, i); });
  if (faces.empty()) return std::nullopt;
  const auto [normal, i] = *rc::gen::elementOf(faces);
  // A segment's two faces both run along it.
  const Vec2c p = core.size() == 2 ? core[0] : core[i],
              q = core.size() == 2 ? core[1] : core[::collide::detail::next_index(i, core.size())];
  const Vec2c t = p + (q - p) * (grid(1, 7) / 8) + normal * (core.radius + radius_sum) - centre;
  return Vec2<T>(T(t.x()), T(t.y()));
}

/// The move of mover that puts a circle on a face of the other shape (toward_face): the circle
/// mover onto a face of fixed, or mover moved back by as much as a circle fixed would move onto
/// mover's face. nullopt when neither is a circle or the other has no face.
template <Scalar T>
std::optional<Vec2<T>> circle_onto_face(const Shape<T>& fixed, const Shape<T>& mover) {
  if (const auto* c = std::get_if<Circle<T>>(&mover)) {
    return toward_face<T>(first_core(fixed), widen(c->center()), c->radius());
  }
  if (const auto* c = std::get_if<Circle<T>>(&fixed)) {
    const std::optional<Vec2<T>> onto = toward_face<T>(first_core(mover), widen(c->center()), c->radius());
    if (onto) return Vec2<T>(-*onto);
  }
  return std::nullopt;
}

/// An offset far along y, for a pair whose placement axis is x: 1e5, 1e6 or 1e7 in float, 1e12,
/// 1e14 or 1e15 in double, either sign (exact in T).
template <Scalar T>
T far_across_offset() {
  const std::vector<double> far =
      std::is_same_v<T, float> ? std::vector<double>{1e5, 1e6, 1e7} : std::vector<double>{1e12, 1e14, 1e15};
  return T(*rc::gen::elementOf(far) * *rc::gen::element(-1.0, 1.0));
}

/// A pair of kinds (A, B) placed on purpose (see the file comment); `only` restricts the placement
/// (the touching law asks for touching and nudged pairs only). With `across`, the pair is always
/// moved far across its placement axis (far_across_offset() along y before the turn, while the
/// shapes meet along x: resting on a floor, against a wall): a resolution margin that grew with
/// the coordinates across the push fails there.
template <Scalar T>
std::pair<Shape<T>, Shape<T>> gen_pair(ShapeKind ka, ShapeKind kb, std::optional<Placement> only = std::nullopt,
                                       bool across = false) {
  using V = Vec2<T>;
  const int e = *rc::gen::weightedElement<int>({{1, -20}, {1, -6}, {6, 0}, {1, 6}, {1, 20}});
  const double s = std::ldexp(1.0, e);
  const auto place = only ? *only
                          : *rc::gen::weightedElement<Placement>({{1, Placement::Separated},
                                                                  {4, Placement::Touching},
                                                                  {2, Placement::Nudged},
                                                                  {2, Placement::Overlapping},
                                                                  {3, Placement::Contained}});
  const bool b_moves = *rc::gen::arbitrary<bool>();  // which of the two is placed against the other
  Shape<T> fixed = gen_shape_of<T>(b_moves ? ka : kb, s);
  ShapeKind kmove = b_moves ? kb : ka;
  Shape<T> mover = gen_shape_of<T>(kmove, place == Placement::Contained ? s / 64 : s);
  V t(0, 0);
  if (place == Placement::Contained) {
    const Vec2c target = inner_point(fixed), from = inner_point(mover);
    t = V(T(target.x() - from.x()), T(target.y() - from.y()));
  } else if (const std::optional<V> onto =
                 (place == Placement::Touching || place == Placement::Nudged) && *rc::gen::arbitrary<bool>()
                     ? circle_onto_face<T>(fixed, mover)
                     : std::nullopt) {
    t = *onto;
    if (place == Placement::Nudged)
      t.x() += T(*rc::gen::inRange(-4, 5)) * ulp_at<T>(extreme_x(fixed, +1).cwiseAbs().maxCoeff());
  } else {
    const Vec2c xa = extreme_x(fixed, +1), xb = extreme_x(mover, -1);
    t = V(T(xa.x() - xb.x()), T(xa.y() - xb.y()));
    const bool shift_y = *rc::gen::inRange(0, 6) == 0;
    if (shift_y) t.y() += T(grid(-4, 4) * s);
    if (place == Placement::Separated) t.x() += T(grid(1, 16) * s / 8);
    if (place == Placement::Overlapping) t.x() -= T(grid(1, 16) * s / 8);
    if (place == Placement::Nudged) {
      const double mag = std::max(std::fabs(xa.x()), std::fabs(xb.x()));
      t.x() += T(*rc::gen::inRange(-4, 5)) * ulp_at<T>(mag);
    }
  }
  mover = moved(mover, t);
  if (across) {
    // Both moved, or neither (a shape that rounding collapses there keeps the pair as it was).
    const V far(T(0), far_across_offset<T>());
    const Expected<Shape<T>> f = translated(fixed, far), m = translated(mover, far);
    if (f && m) {
      fixed = f.value();
      mover = m.value();
    }
  } else if (*rc::gen::inRange(0, 6) == 0) {
    // Far from the origin, sometimes: both moved by the same (exact) large offset.
    const V far(T(1e6 + 64 * grid(-4, 4)), T(-1e6));
    fixed = moved(fixed, far);
    mover = moved(mover, far);
  }
  // Turn the pair (exact), so every axis direction is exercised.
  const int k = *rc::gen::inRange(0, 4);
  const bool mirror = *rc::gen::arbitrary<bool>();
  fixed = laws::turned(fixed, k, mirror);
  mover = laws::turned(mover, k, mirror);
  if (b_moves) return {fixed, mover};
  return {mover, fixed};
}

/// A round end of a circle or capsule (centre, radius), for Pythagorean placements.
template <Scalar T>
std::optional<std::pair<Vec2c, double>> round_end(const Shape<T>& s, bool second) {
  if (const auto* c = std::get_if<Circle<T>>(&s)) return std::pair{widen(c->center()), double(c->radius())};
  if (const auto* c = std::get_if<Capsule<T>>(&s))
    return std::pair{widen(second ? c->b() : c->a()), double(c->radius())};
  return std::nullopt;
}

/// Two round shapes (circles, capsule ends) touching exactly at a Pythagorean distance: centres
/// (3m, 4m) * s apart (turned by quarter turns and mirrors) with radii summing to 5m * s, so no
/// value is rounded; or moved one ulp apart.
template <Scalar T>
std::pair<Shape<T>, Shape<T>> gen_pythagorean_pair(ShapeKind ka, ShapeKind kb, bool nudge) {
  using V = Vec2<T>;
  const double s = std::ldexp(1.0, *rc::gen::weightedElement<int>({{1, -20}, {4, 0}, {1, 20}}));
  const int m = *rc::gen::inRange(1, 5);
  const int ra = *rc::gen::inRange(0, 5 * m + 1);
  auto make = [&](ShapeKind k, const V& centre, int r, bool at_b) -> Shape<T> {
    if (k == ShapeKind::Circle) return Circle<T>(centre, T(r * s));
    const V other(T(double(centre.x()) + grid(-8, 8) * s), T(double(centre.y()) + grid(-8, 8) * s));
    // Only the capsule end at the centre is placed: the rest of the capsule must stay away.
    return at_b ? Capsule<T>(other, centre, T(r * s)) : Capsule<T>(centre, other, T(r * s));
  };
  const V ca(T(grid(-16, 16) * s), T(grid(-16, 16) * s));
  const std::vector<std::pair<int, int>> legs = {{3, 4}, {4, 3}, {-3, 4}, {3, -4}, {-4, -3}, {0, 5}, {5, 0}};
  const auto [lx, ly] = *rc::gen::elementOf(legs);
  V cb(T(double(ca.x()) + lx * m * s), T(double(ca.y()) + ly * m * s));
  if (nudge) cb.x() = std::nextafter(cb.x(), T(lx >= 0 ? 1e30 : -1e30));
  return {make(ka, ca, ra, *rc::gen::arbitrary<bool>()), make(kb, cb, 5 * m - ra, *rc::gen::arbitrary<bool>())};
}

/// A pair for the touching law: touching exactly by construction (extreme points aligned, shared
/// vertices and edges, a vertex on an edge, Pythagorean circles and capsule ends), or nudged a few
/// ulps either way, at every scale the placement keeps exact.
template <Scalar T>
std::pair<Shape<T>, Shape<T>> gen_touching_pair(ShapeKind ka, ShapeKind kb) {
  const bool round =
      (ka == ShapeKind::Circle || ka == ShapeKind::Capsule) && (kb == ShapeKind::Circle || kb == ShapeKind::Capsule);
  const int style = *rc::gen::inRange(0, round ? 4 : 3);
  if (style == 3) return gen_pythagorean_pair<T>(ka, kb, *rc::gen::inRange(0, 3) == 0);
  return gen_pair<T>(ka, kb, style == 2 ? Placement::Nudged : Placement::Touching);
}

/// A pair for the contains_shape law: the second shape built inside the first so that it touches
/// the first's boundary from inside (the same shape; a disc at a core point with the core's radius;
/// a capsule along a core edge; a polygon through the core's vertices), or a pair of gen_pair
/// (half of them one placed inside the other); a third of them with the inner shape then moved by
/// one ulp along an axis, out or further in. A shape the factories reject keeps gen_pair's.
template <Scalar T>
std::pair<Shape<T>, Shape<T>> gen_nested_pair(ShapeKind ka, ShapeKind kb) {
  using V = Vec2<T>;
  auto [a, b] = gen_pair<T>(ka, kb, *rc::gen::arbitrary<bool>() ? std::optional(Placement::Contained) : std::nullopt);
  const ::collide::detail::Core core = first_core(a);
  const std::size_t n = core.size(), i = std::size_t(*rc::gen::inRange(0, int(n)));
  const auto at = [&](std::size_t k) { return V(T(core[k % n].x()), T(core[k % n].y())); };
  const T radius = T(core.radius);
  switch (*rc::gen::inRange(0, 5)) {
    case 0:
      b = a;
      break;
    case 1:
      if (auto c = Circle<T>::make(at(i), radius)) b = c.value();
      break;
    case 2:
      if (auto c = Capsule<T>::make(at(i), at(i + 1), radius)) b = c.value();
      break;
    case 3:
      if (n >= 3) {
        std::vector<V> pts;
        for (std::size_t k = 0; k < n; ++k) pts.push_back(at(k));
        if (*rc::gen::arbitrary<bool>()) pts = {at(i), at(i + 1), at(i + 2)};
        if (auto p = ConvexPolygon<T>::make(pts)) b = p.value();
      }
      break;
    default:
      break;
  }
  if (*rc::gen::inRange(0, 3) == 0) {
    const int axis = *rc::gen::inRange(0, 2), sign = *rc::gen::element(-1, 1);
    V t(0, 0);
    t[axis] = T(sign) * ulp_at<T>(extreme_x(b, sign).cwiseAbs().maxCoeff());
    b = moved(b, t);
  }
  return {a, b};
}

/// A point to test contains() with: a core vertex of the shape, its extreme points, moved by a
/// few ulps or by the radius, a point inside, a grid point nearby, or NaN / infinity.
template <Scalar T>
Vec2<T> gen_point_near(const Shape<T>& s) {
  using V = Vec2<T>;
  const int style = *rc::gen::inRange(0, 8);
  if (style == 0) {
    const std::vector<T> odd = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                                -std::numeric_limits<T>::infinity(), T(0)};
    return V(*rc::gen::elementOf(odd), *rc::gen::elementOf(odd));
  }
  const Vec2c inner = inner_point(s);
  Vec2c base = inner;
  if (style <= 3) {
    base = extreme_x(s, *rc::gen::element(-1, 1));
  } else if (style <= 5) {
    const ::collide::detail::Core core = first_core(s);
    base = core[std::size_t(*rc::gen::inRange(0, int(core.size())))];
    if (core.radius > 0 && *rc::gen::arbitrary<bool>()) base.y() += core.radius * *rc::gen::element(-1.0, 1.0);
  } else if (style == 6) {
    const double size = (widen(bounds(s).max()) - widen(bounds(s).min())).maxCoeff();
    base = inner + Vec2c(grid(-8, 8), grid(-8, 8)) * (size / 4);
  }
  V p(T(base.x()), T(base.y()));
  const int ulps = *rc::gen::inRange(-2, 3);
  for (int i = 0; i < std::abs(ulps); ++i) {
    const int k = *rc::gen::inRange(0, 2);
    p[k] = std::nextafter(p[k], ulps > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity());
  }
  return p;
}

/// A polygon shape with coordinates of no short binary form, whose differences and products round
/// (the dyadic grid never gives them): s turned by an angle about the origin and moved by k / 3 of
/// a far distance, or a sliver of s's size, 3 to 6 points along a turned line off it by 2^-10 to
/// 2^-40 of its length (each rounded to T, then their hull). Any other shape, or a polygon that
/// rounds flat, is kept as it is.
template <Scalar T>
Shape<T> gen_rounding_polygon(const Shape<T>& s) {
  const auto* poly = std::get_if<ConvexPolygon<T>>(&s);
  if (poly == nullptr) return s;
  const double angle = grid(1, 62) / 10, far = *rc::gen::element(0.0, 1.0, 1e4, 1e6);
  const Vec2c shift(grid(-8, 8) * far / 3, grid(-8, 8) * far / 3), u(std::cos(angle), std::sin(angle));
  std::vector<Vec2<T>> points;
  if (*rc::gen::arbitrary<bool>()) {
    for (const Vec2<T>& v : poly->vertices()) {
      const Vec2c q = widen(v);
      points.push_back(
          (Vec2c(u.x() * q.x() - u.y() * q.y(), u.y() * q.x() + u.x() * q.y()) + shift).template cast<T>());
    }
  } else {
    const double size = (widen(poly->vertices()[0]) - widen(poly->vertices()[1])).norm();
    const double off = std::ldexp(size, -*rc::gen::inRange(10, 41));
    const Vec2c start = widen(poly->vertices()[0]) + shift;
    const int n = *rc::gen::inRange(3, 7);
    for (int i = 0; i < n; ++i) {
      const double along = size * grid(0, 64) / 64, across = off * grid(-4, 4);
      points.push_back(Vec2c(start + along * u + across * Vec2c(-u.y(), u.x())).template cast<T>());
    }
  }
  auto hull = ConvexPolygon<T>::make_hull(points);
  return hull ? Shape<T>(std::move(hull).value()) : s;
}

/// A translation: exact dyadic (small or large), or inexact (k / 3, rounded).
template <Scalar T>
Vec2<T> gen_translation(double s) {
  const int style = *rc::gen::inRange(0, 3);
  auto one = [&]() -> T {
    if (style == 0) return T(grid(-64, 64) * s / 4);
    if (style == 1) return T(grid(-64, 64) * 0x1p20);
    return T(grid(-64, 64) * s / 3);
  };
  const T x = one();
  const T y = one();
  return Vec2<T>(x, y);
}

/// Raw values for the rejection law: bit patterns (NaN payloads, infinities, subnormals, huge),
/// special values, and ordinary valid values mixed.
template <Scalar T>
T gen_raw_value() {
  using Bits = std::conditional_t<std::is_same_v<T, float>, std::uint32_t, std::uint64_t>;
  const int style = *rc::gen::inRange(0, 4);
  if (style == 0) {
    const Bits bits = *rc::gen::arbitrary<Bits>();
    T v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  if (style == 1) {
    const std::vector<T> special = {std::numeric_limits<T>::quiet_NaN(),   std::numeric_limits<T>::infinity(),
                                    -std::numeric_limits<T>::infinity(),   std::numeric_limits<T>::denorm_min(),
                                    -std::numeric_limits<T>::denorm_min(), T(-0.0),
                                    std::numeric_limits<T>::max(),         max_magnitude<T>(),
                                    T(max_magnitude<T>() * T(2)),          -T(1)};
    return *rc::gen::elementOf(special);
  }
  return T(grid(-16, 16) / 4);
}

/// Values for the rejection law aimed at one named error of `kind` on purpose (or valid), so
/// that each validation rule is met in every run, whatever the seed: a non-finite or out-of-range
/// value at any index, a negative radius or extent, min > max, a zero axis, and for polygons too
/// few distinct vertices, all collinear, a reflex vertex, a side doubling back, a star winding
/// twice, or a valid clockwise square. Layout as in laws::rejection.
template <Scalar T>
std::vector<T> gen_aimed_values(ShapeKind kind) {
  auto v = [](std::initializer_list<double> xs) {
    std::vector<T> out;
    for (double x : xs) out.push_back(T(x));
    return out;
  };
  const double a = grid(1, 8), b = grid(1, 8);
  std::vector<T> out;
  switch (kind) {
    case ShapeKind::Circle:
    case ShapeKind::Compound:
      out = v({a, b, *rc::gen::element(a, -a, 0.0)});
      break;
    case ShapeKind::Aabb:
      out = *rc::gen::arbitrary<bool>() ? v({a, b, -a, b + 1}) : v({a, b, a + 1, b - 1 - grid(0, 4)});
      break;
    case ShapeKind::Obb: {
      const int style = *rc::gen::inRange(0, 3);
      out = style == 0 ? v({a, b, -a, b, 1, 0}) : style == 1 ? v({a, b, a, -b, 0, 1}) : v({a, b, a, b, 0, 0});
      break;
    }
    case ShapeKind::Capsule:
      out = v({a, b, b, a, *rc::gen::element(a, -a, 0.0)});
      break;
    case ShapeKind::Polygon: {
      const std::vector<std::vector<double>> polygons = {
          {0, 0, a, 0, 0, 0},                        // too few distinct vertices
          {0, 0, a, a, 2 * a, 2 * a, 3 * a, 3 * a},  // all collinear
          {0, 0, 4 * a, 0, a, a, 0, 4 * a},          // reflex vertex (a dart)
          {0, 0, 4 * a, 0, 2 * a, 0, 4 * a, 4 * a},  // doubling back along a side
          {0, 4, 2, -3, -4, 1, 4, 1, -2, -3},        // a star: winds twice
          {0, 0, 0, a, a, a, a, 0},                  // clockwise square (valid)
      };
      const auto& poly = *rc::gen::elementOf(polygons);
      for (double x : poly) out.push_back(T(x));
      break;
    }
  }
  // Sometimes a non-finite or out-of-range value replaces one of them.
  if (*rc::gen::inRange(0, 4) == 0) {
    const std::vector<T> bad = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                                T(max_magnitude<T>() * T(2)), -T(max_magnitude<T>() * T(2))};
    out[std::size_t(*rc::gen::inRange(0, int(out.size())))] = *rc::gen::elementOf(bad);
  }
  return out;
}

}  // namespace collide::props
