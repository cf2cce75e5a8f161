// The laws on one shape: bounds are conservative; raycasts hit the boundary first, with the
// outward normal; a ray from inside leaves where the shape ends; contains() agrees with the oracle.

#include "support.hpp"

#if __has_include("collide/raycast.hpp")
#include "collide/raycast.hpp"
#define COLLIDE_LAWS_HAVE_RAYCAST 1
#endif

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace collide::laws {

using detail::describe;
using detail::farther_than;
using detail::num;
using detail::vec;

template <Scalar T>
Verdict bounds_law(const Shape<T>& s) {
  Verdict v;
  try {
    const Aabb<T> box = bounds(s);
    v.account = "bounds " + describe(box);
    if (!oracle::inside_box(s, box)) {
      v.ok = false;
      v.expected = "shape inside its bounds";
      v.got = "part of the shape outside " + describe(box);
      v.account = "expected " + v.expected + "; got " + v.got + "; s = " + describe(s);
    }
  } catch (const std::exception& e) {
    v.ok = false;
    v.expected = "no exception";
    v.got = e.what();
    v.account = std::string("exception: ") + e.what() + "; s = " + describe(s);
  }
  return v;
}

namespace {

/// o lies in s farther than `bound` from its boundary (for a compound: from some child's
/// boundary, inside that child), exactly: the origins for which the ray must hit at t = 0.
template <Scalar T>
bool deep_inside(const Shape<T>& s, const Vec2c& o, double bound) {
  for (const auto& child : detail::placed_primitives_of(s)) {
    const oracle::Placed x = oracle::placed(child.shape, child.transform);
    if (oracle::contains(x, o) && oracle::compare_boundary_distance(x, o, bound) > 0) return true;
  }
  return false;
}

/// n is an outward unit normal of s's boundary at p (p within bound of s), within the bound: the
/// point q = p + L n lies outside s at distance >= L - slack (for a compound, outside some child
/// that p is near). For a boundary point h with n in its normal cone, dist(h + L n, s) = L
/// exactly; p and n are off h and the exact normal by their rounding, which slack covers. A
/// wrong normal at angle theta loses about L theta^2 / 2, and a flipped one puts q inside.
template <Scalar T>
bool outward_normal(const Shape<T>& s, const Vec2c& p, const Vec2c& n, double bound) {
  const Aabb<T> box = bounds(s);
  const Vec2c size = (box.max().template cast<double>() - box.min().template cast<double>());
  const double length = std::max(size.maxCoeff(), 0x1p20 * bound);
  const double slack = 2 * bound + 4 * detail::eps<T>() * length;
  const Vec2c q = p + n * length;
  for (const auto& child : detail::placed_primitives_of(s)) {
    const oracle::Placed x = oracle::placed(child.shape, child.transform);
    if (!detail::near_boundary(x, p, bound)) continue;
    if (!oracle::contains(x, q) && oracle::compare_boundary_distance(x, q, length - slack) >= 0) return true;
  }
  return false;
}

}  // namespace

template <Scalar T>
Verdict contains_law(const Shape<T>& s, const Vec2<T>& p) {
  Verdict v;
  try {
    const bool got = contains(s, p);
    const Vec2c q = p.template cast<double>();
    v.account = "contains " + vec(p) + " " + detail::yes(got);
    if (!std::isfinite(q.x()) || !std::isfinite(q.y())) {
      if (got) {
        v.ok = false;
        v.expected = "false for a non-finite point";
        v.got = "true";
      }
    } else {
      const bool exact = oracle::contains(s, q);
      v.relation = exact ? Relation::Contained : Relation::Separated;
      v.account += ", exact " + detail::yes(exact);
      if (got != exact) {
        // A difference must come from a rounded child (a round kind, or one placed by a child
        // transform) within the tolerance of its boundary.
        const double tol = contains_tolerance(s, p);
        bool allowed = false;
        for (const auto& child : detail::placed_primitives_of(s)) {
          const bool rounded =
              !child.transform.is_identity() ||
              (!std::holds_alternative<Aabb<T>>(child.shape) && !std::holds_alternative<ConvexPolygon<T>>(child.shape));
          allowed = allowed || (rounded && detail::near_boundary(oracle::placed(child.shape, child.transform), q, tol));
        }
        v.disagreement = true;
        // Inside the band, judged exactly on the shapes the library computed.
        const bool computed = oracle::contains(detail::computed_geometry(s), q);
        if (allowed && got != computed) {
          v.ok = false;
          v.expected = "contains " + detail::yes(computed) + " (the oracle on the shapes the library computed)";
          v.got = "contains " + detail::yes(got);
        } else if (allowed) {
          v.account += "; within contains_tolerance " + num(tol) + " of a rounded boundary: allowed";
        } else {
          v.ok = false;
          v.expected = "contains " + detail::yes(exact);
          v.got = "contains " + detail::yes(got);
        }
      }
    }
    if (!v.ok) v.account = "expected " + v.expected + "; got " + v.got + "; s = " + describe(s) + "; p = " + vec(p);
  } catch (const std::exception& e) {
    v.ok = false;
    v.expected = "no exception";
    v.got = e.what();
    v.account = std::string("exception: ") + e.what() + "; s = " + describe(s) + "; p = " + vec(p);
  }
  return v;
}

template <Scalar T>
Verdict raycast_law(const Shape<T>& s, const Ray<T>& ray, T max_t) {
  Verdict v;
#if defined(COLLIDE_LAWS_HAVE_RAYCAST)
  auto fail = [&](std::string expected, std::string got) {
    v.ok = false;
    v.expected = std::move(expected);
    v.got = std::move(got);
    v.account = "expected " + v.expected + "; got " + v.got + "; s = " + describe(s) + "; ray " + vec(ray.origin) +
                " + t " + vec(ray.direction) + ", max_t " + num(max_t);
  };
  try {
    const Vec2c o = ray.origin.template cast<double>(), d = ray.direction.template cast<double>();
    const double len = d.norm();
    // The library's own bound (raycast.hpp): rays within it of the shape may hit or miss.
    const double bound = raycast_tolerance(s, ray);
    const auto hit = raycast(s, ray, max_t);
    const bool inside = oracle::contains(s, o);
    v.relation = inside ? Relation::Contained : (hit ? Relation::Overlapping : Relation::Separated);
    if (!hit) {
      v.account = "no hit";
      // Nothing within the segment shortened by the bound at its end.
      const double shorten = len > 0 ? bound / len : 0;
      const double t_end = double(max_t) - shorten;
      if (inside && deep_inside(s, o, bound)) {
        fail("a hit at t = 0 (origin inside the shape, deeper than the bound)", "no hit");
      } else if (t_end > 0 && oracle::passes_deeper(s, o, Vec2c(o + d * t_end), bound)) {
        fail("no point deeper than the bound on the segment to max_t", "no hit");
      }
      return v;
    }
    const double t = hit->t;
    const Vec2c p = hit->point.template cast<double>();
    v.account = "hit t " + num(t) + " at " + vec(hit->point);
    if (!(t >= 0) || !(t <= double(max_t))) {
      fail("0 <= t <= max_t", "t " + num(t));
      return v;
    }
    if (inside) {
      if (t != 0 && deep_inside(s, o, bound)) {
        fail("t = 0 for an origin inside the shape (deeper than the bound)", "t " + num(t));
      } else if (d != Vec2c::Zero() && deep_inside(s, o, bound)) {
        const Vec2c dm = d / d.cwiseAbs().maxCoeff();  // exact scaling first: |d|^2 may underflow
        const Vec2c n = hit->normal.template cast<double>();
        if ((n + dm / dm.norm()).cwiseAbs().maxCoeff() > 8 * detail::eps<T>())
          fail("normal -direction / |direction| for an origin inside", "normal " + vec(hit->normal));
      }
      return v;
    }
    // t is returned in T: its rounding, relative or (when t underflows T) absolute, moves o + t d.
    if ((p - (o + d * t)).norm() >
        bound + (4 * detail::eps<T>() * t + double(std::numeric_limits<T>::denorm_min())) * len) {
      fail("point = origin + t * direction", "point " + vec(hit->point));
      return v;
    }
    if (farther_than(s, p, bound)) {
      fail("hit point within " + num(bound) + " of the shape", "point " + vec(hit->point));
      return v;
    }
    const double t_early = t - (len > 0 ? bound / len : 0);
    if (t_early > 0 && oracle::passes_deeper(s, o, Vec2c(o + d * t_early), bound)) {
      fail("no point deeper than the bound before t", "the shape meets the ray before t " + num(t_early));
      return v;
    }
    const Vec2c n = hit->normal.template cast<double>();
    if (d == Vec2c::Zero()) {
      // A zero direction hits only where it starts, with normal (0, 0) (raycast.hpp).
      if (n != Vec2c::Zero()) fail("normal (0, 0) for a zero direction", "normal " + vec(hit->normal));
      return v;
    }
    if (!(std::fabs(n.norm() - 1) <= 8 * detail::eps<T>())) {
      fail("a unit hit normal", "normal " + vec(hit->normal) + " (|n| = " + num(n.norm()) + ")");
      return v;
    }
    // At t = 0 the origin is on the shape (within the bound): -direction / |direction| as for an
    // origin inside, or the outward normal where the ray enters.
    const Vec2c dm = d / d.cwiseAbs().maxCoeff();  // exact scaling first: |d|^2 may underflow
    const Vec2c u = dm / dm.norm();
    const bool backward = t == 0 && (n + u).cwiseAbs().maxCoeff() <= 8 * detail::eps<T>();
    // The normal is judged where the ray really enters: 4 bounds past the point it is deeper than
    // the bound inside. A ray grazing the shape within the bound, or a sliver thinner than that,
    // has no reliable face.
    if (!deep_inside(s, Vec2c(p + u * (4 * bound)), bound)) {
      v.account += "; normal not judged (grazing within the bound)";
      return v;
    }
    if (!backward && !outward_normal(s, p, n, bound)) {
      fail(std::string("the outward normal of the boundary at the hit point") +
               (t == 0 ? " (or -direction / |direction| at t = 0)" : ""),
           "normal " + vec(hit->normal));
      return v;
    }
  } catch (const std::exception& e) {
    v.ok = false;
    v.expected = "no exception";
    v.got = e.what();
    v.account = std::string("exception: ") + e.what() + "; s = " + describe(s);
  }
#else
  (void)s;
  (void)ray;
  (void)max_t;
  v.ok = false;
  v.expected = "collide/raycast.hpp";
  v.got = "the library has no raycast yet";
  v.account = "raycast law: the library has no raycast yet";
#endif
  return v;
}

template Verdict bounds_law<float>(const Shape<float>&);
template Verdict bounds_law<double>(const Shape<double>&);
template <Scalar T>
Verdict raycast_exit_law(const Shape<T>& s, const Ray<T>& ray, T max_t) {
  const std::string context =
      "s = " + describe(s) + "; ray " + vec(ray.origin) + " + t " + vec(ray.direction) + ", max_t " + num(max_t);
  return detail::judged(context, [&](detail::Judgement& r) {
    Verdict& v = r.v;
    const auto fail = [&](const std::string& expected, const std::string& got) { r.require(false, expected, got); };
    const Vec2c o = ray.origin.template cast<double>(), d = ray.direction.template cast<double>();
    const double len = d.norm();
    const double bound = raycast_exit_tolerance(s, ray);
    const auto exit = raycast_exit(s, ray, max_t);
    const bool valid = o.allFinite() && d.allFinite() && std::isfinite(double(max_t)) && max_t >= 0;
    const bool inside = valid && contains(s, ray.origin);
    v.relation = inside ? Relation::Contained : Relation::Separated;
    if (!inside) {
      v.account = "origin outside or bad input";
      if (exit) fail("nothing (origin outside the shape, or bad input)", "exit t " + num(exit->t));
      return;
    }
    if (!exit) {
      fail("an exit for an origin inside the shape", "nothing");
      return;
    }
    const double t = exit->t;
    const Vec2c p = exit->point.template cast<double>();
    const Vec2c n = exit->normal.template cast<double>();
    v.account = "exit t " + num(t) + " at " + vec(exit->point) + " normal " + vec(exit->normal);
    if (!(t >= 0) || !(t <= double(max_t))) {
      fail("0 <= t <= max_t", "t " + num(t));
      return;
    }
    if ((p - (o + d * t)).norm() >
        bound + (4 * detail::eps<T>() * t + double(std::numeric_limits<T>::denorm_min())) * len) {
      fail("point = origin + t * direction", "point " + vec(exit->point));
      return;
    }
    const bool stays = n == Vec2c::Zero();
    if (stays && t != double(max_t)) {
      fail("normal (0, 0) only for a ray still inside at max_t", "t " + num(t) + " < max_t");
      return;
    }
    // Inside up to the exit: the point itself (the segment, for a convex primitive) ...
    if (farther_than(s, p, bound)) {
      fail("the exit point within " + num(bound) + " of the shape", "point " + vec(exit->point));
      return;
    }
    // ... and, for a compound, no gap: a gap begins where the ray leaves a child, which is where
    // that child is first met casting backward from the exit.
    if (len > 0 && std::holds_alternative<Compound<T>>(s)) {
      const Ray<T> back{exit->point, Vec2<T>(-ray.direction)};
      for (const auto& child : detail::placed_primitives_of(s)) {
        const auto h = raycast(child.shape, child.transform, back, exit->t);
        if (!h) continue;
        const double leaves = t - double(h->t) + 3 * bound / len;
        if (leaves >= t - bound / len) continue;
        const Vec2c q = o + d * leaves;
        if (farther_than(s, q, bound)) {
          fail("no point of the ray before the exit farther than " + num(bound) + " from the shape",
               "the ray outside at " + vec(q) + " (t " + num(leaves) + ")");
          return;
        }
      }
    }
    if (stays) return;
    // Not early: the exit point is not deep inside.
    if (deep_inside(s, p, bound)) {
      fail("the exit point within " + num(bound) + " of the boundary", "deeper than that inside");
      return;
    }
    if (!(std::fabs(n.norm() - 1) <= 8 * detail::eps<T>())) {
      fail("a unit exit normal", "normal " + vec(exit->normal) + " (|n| = " + num(n.norm()) + ")");
      return;
    }
    // The normal is judged where the ray really leaves: 4 bounds before the point it was deeper
    // than the bound inside.
    const Vec2c dm = d / d.cwiseAbs().maxCoeff();  // exact scaling first: |d|^2 may underflow
    const Vec2c u = dm / dm.norm();
    if (!deep_inside(s, Vec2c(p - u * (4 * bound)), bound)) {
      v.account += "; normal not judged (the ray runs within the bound of the boundary)";
      return;
    }
    if (!outward_normal(s, p, n, bound))
      fail("the outward normal of the boundary at the exit", "normal " + vec(exit->normal));
  });
}

template Verdict raycast_law<float>(const Shape<float>&, const Ray<float>&, float);
template Verdict raycast_law<double>(const Shape<double>&, const Ray<double>&, double);
template Verdict raycast_exit_law<float>(const Shape<float>&, const Ray<float>&, float);
template Verdict raycast_exit_law<double>(const Shape<double>&, const Ray<double>&, double);
template Verdict contains_law<float>(const Shape<float>&, const Vec2<float>&);
template Verdict contains_law<double>(const Shape<double>&, const Vec2<double>&);

}  // namespace collide::laws
