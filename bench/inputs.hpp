#pragma once
// Benchmark inputs: the same pairs for collide and Box2D, generated once from a fixed seed.
// Everything is float (what Box2D uses); collide computes in double internally either way.

#include "collide/collide.hpp"

#include <box2d/box2d.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace bench {

using collide::Vec2;
using V = Vec2<float>;

/// The placements of a pair: anywhere in a 100 x 100 world, near each other (about half of them
/// overlapping), or exactly touching (every decision needs the exact path).
enum class Placement { Random, Near, Touching };
inline const char* name(Placement p) {
  return p == Placement::Random ? "random" : (p == Placement::Near ? "near" : "touching");
}

/// One shape in both libraries' forms. Box2D shapes are in world coordinates with the identity
/// transform; polygon skins are 0 (m_radius = 0) so both answer for the same sharp shape.
struct CircleIn {
  collide::Circle<float> c;
  b2CircleShape b;
};
struct AabbIn {
  collide::Aabb<float> c;
  b2AABB b;
  b2PolygonShape p;  ///< the same box as a Box2D polygon, for its manifold functions
};
struct ObbIn {
  collide::Obb<float> c;
  b2PolygonShape b;
};
struct CapsuleIn {
  collide::Capsule<float> c;
  b2EdgeShape b;
};
struct HullIn {
  collide::ConvexPolygon<float> c;
  b2PolygonShape b;
};

inline b2Vec2 to_b2(const V& v) {
  return {v.x(), v.y()};
}

class Maker {
 public:
  explicit Maker(unsigned seed) : rng_(seed) {}
  float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

  CircleIn circle(const V& at) { return circle_at(at, uniform(0.5f, 2.0f)); }
  static CircleIn circle_at(const V& at, float r) {
    CircleIn s{collide::Circle<float>(at, r), {}};
    s.b.m_p = to_b2(at);
    s.b.m_radius = r;
    return s;
  }
  AabbIn aabb(const V& at) {
    const V h(uniform(0.5f, 2.0f), uniform(0.5f, 2.0f));
    const V lo = at - h, hi = at + h;
    AabbIn s{collide::Aabb<float>(lo, hi), {}, {}};
    s.b.lowerBound = to_b2(lo);
    s.b.upperBound = to_b2(hi);
    s.p.SetAsBox(h.x(), h.y(), to_b2(at), 0.0f);
    s.p.m_radius = 0;
    return s;
  }
  ObbIn obb(const V& at) {
    const V h(uniform(0.5f, 2.0f), uniform(0.5f, 2.0f));
    const float angle = uniform(-3.14159f, 3.14159f);
    ObbIn s{collide::Obb<float>(at, h, angle), {}};
    s.b.SetAsBox(h.x(), h.y(), to_b2(at), angle);
    s.b.m_radius = 0;
    return s;
  }
  CapsuleIn capsule(const V& at) {
    const float half = uniform(0.5f, 2.0f), angle = uniform(-3.14159f, 3.14159f);
    const V d(half * std::cos(angle), half * std::sin(angle));
    const float r = uniform(0.25f, 1.0f);
    CapsuleIn s{collide::Capsule<float>(at - d, at + d, r), {}};
    s.b.SetTwoSided(to_b2(at - d), to_b2(at + d));
    s.b.m_radius = r;
    return s;
  }
  /// Hull of 3..8 random points in a disc; Box2D's polygon gets exactly the same vertices.
  HullIn hull(const V& at) {
    for (;;) {
      const int n = integer(3, 8);
      const float size = uniform(0.75f, 2.0f);
      std::vector<V> pts;
      for (int i = 0; i < n; ++i) {
        const float a = uniform(0, 6.2831853f), r = size * std::sqrt(uniform(0.2f, 1.0f));
        pts.push_back(at + V(r * std::cos(a), r * std::sin(a)));
      }
      auto poly = collide::ConvexPolygon<float>::make_hull(pts);
      if (!poly) continue;
      const auto vs = poly.value().vertices();
      if (vs.size() < 3 || vs.size() > b2_maxPolygonVertices) continue;
      HullIn s{poly.value(), {}};
      s.b.m_count = static_cast<int32>(vs.size());
      b2Vec2 centroid(0, 0);
      bool ok = true;
      for (std::size_t i = 0; i < vs.size(); ++i) {
        const b2Vec2 p = to_b2(vs[i]), q = to_b2(vs[(i + 1) % vs.size()]);
        const b2Vec2 e = q - p;
        if (e.Length() < 10 * b2_epsilon) ok = false;
        s.b.m_vertices[i] = p;
        s.b.m_normals[i] = b2Cross(e, 1.0f);
        s.b.m_normals[i].Normalize();
        centroid += p;
      }
      if (!ok) continue;
      s.b.m_centroid = (1.0f / float(vs.size())) * centroid;
      s.b.m_radius = 0;
      return s;
    }
  }

  /// Exactly touching circles: centres (3, 4) k apart, radii summing to 5 k (k a multiple of 1/8,
  /// so every value is exact in float).
  void touching_circles(std::size_t n, std::vector<CircleIn>& as, std::vector<CircleIn>& bs) {
    for (std::size_t i = 0; i < n; ++i) {
      const float k = float(integer(1, 16)) / 8, x = float(integer(0, 800)) / 8, y = float(integer(0, 800)) / 8;
      const float ra = k * float(integer(1, 4));
      as.push_back(circle_at(V(x, y), ra));
      bs.push_back(circle_at(V(x + 3 * k, y + 4 * k), 5 * k - ra));
    }
  }
  /// Unturned boxes sharing part of a face exactly (every value a multiple of 1/8).
  void touching_boxes(std::size_t n, std::vector<ObbIn>& as, std::vector<ObbIn>& bs) {
    auto box = [](const V& at, const V& h) {
      ObbIn s{collide::Obb<float>(at, h, 0.0f), {}};
      s.b.SetAsBox(h.x(), h.y(), to_b2(at), 0.0f);
      s.b.m_radius = 0;
      return s;
    };
    for (std::size_t i = 0; i < n; ++i) {
      const V ha(float(integer(4, 16)) / 8, float(integer(4, 16)) / 8);
      const V hb(float(integer(4, 16)) / 8, float(integer(4, 16)) / 8);
      const V pa(float(integer(0, 800)) / 8, float(integer(0, 800)) / 8);
      as.push_back(box(pa, ha));
      bs.push_back(box(pa + V(ha.x() + hb.x(), float(integer(-4, 4)) / 8), hb));
    }
  }

  /// Rough size of a shape (for placing near pairs).
  static float extent(const CircleIn& s) { return s.c.radius(); }
  static float extent(const AabbIn& s) { return 0.5f * (s.c.max() - s.c.min()).norm(); }
  static float extent(const ObbIn& s) { return s.c.half_extents().norm(); }
  static float extent(const CapsuleIn& s) { return 0.5f * (s.c.b() - s.c.a()).norm() + s.c.radius(); }
  static float extent(const HullIn& s) {
    float e = 0;
    const V c = s.c[0];
    for (const V& p : s.c.vertices()) e = std::max(e, (p - c).norm());
    return 0.6f * e;
  }

  /// n pairs: A anywhere in [0, 100]^2; B anywhere too (Random) or at a distance from A drawn
  /// around the sum of the two sizes (Near, tuned for about half overlapping).
  template <class A, class B, class MakeA, class MakeB>
  void pairs(std::size_t n, Placement p, float near_scale, MakeA make_a, MakeB make_b, std::vector<A>& as,
             std::vector<B>& bs) {
    for (std::size_t i = 0; i < n; ++i) {
      const V pa(uniform(0, 100), uniform(0, 100));
      A a = make_a(pa);
      V pb(uniform(0, 100), uniform(0, 100));
      if (p == Placement::Near) {
        // Place B's center at a random direction; its size is drawn first at the origin.
        B probe = make_b(V(0, 0));
        const float reach = (extent(a) + extent(probe)) * near_scale * uniform(0.0f, 1.0f);
        const float ang = uniform(0, 6.2831853f);
        pb = pa + V(reach * std::cos(ang), reach * std::sin(ang));
      }
      as.push_back(std::move(a));
      bs.push_back(make_b(pb));
    }
  }

 private:
  std::mt19937 rng_;
};

}  // namespace bench
