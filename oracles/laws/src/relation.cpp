// laws::relation: the exact relation of two shapes, for the case distribution of every law.

#include "support.hpp"

namespace collide::laws {

using detail::placed_primitives_of;

std::string_view name(Relation r) noexcept {
  switch (r) {
    case Relation::Separated:
      return "separated";
    case Relation::Touching:
      return "touching";
    case Relation::Overlapping:
      return "overlapping";
    case Relation::Contained:
      return "contained";
  }
  return "unknown";
}

namespace {

/// A core inside the placed primitive outer: every vertex of the core is in outer with clearance
/// the core's radius (outer is convex, the inner shape is the convex hull of those discs).
bool inside_placed(const ::collide::detail::Core& core, const oracle::Placed& outer) {
  for (const Vec2c& p : core.pts()) {
    if (!oracle::contains(outer, p)) return false;
    if (core.radius > 0 && oracle::compare_boundary_distance(outer, p, core.radius) < 0) return false;
  }
  return true;
}

/// Every primitive of inner inside one primitive of outer (for a compound outer, inside one
/// child); children as their child transforms place them (inner's cores as imaged in double).
template <Scalar T>
bool contained_in(const Shape<T>& inner, const Shape<T>& outer) {
  std::vector<::collide::detail::Core> in;
  for (const auto& c : placed_primitives_of(inner)) {
    std::visit(
        [&](const auto& x) {
          ::collide::detail::with_image(x, c.transform.pose(),
                                        [&](const auto& img) { in.push_back(::collide::detail::core_of(img)); });
        },
        c.shape);
  }
  for (const auto& o : placed_primitives_of(outer)) {
    const oracle::Placed po = oracle::placed(o.shape, o.transform);
    bool all = true;
    for (const ::collide::detail::Core& core : in) all = all && inside_placed(core, po);
    if (all) return true;
  }
  return false;
}

}  // namespace

template <Scalar T>
Relation relation(const Shape<T>& a, const Shape<T>& b) {
  if (!oracle::overlaps(a, b)) return Relation::Separated;
  // Overlapping with signed distance exactly 0: only boundaries meet. For compounds within_band
  // answers child pair by child pair: every overlapping child pair touches.
  if (oracle::within_band(a, b, 0.0)) return Relation::Touching;
  if (contained_in(a, b) || contained_in(b, a)) return Relation::Contained;
  return Relation::Overlapping;
}

template Relation relation<float>(const Shape<float>&, const Shape<float>&);
template Relation relation<double>(const Shape<double>&, const Shape<double>&);

}  // namespace collide::laws
