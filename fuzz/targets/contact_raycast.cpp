// Fuzz target contact_raycast: contact(), distance(), closest_points(), raycast() and
// signed_distance() against the exact oracle (laws "contact", "distance", "closest_points",
// "raycast" and "signed_distance", the ray's origin as the point). Shapes placed by transforms: the
// same queries with transforms judged on the exact images (laws "placed_outputs",
// "placed_separation", "placed_feature_ids", "placed_speculative" and "placed_shape", the ray's
// origin as the point for contains() and signed_distance()).
//
// Input: flags byte (bit 0: double; bit 6: a transform follows each shape), shape a [xa], shape b
// [xb], then a ray cast at a: origin x y, direction x y, max_t (raw bit patterns of the scalar).

#include "collide/fuzz/pair_target.hpp"
#include "collide/laws/laws.hpp"
#include "collide/oracle/oracle.hpp"
#include "collide/raycast.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace {

using namespace collide;
using namespace collide::fuzz;

template <Scalar T>
struct RayCase {
  Ray<T> ray;
  T max_t;
};

template <Scalar T>
RayCase<T> read_ray(Reader& r) {
  r.set_group(2);
  const Vec2<T> origin = r.point<T>();
  r.set_group(3);
  const T dx = r.scalar<T>(Role::Other);
  const T dy = r.scalar<T>(Role::Other);
  const T max_t = r.scalar<T>(Role::Size);
  return {{origin, Vec2<T>(dx, dy)}, max_t};
}

/// Calls f(a, xa, b, xb, ray) with a valid pair and the ray read after it (the ray may be
/// invalid: the law expects the library's named rejection then).
template <class F>
void decode_case(Reader& r, F&& f) {
  with_placed_pair(r,
                   [&](const PairHeader&, const auto& a, const auto& xa, const auto& b, const auto& xb, Reader& rest) {
                     using T = scalar_of_t<std::remove_cvref_t<decltype(a)>>;
                     f(a, xa, b, xb, read_ray<T>(rest));
                   });
}

template <Scalar T>
bool valid_ray(const RayCase<T>& r) {
  return r.ray.origin.allFinite() && r.ray.direction.allFinite() && std::isfinite(r.max_t) && r.max_t >= T(0) &&
         r.ray.origin.cwiseAbs().maxCoeff() <= max_magnitude<T>() &&
         r.ray.direction.cwiseAbs().maxCoeff() <= max_magnitude<T>() && r.max_t <= max_magnitude<T>();
}

template <Scalar T>
void check(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb,
           const RayCase<T>& ray) {
  const bool placed = !xa.is_identity() || !xb.is_identity();
  try {
    if (placed) {
      require_placed("placed_outputs", laws::placed_outputs(a, xa, b, xb), a, xa, some(b), xb);
      require_placed("placed_separation", laws::placed_separation(a, xa, b, xb), a, xa, some(b), xb);
      require_placed("placed_feature_ids", laws::placed_feature_ids(a, xa, b, xb), a, xa, some(b), xb);
      require_placed("placed_speculative", laws::placed_speculative(a, xa, b, xb), a, xa, some(b), xb);
    } else {
      require(laws::Law::Contact, laws::contact_law(a, b), a, some(b));
      require(laws::Law::Distance, laws::distance_law(a, b), a, some(b));
      require(laws::Law::ClosestPoints, laws::closest_points_law(a, b), a, some(b));
    }
  } catch (const oracle::Unsupported&) {
    // not judged
  }
  const bool finite = ray.ray.origin.allFinite() && ray.ray.direction.allFinite() && std::isfinite(ray.max_t);
  if (!finite || ray.max_t < T(0)) {
    // Documented: a NaN or infinite value, or max_t < 0, gives no hit.
    if (raycast(a, xa, Ray<T>{ray.ray.origin, ray.ray.direction}, ray.max_t)) {
      fail_raw("raycast with a non-finite value or a negative max_t returned a hit");
    }
    return;
  }
  if (!valid_ray(ray)) {
    // Beyond max_magnitude: not covered by the error contract, but the answer must be sane.
    const auto hit = raycast(a, xa, Ray<T>{ray.ray.origin, ray.ray.direction}, ray.max_t);
    if (hit && !(hit->t >= T(0) && hit->t <= ray.max_t)) fail_raw("raycast returned t outside [0, max_t]");
    return;
  }
  try {
    if (placed) {
      require_placed("placed_shape", laws::placed_shape(a, xa, ray.ray.origin, ray.ray, ray.max_t), a, xa);
      return;
    }
    // The ray's origin as a point: its signed distance to a.
    const laws::Verdict sd = laws::signed_distance_law(a, ray.ray.origin);
    if (!sd.ok) {
      fail(laws::Law::SignedDistance, a, std::optional<Shape<T>>(), sd, [&](laws::Case& c) {
        c.px = ray.ray.origin.x();
        c.py = ray.ray.origin.y();
      });
    }
    const laws::Verdict v = laws::raycast_law(a, ray.ray, ray.max_t);
    if (!v.ok) {
      std::fprintf(stderr, "  ray origin %s direction %s max_t %s\n", format_point(widen(ray.ray.origin)).c_str(),
                   format_point(widen(ray.ray.direction)).c_str(), format_value(ray.max_t).c_str());
      fail(laws::Law::Raycast, a, std::optional<Shape<T>>(), v, [&](laws::Case& c) {
        c.ox = ray.ray.origin.x();
        c.oy = ray.ray.origin.y();
        c.dx = ray.ray.direction.x();
        c.dy = ray.ray.direction.y();
        c.max_t = ray.max_t;
      });
    }
  } catch (const oracle::Unsupported&) {
    // not judged
  }
}

}  // namespace

COLLIDE_PLACED_PAIR_EXTRA_FUZZ_TARGET(decode_case, check)
