// Fuzz target resolve: pairs of shapes, mostly overlapping; v = resolve(a, b) must separate them
// according to the exact oracle, and for two primitives |v| must not exceed the exact penetration
// depth plus resolve_margin (law "resolution").
//
// Input: flags byte (bit 0: double; bit 1: first move b so that its bounding-box center lies on
// a's, which makes most pairs overlap deeply), shape a, shape b.

#include "collide/fuzz/pair_target.hpp"
#include "collide/laws/laws.hpp"
#include "collide/oracle/oracle.hpp"

#include <cstddef>
#include <cstdint>

namespace {

using namespace collide;
using namespace collide::fuzz;

template <Scalar T>
Vec2<T> box_center(const Shape<T>& s) {
  const Aabb<T> b = bounds(s);
  return ((widen(b.min()) + widen(b.max())) * 0.5).template cast<T>();
}

template <class F>
void decode_case(Reader& r, F&& f) {
  with_pair(r, [&](const PairHeader& h, const auto& a, const auto& b, Reader&) {
    if ((h.bits & 2) == 0) {
      f(a, b);
      return;
    }
    const auto moved = translated(b, Vec2<scalar_of_t<decltype(a)>>(box_center(a) - box_center(b)));
    if (moved) f(a, moved.value());
  });
}

template <Scalar T>
void check(const Shape<T>& a, const Shape<T>& b) {
  if (!overlaps(a, b)) {
    // Nothing to resolve: the move must be exactly zero.
    if (resolve(a, b) != Vec2<T>::Zero()) require(laws::Law::Resolution, laws::resolution(a, b), a, some(b));
    return;
  }
  try {
    require(laws::Law::Resolution, laws::resolution(a, b), a, some(b));
  } catch (const oracle::Unsupported&) {
    // the oracle cannot judge this pair exactly: not judged
  }
}

}  // namespace

COLLIDE_PAIR_FUZZ_TARGET(decode_case, check)
