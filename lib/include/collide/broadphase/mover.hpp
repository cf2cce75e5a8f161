#pragma once
/// @file broadphase/mover.hpp
/// A mover for characters: move_and_slide() moves a circle or a capsule by a displacement among a
/// World's bodies, stops in front of what it meets and slides along it, as a kinematic character
/// controller does. Built on shape_cast().
///
/// Semantics. The mover is a Circle or a Capsule stored in its local frame and placed by `from`
/// (any other kind is refused: UnsupportedMover). It only translates: its rotation is kept bit for
/// bit. The bodies that block are the live bodies of the world whose filter accepts
/// options.filter (accepts()) and that options.ignore does not list (the character's own body).
/// The mover travels a polyline of straight legs between positions stored in T: result.path[0] is
/// from's position, result.path[result.path_count - 1] the final one. Touching counts as meeting.
///
/// Distances of the contract (in double; eps_T = numeric_limits<T>::epsilon()):
/// - rho = move_rounding(mover, from, displacement) = 4 eps_T M + 4 denorm_min_T, M the largest
///   absolute coordinate of bounds(mover, from) and of from's position, plus |displacement| (no
///   position of the path lies farther out): rho bounds the rounding of a leg's length, and more
///   than twice that of its stored end (within sqrt(2) eps_T M of the exact point it stands for).
/// - band_j = move_band(mover, from, displacement, body_j, x_j): a few cast tolerances of the pair
///   over the move, plus rho and the distance's own error. A blocking body whose exact gap from
///   the mover at `from` exceeds band_j is *clear*; a body within band_j of it may be a *resting
///   contact* (the mover starts touching, nearly touching or overlapping it).
/// - s, the skin (result.skin): the distance the mover keeps from what it meets, at most the
///   larger of options.skin and kMoveSkinFactor * max(rho, the cast tolerances of the bodies
///   near the start).
///
/// Contract:
/// 1. Never a new overlap: at the end, the exact mover overlaps no clear blocking body.
/// 2. Never tunnels: along every leg, the exact mover stays apart from every clear blocking body.
/// 3. Never farther than asked: the legs' lengths sum to at most |displacement| + (path_count - 1)
///    rho; so does the displacement made.
/// 4. Resting contacts are not pushed out of. While the mover stays within band_j of one, that body
///    is not cast against and the move never goes toward it along its contact normal; when the
///    move has a way on, it first lifts off them, along their normals, by up to min(s, |the
///    displacement's part that goes into none of them|), spending that much of the displacement's
///    length. Lifted clear, they block as any other body: a mover resting on a row of flush bodies
///    slides over their seams without catching. A mover overlapping a body deeper than the lift
///    stays in it (resolve() pushes it out).
/// 5. Stops in front: a leg that meets a body ends with the mover apart from it and within
///    s + cast_tolerance + 2 rho of it.
/// 6. Slides: after a hit, the rest of the displacement is projected onto the directions that go
///    into no plane met so far (every hit's normal, and those of the resting contacts it is still
///    within band of), so a move into a wall at an angle goes on along it by the tangential
///    component, and a corner stops it. (A resting contact lifted clear is dropped from them: the
///    normal of a flush neighbour's corner is tilted, and keeping it would raise the mover along
///    that tangent for the rest of the move.)
/// 7. Outcome: Completed (the displacement is used up), Blocked (the planes met leave no way on,
///    the mover is wedged closer to a body than rho / 2, or more than kMoveMaxPlanes planes were met),
///    IterationLimit (options.max_iterations legs taken after the lift, displacement left). Bad
///    input (a NaN, infinite or out-of-range displacement or skin, max_iterations outside
///    [1, kMoveMaxIterations]) is InvalidInput; a mover of another kind UnsupportedMover; both
///    leave the mover where it was (transform == from, displacement zero, no plane).
/// 8. No allocation: the planes and the path are fixed arrays, candidates are visited, not stored.
///    The world is only read: any number of moves may run at once with its other const members.
///
/// A flat floor therefore carries a resting mover the whole horizontal displacement, less at most
/// s for the lift, which raises it by at most s; a mover just above the floor (beyond band_j)
/// moves by exactly the displacement, up to rounding.
///
/// Method, one leg at a time:
///
///     survey the bodies near the mover: resting contacts at the start (their planes), the skin s,
///       the margin m = 2 (the largest cast tolerance near it + rho)
///     clip d against the resting planes: nothing left, stop (nothing moved)
///     lift off them by up to min(s, |what is left|), spent from |d|
///     repeat up to max_iterations times:
///       survey the bodies near the mover: which resting contacts are still within their band,
///         the least gap g of the others
///       kappa = min(s, max(g / 2, g - m)); below rho / 2, stop (wedged)
///       clip d against the hits' planes and those resting planes (projection onto their cone)
///       cast the mover inflated by kappa along d against every candidate body that is not a
///         resting contact still within its band (broadphase query on the swept box)
///       advance to the earliest hit time t: the inflated mover is apart from everything up to t,
///         so the mover keeps kappa from it, more than its stored position's rounding
///       no hit: done; else record the hit's plane and keep (1 - t) d
///
/// kappa follows the gaps: a mover sliding at gap g along a floor never meets the corner of the
/// next flush body (its inflation stays m below g), and each cast starts at least min(g / 2, m)
/// from every body, beyond the cast's tolerance, so that no leg stalls on a hit at its start.

#include "collide/broadphase/common.hpp"
#include "collide/broadphase/world.hpp"
#include "collide/cast.hpp"
#include "collide/contact.hpp"
#include "collide/distance.hpp"
#include "collide/shapes.hpp"
#include "collide/transform.hpp"
#include "collide/transformed.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>

namespace collide::broadphase {

/// The most legs a move takes after its lift: MoveOptions::max_iterations lies in [1, this].
inline constexpr int kMoveMaxIterations = 8;
/// The most planes (resting contacts and hits) a move records; one more stops it (Blocked).
inline constexpr std::size_t kMoveMaxPlanes = 16;
/// The most positions a path holds: the start, the lift's end and one per leg.
inline constexpr std::size_t kMovePathCapacity = std::size_t(kMoveMaxIterations) + 2;
/// The resting limit in units of (cast tolerance + rho): a non-resting body's casts then start
/// beyond their tolerance even at half its gap.
inline constexpr Calc kMoveBandFactor = 4;
/// The automatic skin in units of max(rho, cast tolerance): room for the inflation to shrink by
/// the margin at many hits in a row, each close to the last, and still stay beyond both.
inline constexpr Calc kMoveSkinFactor = 64;

/// Why a move stopped.
enum class MoveOutcome : std::uint8_t {
  Completed,        ///< the displacement was used up (sliding included)
  Blocked,          ///< the planes met leave no way on, or the mover is wedged (see the contract)
  IterationLimit,   ///< max_iterations legs taken with displacement left
  InvalidInput,     ///< NaN, infinite or out-of-range displacement or options: nothing moved
  UnsupportedMover  ///< the mover is neither a circle nor a capsule: nothing moved
};

/// Stable name of a move's outcome, e.g. "Blocked".
constexpr std::string_view name(MoveOutcome o) noexcept {
  switch (o) {
    case MoveOutcome::Completed:
      return "Completed";
    case MoveOutcome::Blocked:
      return "Blocked";
    case MoveOutcome::IterationLimit:
      return "IterationLimit";
    case MoveOutcome::InvalidInput:
      return "InvalidInput";
    case MoveOutcome::UnsupportedMover:
      return "UnsupportedMover";
  }
  return "Unknown";
}

/// A plane the mover met: a resting contact at the start or a hit along the way.
template <Scalar T>
struct MovePlane {
  Vec2<T> normal = Vec2<T>::Zero();  ///< unit, from the mover toward the body; the move then never goes along it
  Vec2<T> point = Vec2<T>::Zero();   ///< where they met, midway between the surfaces, in world coordinates
  ProxyId body;                      ///< the body met
  bool resting = false;              ///< a resting contact at the start (true) or a hit (false)
};

/// What blocks a move, how many legs it may take and the distance it keeps.
template <Scalar T>
struct MoveOptions {
  Filter filter = Filter::everything();  ///< the bodies that block: those whose filter accepts this one
  std::span<const ProxyId> ignore{};     ///< bodies that never block (the character's own body); not owned
  int max_iterations = 4;                ///< legs after the lift, in [1, kMoveMaxIterations]
  T skin = T(0);                         ///< distance kept from what the mover meets; the automatic skin when larger
};

/// The answer of move_and_slide().
template <Scalar T>
struct MoveResult {
  MoveOutcome outcome = MoveOutcome::InvalidInput;    ///< why the move stopped
  Transform<T> transform;                             ///< where it ends: from's rotation, the path's last position
  Vec2<T> displacement = Vec2<T>::Zero();             ///< transform.position() - from.position(), rounded to T
  std::array<MovePlane<T>, kMoveMaxPlanes> planes{};  ///< the planes met, in order: planes[0, plane_count)
  std::size_t plane_count = 0;                        ///< how many planes were met
  std::array<Vec2<T>, kMovePathCapacity> path{};      ///< the legs' ends, from the start: path[0, path_count)
  std::size_t path_count = 0;                         ///< at least 1 (the start)
  Calc skin = 0;                                      ///< the skin s used (0 for refused input)
  Calc rounding = 0;                                  ///< rho of the contract (0 for refused input)

  /// The planes met.
  std::span<const MovePlane<T>> contacts() const noexcept { return {planes.data(), plane_count}; }
  /// The positions the mover passed, from the start to the end.
  std::span<const Vec2<T>> positions() const noexcept { return {path.data(), path_count}; }
};

/// rho of the contract: 4 eps_T M + 4 denorm_min_T, M the largest absolute coordinate of
/// bounds(mover, from) and of from's position, plus |displacement| (every position of the path
/// lies within it). A leg's end is two roundings to T of values within M (sqrt(2) eps_T M), its
/// length off by the rounding of the motion to T and of the clipping in double: 4 eps_T M covers
/// both.
template <AnyShape S>
Calc move_rounding(const S& mover, const Transform<scalar_of_t<S>>& from, const Vec2<scalar_of_t<S>>& displacement) {
  using T = scalar_of_t<S>;
  const Calc m =
      std::max(collide::detail::scale_of(bounds(mover, from)), widen(from.position()).cwiseAbs().maxCoeff()) +
      collide::detail::norm_of(widen(displacement));
  return 4 * Calc(std::numeric_limits<T>::epsilon()) * m + 4 * Calc(std::numeric_limits<T>::denorm_min());
}

namespace detail {

/// The distance below which a body counts as a resting contact, on distance()'s computed value:
/// kMoveBandFactor (e + rho), e = cast_tolerance of the pair over the move.
inline Calc resting_limit(Calc e, Calc rho) noexcept {
  return kMoveBandFactor * (e + rho);
}

/// distance()'s error for a computed gap g of a pair with rounding unit u: 4 u + 4 eps_T g +
/// 2 denorm_min_T (the bound the distance laws judge).
template <Scalar T>
Calc distance_error(Calc g, Calc u) noexcept {
  return 4 * u + 4 * Calc(std::numeric_limits<T>::epsilon()) * g + 2 * Calc(std::numeric_limits<T>::denorm_min());
}

}  // namespace detail

/// band_j of the contract: the exact gap at `from` at or below which the body may be a resting
/// contact. A body counts as resting when distance(mover, from, body, x) is at most
/// kMoveBandFactor (cast_tolerance(mover, from, displacement, body, x, 0, 1) + rho); this is that
/// limit plus distance()'s error, so every body with a larger exact gap is clear.
template <AnyShape S, AnyShape B>
requires std::is_same_v<scalar_of_t<S>, scalar_of_t<B>> Calc
move_band(const S& mover, const Transform<scalar_of_t<S>>& from, const Vec2<scalar_of_t<S>>& displacement,
          const B& body, const Transform<scalar_of_t<S>>& body_transform) {
  using T = scalar_of_t<S>;
  const Calc rho = move_rounding(mover, from, displacement);
  const Calc e = cast_tolerance(mover, from, displacement, body, body_transform, Vec2<T>::Zero(), T(1));
  const Calc limit = detail::resting_limit(e, rho);
  const Calc u = rounding_tolerance(mover, from, body, body_transform);
  return (limit + detail::distance_error<T>(limit, u)) * (1 + 2 * Calc(std::numeric_limits<T>::epsilon()));
}

namespace detail {

/// The input is one move_and_slide() accepts (see InvalidInput in the contract): a finite
/// displacement whose path stays within max_magnitude<T>(), options in range, and room for the
/// mover's radius plus the skin.
template <Scalar T>
bool move_input_valid(T radius, const Transform<T>& from, const Vec2<T>& d, const MoveOptions<T>& options) noexcept {
  const Calc lim = Calc(max_magnitude<T>());
  if (!d.allFinite() || widen(d).cwiseAbs().maxCoeff() > lim) return false;
  const Calc reach = 2 * collide::detail::norm_of(widen(d));
  if (widen(from.position()).cwiseAbs().maxCoeff() + reach > lim) return false;
  if (options.max_iterations < 1 || options.max_iterations > kMoveMaxIterations) return false;
  const Calc skin = Calc(options.skin);
  return std::isfinite(skin) && skin >= 0 && Calc(radius) + 2 * skin <= lim / 2;
}

/// The box of b moved along v (every point of b + s v, s in [0, 1]) grown by pad, rounded outward
/// to T and kept within the range every box may have.
template <Scalar T>
Aabb<T> swept_box(const Aabb<T>& b, const Vec2c& v, Calc pad) noexcept {
  const Vec2c lo = widen(b.min()), hi = widen(b.max());
  const Vec2c slo = (lo.cwiseMin(lo + v).array() - pad).matrix(), shi = (hi.cwiseMax(hi + v).array() + pad).matrix();
  const Aabb<T> out = bounds_from_calc<T>(slo, shi);
  const Vec2<T> top = Vec2<T>::Constant(max_magnitude<T>());
  return collide::detail::AabbAccess::unchecked<T>(out.min().cwiseMax(-top), out.max().cwiseMin(top));
}

/// The projection of d onto the directions that go into no active plane (v . n <= 0 for every
/// active normal n): d itself when it goes into none; else the nearest of its projections onto the
/// planes it goes into that goes into no other; else zero. In the plane these are the only
/// candidates: the nearest point of a cone of half-planes lies on one of their lines, or is its
/// apex.
template <std::size_t N>
Vec2c clip_to_planes(const Vec2c& d, const std::array<Vec2c, N>& normals, const std::array<bool, N>& active,
                     std::size_t count) noexcept {
  // Rounding leaves a projection a hair into its own plane: a slope of 2^-30 is not "into".
  const auto free_of_all = [&](const Vec2c& v) {
    const Calc tol = 0x1p-30 * collide::detail::norm_of(v);
    for (std::size_t i = 0; i < count; ++i) {
      if (active[i] && normals[i].dot(v) > tol) return false;
    }
    return true;
  };
  if (free_of_all(d)) return d;
  Vec2c best = Vec2c::Zero();
  Calc best_loss = std::numeric_limits<Calc>::infinity();
  for (std::size_t i = 0; i < count; ++i) {
    if (!active[i]) continue;
    const Calc into = normals[i].dot(d);
    if (!(into > 0) || into >= best_loss) continue;
    const Vec2c v = d - into * normals[i];
    if (free_of_all(v)) best = v, best_loss = into;
  }
  return best;
}

/// A lift off planes before a motion along `ahead`, of length at most len: across the motion, to
/// the side the planes face away from, when that goes away from each by len / 2 (off a floor and
/// the slightly tilted corner of the next flush body, straight up: nothing spent backward); else
/// away from each normal by len where the planes allow it (a few Gauss-Seidel rounds of "push back
/// along n until v . n <= -len"), without its part against `ahead` when it still goes away from
/// each by len / 2; zero when it would go toward any of them.
template <std::size_t N>
Vec2c lift_off(const std::array<Vec2c, N>& normals, std::size_t count, Calc len, const Vec2c& ahead) noexcept {
  const auto away_from_all = [&](const Vec2c& w, Calc by) {
    for (std::size_t i = 0; i < count; ++i) {
      if (normals[i].dot(w) > -by) return false;
    }
    return true;
  };
  // 1. Across the motion.
  const Vec2c u = collide::detail::unit_of(ahead);
  Vec2c side = perp(u);
  Calc facing = 0;
  for (std::size_t i = 0; i < count; ++i) facing += normals[i].dot(side);
  if (facing > 0) side = -side;
  if (away_from_all(len * side, len / 2)) return len * side;
  // 2. Off each plane by len, as far as they allow.
  Vec2c v = Vec2c::Zero();
  for (int round = 0; round < 4; ++round) {
    for (std::size_t i = 0; i < count; ++i) {
      const Calc short_of = normals[i].dot(v) + len;
      if (short_of > 0) v -= short_of * normals[i];
    }
  }
  const Calc n = collide::detail::norm_of(v);
  if (n > len) v *= len / n;
  const Calc back = v.dot(u);
  if (back < 0 && away_from_all(v - back * u, len / 2)) v -= back * u;
  return away_from_all(v, 0) ? v : Vec2c::Zero();
}

/// One move_and_slide() of a mover of concrete kind M (Circle<T> or Capsule<T>): its state along
/// the path, and the result it fills in. See the method at the top of this file.
template <Scalar T, class BP, class M>
class SlideMove {
 public:
  /// A move of `mover` from `from` among the bodies of `world`, writing into `out`; rho as
  /// move_rounding() gives it.
  SlideMove(const World<T, BP>& world, const M& mover, const Transform<T>& from, const MoveOptions<T>& options,
            Calc rho, MoveResult<T>& out) noexcept
      : world_(world), mover_(mover), options_(options), x_(from), rho_(rho), out_(out) {}

  /// Moves by d (validated): the steps of the method, then the result.
  void run(const Vec2<T>& displacement) {
    Vec2c d = widen(displacement);
    out_.rounding = rho_;
    // 1. The start: resting contacts (exempt from the casts for now), the skin.
    const bool room = survey_start(displacement);
    out_.skin = skin_;
    if (!room) return finish(MoveOutcome::Blocked);
    // 2. Every part of the displacement goes into a resting plane: nothing moves.
    const Vec2c free = clip(d);
    if (!(collide::detail::norm_of(free) > rho_))
      return finish(collide::detail::norm_of(d) > rho_ ? MoveOutcome::Blocked : MoveOutcome::Completed);
    // 3. The lift off the resting contacts, spent from the displacement's length.
    if (resting_count_ > 0 && !lift(d, free)) return;
    // 4. The legs.
    for (int leg = 0; leg < options_.max_iterations; ++leg) {
      const Calc kappa = inflation(survey_gaps());
      const Vec2c v = clip(d);
      if (!(collide::detail::norm_of(v) > rho_))
        return finish(collide::detail::norm_of(d) > rho_ ? MoveOutcome::Blocked : MoveOutcome::Completed);
      if (!(kappa >= rho_ / 2)) return finish(MoveOutcome::Blocked);
      const Hit h = cast_leg(v, kappa);
      if (!h.stopped) return finish(MoveOutcome::Completed);
      if (!add_hit(h)) return finish(MoveOutcome::Blocked);
      d = v * (1 - h.t);
    }
    finish(!(collide::detail::norm_of(clip(d)) > rho_) ? MoveOutcome::Completed : MoveOutcome::IterationLimit);
  }

 private:
  /// Where a leg stopped: the time along it and, for a hit, the plane.
  struct Hit {
    bool stopped = false;  ///< the leg met a body before its end
    Calc t = 1;            ///< the fraction of the leg made
    ProxyId body;
    Vec2c normal = Vec2c::Zero();
    Vec2<T> point = Vec2<T>::Zero();
  };

  /// Whether the world's body `id` blocks: the query applied the filter, the ignore list is here.
  bool blocks(ProxyId id) const noexcept {
    return std::find(options_.ignore.begin(), options_.ignore.end(), id) == options_.ignore.end();
  }

  /// The index of a resting plane of `id`, or kMoveMaxPlanes.
  std::size_t resting_plane_of(ProxyId id) const noexcept {
    for (std::size_t i = 0; i < out_.plane_count; ++i) {
      if (out_.planes[i].resting && out_.planes[i].body == id) return i;
    }
    return kMoveMaxPlanes;
  }

  /// A lower bound on the exact gap from the mover (at x_) of a body whose computed distance is g.
  Calc gap_lower(const Shape<T>& body, const Transform<T>& xb, Calc g) const {
    return g - distance_error<T>(g, rounding_tolerance(mover_, x_, body, xb));
  }

  /// Calls f(id, shape, transform) for every blocking body whose box meets box.
  template <class F>
  void for_each_blocking(const Aabb<T>& box, F&& f) const {
    world_.broadphase().query(
        box,
        [&](ProxyId id) {
          if (blocks(id)) f(id, world_.shape(id), world_.transform(id));
        },
        options_.filter);
  }

  /// Step 1: the bodies near the start, within twice the skin. Each is a resting contact (its
  /// distance at most resting_limit(), with a contact normal) or adds to the least gap; the skin
  /// grows to kMoveSkinFactor times the largest cast tolerance met, and the survey is done again
  /// once with the larger reach when it does; the margin m follows. False when more resting
  /// contacts than planes.
  bool survey_start(const Vec2<T>& displacement) {
    const Vec2<T> zero = Vec2<T>::Zero();
    const Calc own = cast_tolerance(mover_, x_, displacement, mover_, x_, zero, T(1));
    skin_ = std::max(Calc(options_.skin), kMoveSkinFactor * std::max(rho_, own));
    Calc largest = own;
    for (int round = 0; round < 2; ++round) {
      out_.plane_count = resting_count_ = 0;
      exempt_.fill(false);
      gap_min_ = std::numeric_limits<Calc>::infinity();
      bool room = true;
      const Aabb<T> near = swept_box(bounds(mover_, x_), Vec2c::Zero(), 2 * skin_);
      for_each_blocking(near, [&](ProxyId id, const Shape<T>& body, const Transform<T>& xb) {
        const Calc e = cast_tolerance(mover_, x_, displacement, body, xb, zero, T(1));
        largest = std::max(largest, e);
        const Calc limit = resting_limit(e, rho_);
        const Calc g = Calc(distance(mover_, x_, body, xb));
        if (g <= limit) {
          // A resting contact needs its normal: the speculative contact reaches past the limit.
          const T reach = T(2 * limit + 8 * rounding_tolerance(mover_, x_, body, xb));
          if (const auto c = contact(mover_, x_, body, xb, reach)) {
            if (out_.plane_count == kMoveMaxPlanes) {
              room = false;
              return;
            }
            limits_[out_.plane_count] = limit;
            exempt_[out_.plane_count] = true;
            add_plane(MovePlane<T>{c->normal, c->points[0], id, true});
            ++resting_count_;
            return;
          }
        }
        gap_min_ = std::min(gap_min_, gap_lower(body, xb, g));
      });
      if (!room) return false;
      const Calc grown = kMoveSkinFactor * largest;
      if (!(grown > skin_)) break;
      skin_ = grown;
    }
    margin_ = 2 * (largest + rho_);
    return true;
  }

  /// The least gap lower bound of the blocking bodies within twice the skin of the mover (at x_)
  /// that are not resting contacts still within their limit; marks those as exempt from this
  /// leg's casts.
  Calc survey_gaps() {
    exempt_.fill(false);
    Calc least = std::numeric_limits<Calc>::infinity();
    const Aabb<T> near = swept_box(bounds(mover_, x_), Vec2c::Zero(), 2 * skin_);
    for_each_blocking(near, [&](ProxyId id, const Shape<T>& body, const Transform<T>& xb) {
      const Calc g = Calc(distance(mover_, x_, body, xb));
      const std::size_t r = resting_plane_of(id);
      if (r < kMoveMaxPlanes && g <= limits_[r]) {
        exempt_[r] = true;
        return;
      }
      least = std::min(least, gap_lower(body, xb, g));
    });
    return least;
  }

  /// Step 3: lifts off the resting contacts by up to min(s, |free|) (free: the displacement's part
  /// that goes into none of them), across d where it can, and spends the length made from d.
  /// Returns false when the move ended here (the result is written).
  bool lift(Vec2c& d, const Vec2c& free) {
    const Calc len = collide::detail::norm_of(d);
    const Vec2c up = lift_off(normals_, resting_count_, std::min(skin_, collide::detail::norm_of(free)), d);
    const Calc kappa = inflation(gap_min_);
    if (!(collide::detail::norm_of(up) > rho_) || !(kappa >= rho_ / 2)) return true;
    const Hit h = cast_leg(up, kappa);
    if (h.stopped && !add_hit(h)) {
      finish(MoveOutcome::Blocked);
      return false;
    }
    const Calc made = h.t * collide::detail::norm_of(up);
    d *= std::max(Calc(0), len - made) / len;
    return true;
  }

  /// The inflation of a leg whose nearest non-resting body lies at least g away: min(s, max(g / 2,
  /// g - m)) (see the method at the top of this file).
  Calc inflation(Calc g) const noexcept { return std::min(skin_, std::max(g / 2, g - margin_)); }

  /// One leg along v with the mover inflated by kappa (>= rho / 2): the earliest hit over the
  /// blocking bodies not exempt from it (ties: the lowest slot), then the mover advanced to it.
  Hit cast_leg(const Vec2c& v, Calc kappa) {
    const Vec2<T> vt = v.template cast<T>();
    Hit best;
    const M inflated = inflate(kappa);
    const Aabb<T> box = swept_box(bounds(inflated, x_), widen(vt), Calc(0));
    const Vec2<T> zero = Vec2<T>::Zero();
    for_each_blocking(box, [&](ProxyId id, const Shape<T>& body, const Transform<T>& xb) {
      const std::size_t r = resting_plane_of(id);
      if (r < kMoveMaxPlanes && exempt_[r]) return;
      const CastResult<T> c = shape_cast(inflated, x_, vt, body, xb, zero, T(1));
      Hit h;
      h.body = id;
      if (c.outcome == CastOutcome::Hit) {
        h.t = Calc(c.t);
        h.normal = collide::detail::unit_of(widen(c.normal));
        h.point = c.point;
      } else if (c.outcome == CastOutcome::Miss) {
        return;
      } else {
        // At the iteration limit the cast proved [0, t] free and no more; refused input cannot
        // occur for a validated move. Either way the leg stops there, as if facing a wall.
        h.t = c.outcome == CastOutcome::IterationLimit ? Calc(c.t) : Calc(0);
        h.normal = collide::detail::unit_of(v);
        h.point = (widen(x_.position()) + h.t * widen(vt)).template cast<T>();
      }
      h.stopped = true;
      if (!best.stopped || h.t < best.t || (h.t == best.t && id.index < best.body.index)) best = h;
    });
    // The stored position: the leg's end rounded to T, from's rotation kept bit for bit.
    const Vec2<T> step = (best.t * widen(vt)).template cast<T>();
    if (const Expected<Transform<T>> next = x_.moved(step)) x_ = next.value();
    append_position();
    return best;
  }

  /// The mover with its radius grown by at least kappa, rounded up to T.
  M inflate(Calc kappa) const {
    const Calc want = Calc(mover_.radius()) + kappa;
    T r = static_cast<T>(want);
    if (Calc(r) < want) r = std::nextafter(r, std::numeric_limits<T>::infinity());
    if constexpr (std::is_same_v<M, Circle<T>>) {
      return M::make(mover_.center(), r).value();
    } else {
      return M::make(mover_.a(), mover_.b(), r).value();
    }
  }

  /// Records a plane (room checked by the caller), with its unit normal in double for clipping.
  void add_plane(const MovePlane<T>& p) {
    normals_[out_.plane_count] = collide::detail::unit_of(widen(p.normal));
    out_.planes[out_.plane_count++] = p;
  }

  /// Records a leg's hit as a plane; false when the planes are full.
  bool add_hit(const Hit& h) {
    if (out_.plane_count == kMoveMaxPlanes) return false;
    limits_[out_.plane_count] = 0;
    add_plane(MovePlane<T>{h.normal.template cast<T>(), h.point, h.body, false});
    normals_[out_.plane_count - 1] = h.normal;
    return true;
  }

  /// d projected onto the directions that go into no plane met so far: every hit's, and the
  /// resting contacts' still exempt from the casts.
  Vec2c clip(const Vec2c& d) const noexcept {
    std::array<bool, kMoveMaxPlanes> active{};
    for (std::size_t i = 0; i < out_.plane_count; ++i) active[i] = !out_.planes[i].resting || exempt_[i];
    return clip_to_planes(d, normals_, active, out_.plane_count);
  }

  /// Appends the current position to the path.
  void append_position() noexcept {
    if (out_.path_count < kMovePathCapacity) out_.path[out_.path_count++] = x_.position();
  }

  /// Writes the end of the move.
  void finish(MoveOutcome outcome) {
    out_.outcome = outcome;
    out_.transform = x_;
    out_.displacement = x_.position() - out_.path[0];
  }

  const World<T, BP>& world_;
  const M& mover_;
  const MoveOptions<T>& options_;
  Transform<T> x_;  ///< the mover's placement now
  Calc rho_;
  MoveResult<T>& out_;
  Calc skin_ = 0;
  Calc margin_ = 0;                ///< m: twice the largest cast tolerance near the start plus rho
  Calc gap_min_ = 0;               ///< at the start: the least gap lower bound of the non-resting bodies near
  std::size_t resting_count_ = 0;  ///< planes[0, resting_count_) are the resting contacts
  std::array<Vec2c, kMoveMaxPlanes> normals_{};  ///< the planes' unit normals, in double
  std::array<Calc, kMoveMaxPlanes> limits_{};    ///< a resting plane's resting_limit() (0 for hits)
  std::array<bool, kMoveMaxPlanes> exempt_{};    ///< a resting plane's body is not cast this leg
};

}  // namespace detail

/// The kinds a mover may have: a circle or a capsule (grown by a distance, still one).
template <class M>
concept MoverShape = std::is_same_v<M, Circle<scalar_of_t<M>>> || std::is_same_v<M, Capsule<scalar_of_t<M>>>;

/// Moves `mover` (a Circle or a Capsule in its local frame, placed by `from`) by `displacement`
/// among the bodies of `world`, stopping in front of what it meets and sliding along it. See the
/// contract at the top of mover.hpp: nothing it was clear of at the start is overlapped or
/// crossed, and the path is never longer than the displacement (up to rho per leg).
template <MoverShape M, class BP>
MoveResult<scalar_of_t<M>> move_and_slide(const World<scalar_of_t<M>, BP>& world, const M& mover,
                                          const Transform<scalar_of_t<M>>& from,
                                          const Vec2<scalar_of_t<M>>& displacement,
                                          const MoveOptions<scalar_of_t<M>>& options = {}) {
  using T = scalar_of_t<M>;
  MoveResult<T> out;
  out.transform = from;
  out.path[0] = from.position();
  out.path_count = 1;
  // 1. The input.
  if (!detail::move_input_valid(mover.radius(), from, displacement, options)) {
    out.outcome = MoveOutcome::InvalidInput;
    return out;
  }
  // 2. The move.
  detail::SlideMove<T, BP, M>(world, mover, from, options, move_rounding(mover, from, displacement), out)
      .run(displacement);
  return out;
}

/// move_and_slide() of a mover given as a Shape<T>: a circle or a capsule moves; any other kind is
/// refused (UnsupportedMover) and stays where it was.
template <Scalar T, class BP>
MoveResult<T> move_and_slide(const World<T, BP>& world, const Shape<T>& mover, const Transform<T>& from,
                             const Vec2<T>& displacement, const MoveOptions<T>& options = {}) {
  if (const auto* circle = std::get_if<Circle<T>>(&mover))
    return move_and_slide(world, *circle, from, displacement, options);
  if (const auto* capsule = std::get_if<Capsule<T>>(&mover))
    return move_and_slide(world, *capsule, from, displacement, options);
  MoveResult<T> out;
  out.outcome = MoveOutcome::UnsupportedMover;
  out.transform = from;
  out.path[0] = from.position();
  out.path_count = 1;
  return out;
}

}  // namespace collide::broadphase
