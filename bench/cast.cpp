// Shape casts and time of impact: collide's shape_cast / time_of_impact against Box2D 2.4.1's
// b2ShapeCast / b2TimeOfImpact on the same float inputs (near, far and grazing casts of boxes and
// circles against a box), and every answer of both libraries judged by the exact oracle before
// timing: how often an answer comes after the first contact (tunnelling: the exact shapes meet
// before the returned time, or a reported miss while they meet) and how often it comes earlier
// than the library's own tolerance allows (the exact gap at the returned time beyond it).
//
// Box2D's tolerances: b2ShapeCast stops at a separation of target = b2_linearSlop (0.005) within
// 0.5 b2_linearSlop, so a gap above 0.0075 at its time is too early; b2TimeOfImpact aims at
// 0.005 within 0.25 b2_linearSlop (gap above 0.00625). Box2D polygons get m_radius = 0 (the shape
// itself, as in the other benchmarks). collide's: cast_tolerance() and toi_tolerance().
// Time of impact is judged at 64 sample times before the returned t (and on [0, 1] after a miss),
// each library's shapes placed as that library evaluates its motion.

#include "suites.hpp"

#include <collide/collide.hpp>
#include <collide/oracle/oracle.hpp>

#include <benchmark/benchmark.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_time_of_impact.h>
#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace bench {
namespace {

using V = collide::Vec2<float>;
constexpr int kCasts = 256;

/// One cast: a still (at the origin region), b moving by `move` over t in [0, 1], turning by `turn`.
struct CastIn {
  collide::Shape<float> a = collide::Circle<float>(V(0, 0), 0);
  collide::Shape<float> b_world = a, b_local = a;
  b2PolygonShape a2;
  b2PolygonShape b2_box;
  b2CircleShape b2_circle;
  bool b_is_circle = false;
  V b_center = V(0, 0);
  float b_angle = 0;
  V move = V(0, 0);
  float turn = 0;
};

b2PolygonShape box2d_box(V c, V h, float angle) {
  b2PolygonShape s;
  s.SetAsBox(h.x(), h.y(), b2Vec2(c.x(), c.y()), angle);
  s.m_radius = 0;
  return s;
}

/// The casts of one set: "near" (b starts 1-2 units away), "far" (20-40 units away, fast), or
/// "grazing" (b slides past a's top face, its lowest point within 1e-3 above or below it).
std::vector<CastIn> make_set(const std::string& set, bool circle, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<CastIn> out;
  for (int i = 0; i < kCasts; ++i) {
    CastIn c;
    const float a_angle = set == "grazing" ? 0.0f : u(rng);
    c.a = collide::Obb<float>(V(0, 0), V(0.5f, 0.5f), a_angle);
    c.a2 = box2d_box(V(0, 0), V(0.5f, 0.5f), a_angle);
    c.b_is_circle = circle;
    c.b_angle = set == "grazing" ? 0.0f : u(rng);
    const float r = 0.25f;
    if (set == "grazing") {
      c.b_center = V(-3, 0.5f + r + 1e-3f * u(rng));
      c.move = V(6, 0);
    } else {
      const float dist = set == "near" ? 1.5f + 0.5f * u(rng) : 30 + 10 * u(rng);
      const float dir = 3.14159265f * u(rng);
      c.b_center = V(dist * std::cos(dir), dist * std::sin(dir));
      const V aim = V(0.3f * u(rng), 0.3f * u(rng)) - c.b_center;
      c.move = aim * (set == "near" ? 1.5f : 1.2f);
    }
    c.turn = set == "grazing" ? 0.0f : 0.5f * u(rng);
    if (circle) {
      c.b_world = collide::Circle<float>(c.b_center, r);
      c.b_local = collide::Circle<float>(V(0, 0), r);
      c.b2_circle.m_radius = r;
      c.b2_circle.m_p.Set(0, 0);
    } else {
      c.b_world = collide::Obb<float>(c.b_center, V(r, r), c.b_angle);
      c.b_local = collide::Obb<float>(V(0, 0), V(r, r), 0.0f);
      c.b2_box = box2d_box(V(0, 0), V(r, r), 0);
    }
    out.push_back(std::move(c));
  }
  return out;
}

const b2Shape& box2d_b(const CastIn& c) {
  return c.b_is_circle ? static_cast<const b2Shape&>(c.b2_circle) : static_cast<const b2Shape&>(c.b2_box);
}

/// Box2D's shape cast of b (placed at its start) moving by `move` against a.
bool box2d_cast(const CastIn& c, b2ShapeCastOutput* out) {
  b2ShapeCastInput in;
  in.proxyA.Set(&c.a2, 0);
  in.proxyB.Set(&box2d_b(c), 0);
  in.transformA.SetIdentity();
  in.transformB.Set(b2Vec2(c.b_center.x(), c.b_center.y()), c.b_angle);
  in.translationB.Set(c.move.x(), c.move.y());
  return b2ShapeCast(out, &in);
}

b2Sweep box2d_sweep(const CastIn& c) {
  b2Sweep s;
  s.localCenter.SetZero();
  s.c0.Set(c.b_center.x(), c.b_center.y());
  s.c.Set(c.b_center.x() + c.move.x(), c.b_center.y() + c.move.y());
  s.a0 = c.b_angle;
  s.a = c.b_angle + c.turn;
  s.alpha0 = 0;
  return s;
}

b2TOIOutput box2d_toi(const CastIn& c) {
  b2TOIInput in;
  in.proxyA.Set(&c.a2, 0);
  in.proxyB.Set(&box2d_b(c), 0);
  in.sweepA.localCenter.SetZero();
  in.sweepA.c0.SetZero();
  in.sweepA.c.SetZero();
  in.sweepA.a0 = in.sweepA.a = 0;
  in.sweepA.alpha0 = 0;
  in.sweepB = box2d_sweep(c);
  in.tMax = 1;
  b2TOIOutput out;
  b2TimeOfImpact(&out, &in);
  return out;
}

collide::Sweep<float> collide_sweep(const CastIn& c) {
  collide::Sweep<float> s;
  s.c0 = c.b_center;
  s.c1 = c.b_center + c.move;
  s.a0 = c.b_angle;
  s.a1 = c.b_angle + c.turn;
  return s;
}

// ---- the judge ---------------------------------------------------------------------------

struct Counts {
  int hits = 0, tunnelled = 0, too_early = 0, failed = 0, start_overlap = 0, start_missed = 0;
};

/// A linear answer: b (world) moving by move, a still; a hit at t, a miss, or undecided (the
/// last safe time t); tolerance tol. Casts starting in overlap are counted apart: a hit at
/// t = 0 is their right answer, anything else is a missed start.
void judge_linear(const CastIn& c, bool hit, bool undecided, double t, double tol, Counts& k) {
  const collide::Vec2<double> still(0, 0), mv = c.move.cast<double>();
  if (collide::oracle::overlaps(c.b_world, c.a)) {
    ++k.start_overlap;
    if (!(hit && t == 0)) ++k.start_missed;
    return;
  }
  if (!hit) {
    if (collide::oracle::meets_during(c.b_world, mv, c.a, still, 0.0, undecided ? t : 1.0)) ++k.tunnelled;
    return;
  }
  ++k.hits;
  if (t > 0 && collide::oracle::meets_during(c.b_world, mv, c.a, still, 0.0, t)) ++k.tunnelled;
  if (!collide::oracle::meets_during(c.b_world, mv, c.a, still, t, t, tol)) ++k.too_early;
}

/// A rotating answer: the pose of b at time s as placed by `pose`; a at the identity.
template <class Pose>
void judge_swept(const CastIn& c, bool hit, bool undecided, double t, double tol, Pose&& pose, Counts& k) {
  const collide::Vec2<double> one(1, 0), zero(0, 0);
  auto meets = [&](double s, double pad) {
    const auto [q, p] = pose(s);
    return collide::oracle::meets_posed(c.b_local, q, p, c.a, one, zero, pad);
  };
  if (meets(0, 0)) {
    ++k.start_overlap;
    if (!(hit && t == 0)) ++k.start_missed;
    return;
  }
  const double until = hit || undecided ? t : 1.0;
  for (int i = 0; i <= 64; ++i) {
    if (meets(until * i / 64.0, 0)) {
      ++k.tunnelled;
      break;
    }
  }
  if (hit) {
    ++k.hits;
    if (!meets(t, tol)) ++k.too_early;
  }
}

std::string counts_text(const Counts& k) {
  return std::to_string(k.hits) + " hits, " + std::to_string(k.tunnelled) + " after the first contact, " +
         std::to_string(k.too_early) + " too early, " + std::to_string(k.failed) + " undecided, " +
         std::to_string(k.start_overlap) + " starting in overlap (" + std::to_string(k.start_missed) + " not reported)";
}

void judge_set(const std::string& name, const std::vector<CastIn>& casts) {
  Counts lc, lb, rc, rb;
  for (const CastIn& c : casts) {
    const collide::Vec2<float> zero(0, 0);
    const auto r = collide::shape_cast(c.b_world, c.move, c.a, zero, 1.0f);
    judge_linear(c, r.hit(), r.outcome == collide::CastOutcome::IterationLimit, r.t,
                 collide::cast_tolerance(c.b_world, c.move, c.a, zero, 1.0f), lc);
    if (r.outcome == collide::CastOutcome::IterationLimit) ++lc.failed;
    b2ShapeCastOutput o;
    const bool h = box2d_cast(c, &o);
    judge_linear(c, h, false, o.lambda, 1.5 * b2_linearSlop, lb);

    const collide::Sweep<float> sw = collide_sweep(c);
    const auto ti = collide::time_of_impact(c.b_local, sw, c.a, collide::Sweep<float>{}, 1.0f);
    judge_swept(
        c, ti.hit(), ti.outcome == collide::CastOutcome::IterationLimit, ti.t,
        collide::toi_tolerance(c.b_local, sw, c.a, collide::Sweep<float>{}, 1.0f),
        [&](double s) {
          const collide::SweepPose p = collide::sweep_pose(sw, s);
          return std::pair{p.rotation, p.position};
        },
        rc);
    if (ti.outcome == collide::CastOutcome::IterationLimit) ++rc.failed;
    const b2TOIOutput bo = box2d_toi(c);
    const b2Sweep bs = box2d_sweep(c);
    judge_swept(
        c, bo.state == b2TOIOutput::e_touching || bo.state == b2TOIOutput::e_overlapped,
        bo.state == b2TOIOutput::e_failed, bo.t, 1.25 * b2_linearSlop,
        [&](double s) {
          b2Transform xf;
          bs.GetTransform(&xf, float(s));
          return std::pair{collide::Vec2<double>(xf.q.c, xf.q.s), collide::Vec2<double>(xf.p.x, xf.p.y)};
        },
        rb);
    if (bo.state == b2TOIOutput::e_failed || bo.state == b2TOIOutput::e_unknown) ++rb.failed;
  }
  std::printf("judge %s: shape_cast %s | b2ShapeCast %s\n", name.c_str(), counts_text(lc).c_str(),
              counts_text(lb).c_str());
  std::printf("judge %s: time_of_impact %s | b2TimeOfImpact %s\n", name.c_str(), counts_text(rc).c_str(),
              counts_text(rb).c_str());
}

}  // namespace

bool register_cast() {
  static std::vector<std::pair<std::string, std::vector<CastIn>>> sets;
  unsigned seed = 20261127;
  for (const bool circle : {false, true}) {
    for (const char* set : {"near", "far", "grazing"}) {
      sets.push_back({std::string(circle ? "circle_box/" : "box_box/") + set, make_set(set, circle, seed++)});
    }
  }
  for (const auto& [name, casts] : sets) {
    judge_set(name, casts);
    const auto* in = &casts;
    benchmark::RegisterBenchmark(("cast/shape_cast/" + name + "/collide").c_str(), [in](benchmark::State& st) {
      const collide::Vec2<float> zero(0, 0);
      for (auto _ : st) {
        for (const CastIn& c : *in) benchmark::DoNotOptimize(collide::shape_cast(c.b_world, c.move, c.a, zero, 1.0f));
      }
      st.SetItemsProcessed(st.iterations() * kCasts);
    });
    benchmark::RegisterBenchmark(("cast/shape_cast/" + name + "/box2d").c_str(), [in](benchmark::State& st) {
      for (auto _ : st) {
        for (const CastIn& c : *in) {
          b2ShapeCastOutput o;
          benchmark::DoNotOptimize(box2d_cast(c, &o));
          benchmark::DoNotOptimize(o);
        }
      }
      st.SetItemsProcessed(st.iterations() * kCasts);
    });
    benchmark::RegisterBenchmark(("cast/time_of_impact/" + name + "/collide").c_str(), [in](benchmark::State& st) {
      for (auto _ : st) {
        for (const CastIn& c : *in) {
          benchmark::DoNotOptimize(
              collide::time_of_impact(c.b_local, collide_sweep(c), c.a, collide::Sweep<float>{}, 1.0f));
        }
      }
      st.SetItemsProcessed(st.iterations() * kCasts);
    });
    benchmark::RegisterBenchmark(("cast/time_of_impact/" + name + "/box2d").c_str(), [in](benchmark::State& st) {
      for (auto _ : st) {
        for (const CastIn& c : *in) benchmark::DoNotOptimize(box2d_toi(c));
      }
      st.SetItemsProcessed(st.iterations() * kCasts);
    });
  }
  return true;
}

}  // namespace bench
