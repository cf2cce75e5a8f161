// Fuzz target judge_course_notes: the course notes' reference code (course_notes.hpp) through
// its in-process adapter, each answer judged exactly (judge_target.hpp says what a finding is).
//
// The notes keep deliberate slips, which is what they are kept for: the box test compares a y
// with an x, and the box resolution returns the vector reversed (the third, touching circles
// called apart, is a touching-level wrong answer, never a finding). A target that stopped at
// them would stop within seconds and find nothing else, and its seed replay would fail for
// ever; so their classes are measurements here, as are the limits of the notes' formulas at
// subnormal scales (below), and only another class or a crash is a finding. COLLIDE_JUDGE_FUZZ_SLIPS=1 makes them
// findings too: ctest fuzz.seeds.judge_course_notes.slips checks that the seeds then find one.
//
// Input: flags byte (bit 0: double values, else float), shape a, shape b
// (collide/fuzz/decode.hpp); kinds other than circle and aabb are skipped.

#include "course_notes/course_notes_adapter.hpp"
#include "judge_target.hpp"

namespace {

using collide::judge::fuzz_target::decode_case;

collide::judge::fuzz_target::Target<collide::judge::CourseNotesAdapter> g_target({
    "wrong.false_overlap.gross.aabb_aabb",        // the box test: b.max.y < a.min.x
    "wrong.false_apart.gross.aabb_aabb",          // the same comparison, the other way
    "wrong.push_leaves_overlap.gross.aabb_aabb",  // the box resolution, its sign reversed
    // The notes' formulas as written: squared distances underflow for circles below about
    // 2^-511 (apart), and a push divides by a distance that is 0 or subnormal (not finite).
    "wrong.false_apart.gross.circle_circle",
    "crash.non_finite_push.",
});

template <collide::Scalar T>
void check(const collide::Shape<T>& a, const collide::Shape<T>& b) {
  g_target.check(a, b);
}

}  // namespace

COLLIDE_PAIR_FUZZ_TARGET(decode_case, check)
