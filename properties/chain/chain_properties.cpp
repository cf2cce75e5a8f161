/// The laws of chain contacts (collide/chain.hpp, the law table's Chain suite: laws.hpp), for
/// both scalars: one GoogleTest test per law and scalar, each checked by RapidCheck on random
/// chains (open and loops, flat runs with bumps and free zigzags) against every kind, in
/// world space or placed by a transform, with and without a speculative distance; every segment of
/// a chain is judged. A counterexample is saved as a case file (tests/regressions). Depth:
/// RC_PARAMS (ctest: 2,000 cases per law and scalar, seed 1).

#include "collide/chain.hpp"
#include "collide/laws/case_file.hpp"
#include "collide/laws/laws.hpp"
#include "generators.hpp"
#include "law_tests.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace collide::props {
namespace {

/// What the laws judged, printed at the end, so that a run shows they were not vacuous.
struct Stats {
  long segments = 0, face = 0, corner = 0, behind = 0, completeness = 0, compound = 0;
};
Stats g_stats;

/// One case: a chain, a shape (a compound one time in five) placed by a transform (the identity
/// half the time) and a speculative distance.
template <Scalar T>
struct Case {
  Chain<T> chain;
  Shape<T> shape;
  Transform<T> x;
  T speculative;
};

template <Scalar T>
Case<T> gen_case() {
  using V = Vec2<T>;
  const double s = *rc::gen::element(1.0, 1.0 / 64, 1024.0);
  const bool loop = *rc::gen::arbitrary<bool>();
  const int n = *rc::gen::inRange(loop ? 3 : 4, 9);
  const bool floor = *rc::gen::inRange(0, 3) != 0;
  std::vector<V> pts;
  for (int i = 0; i < n; ++i) {
    if (floor) {
      // A floor running right to left, mostly flat, with bumps up and down.
      const int bump = *rc::gen::inRange(0, 4) == 0 ? *rc::gen::inRange(-3, 4) : 0;
      pts.push_back(V(T((16 - 4 * i) * s), T(bump * s)));
    } else {
      pts.push_back(V(T(grid(-16, 16) * s), T(grid(-16, 16) * s)));
    }
  }
  Expected<Chain<T>> chain = Chain<T>::make(pts, loop);
  RC_PRE(chain.has_value());
  const T speculative = *rc::gen::inRange(0, 3) == 0 ? T(grid(1, 4) * s) : T(0);
  const Transform<T> x = *rc::gen::arbitrary<bool>() ? Transform<T>() : gen_transform<T>(s);
  Shape<T> shape = *rc::gen::inRange(0, 5) == 0
                       ? gen_shape<ShapeKind::Compound, T>(s)
                       : std::visit([](const auto& p) { return Shape<T>(p); }, gen_any_primitive<T>(s));
  return {std::move(chain).value(), std::move(shape), x, speculative};
}

template <Scalar T>
using ChainLaw = laws::Verdict (*)(const ChainSegment<T>&, const Shape<T>&, const Transform<T>&, T);

/// The law's function, or nullptr for a law of another suite.
template <Scalar T>
ChainLaw<T> chain_law(laws::Law law) {
  switch (law) {
    case laws::Law::ChainAdmissible:
      return laws::chain_admissible<T>;
    case laws::Law::ChainOneSided:
      return laws::chain_one_sided<T>;
    case laws::Law::ChainSurfaces:
      return laws::chain_surfaces<T>;
    case laws::Law::ChainPresent:
      return laws::chain_present<T>;
    case laws::Law::ChainFaceComplete:
      return laws::chain_face_complete<T>;
    case laws::Law::ChainFaceIds:
      return laws::chain_face_ids<T>;
    default:
      return nullptr;
  }
}

/// Counts what a segment's answer shows: a face or corner contact, a shape behind the front.
template <Scalar T>
void count(const Case<T>& k, const ChainSegment<T>& seg) {
  ++g_stats.segments;
  const std::optional<Contact<T>> c = contact(seg, k.shape, k.x, k.speculative);
  const Vec2c a = widen(seg.a()), b = widen(seg.b()), n = Vec2c(b.y() - a.y(), a.x() - b.x()).normalized();
  if (c) ++((widen(c->normal) - n).norm() <= 1e-4 ? g_stats.face : g_stats.corner);
  if (c && std::holds_alternative<Compound<T>>(k.shape)) ++g_stats.compound;
  const Vec2c ref = std::visit(
      [&](const auto& s) {
        if constexpr (::collide::detail::is_compound_v<decltype(s)>) {
          return a;
        } else if (k.x.is_identity()) {
          return ::collide::detail::reference_point(s);
        } else {
          return ::collide::detail::with_placed(s, k.x,
                                                [](const auto& p) { return ::collide::detail::reference_point(p); });
        }
      },
      k.shape);
  if (orient(a, b, ref) > 0) ++g_stats.behind;
}

/// The property of a chain law: every segment of a generated case judged, the first failure kept
/// as a case.
template <Scalar T>
std::function<void()> property_of(laws::Law law, const std::string& test) {
  const ChainLaw<T> judge = chain_law<T>(law);
  if (judge == nullptr) return {};
  return [=] {
    const Case<T> k = gen_case<T>();
    for (std::size_t i = 0; i < k.chain.size(); ++i) {
      const ChainSegment<T> seg = k.chain.segment(i);
      count(k, seg);
      const laws::Verdict v = judge(seg, k.shape, k.x, k.speculative);
      if (v.ok && v.account.starts_with("claimed")) ++g_stats.completeness;
      judge_case(v, [&] {
        return laws::make_chain_case<T>(law, seg, k.shape, k.x, k.speculative, v,
                                        "property " + test + " " + seed_text());
      });
    }
  };
}

}  // namespace

/// Every law of the Chain suite (law_tests.hpp); each test saves its shrunk counterexample.
void register_all() {
  register_saving_suite(
      laws::LawSuite::Chain,
      []<Scalar T>(laws::Law law, ShapeKind, ShapeKind, const std::string& test) { return property_of<T>(law, test); },
      [](const std::function<void()>& property) { ::rc::detail::checkGTest(property); });
}

}  // namespace collide::props

/// Runs the laws, then prints what they judged: a run that judged nothing proves nothing.
int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  collide::props::register_all();
  const int failed = RUN_ALL_TESTS();
  const collide::props::Stats& s = collide::props::g_stats;
  std::printf(
      "chain laws judged %ld segments: %ld face contacts, %ld corner contacts, %ld contacts of compounds, %ld "
      "shapes behind, %ld completeness claims\n",
      s.segments, s.face, s.corner, s.compound, s.behind, s.completeness);
  return failed;
}
