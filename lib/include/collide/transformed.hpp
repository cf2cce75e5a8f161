#pragma once
/// @file transformed.hpp
/// Every query on shapes stored in local frames and placed by transforms: overlaps, contact,
/// resolve, distance, closest points, signed distance, raycast, contains and bounds, for every kind
/// (compounds included), both scalars and either argument order. The world-space queries are these
/// with the identity.
///
/// Meaning: a shape s with transform x is the exact image of its stored values under x
/// (transform.hpp). Queries compute that image in double (detail/image.hpp) — a compound is never
/// copied: each child is imaged when visited, under the body transform composed with its own —
/// and run the world-space machinery on it. The identity computes nothing: the stored shape is
/// used as is. One pair is computed in a local frame instead (detail/contact_local.hpp): the
/// contact of a circle and a polygon turned by a general rotation, in the polygon's frame, decided
/// there only when its gap is clear of a band that covers the images' rounding, so its answer is
/// still the computed images' (present exactly when they overlap, their features).
///
/// Error contract (the one definition, with the one at the top of tolerances.hpp):
/// - delta_T(s, x) = transform_tolerance(s, x) bounds how far the computed image lies from the
///   exact image (Hausdorff distance): 0 for the identity (and a compound without child
///   transforms); otherwise 16 * 2^-53 * (|p|_inf + 2 L) + 2^-1070, p = x's position, L = the
///   local magnitude (a primitive: the largest absolute coordinate of bounds(s) in its frame; a
///   compound: the largest over its children of |child position|_inf + 2 * that child's).
///   Derivation: a mapped coordinate (q.x u - q.y w) + p is three roundings of double, within
///   3 * 2^-53 (|q.x u| + |q.y w| + |p|) <= 3 * 2^-53 (1.42 L + |p|) of exact; an OBB's turned
///   axis moves its corners by at most 2 * 2^-53 * 1.42 * (hx + hy); an AABB turned into an OBB
///   rounds its centre and half extents once each (2^-53 L); a compound child adds the
///   composition (q rounded twice, p three times). Summed with the Euclidean sqrt(2), each image
///   point is within about 8.5 * 2^-53 (|p| + 2 L) of exact: the stated bound has a factor of 2 to
///   spare. The 2^-1070 floor covers products that underflow.
/// - With the identity, exact translations and quarter turns (q = (+-1, 0) or (0, +-1), and every
///   sum coordinate + position exact in double, which holds for float shapes and positions whose
///   magnitudes are within 2^28 of each other) the image is exact: overlaps and contains are the
///   exact answers, and when the image's values are exact in T too, every answer (contact,
///   distance, raycast included) equals the world-space answer on x(s) built by the factories,
///   which then holds the same values; resolve() may push further, by its margin's delta_T terms.
///   Moving both shapes of a pair by one exact transform keeps the decisions; rounded outputs
///   move within their bounds (their rounding depends on where the shapes are).
/// - overlaps(a, xa, b, xb) equals the exact answer for the exact images whenever their signed
///   distance (gap, or minus the penetration depth) is outside
///   [-overlap_tolerance(a, xa, b, xb), +overlap_tolerance(a, xa, b, xb)], the sum of both delta_T.
///   contains(s, x, p) likewise, with delta_T(s, x) around the boundary.
/// - Rounded outputs (contact depth, points, distance) get delta_T(a) + delta_T(b) added to the
///   world-space bound: rounding_tolerance(a, xa, b, xb) is their unit; resolve()'s margin gets
///   2 (delta_T(a) + delta_T(b)) added; raycast_tolerance(s, x, ray) adds delta_T(s, x).
/// - No allocation: imaging a polygon of at most 8 vertices (ConvexPolygon::kInline) is inline.

#include "collide/compound.hpp"
#include "collide/contains.hpp"
#include "collide/detail/contact_local.hpp"
#include "collide/detail/placement.hpp"
#include "collide/detail/image.hpp"
#include "collide/contact.hpp"
#include "collide/distance.hpp"
#include "collide/overlaps.hpp"
#include "collide/resolve.hpp"
#include "collide/tolerances.hpp"
#include "collide/raycast.hpp"
#include "collide/shape_traits.hpp"
#include "collide/transform.hpp"

#include <algorithm>
#include <optional>
#include <type_traits>

namespace collide {

/// How far the computed image of s under x may lie from the exact image (Hausdorff distance):
/// 16 * 2^-53 * (|position|_inf + 2 L) + 2^-1070, or 0 for the identity on a shape without child
/// transforms. See the contract at the top of this file.
template <AnyShape S>
Calc transform_tolerance(const S& s, const Transform<scalar_of_t<S>>& x) {
  if (x.is_identity()) return placement_tolerance(s);
  return detail::visit_shape(s, [&](const auto& c) { return detail::image_tolerance_of(c, x); });
}

/// The band of overlaps(a, xa, b, xb): transform_tolerance(a, xa) + transform_tolerance(b, xb).
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Calc overlap_tolerance(const A& a,
                                                                               const Transform<scalar_of_t<A>>& xa,
                                                                               const B& b,
                                                                               const Transform<scalar_of_t<A>>& xb) {
  return transform_tolerance(a, xa) + transform_tolerance(b, xb);
}

/// The error unit of the transformed pair's rounded outputs: rounding_tolerance() of the world
/// images (S their largest coordinate) plus transform_tolerance() of each.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Calc rounding_tolerance(const A& a,
                                                                                const Transform<scalar_of_t<A>>& xa,
                                                                                const B& b,
                                                                                const Transform<scalar_of_t<A>>& xb) {
  const Calc s = std::max(detail::scale_of(bounds(a, xa)), detail::scale_of(bounds(b, xb)));
  return kOverlapErrorFactor * kUnitRoundoff * s + kAbsoluteFloor + overlap_tolerance(a, xa, b, xb);
}

/// Conservative world bounding box of s placed by x: it contains the exact image (the computed
/// image's box padded by transform_tolerance(s, x), rounded outward to T). bounds(s) for the identity.
template <AnyShape S>
Aabb<scalar_of_t<S>> bounds(const S& s, const Transform<scalar_of_t<S>>& x) {
  using T = scalar_of_t<S>;
  if (x.is_identity()) return bounds(s);
  return detail::visit_shape(s, [&](const auto& c) {
    const Calc tol = detail::image_tolerance_of(c, x);
    const Aabb<Calc> b = detail::placed_box(c, x);
    return bounds_from_calc<T>((b.min().array() - tol).matrix(), (b.max().array() + tol).matrix());
  });
}

/// overlaps() of a placed by xa and b placed by xb. Exact outside the band overlap_tolerance(a, xa,
/// b, xb); equal to overlaps(a, b) for identities. Symmetric to the bit.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>>
bool overlaps(const A& a, const Transform<scalar_of_t<A>>& xa, const B& b, const Transform<scalar_of_t<A>>& xb) {
  if (xa.is_identity() && xb.is_identity()) return overlaps(a, b);
  return detail::with_placed_pair(a, xa, b, xb,
                                  [](const auto& pa, const auto& pb) { return detail::overlaps_concrete(pa, pb); });
}

/// contact() of the placed shapes, in world space: present exactly when overlaps(a, xa, b, xb).
/// Extra arguments are those of the world-space contact(), passed on. Error: the world-space
/// bound with rounding_tolerance(a, xa, b, xb) as its unit.
template <AnyShape A, AnyShape B, class... Extra>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> std::optional<Contact<scalar_of_t<A>>> contact(
    const A& a, const Transform<scalar_of_t<A>>& xa, const B& b, const Transform<scalar_of_t<A>>& xb,
    const Extra&... extra) {
  using T = scalar_of_t<A>;
  if (xa.is_identity() && xb.is_identity()) return detail::contact_as<T>(a, b, extra...);
  const Calc speculative = detail::speculative_distance(T(extra...));  // T() = 0 without one
  return detail::visit_shapes(a, b, [&](const auto& ca, const auto& cb) {
    std::optional<Contact<T>> out;
    const detail::LocalContact local = detail::contact_local(ca, xa.pose(), cb, xb.pose(), speculative);
    if (local.decided) {
      if (local.contact) detail::round_into(*local.contact, out);
      return out;
    }
    const std::optional<detail::CoreContact> c =
        detail::with_placed_both(ca, xa, cb, xb, [&](const auto& pa, const auto& pb) {
          const auto images = [&] { return detail::image_rounding(ca, xa) + detail::image_rounding(cb, xb); };
          const bool beyond = detail::has_faces(pa) && detail::has_faces(pb) &&
                              (detail::rounds_beyond_image(ca, xa) || detail::rounds_beyond_image(cb, xb));
          std::optional<detail::CoreContact> found =
              detail::contact_concrete(pa, pb, speculative, beyond ? detail::Rounding(images) : detail::Rounding());
          if (found) {
            detail::name_placed_features(ca, pa, xa, *found, false);
            detail::name_placed_features(cb, pb, xb, *found, true);
          }
          return found;
        });
    if (c) detail::round_into(*c, out);
    return out;
  });
}

namespace detail {

/// The per-axis magnitudes that moving a placed by xa rounds to T: the largest absolute x and y of
/// bounds(a, xa) and of xa's position (Transform::moved rounds the position).
template <AnyShape A>
Vec2c placed_moved_scale(const A& a, const Transform<scalar_of_t<A>>& xa) {
  return axis_scale(bounds(a, xa)).cwiseMax(Vec2c(widen(xa.position()).cwiseAbs()));
}

}  // namespace detail

/// The margin resolve(a, xa, b, xb) adds when it pushes along -normal (at most this):
/// resolve_margin()'s formula on the world images, with S_x and S_y the larger of bounds(a, xa)'s
/// coordinates and of xa's position on each axis (the move rounds the position to T), plus
/// 2 (transform_tolerance(a, xa) + transform_tolerance(b, xb)) (the depth is computed on one image
/// and the moved shape is another). resolve_margin(a, b, depth, normal) for two identities.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Calc
resolve_margin(const A& a, const Transform<scalar_of_t<A>>& xa, const B& b, const Transform<scalar_of_t<A>>& xb,
               Calc depth, const Vec2<scalar_of_t<A>>& normal) {
  if (xa.is_identity() && xb.is_identity()) return resolve_margin(a, b, depth, normal);
  const Vec2c sa = detail::placed_moved_scale(a, xa);
  const Calc s = std::max(sa.maxCoeff(), detail::scale_of(bounds(b, xb)));
  return detail::margin_of<scalar_of_t<A>>(s, detail::moved_along(sa, widen(normal)), depth) +
         2 * overlap_tolerance(a, xa, b, xb);
}

/// resolve_margin(a, xa, b, xb, depth, normal) for the worst direction (S_x + S_y in place of
/// |n_x| S_x + |n_y| S_y): at least the margin of every push direction.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Calc resolve_margin(
    const A& a, const Transform<scalar_of_t<A>>& xa, const B& b, const Transform<scalar_of_t<A>>& xb, Calc depth) {
  if (xa.is_identity() && xb.is_identity()) return resolve_margin(a, b, depth);
  const Vec2c sa = detail::placed_moved_scale(a, xa);
  const Calc s = std::max(sa.maxCoeff(), detail::scale_of(bounds(b, xb)));
  return detail::margin_of<scalar_of_t<A>>(s, detail::moved_along(sa, Vec2c(1, 1)), depth) +
         2 * overlap_tolerance(a, xa, b, xb);
}

/// The world-space push that separates a (placed by xa) from b (placed by xb): a's transform
/// moved by it (Transform::moved) no longer overlaps. Zero when they do not overlap. Margin: at most
/// resolve_margin(a, xa, b, xb, depth, normal); tested by moving a's transform only for polygons and
/// compounds, as resolve() does.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Vec2<scalar_of_t<A>> resolve(
    const A& a, const Transform<scalar_of_t<A>>& xa, const B& b, const Transform<scalar_of_t<A>>& xb) {
  using T = scalar_of_t<A>;
  if (xa.is_identity() && xb.is_identity()) return resolve(a, b);
  const Calc extra = 2 * overlap_tolerance(a, xa, b, xb);
  return detail::visit_shape(a, [&](const auto& ca) {
    return detail::with_placed(ca, xa, [&](const auto& pa) {
      return detail::visit_shape(b, [&](const auto& cb) {
        return detail::with_placed(cb, xb, [&](const auto& pb) {
          const Vec2c s_moved =
              detail::axis_scale(detail::calc_bounds(pa)).cwiseMax(Vec2c(widen(xa.position()).cwiseAbs()));
          const auto still = [&](const Vec2<T>& v) -> std::optional<bool> {
            const Expected<Transform<T>> moved = xa.moved(v);
            if (!moved) return std::nullopt;
            return detail::with_placed(ca, *moved, [&](const auto& m) { return detail::overlaps_concrete(m, pb); });
          };
          return detail::resolve_as<T>(pa, pb, s_moved, extra, still);
        });
      });
    });
  });
}

/// distance() of the placed shapes: 0 exactly when overlaps(a, xa, b, xb), otherwise the gap, at
/// least the smallest positive T. Error: within a few rounding_tolerance(a, xa, b, xb) of the
/// exact images' gap.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> scalar_of_t<A> distance(const A& a,
                                                                                const Transform<scalar_of_t<A>>& xa,
                                                                                const B& b,
                                                                                const Transform<scalar_of_t<A>>& xb) {
  using T = scalar_of_t<A>;
  if (xa.is_identity() && xb.is_identity()) return distance(a, b);
  return detail::with_placed_pair(a, xa, b, xb,
                                  [](const auto& pa, const auto& pb) { return detail::distance_as<T>(pa, pb); });
}

/// The error bound of closest_points(a, xa, b, xb): closest_points_tolerance()'s formula with
/// rounding_tolerance(a, xa, b, xb) as its unit and S from the placed boxes.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> Calc closest_points_tolerance(
    const A& a, const Transform<scalar_of_t<A>>& xa, const B& b, const Transform<scalar_of_t<A>>& xb) {
  const Calc s = std::max(detail::scale_of(bounds(a, xa)), detail::scale_of(bounds(b, xb)));
  return detail::witness_tolerance<scalar_of_t<A>>(rounding_tolerance(a, xa, b, xb), s);
}

/// closest_points() of the placed shapes, in world space: the distance is distance(a, xa, b, xb)
/// bit for bit, and the points are as closest_points(a, b) gives them for the computed images.
/// Error: closest_points_tolerance(a, xa, b, xb) against the exact images.
template <AnyShape A, AnyShape B>
requires std::is_same_v<scalar_of_t<A>, scalar_of_t<B>> ClosestPoints<scalar_of_t<A>> closest_points(
    const A& a, const Transform<scalar_of_t<A>>& xa, const B& b, const Transform<scalar_of_t<A>>& xb) {
  using T = scalar_of_t<A>;
  if (xa.is_identity() && xb.is_identity()) return closest_points(a, b);
  return detail::with_placed_pair(a, xa, b, xb,
                                  [](const auto& pa, const auto& pb) { return detail::closest_as<T>(pa, pb); });
}

/// signed_distance_tolerance() for s placed by x: its formula on bounds(s, x), plus
/// transform_tolerance(s, x).
template <AnyShape S>
Calc signed_distance_tolerance(const S& s, const Transform<scalar_of_t<S>>& x, const Vec2<scalar_of_t<S>>& p) {
  if (x.is_identity()) return signed_distance_tolerance(s, p);
  return detail::point_distance_tolerance(bounds(s, x), p) + transform_tolerance(s, x);
}

/// signed_distance() for s placed by x: on the computed image, so that its sign is contains(s, x,
/// p)'s exactly. Error: signed_distance_tolerance(s, x, p) against the exact image.
template <AnyShape S>
scalar_of_t<S> signed_distance(const S& s, const Transform<scalar_of_t<S>>& x, const Vec2<scalar_of_t<S>>& p) {
  using T = scalar_of_t<S>;
  if (x.is_identity()) return signed_distance(s, p);
  const Vec2c v = widen(p);
  return detail::visit_shape(s, [&](const auto& c) {
    return detail::with_placed(c, x, [&](const auto& img) { return detail::signed_distance_as<T>(img, v); });
  });
}

/// contains() for s placed by x: exact for the computed image, so exact for the exact image
/// except for points within transform_tolerance(s, x) of its boundary. NaN gives false.
template <AnyShape S>
bool contains(const S& s, const Transform<scalar_of_t<S>>& x, const Vec2<scalar_of_t<S>>& p) {
  if (x.is_identity()) return contains(s, p);
  const Vec2c q = widen(p);
  if (!std::isfinite(q.x()) || !std::isfinite(q.y())) return false;
  return detail::visit_shape(s, [&](const auto& c) {
    return detail::with_placed(c, x, [&](const auto& img) { return detail::contains_concrete(img, q); });
  });
}

/// raycast_tolerance() for s placed by x: that of the image, plus transform_tolerance(s, x).
template <AnyShape S>
Calc raycast_tolerance(const S& s, const Transform<scalar_of_t<S>>& x, const Ray<scalar_of_t<S>>& ray) {
  return detail::ray_tolerance(bounds(s, x), ray) + transform_tolerance(s, x);
}

/// raycast() against s placed by x, in world space (the ray is a world ray). Error: as raycast()
/// with raycast_tolerance(s, x, ray).
template <AnyShape S>
std::optional<RayHit<scalar_of_t<S>>> raycast(const S& s, const Transform<scalar_of_t<S>>& x,
                                              const Ray<scalar_of_t<S>>& ray, scalar_of_t<S> max_t) {
  using T = scalar_of_t<S>;
  if (x.is_identity()) return raycast(s, ray, max_t);
  return detail::visit_shape(s, [&](const auto& c) {
    return detail::with_placed(c, x, [&](const auto& img) { return detail::raycast_as<T>(img, ray, max_t); });
  });
}

}  // namespace collide
