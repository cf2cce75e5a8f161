// The adversarial check of "exact for every pair": overlaps(), whether contact() exists, and
// contains() against the exact oracle on cases built to sit at the boundary. Its generators are its
// own (not the property suite's): random local shapes (rotated boxes at many angles, slivers,
// near-parallel edges, compounds) are scaled (1e-30 .. 2^400) and offset (0, 1e6, 1e15, 2^100);
// shape b slides along a direction until the answer flips (bisection on the double's bits, so the
// two sides are adjacent values: exact touching whenever it is representable), and every coordinate
// of b is then nudged by 1..4 ulps each way. Contains() likewise for a point sliding out of a
// shape.
//
// Usage: adversarial_exact_decisions [--cases N] [--seed S] [--save-cases DIR]. Prints the number
// of cases judged, the time, the disagreements per pair; exits 1 on any disagreement. With
// --save-cases, the first overlap disagreements of each pair are written there as agreement case
// files, or contact case files when only contact() disagrees (for tests/regressions/).

#include "collide/collide.hpp"
#include "collide/laws/case_file.hpp"
#include "collide/laws/laws.hpp"
#include "collide/oracle/oracle.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace collide;

struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1p-53; }
  double in(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int below(int n) { return int(next() % std::uint64_t(n)); }
};

/// A shape in local coordinates (doubles), placed later by scale and offset into T.
struct Local {
  int kind = 0;            // 0 circle, 1 aabb, 2 obb, 3 capsule, 4 polygon
  std::vector<Vec2c> pts;  // circle: centre; aabb: min, max; obb: centre; capsule: a, b; polygon
  double r = 0;            // radius
  Vec2c half = Vec2c::Zero();
  double angle = 0;
};

const char* kKindName[] = {"circle", "aabb", "obb", "capsule", "polygon", "compound"};

/// An angle from many families: uniform, quarter turns, eighths, and a hair off them.
double pick_angle(Rng& g) {
  const double q = std::numbers::pi / 2;
  switch (g.below(5)) {
    case 0:
      return g.in(0, 2 * std::numbers::pi);
    case 1:
      return q * g.below(4);
    case 2:
      return q / 2 * (2 * g.below(4) + 1);
    case 3:
      return q * g.below(4) + (g.below(2) ? 1 : -1) * std::ldexp(1.0, -20 - g.below(34));
    default:
      return g.in(0, 2 * std::numbers::pi) + std::ldexp(1.0, -g.below(60));
  }
}

/// A size in [0.2, 1], or a sliver (down to 2^-45 of that).
double pick_size(Rng& g, bool allow_sliver) {
  if (allow_sliver && g.below(5) == 0) return std::ldexp(g.in(0.5, 1), -10 - g.below(36));
  return g.in(0.2, 1);
}

Local make_local(Rng& g, int kind, double base_angle) {
  Local l;
  l.kind = kind;
  const double ang = g.below(3) == 0 ? base_angle + std::ldexp(g.in(-1, 1), -g.below(50)) : pick_angle(g);
  const Vec2c jitter(g.in(-0.1, 0.1), g.in(-0.1, 0.1));
  switch (kind) {
    case 0:
      l.pts = {jitter};
      l.r = pick_size(g, true);
      break;
    case 1: {
      const Vec2c h(pick_size(g, true), pick_size(g, true));
      l.pts = {Vec2c(jitter - h), Vec2c(jitter + h)};
      break;
    }
    case 2:
      l.pts = {jitter};
      l.half = Vec2c(pick_size(g, true), pick_size(g, true));
      l.angle = ang;
      break;
    case 3: {
      const double len = g.below(8) == 0 ? 0.0 : pick_size(g, true);
      const Vec2c d(std::cos(ang) * len, std::sin(ang) * len);
      l.pts = {Vec2c(jitter - d), Vec2c(jitter + d)};
      l.r = g.below(6) == 0 ? std::ldexp(1.0, -30 - g.below(20)) : pick_size(g, true);
      break;
    }
    default: {
      const int form = g.below(3);
      if (form == 0) {  // regular-ish n-gon
        const int n = 3 + g.below(6);
        const double rad = pick_size(g, false);
        for (int i = 0; i < n; ++i) {
          const double t = ang + 2 * std::numbers::pi * (i + g.in(-0.2, 0.2)) / n;
          l.pts.push_back(jitter + rad * Vec2c(std::cos(t), std::sin(t)));
        }
      } else if (form == 1) {  // rotated rectangle: edges near-parallel to a box at base_angle
        const Vec2c u(std::cos(ang), std::sin(ang)), v(-u.y(), u.x());
        const double hx = pick_size(g, true), hy = pick_size(g, true);
        l.pts = {Vec2c(jitter - hx * u - hy * v), Vec2c(jitter + hx * u - hy * v), Vec2c(jitter + hx * u + hy * v),
                 Vec2c(jitter - hx * u + hy * v)};
      } else {  // sliver triangle: two nearly parallel long edges
        const Vec2c u(std::cos(ang), std::sin(ang)), v(-u.y(), u.x());
        const double len = g.in(0.5, 1), w = std::ldexp(g.in(0.5, 1), -5 - g.below(35));
        l.pts = {Vec2c(jitter - len * u), Vec2c(jitter + len * u), Vec2c(jitter + w * v)};
      }
      break;
    }
  }
  return l;
}

/// The local shape placed at offset + scale * (local + shift), rounded to T.
template <Scalar T>
std::optional<Primitive<T>> place(const Local& l, double scale, const Vec2c& offset, const Vec2c& shift) {
  auto at = [&](const Vec2c& p) { return Vec2<T>((offset + scale * (p + shift)).template cast<T>()); };
  const T r = static_cast<T>(scale * l.r);
  switch (l.kind) {
    case 0: {
      auto c = Circle<T>::make(at(l.pts[0]), r);
      if (c) return Primitive<T>(c.value());
      return std::nullopt;
    }
    case 1: {
      auto b = Aabb<T>::make(at(l.pts[0]), at(l.pts[1]));
      if (b) return Primitive<T>(b.value());
      return std::nullopt;
    }
    case 2: {
      auto o = Obb<T>::make(at(l.pts[0]), Vec2<T>((scale * l.half).template cast<T>()), static_cast<T>(l.angle));
      if (o) return Primitive<T>(o.value());
      return std::nullopt;
    }
    case 3: {
      auto c = Capsule<T>::make(at(l.pts[0]), at(l.pts[1]), r);
      if (c) return Primitive<T>(c.value());
      return std::nullopt;
    }
    default: {
      std::vector<Vec2<T>> v;
      for (const Vec2c& p : l.pts) v.push_back(at(p));
      auto p = ConvexPolygon<T>::make_hull(v);
      if (p) return Primitive<T>(p.value());
      return std::nullopt;
    }
  }
}

template <Scalar T>
std::optional<Shape<T>> place_all(const std::vector<Local>& parts, double scale, const Vec2c& offset,
                                  const Vec2c& shift) {
  std::vector<Primitive<T>> out;
  for (const Local& l : parts) {
    auto p = place<T>(l, scale, offset, shift);
    if (!p) return std::nullopt;
    out.push_back(*p);
  }
  if (out.size() == 1) return std::visit([](const auto& x) { return Shape<T>(x); }, out[0]);
  auto c = Compound<T>::make(out);
  if (!c) return std::nullopt;
  return Shape<T>(c.value());
}

/// v moved by k ulps toward sign (k = 0: unchanged).
template <Scalar T>
T ulps(T v, int k) {
  const T to = k > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
  for (int i = 0; i < std::abs(k); ++i) v = std::nextafter(v, to);
  return v;
}

/// Every stored position of s moved by (kx, ky) ulps (extents, radii and axes kept).
template <Scalar T>
std::optional<Shape<T>> nudged(const Shape<T>& s, int kx, int ky) {
  auto mv = [&](const Vec2<T>& p) { return Vec2<T>(ulps(p.x(), kx), ulps(p.y(), ky)); };
  auto prim = [&](const auto& x) -> std::optional<Primitive<T>> {
    using S = std::remove_cvref_t<decltype(x)>;
    if constexpr (std::is_same_v<S, Circle<T>>) {
      auto r = Circle<T>::make(mv(x.center()), x.radius());
      if (r) return Primitive<T>(r.value());
    } else if constexpr (std::is_same_v<S, Aabb<T>>) {
      auto r = Aabb<T>::make(mv(x.min()), mv(x.max()));
      if (r) return Primitive<T>(r.value());
    } else if constexpr (std::is_same_v<S, Obb<T>>) {
      auto r = Obb<T>::make_with_axis(mv(x.center()), x.half_extents(), x.axis());
      if (r) return Primitive<T>(r.value());
    } else if constexpr (std::is_same_v<S, Capsule<T>>) {
      auto r = Capsule<T>::make(mv(x.a()), mv(x.b()), x.radius());
      if (r) return Primitive<T>(r.value());
    } else if constexpr (std::is_same_v<S, ConvexPolygon<T>>) {
      std::vector<Vec2<T>> v;
      for (const Vec2<T>& p : x.vertices()) v.push_back(mv(p));
      auto r = ConvexPolygon<T>::make_hull(v);
      if (r) return Primitive<T>(r.value());
    }
    return std::nullopt;
  };
  if (const auto* c = std::get_if<Compound<T>>(&s)) {
    std::vector<Primitive<T>> kids;
    for (const Primitive<T>& k : c->children()) {
      auto p = std::visit(prim, k);
      if (!p) return std::nullopt;
      kids.push_back(*p);
    }
    auto r = Compound<T>::make(kids);
    if (!r) return std::nullopt;
    return Shape<T>(r.value());
  }
  auto p = std::visit(
      [&](const auto& x) -> std::optional<Primitive<T>> {
        if constexpr (std::is_same_v<std::remove_cvref_t<decltype(x)>, Compound<T>>) {
          return std::nullopt;
        } else {
          return prim(x);
        }
      },
      s);
  if (!p) return std::nullopt;
  return std::visit([](const auto& x) { return Shape<T>(x); }, *p);
}

/// Bisection on the bits of lambda in [0, hi] for a flip of f: returns adjacent (lo, hi) with
/// f(lo) != f(hi), or nothing when the ends agree.
template <class F>
std::optional<std::pair<double, double>> flip(F&& f, double hi) {
  std::optional<bool> flo = f(0.0), fhi = f(hi);
  if (!flo || !fhi || *flo == *fhi) return std::nullopt;
  std::uint64_t a = 0, b;
  std::memcpy(&b, &hi, 8);
  while (b - a > 1) {
    const std::uint64_t m = a + (b - a) / 2;
    double x;
    std::memcpy(&x, &m, 8);
    const std::optional<bool> fm = f(x);
    if (!fm) return std::nullopt;
    if (*fm == *flo)
      a = m;
    else
      b = m;
  }
  double x, y;
  std::memcpy(&x, &a, 8);
  std::memcpy(&y, &b, 8);
  return std::make_pair(x, y);
}

struct Tally {
  std::uint64_t cases = 0, disagreements = 0, overlap_cases = 0, contains_cases = 0, skipped = 0;
  std::uint64_t exact_calls = 0;  // judged calls that needed an exact evaluation
  std::map<std::string, std::uint64_t> per_label, bad_label;
  int printed = 0;
  std::string save_dir;
  std::uint64_t seed = 0;
};

template <Scalar T>
std::string text(const Shape<T>& s) {
  std::string out;
  char buf[96];
  auto v = [&](const Vec2<T>& p) {
    std::snprintf(buf, sizeof buf, "(%a, %a)", double(p.x()), double(p.y()));
    out += buf;
  };
  auto prim = [&](const auto& x) {
    using S = std::remove_cvref_t<decltype(x)>;
    if constexpr (std::is_same_v<S, Circle<T>>) {
      out += "circle ";
      v(x.center());
      std::snprintf(buf, sizeof buf, " r %a", double(x.radius()));
      out += buf;
    } else if constexpr (std::is_same_v<S, Aabb<T>>) {
      out += "aabb ";
      v(x.min());
      v(x.max());
    } else if constexpr (std::is_same_v<S, Obb<T>>) {
      out += "obb c ";
      v(x.center());
      out += " h ";
      v(x.half_extents());
      out += " u ";
      v(x.axis());
    } else if constexpr (std::is_same_v<S, Capsule<T>>) {
      out += "capsule ";
      v(x.a());
      v(x.b());
      std::snprintf(buf, sizeof buf, " r %a", double(x.radius()));
      out += buf;
    } else if constexpr (std::is_same_v<S, ConvexPolygon<T>>) {
      out += "polygon";
      for (const Vec2<T>& p : x.vertices()) v(p);
    } else if constexpr (std::is_same_v<S, Compound<T>>) {
      out += "compound {";
      for (const Primitive<T>& k : x.children()) {
        std::visit([&](const auto& y) { out += text<T>(Shape<T>(y)) + "; "; }, k);
      }
      out += "}";
    }
  };
  std::visit(prim, s);
  return out;
}

/// overlaps(a, b) and whether contact(a, b) exists, each against the exact answer: a contact
/// exists exactly when the shapes overlap, and its own path decides that near touching too.
template <Scalar T>
void judge_pair(Tally& t, const std::string& label, const Shape<T>& a, const Shape<T>& b) {
  const std::uint64_t before = detail::exact_evaluations;
  const bool got = overlaps(a, b);
  t.exact_calls += detail::exact_evaluations != before;
  const bool met = contact(a, b).has_value();
  const bool exact = oracle::overlaps(a, b);
  ++t.cases;
  ++t.overlap_cases;
  ++t.per_label[label];
  if (got == exact && met == exact) return;
  ++t.disagreements;
  if (++t.bad_label[label] <= 2 && !t.save_dir.empty()) {
    const std::string source = "adversarial exact_decisions seed " + std::to_string(t.seed);
    const auto path = laws::save_case(
        t.save_dir, got != exact ? laws::make_case<T>(laws::Law::Agreement, a, b, laws::agreement(a, b), source)
                                 : laws::make_case<T>(laws::Law::Contact, a, b, laws::contact_law(a, b), source));
    std::printf("saved %s\n", path.string().c_str());
  }
  if (t.printed++ < 8)
    std::printf("DISAGREE %s: overlaps %d, contact %d, exact %d\n  a = %s\n  b = %s\n", label.c_str(), got, met, exact,
                text(a).c_str(), text(b).c_str());
}

template <Scalar T>
void judge_point(Tally& t, const std::string& label, const Shape<T>& s, const Vec2<T>& p) {
  const std::uint64_t before = detail::exact_evaluations;
  const bool got = contains(s, p);
  t.exact_calls += detail::exact_evaluations != before;
  const bool exact = oracle::contains(s, p);
  ++t.cases;
  ++t.contains_cases;
  ++t.per_label[label];
  if (got == exact) return;
  ++t.disagreements;
  ++t.bad_label[label];
  if (t.printed++ < 8)
    std::printf("DISAGREE %s: contains %d, exact %d\n  s = %s\n  p = (%a, %a)\n", label.c_str(), got, exact,
                text(s).c_str(), double(p.x()), double(p.y()));
}

template <Scalar T>
std::vector<double> scales() {
  if constexpr (std::is_same_v<T, float>) {
    return {1e-30, 1e-10, 1, 1e10, 0x1p100};
  } else {
    return {1e-30, 1e-10, 1, 1e10, 0x1p100, 0x1p200, 0x1p300, 0x1p400};
  }
}

std::vector<Local> make_parts(Rng& g, int kind, double base_angle) {
  std::vector<Local> parts;
  if (kind < 5) {
    parts.push_back(make_local(g, kind, base_angle));
    return parts;
  }
  const int n = 2 + g.below(2);
  for (int i = 0; i < n; ++i) {
    Local l = make_local(g, g.below(5), base_angle);
    const Vec2c d(g.in(-0.3, 0.3), g.in(-0.3, 0.3));
    for (Vec2c& p : l.pts) p += d;
    parts.push_back(l);
  }
  return parts;
}

/// One boundary: a and b (or a and a point) with b sliding along a direction; judged at the flip
/// and at 1..4 ulps around it.
template <Scalar T>
void one_boundary(Rng& g, Tally& t) {
  const auto sc = scales<T>();
  const double scale = sc[std::size_t(g.below(int(sc.size())))];
  const double offs[] = {0, 1e6, 1e15, 0x1p100};
  const double off = offs[g.below(4)];
  const Vec2c offset(g.below(2) ? off : -off, g.below(2) ? off : 0.0);
  const double base_angle = pick_angle(g);
  const int ka = g.below(6);
  const std::vector<Local> pa = make_parts(g, ka, base_angle);
  const auto a = place_all<T>(pa, scale, offset, Vec2c::Zero());
  if (!a) {
    ++t.skipped;
    return;
  }
  // Slide along a face normal of the shared angle half the time (near-parallel edges meet).
  const double dir_angle = g.below(2) ? base_angle + std::numbers::pi / 2 * g.below(4) : pick_angle(g);
  const Vec2c dir(std::cos(dir_angle), std::sin(dir_angle));
  const std::string scalar = std::is_same_v<T, float> ? "float" : "double";

  if (g.below(4) == 0) {  // contains
    const std::string label = std::string("contains-") + kKindName[ka] + "-" + scalar;
    const Vec2c start = pa[0].pts[0];
    auto point_at = [&](double lam) { return Vec2<T>((offset + scale * (start + lam * dir)).template cast<T>()); };
    const auto f = flip([&](double lam) -> std::optional<bool> { return contains(*a, point_at(lam)); }, 4.0);
    if (!f) {
      ++t.skipped;
      return;
    }
    for (double lam : {f->first, f->second}) {
      const Vec2<T> p = point_at(lam);
      for (int kx = -4; kx <= 4; ++kx) {
        for (int ky = -4; ky <= 4; ky += 4) judge_point(t, label, *a, Vec2<T>(ulps(p.x(), kx), ulps(p.y(), ky)));
      }
    }
    return;
  }

  const int kb = g.below(6);
  const std::vector<Local> pb = make_parts(g, kb, base_angle);
  const std::string label = std::string(kKindName[std::min(ka, kb)]) + "_" + kKindName[std::max(ka, kb)] + "-" + scalar;
  auto b_at = [&](double lam) { return place_all<T>(pb, scale, offset, lam * dir); };
  const auto f = flip(
      [&](double lam) -> std::optional<bool> {
        const auto b = b_at(lam);
        if (!b) return std::nullopt;
        return overlaps(*a, *b);
      },
      6.0);
  if (!f) {
    ++t.skipped;
    return;
  }
  for (double lam : {f->first, f->second}) {
    const auto b = b_at(lam);
    if (!b) continue;
    judge_pair(t, label, *a, *b);
    for (int k = 1; k <= 4; ++k) {
      for (const auto& [kx, ky] : {std::pair{k, 0}, std::pair{-k, 0}, std::pair{0, k}, std::pair{0, -k}}) {
        if (const auto nb = nudged(*b, kx, ky)) judge_pair(t, label, *a, *nb);
      }
    }
  }
}

/// Exactly touching round shapes on Pythagorean distances (3, 4, 5) k s at every offset, then
/// nudged: the one family where touching is exact without being axis-aligned.
template <Scalar T>
void pythagorean(Rng& g, Tally& t) {
  const auto sc = scales<T>();
  const double s = sc[std::size_t(g.below(int(sc.size())))];
  const double offs[] = {0, 1e6, 1e15, 0x1p100};
  const double o = offs[g.below(4)];
  const double k = double(1 + g.below(64));
  const T ra = static_cast<T>(s * k * (1 + g.below(4))), rb = static_cast<T>(s * k * 5) - ra;
  const Vec2<T> ca = Vec2c(o, o).template cast<T>();
  const Vec2<T> d = Vec2c(3 * k * s, 4 * k * s).template cast<T>();
  const std::string scalar = std::is_same_v<T, float> ? "float" : "double";
  for (int kx = -4; kx <= 4; ++kx) {
    const Vec2<T> cb(ulps(T(ca.x() + d.x()), kx), T(ca.y() + d.y()));
    auto a = Circle<T>::make(ca, ra);
    auto b = Circle<T>::make(cb, rb);
    if (a && b) judge_pair(t, "circle_circle-" + scalar, Shape<T>(a.value()), Shape<T>(b.value()));
    // The same against a capsule whose end is at cb.
    auto c = Capsule<T>::make(cb, Vec2<T>(cb.x() + T(d.x()), cb.y()), rb);
    if (a && c) judge_pair(t, "circle_capsule-" + scalar, Shape<T>(a.value()), Shape<T>(c.value()));
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t cases = 200000, seed = 1;
  std::string save_dir;
  CLI::App app{"Adversarial boundary cases of the exact decisions, judged by the exact oracle"};
  app.add_option("--cases", cases, "cases to generate (ctest and the mutation score: the default)");
  app.add_option("--seed", seed, "generator seed");
  app.add_option("--save-cases", save_dir, "write each failing case as a case file into this folder");
  CLI11_PARSE(app, argc, argv);
  Rng g{seed};
  Tally t;
  t.save_dir = save_dir;
  t.seed = seed;
  const auto start = std::chrono::steady_clock::now();
  while (t.cases < cases) {
    const int what = g.below(10);
    if (what == 0) {
      g.below(2) ? pythagorean<float>(g, t) : pythagorean<double>(g, t);
    } else {
      what % 2 ? one_boundary<float>(g, t) : one_boundary<double>(g, t);
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "exact decisions: %llu cases (%llu overlaps, %llu contains; %llu generated boundaries skipped), "
      "%llu disagreements, %.1f s, seed %llu\n",
      (unsigned long long)t.cases, (unsigned long long)t.overlap_cases, (unsigned long long)t.contains_cases,
      (unsigned long long)t.skipped, (unsigned long long)t.disagreements, secs, (unsigned long long)seed);
  std::printf("filter decided %.1f %% of these calls without an exact evaluation\n",
              100.0 * double(t.cases - t.exact_calls) / double(t.cases));
  for (const auto& [label, n] : t.per_label) {
    const auto bad = t.bad_label.count(label) ? t.bad_label.at(label) : 0;
    std::printf("  %-28s %9llu%s\n", label.c_str(), (unsigned long long)n,
                bad ? (" DISAGREEMENTS " + std::to_string(bad)).c_str() : "");
  }
  return t.disagreements == 0 ? 0 : 1;
}
