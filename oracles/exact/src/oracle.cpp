/// @file oracle.cpp
/// The exact oracle. Every primitive is a convex core (point, segment or convex polygon with
/// rational vertices) dilated by a radius r. Each question reduces to signs of polynomials in the
/// stored doubles (orientations, dot products, squared distances written without division), so it
/// is decided exactly.
///
/// Filtering, per predicate: every sign is first evaluated in interval arithmetic
/// (CGAL::Interval_nt_advanced under upward rounding); when an interval sign is not certain, that
/// one sign is evaluated again exactly. Every filtered expression is a polynomial in the stored doubles
/// (no division), so the exact pass uses CGAL::Gmpzf (GMP integer mantissa, binary exponent: exact
/// ring operations without the gcd of rationals). Both passes share one template, so the fast path
/// cannot disagree with the exact one. Reported distances use CGAL::Exact_rational.

#include "collide/oracle/oracle.hpp"

#include <CGAL/Exact_rational.h>
#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/Interval_nt.h>
#include <boost/container/small_vector.hpp>
#include <gmp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace collide::oracle {

namespace {

using Interval = CGAL::Interval_nt_advanced;
using Exact = CGAL::Gmpzf;              // exact +, -, * (no gcd): the fallback pass
using Rational = CGAL::Exact_rational;  // with division: exact distances for reports
using Vec2d = Vec2<double>;

int sign_of(const Exact& x) {
  return static_cast<int>(CGAL::sign(x));
}
int sign_of(const Rational& x) {
  return static_cast<int>(CGAL::sign(x));
}

void require_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw InvalidInput(std::string("oracle: non-finite ") + what);
}
void require_finite(const Vec2d& v, const char* what) {
  require_finite(v.x(), what);
  require_finite(v.y(), what);
}

// ---------------------------------------------------------------------------------------------
// CoreInput: the exact input data of one primitive, its convex core and radius (doubles only; the
// rational vertices are made per pass).

struct CoreInput {
  bool is_obb = false;
  boost::container::small_vector<Vec2d, 8> points;  // 1 point, 2 segment, >= 3 CCW convex polygon
  Vec2d center{0, 0}, axis{1, 0};                   // OBB: corners center +- hx*u +- hy*v
  double hx = 0, hy = 0;
  double radius = 0;
  /// Placements applied to every core point, first to last: x -> R(q) x + p with the stored q
  /// (a compound child's own transform, then its body's), evaluated exactly.
  boost::container::small_vector<std::pair<Vec2d, Vec2d>, 2> poses;
};

void require_pose(const Vec2d& p, const Vec2d& q) {
  require_finite(p, "transform position");
  require_finite(q, "transform rotation");
}

CoreInput core_input_of(const Circle<double>& s) {
  require_finite(s.center(), "circle center");
  require_finite(s.radius(), "circle radius");
  CoreInput out;
  out.points.push_back(s.center());
  out.radius = s.radius();
  return out;
}
CoreInput core_input_of(const Aabb<double>& s) {
  require_finite(s.min(), "AABB min");
  require_finite(s.max(), "AABB max");
  const Vec2d lo = s.min(), hi = s.max();
  CoreInput out;
  const bool flat_x = lo.x() == hi.x(), flat_y = lo.y() == hi.y();
  if (flat_x && flat_y) {
    out.points.push_back(lo);
  } else if (flat_x || flat_y) {
    out.points.push_back(lo);
    out.points.push_back(hi);
  } else {
    out.points.assign({lo, Vec2d(hi.x(), lo.y()), hi, Vec2d(lo.x(), hi.y())});
  }
  return out;
}
CoreInput core_input_of(const Obb<double>& s) {
  require_finite(s.center(), "OBB center");
  require_finite(s.half_extents(), "OBB half extents");
  require_finite(s.axis(), "OBB axis");
  CoreInput out;
  out.is_obb = true;
  out.center = s.center();
  out.axis = s.axis();
  out.hx = s.half_extents().x();
  out.hy = s.half_extents().y();
  return out;
}
CoreInput core_input_of(const Capsule<double>& s) {
  require_finite(s.a(), "capsule end");
  require_finite(s.b(), "capsule end");
  require_finite(s.radius(), "capsule radius");
  CoreInput out;
  out.points.push_back(s.a());
  if (s.b() != s.a()) out.points.push_back(s.b());
  out.radius = s.radius();
  return out;
}
CoreInput core_input_of(const ConvexPolygon<double>& s) {
  CoreInput out;
  for (const Vec2d& p : s.vertices()) {
    require_finite(p, "polygon vertex");
    out.points.push_back(p);
  }
  return out;
}
CoreInput core_input_of(const Primitive<double>& s) {
  return std::visit([](const auto& x) { return core_input_of(x); }, s);
}
CoreInput point_spec(const Vec2d& p) {
  require_finite(p, "point");
  CoreInput out;
  out.points.push_back(p);
  return out;
}
CoreInput segment_spec(const Vec2d& p, const Vec2d& q) {
  CoreInput out = point_spec(p);
  require_finite(q, "point");
  if (q != p) out.points.push_back(q);
  return out;
}

/// The primitives of a shape: itself, or a compound's children. A compound of one child is that
/// child placed by its child transform: the questions defined for primitives only answer for it.
struct Parts {
  boost::container::small_vector<CoreInput, 1> items;
  bool compound = false;  ///< more than one child
};

/// The primitives of a placed shape, each with its chain of placements (child, then body).
Parts parts_of(const Placed& s) {
  require_pose(s.position, s.rotation);
  const bool body = !(s.position == Vec2d(0, 0) && s.rotation == Vec2d(1, 0));
  Parts out;
  std::visit(
      [&](const auto& x) {
        using S = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<S, Compound<double>>) {
          out.compound = x.children().size() > 1;
          for (std::size_t i = 0; i < x.children().size(); ++i) {
            CoreInput c = core_input_of(x.children()[i]);
            const Transform<double> t = x.child_transform(i);
            if (!t.is_identity()) c.poses.emplace_back(t.position(), t.rotation());
            out.items.push_back(std::move(c));
          }
        } else {
          out.items.push_back(core_input_of(x));
        }
      },
      s.shape);
  if (body) {
    for (CoreInput& c : out.items) c.poses.emplace_back(s.position, s.rotation);
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Geometry over a number type NT (Interval, Exact, Rational).

template <class NT>
struct P {
  NT x, y;
};
template <class NT>
P<NT> sub(const P<NT>& a, const P<NT>& b) {
  return {NT(a.x - b.x), NT(a.y - b.y)};
}
template <class NT>
NT cross(const P<NT>& a, const P<NT>& b) {
  return NT(a.x * b.y - a.y * b.x);
}
template <class NT>
NT dot(const P<NT>& a, const P<NT>& b) {
  return NT(a.x * b.x + a.y * b.y);
}
template <class NT>
int orient(const P<NT>& a, const P<NT>& b, const P<NT>& c) {
  return sign_of(cross(sub(b, a), sub(c, a)));
}
template <class NT>
bool same_point(const P<NT>& a, const P<NT>& b) {
  return sign_of(NT(a.x - b.x)) == 0 && sign_of(NT(a.y - b.y)) == 0;
}

/// A convex core: 1 vertex (point), 2 (segment, distinct ends) or >= 3 (CCW convex polygon).
template <class NT>
struct Core {
  boost::container::small_vector<P<NT>, 8> v;
  NT radius;
  std::size_t edge_count() const { return v.size() < 2 ? 0 : (v.size() == 2 ? 1 : v.size()); }
  const P<NT>& at(std::size_t i) const { return v[i % v.size()]; }
};

template <class NT>
P<NT> point_of(const Vec2d& p, const P<NT>* shift) {
  if (shift) return {NT(NT(p.x()) + shift->x), NT(NT(p.y()) + shift->y)};
  return {NT(p.x()), NT(p.y())};
}

/// The input's rational vertices, placed by its poses (exact), then moved by *shift when given.
template <class NT>
Core<NT> realize_local(const CoreInput& s, const P<NT>* shift);

template <class NT>
Core<NT> realize(const CoreInput& s, const P<NT>* shift = nullptr) {
  if (s.poses.empty()) return realize_local<NT>(s, shift);
  Core<NT> c = realize_local<NT>(s, nullptr);
  for (const auto& [p, q] : s.poses) {
    const NT px(p.x()), py(p.y()), qx(q.x()), qy(q.y());
    for (P<NT>& v : c.v) v = P<NT>{NT(qx * v.x - qy * v.y + px), NT(qy * v.x + qx * v.y + py)};
  }
  if (shift) {
    for (P<NT>& v : c.v) v = P<NT>{NT(v.x + shift->x), NT(v.y + shift->y)};
  }
  return c;
}

template <class NT>
Core<NT> realize_local(const CoreInput& s, const P<NT>* shift) {
  Core<NT> c;
  c.radius = NT(s.radius);
  if (!s.is_obb) {
    for (const Vec2d& p : s.points) c.v.push_back(point_of<NT>(p, shift));
    return c;
  }
  // center +- hx*u +- hy*v with v = (-u.y, u.x), all exact.
  const NT cx(s.center.x()), cy(s.center.y()), ux(s.axis.x()), uy(s.axis.y());
  const NT hx(s.hx), hy(s.hy);
  const NT ax = hx * ux, ay = hx * uy;     // hx*u
  const NT bx = -(hy * uy), by = hy * ux;  // hy*v
  auto corner = [&](int su, int sv) {
    NT x = cx, y = cy;
    if (su > 0) {
      x += ax;
      y += ay;
    }
    if (su < 0) {
      x -= ax;
      y -= ay;
    }
    if (sv > 0) {
      x += bx;
      y += by;
    }
    if (sv < 0) {
      x -= bx;
      y -= by;
    }
    if (shift) {
      x += shift->x;
      y += shift->y;
    }
    return P<NT>{x, y};
  };
  const bool zx = s.hx == 0, zy = s.hy == 0;
  if (zx && zy) {
    c.v.push_back(corner(0, 0));
  } else if (zx) {
    c.v.push_back(corner(0, -1));
    c.v.push_back(corner(0, 1));
  } else if (zy) {
    c.v.push_back(corner(-1, 0));
    c.v.push_back(corner(1, 0));
  } else {
    c.v.push_back(corner(-1, -1));
    c.v.push_back(corner(1, -1));
    c.v.push_back(corner(1, 1));
    c.v.push_back(corner(-1, 1));
  }
  return c;
}

template <class NT>
NT max_of(const NT& a, const NT& b) {
  if constexpr (std::is_same_v<NT, Interval>) {
    return Interval(std::max(a.inf(), b.inf()), std::max(a.sup(), b.sup()));  // encloses the max
  } else {
    return a < b ? b : a;
  }
}

/// Support of the Minkowski difference D = Q - P in direction n (not unit):
/// max over q of q.n - min over p of p.n. Intervals enclose the max without deciding ties.
template <class NT>
NT support_difference(const Core<NT>& p, const Core<NT>& q, const P<NT>& n) {
  NT hq = dot(q.v[0], n), lp = NT(-dot(p.v[0], n));
  for (std::size_t j = 1; j < q.v.size(); ++j) hq = max_of(hq, dot(q.v[j], n));
  for (std::size_t i = 1; i < p.v.size(); ++i) lp = max_of(lp, NT(-dot(p.v[i], n)));
  return NT(hq + lp);
}

/// Calls f(n) with both normals (+-) of every edge of P and of Q: a superset of the facet
/// normals of D = Q - P.
template <class NT, class F>
void for_each_candidate_normal(const Core<NT>& p, const Core<NT>& q, F&& f) {
  for (const Core<NT>* c : {&p, &q}) {
    for (std::size_t i = 0; i < c->edge_count(); ++i) {
      const P<NT> e = sub(c->at(i + 1), c->v[i]);
      const P<NT> n{NT(-e.y), e.x};
      f(n);
      f(P<NT>{e.y, NT(-e.x)});
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Filtering, one predicate at a time: each sign is computed in intervals from the interval core;
// only an uncertain sign is recomputed exactly, from the exact core (built on first need).
// Callers hold CGAL::Protect_FPU_rounding<true> (upward rounding) for the whole question; the
// exact type uses no floating-point arithmetic, so it is unaffected by the rounding mode.

/// A primitive's core in intervals (always) and exactly (on demand), optionally moved by shift.
class DualCore {
 public:
  explicit DualCore(const CoreInput& s, const Vec2d* shift = nullptr)
      : input_(&s), shift_(shift), interval_(make<Interval>()) {}
  template <class NT>
  const Core<NT>& get() const {
    if constexpr (std::is_same_v<NT, Interval>) {
      return interval_;
    } else {
      if (!exact_) exact_.emplace(make<Exact>());
      return *exact_;
    }
  }
  std::size_t size() const { return interval_.v.size(); }
  std::size_t edge_count() const { return interval_.edge_count(); }
  double radius() const { return input_->radius; }

  /// True when boxes enclosing the two cores grown by their radii (pad = 1) or not (pad = 0)
  /// are disjoint: then the shapes certainly do not meet. Bounds come from the intervals.
  static bool boxes_apart(const DualCore& a, const DualCore& b, bool pad) {
    const double ra = pad ? a.radius() : 0.0, rb = pad ? b.radius() : 0.0;
    double alo[2], ahi[2], blo[2], bhi[2];
    a.enclose(ra, alo, ahi);
    b.enclose(rb, blo, bhi);
    for (int k = 0; k < 2; ++k) {
      if (ahi[k] < blo[k] || bhi[k] < alo[k]) return true;
    }
    return false;
  }

 private:
  template <class NT>
  Core<NT> make() const {
    if (!shift_) return realize<NT>(*input_);
    const P<NT> t{NT(shift_->x()), NT(shift_->y())};
    return realize<NT>(*input_, &t);
  }
  /// Box enclosing the core grown by r (upward rounding is in force: the sums round outward
  /// by computing the lower bound as -(-lo + r)).
  void enclose(double r, double* lo, double* hi) const {
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::numeric_limits<double>::infinity();
      hi[k] = -lo[k];
    }
    for (const P<Interval>& v : interval_.v) {
      lo[0] = std::min(lo[0], v.x.inf());
      lo[1] = std::min(lo[1], v.y.inf());
      hi[0] = std::max(hi[0], v.x.sup());
      hi[1] = std::max(hi[1], v.y.sup());
    }
    for (int k = 0; k < 2; ++k) {
      lo[k] = -(-lo[k] + r);
      hi[k] = hi[k] + r;
    }
  }
  const CoreInput* input_;
  const Vec2d* shift_;
  Core<Interval> interval_;
  mutable std::optional<Core<Exact>> exact_;
};

/// Vertex k (cyclic) of a dual core.
struct Vx {
  const DualCore* c;
  std::size_t k;
  template <class NT>
  const P<NT>& get() const {
    const Core<NT>& core = c->template get<NT>();
    return core.v[k % core.v.size()];
  }
};

/// Sign of f(NT{}) (a value computed from exact inputs): intervals first, exact if uncertain.
template <class F>
int fsign(F&& f) {
  const Interval v = f(Interval{});
  const double lo = v.inf(), hi = v.sup();
  if (lo <= hi) {  // false for NaN bounds (inf - inf after overflow)
    if (lo > 0) return 1;
    if (hi < 0) return -1;
    if (lo == 0 && hi == 0) return 0;
  }
  return sign_of(f(Exact{}));
}

int orient(Vx a, Vx b, Vx c) {
  return fsign([&](auto tag) {
    using NT = decltype(tag);
    const P<NT>& pa = a.get<NT>();
    return cross(sub(b.get<NT>(), pa), sub(c.get<NT>(), pa));
  });
}

/// p on the closed segment [a, b], given that the three are collinear.
bool between(Vx p, Vx a, Vx b) {
  return fsign([&](auto tag) {
           using NT = decltype(tag);
           return dot(sub(p.get<NT>(), a.get<NT>()), sub(p.get<NT>(), b.get<NT>()));
         }) <= 0;
}

bool same_point(Vx a, Vx b) {
  return fsign([&](auto tag) {
           using NT = decltype(tag);
           return NT(a.get<NT>().x - b.get<NT>().x);
         }) == 0 &&
         fsign([&](auto tag) {
           using NT = decltype(tag);
           return NT(a.get<NT>().y - b.get<NT>().y);
         }) == 0;
}

/// p in the closed core.
bool point_in(Vx p, const DualCore& c) {
  if (c.size() == 1) return same_point(p, Vx{&c, 0});
  if (c.size() == 2) return orient(Vx{&c, 0}, Vx{&c, 1}, p) == 0 && between(p, Vx{&c, 0}, Vx{&c, 1});
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (orient(Vx{&c, i}, Vx{&c, i + 1}, p) < 0) return false;
  }
  return true;
}

/// The closed segments [a, b] and [c, d] share a point.
bool segments_meet(Vx a, Vx b, Vx c, Vx d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d);
  if (o1 * o2 > 0) return false;
  const int o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o3 * o4 > 0) return false;
  if (o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0) return true;  // proper crossing
  // An end lies on the other segment's line: the segments meet iff it lies on that segment.
  return (o1 == 0 && between(c, a, b)) || (o2 == 0 && between(d, a, b)) || (o3 == 0 && between(a, c, d)) ||
         (o4 == 0 && between(b, c, d));
}

/// The boxes enclosing the segments' interval vertices are disjoint: the segments cannot meet.
bool edge_boxes_apart(Vx a, Vx b, Vx c, Vx d) {
  const P<Interval>&pa = a.get<Interval>(), &pb = b.get<Interval>(), &pc = c.get<Interval>(), &pd = d.get<Interval>();
  return std::max(pa.x.sup(), pb.x.sup()) < std::min(pc.x.inf(), pd.x.inf()) ||
         std::max(pc.x.sup(), pd.x.sup()) < std::min(pa.x.inf(), pb.x.inf()) ||
         std::max(pa.y.sup(), pb.y.sup()) < std::min(pc.y.inf(), pd.y.inf()) ||
         std::max(pc.y.sup(), pd.y.sup()) < std::min(pa.y.inf(), pb.y.inf());
}

/// The cores share a point: a vertex of one lies in the other, or two edges meet.
bool cores_meet(const DualCore& p, const DualCore& q) {
  if (DualCore::boxes_apart(p, q, false)) return false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (point_in(Vx{&p, i}, q)) return true;
  }
  for (std::size_t j = 0; j < q.size(); ++j) {
    if (point_in(Vx{&q, j}, p)) return true;
  }
  for (std::size_t i = 0; i < p.edge_count(); ++i) {
    for (std::size_t j = 0; j < q.edge_count(); ++j) {
      if (edge_boxes_apart(Vx{&p, i}, Vx{&p, i + 1}, Vx{&q, j}, Vx{&q, j + 1})) continue;
      if (segments_meet(Vx{&p, i}, Vx{&p, i + 1}, Vx{&q, j}, Vx{&q, j + 1})) return true;
    }
  }
  return false;
}

/// sign(dist(p, [a, b])^2 - x), division-free; x is a callable giving the threshold in NT.
template <class X>
int sign_point_segment(Vx p, Vx a, Vx b, const X& x) {
  const int st = fsign([&](auto tag) {
    using NT = decltype(tag);
    return dot(sub(p.get<NT>(), a.get<NT>()), sub(b.get<NT>(), a.get<NT>()));
  });
  auto to_point = [&](Vx q) {
    return fsign([&](auto tag) {
      using NT = decltype(tag);
      const P<NT> w = sub(p.get<NT>(), q.get<NT>());
      return NT(dot(w, w) - x(tag));
    });
  };
  if (st <= 0) return to_point(a);
  const int s2 = fsign([&](auto tag) {
    using NT = decltype(tag);
    const P<NT> e = sub(b.get<NT>(), a.get<NT>());
    return NT(dot(sub(p.get<NT>(), a.get<NT>()), e) - dot(e, e));
  });
  if (s2 >= 0) return to_point(b);
  return fsign([&](auto tag) {
    using NT = decltype(tag);
    const P<NT> e = sub(b.get<NT>(), a.get<NT>());
    const NT c = cross(e, sub(p.get<NT>(), a.get<NT>()));
    return NT(c * c - x(tag) * dot(e, e));
  });
}

/// min over the features (point / segment / edges) f of q of sign(dist(p, f)^2 - x).
template <class X>
int sign_point_features(Vx p, const DualCore& q, const X& x) {
  if (q.size() == 1) {
    return fsign([&](auto tag) {
      using NT = decltype(tag);
      const P<NT> w = sub(p.get<NT>(), Vx{&q, 0}.get<NT>());
      return NT(dot(w, w) - x(tag));
    });
  }
  int best = 1;
  for (std::size_t j = 0; j < q.edge_count() && best > -1; ++j) {
    best = std::min(best, sign_point_segment(p, Vx{&q, j}, Vx{&q, j + 1}, x));
  }
  return best;
}

/// sign(dist(P, Q)^2 - x) for x >= 0. Disjoint convex cores are closest at a vertex of one and a
/// feature of the other.
template <class X>
int sign_dist2_minus(const DualCore& p, const DualCore& q, const X& x) {
  if (cores_meet(p, q)) return -fsign(x);
  int best = 1;
  for (std::size_t i = 0; i < p.size() && best > -1; ++i) best = std::min(best, sign_point_features(Vx{&p, i}, q, x));
  for (std::size_t j = 0; j < q.size() && best > -1; ++j) best = std::min(best, sign_point_features(Vx{&q, j}, p, x));
  return best;
}

/// Threshold callables: a constant double, and the square of a callable.
auto constant(double v) {
  return [v](auto tag) { return decltype(tag)(v); };
}
template <class X>
auto squared(const X& x) {
  return [&x](auto tag) {
    using NT = decltype(tag);
    const NT v = x(tag);
    return NT(v * v);
  };
}

/// The dilated cores overlap: dist^2 <= (ra + rb)^2.
bool dilated_meet(const DualCore& p, const DualCore& q) {
  if (DualCore::boxes_apart(p, q, true)) return false;
  if (p.radius() == 0 && q.radius() == 0) return cores_meet(p, q);
  const double ra = p.radius(), rb = q.radius();
  auto r = [ra, rb](auto tag) {
    using NT = decltype(tag);
    return NT(NT(ra) + NT(rb));
  };
  return sign_dist2_minus(p, q, squared(r)) <= 0;
}

/// For p inside the convex polygon c: min over edges of sign(dist(p, edge line)^2 - x^2), x >= 0.
template <class X>
int sign_boundary_minus(Vx p, const DualCore& c, const X& x) {
  int best = 1;
  for (std::size_t i = 0; i < c.size() && best > -1; ++i) {
    best = std::min(best, fsign([&](auto tag) {
                      using NT = decltype(tag);
                      const P<NT>& a = Vx{&c, i}.get<NT>();
                      const P<NT> e = sub(Vx{&c, i + 1}.get<NT>(), a);
                      const NT h = cross(e, sub(p.get<NT>(), a));
                      const NT xv = x(tag);
                      return NT(h * h - xv * xv * dot(e, e));
                    }));
  }
  return best;
}

/// For cores that meet (origin in D = Q - P): sign(dist(0, boundary of D) - x), x >= 0.
/// dist(0, boundary of D) = min over D's facet normals n of h_D(n) / |n|, each h_D(n) >= 0, so the
/// sign is the min over candidate normals of sign(h^2 - x^2 |n|^2). Two points: D is a point, 0.
template <class X>
int sign_inner_depth_minus(const DualCore& p, const DualCore& q, const X& x) {
  if (p.size() == 1 && q.size() == 1) return -fsign(x);
  int best = 1;
  for (const DualCore* c : {&p, &q}) {
    for (std::size_t i = 0; i < c->edge_count() && best > -1; ++i) {
      for (int side : {1, -1}) {
        best = std::min(best, fsign([&](auto tag) {
                          using NT = decltype(tag);
                          const P<NT> e = sub(Vx{c, i + 1}.get<NT>(), Vx{c, i}.get<NT>());
                          const P<NT> n = side > 0 ? P<NT>{NT(-e.y), e.x} : P<NT>{e.y, NT(-e.x)};
                          const NT h = support_difference(p.get<NT>(), q.get<NT>(), n);
                          const NT xv = x(tag);
                          return NT(CGAL::square(h) - xv * xv * dot(n, n));
                        }));
      }
    }
  }
  return best;
}

// ---------------------------------------------------------------------------------------------
// Primitive-pair questions. Each holds upward rounding for its interval arithmetic.

using Upward = CGAL::Protect_FPU_rounding<true>;

bool prim_overlaps(const CoreInput& a, const CoreInput& b, const Vec2d* shift_a = nullptr) {
  Upward upward;
  const DualCore ca(a, shift_a), cb(b);
  return dilated_meet(ca, cb);
}

/// sign(gap(a, b) - d).
int prim_compare_distance(const CoreInput& a, const CoreInput& b, double d) {
  Upward upward;
  const DualCore ca(a), cb(b);
  const double ra = a.radius, rb = b.radius;
  auto r = [&](auto tag) {
    using NT = decltype(tag);
    return NT(NT(ra) + NT(rb));
  };
  if (sign_dist2_minus(ca, cb, squared(r)) <= 0) return d > 0 ? -1 : (d < 0 ? 1 : 0);  // gap 0
  auto y = [&](auto tag) {
    using NT = decltype(tag);
    return NT(r(tag) + NT(d));
  };
  if (fsign(y) < 0) return 1;
  return sign_dist2_minus(ca, cb, squared(y));
}

/// sign(depth(a, b) - len). See the header for the definition of depth. With D = Qb - Pa (cores):
/// depth = dist(0, boundary of D) + r when the cores meet, else max(0, r - dist(Pa, Pb)).
int prim_compare_depth(const CoreInput& a, const CoreInput& b, double len) {
  Upward upward;
  const DualCore ca(a), cb(b);
  const double ra = a.radius, rb = b.radius;
  if (cores_meet(ca, cb)) {
    auto x = [&](auto tag) {
      using NT = decltype(tag);
      return NT(NT(len) - NT(ra) - NT(rb));
    };
    if (fsign(x) < 0) return 1;
    return sign_inner_depth_minus(ca, cb, x);
  }
  auto r = [&](auto tag) {
    using NT = decltype(tag);
    return NT(NT(ra) + NT(rb));
  };
  if (sign_dist2_minus(ca, cb, squared(r)) >= 0) return len > 0 ? -1 : (len < 0 ? 1 : 0);  // depth 0
  auto y = [&](auto tag) {  // depth = r - dist(Pa, Pb) > 0
    using NT = decltype(tag);
    return NT(NT(ra) + NT(rb) - NT(len));
  };
  if (fsign(y) < 0) return -1;
  return -sign_dist2_minus(ca, cb, squared(y));
}

/// sign(distance from p to the boundary of the dilated core - d).
int prim_compare_boundary(const CoreInput& s, const Vec2d& p, double d) {
  Upward upward;
  const CoreInput ps = point_spec(p);
  const DualCore c(s), pt(ps);
  const double r = s.radius;
  if (sign_dist2_minus(pt, c, squared(constant(r))) > 0) {  // outside: dist(p, core) - r
    auto y = [&](auto tag) {
      using NT = decltype(tag);
      return NT(NT(r) + NT(d));
    };
    if (fsign(y) < 0) return 1;
    return sign_dist2_minus(pt, c, squared(y));
  }
  if (point_in(Vx{&pt, 0}, c)) {  // in the core: dist(p, boundary of core) + r
    auto x = [&](auto tag) {
      using NT = decltype(tag);
      return NT(NT(d) - NT(r));
    };
    if (c.size() < 3) return -fsign(x);
    if (fsign(x) < 0) return 1;
    return sign_boundary_minus(Vx{&pt, 0}, c, x);
  }
  auto y = [&](auto tag) {  // in the rim: r - dist(p, core)
    using NT = decltype(tag);
    return NT(NT(r) - NT(d));
  };
  if (fsign(y) < 0) return -1;
  return -sign_dist2_minus(pt, c, squared(y));
}

/// Some point of the closed segment [p, q] lies in the primitive deeper than d (farther than d
/// from its boundary). In the rim of a dilated core the depth is r - dist(x, core); inside a
/// polygon core it is r plus the least distance to an edge line, h_i(x) / |e_i| with h_i the
/// cross product, affine along the segment: the deep points form an interval of the segment's
/// parameter, cut by one bound per edge. Each |e_i| is rounded up, so only points deeper than d
/// count, and every point deeper than d (1 + 2^-50) does while the edges' squared lengths are
/// normal doubles (edges between 2^-511 and 2^511 long; a longer one answers false).
bool prim_passes_deeper(const CoreInput& s, const Vec2d& p, const Vec2d& q, double d) {
  Upward upward;
  const CoreInput seg = segment_spec(p, q);
  const DualCore c(s), sc(seg);
  const double r = s.radius;
  auto rim = [&](auto tag) {
    using NT = decltype(tag);
    return NT(NT(r) - NT(d));
  };
  if (fsign(rim) > 0) return sign_dist2_minus(sc, c, squared(rim)) < 0;
  if (c.size() < 3) return false;
  const Rational e = Rational(d) - Rational(r);  // >= 0: the depth needed inside the core
  const Core<Rational> core = realize<Rational>(s);
  const P<Rational> a{Rational(p.x()), Rational(p.y())}, w = sub(P<Rational>{Rational(q.x()), Rational(q.y())}, a);
  std::optional<Rational> lo, hi;  // the open interval of parameters deep enough for every edge
  for (std::size_t i = 0; i < core.v.size(); ++i) {
    const P<Rational> ev = sub(core.at(i + 1), core.at(i));
    // From the exact squared length, so that a short edge far out keeps its relative precision.
    const double length = CGAL::sqrt(Interval(CGAL::to_interval(dot(ev, ev)))).sup();
    if (!std::isfinite(length)) return false;
    // h_i(a + t w) = h0 + t k > e * length
    const Rational h0 = cross(ev, sub(a, core.at(i))), k = cross(ev, w);
    const Rational need = e * Rational(length) - h0;
    if (CGAL::is_zero(k)) {
      if (!(need < 0)) return false;
    } else if (k > 0) {
      const Rational t = need / k;
      if (!lo || *lo < t) lo = t;
    } else {
      const Rational t = need / k;
      if (!hi || t < *hi) hi = t;
    }
  }
  return (!lo || *lo < 1) && (!hi || *hi > 0) && (!lo || !hi || *lo < *hi);
}

bool prim_inside_box(const CoreInput& s, const Aabb<double>& box) {
  Upward upward;
  const DualCore c(s);
  const double r = s.radius;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Vx v{&c, i};
    for (int axis = 0; axis < 2; ++axis) {
      const double lo = box.min()[axis], hi = box.max()[axis];
      auto below = [&](auto tag) {  // v - r - lo
        using NT = decltype(tag);
        const P<NT>& q = v.get<NT>();
        return NT((axis == 0 ? q.x : q.y) - NT(r) - NT(lo));
      };
      auto above = [&](auto tag) {  // hi - v - r
        using NT = decltype(tag);
        const P<NT>& q = v.get<NT>();
        return NT(NT(hi) - (axis == 0 ? q.x : q.y) - NT(r));
      };
      if (fsign(below) < 0 || fsign(above) < 0) return false;
    }
  }
  return true;
}

/// The primitive `outer` (a convex core C dilated by R) holds the primitive `inner` (core Q
/// dilated by r): the convex hull of the discs (q, r), q a vertex of Q, lies in the convex outer
/// exactly when each disc does. A disc lies in it when its centre's signed distance to C (minus
/// the depth inside a polygon core) is at most R - r: outside C, dist(q, C)^2 <= (R - r)^2 with
/// R >= r; inside a polygon core, depth(q, C) >= r - R, each edge line's distance compared
/// squared.
bool prim_holds(const CoreInput& outer, const CoreInput& inner) {
  Upward upward;
  const DualCore co(outer), ci(inner);
  const double big = outer.radius, r = inner.radius;
  auto room = [&](auto tag) {  // R - r
    using NT = decltype(tag);
    return NT(NT(big) - NT(r));
  };
  auto need = [&](auto tag) {  // r - R
    using NT = decltype(tag);
    return NT(NT(r) - NT(big));
  };
  for (std::size_t j = 0; j < ci.size(); ++j) {
    const Vx q{&ci, j};
    if (co.size() >= 3 && point_in(q, co)) {
      if (fsign(need) > 0 && sign_boundary_minus(q, co, need) < 0) return false;
      continue;
    }
    if (fsign(room) < 0 || sign_point_features(q, co, squared(room)) > 0) return false;
  }
  return true;
}

/// Exact squared distance between the cores (0 when they meet).
Rational core_dist2(const Core<Rational>& p, const Core<Rational>& q, bool meet) {
  if (meet) return Rational(0);
  auto point_segment = [](const P<Rational>& x, const P<Rational>& a, const P<Rational>& b) -> Rational {
    const P<Rational> e = sub(b, a), w = sub(x, a);
    const Rational t = dot(w, e), len2 = dot(e, e);
    if (sign_of(t) <= 0) return dot(w, w);
    if (sign_of(Rational(t - len2)) >= 0) return dot(sub(x, b), sub(x, b));
    const Rational c = cross(e, w);
    return Rational(c * c / len2);
  };
  auto to_features = [&](const P<Rational>& x, const Core<Rational>& c) -> Rational {
    if (c.v.size() == 1) return dot(sub(x, c.v[0]), sub(x, c.v[0]));
    Rational best = point_segment(x, c.v[0], c.at(1));
    for (std::size_t j = 1; j < c.edge_count(); ++j) best = std::min(best, point_segment(x, c.v[j], c.at(j + 1)));
    return best;
  };
  Rational best = to_features(p.v[0], q);
  for (const P<Rational>& a : p.v) best = std::min(best, to_features(a, q));
  for (const P<Rational>& b : q.v) best = std::min(best, to_features(b, p));
  return best;
}

/// Signed distance of two primitives, computed exactly then rounded (reports only).
double prim_signed_distance(const CoreInput& a, const CoreInput& b) {
  bool meet = false;
  {
    Upward upward;
    meet = cores_meet(DualCore(a), DualCore(b));
  }
  const Core<Rational> ca = realize<Rational>(a), cb = realize<Rational>(b);
  const Rational r = ca.radius + cb.radius;
  const Rational g2 = core_dist2(ca, cb, meet);
  const double rd = CGAL::to_double(r);
  if (g2 > r * r) return std::sqrt(CGAL::to_double(g2)) - rd;
  if (!meet) return -(rd - std::sqrt(CGAL::to_double(g2)));
  if (ca.v.size() == 1 && cb.v.size() == 1) return -rd;
  bool first = true;
  Rational h2;
  for_each_candidate_normal(ca, cb, [&](const P<Rational>& n) {
    const Rational h = support_difference(ca, cb, n);
    const Rational v = h * h / dot(n, n);
    if (first || v < h2) h2 = v;
    first = false;
  });
  return -(std::sqrt(CGAL::to_double(h2)) + rd);
}

/// Calls f(child of a, child of b) for every pair; stops when f returns true.
template <class F>
bool any_pair(const Parts& a, const Parts& b, F&& f) {
  for (const CoreInput& x : a.items) {
    for (const CoreInput& y : b.items) {
      if (f(x, y)) return true;
    }
  }
  return false;
}

// ---------------------------------------------------------------------------------------------
// Mass properties (mass.hpp's definition), exactly: areas and moments of polygons are rationals
// of the stored values; pi and a capsule's length |b - a| are not, so every quantity is a
// bracket [lo, hi] of rationals around the exact value, a point when it is rational.

using Qr = CGAL::Gmpq;

struct Bracket {
  Qr lo, hi;
};
Bracket point_bracket(const Qr& x) {
  return {x, x};
}
Bracket operator+(const Bracket& a, const Bracket& b) {
  return {a.lo + b.lo, a.hi + b.hi};
}
Bracket operator-(const Bracket& a, const Bracket& b) {
  return {a.lo - b.hi, a.hi - b.lo};
}
Bracket operator*(const Bracket& a, const Bracket& b) {
  const Qr p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]})};
}
/// a / b for b > 0 (b.lo > 0).
Bracket operator/(const Bracket& a, const Bracket& b) {
  const Qr p[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  return {std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]})};
}
bool is_zero(const Bracket& a) {
  return CGAL::is_zero(a.lo) && CGAL::is_zero(a.hi);
}

/// pi between two rationals 10^-36 apart.
Bracket pi_bracket() {
  const CGAL::Gmpz scale("1000000000000000000000000000000000000");
  const CGAL::Gmpz digits("3141592653589793238462643383279502884");
  return {Qr(digits, scale), Qr(digits + 1, scale)};
}

/// sqrt(x) for a rational x >= 0, between two rationals within 2^-119 of it relatively:
/// sqrt(n / d) = sqrt(n d 4^k) / (d 2^k), the integer square root taken low and high.
Bracket sqrt_bracket(const Qr& x) {
  if (CGAL::is_zero(x)) return point_bracket(x);
  const CGAL::Gmpz nd = x.numerator() * x.denominator();
  const long bits = long(nd.bit_size());
  const unsigned long k = bits < 240 ? static_cast<unsigned long>((241 - bits) / 2) : 0ul;
  CGAL::Gmpz wide, root, den;
  mpz_mul_2exp(wide.mpz(), nd.mpz(), 2 * k);
  mpz_sqrt(root.mpz(), wide.mpz());
  mpz_mul_2exp(den.mpz(), x.denominator().mpz(), k);
  return {Qr(root, den), Qr(root + 1, den)};
}

/// A shape's exact mass properties at unit density: area, centroid, inertia about the centroid.
struct ExactMass {
  Bracket area;
  Bracket cx, cy;
  Bracket inertia;
};

/// One primitive, in its own frame: a polygon core (radius 0) by its shoelace sums, a point core
/// as a disk, a segment core as a capsule (a rectangle and a disk split at its ends).
ExactMass primitive_mass(const CoreInput& in) {
  const Core<Qr> c = realize_local<Qr>(in, nullptr);
  const Bracket r = point_bracket(c.radius), pi = pi_bracket();
  if (c.v.size() >= 3) {
    if (!CGAL::is_zero(c.radius)) throw Unsupported("oracle: mass of a rounded polygon is not defined");
    Qr a2(0), mx(0), my(0), j(0);
    for (std::size_t i = 0; i < c.v.size(); ++i) {
      const P<Qr>&p = c.v[i], &q = c.at(i + 1);
      const Qr w = cross(p, q);
      a2 += w;
      mx += w * (p.x + q.x);
      my += w * (p.y + q.y);
      j += w * (p.x * p.x + p.x * q.x + q.x * q.x + p.y * p.y + p.y * q.y + q.y * q.y);
    }
    // Centroid sum / (3 a2); polar moment about the origin j / 12, moved to the centroid.
    const Qr cx = mx / (3 * a2), cy = my / (3 * a2);
    const Qr area = a2 / 2;
    return {point_bracket(area), point_bracket(cx), point_bracket(cy),
            point_bracket(j / 12 - area * (cx * cx + cy * cy))};
  }
  if (c.v.size() == 1) {
    const Bracket r2 = r * r;
    return {pi * r2, point_bracket(c.v[0].x), point_bracket(c.v[0].y), pi * r2 * r2 / point_bracket(Qr(2))};
  }
  const P<Qr> d = sub(c.v[1], c.v[0]);
  const Bracket l2 = point_bracket(dot(d, d)), l = sqrt_bracket(l2.lo);
  const Bracket two = point_bracket(Qr(2)), four = point_bracket(Qr(4)), six = point_bracket(Qr(6));
  const Bracket area = two * r * l + pi * r * r;
  const Bracket inertia = pi * (r * r * r * r / two + r * r * l2 / four) + two * r * r * r * l + r * l2 * l / six;
  return {area, point_bracket((c.v[0].x + c.v[1].x) / 2), point_bracket((c.v[0].y + c.v[1].y) / 2), inertia};
}

/// x's exact image of a point: R(q) c + p with q as stored.
void place_point(const Vec2d& p, const Vec2d& q, Bracket& x, Bracket& y) {
  const Bracket px = point_bracket(Qr(p.x())), py = point_bracket(Qr(p.y()));
  const Bracket qx = point_bracket(Qr(q.x())), qy = point_bracket(Qr(q.y()));
  const Bracket nx = qx * x - qy * y + px, ny = qy * x + qx * y + py;
  x = nx;
  y = ny;
}

/// A compound's exact mass properties in its frame: its children's summed, each centroid placed
/// by its child transform (parallel axes for the inertia); children all without area: the mean
/// of their centroids.
ExactMass compound_mass(const Compound<double>& c) {
  std::vector<ExactMass> kids;
  bool any_area = false;
  for (std::size_t i = 0; i < c.children().size(); ++i) {
    ExactMass m = primitive_mass(core_input_of(c.children()[i]));
    const Transform<double> t = c.child_transform(i);
    if (!t.is_identity()) {
      require_pose(t.position(), t.rotation());
      place_point(t.position(), t.rotation(), m.cx, m.cy);
    }
    any_area = any_area || !is_zero(m.area);
    kids.push_back(std::move(m));
  }
  const Bracket zero = point_bracket(Qr(0));
  ExactMass out{zero, zero, zero, zero};
  if (!any_area) {
    const Bracket count = point_bracket(Qr(static_cast<long>(kids.size())));
    for (const ExactMass& k : kids) {
      out.cx = out.cx + k.cx;
      out.cy = out.cy + k.cy;
    }
    out.cx = out.cx / count;
    out.cy = out.cy / count;
    return out;
  }
  Bracket mx = zero, my = zero;
  for (const ExactMass& k : kids) {
    out.area = out.area + k.area;
    mx = mx + k.area * k.cx;
    my = my + k.area * k.cy;
  }
  out.cx = mx / out.area;
  out.cy = my / out.area;
  for (const ExactMass& k : kids) {
    const Bracket dx = k.cx - out.cx, dy = k.cy - out.cy;
    out.inertia = out.inertia + k.inertia + k.area * (dx * dx + dy * dy);
  }
  return out;
}

/// A shape's exact mass properties in its frame.
ExactMass shape_mass(const Shape<double>& s) {
  return std::visit(
      [](const auto& x) -> ExactMass {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, Compound<double>>) {
          return compound_mass(x);
        } else {
          return primitive_mass(core_input_of(x));
        }
      },
      s);
}

/// The five outputs of mass_properties() for s at this density: mass, centroid x and y (placed by
/// s's transform), inertia about the centroid, inertia about the origin.
std::array<Bracket, 5> mass_outputs(const Placed& s, double density) {
  require_finite(density, "density");
  require_pose(s.position, s.rotation);
  const ExactMass m = shape_mass(s.shape);
  const Bracket rho = point_bracket(Qr(density));
  Bracket cx = m.cx, cy = m.cy;
  place_point(s.position, s.rotation, cx, cy);
  const Bracket mass = rho * m.area, inertia = rho * m.inertia;
  return {mass, cx, cy, inertia, inertia + mass * (cx * cx + cy * cy)};
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Public entry points.

namespace exact {

bool overlaps(const Placed& a, const Placed& b) {
  const Parts pa = parts_of(a), pb = parts_of(b);
  return any_pair(pa, pb, [](const CoreInput& x, const CoreInput& y) { return prim_overlaps(x, y); });
}

bool contains(const Placed& s, const Vec2<double>& p) {
  const Parts ps = parts_of(s);
  const CoreInput pt = point_spec(p);
  for (const CoreInput& x : ps.items) {
    if (prim_overlaps(pt, x)) return true;
  }
  return false;
}

int compare_distance(const Placed& a, const Placed& b, double d) {
  require_finite(d, "distance");
  const Parts pa = parts_of(a), pb = parts_of(b);
  int best = 1;  // sign(min gap - d) = min over child pairs of sign(gap - d)
  any_pair(pa, pb, [&](const CoreInput& x, const CoreInput& y) {
    best = std::min(best, prim_compare_distance(x, y, d));
    return best == -1;
  });
  return best;
}

bool within_band(const Placed& a, const Placed& b, double band) {
  require_finite(band, "band");
  const Parts pa = parts_of(a), pb = parts_of(b);
  const bool any_overlap = any_pair(pa, pb, [](const CoreInput& x, const CoreInput& y) { return prim_overlaps(x, y); });
  if (!any_overlap) {
    return any_pair(pa, pb,
                    [&](const CoreInput& x, const CoreInput& y) { return prim_compare_distance(x, y, band) <= 0; });
  }
  const bool deep = any_pair(pa, pb, [&](const CoreInput& x, const CoreInput& y) {
    return prim_overlaps(x, y) && prim_compare_depth(x, y, band) > 0;
  });
  return !deep;
}

bool separates(const Placed& a, const Placed& b, const Vec2<double>& t) {
  require_finite(t, "translation");
  const Parts pa = parts_of(a), pb = parts_of(b);
  return !any_pair(pa, pb, [&](const CoreInput& x, const CoreInput& y) { return prim_overlaps(x, y, &t); });
}

int compare_depth(const Placed& a, const Placed& b, double len) {
  require_finite(len, "length");
  const Parts pa = parts_of(a), pb = parts_of(b);
  if (pa.compound || pb.compound) throw Unsupported("oracle: compare_depth is not defined for compounds");
  return prim_compare_depth(pa.items[0], pb.items[0], len);
}

bool inside_box(const Placed& s, const Aabb<double>& box) {
  require_finite(box.min(), "box min");
  require_finite(box.max(), "box max");
  const Parts ps = parts_of(s);
  for (const CoreInput& x : ps.items) {
    if (!prim_inside_box(x, box)) return false;
  }
  return true;
}

bool contains_shape(const Placed& outer, const Placed& inner) {
  const Parts po = parts_of(outer), pi = parts_of(inner);
  if (po.compound) throw Unsupported("oracle: containment in a compound of several children is not defined");
  for (const CoreInput& x : pi.items) {
    if (!prim_holds(po.items[0], x)) return false;
  }
  return true;
}

int compare_boundary_distance(const Placed& s, const Vec2<double>& p, double d) {
  require_finite(p, "point");
  require_finite(d, "distance");
  const Parts ps = parts_of(s);
  if (!ps.compound) return prim_compare_boundary(ps.items[0], p, d);
  const CoreInput pt = point_spec(p);
  int best = 1;  // outside every child: distance to the union = min over children
  for (const CoreInput& x : ps.items) {
    if (prim_overlaps(pt, x))
      throw Unsupported("oracle: boundary distance of a point inside a compound is not defined");
    best = std::min(best, prim_compare_boundary(x, p, d));
  }
  return best;
}

bool segment_meets(const Placed& s, const Vec2<double>& p, const Vec2<double>& q) {
  const CoreInput seg = segment_spec(p, q);
  const Parts ps = parts_of(s);
  for (const CoreInput& x : ps.items) {
    if (prim_overlaps(seg, x)) return true;
  }
  return false;
}

bool passes_deeper(const Placed& s, const Vec2<double>& p, const Vec2<double>& q, double depth) {
  require_finite(p, "point");
  require_finite(q, "point");
  require_finite(depth, "depth");
  const Parts ps = parts_of(s);
  for (const CoreInput& x : ps.items) {
    if (prim_passes_deeper(x, p, q, depth)) return true;
  }
  return false;
}

double approx_signed_distance(const Placed& a, const Placed& b) {
  const Parts pa = parts_of(a), pb = parts_of(b);
  if (!pa.compound && !pb.compound) return prim_signed_distance(pa.items[0], pb.items[0]);
  bool hit = false;
  double gap = std::numeric_limits<double>::infinity();
  any_pair(pa, pb, [&](const CoreInput& x, const CoreInput& y) {
    if (prim_overlaps(x, y))
      hit = true;
    else
      gap = std::min(gap, prim_signed_distance(x, y));
    return hit;
  });
  return hit ? -0.0 : gap;
}

std::array<bool, kMassOutputs> mass_within(const Placed& s, double density, const MassValues& values,
                                           const MassValues& bounds) {
  const std::array<Bracket, 5> exact = mass_outputs(s, density);
  std::array<bool, kMassOutputs> out{};
  for (std::size_t k = 0; k < kMassOutputs; ++k) {
    require_finite(values[k], "mass property");
    require_finite(bounds[k], "mass property bound");
    const Qr v(values[k]), b(bounds[k]);
    out[k] = v - b <= exact[k].lo && exact[k].hi <= v + b;
  }
  return out;
}

MassValues approx_mass(const Placed& s, double density) {
  const std::array<Bracket, 5> exact = mass_outputs(s, density);
  MassValues out{};
  for (std::size_t k = 0; k < kMassOutputs; ++k) out[k] = CGAL::to_double((exact[k].lo + exact[k].hi) / 2);
  return out;
}

}  // namespace exact

}  // namespace collide::oracle
