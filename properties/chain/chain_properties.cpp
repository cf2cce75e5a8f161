/// The laws of chain contacts (collide/chain.hpp), for both scalars: one GoogleTest test per law
/// and scalar (suite ChainLaws), checked by RapidCheck on random chains (open and loops, flat runs
/// with bumps and free zigzags) against every primitive kind, in world space or placed by a
/// transform, with and without a speculative distance. Each law is a plain function of one segment's answer, returning
/// what failed:
/// 1. admissible: the normal is the segment's front normal n, or lies inside the corner arc the
///    segment owns (exact orient() for the turn), up to T's rounding of a unit vector;
/// 2. one_sided: a shape whose reference point lies behind the front gets no contact;
/// 3. surfaces: each point lies midway between the surfaces: point - normal * separation / 2 on
///    the segment and point + normal * separation / 2 on the shape's boundary (the exact oracle,
///    within the rounding tolerance), the depth is the least separation's penetration, and no
///    separation exceeds the speculative distance;
/// 4. present_when_near: a contact is present only when the oracle puts the shape within the
///    speculative distance (plus the tolerance) of the segment;
/// 5. face_complete: a shape that overlaps the segment (exact), whose reference point lies in
///    front, and whose core has a vertex inside the segment's strip, below the front by more than
///    the tolerance (for a rounded core: its support point against the normal), gets a contact,
///    and a face contact's least separation is no higher than that point;
/// 6. face_ids: a contact is the segment's two-sided contact bit for bit (judged by the pair
///    laws), or each of its points names the segment's edge 0 and a vertex of the shape's core whose
///    sides (or the vertex itself) lie the core's radius from the point's end on the shape.
/// Depth: RC_PARAMS (ctest: 2,000 cases per law and scalar, seed 1).

#include "collide/chain.hpp"
#include "collide/oracle/oracle.hpp"
#include "generators.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace collide::props {
namespace {

/// What the laws judged, printed at the end, so that a run shows they were not vacuous.
struct Stats {
  long segments = 0, face = 0, corner = 0, behind = 0, completeness = 0;
};
Stats g_stats;

/// One case: a chain, a shape placed by a transform (the identity half the time) and a
/// speculative distance.
template <Scalar T>
struct Case {
  Chain<T> chain;
  Primitive<T> shape;
  Transform<T> x;
  T speculative;
};

template <Scalar T>
Case<T> gen_case() {
  using V = Vec2<T>;
  const double s = *rc::gen::element(1.0, 1.0 / 64, 1024.0);
  const bool loop = *rc::gen::arbitrary<bool>();
  const int n = *rc::gen::inRange(loop ? 3 : 4, 9);
  const bool floor = *rc::gen::inRange(0, 3) != 0;
  std::vector<V> pts;
  for (int i = 0; i < n; ++i) {
    if (floor) {
      // A floor running right to left, mostly flat, with bumps up and down.
      const int bump = *rc::gen::inRange(0, 4) == 0 ? *rc::gen::inRange(-3, 4) : 0;
      pts.push_back(V(T((16 - 4 * i) * s), T(bump * s)));
    } else {
      pts.push_back(V(T(grid(-16, 16) * s), T(grid(-16, 16) * s)));
    }
  }
  Expected<Chain<T>> chain = Chain<T>::make(pts, loop);
  RC_PRE(chain.has_value());
  const T speculative = *rc::gen::inRange(0, 3) == 0 ? T(grid(1, 4) * s) : T(0);
  const Transform<T> x = *rc::gen::arbitrary<bool>() ? Transform<T>() : gen_transform<T>(s);
  return {std::move(chain).value(), gen_any_primitive<T>(s), x, speculative};
}

/// Calls f with the shape as the chain's contact meets it: stored for the identity, else its image
/// in double (as every placed query meets a shape).
template <Scalar T, class F>
decltype(auto) with_met_shape(const Case<T>& k, F&& f) {
  return std::visit(
      [&](const auto& s) -> decltype(auto) {
        if (k.x.is_identity()) return f(s);
        return ::collide::detail::with_placed(s, k.x, f);
      },
      k.shape);
}

/// The shape placed, as the exact oracle takes it.
template <Scalar T>
oracle::Placed exact_shape(const Case<T>& k) {
  return oracle::placed(std::visit([](const auto& s) { return Shape<T>(s); }, k.shape), k.x);
}

/// The frame of the segment from p to q in double: p, unit direction, front normal, length.
struct Frame {
  Vec2c a, u, n;
  double length;
};
Frame frame_between(const Vec2c& p, const Vec2c& q) {
  const Vec2c d = q - p;
  const double len = d.norm();
  return {p, d / len, Vec2c(d.y() / len, -d.x() / len), len};
}
template <Scalar T>
Frame frame_of(const ChainSegment<T>& seg) {
  return frame_between(widen(seg.a()), widen(seg.b()));
}

/// The laws' tolerance for lengths: 64 eps_T of the case's scale.
template <Scalar T>
double length_tolerance(const Case<T>& c) {
  double scale = 0;
  for (const Vec2<T>& p : c.chain.points()) scale = std::max(scale, widen(p).cwiseAbs().maxCoeff());
  const Aabb<T> box = std::visit([&](const auto& s) { return bounds(s, c.x); }, c.shape);
  scale = std::max({scale, widen(box.min()).cwiseAbs().maxCoeff(), widen(box.max()).cwiseAbs().maxCoeff()});
  return 64 * double(std::numeric_limits<T>::epsilon()) * scale;
}
/// The tolerance of a unit normal's direction.
template <Scalar T>
double normal_tolerance() {
  return 64 * double(std::numeric_limits<T>::epsilon());
}

double cross(const Vec2c& p, const Vec2c& q) {
  return p.x() * q.y() - p.y() * q.x();
}

/// The core (feature numbering) and radius of the shape as the chain's contact meets it.
template <Scalar T>
::collide::detail::Core met_core(const Case<T>& k) {
  return with_met_shape(k, [](const auto& s) { return ::collide::detail::core_of(s); });
}

/// Whether normal m is the face normal (up to rounding).
bool is_face_normal(const Frame& f, const Vec2c& m, double tol) {
  return (m - f.n).norm() <= tol;
}

// --- the laws --------------------------------------------------------------------------------------

template <Scalar T>
std::optional<std::string> admissible(const Case<T>&, const ChainSegment<T>& seg, const Contact<T>& c) {
  const Frame f = frame_of(seg);
  const Vec2c m = widen(c.normal);
  const double tol = normal_tolerance<T>();
  if (is_face_normal(f, m, tol)) return std::nullopt;
  const auto in_arc = [&](const Vec2c& from, const Vec2c& to) {
    return cross(from, m) >= -tol && cross(m, to) >= -tol;  // the arc is less than a half turn
  };
  const Vec2c before = widen(seg.before()), a = widen(seg.a()), b = widen(seg.b()), after = widen(seg.after());
  if (orient(a, b, after) > 0 && in_arc(f.n, frame_between(b, after).n)) return std::nullopt;
  if (seg.owns_start_corner() && orient(before, a, b) > 0 && in_arc(frame_between(before, a).n, f.n))
    return std::nullopt;
  std::ostringstream o;
  o << "normal (" << m.x() << ", " << m.y() << ") is neither the front normal (" << f.n.x() << ", " << f.n.y()
    << ") nor inside an owned corner arc";
  return o.str();
}

template <Scalar T>
std::optional<std::string> surfaces(const Case<T>& k, const ChainSegment<T>& seg, const Contact<T>& c) {
  const double tol = length_tolerance(k);
  const Vec2c m = widen(c.normal);
  if (c.count < 1 || c.count > 2) return "count " + std::to_string(c.count);
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < std::size_t(c.count); ++i) {
    const double sep = double(c.separations[i]);
    least = std::min(least, sep);
    const Vec2c on_segment = widen(c.points[i]) - m * (sep / 2), on_shape = widen(c.points[i]) + m * (sep / 2);
    if (oracle::compare_boundary_distance(seg.as_capsule(), on_segment, tol) > 0)
      return "point " + std::to_string(i) + ": its segment end lies off the segment";
    if (oracle::compare_boundary_distance(exact_shape(k), on_shape, tol) > 0)
      return "point " + std::to_string(i) + ": its shape end lies off the shape's boundary";
    if (sep > double(k.speculative) + tol) return "point " + std::to_string(i) + ": beyond the speculative distance";
  }
  const double depth = least < 0 ? -least : 0;
  if (std::fabs(double(c.depth) - depth) > tol) return "depth is not the least separation's penetration";
  return std::nullopt;
}

template <Scalar T>
std::optional<std::string> present_when_near(const Case<T>& k, const ChainSegment<T>& seg, const Contact<T>&) {
  if (oracle::compare_distance(seg.as_capsule(), exact_shape(k), double(k.speculative) + length_tolerance(k)) > 0)
    return "a contact of a shape farther than the speculative distance";
  return std::nullopt;
}

/// Whether c is, bit for bit, the segment's two-sided contact (which the pair laws judge).
template <Scalar T>
bool is_two_sided(const Case<T>& k, const ChainSegment<T>& seg, const Contact<T>& c) {
  const std::optional<::collide::detail::CoreContact> core = with_met_shape(k, [&](const auto& s) {
    return ::collide::detail::contact_primitives(seg.as_capsule(), s,
                                                 ::collide::detail::speculative_distance(k.speculative));
  });
  std::optional<Contact<T>> two;
  if (core) ::collide::detail::round_into(*core, two);
  if (!two || two->count != c.count || two->normal != c.normal || two->depth != c.depth) return false;
  for (std::size_t i = 0; i < std::size_t(c.count); ++i) {
    if (two->points[i] != c.points[i] || two->separations[i] != c.separations[i] || !(two->ids[i] == c.ids[i]))
      return false;
  }
  return true;
}

template <Scalar T>
std::optional<std::string> face_ids(const Case<T>& k, const ChainSegment<T>& seg, const Contact<T>& c) {
  if (is_two_sided(k, seg, c)) return std::nullopt;
  const ::collide::detail::Core core = met_core(k);
  const double tol = length_tolerance(k);
  for (std::size_t i = 0; i < std::size_t(c.count); ++i) {
    const FeatureId id = c.ids[i];
    if (id.kind_a != FeatureKind::Edge || id.index_a != 0 || id.kind_b != FeatureKind::Vertex)
      return "point " + std::to_string(i) + " does not name edge 0 and a vertex";
    const std::size_t v = id.index_b, n = core.size();
    if (v >= n) return "point " + std::to_string(i) + " names vertex " + std::to_string(v) + " of " + std::to_string(n);
    // The shape's surface point lies the core's radius from the sides at the vertex it names.
    const Vec2c x = widen(c.points[i]) + widen(c.normal) * (double(c.separations[i]) / 2);
    const auto to_side = [&](const Vec2c& p, const Vec2c& q) {
      const Vec2c d = q - p;
      const double t = d.squaredNorm() > 0 ? std::clamp((x - p).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      return (p + d * t - x).norm();
    };
    const double near = std::min(to_side(core[v], core[(v + 1) % n]), to_side(core[(v + n - 1) % n], core[v]));
    if (std::fabs(near - core.radius) > tol)
      return "point " + std::to_string(i) + " lies off the sides at vertex " + std::to_string(v);
  }
  return std::nullopt;
}

// Laws over a segment whether or not it answered.

template <Scalar T>
std::optional<std::string> one_sided(const Case<T>& k, const ChainSegment<T>& seg, const std::optional<Contact<T>>& c) {
  const Vec2c ref = with_met_shape(k, [](const auto& s) { return ::collide::detail::reference_point(s); });
  if (orient(widen(seg.a()), widen(seg.b()), ref) <= 0) return std::nullopt;
  ++g_stats.behind;
  if (c) return std::string("a contact of a shape whose reference point lies behind the front");
  return std::nullopt;
}

template <Scalar T>
std::optional<std::string> face_complete(const Case<T>& k, const ChainSegment<T>& seg,
                                         const std::optional<Contact<T>>& c) {
  const Vec2c ref = with_met_shape(k, [](const auto& s) { return ::collide::detail::reference_point(s); });
  if (orient(widen(seg.a()), widen(seg.b()), ref) >= 0) return std::nullopt;
  if (!oracle::overlaps(seg.as_capsule(), exact_shape(k))) return std::nullopt;
  const Frame f = frame_of(seg);
  const ::collide::detail::Core core = met_core(k);
  const double tol = length_tolerance(k);
  std::size_t lowest = 0;
  for (std::size_t i = 1; i < core.size(); ++i) {
    if (f.n.dot(core[i] - f.a) < f.n.dot(core[lowest] - f.a)) lowest = i;
  }
  for (std::size_t i = 0; i < core.size(); ++i) {
    if (core.radius > 0 && i != lowest) continue;  // a rounded core: its support point only
    const Vec2c& v = core[i];
    const double t = f.u.dot(v - f.a), h = f.n.dot(v - f.a) - core.radius;
    if (t > tol && t < f.length - tol && h < -tol) {
      ++g_stats.completeness;
      if (!c) return std::string("no contact, though a core vertex lies inside the strip below the front");
      if (is_two_sided(k, seg, *c)) return std::nullopt;
      const double least = double(std::min(c->separations[0], c->separations[std::size_t(c->count - 1)]));
      if (least > h + tol) return "the least separation lies above a core vertex within the strip";
      return std::nullopt;
    }
  }
  return std::nullopt;
}

/// The case and the segment's answer, as a failure report opens.
template <Scalar T>
std::string account(const Case<T>& k, std::size_t i, const std::optional<Contact<T>>& c) {
  std::ostringstream o;
  o.precision(17);
  const ChainSegment<T> seg = k.chain.segment(i);
  o << (k.chain.loop() ? "loop" : "open chain") << " segment " << i << " (" << seg.before().transpose() << ") ("
    << seg.a().transpose() << ") -> (" << seg.b().transpose() << ") (" << seg.after().transpose() << "); shape "
    << name(kind(k.shape)) << " ";
  std::visit(
      [&](const auto& s) {
        o << "bounds (" << bounds(s).min().transpose() << ") (" << bounds(s).max().transpose() << ")";
      },
      k.shape);
  o << " placed at (" << k.x.position().transpose() << ") turned (" << k.x.rotation().transpose() << "); speculative "
    << k.speculative << "; ";
  if (c) {
    o << "contact normal (" << c->normal.transpose() << ") depth " << c->depth << " points";
    for (int j = 0; j < c->count; ++j)
      o << " (" << c->points[std::size_t(j)].transpose() << ") sep " << c->separations[std::size_t(j)];
  } else {
    o << "no contact";
  }
  o << ": ";
  return o.str();
}

/// Runs every segment of a generated case through `law`, reporting the first failure.
template <Scalar T, class Law>
void check(Law law) {
  const Case<T> k = gen_case<T>();
  for (std::size_t i = 0; i < k.chain.size(); ++i) {
    const ChainSegment<T> seg = k.chain.segment(i);
    const std::optional<Contact<T>> c =
        std::visit([&](const auto& s) { return contact(seg, s, k.x, k.speculative); }, k.shape);
    ++g_stats.segments;
    if (c) ++(is_face_normal(frame_of(seg), widen(c->normal), normal_tolerance<T>()) ? g_stats.face : g_stats.corner);
    const std::optional<std::string> failed = law(k, seg, c);
    if (failed) RC_FAIL(account(k, i, c) + *failed);
  }
}
/// A law of contacts, applied to the segments that answered.
template <Scalar T, class Law>
void check_contacts(Law law) {
  check<T>([&](const Case<T>& k, const ChainSegment<T>& seg, const std::optional<Contact<T>>& c) {
    return c ? law(k, seg, *c) : std::nullopt;
  });
}

}  // namespace

RC_GTEST_PROP(ChainLaws, admissible_float, ()) {
  check_contacts<float>(admissible<float>);
}
RC_GTEST_PROP(ChainLaws, admissible_double, ()) {
  check_contacts<double>(admissible<double>);
}
RC_GTEST_PROP(ChainLaws, one_sided_float, ()) {
  check<float>(one_sided<float>);
}
RC_GTEST_PROP(ChainLaws, one_sided_double, ()) {
  check<double>(one_sided<double>);
}
RC_GTEST_PROP(ChainLaws, surfaces_float, ()) {
  check_contacts<float>(surfaces<float>);
}
RC_GTEST_PROP(ChainLaws, surfaces_double, ()) {
  check_contacts<double>(surfaces<double>);
}
RC_GTEST_PROP(ChainLaws, present_when_near_float, ()) {
  check_contacts<float>(present_when_near<float>);
}
RC_GTEST_PROP(ChainLaws, present_when_near_double, ()) {
  check_contacts<double>(present_when_near<double>);
}
RC_GTEST_PROP(ChainLaws, face_complete_float, ()) {
  check<float>(face_complete<float>);
}
RC_GTEST_PROP(ChainLaws, face_complete_double, ()) {
  check<double>(face_complete<double>);
}
RC_GTEST_PROP(ChainLaws, face_ids_float, ()) {
  check_contacts<float>(face_ids<float>);
}
RC_GTEST_PROP(ChainLaws, face_ids_double, ()) {
  check_contacts<double>(face_ids<double>);
}

}  // namespace collide::props

/// Runs the laws, then prints what they judged: a run that judged nothing proves nothing.
int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const int failed = RUN_ALL_TESTS();
  const collide::props::Stats& s = collide::props::g_stats;
  std::printf(
      "chain laws judged %ld segments: %ld face contacts, %ld corner contacts, %ld shapes behind, %ld "
      "completeness claims\n",
      s.segments, s.face, s.corner, s.behind, s.completeness);
  return failed;
}
