// The metamorphic laws: the library's answers on exactly related inputs (arguments swapped,
// both shapes translated, turned or mirrored) must correspond, whatever the oracle says.

#include "collide/judge/judge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace collide::judge {

namespace {

/// Mirror (x -> -x) when asked, then quarter turns counter-clockwise: exact on doubles.
Vec2<double> turn(const Map& m, Vec2<double> v) {
  if (m.mirror) v = Vec2<double>(-v.x(), v.y());
  for (int k = 0; k < ((m.quarter_turns % 4) + 4) % 4; ++k) v = Vec2<double>(-v.y(), v.x());
  return v;
}

/// a + b, or nullopt when the sum rounds (TwoSum's error term is not zero).
std::optional<double> exact_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  const double err = (a - (s - bb)) + (b - bb);
  if (!std::isfinite(s) || err != 0) return std::nullopt;
  return s;
}

std::optional<ShapeData> translate(const ShapeData& d, double tx, double ty) {
  ShapeData out = d;
  const laws::KindCodec codec = laws::codec_of(d.kind);
  for (std::size_t i = 0; i < d.values.size(); ++i) {
    const laws::Role r = codec.fields[i % codec.fields.size()].role;
    if (r != laws::Role::X && r != laws::Role::Y) continue;
    const std::optional<double> s = exact_sum(d.values[i], r == laws::Role::X ? tx : ty);
    if (!s) return std::nullopt;
    out.values[i] = *s;
  }
  return out;
}

ShapeData rotate(const ShapeData& d, const Map& m) {
  ShapeData out = d;
  auto& v = out.values;
  switch (d.kind) {
    case ShapeKind::Circle: {
      const Vec2<double> c = turn(m, {v[0], v[1]});
      v[0] = c.x(), v[1] = c.y();
      break;
    }
    case ShapeKind::Aabb: {
      // The image of the box is the box of its two corners' images.
      const Vec2<double> p = turn(m, {v[0], v[1]}), q = turn(m, {v[2], v[3]});
      v = {std::min(p.x(), q.x()), std::min(p.y(), q.y()), std::max(p.x(), q.x()), std::max(p.y(), q.y())};
      break;
    }
    case ShapeKind::Obb: {
      // centre +- hx u +- hy perp(u): the image has the image centre and axis (a mirrored perp(u)
      // is minus the new perp, the same set under +-).
      const Vec2<double> c = turn(m, {v[0], v[1]}), u = turn(m, {v[4], v[5]});
      v[0] = c.x(), v[1] = c.y(), v[4] = u.x(), v[5] = u.y();
      break;
    }
    case ShapeKind::Capsule: {
      const Vec2<double> p = turn(m, {v[0], v[1]}), q = turn(m, {v[2], v[3]});
      v = {p.x(), p.y(), q.x(), q.y(), v[4]};
      break;
    }
    default: {
      std::vector<Vec2<double>> pts;
      for (std::size_t i = 0; i + 1 < v.size(); i += 2) pts.push_back(turn(m, {v[i], v[i + 1]}));
      if (m.mirror) std::reverse(pts.begin(), pts.end());  // keeps the vertices counter-clockwise
      v.clear();
      for (const auto& q : pts) v.push_back(q.x()), v.push_back(q.y());
    }
  }
  return out;
}

/// The shape's values in a form where equal point sets of one kind compare equal: the normal
/// form, a polygon's vertices starting at the lowest (x, y).
std::optional<ShapeData> canonical(const ShapeData& d) {
  const std::optional<Shape<double>> s = to_shape(d);
  if (!s) return std::nullopt;
  ShapeData c = laws::to_data(*s);
  if (c.kind == ShapeKind::Polygon && c.values.size() >= 6) {
    std::size_t best = 0;
    for (std::size_t i = 2; i + 1 < c.values.size(); i += 2)
      if (c.values[i] < c.values[best] || (c.values[i] == c.values[best] && c.values[i + 1] < c.values[best + 1]))
        best = i;
    std::rotate(c.values.begin(), c.values.begin() + static_cast<long>(best), c.values.end());
  }
  return c;
}

bool same_set(const ShapeData& x, const ShapeData& y) {
  const auto a = canonical(x), b = canonical(y);
  return a && b && a->kind == b->kind && a->values == b->values;
}

/// The vector the related input's push should be, given the base's (both as pushes of a).
Vec2<double> expected_push(const Map& m, Vec2<double> v) {
  switch (m.relation) {
    case Relation::Symmetry:
      return -v;
    case Relation::Translation:
      return v;
    default:
      return turn(m, v);
  }
}

double scale_of(const Answer& a) {
  double s = 0;
  for (const ShapeData* d : {&a.stored_a, &a.stored_b})
    for (double v : d->values) s = std::max(s, std::fabs(v));
  return s;
}

std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string text(const Answer& a, bool push) {
  std::string s = std::string("overlap ") + (a.overlap ? "true" : "false");
  if (push && a.has_push) s += " push (" + num(a.push.x()) + ", " + num(a.push.y()) + ")";
  return s;
}

std::string describe(const Map& m) {
  switch (m.relation) {
    case Relation::Symmetry:
      return "the arguments swapped";
    case Relation::Translation:
      return "both shapes moved by (" + num(m.tx) + ", " + num(m.ty) + ")";
    default:
      return std::string("both shapes") + (m.mirror ? " mirrored (x -> -x) and" : "") + " turned by " +
             std::to_string(m.quarter_turns) + " quarter turns";
  }
}

}  // namespace

std::string_view name(Relation r) noexcept {
  constexpr std::string_view names[] = {"symmetry", "translation", "rotation"};
  return names[static_cast<int>(r)];
}

std::optional<Input> apply(const Map& m, const Input& in) {
  if (in.ask != Query::Overlap) return std::nullopt;
  switch (m.relation) {
    case Relation::Symmetry:
      return Input{in.b, in.a};
    case Relation::Translation: {
      const auto a = translate(in.a, m.tx, m.ty), b = translate(in.b, m.tx, m.ty);
      if (!a || !b) return std::nullopt;
      return Input{*a, *b};
    }
    default:
      return Input{rotate(in.a, m), rotate(in.b, m)};
  }
}

bool law_applies(const Map& m, const Answer& ab, const Answer& ao) {
  if (ab.status != Status::Ok || ao.status != Status::Ok) return false;
  const std::optional<Input> mapped = apply(m, Input{ab.stored_a, ab.stored_b});
  return mapped && same_set(mapped->a, ao.stored_a) && same_set(mapped->b, ao.stored_b);
}

Judgement judge_law(const Info& info, const Map& m, const Input& /*base*/, const Answer& ab, const Judgement& jb,
                    const Input& /*other*/, const Answer& ao, const Judgement& jo) {
  Judgement j;
  for (const Judgement* x : {&jb, &jo})
    if (x->outcome == Outcome::Crash || x->outcome == Outcome::Unjudged) return j;
  if (!law_applies(m, ab, ao)) return j;
  const bool pushes = std::find(info.queries.begin(), info.queries.end(), Query::Push) != info.queries.end();
  const Contract& c = info.contract;
  const double band = c.tol_abs + c.tol_rel * std::max(scale_of(ab), scale_of(ao));
  if (ab.overlap != ao.overlap) {
    j.query = Query::Overlap;
  } else if (ab.overlap && pushes && (ab.has_push || ao.has_push)) {
    if (ab.has_push == ao.has_push) {
      auto as_a = [&](const Answer& a) { return c.push_moves == PushMoves::A ? a.push : Vec2<double>(-a.push); };
      const Vec2<double> want = expected_push(m, as_a(ab)), got = as_a(ao);
      if (!(std::hypot(got.x() - want.x(), got.y() - want.y()) > band)) return j;
    }
    j.query = Query::Push;
  } else {
    return j;
  }
  j.what = std::string(name(m.relation)) + (j.query == Query::Overlap ? "_overlap" : "_push");
  j.got = "base: " + text(ab, j.query == Query::Push) + "; related (" + describe(m) +
          "): " + text(ao, j.query == Query::Push);
  j.expected = j.query == Query::Overlap
                   ? "the same overlap answer for both (the stored geometry maps exactly)"
                   : "the related push equal to the base's mapped by the law, within the band " + num(band);
  j.outcome = Outcome::Convention;
  for (const Judgement* x : {&jb, &jo})
    if (x->outcome == Outcome::Wrong) {
      j.outcome = Outcome::Wrong;
      j.severity = std::max(j.severity, x->severity);
    }
  return j;
}

}  // namespace collide::judge
