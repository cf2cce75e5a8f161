// The laws on a pair of shapes: agreement, symmetry, translation, rotation, resolution,
// hierarchy, representation, contact, distance, touching.

#include "support.hpp"

#include <cmath>
#include <limits>
#include <optional>

namespace collide::laws {

using detail::describe;
using detail::documented_margin;
using detail::farther_than;
using detail::num;
using detail::push_direction;
using detail::vec;
using detail::yes;

namespace {

/// Fills a failed (or disagreeing) verdict.
void fail(Verdict& v, std::string expected, std::string got, const std::string& context) {
  v.ok = false;
  v.expected = std::move(expected);
  v.got = std::move(got);
  v.account = "expected " + v.expected + "; got " + v.got + "; " + context;
}

template <Scalar T>
std::string pair_text(const Shape<T>& a, const Shape<T>& b) {
  return "a = " + describe(a) + "; b = " + describe(b);
}

/// Runs a law body, turning an exception from the oracle or the library into a failed verdict
/// (a law must report, not throw).
template <class F>
Verdict guarded(F&& body) {
  Verdict v;
  try {
    body(v);
  } catch (const std::exception& e) {
    v.ok = false;
    v.expected = "no exception";
    v.got = std::string("exception: ") + e.what();
    v.account = "expected no exception; got " + v.got + (v.account.empty() ? "" : "; " + v.account);
  }
  return v;
}

/// A difference between two library answers for the same exact question, allowed only inside the
/// band of both pairs: records a disagreement, or fails.
template <Scalar T>
void allow_in_band(Verdict& v, const Shape<T>& a, const Shape<T>& b, double band, const std::string& what) {
  v.disagreement = true;
  const bool in_band = oracle::within_band(a, b, band);
  if (in_band) {
    v.account += "; " + what + " (within band " + num(band) + ": allowed)";
  } else {
    fail(v, "identical answers outside the band " + num(band), what,
         "signed distance ~" + num(oracle::approx_signed_distance(a, b)) + "; " + pair_text(a, b));
  }
}

/// Whether the library's overlap answer `got` for (a, b) is the oracle's on the shapes the
/// library computed (computed_geometry(): the exact shapes, or the images of children placed by
/// transforms), as it must be bit for bit; fails v otherwise. This is what makes an answer inside
/// a placement's band a judged case rather than a counted one.
template <Scalar T>
bool agrees_on_computed(Verdict& v, bool got, const Shape<T>& a, const Shape<T>& b, const std::string& which) {
  const bool computed = oracle::overlaps(detail::computed_geometry(a), detail::computed_geometry(b));
  if (got == computed) return true;
  fail(v, which + " overlaps " + yes(computed) + " (the oracle on the shapes the library computed)",
       "overlaps " + yes(got), pair_text(a, b));
  return false;
}

/// An overlap answer `got` differing from the oracle's on the exact shapes, where a compound's
/// children placed by transforms round (overlap_tolerance() > 0): judged on the library's own
/// images, then the exact pair within the placement's band. A disagreement, or a failure.
template <Scalar T>
void judge_placement_rounding(Verdict& v, bool got, const Shape<T>& a, const Shape<T>& b, const std::string& what) {
  v.disagreement = true;
  if (!agrees_on_computed(v, got, a, b, "the pair")) return;
  allow_in_band(v, a, b, overlap_tolerance(a, b), what);
}

}  // namespace

// ---------------------------------------------------------------------------------------------

template <Scalar T>
Verdict agreement(const Shape<T>& a, const Shape<T>& b) {
  return guarded([&](Verdict& v) {
    v.relation = relation(a, b);
    const bool got = overlaps(a, b);
    const bool exact = oracle::overlaps(a, b);
    v.account = "overlaps " + yes(got) + ", exact " + yes(exact);
    if (got == exact) return;
    // Stored shapes are decided exactly (overlap_tolerance 0: any difference fails); a compound
    // whose children are placed by transforms may differ within its placement's band.
    if (overlap_tolerance(a, b) > 0) {
      judge_placement_rounding(v, got, a, b, "overlaps " + yes(got) + ", exact " + yes(exact));
      return;
    }
    v.disagreement = true;
    v.expected = "overlaps " + yes(exact);
    v.got = "overlaps " + yes(got);
    v.ok = false;
    v.account = "expected overlaps " + yes(exact) + "; got " + yes(got) + "; signed distance ~" +
                num(oracle::approx_signed_distance(a, b)) + "; " + pair_text(a, b);
  });
}

template <Scalar T>
Verdict symmetry(const Shape<T>& a, const Shape<T>& b) {
  return guarded([&](Verdict& v) {
    v.relation = relation(a, b);
    const bool ab = overlaps(a, b), ba = overlaps(b, a);
    if (ab != ba) {
      fail(v, "overlaps(a, b) == overlaps(b, a)", "overlaps(a, b) " + yes(ab) + ", overlaps(b, a) " + yes(ba),
           pair_text(a, b));
      return;
    }
    const double tol = rounding_tolerance(a, b);
    const auto cab = contact(a, b), cba = contact(b, a);
    if (bool(cab) != ab || bool(cba) != ba) {
      fail(v, "contact exists exactly when overlaps (" + yes(ab) + ")",
           "contact(a, b) " + yes(bool(cab)) + ", contact(b, a) " + yes(bool(cba)), pair_text(a, b));
      return;
    }
    if (cab) {
      const double d1 = cab->depth, d2 = cba->depth;
      const double dtol = tol + 4 * detail::eps<T>() * std::max(d1, d2);
      if (std::fabs(d1 - d2) > dtol) {
        fail(v, "equal depths (within " + num(dtol) + ")", "depth(a, b) " + num(d1) + ", depth(b, a) " + num(d2),
             pair_text(a, b));
        return;
      }
      const Vec2c n1 = cab->normal.template cast<double>(), n2 = cba->normal.template cast<double>();
      if ((n1 + n2).cwiseAbs().maxCoeff() > 8 * detail::eps<T>()) {
        // Not opposite: allowed only when the depth is attained along both directions (a tie
        // between faces). Check that -n(b, a) also separates a from b by that depth.
        // Compounds: the deepest child pair's tie; other children may block that direction (the
        // equal depth, checked above, is the law there).
        const Vec2c push = n2 * (std::max(d1, d2) + 4 * tol + 4 * detail::eps<T>() * (1 + d1));
        if (!detail::is_compound(a) && !detail::is_compound(b) && !oracle::separates(a, b, push)) {
          fail(v, "opposite normals, or the other order's normal separating by the same depth",
               "normal(a, b) " + vec(cab->normal) + ", normal(b, a) " + vec(cba->normal) + ", depth " + num(d1),
               pair_text(a, b));
          return;
        }
        v.account += "; normals differ on a tie: " + vec(cab->normal) + " vs " + vec(cba->normal);
      }
    }
    const double g1 = distance(a, b), g2 = distance(b, a);
    const double gtol = tol + 4 * detail::eps<T>() * std::max(g1, g2);
    if (std::fabs(g1 - g2) > gtol) {
      fail(v, "equal distances (within " + num(gtol) + ")", "distance(a, b) " + num(g1) + ", distance(b, a) " + num(g2),
           pair_text(a, b));
      return;
    }
    v.account = "overlaps " + yes(ab) + " both ways" + v.account;
  });
}

template <Scalar T>
Verdict translation(const Shape<T>& a, const Shape<T>& b, const Vec2<T>& t) {
  return guarded([&](Verdict& v) {
    v.relation = relation(a, b);
    const Expected<Shape<T>> ma = translated(a, t), mb = translated(b, t);
    if (!ma || !mb) {
      const ShapeError& e = !ma ? ma.error() : mb.error();
      const Error code = e.code();
      // Moving can leave the range or (polygons rounded to T) collapse a sliver: named errors.
      const bool named = code == Error::OutOfRange || code == Error::Collinear || code == Error::TooFewVertices ||
                         code == Error::NonFinite;
      v.account = std::string("move rejected: ") + e.what();
      if (!named) fail(v, "a named range or collapse error", e.what(), pair_text(a, b) + "; t = " + vec(t));
      return;
    }
    const Shape<T>& a2 = ma.value();
    const Shape<T>& b2 = mb.value();
    const bool before = overlaps(a, b), after = overlaps(a2, b2);
    const bool exact = detail::exact_move(a, a2, t) && detail::exact_move(b, b2, t);
    v.account = std::string(exact ? "exact" : "rounded") + " move by " + vec(t) + ": overlaps " + yes(before) + " -> " +
                yes(after);
    if (exact) {
      if (before != after)
        fail(v, "the same answer under an exact move", "overlaps " + yes(before) + " -> " + yes(after),
             pair_text(a, b) + "; t = " + vec(t));
      return;
    }
    // A rounded move: the moved pair is a different exact question. Judged exactly, never
    // counted: the move must be what translated() promises, and both answers the oracle's on the
    // shapes the library computed (the stored shapes, or the images of children placed by
    // transforms); an answer that changes is then explained by the rounding, which must also keep
    // the unmoved pair within its band.
    for (const auto& [s, m] : {std::pair{&a, &a2}, std::pair{&b, &b2}}) {
      if (!detail::moved_as_promised(*s, *m, t)) {
        fail(v, "each stored position plus t rounded once to T, every other value kept", "moved to " + describe(*m),
             "from " + describe(*s) + "; t = " + vec(t));
        return;
      }
    }
    if (!agrees_on_computed(v, before, a, b, "unmoved pair") || !agrees_on_computed(v, after, a2, b2, "moved pair"))
      return;
    const bool exact_after = oracle::overlaps(a2, b2);
    if (after != exact_after) {
      if (overlap_tolerance(a2, b2) > 0) {
        judge_placement_rounding(v, after, a2, b2, "moved pair overlaps " + yes(after) + ", exact " + yes(exact_after));
        return;
      }
      v.disagreement = true;
      fail(v, "moved pair overlaps " + yes(exact_after), "overlaps " + yes(after),
           "moved a = " + describe(a2) + "; moved b = " + describe(b2));
      return;
    }
    if (before != after) {
      const double scale = std::max(::collide::detail::scale_of(bounds(a2)), ::collide::detail::scale_of(bounds(b2)));
      const double band = 4 * detail::eps<T>() * scale + overlap_tolerance(a, b) + overlap_tolerance(a2, b2);
      allow_in_band(v, a, b, band, "answer changed under a rounded move");
    }
  });
}

template <Scalar T>
Verdict rotation(const Shape<T>& a, const Shape<T>& b, int quarter_turns, bool mirror) {
  return guarded([&](Verdict& v) {
    const Shape<T> a0 = detail::turned(a, 0, false), b0 = detail::turned(b, 0, false);
    const Shape<T> a1 = detail::turned(a, quarter_turns, mirror), b1 = detail::turned(b, quarter_turns, mirror);
    v.relation = relation(a0, b0);
    const bool before = overlaps(a0, b0), after = overlaps(a1, b1);
    v.account = std::to_string(quarter_turns) + " quarter turns" + (mirror ? " + mirror" : "") + ": overlaps " +
                yes(before) + " -> " + yes(after);
    if (before == after) return;
    fail(v, "the same answer under an exact rotation", "overlaps " + yes(before) + " -> " + yes(after),
         pair_text(a0, b0));
  });
}

template <Scalar T>
Verdict resolution(const Shape<T>& a, const Shape<T>& b) {
  return guarded([&](Verdict& v) {
    v.relation = relation(a, b);
    const bool got = overlaps(a, b);
    const Vec2<T> push = resolve(a, b);
    if (!got) {
      v.account = "no overlap reported, push " + vec(push);
      if (push != Vec2<T>::Zero()) fail(v, "zero push when overlaps() is false", "push " + vec(push), pair_text(a, b));
      // An exact overlap the library missed is allowed only within the band (as in law agreement).
      if (oracle::overlaps(a, b)) {
        v.disagreement = true;
        if (!agrees_on_computed(v, got, a, b, "the pair")) return;
        const double tol = overlap_tolerance(a, b);
        if (!oracle::within_band(a, b, tol))
          fail(v, "overlaps() true (exact overlap beyond the band " + num(tol) + ")", "no overlap, push " + vec(push),
               pair_text(a, b));
      }
      return;
    }
    const Expected<Shape<T>> moved = translated(a, push);
    std::string moved_note;
    if (!moved) {
      // a + push has no representation in T, and translated() names why (OutOfRange beyond
      // max_magnitude; Collinear or TooFewVertices when rounding collapses a polygon that is thin
      // next to the push). The push is then judged on the exact a + push.
      const Error e = moved.error().code();
      if (e != Error::OutOfRange && e != Error::Collinear && e != Error::TooFewVertices) {
        fail(v, "a + push representable, or a named representation limit",
             std::string("translated failed: ") + moved.error().what(), "push " + vec(push) + "; " + pair_text(a, b));
        return;
      }
      if (!oracle::separates(a, b, push)) {
        fail(v, "exact a + push does not overlap b", "still overlapping", "push " + vec(push) + "; " + pair_text(a, b));
        return;
      }
      moved_note =
          std::string("; a + push not representable in T (") + moved.error().what() + "), exact a + push separates";
    } else if (oracle::overlaps(moved.value(), b)) {
      // Judge the shape translated() really produced (rounded to T), against b.
      fail(v, "a + push does not overlap b",
           "still overlapping, signed distance ~" + num(oracle::approx_signed_distance(moved.value(), b)),
           "push " + vec(push) + "; moved a = " + describe(moved.value()) + "; " + pair_text(a, b));
      return;
    }
    const double len = push.template cast<double>().norm();
    v.account = "push " + vec(push) + " (|v| = " + num(len) + ") separates" + moved_note;
    if (detail::is_compound(a) || detail::is_compound(b)) {
      v.account += "; compound: separation only (no exact depth)";
      return;
    }
    // Minimality: |v| <= depth + margin + slack, i.e. depth >= |v| - margin - slack. The slack is
    // the computed depth's own error (4 tolerances, as the contact law allows) and the rounding of
    // |v| here; v itself is rounded toward zero in T, so its rounding needs no allowance.
    // The margin is judged along the push's own direction (resolve() pushes along -normal).
    const double margin = documented_margin(a, b, len, push_direction(push));
    const double slack = 4 * rounding_tolerance(a, b) + 4 * 0x1p-53 * len;
    // The gap left: at most twice margin + slack (the moved coordinates' rounding to T lies
    // within the margin's own term), so a margin grown from the other shape's extent fails.
    if (moved && oracle::compare_distance(moved.value(), b, 2 * (margin + slack)) > 0) {
      fail(v, "gap left <= 2 (resolve_margin " + num(margin) + " + slack " + num(slack) + ")",
           "gap ~" + num(oracle::approx_signed_distance(moved.value(), b)),
           "push " + vec(push) + "; " + pair_text(a, b));
      return;
    }
    const double lower = len - margin - slack;
    if (lower > 0 && oracle::compare_depth(a, b, lower) < 0) {
      fail(v, "|v| <= exact depth + resolve_margin (" + num(margin) + ") + slack (" + num(slack) + ")",
           "|v| = " + num(len) + ", exact depth < " + num(lower) + " (~" + num(-oracle::approx_signed_distance(a, b)) +
               ")",
           "push " + vec(push) + "; " + pair_text(a, b));
    }
  });
}

template <Scalar T>
Verdict hierarchy(const Shape<T>& compound, const Shape<T>& x) {
  return guarded([&](Verdict& v) {
    const auto* c = std::get_if<Compound<T>>(&compound);
    if (c == nullptr) {
      fail(v, "a compound as first argument", describe(compound), "hierarchy law");
      return;
    }
    v.relation = relation(compound, x);
    const bool whole = overlaps(compound, x);
    // Each child placed by its child transform, asked through the transformed query.
    const auto children = detail::placed_primitives_of(compound);
    const Transform<T> identity;
    bool any = false;
    for (const auto& child : children) any = any || overlaps(child.shape, child.transform, x, identity);
    v.account = "overlaps " + yes(whole) + ", any child " + yes(any);
    if (whole != any) {
      fail(v, "overlaps(compound, x) == any child overlaps x (" + yes(any) + ")", "overlaps " + yes(whole),
           pair_text(compound, x));
      return;
    }
    // The early-out: boxes compared here by their stored values (not by the library's box test).
    const Aabb<T> bc = c->bounds(), bx = bounds(x);
    const bool boxes_meet = !(bc.max().x() < bx.min().x() || bx.max().x() < bc.min().x() ||
                              bc.max().y() < bx.min().y() || bx.max().y() < bc.min().y());
    v.account += std::string("; boxes ") + (boxes_meet ? "meet" : "miss");
    if (boxes_meet) return;
    for (const auto& child : children) {
      if (overlaps(child.shape, child.transform, x, identity) ||
          oracle::overlaps(oracle::placed(child.shape, child.transform), x)) {
        fail(v, "no child overlaps x when the compound's box misses x's box",
             "child " + describe(child.shape, child.transform) + " overlaps x", pair_text(compound, x));
        return;
      }
    }
  });
}

namespace {

/// The other representations of the same point set (see laws::representation), with their
/// names: one add_forms overload per kind, so that std::visit in other_forms() does not compile
/// for a kind without one.
template <Scalar T>
struct Form {
  std::string name;          ///< which representation
  Shape<T> shape;            ///< its stored values
  Transform<T> transform{};  ///< where it is placed (a compound's only child: its transform)
};
template <Scalar T>
struct Forms : std::vector<Form<T>> {
  void emplace_back(std::string n, Shape<T> s, const Transform<T>& x = Transform<T>()) {
    this->push_back(Form<T>{std::move(n), std::move(s), x});
  }
};

template <Scalar T>
void add_forms(const Aabb<T>& box, Forms<T>& out, std::string& skipped) {
  const Vec2<T> lo = box.min(), hi = box.max();
  if (lo.x() < hi.x() && lo.y() < hi.y()) {
    const std::vector<Vec2<T>> v = {lo, Vec2<T>(hi.x(), lo.y()), hi, Vec2<T>(lo.x(), hi.y())};
    out.emplace_back("polygon", ConvexPolygon<T>::make(std::span<const Vec2<T>>(v)).value());
  } else {
    skipped += " polygon (degenerate box)";
  }
  const Vec2<T> c = (lo + hi) / T(2), h = (hi - lo) / T(2);
  const bool exact = c - h == lo && c + h == hi && detail::exact_sum(double(c.x()), double(h.x()), double(hi.x())) &&
                     detail::exact_sum(double(c.y()), double(h.y()), double(hi.y())) &&
                     detail::exact_sum(double(c.x()), -double(h.x()), double(lo.x())) &&
                     detail::exact_sum(double(c.y()), -double(h.y()), double(lo.y()));
  const auto obb = Obb<T>::make_with_axis(c, h, Vec2<T>(1, 0));
  if (exact && obb && obb.value().axis() == Vec2<T>(1, 0)) {
    out.emplace_back("obb", obb.value());
  } else {
    skipped += " obb (centre and half extents not exact)";
  }
}

template <Scalar T>
void add_forms(const Circle<T>& circle, Forms<T>& out, std::string&) {
  out.emplace_back("capsule", Capsule<T>(circle.center(), circle.center(), circle.radius()));
}

template <Scalar T>
void add_forms(const Capsule<T>& cap, Forms<T>& out, std::string& skipped) {
  out.emplace_back("reversed capsule", Capsule<T>(cap.b(), cap.a(), cap.radius()));
  if (cap.a() == cap.b()) {
    out.emplace_back("circle", Circle<T>(cap.a(), cap.radius()));
  } else {
    skipped += " circle (capsule has length)";
  }
}

template <Scalar T>
void add_forms(const ConvexPolygon<T>& poly, Forms<T>& out, std::string& skipped) {
  // Same vertices from another start; and an axis-aligned rectangle as an AABB.
  const auto v = poly.vertices();
  std::vector<Vec2<T>> shifted(v.begin() + 1, v.end());
  shifted.push_back(v[0]);
  out.emplace_back("polygon from vertex 1", ConvexPolygon<T>::make(std::span<const Vec2<T>>(shifted)).value());
  const Aabb<T> box = bounds(poly);
  bool rect = v.size() == 4;
  for (const Vec2<T>& p : v) {
    rect = rect && (p.x() == box.min().x() || p.x() == box.max().x()) &&
           (p.y() == box.min().y() || p.y() == box.max().y());
  }
  if (rect) {
    out.emplace_back("aabb", box);
  } else {
    skipped += " aabb (not an axis-aligned rectangle)";
  }
}

template <Scalar T>
void add_forms(const Compound<T>& comp, Forms<T>& out, std::string&) {
  // Children with their child transforms: reversed, and an only child placed by its transform.
  std::vector<typename Compound<T>::Child> rev;
  for (std::size_t i = comp.children().size(); i-- > 0;) rev.push_back({comp.children()[i], comp.child_transform(i)});
  out.emplace_back("compound reversed", Compound<T>::make_placed(std::move(rev)).value());
  if (comp.children().size() == 1)
    out.emplace_back("its child", to_shape(comp.children().front()), comp.child_transform(0));
}

template <Scalar T>
void add_forms(const Obb<T>& obb, Forms<T>& out, std::string& skipped) {
  const Vec2<T> c = obb.center(), h = obb.half_extents();
  const bool axis_x = obb.axis() == Vec2<T>(1, 0);
  const Vec2<T> lo = c - h, hi = c + h;
  const bool exact = detail::exact_sum(double(c.x()), double(h.x()), double(hi.x())) &&
                     detail::exact_sum(double(c.y()), double(h.y()), double(hi.y())) &&
                     detail::exact_sum(double(c.x()), -double(h.x()), double(lo.x())) &&
                     detail::exact_sum(double(c.y()), -double(h.y()), double(lo.y()));
  if (axis_x && exact) {
    out.emplace_back("aabb", Aabb<T>(lo, hi));
  } else {
    skipped += " aabb (rotated or inexact box)";
  }
  // The same box with its axes exchanged: extents swapped, axis turned a quarter (compared
  // against the box rebuilt from the same input axis, as the rotation law does).
  const Vec2<T> u = obb.axis();
  const auto swapped = Obb<T>::make_with_axis(c, Vec2<T>(h.y(), h.x()), Vec2<T>(-u.y(), u.x()));
  const auto canonical = Obb<T>::make_with_axis(c, h, u);
  if (swapped && canonical &&
      swapped.value().axis() == Vec2<T>(-canonical.value().axis().y(), canonical.value().axis().x()) &&
      canonical.value().axis() == u) {
    out.emplace_back("obb with axes exchanged", swapped.value());
  } else {
    skipped += " obb with axes exchanged (axis not a fixed point of normalisation)";
  }
}

template <Scalar T>
Forms<T> other_forms(const Shape<T>& a, std::string& skipped) {
  Forms<T> out;
  std::visit([&](const auto& s) { add_forms(s, out, skipped); }, a);
  return out;
}

}  // namespace

template <Scalar T>
Verdict representation(const Shape<T>& a, const Shape<T>& x) {
  return guarded([&](Verdict& v) {
    v.relation = relation(a, x);
    std::string skipped;
    const auto forms = other_forms(a, skipped);
    const bool base = overlaps(a, x);
    const bool base_exact = oracle::overlaps(a, x);
    v.account = describe(a) + " overlaps " + yes(base);
    for (const auto& [form, alt, placement] : forms) {
      const bool got = overlaps(alt, placement, x, Transform<T>());
      v.account += "; as " + form + " " + yes(got);
      if (oracle::overlaps(oracle::placed(alt, placement), x) != base_exact) {
        fail(v, "the same point set as " + form + " (oracle agrees)", "oracle differs: " + describe(alt),
             pair_text(a, x));
        return;
      }
      if (got != base) {
        fail(v, "the same answer as " + form, "overlaps " + yes(base) + " vs " + yes(got), pair_text(a, x));
        return;
      }
    }
    if (!skipped.empty()) v.account += "; skipped:" + skipped;
  });
}

template <Scalar T>
Verdict contact_law(const Shape<T>& a, const Shape<T>& b) {
  return guarded([&](Verdict& v) {
    v.relation = relation(a, b);
    const bool got = overlaps(a, b);
    const auto c = contact(a, b);
    if (bool(c) != got) {
      fail(v, "contact exists exactly when overlaps (" + yes(got) + ")", "contact " + yes(bool(c)), pair_text(a, b));
      return;
    }
    if (!c) {
      v.account = "no overlap, no contact";
      return;
    }
    const double tol = rounding_tolerance(a, b);
    const double depth = c->depth;
    const Vec2c n = c->normal.template cast<double>();
    v.account = "contact normal " + vec(c->normal) + " depth " + num(depth) + " points " + std::to_string(c->count);
    if (!(std::fabs(n.norm() - 1) <= 8 * detail::eps<T>())) {
      fail(v, "a unit normal", "|normal| = " + num(n.norm()), pair_text(a, b));
      return;
    }
    if (!(depth >= 0) || !std::isfinite(depth) || c->count < 1 || c->count > 2) {
      fail(v, "finite depth >= 0 and 1 or 2 points", "depth " + num(depth) + ", count " + std::to_string(c->count),
           pair_text(a, b));
      return;
    }
    // The depth is returned in T: near zero that rounds to T's subnormal spacing, which in float
    // (1.4e-45) is far above the double-based tolerance.
    const double bound = 4 * tol + 4 * detail::eps<T>() * depth + double(std::numeric_limits<T>::denorm_min());
    if (!detail::is_compound(a) && !detail::is_compound(b)) {
      const bool too_deep = depth - bound > 0 && oracle::compare_depth(a, b, depth - bound) < 0;
      const bool too_shallow = oracle::compare_depth(a, b, depth + bound) > 0;
      if (too_deep || too_shallow) {
        fail(v, "depth within " + num(bound) + " of the exact depth",
             "depth " + num(depth) + ", exact ~" + num(-oracle::approx_signed_distance(a, b)), pair_text(a, b));
        return;
      }
    } else {
      v.account += "; compound: depth not compared (no exact depth)";
    }
    // Each point lies within depth + bound of both shapes (plus its own rounding to T).
    const double scale = std::max(::collide::detail::scale_of(bounds(a)), ::collide::detail::scale_of(bounds(b)));
    const double point_round = 2 * detail::eps<T>() * scale + double(std::numeric_limits<T>::denorm_min());
    const double reach = depth + bound + point_round;
    for (int i = 0; i < c->count; ++i) {
      const Vec2c p = c->points[std::size_t(i)].template cast<double>();
      for (const Shape<T>* s : {&a, &b}) {
        if (farther_than(*s, p, reach)) {
          fail(v, "contact point within " + num(reach) + " of both shapes",
               "point " + vec(c->points[std::size_t(i)]) + " is farther from " + describe(*s), pair_text(a, b));
          return;
        }
      }
    }
    // The primitives as placed (a compound's children by their child transforms).
    const auto ka = detail::placed_primitives_of(a), kb = detail::placed_primitives_of(b);
    std::vector<oracle::Placed> pa, pb;
    for (const auto& x : ka) pa.push_back(oracle::placed(x.shape, x.transform));
    for (const auto& y : kb) pb.push_back(oracle::placed(y.shape, y.transform));
    // Direction: a moved by -normal * (depth + 2 bounds) no longer overlaps b. For compounds the
    // contact is the deepest child pair's, so some overlapping child pair must be separated. Where
    // children are placed by transforms, a pair may overlap as computed while apart within the
    // placement's band (overlap_tolerance): such a pair may be the one reported.
    const Vec2c push = -n * (depth + 2 * bound);
    const double placed_band = overlap_tolerance(a, b);
    bool separated = false, any_pair = false;
    for (const oracle::Placed& x : pa) {
      for (const oracle::Placed& y : pb) {
        if (separated) continue;
        if (!oracle::overlaps(x, y) && !(placed_band > 0 && oracle::within_band(x, y, placed_band))) continue;
        any_pair = true;
        separated = oracle::separates(x, y, push);
      }
    }
    if (any_pair && !separated) {
      fail(v, "a moved by -normal * (depth + " + num(2 * bound) + ") separated from b",
           "still overlapping after the push " + vec(Vec2c(push)) + " (normal " + vec(c->normal) + ", depth " +
               num(depth) + ")",
           pair_text(a, b));
      return;
    }
    // Midway: within 3/4 of the depth (plus the bound) of both boundaries, the middle half
    // between the surfaces, while a point on one face of a deep contact lies a full depth from
    // the other surface. Judged where "midway between the surfaces" has one meaning: two
    // primitives with interiors that overlap without either containing the other (concentric
    // circles have no such point, a segment no interior).
    const bool judged = v.relation == Relation::Overlapping && pa.size() == 1 && pb.size() == 1 &&
                        detail::has_interior(ka[0].shape) && detail::has_interior(kb[0].shape);
    if (!judged) {
      v.account += "; midway not judged (" + std::string(name(v.relation)) + ")";
      return;
    }
    const double half = depth * 0.75 + 2 * bound + point_round;
    auto near_some = [&](const std::vector<oracle::Placed>& prims, const Vec2c& p) {
      for (const oracle::Placed& x : prims) {
        if (detail::near_boundary(x, p, half)) return true;
      }
      return false;
    };
    for (int i = 0; i < c->count; ++i) {
      const Vec2c p = c->points[std::size_t(i)].template cast<double>();
      for (const auto* prims : {&pa, &pb}) {
        if (!near_some(*prims, p)) {
          fail(v, "contact point midway: within 3/4 depth + " + num(half - depth * 0.75) + " of both boundaries",
               "point " + vec(c->points[std::size_t(i)]) + " farther than " + num(half) + " from the boundary of " +
                   (prims == &pa ? "a" : "b") + " (depth " + num(depth) + ")",
               pair_text(a, b));
          return;
        }
      }
    }
  });
}

template <Scalar T>
Verdict touching(const Shape<T>& a, const Shape<T>& b) {
  return guarded([&](Verdict& v) {
    v.relation = relation(a, b);
    const bool ab = overlaps(a, b), ba = overlaps(b, a);
    const bool exact = oracle::overlaps(a, b);
    v.account = std::string(name(v.relation)) + ": overlaps(a, b) " + yes(ab) + ", overlaps(b, a) " + yes(ba);
    const double tol = overlap_tolerance(a, b);
    if (v.relation == Relation::Touching) {
      // Stored shapes are decided exactly; children placed by transforms may round either way
      // (signed distance 0 is inside any band).
      if ((!ab || !ba) && tol > 0) {
        v.disagreement = true;
        if (!agrees_on_computed(v, ab, a, b, "overlaps(a, b):") || !agrees_on_computed(v, ba, b, a, "overlaps(b, a):"))
          return;
        v.account += "; within the band " + num(tol) + " of a compound's child transforms: allowed";
      } else if (!ab || !ba) {
        fail(v, "overlaps true both ways (exactly touching: signed distance 0)",
             "overlaps(a, b) " + yes(ab) + ", overlaps(b, a) " + yes(ba), pair_text(a, b));
      }
      return;
    }
    if (ab == exact && ba == exact) return;
    if (!agrees_on_computed(v, ab, a, b, "overlaps(a, b):") || !agrees_on_computed(v, ba, b, a, "overlaps(b, a):"))
      return;
    if (oracle::within_band(a, b, tol)) {
      v.disagreement = true;
      v.account += "; within the band " + num(tol) + " (signed distance ~" + num(oracle::approx_signed_distance(a, b)) +
                   "): allowed";
      return;
    }
    fail(v, "overlaps " + yes(exact) + " both ways (signed distance beyond the band " + num(tol) + ")",
         "overlaps(a, b) " + yes(ab) + ", overlaps(b, a) " + yes(ba),
         "signed distance ~" + num(oracle::approx_signed_distance(a, b)) + "; " + pair_text(a, b));
  });
}

template <Scalar T>
Verdict distance_law(const Shape<T>& a, const Shape<T>& b) {
  return guarded([&](Verdict& v) {
    v.relation = relation(a, b);
    const bool got = overlaps(a, b);
    const double d = distance(a, b);
    v.account = "overlaps " + yes(got) + ", distance " + num(d);
    if (got) {
      if (d != 0) fail(v, "distance 0 when overlapping", "distance " + num(d), pair_text(a, b));
      return;
    }
    if (!(d >= 0) || !std::isfinite(d)) {
      fail(v, "finite distance >= 0", "distance " + num(d), pair_text(a, b));
      return;
    }
    // Plus the rounding of the result to T (absolute near T's subnormals).
    const double bound =
        4 * rounding_tolerance(a, b) + 4 * detail::eps<T>() * d + 2 * double(std::numeric_limits<T>::denorm_min());
    const bool too_far = oracle::compare_distance(a, b, d - bound) < 0;   // gap < d - bound
    const bool too_near = oracle::compare_distance(a, b, d + bound) > 0;  // gap > d + bound
    if (too_far || too_near) {
      fail(v, "distance within " + num(bound) + " of the exact gap",
           "distance " + num(d) + ", exact ~" + num(oracle::approx_signed_distance(a, b)), pair_text(a, b));
    }
  });
}

#define COLLIDE_LAWS_INSTANTIATE(T)                                                  \
  template Verdict agreement<T>(const Shape<T>&, const Shape<T>&);                   \
  template Verdict symmetry<T>(const Shape<T>&, const Shape<T>&);                    \
  template Verdict translation<T>(const Shape<T>&, const Shape<T>&, const Vec2<T>&); \
  template Verdict rotation<T>(const Shape<T>&, const Shape<T>&, int, bool);         \
  template Verdict resolution<T>(const Shape<T>&, const Shape<T>&);                  \
  template Verdict hierarchy<T>(const Shape<T>&, const Shape<T>&);                   \
  template Verdict representation<T>(const Shape<T>&, const Shape<T>&);              \
  template Verdict contact_law<T>(const Shape<T>&, const Shape<T>&);                 \
  template Verdict distance_law<T>(const Shape<T>&, const Shape<T>&);                \
  template Verdict touching<T>(const Shape<T>&, const Shape<T>&);

COLLIDE_LAWS_INSTANTIATE(float)
COLLIDE_LAWS_INSTANTIATE(double)

}  // namespace collide::laws
