// Inputs aimed at the hard places: exact and ulp-near touching (found by bisection against the
// oracle), scales from 2^-40 to 2^40, far from the origin, slivers.

#include "collide/judge/judge.hpp"
#include "collide/oracle/oracle.hpp"

#include <cmath>
#include <numbers>

namespace collide::judge {

namespace {

/// Moves every position value of the shape by (dx, dy) (rounded sums: the result is simply the
/// doubles it stores).
void translate(ShapeData& d, double dx, double dy) {
  const laws::KindCodec codec = laws::codec_of(d.kind);
  for (std::size_t i = 0; i < d.values.size(); ++i) {
    const laws::Role r = codec.fields[i % codec.fields.size()].role;
    if (r == laws::Role::X) d.values[i] += dx;
    if (r == laws::Role::Y) d.values[i] += dy;
  }
}

/// Multiplies positions and sizes by 2^k (exact unless it underflows or overflows).
void scale(ShapeData& d, int k) {
  const laws::KindCodec codec = laws::codec_of(d.kind);
  for (std::size_t i = 0; i < d.values.size(); ++i)
    if (codec.fields[i % codec.fields.size()].role != laws::Role::Other) d.values[i] = std::ldexp(d.values[i], k);
}

/// A reference point inside the shape (its centre, a vertex average).
Vec2<double> inner_point(const ShapeData& d) {
  const laws::KindCodec codec = laws::codec_of(d.kind);
  double sx = 0, sy = 0;
  int nx = 0, ny = 0;
  for (std::size_t i = 0; i < d.values.size(); ++i) {
    const laws::Role r = codec.fields[i % codec.fields.size()].role;
    if (r == laws::Role::X) sx += d.values[i], ++nx;
    if (r == laws::Role::Y) sy += d.values[i], ++ny;
  }
  return {nx ? sx / nx : 0.0, ny ? sy / ny : 0.0};
}

bool valid(const ShapeData& d) {
  return is_clean_input(d);
}

}  // namespace

Generator::Generator(std::vector<ShapeKind> kinds, std::uint64_t seed) : kinds_(std::move(kinds)), rng_(seed) {}

void Generator::configure(bool points, bool laws, int scalar_bits) {
  points_ = points;
  laws_ = laws;
  scalar_bits_ = scalar_bits;
}

ShapeData Generator::shape(ShapeKind k, double size, double cx, double cy) {
  std::uniform_real_distribution<double> u(0.25, 1.0), angle(0, 2 * std::numbers::pi);
  // Half the time on a dyadic grid of size/64: exact touching then happens on purpose.
  const bool grid = rng_() & 1;
  auto q = [&](double v) { return grid ? std::ldexp(std::round(std::ldexp(v / size, 6)), -6) * size : v; };
  ShapeData d;
  d.kind = k;
  switch (k) {
    case ShapeKind::Circle:
      d.values = {q(cx), q(cy), q(size * u(rng_))};
      break;
    case ShapeKind::Aabb: {
      const double hx = q(size * u(rng_)), hy = q(size * u(rng_));
      d.values = {q(cx) - hx, q(cy) - hy, q(cx) + hx, q(cy) + hy};
      break;
    }
    case ShapeKind::Obb: {
      // Axis-aligned, a 3-4-5 axis (exact unit) or any angle.
      const int form = static_cast<int>(rng_() % 4);
      const double t = angle(rng_);
      const Vec2<double> ax = form == 0   ? Vec2<double>(1, 0)
                              : form == 1 ? Vec2<double>(0.6, 0.8)
                                          : Vec2<double>(std::cos(t), std::sin(t));
      d.values = {q(cx), q(cy), q(size * u(rng_)), q(size * u(rng_)), ax.x(), ax.y()};
      break;
    }
    case ShapeKind::Capsule: {
      const double t = angle(rng_), h = size * u(rng_);
      d.values = {q(cx - h * std::cos(t)), q(cy - h * std::sin(t)), q(cx + h * std::cos(t)), q(cy + h * std::sin(t)),
                  q(size * u(rng_) / 2)};
      break;
    }
    case ShapeKind::Polygon:
    default: {
      for (int attempt = 0; attempt < 20; ++attempt) {
        const int n = 3 + static_cast<int>(rng_() % 6);
        std::vector<double> ts;
        for (int i = 0; i < n; ++i) ts.push_back(angle(rng_));
        std::sort(ts.begin(), ts.end());
        const double r = size * u(rng_);
        d.values.clear();
        for (double t : ts) {
          d.values.push_back(q(cx + r * std::cos(t)));
          d.values.push_back(q(cy + r * std::sin(t)));
        }
        if (valid(d)) return d;
      }
      d.values = {q(cx - size), q(cy - size), q(cx + size), q(cy - size), q(cx), q(cy + size)};
      break;
    }
  }
  return d;
}

Input Generator::family_random(ShapeKind ka, ShapeKind kb) {
  std::uniform_real_distribution<double> pos(-2.5, 2.5);
  return {shape(ka, 1, 0, 0), shape(kb, 1, pos(rng_), pos(rng_))};
}

Input Generator::family_touching(ShapeKind ka, ShapeKind kb) {
  // b slides from a's inner point along a direction; bisection over the doubles (exact oracle)
  // finds the last overlapping offset and the first separated one, one ulp apart.
  Input in{shape(ka, 1, 0, 0), shape(kb, 1, 0, 0)};
  const std::optional<Shape<double>> a = to_shape(in.a);
  if (!a) return family_random(ka, kb);
  const int form = static_cast<int>(rng_() % 3);
  const double t = std::uniform_real_distribution<double>(0, 2 * std::numbers::pi)(rng_);
  const Vec2<double> dir = form == 0   ? Vec2<double>(rng_() & 1 ? 1 : -1, 0)
                           : form == 1 ? Vec2<double>(0, rng_() & 1 ? 1 : -1)
                                       : Vec2<double>(std::cos(t), std::sin(t));
  const Vec2<double> c = inner_point(in.b);
  translate(in.b, -c.x(), -c.y());
  const Vec2<double> c0 = inner_point(in.a);
  auto at = [&](double s) {
    ShapeData b = in.b;
    translate(b, c0.x() + s * dir.x(), c0.y() + s * dir.y());
    return b;
  };
  auto overlaps_at = [&](double s) {
    const std::optional<Shape<double>> b = to_shape(at(s));
    return b && oracle::overlaps(*a, *b);
  };
  double lo = 0, hi = 8;
  if (!overlaps_at(lo) || overlaps_at(hi)) return family_random(ka, kb);
  while (std::nextafter(lo, hi) < hi) {
    const double mid = lo + (hi - lo) / 2;
    if (mid <= lo || mid >= hi) break;
    (overlaps_at(mid) ? lo : hi) = mid;
  }
  in.b = at(rng_() & 1 ? lo : hi);
  if (!valid(in.b)) return family_random(ka, kb);
  return in;
}

Input Generator::family_nudged(ShapeKind ka, ShapeKind kb) {
  Input in = family_touching(ka, kb);
  ShapeData& s = rng_() & 1 ? in.a : in.b;
  for (int tries = 0; tries < 4; ++tries) {
    ShapeData moved = s;
    double& v = moved.values[rng_() % moved.values.size()];
    const int ulps = 1 + static_cast<int>(rng_() % 4);
    for (int i = 0; i < ulps; ++i) v = std::nextafter(v, rng_() & 1 ? HUGE_VAL : -HUGE_VAL);
    if (valid(moved)) {
      s = moved;
      break;
    }
  }
  return in;
}

Input Generator::family_scaled(ShapeKind ka, ShapeKind kb) {
  Input in = rng_() & 1 ? family_touching(ka, kb) : family_random(ka, kb);
  const int k = static_cast<int>(rng_() % 81) - 40;
  scale(in.a, k);
  scale(in.b, k);
  if (rng_() & 1) {
    // Far from the origin: both moved by one offset of 2^m (the sums round; judged as stored).
    const int m = static_cast<int>(rng_() % 41);
    const double off = std::ldexp(rng_() & 1 ? 1.0 : -1.0, std::max(m, k + 4));
    translate(in.a, off, off / 2);
    translate(in.b, off, off / 2);
  }
  if (!valid(in.a) || !valid(in.b)) return family_random(ka, kb);
  return in;
}

Input Generator::family_sliver(ShapeKind ka, ShapeKind kb) {
  Input in = family_touching(ka, kb);
  // Flatten one shape about its inner point along y by 2^-k, then slide the pair back to touching
  // only for boxes, whose flattening keeps them valid; others keep their place (near or apart).
  ShapeData& s = rng_() & 1 ? in.a : in.b;
  const int k = 10 + static_cast<int>(rng_() % 30);
  const laws::KindCodec codec = laws::codec_of(s.kind);
  const Vec2<double> c = inner_point(s);
  ShapeData flat = s;
  for (std::size_t i = 0; i < flat.values.size(); ++i) {
    const laws::Role r = codec.fields[i % codec.fields.size()].role;
    if (r == laws::Role::Y) flat.values[i] = c.y() + std::ldexp(flat.values[i] - c.y(), -k);
    if (r == laws::Role::Size && (i == 3 || s.kind == ShapeKind::Circle || s.kind == ShapeKind::Capsule))
      flat.values[i] = std::ldexp(flat.values[i], -k);
  }
  if (valid(flat)) s = flat;
  return in;
}

Input Generator::family_point(ShapeKind k) {
  // A point on the boundary (exactly where the values allow: a vertex, a box's edge, a circle's
  // extreme), nudged by a few ulps or not, or anywhere near the shape; then, sometimes, the
  // shape and point scaled and moved far from the origin together.
  Input in;
  in.ask = Query::Contains;
  in.a = shape(k, 1, 0, 0);
  const auto& v = in.a.values;
  std::uniform_real_distribution<double> u01(0, 1), near(-1.5, 1.5);
  const double t = u01(rng_) * 2 * std::numbers::pi;
  auto on_segment = [&](Vec2<double> p, Vec2<double> q) {
    if (rng_() & 1) return rng_() & 1 ? p : q;
    const double s = std::ldexp(std::floor(std::ldexp(u01(rng_), 6)), -6);
    return Vec2<double>(p.x() + (q.x() - p.x()) * s, p.y() + (q.y() - p.y()) * s);
  };
  Vec2<double> p;
  const int form = static_cast<int>(rng_() % 4);
  if (form == 0) {
    p = Vec2<double>(near(rng_), near(rng_));
  } else {
    switch (k) {
      case ShapeKind::Circle: {
        const int side = static_cast<int>(rng_() % 5);
        const double r = v[2];
        p = side == 0   ? Vec2<double>(v[0] + r, v[1])
            : side == 1 ? Vec2<double>(v[0] - r, v[1])
            : side == 2 ? Vec2<double>(v[0], v[1] + r)
            : side == 3 ? Vec2<double>(v[0], v[1] - r)
                        : Vec2<double>(v[0] + r * std::cos(t), v[1] + r * std::sin(t));
        break;
      }
      case ShapeKind::Aabb: {
        const Vec2<double> c[4] = {{v[0], v[1]}, {v[2], v[1]}, {v[2], v[3]}, {v[0], v[3]}};
        const int e = static_cast<int>(rng_() % 4);
        p = on_segment(c[e], c[(e + 1) % 4]);
        break;
      }
      case ShapeKind::Obb: {
        const Vec2<double> ex(v[4] * v[2], v[5] * v[2]), ey(-v[5] * v[3], v[4] * v[3]), o(v[0], v[1]);
        const Vec2<double> c[4] = {o - ex - ey, o + ex - ey, o + ex + ey, o - ex + ey};
        const int e = static_cast<int>(rng_() % 4);
        p = on_segment(c[e], c[(e + 1) % 4]);
        break;
      }
      case ShapeKind::Capsule: {
        const Vec2<double> a(v[0], v[1]), b(v[2], v[3]);
        const Vec2<double> d = (b - a) / std::hypot(b.x() - a.x(), b.y() - a.y());
        const Vec2<double> n(-d.y(), d.x());
        p = rng_() & 1 ? on_segment(a + n * v[4], b + n * v[4]) : Vec2<double>(a - d * v[4]);
        break;
      }
      default: {
        const std::size_t m = v.size() / 2, e = rng_() % m, f = (e + 1) % m;
        p = on_segment({v[2 * e], v[2 * e + 1]}, {v[2 * f], v[2 * f + 1]});
      }
    }
    if (form == 2) {
      double& x = rng_() & 1 ? p.x() : p.y();
      const int ulps = 1 + static_cast<int>(rng_() % 4);
      const double dir = rng_() & 1 ? HUGE_VAL : -HUGE_VAL;
      for (int i = 0; i < ulps; ++i) x = std::nextafter(x, dir);
    }
  }
  in.p = p;
  if (rng_() % 3 == 0) {
    const int sk = static_cast<int>(rng_() % 61) - 30;
    ShapeData moved = in.a;
    scale(moved, sk);
    Vec2<double> q(std::ldexp(p.x(), sk), std::ldexp(p.y(), sk));
    if (rng_() & 1) {
      const double off = std::ldexp(rng_() & 1 ? 1.0 : -1.0, std::max(static_cast<int>(rng_() % 41), sk + 4));
      translate(moved, off, off / 2);
      q = Vec2<double>(q.x() + off, q.y() + off / 2);
    }
    if (valid(moved) && std::isfinite(q.x()) && std::isfinite(q.y())) in.a = moved, in.p = q;
  }
  return in;
}

std::optional<std::pair<Input, Map>> Generator::translated(const Input& in) {
  // Every position and size snapped to a multiple of 2^g with at most B significant bits, so a
  // translation by 2^k (k above every value's exponent, k - g below the scalar's precision)
  // keeps every sum exact.
  double top = 0;
  for (const ShapeData* d : {&in.a, &in.b}) {
    const laws::KindCodec codec = laws::codec_of(d->kind);
    for (std::size_t i = 0; i < d->values.size(); ++i)
      if (codec.fields[i % codec.fields.size()].role != laws::Role::Other) top = std::max(top, std::fabs(d->values[i]));
  }
  if (!(top > 0) || !std::isfinite(top)) return std::nullopt;
  const int e = std::ilogb(top);
  const int bits_choice[] = {6, 10, 14, 18};
  const int b = bits_choice[rng_() % 4];
  const int g = e - b;
  Input s = in;
  for (ShapeData* d : {&s.a, &s.b}) {
    const laws::KindCodec codec = laws::codec_of(d->kind);
    for (std::size_t i = 0; i < d->values.size(); ++i)
      if (codec.fields[i % codec.fields.size()].role != laws::Role::Other)
        d->values[i] = std::ldexp(std::round(std::ldexp(d->values[i], -g)), g);
  }
  if (!valid(s.a) || !valid(s.b)) return std::nullopt;
  const int k_lo = e + 1, k_hi = g + scalar_bits_ - 1;
  if (k_hi < k_lo) return std::nullopt;
  auto offset = [&] {
    const int k = k_lo + static_cast<int>(rng_() % static_cast<unsigned>(k_hi - k_lo + 1));
    return std::ldexp(rng_() & 1 ? 1.0 : -1.0, k);
  };
  Map m;
  m.relation = Relation::Translation;
  const int axes = static_cast<int>(rng_() % 3);
  m.tx = axes != 1 ? offset() : 0.0;
  m.ty = axes != 0 ? offset() : 0.0;
  return std::make_pair(s, m);
}

void Generator::generate(std::size_t n, std::vector<Input>& out, std::vector<Link>* links) {
  for (std::size_t i = 0; i < n;) {
    if (points_ && rng_() % 4 == 0) {
      out.push_back(family_point(kinds_[rng_() % kinds_.size()]));
      ++i;
      continue;
    }
    const ShapeKind ka = kinds_[rng_() % kinds_.size()], kb = kinds_[rng_() % kinds_.size()];
    const int f = static_cast<int>(rng_() % 20);
    Input in = f < 6    ? family_random(ka, kb)
               : f < 11 ? family_touching(ka, kb)
               : f < 14 ? family_nudged(ka, kb)
               : f < 17 ? family_scaled(ka, kb)
                        : family_sliver(ka, kb);
    const std::size_t base = out.size();
    out.push_back(in);
    out.push_back(Input{in.b, in.a});
    i += 2;
    if (!links) continue;
    links->push_back({base, base + 1, Map{}});
    if (!laws_) continue;
    if (rng_() & 1) {
      if (const auto t = translated(in)) {
        if (const std::optional<Input> moved = apply(t->second, t->first)) {
          out.push_back(t->first);
          out.push_back(*moved);
          links->push_back({out.size() - 2, out.size() - 1, t->second});
          i += 2;
        }
      }
    }
    if (rng_() & 1) {
      Map m;
      m.relation = Relation::Rotation;
      m.mirror = rng_() & 1;
      m.quarter_turns = static_cast<int>(rng_() % 3) + (m.mirror ? 0 : 1);
      out.push_back(*apply(m, in));
      links->push_back({base, out.size() - 1, m});
      ++i;
    }
  }
}

}  // namespace collide::judge
