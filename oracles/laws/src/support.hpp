#pragma once
// Helpers shared by the laws' translation units (not installed).

#include "collide/collide.hpp"
// The queries on Shape<T> come compiled from collide::compiled (the same code at the same
// optimisation level): each law unit then instantiates none of them again.
#include "collide/compiled.hpp"
#include "collide/laws/codec.hpp"
#include "collide/laws/laws.hpp"
#include "collide/laws/transform.hpp"
#include "collide/oracle/oracle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace collide::laws::detail {

using ::collide::laws::placed_primitives_of;
using ::collide::laws::primitives_of;
using ::collide::laws::turn;
using ::collide::laws::turned;

/// The distance from x to the segment s (a point when its ends are equal). Coordinates whose
/// squares would underflow or overflow are first scaled by an exact power of two (differences of
/// subnormal numbers are exact), so that a shape 1e-317 across is measured, not taken for a point.
inline double distance_to_segment(const Vec2c& x, const std::array<Vec2c, 2>& s) {
  Vec2c d = s[1] - s[0], w = x - s[0];
  const double m = std::max(d.cwiseAbs().maxCoeff(), w.cwiseAbs().maxCoeff());
  int e = 0;
  if (m > 0 && !::collide::detail::is_plain_magnitude(m)) {
    static_cast<void>(std::frexp(m, &e));
    d = Vec2c(std::ldexp(d.x(), -e), std::ldexp(d.y(), -e));
    w = Vec2c(std::ldexp(w.x(), -e), std::ldexp(w.y(), -e));
  }
  const double dd = d.squaredNorm();
  const double t = dd > 0 ? std::clamp(w.dot(d) / dd, 0.0, 1.0) : 0.0;
  return std::ldexp((w - d * t).norm(), e);
}

/// One law's verdict under construction: the first broken requirement is kept, with the inputs.
struct Judgement {
  Verdict v;
  std::string context;

  void require(bool holds, const std::string& expected, const std::string& got) {
    if (holds || !v.ok) return;
    v.ok = false;
    v.expected = expected;
    v.got = got;
    v.account = "expected " + expected + "; got " + got + "; " + context;
  }
  void note(const std::string& s) { v.account += v.account.empty() ? s : "; " + s; }
};

/// Runs body on a Judgement; an exception (oracle or library) is a broken law, reported.
template <class F>
Verdict judged(const std::string& context, F&& body) {
  Judgement j;
  j.context = context;
  try {
    body(j);
  } catch (const std::exception& e) {
    j.require(false, "no exception", std::string("exception: ") + e.what());
  }
  return j.v;
}

/// Shortest decimal that round-trips, for accounts.
inline std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

using ::collide::laws::codec_detail::hex;

inline std::string yes(bool b) {
  return b ? "true" : "false";
}

template <Scalar T>
std::string vec(const Vec2<T>& v) {
  // Appends (not "(" + string): g++ 12 warns falsely (-Wrestrict) on literal + temporary.
  std::string out = "(";
  out += num(double(v.x()));
  out += ", ";
  out += num(double(v.y()));
  out += ")";
  return out;
}

/// One-line decimal description of a primitive or shape.
template <Scalar T>
std::string describe(const Circle<T>& s) {
  return "circle c=" + vec(s.center()) + " r=" + num(s.radius());
}
template <Scalar T>
std::string describe(const Aabb<T>& s) {
  return "aabb min=" + vec(s.min()) + " max=" + vec(s.max());
}
template <Scalar T>
std::string describe(const Obb<T>& s) {
  return "obb c=" + vec(s.center()) + " h=" + vec(s.half_extents()) + " u=" + vec(s.axis());
}
template <Scalar T>
std::string describe(const Capsule<T>& s) {
  return "capsule a=" + vec(s.a()) + " b=" + vec(s.b()) + " r=" + num(s.radius());
}
template <Scalar T>
std::string describe(const ConvexPolygon<T>& s) {
  std::string out = "polygon";
  for (const Vec2<T>& p : s.vertices()) {
    out += ' ';
    out += vec(p);
  }
  return out;
}
/// A primitive and its placement (a compound child and its transform): " at p=... q=..." unless
/// the identity.
template <Scalar T>
std::string describe(const Primitive<T>& s, const Transform<T>& x) {
  std::string out = std::visit([](const auto& c) { return describe(c); }, s);
  if (!x.is_identity()) {
    out += " at p=";
    out += vec(x.position());
    out += " q=";
    out += vec(x.rotation());
  }
  return out;
}
template <Scalar T>
std::string describe(const Compound<T>& s) {
  std::string out = "compound{";
  for (std::size_t i = 0; i < s.children().size(); ++i) {
    out += i == 0 ? "" : "; ";
    out += describe(s.children()[i], s.child_transform(i));
  }
  return out + "}";
}
template <Scalar T>
std::string describe(const Shape<T>& s) {
  return std::visit([](const auto& x) { return describe(x); }, s);
}
template <Scalar T>
std::string describe(const Primitive<T>& s) {
  return std::visit([](const auto& x) { return describe(x); }, s);
}
/// A shape and its body transform.
template <Scalar T>
std::string placed_text(const Shape<T>& s, const Transform<T>& x) {
  return describe(s) + " at p=" + vec(x.position()) + " q=" + vec(x.rotation());
}

/// The exact relation of two placed shapes (Contained is not told apart from Overlapping).
inline Relation placed_relation(const oracle::Placed& a, const oracle::Placed& b) {
  if (!oracle::overlaps(a, b)) return Relation::Separated;
  return oracle::within_band(a, b, 0.0) ? Relation::Touching : Relation::Overlapping;
}

template <Scalar T>
constexpr double eps() {
  return double(std::numeric_limits<T>::epsilon());
}

template <Scalar T>
bool is_compound(const Shape<T>& s) {
  return std::holds_alternative<Compound<T>>(s);
}

/// resolve()'s margin as resolve_margin()'s documentation states it, written out here so that the
/// resolution laws judge the library's margin instead of taking it from the library:
/// 4 * 64 * 2^-53 * s (s the pair's scale) + 8 eps_T (|n_x| S_x + |n_y| S_y + depth) (n the unit
/// push direction, each |n_i| taken at most 1; S_x, S_y the largest magnitudes per axis that moving
/// a rounds) + 16 subnormal units of double + 2 of T + extra (the placements' tolerances). Summed
/// in the library's order, so that the two agree to the bit.
template <Scalar T>
double documented_margin(double s, const Vec2<double>& s_moved, const Vec2<double>& n, double depth, double extra) {
  const double along = std::min(std::fabs(n.x()), 1.0) * s_moved.x() + std::min(std::fabs(n.y()), 1.0) * s_moved.y();
  return 4 * 64 * 0x1p-53 * s + 8 * eps<T>() * (along + depth) + 16 * 0x1p-1074 +
         2 * double(std::numeric_limits<T>::denorm_min()) + extra;
}

/// The direction a push's margin is judged along, per axis at least that of the normal it was
/// made from: resolve() rounds each component of -n L toward zero in T, so |n_i| L lies below
/// |v_i| plus one unit in the last place of v_i (a whole subnormal unit near zero, where the
/// rounded push can turn far from n), and L >= |v|. (1, 1) (every axis in full) for a zero push.
template <Scalar T>
Vec2<double> push_direction(const Vec2<T>& push) {
  const double len = push.template cast<double>().norm();
  if (!(len > 0)) return Vec2<double>(1, 1);
  Vec2<double> n;
  for (int i = 0; i < 2; ++i) {
    const T m = std::fabs(push[i]);
    const double unit = double(std::nextafter(m, std::numeric_limits<T>::infinity())) - double(m);
    n[i] = std::min(1.0, (double(m) + unit) / len);
  }
  return n;
}

/// The largest absolute x and y of a box.
template <Scalar T>
Vec2<double> axis_magnitudes(const Aabb<T>& box) {
  return {std::max(std::fabs(double(box.min().x())), std::fabs(double(box.max().x()))),
          std::max(std::fabs(double(box.min().y())), std::fabs(double(box.max().y())))};
}

/// documented_margin() of a stored pair: S_x, S_y are a's box's coordinates per axis or, for a
/// compound, the position of a child placed by a transform when larger (a move shifts that
/// position).
template <Scalar T>
double documented_margin(const Shape<T>& a, const Shape<T>& b, double depth, const Vec2<double>& n) {
  Vec2<double> s_moved = axis_magnitudes(bounds(a));
  if (const auto* c = std::get_if<Compound<T>>(&a); c && c->has_child_transforms()) {
    for (std::size_t i = 0; i < c->children().size(); ++i) {
      const Vec2<T> p = c->child_transform(i).position();
      s_moved.x() = std::max(s_moved.x(), std::fabs(double(p.x())));
      s_moved.y() = std::max(s_moved.y(), std::fabs(double(p.y())));
    }
  }
  const double s = std::max(::collide::detail::scale_of(bounds(a)), ::collide::detail::scale_of(bounds(b)));
  return documented_margin<T>(s, s_moved, n, depth, 2 * (placement_tolerance(a) + placement_tolerance(b)));
}

/// documented_margin() of a placed pair: S_x, S_y are a's placed box's coordinates per axis or its
/// position's when larger (a move shifts the transform's position).
template <Scalar T>
double documented_margin(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb,
                         double depth, const Vec2<double>& n) {
  if (xa.is_identity() && xb.is_identity()) return documented_margin(a, b, depth, n);
  Vec2<double> s_moved = axis_magnitudes(bounds(a, xa));
  s_moved.x() = std::max(s_moved.x(), std::fabs(double(xa.position().x())));
  s_moved.y() = std::max(s_moved.y(), std::fabs(double(xa.position().y())));
  const double s = std::max({s_moved.x(), s_moved.y(), ::collide::detail::scale_of(bounds(b, xb))});
  return documented_margin<T>(s, s_moved, n, depth, 2 * overlap_tolerance(a, xa, b, xb));
}

/// The primitive has interior points (no zero radius, extent or width).
template <Scalar T>
bool has_interior(const Primitive<T>& p) {
  return std::visit(
      [](const auto& s) {
        using S = std::remove_cvref_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Circle<T>> || std::is_same_v<S, Capsule<T>>) {
          return s.radius() > 0;
        } else if constexpr (std::is_same_v<S, Aabb<T>>) {
          return s.min().x() < s.max().x() && s.min().y() < s.max().y();
        } else if constexpr (std::is_same_v<S, Obb<T>>) {
          return s.half_extents().x() > 0 && s.half_extents().y() > 0;
        } else {
          return true;  // a stored polygon is never collinear
        }
      },
      p);
}

/// The primitive's core: a circle or capsule with radius 0 (other kinds are their own core).
template <Scalar T>
Primitive<T> core_primitive(const Primitive<T>& p) {
  if (const auto* c = std::get_if<Circle<T>>(&p)) return Circle<T>(c->center(), T(0));
  if (const auto* c = std::get_if<Capsule<T>>(&p)) return Capsule<T>(c->a(), c->b(), T(0));
  return p;
}

/// The primitive is rounded: a circle or capsule with a positive radius.
template <Scalar T>
bool is_rounded(const Primitive<T>& p) {
  if (const auto* c = std::get_if<Circle<T>>(&p)) return c->radius() > 0;
  if (const auto* c = std::get_if<Capsule<T>>(&p)) return c->radius() > 0;
  return false;
}

/// p is within d of the boundary of the closed primitive s (inside or outside), exactly.
template <Scalar T>
bool near_boundary(const Primitive<T>& s, const Vec2<double>& p, double d) {
  return oracle::compare_boundary_distance(s, p, d) <= 0;
}

/// p is within d of the boundary of a placed shape (a child placed by its transform), exactly.
inline bool near_boundary(const oracle::Placed& s, const Vec2<double>& p, double d) {
  return oracle::compare_boundary_distance(s, p, d) <= 0;
}

/// p is farther than d from the closed shape s, exactly. Asked through the point's distance to
/// the boundary rather than to a zero-radius circle at p: a point of a shape near the range's
/// edge (a ray hit, a contact point) may lie beyond max_magnitude, where no Circle can be built.
template <Scalar T>
bool farther_than(const Shape<T>& s, const Vec2<double>& p, double d) {
  return !oracle::contains(s, p) && oracle::compare_boundary_distance(s, p, d) > 0;
}

/// p is farther than d from the closed placed shape s, exactly (as farther_than()).
inline bool farther_than(const oracle::Placed& s, const Vec2<double>& p, double d) {
  return !oracle::contains(s, p) && oracle::compare_boundary_distance(s, p, d) > 0;
}

/// Sign of (signed distance from p to s - x), exactly, for a primitive s or a compound of one
/// child: inside, the signed distance is minus the distance to the boundary; outside, the distance.
inline int compare_signed_distance(const oracle::Placed& s, const Vec2<double>& p, double x) {
  if (oracle::contains(s, p)) return -oracle::compare_boundary_distance(s, p, -x);
  return oracle::compare_boundary_distance(s, p, x);
}

/// The exact parts of s placed by x, each a question compare_signed_distance() answers: s itself,
/// or each child of a compound as a compound of that one child (its child transform kept), placed
/// by x. signed_distance() of s is the least over them.
template <Scalar T>
std::vector<oracle::Placed> exact_parts(const Shape<T>& s, const Transform<T>& x = Transform<T>()) {
  std::vector<oracle::Placed> out;
  if (!std::holds_alternative<Compound<T>>(s)) {
    out.push_back(oracle::placed(s, x));
    return out;
  }
  for (const auto& child : placed_primitives_of(s)) {
    const Shape<T> one(Compound<T>::make_placed({child}).value());
    out.push_back(oracle::placed(one, x));
  }
  return out;
}

/// signed_distance()'s bound as its documentation states it, written out here (not taken from
/// the library): (64 * 2^-53 + 4 eps_T) * max(S, |p|_inf) + 2^-500 + denorm_min_T + placement, S the
/// largest absolute coordinate of the shape's box, `placement` its placement's tolerance.
template <Scalar T>
double documented_point_bound(const Aabb<T>& box, const Vec2<T>& p, double placement) {
  const double m = std::max(::collide::detail::scale_of(box), p.template cast<double>().cwiseAbs().maxCoeff());
  return (64 * 0x1p-53 + 4 * eps<T>()) * m + 0x1p-500 + double(std::numeric_limits<T>::denorm_min()) + placement;
}

/// closest_points()'s bound as its documentation states it: 4 error units + 2 eps_T S + 2
/// denorm_min_T, S the largest absolute coordinate of both shapes' boxes.
template <Scalar T>
double documented_witness_bound(double unit, const Aabb<T>& box_a, const Aabb<T>& box_b) {
  const double s = std::max(::collide::detail::scale_of(box_a), ::collide::detail::scale_of(box_b));
  return 4 * unit + 2 * eps<T>() * s + 2 * double(std::numeric_limits<T>::denorm_min());
}

/// The magnitude of signed_distance()'s answer `got` at the finite point p, judged exactly on the
/// parts of the shape (exact_parts()): within tol of their least signed distance, every part at
/// least got - tol and some part at most got + tol. +infinity only where that least exceeds
/// `top` (the largest finite T) less tol. A broken rule is reported by require(false, expected,
/// got).
template <class Require>
void judge_signed_magnitude(Require&& require, const std::vector<oracle::Placed>& parts, const Vec2<double>& p,
                            double got, double tol, double top) {
  if (std::isnan(got)) {
    require(false, "a number for a finite point", "NaN");
    return;
  }
  if (std::isinf(got)) {
    bool beyond = got > 0;
    for (const oracle::Placed& part : parts) beyond = beyond && compare_signed_distance(part, p, top - tol) > 0;
    require(beyond, "infinity only for a distance beyond " + num(top) + " less the bound " + num(tol), num(got));
    return;
  }
  bool above = true, below = false;
  for (const oracle::Placed& part : parts) {
    above = above && compare_signed_distance(part, p, got - tol) >= 0;
    below = below || compare_signed_distance(part, p, got + tol) <= 0;
  }
  require(above && below, "within " + num(tol) + " of the exact signed distance",
          num(got) + " (the exact one " + (above ? "above " + num(got + tol) : "below " + num(got - tol)) + ")");
}

/// closest_points()'s answer c judged on the exact shapes sa and sb: its distance is `dist`
/// (distance()'s answer) bit for bit, each point lies within tol of its shape (oracle), the two
/// points are one when the distance is 0, and otherwise |point_b - point_a| is the distance within
/// tol. A broken rule is reported by require(false, expected, got).
template <Scalar T, class Require>
void judge_witness(Require&& require, const oracle::Placed& sa, const oracle::Placed& sb, const ClosestPoints<T>& c,
                   T dist, double tol) {
  const Vec2<double> pa = widen(c.point_a), pb = widen(c.point_b);
  require(c.distance == dist, "distance() bit for bit: " + num(dist), num(c.distance));
  if (!pa.allFinite() || !pb.allFinite()) {
    require(false, "finite points", vec(c.point_a) + ", " + vec(c.point_b));
    return;
  }
  require(!farther_than(sa, pa, tol), "point_a within " + num(tol) + " of a", vec(c.point_a));
  require(!farther_than(sb, pb, tol), "point_b within " + num(tol) + " of b", vec(c.point_b));
  if (c.distance == T(0)) {
    require(c.point_a == c.point_b, "one point for shapes that overlap", vec(c.point_a) + " and " + vec(c.point_b));
    return;
  }
  const double apart = ::collide::detail::norm_of(Vec2<double>(pb - pa));
  require(std::fabs(apart - double(c.distance)) <= tol,
          "|point_b - point_a| within " + num(tol) + " of the distance " + num(c.distance), num(apart));
}

/// Exact sum test: a + t rounds to exactly r with no rounding error (computed in double, where
/// float sums are exact unless the exponents are far apart; the two-sum error catches that).
inline bool exact_sum(double a, double t, double r) {
  const double s = a + t;
  const double bb = s - a;
  const double err = (a - (s - bb)) + (t - bb);
  return err == 0 && s == r;
}

/// The stored positions of a primitive (centres, corners, end points, vertices), and the
/// shape-only values (radii, extents, axes) separately.
template <Scalar T>
void positions(const Primitive<T>& p, std::vector<Vec2<T>>& pos, std::vector<T>& other) {
  std::visit(
      [&](const auto& s) {
        using S = std::remove_cvref_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Circle<T>>) {
          pos.push_back(s.center());
          other.push_back(s.radius());
        } else if constexpr (std::is_same_v<S, Aabb<T>>) {
          pos.push_back(s.min());
          pos.push_back(s.max());
        } else if constexpr (std::is_same_v<S, Obb<T>>) {
          pos.push_back(s.center());
          other.insert(other.end(), {s.half_extents().x(), s.half_extents().y(), s.axis().x(), s.axis().y()});
        } else if constexpr (std::is_same_v<S, Capsule<T>>) {
          pos.push_back(s.a());
          pos.push_back(s.b());
          other.push_back(s.radius());
        } else {
          for (const Vec2<T>& q : s.vertices()) pos.push_back(q);
          other.push_back(T(s.size()));
        }
      },
      p);
}

/// A compound child placed by a transform: the transform's position is its position; its own
/// values and the rotation move with it, so they count as shape-only values.
template <Scalar T>
void positions(const Shape<T>& s, std::vector<Vec2<T>>& pos, std::vector<T>& other) {
  if (const auto* c = std::get_if<Compound<T>>(&s)) {
    for (std::size_t i = 0; i < c->children().size(); ++i) {
      const Transform<T> x = c->child_transform(i);
      if (x.is_identity()) {
        positions(c->children()[i], pos, other);
        continue;
      }
      pos.push_back(x.position());
      other.insert(other.end(), {x.rotation().x(), x.rotation().y()});
      std::vector<Vec2<T>> local;
      positions(c->children()[i], local, other);
      for (const Vec2<T>& q : local) other.insert(other.end(), {q.x(), q.y()});
    }
    return;
  }
  std::visit(
      [&](const auto& x) {
        using S = std::remove_cvref_t<decltype(x)>;
        if constexpr (!std::is_same_v<S, Compound<T>>) positions(Primitive<T>(x), pos, other);
      },
      s);
}

/// A quarter turn stored exactly: q is (+-1, 0) or (0, +-1).
template <Scalar T>
bool quarter_turn(const Transform<T>& x) {
  const T c = x.rotation().x(), s = x.rotation().y();
  return (std::fabs(c) == T(1) && s == T(0)) || (c == T(0) && std::fabs(s) == T(1));
}

/// Every child of s (a compound) is imaged exactly in double: placed by the identity, or by a
/// quarter turn whose sums (turned position + child position) do not round.
template <Scalar T>
bool exact_children(const Shape<T>& s) {
  const auto* c = std::get_if<Compound<T>>(&s);
  if (c == nullptr || !c->has_child_transforms()) return true;
  for (std::size_t i = 0; i < c->children().size(); ++i) {
    const Transform<T> x = c->child_transform(i);
    if (x.is_identity()) continue;
    if (!quarter_turn(x)) return false;
    std::vector<Vec2<T>> pos;
    std::vector<T> other;
    positions(c->children()[i], pos, other);
    for (const Vec2<T>& p : pos) {
      const Vec2c r = x.rotate(widen(p));  // exact for a quarter turn
      for (int k = 0; k < 2; ++k) {
        if (!exact_sum(r[k], double(x.position()[k]), r[k] + double(x.position()[k]))) return false;
      }
    }
  }
  return true;
}

/// moved is exactly s with every position moved by t (no rounding anywhere), and both are imaged
/// exactly (exact_children), so the move is exact for the shapes the queries see.
template <Scalar T>
bool exact_move(const Shape<T>& s, const Shape<T>& moved, const Vec2<T>& t) {
  if (!exact_children(s) || !exact_children(moved)) return false;
  std::vector<Vec2<T>> p0, p1;
  std::vector<T> o0, o1;
  positions(s, p0, o0);
  positions(moved, p1, o1);
  if (p0.size() != p1.size() || o0 != o1) return false;
  for (std::size_t i = 0; i < p0.size(); ++i) {
    for (int k = 0; k < 2; ++k) {
      if (!exact_sum(double(p0[i][k]), double(t[k]), double(p1[i][k]))) return false;
    }
  }
  return true;
}

/// moved is what translated(p, t) promises for a primitive (translate.hpp): every stored
/// position plus t rounded once to T, every other value bit for bit. A polygon rebuilt by its
/// factory may start at another vertex, and one that rounding made not strictly convex keeps a
/// subset of its moved vertices (their hull).
template <Scalar T>
bool moved_as_promised(const Primitive<T>& p, const Primitive<T>& moved, const Vec2<T>& t) {
  if (p.index() != moved.index()) return false;
  std::vector<Vec2<T>> p0, p1;
  std::vector<T> o0, o1;
  positions(p, p0, o0);
  positions(moved, p1, o1);
  std::vector<Vec2<T>> expected;
  for (const Vec2<T>& q : p0) expected.push_back(Vec2<T>(q + t));
  if (expected == p1 && o0 == o1) return true;
  if (!std::holds_alternative<ConvexPolygon<T>>(p)) return false;
  const auto before = [](const Vec2<T>& u, const Vec2<T>& w) {
    return u.x() < w.x() || (u.x() == w.x() && u.y() < w.y());
  };
  std::sort(expected.begin(), expected.end(), before);
  std::sort(p1.begin(), p1.end(), before);
  if (p1.size() == expected.size()) return p1 == expected;
  return std::includes(expected.begin(), expected.end(), p1.begin(), p1.end(), before);
}

/// moved is what translated(s, t) promises: a primitive as above; a compound child by child, a
/// child placed by a transform keeping its values and moving the transform's position.
template <Scalar T>
bool moved_as_promised(const Shape<T>& s, const Shape<T>& moved, const Vec2<T>& t) {
  if (s.index() != moved.index()) return false;
  const auto* c = std::get_if<Compound<T>>(&s);
  if (c == nullptr) {
    return std::visit(
        [&](const auto& x) {
          using S = std::remove_cvref_t<decltype(x)>;
          if constexpr (std::is_same_v<S, Compound<T>>) {
            return false;
          } else {
            return moved_as_promised(Primitive<T>(x), Primitive<T>(std::get<S>(moved)), t);
          }
        },
        s);
  }
  const auto& m = std::get<Compound<T>>(moved);
  if (c->children().size() != m.children().size()) return false;
  const auto same_values = [](const Primitive<T>& u, const Primitive<T>& w) {
    return moved_as_promised(u, w, Vec2<T>(T(0), T(0)));  // + 0 rounds nothing
  };
  for (std::size_t i = 0; i < c->children().size(); ++i) {
    const Transform<T> x = c->child_transform(i), y = m.child_transform(i);
    if (x.is_identity() != y.is_identity()) return false;
    if (x.is_identity() ? !moved_as_promised(c->children()[i], m.children()[i], t)
                        : !(y.position() == Vec2<T>(x.position() + t) && y.rotation() == x.rotation() &&
                            same_values(c->children()[i], m.children()[i])))
      return false;
  }
  return true;
}

/// The shapes on which the library decides s placed by x, in double: s's values widened (exact)
/// where nothing rounds, else the images it computes (detail/image.hpp: under a transform, and
/// for the children of a compound that carry transforms). overlaps() is exact on these, so the
/// library's answer must be the oracle's on them bit for bit; how far they lie from the exact
/// placement is the placement's own contract (transform_tolerance()).
template <Scalar T>
Shape<double> computed_geometry(const Shape<T>& s, const Transform<T>& x = Transform<T>()) {
  std::vector<Primitive<double>> parts;
  const auto add = [&](const auto& p) { parts.emplace_back(::collide::detail::widened_shape(p)); };
  std::visit(
      [&](const auto& c) {
        using S = std::remove_cvref_t<decltype(c)>;
        if constexpr (std::is_same_v<S, Compound<T>>) {
          if (x.is_identity()) {
            ::collide::detail::for_each_primitive(c, add);
          } else {
            ::collide::detail::for_each_primitive(placed(c, x.pose()), add);
          }
        } else if (x.is_identity()) {
          add(c);
        } else {
          ::collide::detail::with_image(c, x.pose(), add);
        }
      },
      s);
  if (!std::holds_alternative<Compound<T>>(s)) return std::visit([](auto& p) { return Shape<double>(p); }, parts[0]);
  return Shape<double>(Compound<double>(std::move(parts)));
}

}  // namespace collide::laws::detail
