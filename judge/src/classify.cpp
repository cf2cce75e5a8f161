// Judging one answer: the oracle on the stored geometry, the library's declared contract.

#include "collide/judge/judge.hpp"
#include "collide/oracle/oracle.hpp"

#include <cmath>
#include <cstdio>
#include <span>

namespace collide::judge {

std::string_view name(Query q) noexcept {
  return q == Query::Overlap ? "overlap" : q == Query::Push ? "push" : "contains";
}

std::string_view name(Touching t) noexcept {
  return t == Touching::Overlap ? "overlap" : t == Touching::Apart ? "apart" : "either";
}

std::string_view name(Outcome o) noexcept {
  constexpr std::string_view names[] = {"agree", "convention", "wrong", "crash", "unjudged"};
  return names[static_cast<int>(o)];
}

std::string_view name(Severity s) noexcept {
  constexpr std::string_view names[] = {"none", "touching", "rounding", "gross"};
  return names[static_cast<int>(s)];
}

bool is_clean_input(const ShapeData& d) {
  const std::optional<Shape<double>> s = to_shape(d);
  if (!s || laws::to_data(*s).values.size() != d.values.size()) return false;
  // Positive extents: a zero radius or a flat box is a point or a segment, not an area.
  const auto& v = d.values;
  switch (d.kind) {
    case ShapeKind::Circle:
      return v[2] > 0;
    case ShapeKind::Aabb:
      return v[0] < v[2] && v[1] < v[3];
    case ShapeKind::Obb:
      return v[2] > 0 && v[3] > 0;
    case ShapeKind::Capsule:
      return v[4] > 0;
    default:
      return true;
  }
}

std::optional<Shape<double>> to_shape(const ShapeData& d) {
  if (d.kind == ShapeKind::Compound) return std::nullopt;
  for (double v : d.values)
    if (!std::isfinite(v)) return std::nullopt;
  return visit_kind(d.kind, [&]<ShapeKind K>() -> std::optional<Shape<double>> {
    if constexpr (laws::Codec<K>::layout == laws::Layout::Children) {
      return std::nullopt;
    } else {
      if (laws::value_count(K, d.values.size()) != d.values.size() || d.values.empty()) return std::nullopt;
      if (laws::Codec<K>::layout == laws::Layout::Fixed && d.values.size() != laws::Codec<K>::fields.size())
        return std::nullopt;
      auto made = laws::Codec<K>::template make<double>(std::span<const double>(d.values));
      if (!made) return std::nullopt;
      return Shape<double>(*made);
    }
  });
}

std::string class_key(const Input& input, const Judgement& j) {
  std::string key = std::string(name(j.outcome)) + "." + j.what;
  if (j.severity != Severity::None) key += "." + std::string(name(j.severity));
  if (input.ask == Query::Contains) return key + "." + std::string(name(input.a.kind)) + "_point";
  return key + "." + std::string(name(input.a.kind)) + "_" + std::string(name(input.b.kind));
}

namespace {

std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

double scale_of(const ShapeData& a, const ShapeData& b) {
  double s = 0;
  for (const ShapeData* d : {&a, &b})
    for (double v : d->values) s = std::max(s, std::fabs(v));
  return s;
}

/// The width of "rounding-level" beyond the band: the square root of the scalar's epsilon times
/// the scale (2^-26 for double, 2^-12 for float), which covers cancellation in a normalised short
/// edge or a squared distance; anything farther has no rounding explanation and is gross.
double rounding_allowance(const Contract& c, double scale) {
  const int bits = c.scalar == "float32" ? 24 : 53;
  return std::ldexp(scale, -(bits / 2));
}

/// The larger side of the shape's bounding box.
double size_of(const Shape<double>& s) {
  const Aabb<double> box = std::visit([](const auto& x) { return bounds(x); }, s);
  return std::max(box.max().x() - box.min().x(), box.max().y() - box.min().y());
}

/// A wrong answer or crash on shapes outside the sizes the library is documented for (its
/// contract's min_size and max_size) is the convention "below_min_size" or "above_max_size".
void outside_design_sizes(const Contract& c, double smallest, double largest, Judgement& j) {
  const char* what = c.min_size > 0 && smallest < c.min_size  ? "below_min_size"
                     : c.max_size > 0 && largest > c.max_size ? "above_max_size"
                                                              : nullptr;
  if (what == nullptr) return;
  j.outcome = Outcome::Convention;
  j.severity = Severity::None;
  j.what = what;
}

bool declares(const Info& info, Query q) {
  for (Query x : info.queries)
    if (x == q) return true;
  return false;
}

Judgement unjudged(std::string what) {
  Judgement j;
  j.outcome = Outcome::Unjudged;
  j.what = std::move(what);
  return j;
}

/// Overlap answers that differ from the oracle: touching convention, the band, or how far beyond.
Judgement judge_overlap_disagreement(const Contract& c, const Shape<double>& a, const Shape<double>& b, bool got,
                                     bool exact, double band, double rnd) {
  Judgement j;
  j.query = Query::Overlap;
  j.what = got ? "false_overlap" : "false_apart";
  const double sigma = oracle::approx_signed_distance(a, b);
  j.expected = std::string("overlap ") + (exact ? "true" : "false") + ", signed distance ~" + num(sigma);
  j.got = std::string("overlap ") + (got ? "true" : "false");
  const bool touching = exact && oracle::within_band(a, b, 0);
  if (touching && (c.touching == Touching::Either || (c.touching == Touching::Apart && !got))) {
    j.outcome = Outcome::Convention;
    j.what = "touching";
    return j;
  }
  if (band > 0 && oracle::within_band(a, b, band)) {
    j.outcome = Outcome::Convention;
    j.what = "within_band";
    return j;
  }
  j.outcome = Outcome::Wrong;
  if (touching)
    j.severity = Severity::Touching;
  else
    j.severity = oracle::within_band(a, b, band + rnd) ? Severity::Rounding : Severity::Gross;
  return j;
}

/// A push of a (after the contract's direction): it must leave at most the band of overlap, and
/// be no longer than the exact depth plus the band.
Judgement judge_push(const Shape<double>& a, const Shape<double>& b, Vec2<double> v, double band, double rnd) {
  Judgement j;
  j.query = Query::Push;
  const double len = std::hypot(v.x(), v.y());
  j.got = "push of a (" + num(v.x()) + ", " + num(v.y()) + "), length " + num(len);
  const oracle::Placed moved(a, v, Vec2<double>(1.0, 0.0));
  const double depth = oracle::approx_signed_distance(a, b);
  j.expected = "a push of a no longer than the exact depth ~" + num(-depth) + " that separates the pair";
  if (oracle::compare_depth(moved, b, band) > 0) {
    j.outcome = Outcome::Wrong;
    j.what = "push_leaves_overlap";
    j.severity = oracle::compare_depth(moved, b, band + rnd) > 0 ? Severity::Gross : Severity::Rounding;
    j.expected += "; after this push the exact depth is still > " + num(band);
    return j;
  }
  if (len - band > 0 && oracle::compare_depth(a, b, len - band) < 0) {
    j.outcome = Outcome::Wrong;
    j.what = "push_too_long";
    j.severity = oracle::compare_depth(a, b, len - band - rnd) < 0 ? Severity::Gross : Severity::Rounding;
    return j;
  }
  return j;
}

Judgement judge_pair(const Info& info, const Shape<double>& a, const Shape<double>& b, const Answer& answer,
                     double band, double rnd);

/// A containment answer on the stored shape and point: the contract's touching convention for
/// points on the boundary, its band for points within it of the boundary.
Judgement judge_contains(const Contract& c, const Shape<double>& s, Vec2<double> p, bool got, double band, double rnd) {
  Judgement j;
  j.query = Query::Contains;
  const bool exact = oracle::contains(s, p);
  if (got == exact) return j;
  j.what = got ? "false_inside" : "false_outside";
  const int boundary = oracle::compare_boundary_distance(s, p, 0);
  j.expected = std::string("contains ") + (exact ? "true" : "false") +
               (boundary == 0 ? ", on the boundary" : ", off the boundary");
  j.got = std::string("contains ") + (got ? "true" : "false");
  const Touching t = c.contains_touching.value_or(c.touching);
  if (boundary == 0 && (t == Touching::Either || (t == Touching::Apart && !got))) {
    j.outcome = Outcome::Convention;
    j.what = "touching";
    return j;
  }
  if (band > 0 && oracle::compare_boundary_distance(s, p, band) <= 0) {
    j.outcome = Outcome::Convention;
    j.what = "within_band";
    return j;
  }
  j.outcome = Outcome::Wrong;
  j.severity = boundary == 0                                              ? Severity::Touching
               : oracle::compare_boundary_distance(s, p, band + rnd) <= 0 ? Severity::Rounding
                                                                          : Severity::Gross;
  return j;
}

}  // namespace

Judgement judge_answer(const Info& info, const Input& input, const Answer& answer) {
  if (answer.status == Status::Unsupported) return unjudged("unsupported_input");
  if (answer.status == Status::Hung) {
    Judgement j;
    j.outcome = Outcome::Crash;
    j.query = input.ask;
    j.what = "hang";
    j.got = answer.error.substr(0, 200);
    j.expected = "an answer within the time-out";
    return j;
  }
  if (answer.status == Status::Threw) {
    Judgement j;
    j.outcome = Outcome::Crash;
    j.what = "exception";
    j.query = input.ask;
    j.got = "threw: " + answer.error.substr(0, 200);
    j.expected = "an answer";
    return j;
  }
  if (input.ask == Query::Contains) {
    const std::optional<Shape<double>> s = to_shape(answer.stored_a);
    if (!s) return unjudged("stored_not_a_shape");
    if (!std::isfinite(answer.stored_p.x()) || !std::isfinite(answer.stored_p.y()))
      return unjudged("stored_point_not_finite");
    const Contract& c = info.contract;
    double scale = std::max(std::fabs(answer.stored_p.x()), std::fabs(answer.stored_p.y()));
    for (double v : answer.stored_a.values) scale = std::max(scale, std::fabs(v));
    const double band = c.contains_tol_abs.value_or(c.tol_abs) + c.tol_rel * scale;
    try {
      Judgement j = judge_contains(c, *s, answer.stored_p, answer.contains, band, rounding_allowance(c, scale));
      if (j.outcome == Outcome::Wrong) outside_design_sizes(c, size_of(*s), size_of(*s), j);
      return j;
    } catch (const oracle::InvalidInput&) {
      return unjudged("oracle_invalid_input");
    } catch (const oracle::Unsupported&) {
      return unjudged("oracle_unsupported");
    }
  }
  const std::optional<Shape<double>> a = to_shape(answer.stored_a), b = to_shape(answer.stored_b);
  if (!a || !b) return unjudged("stored_not_a_shape");
  const Contract& c = info.contract;
  const double scale = scale_of(answer.stored_a, answer.stored_b);
  const double band = c.tol_abs + c.tol_rel * scale;
  const double rnd = rounding_allowance(c, scale);
  try {
    Judgement j = judge_pair(info, *a, *b, answer, band, rnd);
    if (j.outcome == Outcome::Wrong || j.outcome == Outcome::Crash)
      outside_design_sizes(c, std::min(size_of(*a), size_of(*b)), std::max(size_of(*a), size_of(*b)), j);
    return j;
  } catch (const oracle::InvalidInput&) {
    return unjudged("oracle_invalid_input");
  } catch (const oracle::Unsupported&) {
    return unjudged("oracle_unsupported");
  }
}

namespace {

/// The judgement of an answer on stored shapes a and b (the band and rounding allowance given).
Judgement judge_pair(const Info& info, const Shape<double>& a_shape, const Shape<double>& b_shape, const Answer& answer,
                     double band, double rnd) {
  const Contract& c = info.contract;
  const Shape<double>* a = &a_shape;  // the oracle's calls below read as on the stored shapes
  const Shape<double>* b = &b_shape;
  {
    const bool exact = oracle::overlaps(*a, *b);
    if (answer.overlap != exact) return judge_overlap_disagreement(c, *a, *b, answer.overlap, exact, band, rnd);
    if (!exact || !declares(info, Query::Push)) return Judgement{};
    if (!answer.has_push) {
      // An overlap within the band may come without a contact (a skin's, a slop's); deeper, a
      // library's overlap test and its contact generation are separate functions, and none of
      // the libraries documents that they agree: a convention, counted and reported.
      if (oracle::compare_depth(*a, *b, band) <= 0) return Judgement{};
      Judgement j;
      j.outcome = Outcome::Convention;
      j.query = Query::Push;
      j.what = "push_missing";
      j.expected = "a push vector (the pair overlaps)";
      j.got = "overlap true without a push";
      return j;
    }
    Vec2<double> v = c.push_moves == PushMoves::A ? answer.push : Vec2<double>(-answer.push);
    if (!std::isfinite(v.x()) || !std::isfinite(v.y())) {
      Judgement j;
      j.outcome = Outcome::Crash;
      j.query = Query::Push;
      j.what = "non_finite_push";
      j.expected = "a finite push vector";
      j.got = "push (" + num(answer.push.x()) + ", " + num(answer.push.y()) + ")";
      return j;
    }
    return judge_push(*a, *b, v, band, rnd);
  }
}

}  // namespace

}  // namespace collide::judge
