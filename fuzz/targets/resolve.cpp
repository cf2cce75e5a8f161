// Fuzz target resolve: pairs of shapes, mostly overlapping; v = resolve(a, b) must separate them
// according to the exact oracle, and for two primitives |v| must not exceed the exact penetration
// depth plus resolve_margin (law "resolution"). Shapes placed by transforms: resolve(a, xa, b, xb)
// judged on the exact images (law "placed_resolution").
//
// Input: flags byte (bit 0: double; bit 1: first move b so that its bounding-box center lies on
// a's, which makes most pairs overlap deeply; bit 6: a transform follows each shape), shape a
// [xa], shape b [xb].

#include "collide/fuzz/pair_target.hpp"
#include "collide/laws/laws.hpp"
#include "collide/oracle/oracle.hpp"

#include <cstddef>
#include <cstdint>

namespace {

using namespace collide;
using namespace collide::fuzz;

template <Scalar T>
Vec2<T> box_center(const Aabb<T>& b) {
  return ((widen(b.min()) + widen(b.max())) * 0.5).template cast<T>();
}

/// With flags bit 1, b (its transform when placed, else its values) moved so that the centres of
/// the placed bounding boxes meet; nothing when the move has no representation.
template <class F>
void decode_case(Reader& r, F&& f) {
  with_placed_pair(r, [&](const PairHeader& h, const auto& a, const auto& xa, const auto& b, const auto& xb, Reader&) {
    using T = scalar_of_t<std::remove_cvref_t<decltype(a)>>;
    if ((h.bits & 2) == 0) {
      f(a, xa, b, xb);
      return;
    }
    const Vec2<T> v = box_center(bounds(a, xa)) - box_center(bounds(b, xb));
    if (!xb.is_identity()) {
      if (const auto moved = xb.moved(v)) f(a, xa, b, moved.value());
      return;
    }
    if (const auto moved = translated(b, v)) f(a, xa, moved.value(), xb);
  });
}

template <Scalar T>
void check(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb) {
  const bool placed = !xa.is_identity() || !xb.is_identity();
  // Nothing to resolve: the move must be exactly zero (the law checks it); otherwise the law.
  if (!overlaps(a, xa, b, xb) && resolve(a, xa, b, xb) == Vec2<T>::Zero()) return;
  try {
    if (placed) {
      require_placed("placed_resolution", laws::placed_resolution(a, xa, b, xb), a, xa, some(b), xb);
    } else {
      require(laws::Law::Resolution, laws::resolution(a, b), a, some(b));
    }
  } catch (const oracle::Unsupported&) {
    // the oracle cannot judge this pair exactly: not judged
  }
}

}  // namespace

COLLIDE_PLACED_PAIR_FUZZ_TARGET(decode_case, check)
