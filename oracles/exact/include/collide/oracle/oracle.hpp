#pragma once
/// @file oracle.hpp
/// The exact oracle: answers about the point sets that shapes' stored values define, decided
/// exactly (CGAL's number types, GMP underneath). Float shapes are widened to double first
/// (exact), and every double is taken as the exact binary rational it stores.
///
/// Each primitive is a convex core (point, segment or convex polygon with exact vertices) dilated
/// by a radius (0 for boxes and polygons); every answer is the sign of a polynomial in the stored
/// values (orientations, dot products, squared distances without division), evaluated in
/// interval arithmetic and, only for a sign the intervals cannot certify, exactly.
///
/// Same convention as the library: shapes are closed sets, touching counts as overlapping.
/// An OBB is center +- hx*u +- hy*v with the stored axis u and v = perp(u), computed exactly.
///
/// Call these qualified (oracle::overlaps(a, b)): an unqualified call with library shapes also
/// finds collide::overlaps and friends by argument-dependent lookup, and the library's versions
/// are more constrained, so they would win or the call would be ambiguous.
///
/// This header has no CGAL include: CGAL stays inside collide::oracle's translation units, and
/// out of collide::collide (the kernel is LGPL).

#include "collide/collide.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace collide::oracle {

/// A question the oracle does not answer exactly (named in what()).
class Unsupported : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// An argument the oracle cannot convert to a rational: a NaN or infinite coordinate, radius,
/// distance or translation (valid shapes never hold one; the guard keeps GMP from trapping).
class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// A shape placed by a transform, as the oracle takes it: the exact image of the stored shape
/// under x -> R(rotation) x + position, rotation (cos, sin) as stored (not normalised), every
/// product and sum exact (transform.hpp). A compound's children are placed by their own
/// transforms first. A Shape<double> converts to the identity placement.
struct Placed {
  Shape<double> shape;              ///< the stored (local) shape, widened to double
  Vec2<double> position{0.0, 0.0};  ///< the transform's position
  Vec2<double> rotation{1.0, 0.0};  ///< the transform's rotation, as stored
  /// The identity placement: the shape itself.
  Placed(Shape<double> s) : shape(std::move(s)) {}  // NOLINT(google-explicit-constructor)
  /// The shape under the transform (position, rotation).
  Placed(Shape<double> s, const Vec2<double>& p, const Vec2<double>& q)
      : shape(std::move(s)), position(p), rotation(q) {}
};

/// The exact answers, on double shapes. The templates below accept any shape type and scalar.
/// Every function throws InvalidInput on a non-finite argument. Thread-safe (no shared state; the
/// FPU rounding mode is set and restored per call).
namespace exact {
bool overlaps(const Placed& a, const Placed& b);
bool contains(const Placed& s, const Vec2<double>& p);
bool contains_shape(const Placed& outer, const Placed& inner);
int compare_distance(const Placed& a, const Placed& b, double d);
bool within_band(const Placed& a, const Placed& b, double band);
bool separates(const Placed& a, const Placed& b, const Vec2<double>& t);
int compare_depth(const Placed& a, const Placed& b, double len);
bool inside_box(const Placed& s, const Aabb<double>& box);
int compare_boundary_distance(const Placed& s, const Vec2<double>& p, double d);
bool segment_meets(const Placed& s, const Vec2<double>& p, const Vec2<double>& q);
bool passes_deeper(const Placed& s, const Vec2<double>& p, const Vec2<double>& q, double depth);
double approx_signed_distance(const Placed& a, const Placed& b);
}  // namespace exact

/// Any shape type as an exact Shape<double>.
template <AnyShape S>
Shape<double> as_exact_input(const S& s) {
  if constexpr (VariantShape<S>) {
    if constexpr (std::is_same_v<S, Shape<double>>) {
      return s;
    } else if constexpr (std::is_same_v<S, Shape<float>>) {
      return widened(s);
    } else {
      return std::visit([](const auto& x) { return as_exact_input(x); }, s);
    }
  } else if constexpr (std::is_same_v<scalar_of_t<S>, double>) {
    return Shape<double>(s);
  } else {
    return Shape<double>(widened(s));
  }
}

/// A placed shape is already an exact input.
inline const Placed& as_exact_input(const Placed& p) {
  return p;
}

/// Any shape with a transform as the oracle's exact input (both widened exactly).
template <AnyShape S>
Placed placed(const S& s, const Transform<scalar_of_t<S>>& x) {
  return Placed(as_exact_input(s), x.position().template cast<double>(), x.rotation().template cast<double>());
}

/// What the oracle takes: any library shape, or a Placed one.
template <class S>
concept OracleInput = AnyShape<S> || std::is_same_v<std::remove_cvref_t<S>, Placed>;

/// Exact: the closed shapes share a point.
template <OracleInput A, OracleInput B>
bool overlaps(const A& a, const B& b) {
  return exact::overlaps(as_exact_input(a), as_exact_input(b));
}

/// Exact: p lies in the closed shape.
template <OracleInput S, Scalar T>
bool contains(const S& s, const Vec2<T>& p) {
  return exact::contains(as_exact_input(s), p.template cast<double>());
}

/// Exact: the closed shape inner lies wholly in the closed shape outer (touching from inside
/// counts). outer must be a primitive or a compound of one child (placed by its child transform);
/// a compound of several children throws Unsupported (containment in a union is not defined
/// here). Circles and capsules are decided through squared distances, without square roots.
template <OracleInput O, OracleInput I>
bool contains(const O& outer, const I& inner) {
  return exact::contains_shape(as_exact_input(outer), as_exact_input(inner));
}

/// Exact sign of (gap(a, b) - d), gap = Euclidean distance between the closed shapes (0 when they
/// overlap). d must be finite (InvalidInput otherwise); a negative d gives +1.
template <OracleInput A, OracleInput B>
int compare_distance(const A& a, const B& b, double d) {
  return exact::compare_distance(as_exact_input(a), as_exact_input(b), d);
}

/// Exact: the signed distance sigma (gap if separated, -depth if overlapping) satisfies
/// |sigma| <= band. This is the region where overlaps() may disagree with the oracle.
///
/// With a compound on either side (children a_i, b_j), defined child by child, because the
/// library ORs its child decisions and may err on each child pair within its band:
/// - no child pair overlaps: true iff min over pairs of gap(a_i, b_j) <= band;
/// - some child pair overlaps: true iff every overlapping child pair has depth <= band.
/// For two primitives this is exactly |sigma| <= band. Never throws Unsupported.
template <OracleInput A, OracleInput B>
bool within_band(const A& a, const B& b, double band) {
  return exact::within_band(as_exact_input(a), as_exact_input(b), band);
}

/// Exact: a moved by t (exact rational sum, no rounding) does not overlap b.
template <OracleInput A, OracleInput B, Scalar T>
bool separates(const A& a, const B& b, const Vec2<T>& t) {
  return exact::separates(as_exact_input(a), as_exact_input(b), t.template cast<double>());
}

/// Exact sign of (depth(a, b) - len). depth = infimum of |t| over translations t of a after which
/// the shapes do not overlap (0 when they do not overlap now). With cores Pa, Pb, radii summing
/// to r and D = Pb - Pa (Minkowski difference): depth = dist(0, boundary of D) + r when the cores
/// meet, else max(0, r - dist(Pa, Pb)). Pairs of primitives only (a compound of one child counts as
/// that child placed by its child transform); any other compound throws Unsupported.
template <OracleInput A, OracleInput B>
int compare_depth(const A& a, const B& b, double len) {
  return exact::compare_depth(as_exact_input(a), as_exact_input(b), len);
}

/// Exact: the closed shape lies inside the closed box.
template <OracleInput S, Scalar T>
bool inside_box(const S& s, const Aabb<T>& box) {
  // A bounding box may lie beyond max_magnitude() (it is rounded outward): widen it unchecked.
  return exact::inside_box(as_exact_input(s), detail::AabbAccess::unchecked<double>(box.min().template cast<double>(),
                                                                                    box.max().template cast<double>()));
}

/// Exact sign of (distance from p to the shape's boundary - d). For p inside the closed shape
/// this is the point's depth (distance to the nearest boundary point). A compound of one child
/// answers as that child placed by its child transform; a larger compound answers only for p
/// outside all its children (min over children), and p inside a child throws Unsupported.
template <OracleInput S, Scalar T>
int compare_boundary_distance(const S& s, const Vec2<T>& p, double d) {
  return exact::compare_boundary_distance(as_exact_input(s), p.template cast<double>(), d);
}

/// Exact: the closed segment [p, q] meets the closed shape.
template <OracleInput S>
bool segment_meets(const S& s, const Vec2<double>& p, const Vec2<double>& q) {
  return exact::segment_meets(as_exact_input(s), p, q);
}

/// Exact up to a relative 2^-50 of depth: some point of the closed segment [p, q] lies inside the
/// shape farther than depth from its boundary (for a compound: inside some child, farther than
/// depth from that child's boundary). True only for such a point, and whenever some point is
/// deeper than depth (1 + 2^-50) (polygon edges between 2^-511 and 2^511 long; an edge shorter
/// counts as longer, one longer makes the answer false). A thin shape is never passed deep.
template <OracleInput S>
bool passes_deeper(const S& s, const Vec2<double>& p, const Vec2<double>& q, double depth) {
  return exact::passes_deeper(as_exact_input(s), p, q, depth);
}

/// For reports only: the signed distance rounded to double (gap > 0, touching 0, -depth < 0;
/// compounds report -0 when overlapping).
template <OracleInput A, OracleInput B>
double approx_signed_distance(const A& a, const B& b) {
  return exact::approx_signed_distance(as_exact_input(a), as_exact_input(b));
}

/// The outputs of mass_properties(), in this order: mass, centroid x, centroid y, inertia about
/// the centroid, inertia about the origin.
enum class MassOutput : std::uint8_t { Mass, CentroidX, CentroidY, Inertia, OriginInertia };
/// How many outputs mass_properties() has.
inline constexpr std::size_t kMassOutputs = 5;
/// One value per output, in MassOutput's order.
using MassValues = std::array<double, kMassOutputs>;

namespace exact {
std::array<bool, kMassOutputs> mass_within(const Placed& s, double density, const MassValues& values,
                                           const MassValues& bounds);
MassValues approx_mass(const Placed& s, double density);
}  // namespace exact

/// Exact, per output k: |values[k] - x| <= bounds[k] for the exact output x of mass.hpp's
/// definition for s at this density (placed: the centroid is the placement's image, mass and
/// inertia are kept). Shapes with a round part (pi) and capsules (their length |b - a|) are judged
/// for every x in a bracket of rationals around the exact value, 2^-119 wide relatively: only a
/// value within that of the bound's edge can be judged outside. Values, bounds and the density must
/// be finite (InvalidInput otherwise).
template <OracleInput S>
std::array<bool, kMassOutputs> mass_within(const S& s, double density, const MassValues& values,
                                           const MassValues& bounds) {
  return exact::mass_within(as_exact_input(s), density, values, bounds);
}

/// For reports, and for the bounds that scale with them: the exact outputs rounded to double
/// (the middle of their brackets).
template <OracleInput S>
MassValues approx_mass(const S& s, double density) {
  return exact::approx_mass(as_exact_input(s), density);
}

}  // namespace collide::oracle

// ---------------------------------------------------------------------------------------------
// Moving shapes (cast_oracle.cpp): shape casts and time of impact judged exactly.

namespace collide::oracle {

namespace exact {
bool meets_during(const Placed& a, const Vec2<double>& va, const Placed& b, const Vec2<double>& vb, double t0,
                  double t1, double pad);
bool meets_posed(const Shape<double>& a, const Vec2<double>& qa, const Vec2<double>& pa, const Shape<double>& b,
                 const Vec2<double>& qb, const Vec2<double>& pb, double pad);
}  // namespace exact

/// Exact: at some time s in [t0, t1] (either order), the shapes a + va s and b + vb s (exact
/// rational positions) are at most pad apart (pad = 0: they overlap, touching included; a negative
/// pad counts as 0). For two primitives the set of such s is an interval, so this is one static
/// test of a's core swept by (va - vb) over [t0, t1] against b; compounds: some pair of children.
/// Hence, with t* the exact first contact time: t* <= t  <=>  meets_during(a, va, b, vb, 0, t).
/// Either shape may be placed by a transform (oracle::placed()): its exact image moves.
template <OracleInput A, OracleInput B, Scalar T>
bool meets_during(const A& a, const Vec2<T>& va, const B& b, const Vec2<T>& vb, double t0, double t1, double pad = 0) {
  return exact::meets_during(as_exact_input(a), va.template cast<double>(), as_exact_input(b),
                             vb.template cast<double>(), t0, t1, pad);
}

/// Exact: the shape a placed at pose (qa, pa) and b at (qb, pb) are at most pad apart. A pose maps
/// a local point x to R(q) x + p, R(q) = [[q.x, -q.y], [q.y, q.x]], evaluated exactly (q need not be
/// a unit vector: the map is the one the doubles define); radii are kept.
template <AnyShape A, AnyShape B>
bool meets_posed(const A& a, const Vec2<double>& qa, const Vec2<double>& pa, const B& b, const Vec2<double>& qb,
                 const Vec2<double>& pb, double pad = 0) {
  return exact::meets_posed(as_exact_input(a), qa, pa, as_exact_input(b), qb, pb, pad);
}

}  // namespace collide::oracle
