#pragma once
/// @file laws.hpp
/// The laws every answer of the library must obey, as plain functions. Each law asks the library,
/// asks the exact oracle, and returns a Verdict; none throws on a broken law. The property suite,
/// the fuzz targets and the regression replay all call these same functions, so a counterexample
/// found by one is judged the same way by the others.
///
/// Every law takes shapes as Shape<T>, T = float or double (explicitly instantiated in
/// collide_laws). Decisions are exact for every pair (overlap_tolerance(a, b) is 0): the laws on
/// overlaps() demand equality. "Tolerance" below is rounding_tolerance(a, b) from tolerances.hpp (the
/// error unit of rounded outputs) for depths, points and distances.

#include "collide/collide.hpp"

#include <array>
#include <cstdint>
#include <iterator>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace collide::laws {

/// The exact relation of two shapes, from the oracle.
enum class Relation {
  Separated,    ///< no common point
  Touching,     ///< common points, but exact signed distance 0 (boundaries only)
  Overlapping,  ///< interiors meet and neither contains the other
  Contained,    ///< one shape lies inside the other (the container a primitive or a compound child)
};

/// "separated", "touching", "overlapping", "contained".
std::string_view name(Relation r) noexcept;

/// The result of checking one law on one input.
struct Verdict {
  bool ok = true;             ///< the law holds
  bool disagreement = false;  ///< the library disagreed with the oracle where the contract allows it
  Relation relation{};        ///< exact relation of the law's main pair (for the case distribution)
  std::string account;        ///< what was checked and, when !ok or disagreement, the values
  std::string expected;       ///< when !ok or disagreement: what the law required (oracle side), one line
  std::string got;            ///< when !ok or disagreement: what the library answered, one line
};

/// Exact relation of a and b (several oracle calls). For a compound container, Contained means
/// inside one child. OBB corners enter the containment test rounded to double; the Separated /
/// Touching / Overlapping split is exact.
template <Scalar T>
Relation relation(const Shape<T>& a, const Shape<T>& b);

/// Law agreement. overlaps(a, b) equals oracle::overlaps(a, b), for every pair and both scalars. A
/// compound whose children carry transforms may differ only within its placement's band, and then
/// its answer must be the oracle's on the children's images the library computed, bit for bit.
template <Scalar T>
Verdict agreement(const Shape<T>& a, const Shape<T>& b);

/// Law symmetry. overlaps(a, b) == overlaps(b, a) bit for bit; contact(a, b) and contact(b, a) both exist
/// or neither does, with opposite normals and equal depths; distance(a, b) == distance(b, a).
/// Normals and depths are compared within the tolerance (the two orders round differently); when
/// the normals are not opposite (a tie between faces) the depths must still be equal and, for two
/// primitives, the other order's normal must separate the pair by that depth (oracle::separates).
template <Scalar T>
Verdict symmetry(const Shape<T>& a, const Shape<T>& b);

/// Law translation. Moving both shapes by t (with translated()): when both moves are exact (every stored
/// value moved by exactly t), overlaps() gives the identical answer. Otherwise each case is judged
/// exactly: the moved shapes are what translated() promises (each stored position plus t rounded
/// once to T, bit for bit), both answers are the oracle's on the shapes the library computed (for
/// children placed by transforms, their images), the moved pair agrees with the oracle outside the
/// placement's band, and the answer changes only where the unmoved pair is within 4 eps_T S of
/// touching (the rounding of the move). A move that leaves the representable range is rejected by
/// translated() with a named error and is not a failure.
template <Scalar T>
Verdict translation(const Shape<T>& a, const Shape<T>& b, const Vec2<T>& t);

/// Law rotation. Rotating both shapes about the origin by quarter_turns * 90 degrees, then mirroring
/// x -> -x when mirror is set (both exact on the stored values), gives identical answers of
/// overlaps(). An OBB is first rebuilt through make_with_axis from its own axis, so that the
/// rotated box is exactly the rotated point set.
template <Scalar T>
Verdict rotation(const Shape<T>& a, const Shape<T>& b, int quarter_turns, bool mirror);

/// Law resolution. v = resolve(a, b): zero when overlaps(a, b) is false (an exact overlap then allowed only
/// within the band); otherwise the shape a' that translated(a, v) produces does not overlap b
/// (oracle), and, for two primitives, |v| <= exact depth + resolve_margin + slack, where slack =
/// 4 tolerances (the computed depth's own error, as in contact_law) plus v's rounding to T
/// (oracle::compare_depth), and the gap left by the moved a' at most 2 (resolve_margin + slack);
/// resolve_margin(a, b, |v|, v / |v|) as documented, along the push's own direction.
/// Compounds: separation only (the oracle has no exact depth for them).
template <Scalar T>
Verdict resolution(const Shape<T>& a, const Shape<T>& b);

/// Law bounds. bounds(s) contains s exactly (oracle::inside_box).
template <Scalar T>
Verdict bounds_law(const Shape<T>& s);

/// Law raycast. raycast(s, ray, max_t), judged by raycast.hpp's contract with its bound
/// delta = raycast_tolerance(s, ray): a hit has 0 <= t <= max_t, its point is within delta of the
/// shape and of origin + t * direction; an origin inside the shape (deeper than delta) hits at
/// t = 0; before the hit (or up to max_t when there is none) the ray passes no point deeper than
/// delta inside the shape (a compound: inside a child, deeper than delta in it), checked by
/// oracle::passes_deeper.
/// The hit normal: a unit vector; at t = 0, -direction / |direction|; otherwise an outward normal
/// of the boundary at the point: q = point + L * normal (L the shape's size, at least 2^20 bounds)
/// lies outside the shape (for compounds, outside some child near the point) at distance at least
/// L - 2 bounds - 4 eps_T L, which holds for every normal in the boundary's normal cone there.
template <Scalar T>
Verdict raycast_law(const Shape<T>& s, const Ray<T>& ray, T max_t);

/// Law raycast_exit. e = raycast_exit(s, ray, max_t), judged by raycast.hpp's contract with its
/// bound delta = raycast_exit_tolerance(s, ray): e exists exactly when contains(s, origin) (the
/// library's exact decision, itself judged by law contains); 0 <= t <= max_t; its point is within
/// delta (plus t's rounding) of origin + t * direction; normal (0, 0) only with t = max_t. Before
/// the exit the ray stays in the shape within delta, exactly: the point is not farther than delta
/// from the shape (for a primitive, convex, this holds the whole segment from the origin), and for
/// a compound no point just past where the ray leaves a child (3 delta on, found by casting each
/// child backward from the exit) before the exit is farther than delta from the union. At a
/// boundary exit the point is not deeper than delta inside any child (the exit is not early), and
/// where the ray was deeper than delta inside 4 delta before it, the normal is a unit outward
/// normal there (as law raycast judges it). Every judgement is the oracle's.
template <Scalar T>
Verdict raycast_exit_law(const Shape<T>& s, const Ray<T>& ray, T max_t);

/// Law hierarchy. overlaps(compound, x) == any child overlaps x (library against library, identical), and
/// the bounding-box early-out never changes an answer: when the compound's cached box misses x's
/// box, no child overlaps x, by the library and by the oracle. compound must hold a Compound.
template <Scalar T>
Verdict hierarchy(const Shape<T>& compound, const Shape<T>& x);

/// Law representation. The same point set in another representation gives the identical overlaps() answer
/// against x: an AABB as a 4-vertex ConvexPolygon and as an unrotated OBB; a circle as a
/// zero-length capsule; a zero-length capsule as a circle; an OBB with axis (1, 0) as an AABB.
/// A representation that cannot be built exactly (e.g. a degenerate box as a polygon) is skipped
/// and named in the account. Any difference fails (decisions are exact).
template <Scalar T>
Verdict representation(const Shape<T>& a, const Shape<T>& x);

/// Law contact. contact(a, b) exists exactly when overlaps(a, b); its normal is a unit vector, its
/// depth >= 0 and, for primitives, within 4 tolerances of the exact depth (plus T's rounding);
/// each contact point lies within depth + 4 tolerances of both shapes. Direction: moving a by
/// -normal * (depth + 2 bounds) separates it from b (oracle::separates; for compounds, some
/// overlapping child pair). Midway, for two primitives with interiors that overlap without
/// containment: each point lies within 3/4 depth + 2 bounds of both boundaries (the middle half
/// between the surfaces), so a point on one shape's face of a deep contact fails.
/// bound = 4 rounding tolerances + T's rounding of depth and points.
template <Scalar T>
Verdict contact_law(const Shape<T>& a, const Shape<T>& b);

/// Law distance. distance(a, b) is 0 exactly when overlaps(a, b), and otherwise within 4 tolerances
/// (plus T's rounding) of the exact gap (oracle::compare_distance): a distance of 0 for shapes
/// 3 apart fails, as does any value off the exact gap by more than the bound.
template <Scalar T>
Verdict distance_law(const Shape<T>& a, const Shape<T>& b);

/// Law contains. contains(s, p) equals oracle::contains(s, p). Exact for AABBs and polygons (and
/// compounds of them); for circles, capsules and OBBs a difference is allowed only when p lies
/// within contains_tolerance(s, p) of the boundary (of the child that differs), and is then a
/// disagreement. NaN or infinite points: false.
template <Scalar T>
Verdict contains_law(const Shape<T>& s, const Vec2<T>& p);

/// Law contains_shape. contains(outer, inner) for both orders of the pair: for a primitive outer,
/// exactly oracle::contains(outer, inner) (an inner compound with child transforms: the oracle on
/// the images the library computed, a difference from the exact answer being a disagreement), the
/// same answer for the concrete outer as for the variant; for a compound outer,
/// Error::CompoundOuter. Any other difference fails (decisions are exact).
template <Scalar T>
Verdict contains_shape_law(const Shape<T>& a, const Shape<T>& b);

/// Law signed_distance. d = signed_distance(s, p): d <= 0 exactly when contains(s, p) (to the bit),
/// and so when the oracle's containment holds (a compound with child transforms: a difference only
/// within placement_tolerance(s) of a child's boundary, where the oracle on the library's images
/// agrees); d within signed_distance_tolerance(s, p)'s documented formula of the exact signed
/// distance (for a compound
/// the least of its children's, each judged by oracle::compare_boundary_distance), +infinity only
/// where that exceeds the largest finite T less the bound. NaN for a NaN point, +infinity for an
/// infinite one.
template <Scalar T>
Verdict signed_distance_law(const Shape<T>& s, const Vec2<T>& p);

/// Law closest_points. c = closest_points(a, b), in both argument orders: c.distance is distance()'s
/// answer bit for bit; each point lies within closest_points_tolerance(a, b)'s documented formula
/// (4 rounding_tolerance(a, b) + 2 eps_T S + 2 denorm_min_T) of its shape (oracle);
/// for a distance of 0 the two points are one, otherwise |point_b - point_a| is the distance within
/// that bound (so the points realise the gap: a point deeper than the bound inside its shape would
/// lie farther from the other shape).
template <Scalar T>
Verdict closest_points_law(const Shape<T>& a, const Shape<T>& b);

/// Law touching. Touching judged exactly: when the oracle says a and b touch (signed distance exactly
/// 0), overlaps(a, b) and overlaps(b, a) are true, for every pair (no band); when the oracle says
/// they are apart or overlapping by more than overlap_tolerance(a, b), both answers equal the
/// oracle's; within the band (signed distance not 0) a difference is a disagreement.
template <Scalar T>
Verdict touching(const Shape<T>& a, const Shape<T>& b);

/// Law scene. A scene (the children of the compound `group`, each taken as a shape):
/// broadphase::find_overlapping_shapes() lists exactly the pairs overlaps() reports one pair at a
/// time, find_contacts() gives one contact per such pair with contact()'s bits, and
/// pairs_involving() on a DynamicTree of their bounds gives each pair of meeting boxes with a proxy
/// in the first half exactly once. Narrowphase::for_each_contact, on the shapes and up to three
/// compounds of neighbouring shapes (every ordered pair under identities; then every pair once
/// under one turned transform with a speculative distance, on the same object), reports exactly
/// the pairs contact() finds, each once with contact()'s bits, kind pair by kind pair in the
/// registry's order and by index within one; refuses a call from its own callback (Reentered)
/// while another Narrowphase may be called there; and refuses a pair naming a shape beyond the
/// list, in either place, or one transform fewer than shapes (BadPair), before any contact.
template <Scalar T>
Verdict scene(const Shape<T>& group);

/// Law rejection. Building a shape of `kind` from raw values (any bit patterns) through its make():
/// NaN or infinity gives Error::NonFinite, a magnitude above max_magnitude<T>() Error::OutOfRange
/// (first offending value in argument order), then the kind's own named errors (negative radius
/// or extent, min > max, zero axis; polygons: TooFewVertices, Collinear or NonConvex), and
/// valid values give a shape. Never throws, crashes or hangs. Value layout per kind is that of
/// its codec (codec.hpp: the factory, the field order and the kind's rules); a compound is built
/// from one circle child per three values.
template <Scalar T>
Verdict rejection(ShapeKind kind, std::span<const T> values);

/// What a law takes, and so how its tests are registered: per unordered pair of kinds, per kind,
/// raw values per kind, one group of shapes, raw values of a transform (once), or a chain segment
/// and a shape (once).
enum class LawInputs : std::uint8_t { Pair, Shape, Values, Scene, TransformValues, Chain };

/// Which property suite runs a law: world-space shapes (properties/laws_test.cpp), shapes placed
/// by transforms (properties/transform_test.cpp), moving shapes (properties/cast_test.cpp), or
/// chain segments (properties/chain/chain_properties.cpp).
enum class LawSuite : std::uint8_t { Static, Placed, Moving, Chain };

/// Every law, in the order of law_table.inc.
enum class Law : std::uint8_t {
#define COLLIDE_LAW(id, law_name, inputs, suite, description) id,
#include "collide/laws/law_table.inc"
#undef COLLIDE_LAW
};

/// One row of the law table.
struct LawInfo {
  Law law;                       ///< the law
  std::string_view name;         ///< as in case files, test names, ctest names, reports
  LawInputs inputs;              ///< what it takes
  LawSuite suite;                ///< which property suite runs it
  std::string_view description;  ///< one line
};

/// The law table (law_table.inc), in Law order.
inline constexpr LawInfo kLaws[] = {
#define COLLIDE_LAW(id, law_name, inputs, suite, description) \
  {Law::id, #law_name, LawInputs::inputs, LawSuite::suite, description},
#include "collide/laws/law_table.inc"
#undef COLLIDE_LAW
};

/// Number of laws.
inline constexpr std::size_t kLawCount = std::size(kLaws);

/// The table row of a law.
constexpr const LawInfo& info(Law l) noexcept {
  return kLaws[static_cast<std::size_t>(l)];
}
/// The name of a law, e.g. "agreement".
constexpr std::string_view name(Law l) noexcept {
  return info(l).name;
}
/// The law named `s`, or nullopt.
constexpr std::optional<Law> law_from_name(std::string_view s) noexcept {
  for (const LawInfo& row : kLaws) {
    if (row.name == s) return row.law;
  }
  return std::nullopt;
}
/// "pair", "shape", "values", "scene", "transform_values", "chain".
constexpr std::string_view name(LawInputs i) noexcept {
  constexpr std::string_view names[] = {"pair", "shape", "values", "scene", "transform_values", "chain"};
  return names[static_cast<std::size_t>(i)];
}
/// "static", "placed", "moving", "chain".
constexpr std::string_view name(LawSuite s) noexcept {
  constexpr std::string_view names[] = {"static", "placed", "moving", "chain"};
  return names[static_cast<std::size_t>(s)];
}

// ---------------------------------------------------------------------------------------------
// Shapes placed by transforms (transformed.hpp). Each law judges the library on the exact images
// (oracle::placed): a shape with transform x is the exact image of its stored values under x.

/// Law placed_agreement. overlaps(a, xa, b, xb) equals the oracle's answer on the exact images outside the band
/// overlap_tolerance(a, xa, b, xb) (inside it a difference is a disagreement, and the answer must be
/// the oracle's on the images the library computed, bit for bit); it is symmetric to
/// the bit, equals overlaps(a, b) for identities, and contact() / distance() agree with it.
template <Scalar T>
Verdict placed_agreement(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb);

/// Law placed_outputs. The rounded outputs of placed shapes against the exact images: contact normal a unit
/// vector, depth >= 0 and (two primitives) within 4 rounding_tolerance(a, xa, b, xb) plus T's
/// rounding of the exact depth, a moved by -normal (depth + 2 bounds) apart, each point within
/// depth + bound of both shapes; distance within that bound of the exact gap; closest_points() in
/// both orders judged as in law closest_points, on the exact images with
/// closest_points_tolerance(a, xa, b, xb).
template <Scalar T>
Verdict placed_outputs(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb);

/// Law placed_resolution. v = resolve(a, xa, b, xb): zero without an overlap; otherwise a with its transform
/// moved by v (Transform::moved; OutOfRange allowed, then the exact move is judged) is apart from b
/// by the oracle, and for two primitives the gap left is at most 2 (resolve_margin(a, xa, b, xb,
/// |v|, v / |v|) + slack) and |v| at most the exact depth + margin + slack (slack as in law resolution).
template <Scalar T>
Verdict placed_resolution(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb);

/// Law placed_shape. One placed shape: bounds(s, x) contains the exact image; contains(s, x, p) equals the
/// oracle outside transform_tolerance(s, x) of the boundary; signed_distance(s, x, p) has contains(s,
/// x, p)'s sign and lies within signed_distance_tolerance(s, x, p) of the exact image's signed
/// distance (NaN and infinite points as in law signed_distance); a raycast hit has 0 <= t <= max_t and
/// its point within raycast_tolerance(s, x, ray) of the image and on the ray; a miss means no
/// point of the segment to max_t lies deeper than that bound in the image (oracle::passes_deeper).
/// Identity: the world-space answers.
template <Scalar T>
Verdict placed_shape(const Shape<T>& s, const Transform<T>& x, const Vec2<T>& p, const Ray<T>& ray, T max_t);

/// Law placed_covariance. Moving both shapes by the same transform x keeps every answer: exactly (overlaps and
/// contains identical) when x is a quarter turn with every mapped coordinate exact; otherwise
/// overlaps() may change only within overlap_tolerance(a, x, b, x) plus the scaling band of |q|
/// (R(q) scales positions by |q|, not radii); distance and depth kept within both pairs' bounds.
template <Scalar T>
Verdict placed_covariance(const Shape<T>& a, const Shape<T>& b, const Transform<T>& x);

/// Law placed_image. A shape with transform x equals the world shape x(s) built by the factories in T:
/// identical overlaps, distance and contact when every mapped value is exact in T (the depth of a
/// turned AABB, an OBB then, within the bounds); otherwise
/// overlaps() differs only within transform_tolerance(s, x) plus T's rounding of the built shape,
/// and distances within the bounds.
template <Scalar T>
Verdict placed_image(const Shape<T>& s, const Transform<T>& x, const Shape<T>& other);

/// Law transform_rejection. Transform::make(p, angle) and make_with_rotation(p, r) from raw values (position,
/// angle, rotation: values 0, 1 | 2 | 3, 4): NaN or infinity gives NonFinite and a magnitude above
/// max_magnitude<T>() OutOfRange, at the first offending value; a zero rotation vector
/// ZeroRotation; a rotation with | |r|^2 - 1 | <= 4 eps_T is kept bit for bit, any other is
/// normalised (within 2 eps_T of r / |r|); make() stores (cos, sin) with |q|^2 within 4 eps_T of
/// 1; moved() names an out-of-range position and keeps the rotation.
template <Scalar T>
Verdict transform_rejection(std::span<const T> values);

// ---------------------------------------------------------------------------------------------
// Contact manifolds (oracles/laws/src/manifold_laws.cpp). The bound of a point below is
// 4 rounding tolerances plus the rounding to T of the point (2 eps_T S) and of the separation,
// and the normal's rounding over half the separation (8 eps_T |s|).

/// Law separation. Every point of contact(a, b) has a finite separation s <= bound (no speculative
/// distance: penetrating or touching), and its surface points lie where s says: a's at
/// p - normal s / 2 and b's at p + normal s / 2 each within the bound of that shape's boundary
/// (oracle::compare_boundary_distance), rounded shapes as well as sharp ones; and no point is deeper
/// than the exact depth of its pair (oracle::compare_depth) by more than the bound. For compounds
/// the pair is the children the point's id names.
template <Scalar T>
Verdict manifold_separation(const Shape<T>& a, const Shape<T>& b);

/// Law feature_ids. Feature ids of contact(a, b) (numbering in collide/feature.hpp): each id names an
/// existing child, vertex or edge of each shape, lying within the shape's radius + bound + 4 depth
/// of that shape's surface point (a vertex counts with its adjacent edges, along which a clipped
/// point slides); two points have different ids; and stability: with b moved by +t and by -t
/// (t = 2^k (3, 4), k = ilogb S - 20 with S the larger bounding-box side, or the pair's scale for
/// two points, raised up to 8 to T's spacing at b's coordinates; only moves that add exactly to
/// every stored position count, so that the motion passes through b), when both moved pairs give
/// contacts with the same
/// ids and point count, the unmoved pair gives those ids too (the features did not change on the
/// way), unless a compound's unmoved pair has the child pair the moves name tied for the deepest
/// within the bound (the contract's deepest child pair is either then: a tie that holds at the
/// unmoved configuration only, as a point at a circle's centre beside a face exactly as deep), or
/// the ids differ only by a vertex against an edge of the same child ending at it, with the
/// unmoved point's surface point on that child within its radius + 2 |t| + 2 sqrt(size bound) of
/// the vertex (which of the two is nearer is a difference of squared distances, each rounded by
/// its length times the bound: within that reach of the vertex the rounding chooses).
/// OBBs thinner than their corners' rounding are not rebuilt (named in the account).
template <Scalar T>
Verdict manifold_ids(const Shape<T>& a, const Shape<T>& b);

/// Law resting. Two primitives whose cores have faces exactly parallel (up to 1e-12 of their
/// lengths' product) and facing each other, with contact(a, b)'s normal along the first face's
/// outward normal (within 1e-6) and its depth the faces' own penetration (their lines' distance
/// less the radii) within the bound: when the faces' common stretch along them is longer than the
/// cores' distance across them (0 when the cores meet) plus 64 bounds, the contact has two points,
/// at the stretch's two ends within 4 bounds along the faces (a box resting on a box or a capsule
/// lying on a face does not rock on one point). Where the faces' directions are parallel to the
/// bit (their cross product 0), both points name the reference face (kind Edge, its index) of
/// the shape whose kind comes first in the registry, a's for two of one kind, as feature.hpp rules
/// for faces equally deep. A shorter stretch may give one point: across a gap longer than the
/// faces, the normal follows the closest points (contact_cores.hpp, closest_normal). Judged in
/// both orders, (a, b) and (b, a). Compounds are not judged. bound: as manifold_separation's at the
/// contact's depth.
template <Scalar T>
Verdict manifold_resting(const Shape<T>& a, const Shape<T>& b);

/// Law speculative. contact(a, b, speculative) with speculative = 2^(ilogb(size) - 3), size the larger
/// bounding-box side: for overlapping pairs it exists, with contact(a, b)'s normal and depth and at
/// least its point count; for pairs apart it exists when the exact gap is below speculative - bound
/// and not when above speculative + bound; a speculative contact of shapes apart has depth 0, a
/// unit normal along which a approaches b by its smallest separation less the bound without meeting
/// it (oracle::separates), that separation within the bound of the exact gap, and every point's
/// separation at most speculative + bound and judged as in manifold_separation.
template <Scalar T>
Verdict manifold_speculative(const Shape<T>& a, const Shape<T>& b);

// ---------------------------------------------------------------------------------------------
// Mass properties (oracles/laws/src/mass_law.cpp).

/// Law mass. mass_properties(s, density), judged by mass.hpp's contract against the oracle's exact
/// mass, centroid, inertia and origin inertia (oracle::mass_within), each within the bound the
/// contract documents, written out here from the exact values (so mass_tolerance() is judged too:
/// it must agree with that bound to 2^-20); OutOfRange only where an exact output plus its bound
/// passes T's largest value. Placed by x: the centroid and origin inertia judged on x's exact
/// image, mass and inertia those of world space to the bit. Moved by t (translated()): judged
/// again, and an exact move (every stored position plus t exact) keeps mass and inertia to the bit.
/// A density that is NaN or infinite gives NonFinite in both forms, a negative one NegativeDensity.
template <Scalar T>
Verdict mass_law(const Shape<T>& s, T density, const Vec2<T>& t, const Transform<T>& x);

/// Laws placed_separation, placed_feature_ids and placed_speculative: separation, feature_ids and
/// speculative for a placed by xa and b placed by xb, judged on the exact images (a point's pair:
/// the children its id names, each the exact image under its child transform and then its body's),
/// with rounding_tolerance(a, xa, b, xb) as the bound's unit and bounds(s, x) for the sizes; for
/// feature_ids' stability b moves by +t and -t in its own frame (its stored values, as in
/// feature_ids; its body transform kept), so that its exact image moves by the turned t. With two
/// identities each is its world-space law.
template <Scalar T>
Verdict placed_separation(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb);
template <Scalar T>
Verdict placed_feature_ids(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb);
template <Scalar T>
Verdict placed_speculative(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb);

}  // namespace collide::laws

// ---------------------------------------------------------------------------------------------
// Moving shapes: shape_cast() (cast.hpp) and time_of_impact() (time_of_impact.hpp), judged by the
// oracle's exact answers for moving shapes (oracle::meets_during, oracle::meets_posed).

namespace collide::laws {

/// The motion of a linear cast: a placed by xa moves at va, b placed by xb at vb, over
/// [0, max_t]. With both transforms the identity the laws call the world-space shape_cast().
template <Scalar T>
struct CastInput {
  Vec2<T> va;            ///< velocity of a
  Vec2<T> vb;            ///< velocity of b
  T max_t;               ///< end of the interval
  Transform<T> xa = {};  ///< a's placement (its stored values are local to it)
  Transform<T> xb = {};  ///< b's placement
};

/// Cast law. shape_cast(a, xa, va, b, xb, vb, max_t), judged by cast.hpp's contract with
/// eps = cast_tolerance() on the exact images (oracle::placed): a valid answer with
/// 0 <= t <= max_t; shapes overlapping at the start (oracle) hit at t = 0, with the normal and
/// first point of contact(a, xa, b, xb) when that exists (a unit normal otherwise); a hit with
/// t > 0 leaves the exact shapes apart over [0, t] (no tunnelling) and within eps at t
/// (accuracy), with a unit normal from a toward b (point + L normal is at least L - slack from a,
/// point - L normal from b) and a point within eps of both; a miss has no exact contact in
/// [0, max_t]; an iteration limit none in [0, t]. Relation: Overlapping or Separated at the start.
template <Scalar T>
Verdict cast_law(const Shape<T>& a, const Shape<T>& b, const CastInput<T>& in);

/// Cast leaving law. shape_cast(..., CastOptions{.stop_at_overlap = false}), judged by cast.hpp's
/// "Leaving an overlap" with eps = cast_tolerance(): when contact(a, xa, b, xb) is absent or its
/// normal closes along va - vb, the default cast's answer bit for bit; otherwise a valid answer
/// with 0 <= t <= max_t in which every pair of primitives (oracle::placed parts) apart by more than
/// eps at the start is apart over [0, t] (over [0, max_t] after a miss), a hit is within eps of a
/// pair that did not overlap at the start, with a unit normal, and a pair of shapes whose every
/// pair of primitives overlaps at the start is a miss. Relation: Overlapping or Separated at the
/// start.
template <Scalar T>
Verdict cast_leaving(const Shape<T>& a, const Shape<T>& b, const CastInput<T>& in);

/// Cast symmetry and relative motion: swapping a and b (with their transforms) gives the same
/// outcome and t bit for bit and the reversed normal (bit for bit, except at t = 0 from an
/// overlap, where the normal is contact()'s, judged by the contact law); cast(a, va - vb, b, 0)
/// gives the same outcome, t and normal whenever va - vb is exact in T, and its point moved by
/// vb t (within T's rounding).
template <Scalar T>
Verdict cast_symmetry(const Shape<T>& a, const Shape<T>& b, const CastInput<T>& in);

/// Cast translation invariance: both shapes moved by d (translated(), or their transforms
/// moved by d when either is not the identity) obey the cast law; when both moves are exact, a
/// hit before the move and a miss after it (or the reverse) are allowed only for a motion that
/// passes within the larger tolerance without touching (a disagreement).
template <Scalar T>
Verdict cast_translation(const Shape<T>& a, const Shape<T>& b, const CastInput<T>& in, const Vec2<T>& d);

/// A zero-radius circle cast from the ray's origin along its direction against a still s agrees
/// with raycast(s, ray, max_t) on hit or miss, except for a ray passing within the larger of the
/// two tolerances (a disagreement), and never misses when the exact dot meets s within max_t;
/// both start inside: both at t = 0, unless the origin lies within the larger tolerance of the
/// boundary (either answer there is within both contracts: a disagreement).
template <Scalar T>
Verdict cast_raycast(const Shape<T>& s, const Ray<T>& ray, T max_t);

/// Time-of-impact law. time_of_impact(a, sa, b, sb, max_t), judged by time_of_impact.hpp's
/// contract with eps = toi_tolerance(): a valid answer with 0 <= t <= max_t; at each sample time
/// f * t (f in samples, within [0, 1]; f * max_t after a miss) the shapes placed exactly at
/// sweep_pose() are apart (oracle::meets_posed); at a hit's t they are within eps; a unit normal;
/// where they are apart at t, the normal points from a toward b and the point lies within the
/// tolerance of both, as cast_law() judges them; the swapped query gives the same t and the
/// reversed normal.
template <Scalar T>
Verdict toi_law(const Shape<T>& a, const Sweep<T>& sa, const Shape<T>& b, const Sweep<T>& sb, T max_t,
                std::span<const double> samples);

/// The sample times of the time-of-impact law in the property suite and in regression cases.
inline constexpr std::array<double, 8> kToiSamples = {0, 0.125, 0.25, 0.5, 0.75, 0.875, 0.999, 1};

// ---------------------------------------------------------------------------------------------
// Chains (collide/chain.hpp). Each law judges contact(s, b, xb, speculative) of one segment s and
// a shape b placed by xb, on the semantics stated in chain.hpp, against the exact oracle. A
// compound is judged through its children, each on its own as the library meets it (its image
// under its own transform and xb): a contact through the child its ids name, no contact through
// every child. Lengths are judged within 64 eps_T of the case's scale (the largest coordinate of
// the segment, its neighbours and b's bounds) plus twice transform_tolerance(b, xb), directions
// within 64 eps_T.

/// Law chain_admissible. The normal is the segment's front normal, or lies inside a corner arc the
/// segment owns (the turn decided by exact orient()).
template <Scalar T>
Verdict chain_admissible(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative);

/// Law chain_one_sided. A shape whose reference point (chain.hpp) lies strictly behind the
/// segment gets no contact.
template <Scalar T>
Verdict chain_one_sided(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative);

/// Law chain_surfaces. Each point lies midway between the surfaces: point - normal * separation / 2
/// on the segment and point + normal * separation / 2 on the exact shape's boundary; no separation
/// exceeds the speculative distance; a face contact's depth is the least separation's penetration
/// (a corner contact's is contact()'s, which the pair laws judge).
template <Scalar T>
Verdict chain_surfaces(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative);

/// Law chain_present. A contact is present only when the exact shape lies within the speculative
/// distance of the segment.
template <Scalar T>
Verdict chain_present(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative);

/// Law chain_face_complete. A shape that overlaps the segment (exact; a placed shape by more than
/// its transform_tolerance(), within which overlaps() may go either way), whose reference point lies
/// in front, and whose core's lowest point within the segment's strip (narrowed by the tolerance
/// at both ends) lies below the front by more than the tolerance once lowered by the core's
/// radius, gets a contact; unless it is the two-sided contact of a corner, its least separation
/// is no higher than that point. A compound's contact is its deepest child's: no child alone gets
/// a deeper one. The account of a case that makes this claim begins "claimed".
template <Scalar T>
Verdict chain_face_complete(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative);

/// Law chain_face_ids. A contact is the segment's two-sided contact bit for bit (which the pair
/// laws judge, its ids renamed for a placed shape as the contact renames them), or each of its
/// points names the segment's edge 0 and a vertex of the shape's stored core (mapped by xb) whose
/// sides (or the vertex itself) lie the core's radius from the point's end on the shape.
template <Scalar T>
Verdict chain_face_ids(const ChainSegment<T>& s, const Shape<T>& b, const Transform<T>& xb, T speculative);

}  // namespace collide::laws
