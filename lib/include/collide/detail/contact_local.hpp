#pragma once
/// @file detail/contact_local.hpp
/// Contacts of placed shapes computed in one shape's local frame, where that saves imaging it: a
/// circle against a polygon turned by a general rotation maps the circle's centre into the
/// polygon's frame instead of mapping every vertex and normal of the polygon into the world.
///
/// The answer must stay that of the computed images (transformed.hpp: contact() is exact on
/// them), so the local gap decides only when it is clear of a band covering both the local
/// computation's rounding and the images' distance from the exact images (image_tolerance()).
/// Otherwise, and in every rare case, the caller images both shapes as usual. Quarter turns and
/// translations keep the image path, whose answers they keep exactly (the transform laws).

#include "collide/detail/contact_pairs.hpp"
#include "collide/detail/image.hpp"
#include "collide/shapes.hpp"
#include "collide/transform.hpp"

#include <algorithm>
#include <array>
#include <optional>

namespace collide::detail {

/// A contact computed in a local frame: decided (the contact, or none), or left to the images.
struct LocalContact {
  bool decided = false;
  std::optional<CoreContact> contact;
};

/// Circle a placed by xa against polygon b placed by xb, in b's frame. With xb = (p, q) and
/// g = |q|^2, the circle's image centre c_w has the local preimage R(q)^T (c_w - p) / g, and the
/// exact image of b is b scaled by |q|, turned and moved, so every signed distance in the world
/// is |q| times the local one. The local values carry a few roundings of their scale and of
/// |c_w - p| (band_of() of their sum covers both); the computed image of b lies within
/// image_tolerance() of its exact image, which the band adds. The face normals in the world are
/// the image's (b's cached normals turned by q / |q|, as with_image() turns them), the closest
/// vertex is the image's vertex, so a decided contact has the image path's features.
template <Scalar T>
LocalContact contact_circle_polygon_local(const Circle<T>& a, const Pose& xa, const ConvexPolygon<T>& b, const Pose& xb,
                                          Calc speculative) {
  const Vec2c* normals = PolygonAccess::normals(b);
  if (!normals || xb.q.x() == 0 || xb.q.y() == 0) return {};
  const Calc extent = PolygonAccess::largest_coordinate(b);
  const Calc image_band = image_tolerance(xb, extent);
  // A polygon whose image may turn right somewhere is imaged as the hull of its rounded vertices.
  if (!(PolygonAccess::turn_margin(b) > image_band)) return {};
  const Vec2c cw = image_point(xa, widen(a.center()));  // the circle's image centre, as with_image() maps it
  const Calc r = a.radius();
  const Vec2c rel = cw - xb.p;
  const Calc g = xb.q.squaredNorm(), k = inverse_norm_near_unit(g), len = g * k;  // 1 / |q| and |q|
  const Vec2c c = Vec2c(xb.q.x() * rel.x() + xb.q.y() * rel.y(), xb.q.x() * rel.y() - xb.q.y() * rel.x()) * (k * k);
  const Calc own = std::max(c.cwiseAbs().maxCoeff(), r), scale = std::max(own, extent);
  const Calc values = scale + rel.cwiseAbs().maxCoeff();
  if (!(scale >= kTinyCore && values <= kPlainNormHigh)) return {};
  const Calc band = band_of(values) + image_band;
  const std::size_t m = b.size();
  std::array<Calc, ConvexPolygon<T>::kInline> excesses{};
  for (std::size_t i = 0; i < m; ++i) excesses[i] = (c - widen(b[i])).dot(normals[i]);
  const auto [face, local_excess] = face_of_largest_excess(b, excesses.data(), own);
  const Calc excess = local_excess * len, reach = r + std::max(speculative, Calc(0));
  if (excess > reach + band) return {true, std::nullopt};
  const auto turned = [&](unsigned i) {  // the image's normal of face i (with_image())
    const Calc cq = xb.q.x() * k, sq = xb.q.y() * k, nx = normals[i].x(), ny = normals[i].y();
    return Vec2c(cq * nx - sq * ny, sq * nx + cq * ny);
  };
  if (!(local_excess > 0)) {
    if (!(excess - r < -band) || projects_beyond_face(b, c, face, band)) return {};
    return {true, circle_contact_inside(cw, r, turned(face), excess, face)};
  }
  const std::optional<CoreFeature> feature = feature_beyond_face(b, c, face);
  if (!feature) return {};
  const Vec2c n_face = turned(face);
  const Vec2c on_q = feature->edge ? Vec2c(cw - n_face * excess) : image_point(xb, widen(b[feature->index]));
  const Calc dist = feature->edge ? excess : norm_of(on_q - cw), gap = dist - r;
  if (gap > reach + band) return {true, std::nullopt};
  if (!(gap < -band) || !(dist > band)) return {};
  return {true, circle_contact_from_closest(cw, r, on_q, dist, *feature, n_face)};
}

/// contact_circle_polygon_local() for a pair in either order (the other order: the same contact
/// seen from the polygon, as contact_primitives() turns it); every other pair is left to the images.
template <class A, class B>
LocalContact contact_local(const A& a, const Pose& xa, const B& b, const Pose& xb, Calc speculative) {
  using T = scalar_of_t<A>;
  if constexpr (std::is_same_v<A, Circle<T>> && std::is_same_v<B, ConvexPolygon<T>>) {
    return contact_circle_polygon_local(a, xa, b, xb, speculative);
  } else if constexpr (std::is_same_v<A, ConvexPolygon<T>> && std::is_same_v<B, Circle<T>>) {
    LocalContact out = contact_circle_polygon_local(b, xb, a, xa, speculative);
    if (out.contact) out.contact = reversed(*out.contact);
    return out;
  } else {
    return {};
  }
}

}  // namespace collide::detail
