/// @file cast_oracle.cpp
/// The exact oracle for moving shapes (shape casts and time of impact).
///
/// Linear motion. a moves to a + va s and b to b + vb s; only w = va - vb matters. For two convex
/// primitives (cores Pa, Pb dilated by ra, rb) the times s at which the gap is at most pad form an
/// interval (the gap along a line of relative positions is a convex function), so "some time in
/// [t0, t1] has gap <= pad" is one static question: the core Pa swept by w over [t0, t1] is the
/// convex hull of Pa + w t0 and Pa + w t1, and it must come within ra + rb + pad of Pb. With
/// t1 = t, pad = 0 this decides t* <= t for the first contact time t*; with t0 = t1 = t it is the
/// overlap (or the gap bound) at time t. A compound meets when some pair of children does.
///
/// Posed and placed shapes. A shape at a pose (rotation q, position p, both doubles) is the exact
/// image of its stored local values: x -> R(q) x + p with R(q) = [[qx, -qy], [qy, qx]], all exact;
/// a compound child is placed by its own transform first (as oracle::Placed defines it).
///
/// Every value is an exact binary rational (sums and products of doubles), so the whole
/// computation runs in CGAL::Gmpzf (exact +, -, *); every decision is the sign of a polynomial
/// in them (orientations, dot products, squared distances written without division).

#include "collide/oracle/oracle.hpp"

#include <CGAL/Gmpzf.h>
#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <variant>

namespace collide::oracle {

namespace {

using NT = CGAL::Gmpzf;
using Vec2d = Vec2<double>;

int sign_of(const NT& x) {
  return static_cast<int>(CGAL::sign(x));
}

void require_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw InvalidInput(std::string("oracle: non-finite ") + what);
}
void require_finite(const Vec2d& v, const char* what) {
  require_finite(v.x(), what);
  require_finite(v.y(), what);
}

struct P {
  NT x, y;
};
P sub(const P& a, const P& b) {
  return {a.x - b.x, a.y - b.y};
}
NT cross(const P& a, const P& b) {
  return a.x * b.y - a.y * b.x;
}
NT dot(const P& a, const P& b) {
  return a.x * b.x + a.y * b.y;
}
int orient(const P& a, const P& b, const P& c) {
  return sign_of(cross(sub(b, a), sub(c, a)));
}
bool less_xy(const P& a, const P& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}
bool same(const P& a, const P& b) {
  return a.x == b.x && a.y == b.y;
}

using Points = boost::container::small_vector<P, 16>;

/// A convex core: 1 point, 2 distinct points, or >= 3 counter-clockwise vertices; plus a radius.
struct Core {
  Points v;
  NT radius{0};
  std::size_t edge_count() const { return v.size() < 2 ? 0 : (v.size() == 2 ? 1 : v.size()); }
  const P& at(std::size_t i) const { return v[i % v.size()]; }
};

/// The defining points of a primitive (OBB corners exact) and its radius.
Core local_core(const Primitive<double>& s) {
  Core c;
  std::visit(
      [&](const auto& x) {
        using S = std::decay_t<decltype(x)>;
        auto push = [&](const Vec2d& p) {
          require_finite(p, "point");
          c.v.push_back({NT(p.x()), NT(p.y())});
        };
        if constexpr (std::is_same_v<S, Circle<double>>) {
          push(x.center());
          require_finite(x.radius(), "radius");
          c.radius = NT(x.radius());
        } else if constexpr (std::is_same_v<S, Aabb<double>>) {
          push(x.min());
          push(Vec2d(x.max().x(), x.min().y()));
          push(x.max());
          push(Vec2d(x.min().x(), x.max().y()));
        } else if constexpr (std::is_same_v<S, Obb<double>>) {
          require_finite(x.center(), "OBB center");
          require_finite(x.half_extents(), "OBB half extents");
          require_finite(x.axis(), "OBB axis");
          const NT cx(x.center().x()), cy(x.center().y()), ux(x.axis().x()), uy(x.axis().y());
          const NT hx(x.half_extents().x()), hy(x.half_extents().y());
          const NT ax = hx * ux, ay = hx * uy, bx = -(hy * uy), by = hy * ux;
          for (const auto& [su, sv] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
            c.v.push_back({su > 0 ? NT(cx + ax) : NT(cx - ax), su > 0 ? NT(cy + ay) : NT(cy - ay)});
            P& q = c.v.back();
            q.x = sv > 0 ? NT(q.x + bx) : NT(q.x - bx);
            q.y = sv > 0 ? NT(q.y + by) : NT(q.y - by);
          }
        } else if constexpr (std::is_same_v<S, Capsule<double>>) {
          push(x.a());
          push(x.b());
          require_finite(x.radius(), "radius");
          c.radius = NT(x.radius());
        } else {
          for (const Vec2d& p : x.vertices()) push(p);
        }
      },
      s);
  return c;
}

/// The convex hull of a point set as a core (point, segment or counter-clockwise polygon).
Core hull_of(Points pts, const NT& radius) {
  std::sort(pts.begin(), pts.end(), less_xy);
  pts.erase(std::unique(pts.begin(), pts.end(), same), pts.end());
  Core c;
  c.radius = radius;
  if (pts.size() <= 2) {
    c.v = pts;
    return c;
  }
  Points h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {  // lower chain
    while (k >= 2 && orient(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  const std::size_t lower = k + 1;
  for (std::size_t i = pts.size() - 1; i-- > 0;) {  // upper chain
    while (k >= lower && orient(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);  // the last point repeats the first
  c.v = h;
  if (c.v.size() == 2 && same(c.v[0], c.v[1])) c.v.resize(1);
  return c;
}

bool between(const P& p, const P& a, const P& b) {
  return sign_of(dot(sub(p, a), sub(p, b))) <= 0;
}

bool point_in(const P& p, const Core& c) {
  if (c.v.size() == 1) return same(p, c.v[0]);
  if (c.v.size() == 2) return orient(c.v[0], c.v[1], p) == 0 && between(p, c.v[0], c.v[1]);
  for (std::size_t i = 0; i < c.v.size(); ++i) {
    if (orient(c.v[i], c.at(i + 1), p) < 0) return false;
  }
  return true;
}

bool segments_meet(const P& a, const P& b, const P& c, const P& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && between(c, a, b)) || (o2 == 0 && between(d, a, b)) || (o3 == 0 && between(a, c, d)) ||
         (o4 == 0 && between(b, c, d));
}

bool cores_meet(const Core& p, const Core& q) {
  for (const P& x : p.v) {
    if (point_in(x, q)) return true;
  }
  for (const P& x : q.v) {
    if (point_in(x, p)) return true;
  }
  for (std::size_t i = 0; i < p.edge_count(); ++i) {
    for (std::size_t j = 0; j < q.edge_count(); ++j) {
      if (segments_meet(p.v[i], p.at(i + 1), q.v[j], q.at(j + 1))) return true;
    }
  }
  return false;
}

/// sign(dist(x, [a, b])^2 - r2), division-free.
int sign_point_segment(const P& x, const P& a, const P& b, const NT& r2) {
  const P e = sub(b, a), w = sub(x, a);
  const NT t = dot(w, e);
  if (sign_of(t) <= 0) return sign_of(dot(w, w) - r2);
  const NT len2 = dot(e, e);
  if (sign_of(t - len2) >= 0) {
    const P u = sub(x, b);
    return sign_of(dot(u, u) - r2);
  }
  const NT c = cross(e, w);
  return sign_of(c * c - r2 * len2);
}

int sign_point_core(const P& x, const Core& c, const NT& r2) {
  if (c.v.size() == 1) {
    const P u = sub(x, c.v[0]);
    return sign_of(dot(u, u) - r2);
  }
  int best = 1;
  for (std::size_t j = 0; j < c.edge_count() && best > -1; ++j)
    best = std::min(best, sign_point_segment(x, c.v[j], c.at(j + 1), r2));
  return best;
}

/// The dilated cores come within pad of each other: dist(P, Q) <= rp + rq + pad.
bool within(const Core& p, const Core& q, const NT& pad) {
  if (cores_meet(p, q)) return true;
  const NT r = p.radius + q.radius + pad;
  const NT r2 = r * r;
  for (const P& x : p.v) {
    if (sign_point_core(x, q, r2) <= 0) return true;
  }
  for (const P& x : q.v) {
    if (sign_point_core(x, p, r2) <= 0) return true;
  }
  return false;
}

Core posed(const Core& c, const Vec2d& q, const Vec2d& p) {
  require_finite(q, "rotation");
  require_finite(p, "position");
  const NT qc(q.x()), qs(q.y()), px(p.x()), py(p.y());
  Points pts;
  for (const P& x : c.v) pts.push_back({qc * x.x - qs * x.y + px, qs * x.x + qc * x.y + py});
  return hull_of(pts, c.radius);
}

bool is_identity(const Vec2d& q, const Vec2d& p) {
  return p == Vec2d(0, 0) && q == Vec2d(1, 0);
}

using Cores = boost::container::small_vector<Core, 4>;

/// The exact cores of a placed shape's primitives (itself, or a compound's children): each
/// child's core placed by its own transform, then by the body's.
Cores cores_of(const Placed& s) {
  Cores out;
  const bool body = !is_identity(s.rotation, s.position);
  auto add = [&](const Primitive<double>& x, const Transform<double>& own) {
    Core c = local_core(x);
    if (!own.is_identity()) c = posed(c, own.rotation(), own.position());
    if (body) c = posed(c, s.rotation, s.position);
    out.push_back(hull_of(c.v, c.radius));
  };
  std::visit(
      [&](const auto& x) {
        using S = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<S, Compound<double>>) {
          for (std::size_t i = 0; i < x.children().size(); ++i) add(x.children()[i], x.child_transform(i));
        } else {
          add(Primitive<double>(x), Transform<double>());
        }
      },
      s.shape);
  return out;
}

}  // namespace

namespace exact {

bool meets_during(const Placed& a, const Vec2<double>& va, const Placed& b, const Vec2<double>& vb, double t0,
                  double t1, double pad) {
  require_finite(va, "velocity");
  require_finite(vb, "velocity");
  require_finite(t0, "time");
  require_finite(t1, "time");
  require_finite(pad, "pad");
  if (t1 < t0) std::swap(t0, t1);
  const P w{NT(va.x()) - NT(vb.x()), NT(va.y()) - NT(vb.y())};
  const P d0{w.x * NT(t0), w.y * NT(t0)}, d1{w.x * NT(t1), w.y * NT(t1)};
  const NT padn(std::max(pad, 0.0));
  const Cores cb = cores_of(b);
  for (const Core& ca : cores_of(a)) {
    Points swept;
    for (const P& p : ca.v) {
      swept.push_back({p.x + d0.x, p.y + d0.y});
      swept.push_back({p.x + d1.x, p.y + d1.y});
    }
    const Core sa = hull_of(swept, ca.radius);
    for (const Core& q : cb) {
      if (within(sa, q, padn)) return true;
    }
  }
  return false;
}

bool meets_posed(const Shape<double>& a, const Vec2<double>& qa, const Vec2<double>& pa, const Shape<double>& b,
                 const Vec2<double>& qb, const Vec2<double>& pb, double pad) {
  require_finite(pad, "pad");
  const NT padn(std::max(pad, 0.0));
  const Cores cb = cores_of(Placed(b, pb, qb));
  for (const Core& ca : cores_of(Placed(a, pa, qa))) {
    for (const Core& q : cb) {
      if (within(ca, q, padn)) return true;
    }
  }
  return false;
}

}  // namespace exact

}  // namespace collide::oracle
