#pragma once
/// @file contact.hpp
/// Contact manifolds of two shapes, and contact with a speculative distance. Error contract:
/// tolerances.hpp.

#include "collide/compound.hpp"
#include "collide/decide.hpp"
#include "collide/feature.hpp"
#include "collide/detail/contact_cores.hpp"
#include "collide/detail/contact_pairs.hpp"
#include "collide/detail/convex_core.hpp"
#include "collide/registry.hpp"
#include "collide/shape_traits.hpp"
#include "collide/shapes.hpp"
#include "collide/tolerances.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <type_traits>

namespace collide {

/// Where two shapes touch: a contact manifold of one or two points, for a physics solver.
///
/// Units are the shapes' own; the normal points from a toward b. A point's separation is the
/// signed distance between the two surfaces along the normal at that point: negative when they
/// penetrate (then -separation is that point's penetration), positive for a speculative point of
/// shapes still apart. The point itself lies midway between the surfaces, so a's surface point is
/// point - normal * separation / 2 and b's is point + normal * separation / 2.
template <Scalar T>
struct Contact {
  Vec2<T> normal;                 ///< unit vector pointing from a toward b (a moves along -normal to separate)
  T depth;                        ///< penetration depth along normal, >= 0 (0 when only touching or apart)
  int count;                      ///< number of valid entries in points, ids and separations: 1 or 2
  std::array<Vec2<T>, 2> points;  ///< contact points, midway between the two surfaces
  std::array<FeatureId, 2> ids;   ///< per point, the features of a and b that produced it (feature.hpp)
  std::array<T, 2> separations;   ///< per point, signed surface distance along normal (< 0 penetrating)
};

namespace detail {

/// A CoreContact rounded to T, as the value that initialises a Contact<T>: emplace() builds the
/// contact from it in place, field by field, without zeroing it first (every field is written) or
/// copying it (a copy of a contact written piecewise would be read back in wider pieces than it
/// was stored).
template <Scalar T>
struct RoundedContact {
  const CoreContact& c;
  operator Contact<T>() const {
    return {c.normal.template cast<T>(),
            static_cast<T>(c.depth),
            c.count,
            {c.points[0].template cast<T>(), c.points[1].template cast<T>()},
            c.ids,
            {static_cast<T>(c.separations[0]), static_cast<T>(c.separations[1])}};
  }
};

/// Makes out hold c rounded to T (RoundedContact).
template <Scalar T>
void round_into(const CoreContact& c, std::optional<Contact<T>>& out) {
  out.emplace(RoundedContact<T>{c});
}

/// The contact of two primitives in either order (contact_pair() takes registry order; the other
/// order is the same contact seen from b: normal reversed, ids swapped). A stored float shape met
/// by a double image (a transformed query) is widened first, exactly. rounding: as contact_pair().
template <PrimitiveShape A, PrimitiveShape B>
std::optional<CoreContact> contact_primitives(const A& a, const B& b, Calc speculative, Rounding rounding = {}) {
  if constexpr (!std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>) {
    if constexpr (std::is_same_v<scalar_of_t<A>, float>) {
      return contact_primitives(widened_shape(a), b, speculative, rounding);
    } else {
      return contact_primitives(a, widened_shape(b), speculative, rounding);
    }
  } else if constexpr (static_cast<int>(kind_of_v<A>) <= static_cast<int>(kind_of_v<B>)) {
    return contact_pair(a, b, speculative, rounding);
  } else {
    std::optional<CoreContact> c = contact_pair(b, a, speculative, rounding);
    if (c) *c = reversed(*c);
    return c;
  }
}

/// The index of a contact's deepest point: the least separation, the first of equals.
inline std::size_t deepest_point(const CoreContact& c) noexcept {
  return c.count > 1 && c.separations[1] < c.separations[0] ? 1 : 0;
}
/// The largest coordinate of a contact's deepest point. A speculative distance only adds points
/// farther apart, so this scale is the same with and without it.
inline Calc deepest_point_scale(const CoreContact& c) noexcept {
  return c.points[deepest_point(c)].cwiseAbs().maxCoeff();
}

/// Overlapping contacts before speculative ones, then the deeper (or the nearer) by more than a
/// tie (kFaceOrderTie units of roundoff of the deepest points' scale): child pairs equally deep up
/// to rounding keep their order, so that the ids stay put while such a pair slides.
inline bool deeper_contact(const CoreContact& c, const CoreContact& than) noexcept {
  if (c.overlapping != than.overlapping) return c.overlapping;
  const Calc tie = tie_of(std::max(deepest_point_scale(c), deepest_point_scale(than)));
  return c.overlapping ? c.depth > than.depth + tie
                       : c.separations[deepest_point(c)] < than.separations[deepest_point(than)] - tie;
}

/// The contact of concrete shapes, stored or placed (images, placed compounds). rounding: as
/// contact_pair() takes it (empty for stored primitives).
template <class A, class B>
std::optional<CoreContact> contact_concrete(const A& a, const B& b, Calc speculative = 0, Rounding rounding = {}) {
  if constexpr (is_compound_v<A> || is_compound_v<B>) {
    // The cached bounding boxes first (without a speculative distance), then every child pair.
    if (!(speculative > 0) && !decide::aabb_aabb(calc_bounds(a), calc_bounds(b))) return std::nullopt;
    std::optional<CoreContact> best;
    std::uint16_t ia = 0;
    for_each_primitive(a, [&](const auto& ca) {
      std::uint16_t ib = 0;
      for_each_primitive(b, [&](const auto& cb) {
        std::optional<CoreContact> c = contact_primitives(ca, cb, speculative, rounding);
        if (c && (!best || deeper_contact(*c, *best))) {
          for (FeatureId& id : c->ids) {
            id.child_a = ia;
            id.child_b = ib;
          }
          best = c;
        }
        ++ib;
      });
      ++ia;
    });
    if (best) {
      name_child_features(a, *best, false);
      name_child_features(b, *best, true);
    }
    return best;
  } else {
    return contact_primitives(a, b, speculative, rounding);
  }
}

/// A speculative distance as contact() takes it: negative or NaN counts as 0.
template <Scalar T>
Calc speculative_distance(T speculative) noexcept {
  return speculative > 0 ? Calc(speculative) : Calc(0);
}

/// contact() with its result in T, for shapes stored or placed; speculative as contact() takes it.
template <Scalar T, class A, class B>
std::optional<Contact<T>> contact_as(const A& a, const B& b, T speculative = T(0)) {
  const Calc spec = speculative_distance(speculative);
  const std::optional<CoreContact> c = visit_shapes(a, b, [&](const auto& ca, const auto& cb) {
    // A compound's children placed by child transforms are images; primitives are stored exactly.
    const auto placements = [&] { return placement_tolerance(ca) + placement_tolerance(cb); };
    constexpr bool compound = is_compound_v<std::decay_t<decltype(ca)>> || is_compound_v<std::decay_t<decltype(cb)>>;
    return contact_concrete(ca, cb, spec, compound ? Rounding(placements) : Rounding());
  });
  std::optional<Contact<T>> out;
  if (c) round_into(*c, out);
  return out;
}

}  // namespace detail

/// Contact with a speculative distance (in the shapes' units), as a solver uses to stop shapes
/// before they meet: present when overlaps(a, b), and also when the shapes are apart by at most
/// `speculative` (decided on the rounded gap: a pair within a few rounding_tolerance(a, b) of
/// that distance may go either way). A speculative contact of shapes apart has depth 0 and, when
/// the closest points lie inside a face, the other shape's facing side clipped to it (a point per
/// end apart by at most `speculative`), else one point between the closest points; its least
/// separation is the gap (>= 0); an overlapping pair keeps the points of contact(a, b) and adds
/// clipped points apart by at most `speculative`.
/// overlaps() stays the exact answer. A negative or NaN `speculative` counts as 0 (contact(a, b));
/// an infinite one reports every pair. For compounds, an overlapping child pair wins over the
/// nearest pair apart.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> std::optional<Contact<scalar_of_t<A>>> contact(
    const A& a, const B& b, scalar_of_t<A> speculative) {
  return detail::contact_as<scalar_of_t<A>>(a, b, speculative);
}

/// Contact of two shapes: present exactly when overlaps(a, b). For a compound, the deepest contact
/// among its overlapping child pairs (the ids name the children; pairs equally deep up to rounding
/// keep their order). Coincident circle centres give normal (1, 0).
/// Error: normal, depth, points and separations are rounded results, each within a few
/// rounding_tolerance(a, b) of the exact values (depth of the exact depth; each separation of the
/// exact signed distance of the surfaces along the normal at its point).
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> std::optional<Contact<scalar_of_t<A>>> contact(const A& a,
                                                                                                       const B& b) {
  return contact(a, b, scalar_of_t<A>(0));
}

}  // namespace collide
