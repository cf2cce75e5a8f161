// Fuzz target judge_box2d: Box2D 2.4.1 (Debian libbox2d-dev) through its in-process adapter,
// each answer judged exactly (judge_target.hpp says what a finding is). Box2D documents no
// class of wrong answers, so every gross wrong answer and every crash is a finding.
//
// Input: flags byte (bit 0: double values, else float), shape a, shape b
// (collide/fuzz/decode.hpp); kinds the adapter does not build are skipped.

#include "box2d/box2d_adapter.hpp"
#include "judge_target.hpp"

namespace {

using collide::judge::fuzz_target::decode_case;

collide::judge::fuzz_target::Target<collide::judge::Box2dAdapter> g_target;

template <collide::Scalar T>
void check(const collide::Shape<T>& a, const collide::Shape<T>& b) {
  g_target.check(a, b);
}

}  // namespace

COLLIDE_PAIR_FUZZ_TARGET(decode_case, check)
