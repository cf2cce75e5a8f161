// laws::relation: the exact relation of two shapes, for the case distribution of every law.

#include "support.hpp"

namespace collide::laws {

using detail::primitives_of;

std::string_view name(Relation r) noexcept {
  switch (r) {
    case Relation::Separated: return "separated";
    case Relation::Touching: return "touching";
    case Relation::Overlapping: return "overlapping";
    case Relation::Contained: return "contained";
  }
  return "unknown";
}

namespace {

/// inner lies inside the primitive outer: every vertex of inner's core is in outer with clearance
/// inner's radius (outer is convex, inner is the convex hull of those discs).
template <Scalar T>
bool inside_primitive(const Primitive<T>& inner, const Primitive<T>& outer) {
  const ::collide::detail::Core core =
      std::visit([](const auto& s) { return ::collide::detail::core_of(s); }, inner);
  for (const Vec2c& p : core.pts()) {
    if (!oracle::contains(outer, p)) return false;
    if (core.radius > 0 && oracle::compare_boundary_distance(outer, p, core.radius) < 0) return false;
  }
  return true;
}

/// Every primitive of inner inside one primitive of outer (for a compound outer, inside one child).
template <Scalar T>
bool contained_in(const Shape<T>& inner, const Shape<T>& outer) {
  const std::vector<Primitive<T>> in = primitives_of(inner), out = primitives_of(outer);
  for (const Primitive<T>& o : out) {
    bool all = true;
    for (const Primitive<T>& i : in) all = all && inside_primitive(i, o);
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
