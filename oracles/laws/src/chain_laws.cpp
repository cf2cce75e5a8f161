// The laws of chain contacts (collide/chain.hpp): contact(segment, shape, x, speculative) of one
// segment against the exact oracle, on the semantics the header states.

#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace collide::laws {

using detail::describe;
using detail::distance_to_segment;
using detail::judged;
using detail::Judgement;
using detail::num;

namespace {

/// The frame of the segment from p to q in double: p, unit direction, front normal, length.
struct Frame {
  Vec2c a, u, n;
  double length;
};
Frame frame_between(const Vec2c& p, const Vec2c& q) {
  // Scaled by a power of two first (exactly): a subnormal difference keeps its direction.
  const Vec2c d = q - p;
  int e = 0;
  static_cast<void>(std::frexp(std::max(std::fabs(d.x()), std::fabs(d.y())), &e));
  const Vec2c s(std::ldexp(d.x(), -e), std::ldexp(d.y(), -e));
  const double len = s.norm();
  return {p, s / len, Vec2c(s.y() / len, -s.x() / len), std::ldexp(len, e)};
}
template <Scalar T>
Frame frame_of(const ChainSegment<T>& s) {
  return frame_between(widen(s.a()), widen(s.b()));
}

/// What every chain law reads: the segment's answer and the primitive as the contact meets it
/// (stored for the identity, else its image in double, as every placed query meets a shape). For
/// a compound, one child (`child`, its index; -1 for a primitive shape) met as the library meets
/// it: through its image under the child's own transform and x.
template <Scalar T>
struct ChainCase {
  const ChainSegment<T>& s;
  const Shape<T>& whole;
  const Primitive<T>& b;  ///< the primitive judged: the shape, or the compound's child
  int child;
  const Transform<T>& x;
  T speculative;
  std::optional<Contact<T>> c;
  double tol;  ///< lengths: length_tolerance()

  const Compound<T>* compound() const { return std::get_if<Compound<T>>(&whole); }
  /// The body pose a placed compound's children are imaged under (the identity's: none).
  ::collide::detail::Pose body() const { return x.is_identity() ? ::collide::detail::Pose{} : x.pose(); }
  /// Whether the primitive is met as stored: the shape in world space, or a child of a world-space
  /// compound without child transforms.
  bool met_as_stored() const { return x.is_identity() && (child < 0 || !compound()->has_child_transforms()); }

  template <class F>
  auto with_met_shape(F&& f) const {
    return std::visit(
        [&](const auto& p) {
          if (met_as_stored()) return f(p);
          if (child < 0) return ::collide::detail::with_placed(p, x, f);
          std::optional<decltype(f(p))> out;
          ::collide::detail::visit_child(*compound(), std::size_t(child), body(),
                                         [&](const auto& image) { out.emplace(f(image)); });
          return *out;
        },
        b);
  }
  /// Child i of the compound alone, with its own transform: placed by x, met as it is met within.
  Shape<T> only_child(std::size_t i) const {
    return Compound<T>::make_placed({{compound()->children()[i], compound()->child_transform(i)}}).value();
  }
  oracle::Placed exact_shape() const { return oracle::placed(child < 0 ? whole : only_child(std::size_t(child)), x); }
  ::collide::detail::Core met_core() const {
    return with_met_shape([](const auto& p) { return ::collide::detail::core_of(p); });
  }
  /// The stored primitive's core (numbered as feature ids name a placed shape's features) mapped
  /// by the child's transform and x in double: within rounding of the core the contact met.
  ::collide::detail::Core stored_core_placed() const {
    const ::collide::detail::Core stored = std::visit([](const auto& p) { return ::collide::detail::core_of(p); }, b);
    const Transform<T> own = child < 0 ? Transform<T>() : compound()->child_transform(std::size_t(child));
    ::collide::detail::Core out;
    out.radius = stored.radius;
    for (std::size_t i = 0; i < stored.size(); ++i) out.push(x.apply(own.apply(stored[i])));
    return out;
  }
  Vec2c reference_point() const {
    return with_met_shape([](const auto& p) { return ::collide::detail::reference_point(p); });
  }
  /// Whether c is, bit for bit, the segment's two-sided contact (which the pair laws judge).
  bool is_two_sided() const {
    const Calc spec = ::collide::detail::speculative_distance(speculative);
    std::optional<::collide::detail::CoreContact> core;
    if (child < 0) {
      // As the contact names features of a placed shape: the stored shape's (placement.hpp).
      core = std::visit(
          [&](const auto& stored) {
            if (x.is_identity()) return ::collide::detail::contact_primitives(s.as_capsule(), stored, spec);
            return ::collide::detail::with_placed(stored, x, [&](const auto& p) {
              std::optional<::collide::detail::CoreContact> found =
                  ::collide::detail::contact_primitives(s.as_capsule(), p, spec);
              if (found) ::collide::detail::name_placed_features(stored, p, x, *found, true);
              return found;
            });
          },
          b);
    } else {
      // As a compound's contact names its child and that child's features (shape_traits.hpp).
      core =
          with_met_shape([&](const auto& p) { return ::collide::detail::contact_primitives(s.as_capsule(), p, spec); });
      if (core) {
        for (FeatureId& id : core->ids) id.child_b = std::uint16_t(child);
        if (!met_as_stored()) ::collide::detail::name_child_features(*compound(), body(), *core, true);
      }
    }
    std::optional<Contact<T>> two;
    if (core) ::collide::detail::round_into(*core, two);
    if (!c || !two || two->count != c->count || two->normal != c->normal || two->depth != c->depth) return false;
    for (std::size_t i = 0; i < std::size_t(c->count); ++i) {
      if (two->points[i] != c->points[i] || two->separations[i] != c->separations[i] || !(two->ids[i] == c->ids[i]))
        return false;
    }
    return true;
  }
};

/// The laws' tolerance for lengths: 64 eps_T of the largest coordinate of the segment, its
/// neighbours and the placed shape's bounds, plus 8 denorm_min_T and twice the placement's
/// transform_tolerance().
template <Scalar T>
double length_tolerance(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& x) {
  double scale = 0;
  for (const Vec2<T>& p : {s.before(), s.a(), s.b(), s.after()})
    scale = std::max(scale, widen(p).cwiseAbs().maxCoeff());
  const Aabb<T> box = bounds(b, x);
  scale = std::max({scale, widen(box.min()).cwiseAbs().maxCoeff(), widen(box.max()).cwiseAbs().maxCoeff()});
  // Plus the points' rounding to T where it is absolute (subnormal coordinates), and the placed
  // image's own error, both the contact's and the laws' (the placement contract, transformed.hpp).
  const double image = double(transform_tolerance(b, x));
  return 64 * double(std::numeric_limits<T>::epsilon()) * scale + 8 * double(std::numeric_limits<T>::denorm_min()) +
         2 * image;
}

std::string point_text(const Vec2c& p) {
  return "(" + num(p.x()) + ", " + num(p.y()) + ")";
}

template <Scalar T>
std::string answer_text(const std::optional<Contact<T>>& c) {
  if (!c) return "no contact";
  std::string out = "contact normal " + point_text(widen(c->normal)) + " depth " + num(double(c->depth)) + " points";
  for (std::size_t i = 0; i < std::size_t(c->count); ++i)
    out += " " + point_text(widen(c->points[i])) + " sep " + num(double(c->separations[i]));
  return out;
}

/// Runs law(k, r) on the segment's answer, and a shape the segment's factory would refuse is a
/// broken input. A compound is judged through its children, each on its own as the library meets
/// it: a contact through the child its ids name (all the same one), no contact through every child.
template <Scalar T, class Law>
Verdict chain_judged(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& x, T speculative, Law law) {
  const std::string context = "segment " + point_text(widen(s.before())) + " " + point_text(widen(s.a())) + " -> " +
                              point_text(widen(s.b())) + " " + point_text(widen(s.after())) +
                              (s.owns_start_corner() ? " (owns its start)" : "") + "; b = " + describe(b) +
                              " placed at " + point_text(widen(x.position())) + " turned " +
                              point_text(widen(x.rotation())) + "; speculative " + num(double(speculative));
  return judged(context, [&](Judgement& r) {
    const std::optional<Contact<T>> c = contact(s, b, x, speculative);
    const double tol = length_tolerance(s, b, x);
    r.note(answer_text(c));
    const std::vector<Primitive<T>> p = primitives_of(b);
    if (!std::holds_alternative<Compound<T>>(b)) {
      law(ChainCase<T>{s, b, p[0], -1, x, speculative, c, tol}, r);
      return;
    }
    if (c) {
      const std::size_t j = c->ids[0].child_b;
      r.require(j < p.size(), "ids naming one of the compound's " + std::to_string(p.size()) + " children",
                "child " + std::to_string(j));
      for (std::size_t i = 0; i < std::size_t(c->count) && r.v.ok; ++i) {
        r.require(c->ids[i].child_b == j && c->ids[i].child_a == 0, "every point naming child " + std::to_string(j),
                  "point " + std::to_string(i) + " naming child " + std::to_string(c->ids[i].child_b));
      }
      if (!r.v.ok) return;
      r.note("judged through child " + std::to_string(j));
      law(ChainCase<T>{s, b, p[j], int(j), x, speculative, c, tol}, r);
      return;
    }
    for (std::size_t j = 0; j < p.size() && r.v.ok; ++j)
      law(ChainCase<T>{s, b, p[j], int(j), x, speculative, c, tol}, r);
  });
}

bool is_face_normal(const Frame& f, const Vec2c& m, double tol) {
  return (m - f.n).norm() <= tol;
}

template <Scalar T>
double normal_tolerance() {
  return 64 * double(std::numeric_limits<T>::epsilon());
}

/// The height above the front of the core's lowest point within the segment's strip narrowed by
/// tol at both ends: the least over its vertices there and the ends of its sides cut to it
/// (nullopt when the core misses it). The shape's lowest point there lies the radius lower.
std::optional<double> lowest_in_inner_strip(const Frame& f, const ::collide::detail::Core& core, double tol) {
  const double lo = tol, hi = f.length - tol;
  if (!(lo < hi)) return std::nullopt;
  std::optional<double> least;
  const auto take = [&](const Vec2c& p) {
    const double h = f.n.dot(p - f.a);
    if (!least || h < *least) least = h;
  };
  const std::size_t n = core.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2c p = core[i], q = core[(i + 1) % n];
    const double tp = f.u.dot(p - f.a), tq = f.u.dot(q - f.a);
    if (tp >= lo && tp <= hi) take(p);
    if (n == 1 || tp == tq) continue;
    for (const double edge : {lo, hi}) {
      const double w = (edge - tp) / (tq - tp);  // where the side meets the narrowed strip's edge
      if (w > 0 && w < 1) take(p + (q - p) * w);
    }
  }
  return least;
}

/// A compound's contact is its deepest child's (as contact() picks the deepest child pair): no
/// child's own contact (the child alone, placed the same way) is deeper, or nearer when neither
/// sinks in, by more than the tolerance.
template <Scalar T>
void no_deeper_child(const ChainCase<T>& k, Judgement& r) {
  const Contact<T>& c = *k.c;
  const auto least = [](const Contact<T>& x) {
    return double(std::min(x.separations[0], x.separations[std::size_t(x.count - 1)]));
  };
  for (std::size_t i = 0; i < k.compound()->children().size() && r.v.ok; ++i) {
    if (int(i) == k.child) continue;
    const std::optional<Contact<T>> own = contact(k.s, k.only_child(i), k.x, k.speculative);
    if (!own) continue;
    const bool deeper = own->depth > T(0) || c.depth > T(0) ? double(own->depth) > double(c.depth) + k.tol
                                                            : least(*own) < least(c) - k.tol;
    r.require(!deeper,
              "the deepest child's contact (child " + std::to_string(k.child) + ", depth " + num(double(c.depth)) +
                  ", least separation " + num(least(c)) + ")",
              "child " + std::to_string(i) + " alone deeper: depth " + num(double(own->depth)) + ", least separation " +
                  num(least(*own)));
  }
}

}  // namespace

template <Scalar T>
Verdict chain_admissible(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative) {
  return chain_judged(s, b, xb, speculative, [&](const ChainCase<T>& k, Judgement& r) {
    if (!k.c) return;
    const Frame f = frame_of(s);
    const Vec2c m = widen(k.c->normal);
    const double tol = normal_tolerance<T>();
    if (is_face_normal(f, m, tol)) return;
    const auto in_arc = [&](const Vec2c& from, const Vec2c& to) {
      return cross(from, m) >= -tol && cross(m, to) >= -tol;  // the arc is less than a half turn
    };
    const Vec2c before = widen(s.before()), a = widen(s.a()), e = widen(s.b()), after = widen(s.after());
    const bool at_end = orient(a, e, after) > 0 && in_arc(f.n, frame_between(e, after).n);
    const bool at_start = s.owns_start_corner() && orient(before, a, e) > 0 && in_arc(frame_between(before, a).n, f.n);
    r.require(at_end || at_start, "the front normal " + point_text(f.n) + " or a normal inside an owned corner arc",
              "normal " + point_text(m));
  });
}

template <Scalar T>
Verdict chain_one_sided(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative) {
  return chain_judged(s, b, xb, speculative, [&](const ChainCase<T>& k, Judgement& r) {
    if (orient(widen(s.a()), widen(s.b()), k.reference_point()) <= 0) return;
    r.require(!k.c, "no contact for a shape whose reference point lies behind the front", "a contact");
  });
}

template <Scalar T>
Verdict chain_surfaces(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative) {
  return chain_judged(s, b, xb, speculative, [&](const ChainCase<T>& k, Judgement& r) {
    if (!k.c) return;
    const Contact<T>& c = *k.c;
    r.require(c.count == 1 || c.count == 2, "1 or 2 points", std::to_string(c.count));
    if (!r.v.ok) return;
    const Vec2c m = widen(c.normal);
    const oracle::Placed shape = k.exact_shape();
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < std::size_t(c.count); ++i) {
      const double sep = double(c.separations[i]);
      least = std::min(least, sep);
      const Vec2c on_segment = widen(c.points[i]) - m * (sep / 2), on_shape = widen(c.points[i]) + m * (sep / 2);
      const std::string at = "point " + std::to_string(i) + " ";
      r.require(oracle::compare_boundary_distance(s.as_capsule(), on_segment, k.tol) <= 0,
                at + "with its segment end on the segment", "its end " + point_text(on_segment) + " off it");
      r.require(oracle::compare_boundary_distance(shape, on_shape, k.tol) <= 0,
                at + "with its shape end on the exact shape's boundary", "its end " + point_text(on_shape) + " off it");
      r.require(sep <= double(k.speculative) + k.tol, at + "within the speculative distance", "separation " + num(sep));
    }
    // A corner contact is contact()'s, whose depth (the shapes' least translation) the pair laws
    // judge: clipping may leave only shallower points there.
    if (k.is_two_sided()) return;
    const double depth = least < 0 ? -least : 0;
    r.require(std::fabs(double(c.depth) - depth) <= k.tol, "depth " + num(depth) + ", the least separation's",
              "depth " + num(double(c.depth)));
  });
}

template <Scalar T>
Verdict chain_present(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative) {
  return chain_judged(s, b, xb, speculative, [&](const ChainCase<T>& k, Judgement& r) {
    if (!k.c) return;
    r.require(oracle::compare_distance(s.as_capsule(), k.exact_shape(), double(k.speculative) + k.tol) <= 0,
              "a contact only within the speculative distance of the exact shape", "a contact of a shape farther");
  });
}

template <Scalar T>
Verdict chain_face_complete(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative) {
  return chain_judged(s, b, xb, speculative, [&](const ChainCase<T>& k, Judgement& r) {
    if (k.child >= 0 && k.c) no_deeper_child(k, r);
    if (orient(widen(s.a()), widen(s.b()), k.reference_point()) >= 0) return;
    if (!oracle::overlaps(s.as_capsule(), k.exact_shape())) return;
    // A placed shape overlapping by no more than its image's error may be met or missed
    // (overlaps() is exact outside that band only: transformed.hpp).
    const double band = double(transform_tolerance(k.whole, k.x));
    if (band > 0 && oracle::within_band(s.as_capsule(), k.exact_shape(), band)) return;
    const Frame f = frame_of(s);
    const ::collide::detail::Core core = k.met_core();
    const std::optional<double> h = lowest_in_inner_strip(f, core, k.tol);
    if (!h || !(*h - core.radius < -k.tol)) return;
    const double lowest = *h - core.radius;
    r.v.account = "claimed: the shape reaches " + num(lowest) + " below the front within the strip; " + r.v.account;
    r.require(k.c.has_value(), "a contact: the shape reaches " + num(lowest) + " below the front within the strip",
              "no contact");
    if (!k.c || k.is_two_sided()) return;
    const double least = double(std::min(k.c->separations[0], k.c->separations[std::size_t(k.c->count - 1)]));
    r.require(least <= lowest + k.tol, "a least separation no higher than " + num(lowest),
              "least separation " + num(least));
  });
}

template <Scalar T>
Verdict chain_face_ids(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative) {
  return chain_judged(s, b, xb, speculative, [&](const ChainCase<T>& k, Judgement& r) {
    if (!k.c || k.is_two_sided()) return;
    const Contact<T>& c = *k.c;
    const ::collide::detail::Core core = k.stored_core_placed();
    const std::size_t n = core.size();
    if (const std::size_t met = k.met_core().size(); met != n) {
      // A shape thinner than its rounding: the stored corners or the image's rounded onto fewer
      // points, and the ids follow the one the contact met (as the placed pair laws skip it).
      r.note("ids not judged: the stored core has " + std::to_string(n) + " points, the one met " +
             std::to_string(met));
      return;
    }
    for (std::size_t i = 0; i < std::size_t(c.count) && r.v.ok; ++i) {
      const FeatureId id = c.ids[i];
      const std::string at = "point " + std::to_string(i) + " ";
      r.require(id.kind_a == FeatureKind::Edge && id.index_a == 0 && id.kind_b == FeatureKind::Vertex,
                at + "naming the segment's edge 0 and a vertex of the shape", "another feature pair");
      const std::size_t v = id.index_b;
      r.require(v < n, at + "naming one of the core's " + std::to_string(n) + " vertices",
                "vertex " + std::to_string(v));
      if (!r.v.ok) return;
      // The shape's surface point lies the core's radius from the sides at the vertex it names.
      const Vec2c x = widen(c.points[i]) + widen(c.normal) * (double(c.separations[i]) / 2);
      const double near = std::min(distance_to_segment(x, {core[v], core[(v + 1) % n]}),
                                   distance_to_segment(x, {core[(v + n - 1) % n], core[v]}));
      r.require(std::fabs(near - core.radius) <= k.tol,
                at + "lying the core's radius " + num(core.radius) + " from the sides at vertex " + std::to_string(v),
                "distance " + num(near));
    }
  });
}

#define COLLIDE_CHAIN_LAW(law)                                                                                  \
  template Verdict law<float>(const ChainSegment<float>&, const Shape<float>&, const Transform<float>&, float); \
  template Verdict law<double>(const ChainSegment<double>&, const Shape<double>&, const Transform<double>&, double);
COLLIDE_CHAIN_LAW(chain_admissible)
COLLIDE_CHAIN_LAW(chain_one_sided)
COLLIDE_CHAIN_LAW(chain_surfaces)
COLLIDE_CHAIN_LAW(chain_present)
COLLIDE_CHAIN_LAW(chain_face_complete)
COLLIDE_CHAIN_LAW(chain_face_ids)
#undef COLLIDE_CHAIN_LAW

}  // namespace collide::laws
