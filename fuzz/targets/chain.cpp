// Fuzz target chain: contact(segment, b, xb, speculative) of one chain segment (collide/chain.hpp)
// against the exact oracle, through the six chain laws (the law table's Chain suite), a compound b
// through its children. An invalid speculative distance is not judged, but must give an answer
// without a crash.
//
// Input: a pair as every pair target reads it (flags byte, bit 0: double; bit 6: a transform after
// each shape), shape a, shape b, then the segment's neighbours: the point before a, the point after
// b, an options byte (bit 0: the segment owns the corner at its start, as the first segment of an
// open chain) and the speculative distance (raw bit patterns of the scalar). Shape a must be a
// capsule: its core is the segment (its radius and its transform are read and not used).

#include "collide/chain.hpp"
#include "collide/fuzz/pair_target.hpp"
#include "collide/laws/laws.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <variant>

namespace {

using namespace collide;
using namespace collide::fuzz;

template <Scalar T>
struct Neighbours {
  Vec2<T> before, after;
  bool owns_start;
  T speculative;
};

template <Scalar T>
Neighbours<T> read_neighbours(Reader& r) {
  r.set_group(2);
  const Vec2<T> before = r.point<T>();
  const Vec2<T> after = r.point<T>();
  r.set_group(3);
  const bool owns_start = (r.byte() & 1) != 0;
  return {before, after, owns_start, r.scalar<T>(Role::Size)};
}

/// Calls f(a, xa, b, xb, neighbours) with a valid pair and the neighbours read after it.
template <class F>
void decode_case(Reader& r, F&& f) {
  with_placed_pair(r,
                   [&](const PairHeader&, const auto& a, const auto& xa, const auto& b, const auto& xb, Reader& rest) {
                     using T = scalar_of_t<std::remove_cvref_t<decltype(a)>>;
                     f(a, xa, b, xb, read_neighbours<T>(rest));
                   });
}

/// The segment of a case: a capsule's core between the neighbours, made as a chain makes it (the
/// first segment of an open chain when it owns its start); a named error when the points refuse.
template <Scalar T>
Expected<ChainSegment<T>> segment_of(const Capsule<T>& core, const Neighbours<T>& n) {
  if (!n.owns_start) return ChainSegment<T>::make(n.before, core.a(), core.b(), n.after);
  const std::array<Vec2<T>, 4> points = {n.before, core.a(), core.b(), n.after};
  Expected<Chain<T>> chain = Chain<T>::make(points, false);
  if (!chain) return chain.error();
  return chain.value().segment(0);
}

template <Scalar T>
void check(const Shape<T>& a, const Transform<T>&, const Shape<T>& b, const Transform<T>& xb, const Neighbours<T>& n) {
  const Capsule<T>* core = std::get_if<Capsule<T>>(&a);
  if (core == nullptr) return;
  const Expected<ChainSegment<T>> made = segment_of(*core, n);
  if (!made) return;  // a named error: the factories' own laws are judged by shapes_from_bytes
  const ChainSegment<T>& s = made.value();
  const bool judged_spec = std::isfinite(n.speculative) && n.speculative >= T(0) && n.speculative <= max_magnitude<T>();
  if (!judged_spec) {
    // Not judged by the laws; any answer must be sane.
    const std::optional<Contact<T>> c = contact(s, b, xb, n.speculative);
    if (c && !(c->count >= 1 && c->count <= 2 && c->depth >= T(0)))
      fail_raw("chain contact with an unjudged speculative distance has ", c->count, " points and depth ",
               double(c->depth));
    return;
  }
  using Judge = laws::Verdict (*)(const ChainSegment<T>&, const Shape<T>&, const Transform<T>&, T);
  constexpr std::pair<laws::Law, Judge> kChainLaws[] = {
      {laws::Law::ChainAdmissible, laws::chain_admissible<T>},
      {laws::Law::ChainOneSided, laws::chain_one_sided<T>},
      {laws::Law::ChainSurfaces, laws::chain_surfaces<T>},
      {laws::Law::ChainPresent, laws::chain_present<T>},
      {laws::Law::ChainFaceComplete, laws::chain_face_complete<T>},
      {laws::Law::ChainFaceIds, laws::chain_face_ids<T>},
  };
  for (const auto& row : kChainLaws) {
    const laws::Law law = row.first;  // not a structured binding: clang 14 cannot capture one
    const laws::Verdict v = row.second(s, b, xb, n.speculative);
    if (v.ok) continue;
    fail(law, Shape<T>(s.as_capsule()), some(b), v,
         [&](laws::Case& c) { c = laws::make_chain_case<T>(law, s, b, xb, n.speculative, v, c.source); });
  }
}

}  // namespace

COLLIDE_PLACED_PAIR_EXTRA_FUZZ_TARGET(decode_case, check)
