// Fuzz target overlap_oracle: two shapes of any kinds, float or double, decoded from raw bit
// patterns; overlaps() must equal the exact oracle's answer, touching included (law "agreement":
// every decision is exact), and must not depend on the argument order (law "symmetry").
//
// Input: flags byte (bit 0: double), shape a, shape b (format in collide/fuzz/decode.hpp).

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
  with_pair(r, pair_only(f));
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

}  // namespace

COLLIDE_PAIR_FUZZ_TARGET(decode_case, check)
