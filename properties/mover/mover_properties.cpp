/// The laws of move_and_slide() (collide/broadphase/mover.hpp), judged by the exact oracle, for
/// both scalars: one GoogleTest test per law and scalar (suite MoverLaws), checked by RapidCheck.
///
/// The laws are plain functions of a finished move (a Move: the world's bodies, the mover, its
/// start, the displacement, the options and the answer) returning what failed, or nothing:
/// 1. no_new_overlap: the mover ends overlapping no clear blocking body (exact overlaps);
/// 2. never_tunnels: every leg is free of every clear blocking body: the oracle's exact
///    "meets during" of the mover swept along the leg;
/// 3. never_farther: the legs sum to at most |displacement| + (path_count - 1) rho, the answer is
///    consistent (path, transform, displacement), and rho and the skin are within the contract;
/// 4. floor_slide: a circle or capsule resting on a flat floor (one long box, or a row of flush
///    boxes, rectangles or OBBs, in world space or placed by translations), touching or just
///    above it, moved horizontally goes the whole way less at most the skin, rising at most the
///    skin and never sinking;
/// 5. wall_stop: moved head-on into a wall it stops in front of it, within the skin and the
///    cast's tolerance; moved at an angle it slides along it by the tangential component.
/// A body is clear when the oracle puts its exact gap from the mover at the start above
/// move_band(); the laws say nothing of the others (resting contacts).
///
/// Scenes for laws 1-3: one to eight bodies of every kind (compounds with child transforms
/// included) on a dyadic grid (generators.hpp), some placed by transforms, some filtered out or
/// ignored; the mover is a circle or a capsule (radius 0 sometimes), placed at random, or resting
/// on a body's box top (touching, a hair above or below); displacements random, aimed at a body,
/// axis-aligned or zero. Laws 4 and 5 build their own scenes, mirrored by quarter turns.
///
/// Depth: RC_PARAMS (ctest: 200 cases per law and scalar, seed 1).

#include "collide/broadphase.hpp"
#include "collide/laws/codec.hpp"
#include "collide/oracle/oracle.hpp"
#include "generators.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace collide::props {
namespace {

namespace bp = collide::broadphase;

/// What the laws judged, printed at the end, so that a run shows they were not vacuous.
struct Stats {
  long moves = 0, clear_bodies = 0, hit_bodies = 0, legs_judged = 0, hits = 0, resting = 0, slid = 0;
};
Stats g_stats;

/// A body of a scene: its shape in its own frame, its transform, its filter, and whether the move
/// ignores it.
template <Scalar T>
struct SceneBody {
  Shape<T> shape;
  Transform<T> x;
  bp::Filter filter{};
  bool ignored = false;
};

/// One move: the scene, the call and its answer.
template <Scalar T>
struct Move {
  std::vector<SceneBody<T>> bodies;
  Shape<T> mover = Circle<T>(Vec2<T>(0, 0), T(1));
  Transform<T> from;
  Vec2<T> d = Vec2<T>::Zero();
  int max_iterations = 4;
  T skin = 0;
  bp::Filter filter = bp::Filter::everything();
  bp::MoveResult<T> result;
};

/// Builds the world of m, runs the move and keeps its answer.
template <Scalar T>
void run(Move<T>& m) {
  bp::World<T> world;
  std::vector<bp::ProxyId> ignore;
  for (const SceneBody<T>& b : m.bodies) {
    const bp::ProxyId id = world.add(b.shape, b.x, 0, b.filter);
    if (b.ignored) ignore.push_back(id);
  }
  bp::MoveOptions<T> options;
  options.filter = m.filter;
  options.ignore = ignore;
  options.max_iterations = m.max_iterations;
  options.skin = m.skin;
  m.result = bp::move_and_slide(world, m.mover, m.from, m.d, options);
}

// --- the oracle's view of a move -----------------------------------------------------------------

/// The mover placed at p with the start's rotation, as the oracle takes it (the exact image).
template <Scalar T>
oracle::Placed mover_at(const Move<T>& m, const Vec2<T>& p) {
  return oracle::Placed(oracle::as_exact_input(m.mover), p.template cast<double>(),
                        m.from.rotation().template cast<double>());
}

/// Whether body b blocks the move: its filter accepts the move's, and the move does not ignore it.
template <Scalar T>
bool blocks(const Move<T>& m, const SceneBody<T>& b) {
  return bp::accepts(b.filter, m.filter) && !b.ignored;
}

/// Whether body b is clear at the start: its exact gap from the mover exceeds move_band().
template <Scalar T>
bool clear_at_start(const Move<T>& m, const SceneBody<T>& b) {
  const double band = bp::move_band(m.mover, m.from, m.d, b.shape, b.x);
  return oracle::compare_distance(mover_at(m, m.from.position()), oracle::placed(b.shape, b.x), band) > 0;
}

/// b - a as the oracle's velocity and how far the double difference may be from the exact one
/// (two-sum per coordinate): the leg from a to b lies within that pad of a + v s, s in [0, 1].
inline std::pair<Vec2<double>, double> exact_step(const Vec2<double>& a, const Vec2<double>& b) {
  Vec2<double> v;
  double pad = 0;
  for (int k = 0; k < 2; ++k) {
    const double s = b[k] - a[k], back = s - b[k];
    const double e = (b[k] - (s - back)) + (-a[k] - back);
    v[k] = s;
    pad += std::fabs(e);
  }
  return {v, pad * (1 + 0x1p-50)};
}

/// The independent bound on rho the laws hold the answer to: 4 eps_T (the larger of the mover's
/// scale and its position's at the start, + |displacement|) + 4 denorm_min_T, computed here.
template <Scalar T>
double rho_cap(const Move<T>& m) {
  const Aabb<T> box = bounds(m.mover, m.from);
  const double scale = std::max({widen(box.min()).cwiseAbs().maxCoeff(), widen(box.max()).cwiseAbs().maxCoeff(),
                                 widen(m.from.position()).cwiseAbs().maxCoeff()});
  const double reach = std::hypot(double(m.d.x()), double(m.d.y()));
  return (4 * double(std::numeric_limits<T>::epsilon()) * (scale + reach) +
          4 * double(std::numeric_limits<T>::denorm_min())) *
         (1 + 0x1p-40);
}

/// A readable account of a move, for a counterexample.
template <Scalar T>
std::string describe(const Move<T>& m) {
  std::ostringstream o;
  o.precision(17);
  const auto values = [&](const Shape<T>& s) {
    const laws::ShapeData d = laws::to_data(s);
    std::ostringstream v;
    v.precision(17);
    v << name(d.kind);
    for (double x : d.values) v << ' ' << x;
    for (const laws::ShapeData& c : d.children) {
      v << " [" << name(c.kind);
      for (double x : c.values) v << ' ' << x;
      if (c.placement) v << " @ " << c.placement->values[0] << ' ' << c.placement->values[1];
      v << ']';
    }
    return v.str();
  };
  const auto place = [](const Transform<T>& x) {
    std::ostringstream v;
    v.precision(17);
    v << '(' << double(x.position().x()) << ", " << double(x.position().y()) << ") turned (" << double(x.rotation().x())
      << ", " << double(x.rotation().y()) << ')';
    return v.str();
  };
  o << (std::is_same_v<T, float> ? "float" : "double") << " move of " << values(m.mover) << " from " << place(m.from)
    << " by (" << double(m.d.x()) << ", " << double(m.d.y()) << "), max_iterations " << m.max_iterations << ", skin "
    << double(m.skin) << "\n";
  for (std::size_t j = 0; j < m.bodies.size(); ++j) {
    const SceneBody<T>& b = m.bodies[j];
    o << "  body " << j << ": " << values(b.shape) << " placed " << place(b.x)
      << (blocks(m, b) ? "" : " (not blocking)") << "\n";
  }
  const bp::MoveResult<T>& r = m.result;
  o << "  answer: " << bp::name(r.outcome) << ", skin " << r.skin << ", rho " << r.rounding << ", path";
  for (const Vec2<T>& p : r.positions()) o << " (" << double(p.x()) << ", " << double(p.y()) << ")";
  for (const bp::MovePlane<T>& p : r.contacts()) {
    o << "\n  plane of body " << p.body.index << (p.resting ? " (resting)" : " (hit)") << " normal ("
      << double(p.normal.x()) << ", " << double(p.normal.y()) << ")";
  }
  return o.str();
}

// --- the laws ---------------------------------------------------------------------------------------

/// Law 1: the mover ends overlapping no clear blocking body.
template <Scalar T>
std::string no_new_overlap(const Move<T>& m) {
  const oracle::Placed end = mover_at(m, m.result.transform.position());
  for (std::size_t j = 0; j < m.bodies.size(); ++j) {
    const SceneBody<T>& b = m.bodies[j];
    if (!blocks(m, b) || !clear_at_start(m, b)) continue;
    if (oracle::overlaps(end, oracle::placed(b.shape, b.x)))
      return "ends overlapping body " + std::to_string(j) + ", clear of it at the start";
  }
  return "";
}

/// Law 2: along every leg the mover is apart from every clear blocking body (exactly: the oracle's
/// first contact of the mover moving along the leg is not within it).
template <Scalar T>
std::string never_tunnels(const Move<T>& m) {
  const auto path = m.result.positions();
  const Vec2<double> still(0, 0);
  for (std::size_t j = 0; j < m.bodies.size(); ++j) {
    const SceneBody<T>& b = m.bodies[j];
    if (!blocks(m, b) || !clear_at_start(m, b)) continue;
    const oracle::Placed body = oracle::placed(b.shape, b.x);
    ++g_stats.clear_bodies;
    g_stats.hit_bodies += std::any_of(m.result.contacts().begin(), m.result.contacts().end(),
                                      [&](const bp::MovePlane<T>& p) { return p.body.index == j && !p.resting; });
    for (std::size_t k = 0; k + 1 < path.size(); ++k) {
      ++g_stats.legs_judged;
      const auto [v, pad] = exact_step(path[k].template cast<double>(), path[k + 1].template cast<double>());
      if (oracle::meets_during(mover_at(m, path[k]), v, body, still, 0.0, 1.0, pad))
        return "leg " + std::to_string(k) + " meets body " + std::to_string(j) + ", clear of it at the start";
    }
  }
  return "";
}

/// Law 3: never farther than asked, and the answer is the contract's: the path starts at from and
/// ends at the transform, whose rotation is from's bit for bit; the displacement is the difference
/// rounded to T; rho and the skin within their bounds.
template <Scalar T>
std::string never_farther(const Move<T>& m) {
  const bp::MoveResult<T>& r = m.result;
  if (r.outcome == bp::MoveOutcome::InvalidInput || r.outcome == bp::MoveOutcome::UnsupportedMover)
    return "a valid move refused: " + std::string(bp::name(r.outcome));
  const auto path = r.positions();
  if (path.empty() || path.front() != m.from.position() || path.back() != r.transform.position())
    return "the path does not run from the start to the transform";
  if (r.transform.rotation() != m.from.rotation()) return "the rotation changed";
  if (r.displacement != Vec2<T>(r.transform.position() - m.from.position())) return "displacement is not end - start";
  if (!(r.rounding <= rho_cap(m))) return "rho " + std::to_string(r.rounding) + " above its bound";
  double own = cast_tolerance(m.mover, m.from, m.d, m.mover, m.from, Vec2<T>::Zero(), T(1));
  for (const SceneBody<T>& b : m.bodies) {
    own = std::max(own, cast_tolerance(m.mover, m.from, m.d, b.shape, b.x, Vec2<T>::Zero(), T(1)));
  }
  const double skin_cap = std::max(double(m.skin), bp::kMoveSkinFactor * std::max(rho_cap(m), own)) * (1 + 0x1p-40);
  if (!(r.skin <= skin_cap)) return "skin " + std::to_string(r.skin) + " above its bound";
  double length = 0;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    length += std::hypot(double(path[k + 1].x()) - double(path[k].x()), double(path[k + 1].y()) - double(path[k].y()));
  }
  const double asked = std::hypot(double(m.d.x()), double(m.d.y()));
  // The sums here round too: 2^-48 of the lengths covers them.
  const double limit = asked + double(path.size() - 1) * r.rounding + 0x1p-48 * (length + asked);
  if (!(length <= limit)) {
    std::ostringstream o;
    o.precision(17);
    o << "legs of total length " << length << " for a displacement of length " << asked << " (limit " << limit << ")";
    return o.str();
  }
  return "";
}

// --- scenes -------------------------------------------------------------------------------------

/// An integer in [lo, hi), uniform whatever RapidCheck's size (a choice of scene, not a value to
/// grow): inRange scales its range down with the size.
inline int pick(int lo, int hi) {
  return *rc::gen::resize(100, rc::gen::inRange(lo, hi));
}

/// True or false, evenly.
inline bool coin() {
  return pick(0, 2) == 1;
}

/// A mover: a circle, a capsule of any direction, a point or a segment (radius 0), at scale s
/// about the origin of its frame.
template <Scalar T>
Shape<T> gen_mover(double s) {
  using V = Vec2<T>;
  const bool round = pick(0, 8) != 0;
  const T radius = T(round ? grid(1, 8) * s / 4 : 0.0);
  const V c(T(grid(-2, 2) * s / 2), T(grid(-2, 2) * s / 2));
  if (coin()) return Circle<T>(c, radius);
  const V half(T(grid(-8, 8) * s / 8), T(grid(-8, 8) * s / 8));
  return Capsule<T>(V(c - half), V(c + half), radius);
}

/// A move among one to eight bodies (see the top of this file).
template <Scalar T>
Move<T> gen_scene_move() {
  using V = Vec2<T>;
  Move<T> m;
  const double s = std::array<double, 4>{0.25, 0.5, 1.0 / 16, 4.0}[std::size_t(pick(0, 4))];
  const int n = pick(1, 9);
  const bool filtering = pick(0, 4) == 0;
  for (int i = 0; i < n; ++i) {
    // Half the bodies at half the scale, spread by a translation: room between them.
    const bool spread = coin();
    const auto kind = static_cast<ShapeKind>(pick(0, int(kKindCount)));
    SceneBody<T> b{gen_shape_of<T>(kind, spread ? s / 2 : s), Transform<T>()};
    if (spread) b.x = Transform<T>::make_translation(V(T(grid(-32, 32) * s / 2), T(grid(-32, 32) * s / 2))).value();
    if (pick(0, 3) == 0) b.x = gen_transform<T>(s);
    if (filtering && pick(0, 3) == 0) b.filter = bp::Filter{2, 0xffffffffu};
    b.ignored = pick(0, 10) == 0;
    m.bodies.push_back(b);
  }
  if (filtering) m.filter = bp::Filter{1, 1};
  m.mover = gen_mover<T>(s);
  // The start: anywhere (clear of every body when one of four tries is), or on top of a body's
  // box (touching, a hair above or below).
  const int start = pick(0, 3);
  if (start == 0) {
    for (int attempt = 0; attempt < 4; ++attempt) {
      m.from = gen_transform<T>(s);
      const bool clear = std::none_of(m.bodies.begin(), m.bodies.end(),
                                      [&](const SceneBody<T>& b) { return overlaps(m.mover, m.from, b.shape, b.x); });
      if (clear) break;
    }
  } else {
    const SceneBody<T>& under = m.bodies[std::size_t(pick(0, n))];
    const Aabb<T> box = bounds(under.shape, under.x);
    const Aabb<T> own = bounds(m.mover);
    const double x = double(box.min().x()) + (double(box.max().x()) - double(box.min().x())) * grid(0, 8) / 8;
    double y = double(box.max().y()) - double(own.min().y());
    const int hair = pick(-2, 3);
    y += hair * std::fabs(y) * double(std::numeric_limits<T>::epsilon()) * 4;
    const Expected<Transform<T>> x0 = Transform<T>::make_translation(V(T(x), T(y)));
    m.from = x0 ? x0.value() : Transform<T>();
  }
  // The displacement: none, aimed at a body's centre (half to three times the way), along an
  // axis, or random.
  const int aim = pick(0, 8);
  if (aim == 0) {
    m.d = V::Zero();
  } else if (aim <= 4) {
    const SceneBody<T>& target = m.bodies[std::size_t(pick(0, n))];
    const Aabb<T> box = bounds(target.shape, target.x);
    const Vec2c centre = (widen(box.min()) + widen(box.max())) / 2, here = widen(m.from.position());
    m.d = ((centre - here) * (grid(2, 12) / 4)).template cast<T>();
  } else if (aim == 5) {
    const T len = T(grid(-64, 64) * s / 4);
    m.d = coin() ? V(len, 0) : V(0, len);
  } else {
    m.d = V(T(grid(-64, 64) * s / 4), T(grid(-64, 64) * s / 4));
  }
  if (!m.d.allFinite()) m.d = V::Zero();
  m.max_iterations = pick(1, bp::kMoveMaxIterations + 1);
  m.skin = pick(0, 3) == 0 ? T(grid(0, 16) * s / 64) : T(0);
  run(m);
  return m;
}

/// A floor move: the floor, the mover resting on it, the horizontal displacement D.
template <Scalar T>
struct FloorMove {
  Move<T> move;
  double top = 0;      ///< the floor's top
  bool exact = false;  ///< the mover's lowest point is exactly at top + gap (no rotation)
};

/// Law 4's scene: a long box or a row of flush boxes, rectangles or OBBs, in world space or placed
/// by translations, with a circle or a capsule (level, upright or tilted) on it, touching or
/// just above; moved horizontally by up to 8.
template <Scalar T>
FloorMove<T> gen_floor_move() {
  using V = Vec2<T>;
  FloorMove<T> f;
  Move<T>& m = f.move;
  f.top = grid(-16, 16) / 8;
  const double along = grid(1, 64) / 8 * (coin() ? 1 : -1);
  const double x0 = grid(-16, 16) / 4;
  // The mover and how far its lowest point lies below its position.
  const double r = grid(1, 8) / 8, half = grid(0, 8) / 8;
  const int style = pick(0, 4);
  double below = r;
  double angle = 0;
  if (style == 0) {
    m.mover = Circle<T>(V(0, 0), T(r));
  } else if (style == 1) {
    m.mover = Capsule<T>(V(T(-half), 0), V(T(half), 0), T(r));
  } else if (style == 2) {
    m.mover = Capsule<T>(V(0, T(-half)), V(0, T(half)), T(r));
    below = half + r;
  } else {
    m.mover = Capsule<T>(V(T(-half), 0), V(T(half), 0), T(r));
    angle = grid(-15, 15) / 10;
  }
  const int gap_style = pick(0, 4);
  const double gap = gap_style == 0 ? 0.0 : gap_style == 1 ? grid(1, 64) * 0x1p-12 : grid(1, 16) / 32;
  if (angle != 0) {
    m.from = Transform<T>::make(V(T(x0), T(f.top + 1)), T(angle)).value();
    // The lowest point of the turned capsule, from its stored rotation (within rounding of exact).
    const double drop = std::fabs(double(m.from.rotation().y()) * half) + r;
    m.from = Transform<T>::make_with_rotation(V(T(x0), T(f.top + drop + gap)), m.from.rotation()).value();
  } else {
    m.from = Transform<T>::make_translation(V(T(x0), T(f.top + below + gap))).value();
    f.exact = true;
  }
  // The floor, reaching 4 beyond the mover's path on both sides.
  const bool placed = coin();
  if (pick(0, 3) == 0) {
    const Aabb<T> local(V(-128, -1), V(128, 0));
    if (placed) {
      m.bodies.push_back({local, Transform<T>::make_translation(V(0, T(f.top))).value()});
    } else {
      m.bodies.push_back({Aabb<T>(V(-128, T(f.top - 1)), V(128, T(f.top))), Transform<T>()});
    }
  } else {
    const double w = grid(1, 8) / 4;
    const double lo = std::floor((std::min(x0, x0 + along) - 4) / w) * w, hi = std::max(x0, x0 + along) + 4;
    for (double x = lo; x < hi; x += w) {
      const int kind = pick(0, 3);
      const double a = placed ? 0.0 : x, b = placed ? w : x + w, y0 = placed ? -1.0 : f.top - 1,
                   y1 = placed ? 0.0 : f.top;
      Shape<T> tile = Aabb<T>(V(T(a), T(y0)), V(T(b), T(y1)));
      if (kind == 1) tile = ConvexPolygon<T>({V(T(a), T(y0)), V(T(b), T(y0)), V(T(b), T(y1)), V(T(a), T(y1))});
      if (kind == 2) {
        tile = Obb<T>::make_with_axis(V(T((a + b) / 2), T((y0 + y1) / 2)), V(T(w / 2), T(0.5)), V(1, 0)).value();
      }
      m.bodies.push_back({tile, placed ? Transform<T>::make_translation(V(T(x), T(f.top))).value() : Transform<T>()});
    }
  }
  m.d = V(T(along), 0);
  m.skin = pick(0, 4) == 0 ? T(grid(1, 8) / 256) : T(0);
  run(m);
  return f;
}

/// Law 4: a floor move goes the whole way less at most the skin, rising at most the skin and never
/// sinking, up to rho per leg.
template <Scalar T>
std::string floor_slide(const FloorMove<T>& f) {
  const Move<T>& m = f.move;
  const bp::MoveResult<T>& r = m.result;
  if (r.outcome != bp::MoveOutcome::Completed) return "a floor move ended " + std::string(bp::name(r.outcome));
  if (!(r.rounding <= rho_cap(m))) return "rho above its bound";
  const double slack = double(r.path_count) * r.rounding;
  const double along = double(m.d.x()), sign = along > 0 ? 1 : -1;
  const double dx = (double(r.transform.position().x()) - double(m.from.position().x())) * sign;
  const double dy = double(r.transform.position().y()) - double(m.from.position().y());
  std::ostringstream o;
  o.precision(17);
  if (!(dx >= std::fabs(along) - r.skin - slack && dx <= std::fabs(along) + slack))
    o << "moved " << dx << " along the floor for " << std::fabs(along) << " (skin " << r.skin << ")";
  else if (!(dy >= -slack && dy <= r.skin + slack))
    o << "rose " << dy << " (skin " << r.skin << ", rho " << r.rounding << ")";
  return o.str();
}

/// A wall move: the wall (body 0), a quarter turn k that places the scene, the canonical
/// displacement (toward the wall along +x, possibly with a tangential part).
template <Scalar T>
struct WallMove {
  Move<T> move;
  int turn = 0;
  Vec2<double> canonical = Vec2<double>::Zero();
};

/// (x, y) turned by k quarter turns (exact).
template <class V>
V quarter_turned(const V& v, int k) {
  switch (k & 3) {
    case 1:
      return V(-v.y(), v.x());
    case 2:
      return V(-v.x(), -v.y());
    case 3:
      return V(v.y(), -v.x());
    default:
      return v;
  }
}

/// Law 5's scene, in a canonical frame turned by k quarter turns: a tall wall [w, w + t] x [-64,
/// 64] (a box, a rectangle or an OBB, placed by the turn), a circle or a capsule turned by any
/// angle, clear of it by 1/16 to 2; moved toward it head-on past it, or at an angle.
template <Scalar T>
WallMove<T> gen_wall_move(bool head_on) {
  using V = Vec2<T>;
  WallMove<T> w;
  Move<T>& m = w.move;
  w.turn = pick(0, 4);
  const std::array<V, 4> quarter = {V(1, 0), V(0, 1), V(-1, 0), V(0, -1)};
  const double wx = grid(-8, 8) / 4, thick = grid(1, 8) / 8;
  const int kind = pick(0, 3);
  Shape<T> wall = Aabb<T>(V(T(wx), -64), V(T(wx + thick), 64));
  if (kind == 1) wall = ConvexPolygon<T>({V(T(wx), -64), V(T(wx + thick), -64), V(T(wx + thick), 64), V(T(wx), 64)});
  if (kind == 2) wall = Obb<T>::make_with_axis(V(T(wx + thick / 2), 0), V(T(thick / 2), 64), V(1, 0)).value();
  m.bodies.push_back({wall, Transform<T>::make_with_rotation(V(0, 0), quarter[std::size_t(w.turn)]).value()});
  m.mover = gen_mover<T>(0.25);
  // The mover turned by any angle, then put clear of the wall by `clear` in the canonical frame.
  const Transform<T> turned = Transform<T>::make(V(0, 0), T(grid(-31, 31) / 10)).value();
  const double reach = double(bounds(m.mover, turned).max().x());
  const double clear = grid(1, 32) / 16, y0 = grid(-16, 16) / 4;
  const V p(T(wx - clear - reach), T(y0));
  m.from =
      Transform<T>::make_with_rotation(quarter_turned(p, w.turn), quarter_turned(turned.rotation(), w.turn)).value();
  const double along = clear + grid(1, 32) / 8, across = head_on ? 0.0 : grid(1, 32) / 8 * (coin() ? 1 : -1);
  w.canonical = Vec2<double>(along, across);
  m.d = quarter_turned(V(T(along), T(across)), w.turn);
  m.skin = pick(0, 4) == 0 ? T(clear / 8) : T(0);
  run(m);
  return w;
}

/// Law 5: head-on, the mover stops in front of the wall (Blocked, within skin + tolerance of it,
/// not moved across the motion); at an angle it slides along the wall by the whole tangential
/// component (Completed) and ends within skin + tolerance of it.
template <Scalar T>
std::string wall_stop(const WallMove<T>& w, bool head_on) {
  const Move<T>& m = w.move;
  const bp::MoveResult<T>& r = m.result;
  const SceneBody<T>& wall = m.bodies[0];
  if (!(r.rounding <= rho_cap(m))) return "rho above its bound";
  if (r.outcome != (head_on ? bp::MoveOutcome::Blocked : bp::MoveOutcome::Completed))
    return "a wall move ended " + std::string(bp::name(r.outcome));
  // The move in the canonical frame (turned back exactly).
  const Vec2<double> moved = quarter_turned(
      Vec2<double>(r.transform.position().template cast<double>() - m.from.position().template cast<double>()),
      4 - w.turn);
  const double slack = double(r.path_count) * r.rounding;
  const double tangential = w.canonical.y();
  std::ostringstream o;
  o.precision(17);
  const double d_len = std::hypot(w.canonical.x(), w.canonical.y());
  if (!(std::fabs(moved.y() - tangential) <= slack + 0x1p-30 * d_len)) {
    o << "moved " << moved.y() << " along the wall for " << tangential;
    return o.str();
  }
  if (!(moved.x() >= 0 && moved.x() <= w.canonical.x() + slack)) {
    o << "moved " << moved.x() << " toward the wall for " << w.canonical.x();
    return o.str();
  }
  // Within skin + tolerance of the wall: the cast tolerance of the mover grown by the skin, over
  // twice the displacement (every leg's motion and start lie within it).
  const Shape<T> grown = std::visit(
      [&](const auto& s) -> Shape<T> {
        using S = std::decay_t<decltype(s)>;
        const auto grown_radius = [&](T radius) {
          return std::nextafter(T(double(radius) + r.skin), std::numeric_limits<T>::infinity());
        };
        if constexpr (std::is_same_v<S, Circle<T>>) {
          return Circle<T>(s.center(), grown_radius(s.radius()));
        } else if constexpr (std::is_same_v<S, Capsule<T>>) {
          return Capsule<T>(s.a(), s.b(), grown_radius(s.radius()));
        } else {
          return s;
        }
      },
      m.mover);
  const double tol =
      2 * cast_tolerance(grown, m.from, Vec2<T>(2 * m.d), wall.shape, wall.x, Vec2<T>::Zero(), T(1)) + 4 * r.rounding;
  if (oracle::compare_distance(mover_at(m, r.transform.position()), oracle::placed(wall.shape, wall.x), r.skin + tol) >
      0) {
    o << "stopped farther than skin " << r.skin << " + " << tol << " from the wall, gap ~"
      << oracle::approx_signed_distance(mover_at(m, r.transform.position()), oracle::placed(wall.shape, wall.x));
    return o.str();
  }
  return "";
}

// --- the tests ----------------------------------------------------------------------------------

/// Fails the property with the law's account and the move's, when the law does not hold.
template <Scalar T>
void hold(const std::string& why, const Move<T>& m) {
  if (!why.empty()) RC_FAIL(why + "\n" + describe(m));
}

/// Tags a scene by what its move met, so that a run shows the laws were exercised.
template <Scalar T>
void tag(const Move<T>& m) {
  bool resting = false, hit = false;
  for (const bp::MovePlane<T>& p : m.result.contacts()) (p.resting ? resting : hit) = true;
  ++g_stats.moves;
  g_stats.resting += resting;
  g_stats.hits += hit;
  g_stats.slid += hit && m.result.outcome == bp::MoveOutcome::Completed;
  RC_TAG(std::string(bp::name(m.result.outcome)), resting ? "resting" : "free", hit ? "hit" : "no hit");
}

template <Scalar T>
void scene_law(std::string (*law)(const Move<T>&)) {
  const Move<T> m = gen_scene_move<T>();
  tag(m);
  hold(law(m), m);
}

RC_GTEST_PROP(MoverLaws, no_new_overlap_float, ()) {
  scene_law<float>(&no_new_overlap<float>);
}
RC_GTEST_PROP(MoverLaws, no_new_overlap_double, ()) {
  scene_law<double>(&no_new_overlap<double>);
}
RC_GTEST_PROP(MoverLaws, never_tunnels_float, ()) {
  scene_law<float>(&never_tunnels<float>);
}
RC_GTEST_PROP(MoverLaws, never_tunnels_double, ()) {
  scene_law<double>(&never_tunnels<double>);
}
RC_GTEST_PROP(MoverLaws, never_farther_float, ()) {
  scene_law<float>(&never_farther<float>);
}
RC_GTEST_PROP(MoverLaws, never_farther_double, ()) {
  scene_law<double>(&never_farther<double>);
}

template <Scalar T>
void floor_law() {
  const FloorMove<T> f = gen_floor_move<T>();
  tag(f.move);
  hold(floor_slide(f), f.move);
  // The floor scenes are moves too: laws 1 to 3 hold for them.
  hold(no_new_overlap(f.move), f.move);
  hold(never_farther(f.move), f.move);
}
RC_GTEST_PROP(MoverLaws, floor_slide_float, ()) {
  floor_law<float>();
}
RC_GTEST_PROP(MoverLaws, floor_slide_double, ()) {
  floor_law<double>();
}

template <Scalar T>
void wall_law() {
  const bool head_on = coin();
  const WallMove<T> w = gen_wall_move<T>(head_on);
  tag(w.move);
  RC_TAG(head_on ? "head-on" : "at an angle");
  hold(wall_stop(w, head_on), w.move);
  hold(no_new_overlap(w.move), w.move);
}
RC_GTEST_PROP(MoverLaws, wall_stop_float, ()) {
  wall_law<float>();
}
RC_GTEST_PROP(MoverLaws, wall_stop_double, ()) {
  wall_law<double>();
}

}  // namespace
}  // namespace collide::props

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const int rc = RUN_ALL_TESTS();
  const collide::props::Stats& s = collide::props::g_stats;
  std::printf(
      "mover stats: moves=%ld with_resting_contacts=%ld with_hits=%ld slid_to_completion=%ld "
      "clear_bodies_judged_along_legs=%ld of_them_hit=%ld legs_judged=%ld\n",
      s.moves, s.resting, s.hits, s.slid, s.clear_bodies, s.hit_bodies, s.legs_judged);
  return rc;
}
