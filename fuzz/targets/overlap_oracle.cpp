// Fuzz target overlap_oracle: two shapes of any kinds, float or double, decoded from raw bit
// patterns; overlaps() must equal the exact oracle's answer, touching included (law "agreement":
// every decision is exact), and must not depend on the argument order (law "symmetry"). Shapes
// placed by transforms: overlaps(a, xa, b, xb) against the exact images (law "placed_agreement").
//
// Input: flags byte (bit 0: double; bit 6: a transform follows each shape), shape a [xa], shape
// b [xb] (format in collide/fuzz/decode.hpp).

#include "collide/fuzz/pair_target.hpp"
#include "collide/laws/laws.hpp"
#include "collide/oracle/oracle.hpp"

#include <cstddef>
#include <cstdint>

namespace {

using namespace collide;
using namespace collide::fuzz;

template <class F>
void decode_case(Reader& r, F&& f) {
  with_placed_pair(r, placed_pair_only(f));
}

template <Scalar T>
void check(const Shape<T>& a, const Shape<T>& b) {
  // Fast path of the agreement law: the library and the oracle give the same answer. Only a
  // difference needs the law itself (and its account of the values).
  const bool got = overlaps(a, b);
  if (got != overlaps(b, a)) require(laws::Law::Symmetry, laws::symmetry(a, b), a, some(b));
  try {
    if (got == oracle::overlaps(a, b)) return;
  } catch (const oracle::Unsupported&) {
    return;  // a question the oracle cannot decide exactly is not judged
  }
  require(laws::Law::Agreement, laws::agreement(a, b), a, some(b));
}

template <Scalar T>
void check(const Shape<T>& a, const Transform<T>& xa, const Shape<T>& b, const Transform<T>& xb) {
  if (xa.is_identity() && xb.is_identity()) {
    check(a, b);
    return;
  }
  // Fast path of the placed agreement law, as above.
  const bool got = overlaps(a, xa, b, xb);
  bool judge = got != overlaps(b, xb, a, xa);
  try {
    judge = judge || got != oracle::overlaps(oracle::placed(a, xa), oracle::placed(b, xb));
  } catch (const oracle::Unsupported&) {
    return;
  }
  if (judge) require_placed("placed_agreement", laws::placed_agreement(a, xa, b, xb), a, xa, some(b), xb);
}

}  // namespace

COLLIDE_PLACED_PAIR_FUZZ_TARGET(decode_case, check)
