// The laws on contact manifolds: per-point separations, feature ids, speculative contacts.

#include "support.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace collide::laws {

using detail::describe;
using detail::num;
using detail::vec;

namespace {

/// One law's verdict under construction: the first broken requirement is kept.
struct Judgement {
  Verdict v;
  std::string context;
  bool broken(std::string expected, std::string got) {
    v.ok = false;
    v.expected = std::move(expected);
    v.got = std::move(got);
    v.account = "expected " + v.expected + "; got " + v.got + "; " + context;
    return true;
  }
};

/// Runs a manifold law body; an exception from the oracle or the library fails the law.
template <Scalar T, class F>
Verdict judged(const Shape<T>& a, const Shape<T>& b, F&& body) {
  Judgement j;
  j.context = "a = " + describe(a) + "; b = " + describe(b);
  try {
    j.v.relation = relation(a, b);
    body(j);
  } catch (const std::exception& e) {
    j.broken("no exception", std::string("exception: ") + e.what());
  }
  return j.v;
}

/// judged() on contact(a, b), when there is one.
template <Scalar T, class F>
Verdict judged_contact(const Shape<T>& a, const Shape<T>& b, F&& body) {
  return judged(a, b, [&](Judgement& j) {
    const auto c = contact(a, b);
    if (c) {
      body(j, *c);
    } else {
      j.v.account = "no contact";
    }
  });
}

/// The bound of a contact point's rounded values: 4 rounding tolerances (as contact_law), the
/// rounding of the point and of the separation to T, and the normal's rounding over half the
/// separation.
template <Scalar T>
double point_bound(const Shape<T>& a, const Shape<T>& b, double separation) {
  const double scale = std::max(::collide::detail::scale_of(bounds(a)), ::collide::detail::scale_of(bounds(b)));
  return 4 * rounding_tolerance(a, b) + 2 * detail::eps<T>() * scale + 8 * detail::eps<T>() * std::fabs(separation) +
         2 * double(std::numeric_limits<T>::denorm_min());
}

/// A primitive placed by its child transform (the identity outside compounds).
template <Scalar T>
using Placed = typename Compound<T>::Child;

/// The primitive a feature id's child index names (nullptr when the index is out of range).
template <class P>
const P* child_named(const std::vector<P>& prims, std::uint16_t child) {
  return child < prims.size() ? &prims[child] : nullptr;
}

/// A named feature as segments of the primitive's core (a vertex: its one or two adjacent edges,
/// or the point itself), and the radius around them; false when the numbering of feature.hpp does
/// not name such a feature, or the shape is numbered along rounded corners (a box thinner than
/// their rounding), which the law does not rebuild.
struct FeatureShape {
  std::vector<std::array<Vec2c, 2>> segments;
  double radius = 0;
};
template <Scalar T>
bool feature_shape(const Primitive<T>& p, FeatureKind kind, unsigned index, FeatureShape& out) {
  std::vector<Vec2c> core;
  std::visit(
      [&](const auto& s) {
        using S = std::remove_cvref_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Circle<T>>) {
          core = {widen(s.center())};
          out.radius = s.radius();
        } else if constexpr (std::is_same_v<S, Capsule<T>>) {
          core = {widen(s.a())};
          if (s.b() != s.a()) core.push_back(widen(s.b()));
          out.radius = s.radius();
        } else if constexpr (std::is_same_v<S, Aabb<T>>) {
          const Vec2c lo = widen(s.min()), hi = widen(s.max());
          if (lo.x() == hi.x() || lo.y() == hi.y()) {
            core = {lo};
            if (hi != lo) core.push_back(hi);
          } else {
            core = {lo, Vec2c(hi.x(), lo.y()), hi, Vec2c(lo.x(), hi.y())};
          }
        } else if constexpr (std::is_same_v<S, Obb<T>>) {
          const ::collide::detail::Core k = ::collide::detail::core_of(s);
          const Vec2c c = widen(s.center()), u = widen(s.axis());
          const Vec2c ex = u * double(s.half_extents().x()), ey = perp(u) * double(s.half_extents().y());
          const bool flat = s.half_extents().x() == 0 || s.half_extents().y() == 0;
          const Vec2c first = c - ex - ey;
          // Numbered as documented only when the core kept the computed corners in order.
          if ((flat && k.size() <= 2) || (!flat && k.size() == 4 && k[0] == first)) {
            for (const Vec2c& x : k.pts()) core.push_back(x);
          }
        } else {
          for (const Vec2<T>& x : s.vertices()) core.push_back(widen(x));
        }
      },
      p);
  const std::size_t n = core.size();
  if (n == 0) return false;
  auto edge = [&](std::size_t i) { return std::array<Vec2c, 2>{core[i % n], core[(i + 1) % n]}; };
  if (kind == FeatureKind::Vertex) {
    if (index >= n) return false;
    if (n == 1) out.segments = {{core[0], core[0]}};
    if (n == 2) out.segments = {{core[index], core[index]}, {core[0], core[1]}};
    if (n >= 3) out.segments = {edge(index), edge(index + n - 1)};
    return true;
  }
  if (n == 1 || (n == 2 && index > 1) || (n >= 3 && index >= n)) return false;
  out.segments = {n == 2 ? std::array<Vec2c, 2>{core[0], core[1]} : edge(index)};
  return true;
}

double distance_to_segment(const Vec2c& x, const std::array<Vec2c, 2>& s) {
  const Vec2c d = s[1] - s[0];
  const double dd = d.squaredNorm();
  const double t = dd > 0 ? std::clamp((x - s[0]).dot(d) / dd, 0.0, 1.0) : 0.0;
  return (x - (s[0] + d * t)).norm();
}

/// The surface points of point i: a's at p - n s / 2, b's at p + n s / 2.
template <Scalar T>
std::array<Vec2c, 2> surface_points(const Contact<T>& c, int i) {
  const Vec2c p = c.points[std::size_t(i)].template cast<double>(), n = c.normal.template cast<double>();
  const double s = c.separations[std::size_t(i)];
  return {Vec2c(p - n * (s / 2)), Vec2c(p + n * (s / 2))};
}

/// The primitive pair of point i (children named by its id); false, with the law broken, when an
/// id names a child that does not exist.
template <Scalar T>
bool point_pair(Judgement& j, const Shape<T>& a, const Shape<T>& b, const Contact<T>& c, int i, const Placed<T>*& pa,
                const Placed<T>*& pb, std::vector<Placed<T>>& ka, std::vector<Placed<T>>& kb) {
  ka = detail::placed_primitives_of(a);
  kb = detail::placed_primitives_of(b);
  const FeatureId& id = c.ids[std::size_t(i)];
  pa = child_named(ka, id.child_a);
  pb = child_named(kb, id.child_b);
  if (pa != nullptr && pb != nullptr) return true;
  j.broken("point " + std::to_string(i) + "'s id names children of a and b",
           "child " + std::to_string(id.child_a) + " of " + std::to_string(ka.size()) + ", child " +
               std::to_string(id.child_b) + " of " + std::to_string(kb.size()));
  return false;
}

/// The separation requirements of one point (see manifold_separation in laws.hpp).
template <Scalar T>
bool check_point_separation(Judgement& j, const Shape<T>& a, const Shape<T>& b, const Contact<T>& c, int i) {
  const double s = c.separations[std::size_t(i)];
  if (!std::isfinite(s)) return !j.broken("a finite separation", "separation " + num(s));
  const Placed<T>*pa = nullptr, *pb = nullptr;
  std::vector<Placed<T>> ka, kb;
  if (!point_pair(j, a, b, c, i, pa, pb, ka, kb)) return false;
  const double bound = point_bound(a, b, s);
  const std::array<Vec2c, 2> x = surface_points(c, i);
  const Placed<T>* prims[2] = {pa, pb};
  for (int k = 0; k < 2; ++k) {
    const oracle::Placed p = oracle::placed(prims[k]->shape, prims[k]->transform);
    if (!detail::near_boundary(p, x[std::size_t(k)], bound)) {
      return !j.broken("point " + std::to_string(i) + ": " + (k == 0 ? "a" : "b") + "'s surface point " +
                           (k == 0 ? "p - n s/2" : "p + n s/2") + " within " + num(bound) + " of its boundary",
                       "point " + vec(c.points[std::size_t(i)]) + ", separation " + num(s) + ", normal " +
                           vec(c.normal) + ": surface point " + vec(Vec2<double>(x[std::size_t(k)])) +
                           " is farther (from " + describe(prims[k]->shape, prims[k]->transform) + ")");
    }
  }
  // No point deeper than the exact depth of its pair (nor nearer than its exact gap).
  const oracle::Placed sa = oracle::placed(pa->shape, pa->transform), sb = oracle::placed(pb->shape, pb->transform);
  if (s < 0 && -s - bound > 0 && oracle::compare_depth(sa, sb, -s - bound) < 0) {
    return !j.broken("point " + std::to_string(i) + " no deeper than the exact depth + " + num(bound),
                     "separation " + num(s) + ", exact depth ~" + num(-oracle::approx_signed_distance(sa, sb)));
  }
  if (s > 0 && oracle::compare_distance(sa, sb, s + bound) > 0) {
    return !j.broken("point " + std::to_string(i) + " no nearer than the exact gap - " + num(bound),
                     "separation " + num(s) + ", exact gap ~" + num(oracle::approx_signed_distance(sa, sb)));
  }
  return true;
}

/// The feature-id requirements of one point: each id names a feature of its shape that lies
/// near that shape's surface point.
template <Scalar T>
bool check_point_features(Judgement& j, const Shape<T>& a, const Shape<T>& b, const Contact<T>& c, int i,
                          std::string& skipped) {
  const Placed<T>*pa = nullptr, *pb = nullptr;
  std::vector<Placed<T>> ka, kb;
  if (!point_pair(j, a, b, c, i, pa, pb, ka, kb)) return false;
  const FeatureId& id = c.ids[std::size_t(i)];
  const std::array<Vec2c, 2> x = surface_points(c, i);
  const double bound = point_bound(a, b, c.separations[std::size_t(i)]) + 4 * double(c.depth);
  const Placed<T>* prims[2] = {pa, pb};
  const FeatureKind kinds[2] = {id.kind_a, id.kind_b};
  const unsigned index[2] = {id.index_a, id.index_b};
  for (int k = 0; k < 2; ++k) {
    FeatureShape f;
    if (!feature_shape(prims[k]->shape, kinds[k], index[k], f)) {
      if (std::holds_alternative<Obb<T>>(prims[k]->shape)) {
        skipped += " obb numbered along rounded corners";
        continue;
      }
      return !j.broken("point " + std::to_string(i) + "'s id names a feature of " + (k == 0 ? "a" : "b"),
                       std::string(kinds[k] == FeatureKind::Edge ? "edge " : "vertex ") + std::to_string(index[k]) +
                           " of " + describe(prims[k]->shape, prims[k]->transform));
    }
    // The feature as its child transform places it (rounded in double: within the bound).
    for (auto& seg : f.segments) {
      for (Vec2c& q : seg) q = prims[k]->transform.apply(q);
    }
    double d = std::numeric_limits<double>::infinity();
    for (const auto& seg : f.segments) d = std::min(d, distance_to_segment(x[std::size_t(k)], seg));
    if (!(d <= f.radius + bound)) {
      return !j.broken(
          "point " + std::to_string(i) + "'s " + (k == 0 ? "a" : "b") + " feature (" +
              (kinds[k] == FeatureKind::Edge ? "edge " : "vertex ") + std::to_string(index[k]) + ") within radius + " +
              num(bound) + " of its surface point",
          "distance " + num(d) + " from " + vec(Vec2<double>(x[std::size_t(k)])) + " (radius " + num(f.radius) + ")");
    }
  }
  return true;
}

/// The ids of a contact as a sorted list.
template <Scalar T>
std::vector<std::uint64_t> id_keys(const Contact<T>& c) {
  std::vector<std::uint64_t> k;
  for (int i = 0; i < c.count; ++i) k.push_back(c.ids[std::size_t(i)].key());
  std::sort(k.begin(), k.end());
  return k;
}

template <Scalar T>
std::string ids_text(const Contact<T>& c) {
  std::string out;
  for (int i = 0; i < c.count; ++i) {
    const FeatureId& id = c.ids[std::size_t(i)];
    out += (i ? ", " : "") + std::string("[") + std::to_string(id.child_a) + ":" +
           (id.kind_a == FeatureKind::Edge ? "e" : "v") + std::to_string(id.index_a) + " " +
           std::to_string(id.child_b) + ":" + (id.kind_b == FeatureKind::Edge ? "e" : "v") +
           std::to_string(id.index_b) + "]";
  }
  return out;
}

/// Whether the child pair that moved's ids name differs from c's and, on the unmoved shapes,
/// overlaps as deeply as c within the point bound plus twice the move's length: a compound's
/// contact is the deepest among its child pairs, and a pair's depth changes by at most the length
/// of a move, so a pair that is deepest after b moves by +t and by -t is, unmoved, within 2 |t| of
/// the deepest. That is how a motion changes the deepest pair at one configuration only (a child
/// pair whose depth peaks there, as a point at a circle's centre, beside one whose depth falls on
/// one side and rises on the other).
template <Scalar T>
bool tied_child_pairs(const Shape<T>& a, const Shape<T>& b, const Contact<T>& c, const Contact<T>& moved, double move) {
  const FeatureId &was = c.ids[0], &now = moved.ids[0];
  if (was.child_a == now.child_a && was.child_b == now.child_b) return false;
  const std::vector<Placed<T>> ka = detail::placed_primitives_of(a), kb = detail::placed_primitives_of(b);
  const Placed<T>*pa = child_named(ka, now.child_a), *pb = child_named(kb, now.child_b);
  if (pa == nullptr || pb == nullptr) return false;
  const auto other = std::visit(
      [&](const auto& x, const auto& y) { return contact(x, pa->transform, y, pb->transform); }, pa->shape, pb->shape);
  return other && std::fabs(double(other->depth) - double(c.depth)) <= point_bound(a, b, double(c.depth)) + 2 * move;
}

/// Whether the face that moved's contact names is, on the unmoved shapes, as shallow as c's within
/// the point bound plus twice the move's length: a's depth along a fixed normal changes by at most
/// the length of a move of b, so a normal of least depth after b moves by +t and by -t is, unmoved,
/// within 2 |t| of the least depth, and either face may be reported. Such a tie holds where the
/// depth behind two faces has a corner (a circle's centre on a box's medial axis). Only for faces
/// whose normals differ (by more than 2.5 degrees): parallel faces tied up to rounding must keep
/// their order, and an incident face changing under one normal is no tie of depths.
template <Scalar T>
bool tied_faces(const Shape<T>& a, const Shape<T>& b, const Contact<T>& c, const Contact<T>& moved, double move) {
  const Vec2<double> n = moved.normal.template cast<double>();
  if (!(std::fabs(n.norm() - 1) <= 8 * detail::eps<T>())) return false;
  if (n.dot(c.normal.template cast<double>()) > 0.999) return false;
  const double reach = double(c.depth) + 2 * move + point_bound(a, b, double(c.depth));
  return oracle::separates(a, b, Vec2<double>(-n * reach));
}

/// b moved by t, or nullopt when the move has no representation in T.
template <Scalar T>
std::optional<Shape<T>> moved(const Shape<T>& b, const Vec2<T>& t) {
  return std::visit(
      [&](const auto& s) -> std::optional<Shape<T>> {
        const auto m = translated(s, t);
        if (!m) return std::nullopt;
        return Shape<T>(m.value());
      },
      b);
}

}  // namespace

template <Scalar T>
Verdict manifold_separation(const Shape<T>& a, const Shape<T>& b) {
  return judged_contact(a, b, [&](Judgement& j, const Contact<T>& k) {
    const Contact<T>* c = &k;
    j.v.account = "contact of " + std::to_string(c->count) + " points, separations " + num(c->separations[0]) +
                  (c->count > 1 ? ", " + num(c->separations[1]) : "");
    for (int i = 0; i < c->count; ++i) {
      if (!(c->separations[std::size_t(i)] <= point_bound(a, b, 0))) {
        j.broken("point " + std::to_string(i) + " penetrating or touching (separation <= " + num(point_bound(a, b, 0)) +
                     ") without a speculative distance",
                 "separation " + num(c->separations[std::size_t(i)]));
        return;
      }
      if (!check_point_separation(j, a, b, *c, i)) return;
    }
  });
}

template <Scalar T>
Verdict manifold_ids(const Shape<T>& a, const Shape<T>& b) {
  return judged_contact(a, b, [&](Judgement& j, const Contact<T>& k) {
    const Contact<T>* c = &k;
    std::string skipped;
    for (int i = 0; i < c->count; ++i) {
      if (!check_point_features(j, a, b, *c, i, skipped)) return;
    }
    if (c->count == 2 && c->ids[0] == c->ids[1]) {
      j.broken("two points with different ids", "both " + ids_text(*c));
      return;
    }
    j.v.account = "ids " + ids_text(*c) + (skipped.empty() ? "" : "; not rebuilt:" + skipped);
    // Stability: b moved by +-t, t tiny next to the shapes. When both moves give the same ids,
    // the features did not change on the way, so the unmoved pair has those ids too.
    // The move is (3, 4) times a power of two, so that it adds exactly to the stored positions
    // (exact_move): only then does the motion from b - t to b + t pass through b itself.
    // Its length follows the shapes' size (their coordinates' magnitude when both are points), so
    // that the move stays tiny next to them.
    const auto side = [](const Aabb<T>& x) {
      return std::max(double(x.max().x() - x.min().x()), double(x.max().y() - x.min().y()));
    };
    const double size = std::max(side(bounds(a)), side(bounds(b)));
    const double scale =
        size > 0 ? size : std::max(::collide::detail::scale_of(bounds(a)), ::collide::detail::scale_of(bounds(b)));
    if (!(scale > 0) || !std::isfinite(scale)) return;
    // At least T's spacing at b's largest coordinate, so that 3 and 4 times it add exactly to
    // b's stored positions (a sum crossing a power of two may still round: exact_move checks);
    // up to 2^-12 of the size, beyond which the move is not tiny next to the shapes: not used.
    const double reach = ::collide::detail::scale_of(bounds(b));
    const int want = std::ilogb(scale) - 20;
    const int spacing = reach > 0 ? std::ilogb(reach) - std::numeric_limits<T>::digits + 1 : want;
    if (spacing > want + 8) {
      j.v.account += "; move rounds";
      return;
    }
    const T quarter = static_cast<T>(std::ldexp(1.0, std::max(want, spacing)));
    if (!(quarter > 0) || !std::isfinite(double(quarter))) return;
    const Vec2<T> t(T(3) * quarter, T(4) * quarter);
    const auto plus = moved(b, Vec2<T>(t)), minus = moved(b, Vec2<T>(-t));
    if (!plus || !minus) {
      j.v.account += "; move not representable";
      return;
    }
    if (!detail::exact_move(b, *plus, t) || !detail::exact_move(b, *minus, Vec2<T>(-t))) {
      j.v.account += "; move rounds";
      return;
    }
    const auto cp = contact(a, *plus), cm = contact(a, *minus);
    if (!cp || !cm || cp->count != c->count || cm->count != c->count || id_keys(*cp) != id_keys(*cm)) {
      j.v.account += "; features change within the move";
      return;
    }
    if (id_keys(*c) != id_keys(*cp)) {
      const double move = t.template cast<double>().norm();
      if (tied_child_pairs(a, b, *c, *cp, move)) {
        j.v.account += "; child pairs tied for the deepest (either may be reported)";
        return;
      }
      if (tied_faces(a, b, *c, *cp, move)) {
        j.v.account += "; faces tied for the least depth within the move (either may be reported)";
        return;
      }
      j.broken("the ids of b moved by +-" + vec(t) + " (" + ids_text(*cp) + ") for b itself", ids_text(*c));
    }
  });
}

template <Scalar T>
Verdict manifold_speculative(const Shape<T>& a, const Shape<T>& b) {
  return judged(a, b, [&](Judgement& j) {
    // A speculative distance of about a tenth of the pair's size, a power of two (exact in T).
    const auto box = [](const Aabb<T>& x) {
      return std::max(double(x.max().x() - x.min().x()), double(x.max().y() - x.min().y()));
    };
    const double size = std::max(box(bounds(a)), box(bounds(b)));
    const T spec = static_cast<T>(std::ldexp(1.0, std::ilogb(std::max(size, 1e-30)) - 3));
    const bool over = overlaps(a, b);
    const auto c = contact(a, b, spec);
    const double bound = point_bound(a, b, double(spec));
    j.v.account = "speculative " + num(spec) + ": " + (c ? "contact" : "none") + (over ? " (overlapping)" : "");
    if (over) {
      const auto plain = contact(a, b);
      if (!c || c->normal != plain->normal || c->depth != plain->depth || c->count < plain->count) {
        j.broken("for an overlapping pair, contact(a, b)'s normal and depth and at least its points",
                 c ? "normal " + vec(c->normal) + " depth " + num(c->depth) + " count " + std::to_string(c->count)
                   : std::string("no contact"));
        return;
      }
    } else if (!c) {
      if (oracle::compare_distance(a, b, double(spec) - bound) < 0) {
        j.broken("a speculative contact for a gap below " + num(double(spec) - bound),
                 "none; exact gap ~" + num(oracle::approx_signed_distance(a, b)));
      }
      return;
    } else {
      if (oracle::compare_distance(a, b, double(spec) + bound) > 0) {
        j.broken("no contact for a gap above " + num(double(spec) + bound),
                 "a contact; exact gap ~" + num(oracle::approx_signed_distance(a, b)));
        return;
      }
      if (c->depth != 0) {
        j.broken("depth 0 for shapes apart", "depth " + num(c->depth));
        return;
      }
      // The shapes approach along the normal by its gap less the bound without meeting.
      const Vec2c n = c->normal.template cast<double>();
      if (!(std::fabs(n.norm() - 1) <= 8 * detail::eps<T>())) {
        j.broken("a unit normal", "|normal| = " + num(n.norm()));
        return;
      }
      const double s0 = std::min(double(c->separations[0]), c->count > 1 ? double(c->separations[1]) : 1e300);
      if (s0 - bound > 0 && !oracle::separates(a, b, Vec2<double>(n * (s0 - bound)))) {
        j.broken("a moved by normal * (separation - " + num(bound) + ") still apart from b",
                 "overlapping after " + vec(Vec2<double>(n * (s0 - bound))) + " (separation " + num(s0) + ")");
        return;
      }
      // The smallest separation is the gap.
      if (oracle::compare_distance(a, b, s0 - bound) < 0 || oracle::compare_distance(a, b, s0 + bound) > 0) {
        j.broken("the smallest separation within " + num(bound) + " of the exact gap",
                 "separation " + num(s0) + ", exact gap ~" + num(oracle::approx_signed_distance(a, b)));
        return;
      }
    }
    for (int i = 0; i < c->count; ++i) {
      if (!(c->separations[std::size_t(i)] <= double(spec) + bound)) {
        j.broken("every point apart by at most the speculative distance " + num(spec),
                 "separation " + num(c->separations[std::size_t(i)]));
        return;
      }
      if (!check_point_separation(j, a, b, *c, i)) return;
    }
  });
}

#define COLLIDE_MANIFOLD_LAWS_INSTANTIATE(T)                                 \
  template Verdict manifold_separation<T>(const Shape<T>&, const Shape<T>&); \
  template Verdict manifold_ids<T>(const Shape<T>&, const Shape<T>&);        \
  template Verdict manifold_speculative<T>(const Shape<T>&, const Shape<T>&);

COLLIDE_MANIFOLD_LAWS_INSTANTIATE(float)
COLLIDE_MANIFOLD_LAWS_INSTANTIATE(double)

}  // namespace collide::laws
