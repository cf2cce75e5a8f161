#pragma once
/// @file config.hpp
/// Scalar types, the vector type, and the numeric limits every shape and query obeys.

#include <Eigen/Core>

#include <cmath>
#include <concepts>
#include <limits>

namespace collide {

/// The two supported scalars: float (what games use) and double (large worlds).
template <class T>
concept Scalar = std::same_as<T, float> || std::same_as<T, double>;

/// A 2D vector of scalar T (Eigen fixed-size column vector).
template <Scalar T>
using Vec2 = Eigen::Matrix<T, 2, 1>;

/// Queries compute in double whatever the stored scalar: float inputs convert exactly, and the
/// product of two floats is exact in double, so float shapes lose nothing before the first sum.
using Calc = double;
/// A vector in the computation's precision.
using Vec2c = Eigen::Matrix<Calc, 2, 1>;

/// Largest magnitude a stored value may have; larger values are rejected with Error::OutOfRange.
/// float: 2^125 (about 4.25e37), so that a bounding box (center + extents) still fits in a float.
/// double: 2^500 (about 3.3e150), so that squares of values and of their differences cannot
/// overflow the computation type.
template <Scalar T>
constexpr T max_magnitude() noexcept {
  if constexpr (std::same_as<T, float>) {
    return 0x1p+125f;
  } else {
    return 0x1p+500;
  }
}

/// Double's unit roundoff: the largest relative error of one rounded operation.
inline constexpr Calc kUnitRoundoff = 0x1p-53;

/// Magnitudes above this are far from underflow: their squares and products of two stay normal
/// doubles, so filters and normalisations may trust their relative error bounds.
inline constexpr Calc kUnderflowMargin = 0x1p-1000;

/// Magnitudes below this are far from overflow (their squares stay finite).
inline constexpr Calc kOverflowMargin = 0x1p1000;

/// Vectors whose largest component lies in [kPlainNormLow, kPlainNormHigh] have a norm computed
/// without scaling (their squared components are normal doubles); others are first scaled by an
/// exact power of two, so that a direction between points 1e-159 apart keeps its 53 bits.
inline constexpr Calc kPlainNormLow = 0x1p-500;
/// See kPlainNormLow.
inline constexpr Calc kPlainNormHigh = 0x1p500;

/// Floating-point filters (decide.hpp, predicates.hpp) give no answer when the magnitude of their
/// terms is below this: products of such terms may have underflowed, which relative bounds miss;
/// the exact fallback decides instead.
inline constexpr Calc kFilterFloor = 0x1p-900;

/// orient()'s expansion arithmetic (predicates.hpp) needs every non-zero coordinate within this
/// factor of the largest (its products, after scaling, stay normal doubles); wider spreads are
/// evaluated in exact binary arithmetic instead.
inline constexpr Calc kExpansionSpread = 0x1p-995;

/// Absolute error of one rounded product whose result underflows: 32 units of the smallest
/// subnormal, a wide margin over the half unit a subnormal product can lose.
inline constexpr Calc kProductUnderflow = 0x1p-1069;

/// Relative slack on a computed error bound before it proves a sign: covers the rounding of the
/// bound's own sums (a few units of 2^-53) with a wide margin.
inline constexpr Calc kBoundSlack = 0x1p-40;

/// An OBB whose smaller half extent is below this times its magnitude (centre plus larger half
/// extent), or below kUnderflowMargin, may have corners that round onto each other: its rounded
/// corners are checked for convexity before they are trusted as a box.
inline constexpr Calc kThinBoxRatio = 0x1p-40;

/// Cores (and polygons being validated) whose every value is below this magnitude are scaled up
/// by an exact power of two before any rounded computation: squares of coordinates below about
/// 2^-537 underflow, which would leave decisions, depths and distances only absolute-accurate.
inline constexpr Calc kTinyCore = 0x1p-400;

/// The smallest positive double (a subnormal): the absolute error of one rounded operation whose
/// result underflows, which relative bounds (kUnitRoundoff) miss.
inline constexpr Calc kSmallestDouble = 0x1p-1074;

/// Broadphase ray queries: relative pad of the box around a ray segment, which bounds the
/// rounding of its end point origin + direction * max_t (a few units of 2^-53) with a wide
/// margin, so the box never misses a proxy the segment reaches; a looser box only adds candidates.
inline constexpr Calc kRayBoxPad = 0x1p-40;

/// Broadphase ray queries: absolute pad of that box, for segments at or near the origin.
inline constexpr Calc kRayBoxPadFloor = 0x1p-1000;

/// Sweep-and-prune queries: relative slack on the widest entry when choosing where a scan starts
/// (start = lo.x - widest * (1 + slack), then one ulp lower), which covers the rounding of that
/// subtraction with a wide margin; a lower start only scans more entries.
inline constexpr Calc kSweepWidthSlack = 0x1p-40;

/// Contact generation: two faces whose normalised alignment with the reference normal differs by
/// less than this are equally anti-parallel (a polygon side split by a vertex one ulp off its line).
inline constexpr Calc kFaceTieTolerance = 0x1p-40;

/// Contact generation: an incident face more than this many times as long as the reference face
/// is not clipped against it (its clipped ends would move by more than the reference face is
/// long); the witness point is used instead.
inline constexpr Calc kClipLengthRatioRoot = 0x1p20;
/// kClipLengthRatioRoot squared, compared with the faces' squared lengths.
inline constexpr Calc kClipLengthRatio = kClipLengthRatioRoot * kClipLengthRatioRoot;

/// Contact generation: a face replaces an earlier one as the face of least penetration only when
/// shallower by more than this many units of roundoff of the pair's scale (a quarter of
/// kOverlapErrorFactor), so that faces equally deep up to rounding keep their order and their
/// feature ids while the pair moves.
inline constexpr Calc kFaceOrderTie = 16.0;

/// Contact generation: the cosine within which a face of the second shape counts as parallel to
/// (facing) the first shape's face of least penetration (about 3.6 degrees), so that the images'
/// rounding widens the tie between them (detail::least_penetration_by()): parallel faces equally
/// deep in the exact shapes keep the first shape's face as the reference.
inline constexpr Calc kParallelFaceCosine = 0.998;

/// Absolute floor of the error bounds of rounded outputs (about 3.1e-151; decisions are exact
/// and need none). A bound, not the typical error: shapes whose every value is below 2^-400 are
/// rescaled exactly by a power of two before any rounded computation (see detail::tiny_scale), so
/// their depths and distances are relative-accurate; the floor covers pairs mixing tiny and
/// ordinary magnitudes, whose squares can still underflow.
inline constexpr Calc kAbsoluteFloor = 0x1p-500;

/// Relative factor of the error unit of rounded outputs (depths, normals, distances), in units
/// of double's unit roundoff (2^-53). See rounding_tolerance() in tolerances.hpp; overlap decisions
/// are exact and have no tolerance.
inline constexpr Calc kOverlapErrorFactor = 64.0;

/// Roundings of float's unit roundoff (2^-24), per unit of the pair's size, that a test computed
/// in float keeps between its answer and the boundary (detail::circle_beyond_box_in_float: 9
/// needed).
inline constexpr float kFloatFilterRoundings = 16.0f;

/// Shape casts and time of impact (cast.hpp, time_of_impact.hpp): conservative advancement stops
/// when the computed gap is within twice its target separation, target = this factor * 2^-53 * M
/// + kAbsoluteFloor, M being the motion's scale (the largest coordinate the moving shapes reach).
/// The factor leaves a wide margin over the rounding of the moved cores (a few units of 2^-53 M),
/// so every step stays provably short of contact.
inline constexpr Calc kCastTargetFactor = 256.0;

/// Shape casts and time of impact: relative inflation of a computed bound on how fast the shapes
/// can approach (a speed, a reach), covering the bound's own rounding (a few units of 2^-53) with
/// a margin, so that a step computed from it never passes the first contact.
inline constexpr Calc kMotionBoundSlack = 0x1p-48;

/// Shape casts and time of impact: advancement steps per pair of primitives before giving up; the
/// result is then CastOutcome::IterationLimit with the last time proven free of contact.
inline constexpr int kCastMaxIterations = 64;

/// Mass properties (mass.hpp): a fan triangle whose doubled area is below this times the sum of its
/// edge products is summed exactly, since the terms the fast sum drops (2^-106 of those products)
/// could then pass 2^-66 of its area; above it the fast sum keeps the area within 3 roundings.
inline constexpr Calc kThinTriangle = 0x1p-40;

}  // namespace collide
