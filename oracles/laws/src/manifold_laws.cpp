// The laws on contact manifolds: per-point separations, feature ids, speculative contacts, for
// shapes in world space and for shapes placed by body transforms (one implementation: the
// world-space laws are the placed ones with two identities).

#include "support.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace collide::laws {

using detail::describe;
using detail::distance_to_segment;
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

/// The pair a manifold law judges: a and b, each placed by its body transform. With two
/// identities (the world-space laws) the world-space queries, bounds and tolerance are used, as
/// the laws were written for them.
template <Scalar T>
struct PairIn {
  Shape<T> a, b;
  Transform<T> xa, xb;

  bool world() const { return xa.is_identity() && xb.is_identity(); }
  /// contact(), with a speculative distance when given.
  std::optional<Contact<T>> contact(std::optional<T> speculative = std::nullopt) const {
    if (world()) return speculative ? collide::contact(a, b, *speculative) : collide::contact(a, b);
    return speculative ? collide::contact(a, xa, b, xb, *speculative) : collide::contact(a, xa, b, xb);
  }
  bool overlapping() const { return world() ? collide::overlaps(a, b) : collide::overlaps(a, xa, b, xb); }
  /// The exact images.
  oracle::Placed exact_a() const { return oracle::placed(a, xa); }
  oracle::Placed exact_b() const { return oracle::placed(b, xb); }
  Aabb<T> box_a() const { return world() ? bounds(a) : bounds(a, xa); }
  Aabb<T> box_b() const { return world() ? bounds(b) : bounds(b, xb); }
  /// The unit of the rounded outputs' error.
  double tolerance() const { return world() ? rounding_tolerance(a, b) : rounding_tolerance(a, xa, b, xb); }
  std::string text() const {
    return world() ? "a = " + describe(a) + "; b = " + describe(b)
                   : "a = " + detail::placed_text(a, xa) + "; b = " + detail::placed_text(b, xb);
  }
};

/// Runs a manifold law body; an exception from the oracle or the library fails the law.
template <Scalar T, class F>
Verdict judged(const PairIn<T>& in, F&& body) {
  Judgement j;
  j.context = in.text();
  try {
    j.v.relation = in.world() ? relation(in.a, in.b) : detail::placed_relation(in.exact_a(), in.exact_b());
    body(j);
  } catch (const std::exception& e) {
    j.broken("no exception", std::string("exception: ") + e.what());
  }
  return j.v;
}

/// judged() on the pair's contact, when there is one.
template <Scalar T, class F>
Verdict judged_contact(const PairIn<T>& in, F&& body) {
  return judged(in, [&](Judgement& j) {
    const auto c = in.contact();
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
double point_bound(const PairIn<T>& in, double separation) {
  const double scale = std::max(::collide::detail::scale_of(in.box_a()), ::collide::detail::scale_of(in.box_b()));
  return 4 * in.tolerance() + 2 * detail::eps<T>() * scale + 8 * detail::eps<T>() * std::fabs(separation) +
         2 * double(std::numeric_limits<T>::denorm_min());
}

/// A primitive of a placed shape: a compound's child with its child transform (or the shape
/// itself with the identity), and the shape's body transform.
template <Scalar T>
struct Placed {
  Primitive<T> shape;
  Transform<T> transform;  ///< the child transform
  Transform<T> body;

  /// The primitive alone, placed as in its shape: a compound of it with its child transform when
  /// the body is not the identity (the body transform then places that compound).
  Shape<T> alone() const { return Shape<T>(Compound<T>::make_placed({{shape, transform}}).value()); }
  /// Its exact image: the body after the child transform.
  oracle::Placed exact() const {
    if (transform.is_identity()) return oracle::placed(shape, body);
    return body.is_identity() ? oracle::placed(shape, transform) : oracle::placed(alone(), body);
  }
  /// A point of the primitive's frame in the world (rounded in double).
  Vec2c apply(const Vec2c& x) const { return body.apply(transform.apply(x)); }
  std::string text() const {
    return describe(shape, transform) +
           (body.is_identity() ? "" : " in a body at p=" + vec(body.position()) + " q=" + vec(body.rotation()));
  }
};

/// The primitives of s placed by body.
template <Scalar T>
std::vector<Placed<T>> placed_parts(const Shape<T>& s, const Transform<T>& body) {
  std::vector<Placed<T>> out;
  for (auto& c : detail::placed_primitives_of(s)) out.push_back({std::move(c.shape), c.transform, body});
  return out;
}

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
/// The core's points of a primitive as feature.hpp numbers them (empty when the numbering is not
/// rebuilt, as feature_shape() says), and its radius.
template <Scalar T>
std::vector<Vec2c> feature_core(const Primitive<T>& p, double& radius) {
  std::vector<Vec2c> core;
  std::visit(
      [&](const auto& s) {
        using S = std::remove_cvref_t<decltype(s)>;
        if constexpr (std::is_same_v<S, Circle<T>>) {
          core = {widen(s.center())};
          radius = s.radius();
        } else if constexpr (std::is_same_v<S, Capsule<T>>) {
          core = {widen(s.a())};
          if (s.b() != s.a()) core.push_back(widen(s.b()));
          radius = s.radius();
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
  return core;
}

template <Scalar T>
bool feature_shape(const Primitive<T>& p, FeatureKind kind, unsigned index, FeatureShape& out) {
  const std::vector<Vec2c> core = feature_core(p, out.radius);
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
bool point_pair(Judgement& j, const PairIn<T>& in, const Contact<T>& c, int i, const Placed<T>*& pa,
                const Placed<T>*& pb, std::vector<Placed<T>>& ka, std::vector<Placed<T>>& kb) {
  ka = placed_parts(in.a, in.xa);
  kb = placed_parts(in.b, in.xb);
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
bool check_point_separation(Judgement& j, const PairIn<T>& in, const Contact<T>& c, int i) {
  const double s = c.separations[std::size_t(i)];
  if (!std::isfinite(s)) return !j.broken("a finite separation", "separation " + num(s));
  const Placed<T>*pa = nullptr, *pb = nullptr;
  std::vector<Placed<T>> ka, kb;
  if (!point_pair(j, in, c, i, pa, pb, ka, kb)) return false;
  const double bound = point_bound(in, s);
  const std::array<Vec2c, 2> x = surface_points(c, i);
  const Placed<T>* prims[2] = {pa, pb};
  for (int k = 0; k < 2; ++k) {
    const oracle::Placed p = prims[k]->exact();
    if (!detail::near_boundary(p, x[std::size_t(k)], bound)) {
      return !j.broken("point " + std::to_string(i) + ": " + (k == 0 ? "a" : "b") + "'s surface point " +
                           (k == 0 ? "p - n s/2" : "p + n s/2") + " within " + num(bound) + " of its boundary",
                       "point " + vec(c.points[std::size_t(i)]) + ", separation " + num(s) + ", normal " +
                           vec(c.normal) + ": surface point " + vec(Vec2<double>(x[std::size_t(k)])) +
                           " is farther (from " + prims[k]->text() + ")");
    }
  }
  // No point deeper than the exact depth of its pair (nor nearer than its exact gap).
  const oracle::Placed sa = pa->exact(), sb = pb->exact();
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

/// Whether a placed box or polygon is thinner than w (the least, over its edges, of its farthest
/// vertex's distance from the edge's line): its image's corners, rounded by about w, need not keep
/// the numbering of its stored ones, as for an OBB thinner than its corners' rounding.
template <Scalar T>
bool thinner_than(const Placed<T>& part, double w) {
  double radius = 0;
  const std::vector<Vec2c> core = feature_core(part.shape, radius);
  const std::size_t n = core.size();
  if (n < 3) return false;
  double thinnest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2c e = core[(i + 1) % n] - core[i];
    const double len = e.norm();
    if (!(len > 0)) return true;
    double far = 0;
    for (const Vec2c& x : core) far = std::max(far, std::fabs(perp(e).dot(x - core[i])) / len);
    thinnest = std::min(thinnest, far);
  }
  return thinnest <= w;
}

/// The feature-id requirements of one point: each id names a feature of its shape that lies
/// near that shape's surface point.
template <Scalar T>
bool check_point_features(Judgement& j, const PairIn<T>& in, const Contact<T>& c, int i, std::string& skipped) {
  const Placed<T>*pa = nullptr, *pb = nullptr;
  std::vector<Placed<T>> ka, kb;
  if (!point_pair(j, in, c, i, pa, pb, ka, kb)) return false;
  const FeatureId& id = c.ids[std::size_t(i)];
  const std::array<Vec2c, 2> x = surface_points(c, i);
  const double bound = point_bound(in, c.separations[std::size_t(i)]) + 4 * double(c.depth);
  const Placed<T>* prims[2] = {pa, pb};
  const FeatureKind kinds[2] = {id.kind_a, id.kind_b};
  const unsigned index[2] = {id.index_a, id.index_b};
  for (int k = 0; k < 2; ++k) {
    if (!in.world() && thinner_than(*prims[k], bound)) {
      skipped += " a placed image thinner than its rounding";
      continue;
    }
    FeatureShape f;
    if (!feature_shape(prims[k]->shape, kinds[k], index[k], f)) {
      if (std::holds_alternative<Obb<T>>(prims[k]->shape)) {
        skipped += " obb numbered along rounded corners";
        continue;
      }
      return !j.broken("point " + std::to_string(i) + "'s id names a feature of " + (k == 0 ? "a" : "b"),
                       std::string(kinds[k] == FeatureKind::Edge ? "edge " : "vertex ") + std::to_string(index[k]) +
                           " of " + prims[k]->text());
    }
    // The feature as its child and body transforms place it (rounded in double: within the bound).
    for (auto& seg : f.segments) {
      for (Vec2c& q : seg) q = prims[k]->apply(q);
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
bool tied_child_pairs(const PairIn<T>& in, const Contact<T>& c, const Contact<T>& moved, double move) {
  const FeatureId &was = c.ids[0], &now = moved.ids[0];
  if (was.child_a == now.child_a && was.child_b == now.child_b) return false;
  const std::vector<Placed<T>> ka = placed_parts(in.a, in.xa), kb = placed_parts(in.b, in.xb);
  const Placed<T>*pa = child_named(ka, now.child_a), *pb = child_named(kb, now.child_b);
  if (pa == nullptr || pb == nullptr) return false;
  const auto other =
      in.world() ? std::visit([&](const auto& x, const auto& y) { return contact(x, pa->transform, y, pb->transform); },
                              pa->shape, pb->shape)
                 : contact(pa->alone(), in.xa, pb->alone(), in.xb);
  return other && std::fabs(double(other->depth) - double(c.depth)) <= point_bound(in, double(c.depth)) + 2 * move;
}

/// Whether the face that moved's contact names is, on the unmoved shapes, as shallow as c's within
/// the point bound plus twice the move's length: a's depth along a fixed normal changes by at most
/// the length of a move of b, so a normal of least depth after b moves by +t and by -t is, unmoved,
/// within 2 |t| of the least depth, and either face may be reported. Such a tie holds where the
/// depth behind two faces has a corner (a circle's centre on a box's medial axis). Only for faces
/// whose normals differ (by more than 2.5 degrees): parallel faces tied up to rounding must keep
/// their order, and an incident face changing under one normal is no tie of depths.
template <Scalar T>
bool tied_faces(const PairIn<T>& in, const Contact<T>& c, const Contact<T>& moved, double move) {
  const Vec2<double> n = moved.normal.template cast<double>();
  if (!(std::fabs(n.norm() - 1) <= 8 * detail::eps<T>())) return false;
  if (n.dot(c.normal.template cast<double>()) > 0.999) return false;
  const double reach = double(c.depth) + 2 * move + point_bound(in, double(c.depth));
  return oracle::separates(in.exact_a(), in.exact_b(), Vec2<double>(-n * reach));
}

/// Whether features i0 and i1 (both of kind k) of the placed core lie within bound of each other.
template <Scalar T>
bool merged(const Placed<T>& part, const std::vector<Vec2c>& core, FeatureKind k, unsigned i0, unsigned i1,
            double bound) {
  const std::size_t n = core.size();
  const auto at = [&](std::size_t i) { return part.apply(core[i % n]); };
  if (k == FeatureKind::Vertex) return (at(i0) - at(i1)).norm() <= bound;
  const std::array<Vec2c, 2> e0{at(i0), at(i0 + 1)}, e1{at(i1), at(i1 + 1)};
  return std::max({distance_to_segment(e0[0], e1), distance_to_segment(e0[1], e1), distance_to_segment(e1[0], e0),
                   distance_to_segment(e1[1], e0)}) <= bound;
}

/// Whether the ids of c and of moved differ only where one names a vertex of a child and the other
/// an edge of that child ending at the vertex, with c's surface point on that child within reach
/// of the vertex: the radius, twice the move, and 2 sqrt(size bound). Which of a vertex and an edge
/// ending at it is nearer turns on two squared distances that differ by (l |d|)^2 for a point
/// l |d| along the edge past the vertex, each rounded by about its length (at most size) times the
/// bound: within 2 sqrt(size bound) of the vertex the rounding chooses, and either is right.
/// Or where both name vertices, or both edges, of a child that lie within the point bound of each
/// other (edges: each end within it of the other edge; a sliver's two long sides), or of a child
/// no larger than that bound: rounding at the moved positions may merge them, and either names
/// what they became.
template <Scalar T>
bool tied_features(const PairIn<T>& in, const Contact<T>& c, const Contact<T>& moved, double move, double size) {
  const std::vector<Placed<T>> ka = placed_parts(in.a, in.xa), kb = placed_parts(in.b, in.xb);
  const double reach = 2 * move + 2 * std::sqrt(size * point_bound(in, 0));
  // Side 0 (a) or 1 (b) of c's point i: its feature (k0, i0) against moved's (k1, i1) on that child.
  const auto side_tied = [&](int i, int side, FeatureKind k0, unsigned i0, FeatureKind k1, unsigned i1,
                             std::uint16_t child) {
    if (k0 == k1 && i0 == i1) return true;
    const unsigned vertex = k0 == FeatureKind::Vertex ? i0 : i1, edge = k0 == FeatureKind::Edge ? i0 : i1;
    const Placed<T>* part = child_named(side == 0 ? ka : kb, child);
    if (part == nullptr) return false;
    double radius = 0;
    const std::vector<Vec2c> core = feature_core(part->shape, radius);
    const std::size_t n = core.size();
    if (k0 == k1) {
      // A child smaller than the bound is one point up to rounding, whatever features it has.
      const double extent = std::visit(
          [](const auto& x) {
            const auto box = bounds(x);
            return std::max(double(box.max().x()) - double(box.min().x()),
                            double(box.max().y()) - double(box.min().y()));
          },
          part->shape);
      if (extent <= point_bound(in, 0)) return true;
      // A capsule's two sides lie 2 radius apart however near its core's ends are.
      const bool sides_apart = k0 == FeatureKind::Edge && 2 * radius > point_bound(in, 0);
      return n >= 2 && i0 < n && i1 < n && !sides_apart && merged(*part, core, k0, i0, i1, point_bound(in, 0));
    }
    if (n < 2 || vertex >= n) return false;
    const bool incident = n == 2 ? edge <= 1 : edge < n && (edge == vertex || edge == (vertex + n - 1) % n);
    if (!incident) return false;
    const Vec2c x = surface_points(c, i)[std::size_t(side)];
    return (x - part->apply(core[vertex])).norm() <= radius + reach;
  };
  const auto point_tied = [&](int i, int k) {
    const FeatureId &p = c.ids[std::size_t(i)], &q = moved.ids[std::size_t(k)];
    if (p.child_a != q.child_a || p.child_b != q.child_b) return false;
    return side_tied(i, 0, p.kind_a, p.index_a, q.kind_a, q.index_a, p.child_a) &&
           side_tied(i, 1, p.kind_b, p.index_b, q.kind_b, q.index_b, p.child_b);
  };
  if (c.count != moved.count) return false;
  if (c.count == 1) return point_tied(0, 0);
  return (point_tied(0, 0) && point_tied(1, 1)) || (point_tied(0, 1) && point_tied(1, 0));
}

/// The pair with b moved by t in its own frame (its stored values; a placed b keeps its body
/// transform, so that b's exact image moves by the turned t); nullopt, with the reason, when the
/// move has no representation in T or does not add exactly to every stored position (only then
/// does the motion from b - t to b + t pass through b).
template <Scalar T>
std::optional<PairIn<T>> with_b_moved(const PairIn<T>& in, const Vec2<T>& t, std::string& why) {
  const auto m = std::visit(
      [&](const auto& s) -> std::optional<Shape<T>> {
        const auto r = translated(s, t);
        if (!r) return std::nullopt;
        return Shape<T>(r.value());
      },
      in.b);
  if (!m) return why = "move not representable", std::nullopt;
  if (!detail::exact_move(in.b, *m, t)) return why = "move rounds", std::nullopt;
  PairIn<T> out = in;
  out.b = *m;
  return out;
}

template <Scalar T>
Verdict separation_of(const PairIn<T>& in) {
  return judged_contact(in, [&](Judgement& j, const Contact<T>& k) {
    const Contact<T>* c = &k;
    j.v.account = "contact of " + std::to_string(c->count) + " points, separations " + num(c->separations[0]) +
                  (c->count > 1 ? ", " + num(c->separations[1]) : "");
    for (int i = 0; i < c->count; ++i) {
      if (!(c->separations[std::size_t(i)] <= point_bound(in, 0))) {
        j.broken("point " + std::to_string(i) + " penetrating or touching (separation <= " + num(point_bound(in, 0)) +
                     ") without a speculative distance",
                 "separation " + num(c->separations[std::size_t(i)]));
        return;
      }
      if (!check_point_separation(j, in, *c, i)) return;
    }
  });
}

template <Scalar T>
Verdict feature_ids_of(const PairIn<T>& in) {
  return judged_contact(in, [&](Judgement& j, const Contact<T>& k) {
    const Contact<T>* c = &k;
    std::string skipped;
    for (int i = 0; i < c->count; ++i) {
      if (!check_point_features(j, in, *c, i, skipped)) return;
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
    const double size = std::max(side(in.box_a()), side(in.box_b()));
    const double scale =
        size > 0 ? size : std::max(::collide::detail::scale_of(in.box_a()), ::collide::detail::scale_of(in.box_b()));
    if (!(scale > 0) || !std::isfinite(scale)) return;
    // At least T's spacing at b's largest stored coordinate, so that 3 and 4 times it add exactly
    // to b's stored positions (a sum crossing a power of two may still round: with_b_moved
    // checks); up to 2^-12 of the size, beyond which the move is not tiny next to the shapes: not used.
    const double reach = ::collide::detail::scale_of(bounds(in.b));
    const int want = std::ilogb(scale) - 20;
    const int spacing = reach > 0 ? std::ilogb(reach) - std::numeric_limits<T>::digits + 1 : want;
    if (spacing > want + 8) {
      j.v.account += "; move rounds";
      return;
    }
    const T quarter = static_cast<T>(std::ldexp(1.0, std::max(want, spacing)));
    if (!(quarter > 0) || !std::isfinite(double(quarter))) return;
    const Vec2<T> t(T(3) * quarter, T(4) * quarter);
    std::string why;
    const auto plus = with_b_moved(in, t, why);
    const auto minus = plus ? with_b_moved(in, Vec2<T>(-t), why) : std::nullopt;
    if (!plus || !minus) {
      j.v.account += "; " + why;
      return;
    }
    const auto cp = plus->contact(), cm = minus->contact();
    if (!cp || !cm || cp->count != c->count || cm->count != c->count || id_keys(*cp) != id_keys(*cm)) {
      j.v.account += "; features change within the move";
      return;
    }
    if (id_keys(*c) != id_keys(*cp)) {
      const double move = t.template cast<double>().norm();
      if (tied_child_pairs(in, *c, *cp, move)) {
        j.v.account += "; child pairs tied for the deepest (either may be reported)";
        return;
      }
      if (tied_faces(in, *c, *cp, move)) {
        j.v.account += "; faces tied for the least depth within the move (either may be reported)";
        return;
      }
      if (tied_features(in, *c, *cp, move, scale)) {
        j.v.account +=
            "; a vertex and an edge ending at it, or two features merged by rounding, tied (either may be reported)";
        return;
      }
      j.broken("the ids of b moved by +-" + vec(t) + " (" + ids_text(*cp) + ") for b itself", ids_text(*c));
    }
  });
}

template <Scalar T>
Verdict speculative_of(const PairIn<T>& in) {
  return judged(in, [&](Judgement& j) {
    // A speculative distance of about a tenth of the pair's size, a power of two (exact in T).
    const auto box = [](const Aabb<T>& x) {
      return std::max(double(x.max().x() - x.min().x()), double(x.max().y() - x.min().y()));
    };
    const double size = std::max(box(in.box_a()), box(in.box_b()));
    const T spec = static_cast<T>(std::ldexp(1.0, std::ilogb(std::max(size, 1e-30)) - 3));
    const bool over = in.overlapping();
    const auto c = in.contact(spec);
    const double bound = point_bound(in, double(spec));
    const oracle::Placed ea = in.exact_a(), eb = in.exact_b();
    j.v.account = "speculative " + num(spec) + ": " + (c ? "contact" : "none") + (over ? " (overlapping)" : "");
    if (over) {
      const auto plain = in.contact();
      if (!c || c->normal != plain->normal || c->depth != plain->depth || c->count < plain->count) {
        j.broken("for an overlapping pair, contact(a, b)'s normal and depth and at least its points",
                 c ? "normal " + vec(c->normal) + " depth " + num(c->depth) + " count " + std::to_string(c->count)
                   : std::string("no contact"));
        return;
      }
    } else if (!c) {
      if (oracle::compare_distance(ea, eb, double(spec) - bound) < 0) {
        j.broken("a speculative contact for a gap below " + num(double(spec) - bound),
                 "none; exact gap ~" + num(oracle::approx_signed_distance(ea, eb)));
      }
      return;
    } else {
      if (oracle::compare_distance(ea, eb, double(spec) + bound) > 0) {
        j.broken("no contact for a gap above " + num(double(spec) + bound),
                 "a contact; exact gap ~" + num(oracle::approx_signed_distance(ea, eb)));
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
      if (s0 - bound > 0 && !oracle::separates(ea, eb, Vec2<double>(n * (s0 - bound)))) {
        j.broken("a moved by normal * (separation - " + num(bound) + ") still apart from b",
                 "overlapping after " + vec(Vec2<double>(n * (s0 - bound))) + " (separation " + num(s0) + ")");
        return;
      }
      // The smallest separation is the gap.
      if (oracle::compare_distance(ea, eb, s0 - bound) < 0 || oracle::compare_distance(ea, eb, s0 + bound) > 0) {
        j.broken("the smallest separation within " + num(bound) + " of the exact gap",
                 "separation " + num(s0) + ", exact gap ~" + num(oracle::approx_signed_distance(ea, eb)));
        return;
      }
    }
    // Each point's surface points lie on the shapes (so the nearest realises the gap) and its
    // feature ids name features there: a solver warm-starts a speculative contact from them.
    std::string skipped;
    for (int i = 0; i < c->count; ++i) {
      if (!(c->separations[std::size_t(i)] <= double(spec) + bound)) {
        j.broken("every point apart by at most the speculative distance " + num(spec),
                 "separation " + num(c->separations[std::size_t(i)]));
        return;
      }
      if (!check_point_separation(j, in, *c, i)) return;
      if (!check_point_features(j, in, *c, i, skipped)) return;
    }
    if (c->count == 2 && c->ids[0] == c->ids[1]) {
      j.broken("two points with different ids", "both " + ids_text(*c));
      return;
    }
    j.v.account += "; ids " + ids_text(*c) + (skipped.empty() ? "" : "; not rebuilt:" + skipped);
  });
}

/// A face of a core: its ends (in the core's turning order) and its outward unit normal.
struct CoreFace {
  Vec2c from, to, normal;
};
/// The faces of a core as feature_core() gives it: a polygon's edges, a segment's two sides.
std::vector<CoreFace> faces_of(const std::vector<Vec2c>& core) {
  std::vector<CoreFace> out;
  const std::size_t n = core.size();
  const auto face = [](const Vec2c& from, const Vec2c& to) {
    const Vec2c e = to - from;
    return CoreFace{from, to, Vec2c(e.y(), -e.x()) / e.norm()};
  };
  if (n == 2) {
    out = {face(core[0], core[1]), face(core[1], core[0])};
  } else if (n > 2) {
    for (std::size_t i = 0; i < n; ++i) out.push_back(face(core[i], core[(i + 1) % n]));
  }
  return out;
}

/// Two faces resting on each other (see manifold_resting in laws.hpp).
template <Scalar T>
Verdict resting_of(const PairIn<T>& in) {
  return judged_contact(in, [&](Judgement& j, const Contact<T>& c) {
    if (std::holds_alternative<Compound<T>>(in.a) || std::holds_alternative<Compound<T>>(in.b)) {
      j.v.account = "a compound: not judged";
      return;
    }
    double ra = 0, rb = 0;
    const std::vector<CoreFace> fa = faces_of(feature_core(primitives_of(in.a).front(), ra));
    const std::vector<CoreFace> fb = faces_of(feature_core(primitives_of(in.b).front(), rb));
    const Vec2c normal = widen(c.normal);
    const double bound = point_bound(in, c.depth);
    j.v.account = "no faces resting on each other";
    for (std::size_t ip = 0; ip < fa.size(); ++ip) {
      const CoreFace& p = fa[ip];
      const Vec2c ep = p.to - p.from, u = ep / ep.norm();
      if (!((normal - p.normal).norm() <= 1e-6)) continue;  // the contact is not across this face
      for (const CoreFace& q : fb) {
        const Vec2c eq = q.to - q.from;
        const double cross = ep.x() * eq.y() - ep.y() * eq.x();
        if (!(ep.dot(eq) < 0 && std::fabs(cross) <= 1e-12 * ep.norm() * eq.norm())) continue;
        const double gap = (q.from - p.from).dot(p.normal), depth = ra + rb - gap;
        const double lo = std::max(p.from.dot(u), std::min(q.from.dot(u), q.to.dot(u)));
        const double hi = std::min(p.to.dot(u), std::max(q.from.dot(u), q.to.dot(u)));
        // A stretch shorter than the cores' distance across it leaves the normal to the closest points.
        if (!(depth >= 0) || std::fabs(depth - double(c.depth)) > bound || !(hi - lo > std::max(gap, 0.0) + 64 * bound))
          continue;
        j.v.account = "faces resting on each other along [" + num(lo) + ", " + num(hi) + "] at depth " + num(depth);
        if (c.count != 2) {
          j.broken("two points, one at each end of the faces' common stretch [" + num(lo) + ", " + num(hi) + "]",
                   std::to_string(c.count) + " point");
          return;
        }
        const double s0 = widen(c.points[0]).dot(u), s1 = widen(c.points[1]).dot(u);
        if (std::fabs(std::min(s0, s1) - lo) > 4 * bound || std::fabs(std::max(s0, s1) - hi) > 4 * bound) {
          j.broken("points at the ends of the faces' common stretch [" + num(lo) + ", " + num(hi) + "] within " +
                       num(4 * bound),
                   "points along the faces at " + num(s0) + " and " + num(s1));
          return;
        }
        // Faces parallel to the bit are equally deep up to rounding: the reference face is that
        // of the shape whose kind comes first in the registry, a's for two of one kind.
        const bool a_first = static_cast<int>(kind(in.a)) <= static_cast<int>(kind(in.b));
        const std::size_t ref = a_first ? ip : std::size_t(&q - fb.data());
        for (std::size_t k = 0; cross == 0 && k < 2; ++k) {
          const FeatureId& id = c.ids[k];
          const FeatureKind got = a_first ? id.kind_a : id.kind_b;
          const unsigned index = a_first ? id.index_a : id.index_b;
          const std::string owner = a_first ? "a's" : "b's";
          if (got != FeatureKind::Edge || index != ref) {
            j.broken("each point naming " + owner + " face " + std::to_string(ref) +
                         " (of two faces parallel to the bit, the reference face is that of the kind first in "
                         "the registry)",
                     "point " + std::to_string(k) + " names " + owner + " " +
                         (got == FeatureKind::Edge ? "edge " : "vertex ") + std::to_string(index));
            return;
          }
        }
      }
    }
  });
}

}  // namespace

template <Scalar T>
Verdict manifold_resting(const Shape<T>& a, const Shape<T>& b) {
  // Both orders: the suite draws pairs in registry order, and the reference face of tied faces
  // is chosen by that order.
  Verdict v = resting_of(PairIn<T>{a, b, {}, {}});
  if (!v.ok) return v;
  Verdict w = resting_of(PairIn<T>{b, a, {}, {}});
  if (!w.ok) {
    w.account = "in the order (b, a): " + w.account;
    return w;
  }
  return v;
}
template <Scalar T>
Verdict manifold_separation(const Shape<T>& a, const Shape<T>& b) {
  return separation_of(PairIn<T>{a, b, {}, {}});
}
template <Scalar T>
Verdict manifold_ids(const Shape<T>& a, const Shape<T>& b) {
  return feature_ids_of(PairIn<T>{a, b, {}, {}});
}
template <Scalar T>
Verdict manifold_speculative(const Shape<T>& a, const Shape<T>& b) {
  return speculative_of(PairIn<T>{a, b, {}, {}});
}
template <Scalar T>
Verdict placed_separation(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb) {
  return separation_of(PairIn<T>{a, b, xa, xb});
}
template <Scalar T>
Verdict placed_feature_ids(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb) {
  return feature_ids_of(PairIn<T>{a, b, xa, xb});
}
template <Scalar T>
Verdict placed_speculative(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb) {
  return speculative_of(PairIn<T>{a, b, xa, xb});
}

#define COLLIDE_MANIFOLD_LAWS_INSTANTIATE(T)                                                                          \
  template Verdict manifold_resting<T>(const Shape<T>&, const Shape<T>&);                                             \
  template Verdict manifold_separation<T>(const Shape<T>&, const Shape<T>&);                                          \
  template Verdict manifold_ids<T>(const Shape<T>&, const Shape<T>&);                                                 \
  template Verdict manifold_speculative<T>(const Shape<T>&, const Shape<T>&);                                         \
  template Verdict placed_separation<T>(const Shape<T>&, const Transform<T>&, const Shape<T>&, const Transform<T>&);  \
  template Verdict placed_feature_ids<T>(const Shape<T>&, const Transform<T>&, const Shape<T>&, const Transform<T>&); \
  template Verdict placed_speculative<T>(const Shape<T>&, const Transform<T>&, const Shape<T>&, const Transform<T>&);

COLLIDE_MANIFOLD_LAWS_INSTANTIATE(float)
COLLIDE_MANIFOLD_LAWS_INSTANTIATE(double)

}  // namespace collide::laws
