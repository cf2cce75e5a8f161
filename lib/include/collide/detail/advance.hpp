#pragma once
/// @file detail/advance.hpp
/// Pieces shared by shape casts (cast.hpp) and time of impact (time_of_impact.hpp): the result
/// types, the answer of one pair of cores, how pairs of children combine, and how a time is
/// rounded to the stored scalar without moving it later.

#include "collide/config.hpp"
#include "collide/detail/contact_cores.hpp"
#include "collide/detail/contact_pairs.hpp"
#include "collide/detail/convex_core.hpp"
#include "collide/shape_traits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace collide {

/// How a cast or a time-of-impact query ended.
enum class CastOutcome : std::uint8_t {
  Hit,             ///< the shapes meet (within the query's tolerance) at t
  Miss,            ///< they stay apart over the whole interval; t = max_t
  IterationLimit,  ///< undecided after kCastMaxIterations steps: apart on [0, t], nothing known after
  InvalidInput,    ///< a NaN or infinite value, max_t < 0, or a motion beyond the representable range
};

/// The answer of shape_cast() or time_of_impact().
template <Scalar T>
struct CastResult {
  CastOutcome outcome = CastOutcome::Miss;  ///< see CastOutcome
  T t = 0;                                  ///< time of the hit; max_t on a miss; the last safe time at the limit
  Vec2<T> point = Vec2<T>::Zero();          ///< on a hit: midway between the two surfaces at t
  Vec2<T> normal = Vec2<T>::Zero();         ///< on a hit: unit, from a toward b at t
  int iterations = 0;                       ///< advancement steps taken (the largest over child pairs)
  /// True for CastOutcome::Hit.
  bool hit() const noexcept { return outcome == CastOutcome::Hit; }
};

namespace detail {

/// The answer for one pair of primitives, in the computation's precision.
struct CoreCast {
  CastOutcome outcome = CastOutcome::Miss;
  Calc s = 0;                    ///< time (hit or last safe time)
  Vec2c normal = Vec2c::Zero();  ///< from the first core toward the second
  Vec2c point = Vec2c::Zero();   ///< midway between the surfaces
  int iterations = 0;
};

/// The target separation of an advancement whose moving shapes reach coordinates up to m.
inline Calc advance_target(Calc m) noexcept {
  return kCastTargetFactor * kUnitRoundoff * m + kAbsoluteFloor;
}

/// Separation of the dilated cores along unit n (from p toward q): at most their gap.
inline Calc separation_along(const Core& p, const Core& q, const Vec2c& n) noexcept {
  return -support(q, -n) - support(p, n) - p.radius - q.radius;
}

/// The unit outward face normals of a core (for_each_face), computed once and kept while the core
/// only moves or turns; a core with more than 8 faces is not kept (complete = false).
struct KeptFaces {
  std::array<Vec2c, 8> normal;
  std::array<unsigned, 8> index;  ///< the face's index as for_each_face() gives it
  std::size_t count = 0;
  bool complete = true;
};

inline KeptFaces kept_faces(const Core& c) {
  KeptFaces k;
  for_each_face(c, [&](const Vec2c& n, unsigned i) {
    if (k.count < k.normal.size()) {
      k.index[k.count] = i;
      k.normal[k.count++] = n;
    } else {
      k.complete = false;
    }
  });
  return k;
}

/// A primitive's core and its faces' unit normals, kept for the whole query. A box's normals come
/// from its stored axis and a polygon's are the ones it cached (hull_of()): one square root for a
/// box where its corners would take four. Any unit normal bounds a step, and where the corners'
/// rounding tilts a face off its axis, face_witness() measures the gap from the face itself.
struct Part {
  Core core;
  KeptFaces faces;
};

template <class S>
Part part_of(const S& s) {
  Part out;
  if constexpr (requires(Hull & h) { hull_of(s, h); }) {
    Hull h;
    if (hull_of(s, h) && h.normals() && h.core.size() <= out.faces.normal.size()) {
      const Vec2c* normals = h.normals();
      out.core = std::move(h.core);
      out.faces.count = out.core.size();
      for (std::size_t i = 0; i < out.faces.count; ++i) {
        out.faces.normal[i] = normals[i];
        out.faces.index[i] = static_cast<unsigned>(i);
      }
      return out;
    }
  }
  out.core = core_of(s);
  out.faces = kept_faces(out.core);
  return out;
}

/// Calls f(n, i) with each face normal of c and its index: the kept ones, or recomputed when they were not all
/// kept.
template <class F>
void for_each_kept_face(const KeptFaces& k, const Core& c, F&& f) {
  if (!k.complete) return for_each_face(c, f);
  for (std::size_t i = 0; i < k.count; ++i) f(k.normal[i], k.index[i]);
}

/// The direction that separates the cores best among the closest points' unit direction d (zero
/// when they coincide) and the axes each_axis(f) lists (every face normal, from p toward q). At a
/// small gap the closest points are only a few roundings apart and their direction is off by up to
/// about rounding / gap; a face normal is exact to rounding, and for a face nearest a vertex it
/// separates as well as the gap itself. (Along a direction off by 2e-4 rad, a sliver 128 long can
/// show a negative separation at a gap of 5e-7.)
template <class Axes>
Vec2c best_axis(const Core& p, const Core& q, const Vec2c& d, Axes&& each_axis) {
  Vec2c best = d == Vec2c::Zero() ? Vec2c(1, 0) : d;
  Calc best_sep = separation_along(p, q, best);
  each_axis([&](const Vec2c& n) {
    const Calc sep = separation_along(p, q, n);
    if (sep > best_sep) best_sep = sep, best = n;
  });
  return best;
}

/// Hit at time s for cores p, q (already moved there) that are apart, with the point midway
/// between the closest points of the two surfaces. Its normal is *face_normal where the closest
/// points meet that face (face_witness()), else best_axis() over each_axis.
template <class Axes>
CoreCast hit_between(const Core& p, const Core& q, const Closest& cl, Calc s, int iterations, const Vec2c* face_normal,
                     Axes&& each_axis) {
  CoreCast out;
  out.outcome = CastOutcome::Hit;
  out.s = s;
  out.iterations = iterations;
  const Vec2c d = unit_of(cl.on_q - cl.on_p);
  out.normal = face_normal ? *face_normal : best_axis(p, q, d, each_axis);
  // The surface points lie along the closest points' own direction (accurate whenever the radii
  // are not small next to the rounding; with small radii it hardly matters).
  const Vec2c along = d == Vec2c::Zero() ? out.normal : d;
  out.point = ((cl.on_p + along * p.radius) + (cl.on_q - along * q.radius)) * 0.5;
  return out;
}

/// Hit at s for cores that overlap there: the normal and first point of their contact.
inline CoreCast hit_overlapping(const Core& p, const Core& q, Calc s, int iterations) {
  const CoreContact c = contact_cores(p, q);
  CoreCast out;
  out.outcome = CastOutcome::Hit;
  out.s = s;
  out.iterations = iterations;
  out.normal = c.normal;
  out.point = c.points[0];
  return out;
}

/// The answer with its normal reversed (the same pair asked in the other order).
inline CoreCast reversed(CoreCast c) noexcept {
  c.normal = -c.normal;
  return c;
}

/// A strict order on cores (point count, then coordinates, then radius), so that a pair is always
/// advanced in one order whichever order it was asked in: the two orders give the same bits.
inline bool core_before(const Core& p, const Core& q) noexcept {
  if (p.size() != q.size()) return p.size() < q.size();
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < 2; ++k) {
      if (p[i][k] != q[i][k]) return p[i][k] < q[i][k];
    }
  }
  return p.radius < q.radius;
}

/// Whether the pair of cores {p, q} comes before {p2, q2} in an order that does not depend on
/// which core of a pair is first: each pair's cores sorted by core_before(), then compared.
inline bool pair_before(const Core& p, const Core& q, const Core& p2, const Core& q2) noexcept {
  const bool swap = core_before(q, p), swap2 = core_before(q2, p2);
  const Core &lo = swap ? q : p, &hi = swap ? p : q, &lo2 = swap2 ? q2 : p2, &hi2 = swap2 ? p2 : q2;
  if (core_before(lo, lo2)) return true;
  if (core_before(lo2, lo)) return false;
  return core_before(hi, hi2);
}

/// Calls f(p, q, until) with the parts (part_of()) of every pair of primitives of a and b (a
/// compound's children), until the earliest answer so far, and keeps the earliest: of hits and limits the earlier wins
/// (a limit earlier than every hit makes the whole answer a limit there); two misses stay a miss. Pairs answering at
/// the same time are ranked by pair_before(), so that the shapes asked in the other order keep the same pair (and so
/// the reversed normal).
template <class A, class B, class F>
CoreCast earliest_over_pairs(const A& a, const B& b, Calc s_max, F&& f) {
  CoreCast best{CastOutcome::Miss, s_max, Vec2c::Zero(), Vec2c::Zero(), 0};
  Core best_p, best_q;
  visit_shape(a, [&](const auto& ca) {
    visit_shape(b, [&](const auto& cb) {
      // Only a compound has later pairs to rank against the best.
      constexpr bool ranked = is_compound_v<decltype(ca)> || is_compound_v<decltype(cb)>;
      for_each_primitive(ca, [&](const auto& pa) {
        for_each_primitive(cb, [&](const auto& pb) {
          // A later pair only has to be followed up to the earliest answer so far, that time included:
          // an advancement stops with a miss only past its bound, so a pair tied with the best is ranked.
          const Calc until = best.outcome == CastOutcome::Miss ? s_max : best.s;
          const Part p = part_of(pa), q = part_of(pb);
          const CoreCast c = f(p, q, until);
          const int iterations = std::max(best.iterations, c.iterations);
          const bool open = best.outcome != CastOutcome::Miss;
          if (c.outcome != CastOutcome::Miss &&
              (!open || c.s < best.s || (c.s == best.s && pair_before(p.core, q.core, best_p, best_q)))) {
            best = c;
            if constexpr (ranked) best_p = p.core, best_q = q.core;
          }
          best.iterations = iterations;
        });
      });
    });
  });
  return best;
}

/// s in T, rounded toward zero: a time proven safe stays safe.
template <Scalar T>
T time_toward_zero(Calc s) noexcept {
  T t = static_cast<T>(s);
  if (static_cast<Calc>(t) > s) t = std::nextafter(t, T(0));
  return t;
}

/// The answer rounded to T. A hit's point and normal are rounded to nearest; its time toward zero.
template <Scalar T>
CastResult<T> to_result(const CoreCast& c, Calc max_t) {
  CastResult<T> out;
  out.outcome = c.outcome;
  out.iterations = c.iterations;
  out.t = time_toward_zero<T>(c.outcome == CastOutcome::Miss ? max_t : c.s);
  if (c.outcome == CastOutcome::Hit) {
    out.point = c.point.template cast<T>();
    out.normal = c.normal.template cast<T>();
  }
  return out;
}

/// The named error answer.
template <Scalar T>
CastResult<T> invalid_cast() noexcept {
  CastResult<T> out;
  out.outcome = CastOutcome::InvalidInput;
  return out;
}

}  // namespace detail
}  // namespace collide
