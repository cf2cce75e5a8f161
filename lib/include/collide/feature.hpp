#pragma once
/// @file feature.hpp
/// Feature ids of contact points: which vertex or edge of each shape produced a point, so that a
/// physics solver can match the points of one frame to those of the next (warm starting).
///
/// Numbering, per shape (its convex core; see detail/convex_core.hpp):
/// - Circle: vertex 0 is the centre.
/// - Capsule: vertex 0 is a(), vertex 1 is b(); edge 0 is the side whose outward normal is
///   (d.y, -d.x) with d = b() - a() (the right-hand side going from a to b), edge 1 the other side.
///   A capsule with a() == b() has vertex 0 only.
/// - AABB: vertices 0..3 are (min.x, min.y), (max.x, min.y), (max.x, max.y), (min.x, max.y); edge i
///   runs from vertex i to vertex i + 1 (0 bottom, 1 right, 2 top, 3 left). A box flat on one axis
///   is the segment from vertex 0 = min() to vertex 1 = max() (edges 0 and 1 its sides, as for a
///   capsule); a point box has vertex 0 only.
/// - OBB: vertices 0..3 are c - ex - ey, c + ex - ey, c + ex + ey, c - ex + ey (ex = hx axis(),
///   ey = hy perp(axis())), edges as for the AABB. A box flat on one axis is the segment from
///   c - ex - ey to c + ex + ey. (A box thinner than the rounding of its corners is numbered along
///   the convex hull of its computed corners.)
/// - Polygon: vertex i is vertices()[i]; edge i runs from vertex i to vertex i + 1 (mod size()).
///   A placed polygon keeps this numbering when rounding makes its image not strictly convex (the
///   image is then the hull of its rounded vertices): an edge of that hull merged from several
///   faces is named by the face its point lies nearest, and a vertex that rounding merged with
///   others by the one whose edges lie nearest its point.
/// - Compound: the child's index in children() is child_a / child_b, the rest numbers the child.
///
/// A point of a face contact carries the reference face (an edge) on the shape that owns it and
/// the incident vertex it comes from on the other shape; an incident vertex clipped back to the
/// reference face's side keeps that vertex's id, so the ids stay the same while the two faces stay
/// the reference and incident faces. Of two parallel faces equally deep up to rounding (for
/// placed shapes, up to their images' rounding too: transform_tolerance()), the reference face is
/// that of the shape whose kind comes first in the registry (a turned AABB counts as an OBB), a's
/// for two of one kind: contact(b, a) is contact(a, b) seen from b. A point of two rounded cores
/// apart (circles, capsules) names the closest features of the cores; between parallel faces,
/// where every point of their common span is closest, it names both edges.

#include <cstdint>

namespace collide {

/// The kind of a feature of a shape's core.
enum class FeatureKind : std::uint8_t {
  Vertex,  ///< a vertex (a circle's centre, a capsule's end, a box or polygon corner)
  Edge,    ///< an edge (a box or polygon side, a capsule's side)
};

/// Which features of the two shapes produced one contact point (see the numbering above). Equal
/// ids in two frames mean the same pair of features.
struct FeatureId {
  std::uint16_t child_a = 0;                 ///< index of a's child (0 for a primitive)
  std::uint16_t child_b = 0;                 ///< index of b's child (0 for a primitive)
  std::uint8_t index_a = 0;                  ///< vertex or edge index on a (or its child)
  std::uint8_t index_b = 0;                  ///< vertex or edge index on b (or its child)
  FeatureKind kind_a = FeatureKind::Vertex;  ///< whether index_a names a vertex or an edge
  FeatureKind kind_b = FeatureKind::Vertex;  ///< whether index_b names a vertex or an edge
  /// Field by field.
  friend constexpr bool operator==(const FeatureId&, const FeatureId&) noexcept = default;
  /// The same features with a and b exchanged (the id of the point in contact(b, a)).
  constexpr FeatureId swapped() const noexcept { return {child_b, child_a, index_b, index_a, kind_b, kind_a}; }
  /// All fields packed in one integer, for hashing and sorting.
  constexpr std::uint64_t key() const noexcept {
    return std::uint64_t(child_a) << 48 | std::uint64_t(child_b) << 32 | std::uint64_t(index_a) << 24 |
           std::uint64_t(index_b) << 16 | std::uint64_t(kind_a) << 8 | std::uint64_t(kind_b);
  }
};

}  // namespace collide
