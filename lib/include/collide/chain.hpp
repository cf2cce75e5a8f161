#pragma once
/// @file chain.hpp
/// Chains: runs of one-sided segments for level geometry, each knowing its neighbours, so that a
/// shape sliding across a joint gets the chain's normal and never the joint's sideways one (no
/// ghost collisions). Error contract: tolerances.hpp, as contact().
///
/// Semantics, exactly:
/// - A chain is a list of points, open or a loop. A loop of n >= 3 points has n segments, p[i] to
///   p[i + 1] (wrapping). An open chain of n >= 4 points has n - 3 segments, p[1] to p[2] up to
///   p[n - 3] to p[n - 2]: its first and last points are ghosts, which only shape the joints at
///   the ends (end a chain with a point continuing its line for a flat end).
/// - Each segment is one-sided: its front is the right-hand side going from a to b, as for the
///   edges of a counter-clockwise polygon (a loop listed counter-clockwise bounds a solid inside
///   and is hit from outside; a floor runs right to left). Its front normal n is that side's
///   outward unit normal. A shape whose reference point (a circle's or box's centre, a capsule's
///   midpoint, a polygon's vertex mean) lies strictly behind the segment's line gets no contact
///   from it.
/// - A joint is convex when the chain turns left there (orient() > 0, as at a polygon's corner),
///   flat when it goes straight on, concave when it turns right. A segment's admissible normals
///   are n, and at a convex joint the arc from n to the next segment's normal: that corner region
///   belongs to the segment ending there (and, at the start of an open chain, the arc from the
///   ghost segment's normal to n belongs to the first segment). A contact's normal, from the
///   segment toward the shape, is always admissible: a shape touching a joint from another
///   direction is answered along n or not at all.
/// - contact(segment, shape) is the segment taken as two-sided (a capsule of radius 0, as
///   contact() answers it) where that contact's normal lies strictly inside the segment's own
///   corner arc; otherwise it is the face contact along n, from the points of the shape's boundary
///   within the strip of points whose projection falls on the segment: a box's or polygon's side
///   facing the segment clipped to the strip (each clipped point keeps its vertex's id), or its
///   lowest point in the strip when that side lies outside it; a circle's lowest point when its
///   centre lies in the strip; a capsule's core clipped to the strip, each end lowered to the
///   capsule's lowest point there. These are contact()'s clipping steps with the segment as the
///   reference face. It is present when the two-sided contact is present and a face point lies
///   within `speculative` of the front (up to the rounding of its separation, as contact() keeps
///   clipped points).
/// - Error: as contact(): the normal, depth, points and separations are rounded results within a
///   few rounding_tolerance(segment.as_capsule(), shape) of the exact values.
/// - Feature ids: the segment is numbered as a capsule (vertex 0 = a, vertex 1 = b, edge 0 = the
///   front); a face point names edge 0 of the segment and the shape's vertex it comes from.
/// - A compound meets a segment child by child, each by these rules (its own reference point), the
///   deepest contact winning as contact() picks it; a shape placed by a transform meets it as its
///   image, as every placed query does (transformed.hpp).
///
/// Everything else (overlaps, distance, raycast, casts) treats a segment as the closed two-sided
/// segment it is: `segment.as_capsule()`. In a World (broadphase/world.hpp) a segment is a body
/// that stays where it was added; two segments never touch.

#include "collide/bounds.hpp"
#include "collide/contact.hpp"
#include "collide/transform.hpp"
#include "collide/transformed.hpp"
#include "collide/detail/placement.hpp"
#include "collide/error.hpp"
#include "collide/predicates.hpp"
#include "collide/shape_traits.hpp"
#include "collide/shapes.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace collide {

template <Scalar T>
class Chain;

/// One segment of a chain, from a() to b(), between the ghost points before() and after() that
/// shape its joints. Copied out of a chain by Chain::segment(), or made on its own.
template <Scalar T>
class ChainSegment {
 public:
  /// Errors: NonFinite, OutOfRange (index 0..7 = before.x, before.y, a.x, a.y, b.x, b.y, after.x,
  /// after.y), ZeroLengthSegment (index 0..2: before-a, a-b, b-after), FoldedChain (index 0 at a,
  /// 1 at b: the chain turns straight back).
  static Expected<ChainSegment> make(const Vec2<T>& before, const Vec2<T>& a, const Vec2<T>& b,
                                     const Vec2<T>& after) noexcept {
    ShapeError e = detail::placeholder_error();
    if (!detail::check_values<T>({before.x(), before.y(), a.x(), a.y(), b.x(), b.y(), after.x(), after.y()}, &e))
      return e;
    const std::array<Vec2<T>, 4> p = {before, a, b, after};
    for (long i = 0; i < 3; ++i) {
      if (p[std::size_t(i)] == p[std::size_t(i) + 1])
        return ShapeError(Error::ZeroLengthSegment, i, "consecutive chain points coincide");
    }
    for (long i = 0; i < 2; ++i) {
      if (folds(p[std::size_t(i)], p[std::size_t(i) + 1], p[std::size_t(i) + 2]))
        return ShapeError(Error::FoldedChain, i, "chain turns straight back");
    }
    return ChainSegment(before, a, b, after, false);
  }
  /// Throws ShapeError where make() returns it.
  ChainSegment(const Vec2<T>& before, const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& after)
      : ChainSegment(make(before, a, b, after).value()) {}

  const Vec2<T>& before() const noexcept { return before_; }  ///< ghost point before a
  const Vec2<T>& a() const noexcept { return a_; }            ///< start
  const Vec2<T>& b() const noexcept { return b_; }            ///< end
  const Vec2<T>& after() const noexcept { return after_; }    ///< ghost point after b
  /// Whether the corner arc at a belongs to this segment (the first segment of an open chain).
  bool owns_start_corner() const noexcept { return owns_start_; }
  /// The segment as a two-sided shape: the capsule of radius 0 from a to b.
  Capsule<T> as_capsule() const noexcept { return detail::ShapeAccess::capsule(a_, b_, T(0)); }

 private:
  friend class Chain<T>;
  ChainSegment(const Vec2<T>& before, const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& after, bool owns_start)
      : before_(before), a_(a), b_(b), after_(after), owns_start_(owns_start) {}
  /// p -> q -> r goes straight back: collinear, and r lies back toward p.
  static bool folds(const Vec2<T>& p, const Vec2<T>& q, const Vec2<T>& r) noexcept {
    const Vec2c d = widen(q) - widen(p), e = widen(r) - widen(q);
    return orient(widen(p), widen(q), widen(r)) == 0 && d.dot(e) < 0;  // collinear: both terms share the sign
  }
  Vec2<T> before_, a_, b_, after_;
  bool owns_start_ = false;
};

/// A chain of one-sided segments (see the file's comment), open or a loop.
template <Scalar T>
class Chain {
 public:
  /// Errors: NonFinite, OutOfRange (index = 2 * point + coordinate), TooFewVertices (fewer than 4
  /// points open, 3 as a loop), ZeroLengthSegment (index = the first of two coinciding consecutive
  /// points), FoldedChain (index = the point where the chain turns straight back).
  static Expected<Chain> make(std::span<const Vec2<T>> points, bool loop) {
    const std::size_t n = points.size();
    ShapeError e = detail::placeholder_error();
    for (std::size_t i = 0; i < n; ++i) {
      if (!detail::check_value(points[i].x(), long(2 * i), &e) ||
          !detail::check_value(points[i].y(), long(2 * i + 1), &e))
        return e;
    }
    if (n < (loop ? 3u : 4u))
      return ShapeError(Error::TooFewVertices, -1,
                        loop ? "a chain loop needs 3 points" : "an open chain needs 4 points");
    const std::size_t joints = loop ? n : n - 1;
    for (std::size_t i = 0; i < joints; ++i) {
      if (points[i] == points[(i + 1) % n])
        return ShapeError(Error::ZeroLengthSegment, long(i), "consecutive chain points coincide");
    }
    for (std::size_t i = loop ? 0 : 1; i < (loop ? n : n - 1); ++i) {
      if (ChainSegment<T>::folds(points[(i + n - 1) % n], points[i], points[(i + 1) % n]))
        return ShapeError(Error::FoldedChain, long(i), "chain turns straight back");
    }
    return Chain(std::vector<Vec2<T>>(points.begin(), points.end()), loop);
  }
  /// Throws ShapeError where make() returns it.
  Chain(std::initializer_list<Vec2<T>> points, bool loop)
      : Chain(make(std::span<const Vec2<T>>(points.begin(), points.size()), loop).value()) {}

  /// The points as given (an open chain's first and last are ghosts).
  std::span<const Vec2<T>> points() const noexcept { return points_; }
  /// Whether the chain closes on itself (its last point joins its first).
  bool loop() const noexcept { return loop_; }
  /// Number of segments: points().size() for a loop, points().size() - 3 open.
  std::size_t size() const noexcept { return loop_ ? points_.size() : points_.size() - 3; }
  /// Segment i (0 <= i < size()), with its neighbours as ghosts.
  ChainSegment<T> segment(std::size_t i) const noexcept {
    const std::size_t n = points_.size(), s = loop_ ? i : i + 1;
    return ChainSegment<T>(points_[(s + n - 1) % n], points_[s], points_[(s + 1) % n], points_[(s + 2) % n],
                           !loop_ && i == 0);
  }

 private:
  Chain(std::vector<Vec2<T>> points, bool loop) : points_(std::move(points)), loop_(loop) {}
  std::vector<Vec2<T>> points_;
  bool loop_;
};

namespace detail {

/// A segment's frame in Calc: its start, unit direction u, front normal n (u turned clockwise)
/// and length.
struct SegmentFrame {
  Vec2c a, u, n;
  Calc length;
  /// Whether p projects onto the segment: it lies in the segment's strip.
  bool in_strip(const Vec2c& p) const noexcept {
    const Calc t = u.dot(p - a);
    return t >= 0 && t <= length;
  }
};
inline SegmentFrame segment_frame(const Vec2c& a, const Vec2c& b) noexcept {
  const Vec2c d = b - a;
  const Vec2c u = unit_of(d);  // scaled: a segment 1e-300 long still has a direction
  return {a, u, Vec2c(u.y(), -u.x()), norm_of(d)};
}

/// Whether normal m lies strictly inside a corner arc the segment owns: at b when the chain turns
/// left there (from n to the next segment's normal), at a when it owns that corner and turns left
/// there (from the ghost segment's normal to n).
template <Scalar T>
bool in_own_corner(const ChainSegment<T>& s, const SegmentFrame& f, const Vec2c& m) noexcept {
  const Vec2c a = widen(s.a()), b = widen(s.b());
  if (orient(a, b, widen(s.after())) > 0) {
    const Vec2c next = segment_frame(b, widen(s.after())).n;
    if (cross(f.n, m) > 0 && cross(m, next) >= 0) return true;
  }
  if (s.owns_start_corner() && orient(widen(s.before()), a, b) > 0) {
    const Vec2c prev = segment_frame(widen(s.before()), a).n;
    if (cross(prev, m) >= 0 && cross(m, f.n) > 0) return true;
  }
  return false;
}

/// The reference point of the one-sided test: a circle's or box's centre, a capsule's midpoint,
/// a polygon's vertex mean (each computed in Calc).
template <class B>
Vec2c reference_point(const B& s) noexcept {
  using T = scalar_of_t<B>;
  if constexpr (std::is_same_v<B, Circle<T>> || std::is_same_v<B, Obb<T>>) {
    return widen(s.center());
  } else if constexpr (std::is_same_v<B, Aabb<T>>) {
    return (widen(s.min()) + widen(s.max())) / 2;
  } else if constexpr (std::is_same_v<B, Capsule<T>>) {
    return (widen(s.a()) + widen(s.b())) / 2;
  } else {
    Vec2c sum = Vec2c::Zero();
    for (const Vec2<T>& v : s.vertices()) sum += widen(v) / Calc(s.size());  // each term, so no overflow
    return sum;
  }
}

/// The lowest point of core c (its vertices and its sides' crossings of the strip's two edges)
/// within the segment's strip, as a one-point incident face naming the vertex it lies at or after;
/// count 0 when no part of the core lies in the strip.
inline IncidentFace lowest_in_strip(const SegmentFrame& f, const Core& c) {
  IncidentFace out;
  Calc best = 0;
  const auto consider = [&](const Vec2c& p, std::size_t id) {
    const Calc h = f.n.dot(p - f.a);
    if (out.count == 1 && !(h < best)) return;
    best = h;
    out = {{p, Vec2c::Zero()}, {unsigned(id), 0}, 1};
  };
  const std::size_t n = c.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2c &p = c[i], &q = c[next_index(i, n)];
    if (f.in_strip(p)) consider(p, i);
    if (n == 1) break;
    const Calc tp = f.u.dot(p - f.a), tq = f.u.dot(q - f.a);
    for (const Calc edge : {Calc(0), f.length}) {
      if ((tp < edge) != (tq < edge))
        consider(p + (q - p) * ((edge - tp) / (tq - tp)), f.in_strip(p) ? i : next_index(i, n));
    }
  }
  return out;
}

/// Step 3 checked for a normal that is not the pair's own axis but the segment's: a sliver's faces
/// can all lie nearly across it, and the face rounding finds most anti-parallel may end above the
/// core's lowest vertex. Heights along a convex core's boundary fall to the lowest vertex and rise
/// again, so walk downhill from the face's lower end; when that leaves the face, take the more
/// anti-parallel of the two faces at the vertex reached.
inline void reach_lowest_vertex(IncidentFace& incident, const SegmentFrame& f, const Core& c) {
  const std::size_t n = c.size();
  if (incident.count != 2 || n < 3) return;
  const auto height = [&](std::size_t i) { return f.n.dot(c[i] - f.a); };
  const auto prev = [&](std::size_t i) { return i == 0 ? n - 1 : i - 1; };
  const std::size_t j = incident.vertices[0], j1 = incident.vertices[1];
  const bool back = height(j) <= height(j1);
  std::size_t k = back ? j : j1;
  for (std::size_t step = 0; step < n; ++step) {
    const std::size_t next = back ? prev(k) : next_index(k, n);
    if (!(height(next) < height(k))) break;
    k = next;
  }
  if (k == j || k == j1) return;
  const std::size_t before = prev(k);
  const auto alignment = [&](std::size_t from) { return face_alignment(c[next_index(from, n)] - c[from], f.n); };
  incident = incident_edge(c, alignment(before) < alignment(k) ? before : k);
}

/// The face contact along the front normal of the segment core `segment` (two points, a to b;
/// see the file's comment), at the cores' own scale: the segment as the reference face of the
/// contact engine's steps 3 to 5 (detail/contact_cores.hpp), the shape's core as the incident
/// core, so that ties between its faces, ends exactly at reach and tilted capsules are handled as
/// contact() handles them.
///
///   incident = the core's face most anti-parallel to n (its point, for a point core), moved to
///              the core's lowest vertex when rounding chose a face beside it
///   clip it to the strip (a point: keep it when it lies in the strip)
///   if nothing is left: the core's lowest point in the strip (a polygon's side beyond the strip)
///   keep the points within reach, midway between the surfaces
///   empty when no point is kept
inline std::optional<CoreContact> face_contact_at_scale(const Core& segment, const Core& shape, Calc speculative,
                                                        const Vec2c* normals) {
  const SegmentFrame f = segment_frame(segment[0], segment[1]);
  const ReferenceFace face{&segment, &shape, segment[0], segment[1], f.n, 0, 0};
  IncidentFace incident = find_incident_face(face, normals);
  reach_lowest_vertex(incident, f, shape);
  const bool met = incident.count == 1 ? f.in_strip(incident.ends[0]) : clip_to_reference_face(incident, face);
  if (!met) incident = lowest_in_strip(f, shape);
  CoreContact c;
  c.normal = f.n;
  keep_points_within_reach(incident, face, c, speculative);
  if (c.count == 0) return std::nullopt;
  const Calc least = c.count == 1 ? c.separations[0] : std::min(c.separations[0], c.separations[1]);
  c.depth = least < 0 ? -least : Calc(0);
  c.overlapping = least <= 0;
  return c;
}

/// face_contact_at_scale() of the segment from a to b, after exact rescaling of tiny cores (as
/// contact_cores() rescales them: products of subnormal coordinates would lose their bits).
/// normals: the shape's unit face normals when cached (a polygon's), else nullptr.
inline std::optional<CoreContact> face_contact(const Vec2c& a, const Vec2c& b, const Core& shape, Calc speculative,
                                               const Vec2c* normals = nullptr) {
  Core segment;
  segment.push(a);
  segment.push(b);
  const int k = tiny_scale(segment, shape);
  if (k == 0) return face_contact_at_scale(segment, shape, speculative, normals);
  std::optional<CoreContact> c =
      face_contact_at_scale(scaled(segment, k), scaled(shape, k), std::ldexp(speculative, k), normals);
  if (c) *c = unscaled(*c, k);
  return c;
}

/// face_contact() of a circle (a point core c of radius r) without building cores, the answer
/// the contact engine's steps give it: its lowest point when c lies in the strip, kept within
/// reach (and the rounding of its separation beyond) as keep_points_within_reach() keeps it.
inline std::optional<CoreContact> circle_face_contact(const SegmentFrame& f, const Vec2c& b, const Vec2c& c, Calc r,
                                                      Calc speculative) {
  if (!f.in_strip(c)) return std::nullopt;
  const Calc s = f.n.dot(c - f.a), reach = r + speculative;
  if (s > reach) {
    const Calc scale = std::max({f.a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff(), c.cwiseAbs().maxCoeff(), reach});
    if (s > reach + kOverlapErrorFactor * kUnitRoundoff * scale) return std::nullopt;
  }
  CoreContact out;
  out.normal = f.n;
  out.count = 1;
  out.points[0] = c + f.n * ((-s - r) * 0.5);
  out.separations[0] = s - r;
  out.ids[0] = FeatureId{0, 0, 0, 0, FeatureKind::Edge, FeatureKind::Vertex};
  out.depth = s < r ? r - s : Calc(0);
  out.overlapping = s <= r;
  return out;
}

/// The contact of segment s and a concrete primitive b (stored, or an image in double), by the
/// rules of the file's comment.
template <Scalar T, class B>
std::optional<CoreContact> chain_contact_primitive(const ChainSegment<T>& s, const B& b, Calc speculative) {
  const Vec2c a = widen(s.a()), e = widen(s.b());
  if (orient(a, e, reference_point(b)) > 0) return std::nullopt;  // behind the front
  std::optional<CoreContact> two_sided = contact_primitives(s.as_capsule(), b, speculative);
  if (!two_sided) return two_sided;
  const SegmentFrame f = segment_frame(a, e);
  if (in_own_corner(s, f, two_sided->normal)) return two_sided;
  if constexpr (std::is_same_v<B, Circle<scalar_of_t<B>>>) {
    return circle_face_contact(f, e, widen(b.center()), Calc(b.radius()), speculative);
  } else if constexpr (std::is_same_v<B, ConvexPolygon<scalar_of_t<B>>>) {
    return face_contact(a, e, core_of(b), speculative, PolygonAccess::normals(b));  // not computed again
  } else {
    return face_contact(a, e, core_of(b), speculative);
  }
}

/// chain_contact_primitive() of a concrete shape: a primitive, or each child of a compound (stored
/// or placed) on its own, the deepest contact winning as contact() picks it.
template <Scalar T, class B>
std::optional<CoreContact> chain_contact_concrete(const ChainSegment<T>& s, const B& b, Calc speculative) {
  if constexpr (is_compound_v<B>) {
    std::optional<CoreContact> best;
    std::uint16_t ib = 0;
    for_each_primitive(b, [&](const auto& child) {
      std::optional<CoreContact> c = chain_contact_primitive(s, child, speculative);
      if (c && (!best || deeper_contact(*c, *best))) {
        for (FeatureId& id : c->ids) id.child_b = ib;
        best = c;
      }
      ++ib;
    });
    if (best) name_child_features(b, *best, true);
    return best;
  } else {
    return chain_contact_primitive(s, b, speculative);
  }
}

/// The contact of segment s and any shape b placed by xb, rounded to T; from b toward the segment
/// (normal reversed, ids swapped) when `from_b`.
template <Scalar T, AnyShape B>
std::optional<Contact<T>> chain_contact_as(const ChainSegment<T>& s, const B& b, const Transform<T>& xb, T speculative,
                                           bool from_b = false) {
  const Calc spec = speculative_distance(speculative);
  std::optional<CoreContact> c = visit_shape(b, [&](const auto& cb) -> std::optional<CoreContact> {
    if (xb.is_identity()) return chain_contact_concrete(s, cb, spec);
    return with_placed(cb, xb, [&](const auto& pb) {
      std::optional<CoreContact> found = chain_contact_concrete(s, pb, spec);
      if (found) name_placed_features(cb, pb, xb, *found, true);
      return found;
    });
  });
  std::optional<Contact<T>> out;
  if (c) round_into(from_b ? reversed(*c) : *c, out);
  return out;
}

}  // namespace detail

/// The contact of a chain segment (as a) and a world-space shape b of any kind, by the rules of
/// the file's comment (a compound: each child on its own, the deepest contact); speculative as
/// contact() takes it. The normal points from the segment toward b.
template <Scalar T, AnyShape B>
requires std::is_same_v<scalar_of_t<B>, T> std::optional<Contact<T>> contact(const ChainSegment<T>& s, const B& b,
                                                                             T speculative = T(0)) {
  return detail::chain_contact_as(s, b, Transform<T>(), speculative);
}

/// contact() of a chain segment (in world space) and a shape b placed by the transform xb.
template <Scalar T, AnyShape B>
requires std::is_same_v<scalar_of_t<B>, T> std::optional<Contact<T>> contact(const ChainSegment<T>& s, const B& b,
                                                                             const Transform<T>& xb,
                                                                             T speculative = T(0)) {
  return detail::chain_contact_as(s, b, xb, speculative);
}

/// Calls f(i, contact) for every segment i of the chain that has a contact with the world-space
/// shape b, in segment order; speculative as contact() takes it. Segments whose boxes, grown by
/// speculative, miss b's are skipped without a contact computed. Allocates nothing.
template <Scalar T, AnyShape B, class F>
requires std::is_same_v<scalar_of_t<B>, T>
void for_each_contact(const Chain<T>& chain, const B& b, T speculative, F&& f) {
  const Aabb<T> box = bounds(b);  // holds b, rounded outward
  const Calc reach = detail::speculative_distance(speculative);
  const Vec2c lo = widen(box.min()), hi = widen(box.max());
  const std::span<const Vec2<T>> p = chain.points();
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const std::size_t n = p.size(), s = chain.loop() ? i : i + 1;
    const Vec2c q0 = widen(p[s]), q1 = widen(p[(s + 1) % n]);
    if (std::min(q0.x(), q1.x()) - reach > hi.x() || std::max(q0.x(), q1.x()) + reach < lo.x() ||
        std::min(q0.y(), q1.y()) - reach > hi.y() || std::max(q0.y(), q1.y()) + reach < lo.y())
      continue;
    if (std::optional<Contact<T>> c = contact(chain.segment(i), b, speculative)) f(i, *c);
  }
}

}  // namespace collide
