/// @file transform_laws.cpp
/// The laws of shapes placed by transforms (transformed.hpp), judged on the exact images the
/// oracle computes (oracle::Placed).

#include "collide/laws/laws.hpp"
#include "support.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace collide::laws {

using detail::describe;
using detail::documented_margin;
using detail::judged;
using detail::Judgement;
using detail::num;
using detail::placed_relation;
using detail::placed_text;
using detail::push_direction;
using detail::quarter_turn;
using detail::vec;
using detail::yes;

namespace {

template <Scalar T>
std::string pair_context(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb) {
  return "a = " + placed_text(a, xa) + "; b = " + placed_text(b, xb);
}

/// A point as an exact oracle input (a zero circle, built unchecked: the point may lie beyond the
/// range a stored circle accepts).
inline oracle::Placed point_input(const Vec2<double>& p) {
  return oracle::Placed(Shape<double>(collide::detail::ShapeAccess::circle<double>(p, 0.0)));
}

/// Every mapped coordinate of s's stored positions under x is exact in U (double: the images; T:
/// the world shape a factory builds). Compounds with child transforms never count as exact. An
/// AABB turned (not only moved) is imaged as a box from its centre and half extents, which must
/// be exact too.
template <Scalar U, Scalar T>
bool exact_image(const Shape<T>& s, const Transform<T>& x) {
  if (!quarter_turn(x)) return false;
  if (const auto* c = std::get_if<Compound<T>>(&s); c != nullptr && c->has_child_transforms()) return false;
  if (x.rotation() != Vec2<T>(T(1), T(0))) {
    for (const Primitive<T>& p : detail::primitives_of(s)) {
      const auto* box = std::get_if<Aabb<T>>(&p);
      for (int k = 0; box != nullptr && k < 2; ++k) {
        const double lo = box->min()[k], hi = box->max()[k];
        if (!detail::exact_sum(lo, hi, lo + hi) || !detail::exact_sum(hi, -lo, hi - lo)) return false;
      }
    }
  }
  std::vector<Vec2<T>> pos;
  std::vector<T> other;
  detail::positions(s, pos, other);
  for (const Vec2<T>& p : pos) {
    const Vec2c r = x.rotate(widen(p));  // exact for a quarter turn
    for (int k = 0; k < 2; ++k) {
      const double sum = r[k] + double(x.position()[k]);
      if (!detail::exact_sum(r[k], double(x.position()[k]), sum) || double(U(sum)) != sum) return false;
    }
  }
  return true;
}

/// How much the exact images' signed distance may move when both shapes of a pair are placed by
/// the same x instead of none: R(q) scales positions by |q| (1 up to one rounding of T) but not
/// radii or extents, so a distance changes by at most ||q| - 1| times the pair's largest
/// coordinate, twice.
template <Scalar T>
double scaling_band(const Shape<T>& a, const Shape<T>& b, const Transform<T>& x) {
  const double q = widen(x.rotation()).norm();
  const double s = std::max(collide::detail::scale_of(bounds(a)), collide::detail::scale_of(bounds(b)));
  return 2 * std::fabs(q - 1) * 4 * s + 4 * 0x1p-53 * s;
}

/// The world shape x(s) built by the factories in T (the values rounded to T), or nothing when a
/// factory refuses the rounded values.
template <Scalar T>
std::optional<Shape<T>> world_shape(const Shape<T>& s, const Transform<T>& x) {
  using V = Vec2<T>;
  const auto to_t = [](const Vec2c& v) { return V(v.template cast<T>()); };
  const auto prim = [&](const auto& c, const collide::detail::Pose& pose) -> std::optional<Primitive<T>> {
    using S = std::remove_cvref_t<decltype(c)>;
    const auto map = [&](const V& p) { return to_t(pose.apply(widen(p))); };
    if constexpr (std::is_same_v<S, Circle<T>>) {
      auto e = Circle<T>::make(map(c.center()), c.radius());
      return e ? std::optional<Primitive<T>>(*e) : std::nullopt;
    } else if constexpr (std::is_same_v<S, Capsule<T>>) {
      auto e = Capsule<T>::make(map(c.a()), map(c.b()), c.radius());
      return e ? std::optional<Primitive<T>>(*e) : std::nullopt;
    } else if constexpr (std::is_same_v<S, Obb<T>>) {
      auto e = Obb<T>::make_with_axis(map(c.center()), c.half_extents(), to_t(pose.rotate(widen(c.axis()))));
      return e ? std::optional<Primitive<T>>(*e) : std::nullopt;
    } else if constexpr (std::is_same_v<S, Aabb<T>>) {
      const V p = map(c.min()), r = map(c.max());
      if (pose.q.x() == 0 || pose.q.y() == 0) {
        auto e = Aabb<T>::make(p.cwiseMin(r), p.cwiseMax(r));
        return e ? std::optional<Primitive<T>>(*e) : std::nullopt;
      }
      const Vec2c centre = (widen(c.min()) + widen(c.max())) * 0.5, half = (widen(c.max()) - widen(c.min())) * 0.5;
      auto e = Obb<T>::make_with_axis(to_t(pose.apply(centre)), to_t(half), to_t(pose.q));
      return e ? std::optional<Primitive<T>>(*e) : std::nullopt;
    } else {
      std::vector<V> pts;
      for (const V& p : c.vertices()) pts.push_back(map(p));
      auto e = ConvexPolygon<T>::make(pts);
      if (!e) e = ConvexPolygon<T>::make_hull(pts);
      return e ? std::optional<Primitive<T>>(*e) : std::nullopt;
    }
  };
  const collide::detail::Pose body = x.pose();
  if (const auto* c = std::get_if<Compound<T>>(&s)) {
    std::vector<Primitive<T>> kids;
    for (std::size_t i = 0; i < c->children().size(); ++i) {
      const collide::detail::Pose pose = collide::detail::compose(body, c->child_transform(i).pose());
      const auto k = std::visit([&](const auto& ch) { return prim(ch, pose); }, c->children()[i]);
      if (!k) return std::nullopt;
      kids.push_back(*k);
    }
    return Shape<T>(Compound<T>(std::move(kids)));
  }
  const auto k = std::visit(
      [&](const auto& ch) -> std::optional<Primitive<T>> {
        if constexpr (std::is_same_v<std::remove_cvref_t<decltype(ch)>, Compound<T>>) {
          return std::nullopt;  // handled above
        } else {
          return prim(ch, body);
        }
      },
      s);
  if (!k) return std::nullopt;
  return to_shape(*k);
}

/// A pair law's body, run with the exact images of both placed shapes (the relation recorded).
template <Scalar T, class F>
Verdict judged_pair(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb, F&& body) {
  return judged(pair_context(a, xa, b, xb), [&](Judgement& j) {
    const oracle::Placed pa = oracle::placed(a, xa), pb = oracle::placed(b, xb);
    j.v.relation = placed_relation(pa, pb);
    body(j, pa, pb);
  });
}

template <Scalar T>
bool primitives_only(const Shape<T>& a, const Shape<T>& b) {
  return !detail::is_compound(a) && !detail::is_compound(b);
}

/// The bound of a rounded output of magnitude m (a depth or a distance): 4 error units plus its
/// rounding to T.
template <Scalar T>
double output_bound(double unit, double m) {
  return 4 * unit + 4 * detail::eps<T>() * m + 2 * double(std::numeric_limits<T>::denorm_min());
}

}  // namespace

template <Scalar T>
Verdict placed_agreement(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb) {
  return judged_pair(a, xa, b, xb, [&](Judgement& j, const oracle::Placed& pa, const oracle::Placed& pb) {
    const bool got = overlaps(a, xa, b, xb);
    const bool rev = overlaps(b, xb, a, xa);
    j.note("overlaps " + yes(got));
    j.require(got == rev, "overlaps(b, xb, a, xa) == overlaps(a, xa, b, xb)", yes(rev) + " against " + yes(got));
    if (xa.is_identity() && xb.is_identity())
      j.require(got == overlaps(a, b), "the world-space answer for identities", yes(got));
    j.require(bool(contact(a, xa, b, xb)) == got, "contact present exactly when overlaps", yes(!got));
    j.require((distance(a, xa, b, xb) == T(0)) == got, "distance 0 exactly when overlaps", yes(!got));
    const bool exact = oracle::overlaps(pa, pb);
    if (got != exact) {
      j.v.disagreement = true;
      const double band = overlap_tolerance(a, xa, b, xb);
      j.note("differs from the exact images within band " + num(band));
      // Judged exactly, never counted: the oracle on the images the library computed.
      const bool computed = oracle::overlaps(detail::computed_geometry(a, xa), detail::computed_geometry(b, xb));
      j.require(got == computed, "overlaps " + yes(computed) + " (the oracle on the images the library computed)",
                yes(got));
      j.require(oracle::within_band(pa, pb, band),
                "the oracle's answer " + yes(exact) + " outside the band " + num(band),
                yes(got) + ", signed distance ~" + num(oracle::approx_signed_distance(pa, pb)));
    }
  });
}

template <Scalar T>
Verdict placed_outputs(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb) {
  return judged_pair(a, xa, b, xb, [&](Judgement& j, const oracle::Placed& pa, const oracle::Placed& pb) {
    const bool primitives = primitives_only(a, b);
    const double unit = rounding_tolerance(a, xa, b, xb);
    // Contact: unit normal, depth against the exact images' depth, normal separating, points midway.
    if (const auto c = contact(a, xa, b, xb)) {
      const double depth = c->depth, bound = output_bound<T>(unit, depth);
      const Vec2c n = widen(c->normal);
      j.note("contact depth " + num(depth) + " normal " + vec(c->normal));
      j.require(std::fabs(n.norm() - 1) <= 8 * detail::eps<T>(), "a unit normal", vec(c->normal));
      j.require(depth >= 0, "depth >= 0", num(depth));
      if (primitives) {
        j.require(oracle::compare_depth(pa, pb, depth + bound) <= 0, "exact depth <= depth + " + num(bound),
                  "exact depth ~" + num(-oracle::approx_signed_distance(pa, pb)));
        j.require(depth - bound <= 0 || oracle::compare_depth(pa, pb, depth - bound) >= 0,
                  "exact depth >= depth - " + num(bound),
                  "exact depth ~" + num(-oracle::approx_signed_distance(pa, pb)));
        const Vec2<double> away = -n * (depth + 2 * bound);
        j.require(oracle::separates(pa, pb, away), "a moved by -normal (depth + 2 bounds) apart", "still overlapping");
      }
      for (int i = 0; i < c->count; ++i) {
        const oracle::Placed pt = point_input(widen(c->points[std::size_t(i)]));
        const double reach =
            depth + bound + 4 * detail::eps<T>() * widen(c->points[std::size_t(i)]).cwiseAbs().maxCoeff();
        j.require(oracle::compare_distance(pa, pt, reach) <= 0 && oracle::compare_distance(pb, pt, reach) <= 0,
                  "contact point within depth + bound of both shapes", vec(c->points[std::size_t(i)]));
      }
    }
    // Distance against the exact gap.
    const double d = distance(a, xa, b, xb);
    if (d > 0) {
      const double bound = output_bound<T>(unit, d);
      j.note("distance " + num(d));
      j.require(oracle::compare_distance(pa, pb, d - bound) >= 0 && oracle::compare_distance(pa, pb, d + bound) <= 0,
                "distance within " + num(bound) + " of the exact gap",
                num(d) + ", exact ~" + num(oracle::approx_signed_distance(pa, pb)));
    }
    // Closest points, both orders: distance()'s distance to the bit, the points on the exact images.
    for (const bool swap : {false, true}) {
      const ClosestPoints<T> w = swap ? closest_points(b, xb, a, xa) : closest_points(a, xa, b, xb);
      const std::string order = swap ? "closest_points(b, xb, a, xa): " : "closest_points(a, xa, b, xb): ";
      detail::judge_witness<T>(
          [&](bool holds, const std::string& e, const std::string& g) { j.require(holds, order + e, g); },
          swap ? pb : pa, swap ? pa : pb, w, swap ? distance(b, xb, a, xa) : distance(a, xa, b, xb),
          detail::documented_witness_bound(unit, bounds(a, xa), bounds(b, xb)));
    }
  });
}

template <Scalar T>
Verdict placed_resolution(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb) {
  return judged_pair(a, xa, b, xb, [&](Judgement& j, const oracle::Placed& pa, const oracle::Placed& pb) {
    const bool got = overlaps(a, xa, b, xb);
    const Vec2<T> push = resolve(a, xa, b, xb);
    j.note("push " + vec(push));
    if (!got) {
      j.require(push == Vec2<T>::Zero(), "zero push when overlaps() is false", vec(push));
      return;
    }
    const Expected<Transform<T>> moved = xa.moved(push);
    if (!moved) {
      j.require(moved.error().code() == Error::OutOfRange, "a moved transform, or OutOfRange", moved.error().what());
      j.require(oracle::separates(pa, pb, Vec2<double>(push.template cast<double>())), "exact a + push apart from b",
                "still overlapping");
      return;
    }
    const oracle::Placed after = oracle::placed(a, *moved);
    j.require(!oracle::overlaps(after, pb), "a with its moved transform apart from b",
              "still overlapping, signed distance ~" + num(oracle::approx_signed_distance(after, pb)));
    if (!primitives_only(a, b)) return;
    // The gap left and the push's length, against the documented margin.
    const double len = push.template cast<double>().norm();
    const double margin = documented_margin(a, xa, b, xb, len, push_direction(push));
    const double slack = 4 * rounding_tolerance(a, xa, b, xb) + 4 * 0x1p-53 * len;
    j.require(oracle::compare_distance(after, pb, 2 * margin + 2 * slack) <= 0,
              "gap left <= 2 (margin " + num(margin) + " + slack " + num(slack) + ")",
              "gap ~" + num(oracle::approx_signed_distance(after, pb)));
    const double lower = len - margin - slack;
    j.require(lower <= 0 || oracle::compare_depth(pa, pb, lower) >= 0, "|push| <= exact depth + margin + slack",
              "|push| " + num(len) + ", exact depth ~" + num(-oracle::approx_signed_distance(pa, pb)));
  });
}

template <Scalar T>
Verdict placed_shape(const Shape<T>& s, const Transform<T>& x, const Vec2<T>& p, const Ray<T>& ray, T max_t) {
  return judged(
      "s = " + placed_text(s, x) + "; p = " + vec(p) + "; ray " + vec(ray.origin) + " + t " + vec(ray.direction) +
          ", max_t " + num(max_t),
      [&](Judgement& j) {
        const oracle::Placed ps = oracle::placed(s, x);
        const double tol = transform_tolerance(s, x);
        // Bounds contain the exact image.
        const Aabb<T> box = bounds(s, x);
        j.require(oracle::inside_box(ps, box), "bounds(s, x) containing the exact image",
                  vec(box.min()) + " .. " + vec(box.max()));
        // Containment, exact outside the band.
        const bool in = contains(s, x, p);
        const T sd = signed_distance(s, x, p);
        if (!p.allFinite()) {
          j.require(!in, "no NaN or infinite point contained", "contained");
          const bool nan = std::isnan(p.x()) || std::isnan(p.y());
          j.require(nan ? std::isnan(sd) : sd == std::numeric_limits<T>::infinity(),
                    nan ? "signed distance NaN for a NaN point" : "signed distance +infinity for an infinite point",
                    num(sd));
          return;
        }
        // Signed distance: contains(s, x, p)'s sign to the bit, the exact image's value within its bound.
        j.require((sd <= T(0)) == in, "signed_distance <= 0 exactly when contains (" + yes(in) + ")", num(sd));
        detail::judge_signed_magnitude(
            [&](bool holds, const std::string& e, const std::string& g) { j.require(holds, e, g); },
            detail::exact_parts(s, x), widen(p), double(sd), detail::documented_point_bound(bounds(s, x), p, tol),
            double(std::numeric_limits<T>::max()));
        const bool exact_in = oracle::contains(ps, p);
        j.v.relation = in ? Relation::Contained : Relation::Separated;
        if (in != exact_in) {
          j.v.disagreement = true;
          const bool computed = oracle::contains(detail::computed_geometry(s, x), widen(p));
          j.require(in == computed, "contains " + yes(computed) + " (the oracle on the image the library computed)",
                    yes(in));
          j.require(oracle::within_band(ps, point_input(widen(p)), tol),
                    "contains " + yes(exact_in) + " outside the band " + num(tol), yes(in));
        }
        if (x.is_identity()) {
          const Aabb<T> world = bounds(s);
          const T world_sd = signed_distance(s, p);
          j.require(in == contains(s, p) && box.min() == world.min() && box.max() == world.max() &&
                        (sd == world_sd || (std::isnan(sd) && std::isnan(world_sd))),
                    "the world-space answers for the identity", "a difference");
        }
        // Ray cast: a hit lies on the image within the bound; a miss passes no deeper.
        const double delta = raycast_tolerance(s, x, Ray<T>{ray.origin, ray.direction});
        const auto hit = raycast(s, x, Ray<T>{ray.origin, ray.direction}, max_t);
        const Vec2c o = widen(ray.origin), d = widen(ray.direction);
        if (hit) {
          const double t = hit->t;
          j.note("hit t " + num(t));
          j.require(t >= 0 && t <= double(max_t), "0 <= t <= max_t", num(t));
          const Vec2c q = widen(hit->point);
          j.require(oracle::compare_distance(ps, point_input(q), delta) <= 0,
                    "hit point within " + num(delta) + " of the shape", vec(hit->point));
          const double off = (o + d * t - q).norm();
          j.require(off <= delta +
                               (4 * detail::eps<T>() * t + double(std::numeric_limits<T>::denorm_min())) * d.norm() +
                               4 * detail::eps<T>() * q.norm(),
                    "hit point on the ray", "off by " + num(off));
        } else if (d.allFinite() && (d.x() != 0 || d.y() != 0)) {
          const Vec2c end = o + d * double(max_t);
          if (end.allFinite() && end.cwiseAbs().maxCoeff() < 0x1p120)
            j.require(!oracle::passes_deeper(ps, o, end, delta),
                      "a miss only where no point of the segment is deeper than " + num(delta) + " in the shape",
                      "no hit, the segment passes deeper");
        }
      });
}

template <Scalar T>
Verdict placed_covariance(const Shape<T>& a, const Shape<T>& b, const Transform<T>& x) {
  return judged_pair(a, x, b, x, [&](Judgement& j, const oracle::Placed& pa, const oracle::Placed& pb) {
    const bool exact = exact_image<double>(a, x) && exact_image<double>(b, x);
    const bool world = overlaps(a, b), moved = overlaps(a, x, b, x);
    j.note(std::string(exact ? "exact" : "rounded") + " placement; overlaps " + yes(world) + " -> " + yes(moved));
    if (exact) {
      j.require(world == moved, "the world answer, unchanged by an exact placement", yes(moved));
      const Vec2<T> p(T(0.25), T(-0.5));
      const Vec2c pw = x.apply(widen(p));
      // The point's image must be exact too (in T), not only the shapes'.
      if (exact_image<T>(Shape<T>(Circle<T>(p, T(0))), x))
        j.require(contains(a, p) == contains(a, x, pw.template cast<T>()), "contains unchanged by an exact placement",
                  "a difference");
    } else if (world != moved) {
      j.v.disagreement = true;
      const bool computed = oracle::overlaps(detail::computed_geometry(a, x), detail::computed_geometry(b, x));
      j.require(moved == computed, "overlaps " + yes(computed) + " (the oracle on the images the library computed)",
                yes(moved));
      const double band = overlap_tolerance(a, x, b, x) + scaling_band(a, b, x);
      j.require(oracle::within_band(pa, pb, band), "the world answer outside the band " + num(band), yes(moved));
    }
    // Rounded outputs keep their values within both bounds and the scaling.
    const double unit = rounding_tolerance(a, b) + rounding_tolerance(a, x, b, x) + scaling_band(a, b, x);
    const T dw = distance(a, b), dm = distance(a, x, b, x);
    j.require(std::fabs(double(dw) - double(dm)) <= output_bound<T>(unit, std::max(dw, dm)),
              "distance kept within " + num(output_bound<T>(unit, std::max(dw, dm))), num(dw) + " -> " + num(dm));
    const auto cw = contact(a, b), cm = contact(a, x, b, x);
    if (cw && cm && !detail::is_compound(a) && !detail::is_compound(b)) {
      const double bound = output_bound<T>(unit, std::max(cw->depth, cm->depth));
      j.require(std::fabs(double(cw->depth) - double(cm->depth)) <= bound, "depth kept within " + num(bound),
                num(cw->depth) + " -> " + num(cm->depth));
    }
  });
}

template <Scalar T>
Verdict placed_image(const Shape<T>& s, const Transform<T>& x, const Shape<T>& other) {
  return judged("s = " + placed_text(s, x) + "; other = " + describe(other), [&](Judgement& j) {
    const oracle::Placed ps = oracle::placed(s, x);
    j.v.relation = placed_relation(ps, oracle::Placed(oracle::as_exact_input(other)));
    const std::optional<Shape<T>> w = world_shape(s, x);
    if (!w) {
      j.note("the factories refuse the image rounded to T");
      return;
    }
    const Transform<T> id;
    const bool exact = exact_image<T>(s, x);
    const bool placed = overlaps(s, x, other, id), built = overlaps(*w, other);
    j.note(std::string(exact ? "exact" : "rounded") + " image; overlaps " + yes(placed) + ", built " + yes(built));
    const auto cp = contact(s, x, other, id), cb = contact(*w, other);
    const T dp = distance(s, x, other, id), db = distance(*w, other);
    if (exact) {
      j.require(placed == built, "the answer for the world shape built by the factory", yes(placed));
      j.require(dp == db, "the distance of the built shape", num(dp) + " against " + num(db));
      // A turned AABB's image is an OBB (its ids keep the box's numbering), whose contact is
      // computed by another pair's code than the built AABB's: equal within the bounds only.
      const bool turned_box = std::holds_alternative<Aabb<T>>(s) && x.rotation() != Vec2<T>(1, 0);
      if (cp && cb && !turned_box) {
        j.require(cp->depth == cb->depth && cp->normal == cb->normal, "the contact of the built shape",
                  num(cp->depth) + " " + vec(cp->normal) + " against " + num(cb->depth) + " " + vec(cb->normal));
      } else if (cp && cb) {
        const double bound = output_bound<T>(rounding_tolerance(s, x, other, id) + rounding_tolerance(*w, other),
                                             std::max(cp->depth, cb->depth));
        j.require(std::fabs(double(cp->depth) - double(cb->depth)) <= bound,
                  "the built shape's depth within " + num(bound), num(cp->depth) + " against " + num(cb->depth));
      }
      return;
    }
    // The built shape differs from the exact image by T's rounding of its values.
    const double sw = collide::detail::scale_of(bounds(*w));
    const double band =
        transform_tolerance(s, x) + 8 * detail::eps<T>() * (sw + 2 * collide::detail::scale_of(bounds(s)));
    if (placed != built) {
      j.v.disagreement = true;
      j.require(oracle::within_band(ps, oracle::as_exact_input(other), band),
                "the built shape's answer outside the band " + num(band), yes(placed));
    }
    const double unit = rounding_tolerance(s, x, other, id) + rounding_tolerance(*w, other) + band;
    j.require(std::fabs(double(dp) - double(db)) <= output_bound<T>(unit, std::max(dp, db)),
              "the built shape's distance within " + num(output_bound<T>(unit, std::max(dp, db))),
              num(dp) + " against " + num(db));
  });
}

template <Scalar T>
Verdict transform_rejection(std::span<const T> values) {
  const auto at = [&](std::size_t i) { return i < values.size() ? values[i] : T(0); };
  std::ostringstream text;  // a stream: g++ 12 warns falsely (-Wrestrict) on strings grown in a loop
  text << "values";
  for (std::size_t i = 0; i < 5; ++i) text << ' ' << num(double(at(i)));
  return judged(text.str(), [&](Judgement& j) {
    const Vec2<T> p(at(0), at(1)), r(at(3), at(4));
    // The first bad value in argument order names the error.
    const auto expect_values = [&](std::initializer_list<T> vals) -> std::optional<std::pair<Error, long>> {
      long i = 0;
      for (T v : vals) {
        if (!std::isfinite(v)) return std::pair{Error::NonFinite, i};
        if (std::fabs(v) > max_magnitude<T>()) return std::pair{Error::OutOfRange, i};
        ++i;
      }
      return std::nullopt;
    };
    const auto check = [&](const Expected<Transform<T>>& e, std::optional<std::pair<Error, long>> want,
                           const char* what) {
      if (want) {
        j.require(!e && e.error().code() == want->first && e.error().index() == want->second,
                  std::string(what) + ": " + std::string(name(want->first)) + " at " + std::to_string(want->second),
                  e ? "a transform" : e.error().what());
      } else {
        j.require(bool(e), std::string(what) + ": a transform", e ? "" : e.error().what());
      }
    };
    const auto bad_angle = expect_values({at(0), at(1), at(2)});
    const Expected<Transform<T>> ea = Transform<T>::make(p, at(2));
    check(ea, bad_angle, "make");
    if (ea) {
      const double q2 = widen(ea->rotation()).squaredNorm();
      j.require(std::fabs(q2 - 1) <= 4 * detail::eps<T>() && ea->position() == p, "|q|^2 within 4 eps of 1, p kept",
                "q " + vec(ea->rotation()));
    }
    auto bad_rot = expect_values({at(0), at(1), at(3), at(4)});
    if (!bad_rot && r.x() == T(0) && r.y() == T(0)) bad_rot = std::pair{Error::ZeroRotation, -1L};
    const Expected<Transform<T>> er = Transform<T>::make_with_rotation(p, r);
    check(er, bad_rot, "make_with_rotation");
    if (er) {
      const Vec2c rc = widen(r);
      const Vec2c q = widen(er->rotation());
      if (std::fabs(rc.squaredNorm() - 1) <= 4 * detail::eps<T>()) {
        j.require(er->rotation() == r, "a unit rotation kept bit for bit", vec(er->rotation()));
      } else {
        int exp2 = 0;  // scaled by a power of two first (exact): a subnormal r keeps its direction
        static_cast<void>(std::frexp(rc.cwiseAbs().maxCoeff(), &exp2));
        const Vec2c rs(std::ldexp(rc.x(), -exp2), std::ldexp(rc.y(), -exp2));
        const Vec2c unit = rs / std::hypot(rs.x(), rs.y());
        j.require((q - unit).cwiseAbs().maxCoeff() <= 2 * detail::eps<T>() &&
                      std::fabs(q.squaredNorm() - 1) <= 4 * detail::eps<T>(),
                  "the rotation normalised: " + vec(unit), vec(er->rotation()));
      }
      // Moving it: a named error when the position leaves the range, else the rotation kept.
      const Expected<Transform<T>> m = er->moved(p);
      const Vec2<T> sum = p + p;
      const auto bad_move = expect_values({sum.x(), sum.y()});
      check(m, bad_move, "moved");
      if (m) j.require(m->rotation() == er->rotation(), "moved keeps the rotation", vec(m->rotation()));
    }
    j.v.relation = Relation::Separated;
  });
}

#define COLLIDE_TRANSFORM_LAWS_INSTANTIATE(T)                                                                        \
  template Verdict placed_agreement<T>(const Shape<T>&, const Transform<T>&, const Shape<T>&, const Transform<T>&);  \
  template Verdict placed_outputs<T>(const Shape<T>&, const Transform<T>&, const Shape<T>&, const Transform<T>&);    \
  template Verdict placed_resolution<T>(const Shape<T>&, const Transform<T>&, const Shape<T>&, const Transform<T>&); \
  template Verdict placed_shape<T>(const Shape<T>&, const Transform<T>&, const Vec2<T>&, const Ray<T>&, T);          \
  template Verdict placed_covariance<T>(const Shape<T>&, const Shape<T>&, const Transform<T>&);                      \
  template Verdict placed_image<T>(const Shape<T>&, const Transform<T>&, const Shape<T>&);                           \
  template Verdict transform_rejection<T>(std::span<const T>);

COLLIDE_TRANSFORM_LAWS_INSTANTIATE(float)
COLLIDE_TRANSFORM_LAWS_INSTANTIATE(double)

}  // namespace collide::laws
