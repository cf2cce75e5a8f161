/// The property suite of world-space shapes: every law of the law table's Static suite, for every
/// pair of kinds from the registry and both scalars, as one GoogleTest test each (suite = law,
/// name = <pair>_<scalar>), checked by RapidCheck.
///
/// Per test it records the cases, their exact relation (RC_CLASSIFY), disagreements within the
/// band (a measurement: each one is judged exactly by its law, never counted against a limit) and
/// failures; with COLLIDE_PROPS_REPORT set, one JSON line per test is appended there.
/// A counterexample (RapidCheck's last, shrunk one) is saved as a case file + SVG under
/// COLLIDE_CASES_DIR (default: the source tree's tests/regressions).

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "collide/laws/case_file.hpp"
#include "collide/laws/codec.hpp"
#include "collide/laws/laws.hpp"
#include "generators.hpp"
#include "law_tests.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace collide::props {
namespace {

/// What one test saw.
struct Tally {
  long cases = 0;
  std::array<long, 4> relations{};
  long disagreements = 0;
  bool failed = false;
  std::optional<laws::Case> counterexample;  // the last failing input (after shrinking)

  void record(const laws::Verdict& v, bool classify) {
    if (failed) return;  // shrinking replays inputs: count only the search
    ++cases;
    if (classify) ++relations[static_cast<std::size_t>(v.relation)];
    if (v.disagreement) ++disagreements;
  }
};

Tally g_tally;

/// Checks a verdict inside a property: counts it, keeps the input when it fails, asserts.
template <Scalar T>
void judge(const laws::Verdict& v, laws::Law law, const std::string& pair, const Shape<T>& a,
           const std::optional<Shape<T>>& b, bool classify, const std::function<void(laws::Case&)>& extra = {}) {
  g_tally.record(v, classify);
  if (classify) RC_CLASSIFY(true, std::string(laws::name(v.relation)));
  if (v.disagreement) RC_TAG(std::string("disagreement"));
  if (!v.ok) {
    g_tally.failed = true;
    const std::string scalar = std::is_same_v<T, float> ? "float" : "double";
    laws::Case c = laws::make_case<T>(
        law, a, b, v, "property " + std::string(laws::name(law)) + " " + pair + " " + scalar + " " + seed_text());
    if (extra) extra(c);
    g_tally.counterexample = c;
  }
  if (!v.ok) RC_FAIL(v.account);
}

/// Saves the counterexample and writes the test's record.
void finish(const std::string& law, const std::string& pair, const std::string& scalar) {
  std::string saved;
  if (g_tally.counterexample) saved = save_counterexample(*g_tally.counterexample);
  const std::string report = env_or("COLLIDE_PROPS_REPORT", "");
  if (!report.empty()) {
    nlohmann::json record = {{"law", law},
                             {"pair", pair},
                             {"scalar", scalar},
                             {"cases", g_tally.cases},
                             {"disagreements", g_tally.disagreements},
                             {"failed", g_tally.failed},
                             {"case_file", saved}};
    for (std::size_t i = 0; i < 4; ++i)
      record[std::string(laws::name(static_cast<laws::Relation>(i)))] = g_tally.relations[i];
    std::ofstream out(report, std::ios::app);
    out << record.dump() << '\n';
  }
}

/// The fewest cases of a relation that a generator aiming at it with probability >= p gives in n
/// cases, except with probability below 1e-9 (binomial lower tail): a check at this count fails on
/// correct code about once in a billion runs, at any seed, yet fails for sure when a generator
/// stops producing that relation once n is large enough (n >= 400 for p = 5%).
long floor_count(long n, double p) {
  double cdf = 0;
  for (long k = 0; k <= n; ++k) {
    const double log_pmf = std::lgamma(double(n) + 1) - std::lgamma(double(k) + 1) - std::lgamma(double(n - k) + 1) +
                           double(k) * std::log(p) + double(n - k) * std::log1p(-p);
    cdf += std::exp(log_pmf);
    if (cdf > 1e-9) return k;
  }
  return n;
}

/// Each relation the generators aim at (at least 1 in 20 cases by construction: see generators.hpp)
/// appears at least floor_count(cases, 5%) times.
void expect_distribution(const std::string& what, const std::vector<laws::Relation>& aimed) {
  if (g_tally.failed) return;
  const long need = floor_count(g_tally.cases, 0.05);
  for (const laws::Relation r : aimed) {
    const long got = g_tally.relations[static_cast<std::size_t>(r)];
    EXPECT_GE(got, need) << what << ": relation '" << laws::name(r) << "' has " << got << " of " << g_tally.cases
                         << " cases (fewer than " << need << ", the 1e-9 quantile for a 5% share)";
  }
}

/// The property of `law` for the kinds ka and kb (kb is ka for the laws of one shape), as a
/// RapidCheck body; empty for a law of another suite (a law of this suite without one registers a
/// failing test that names it).
template <Scalar T>
std::function<void()> property_of(laws::Law law, ShapeKind ka, ShapeKind kb, const std::string& subject) {
  using laws::Law;
  auto simple = [=](laws::Verdict (*f)(const Shape<T>&, const Shape<T>&)) -> std::function<void()> {
    return [=] {
      const auto [a, b] = gen_pair<T>(ka, kb);
      judge<T>(f(a, b), law, subject, a, b, true);
    };
  };
  switch (law) {
    case Law::Agreement:
      return simple(&laws::agreement<T>);
    case Law::Symmetry:
      return simple(&laws::symmetry<T>);
    case Law::Resolution:
      return [=] {
        // A quarter of the pairs far across the axis they meet along (gen_pair's `across`).
        const bool across = *rc::gen::inRange(0, 4) == 0;
        const auto [a, b] = gen_pair<T>(ka, kb, std::nullopt, across);
        judge<T>(laws::resolution(a, b), law, subject, a, b, true);
      };
    case Law::Contact:
      return simple(&laws::contact_law<T>);
    case Law::Distance:
      return simple(&laws::distance_law<T>);
    case Law::Separation:
      return simple(&laws::manifold_separation<T>);
    case Law::FeatureIds:
      return simple(&laws::manifold_ids<T>);
    case Law::Resting:
      return simple(&laws::manifold_resting<T>);
    case Law::Speculative:
      return simple(&laws::manifold_speculative<T>);
    case Law::Mass:
      return [=] {
        // A shape as the other laws draw them (half of the polygons turned and moved far, or
        // slivers, so that their fans' products round); a density that keeps T's range, passes
        // it, or is bad (one in sixteen); a move and a placement at the shape's scale.
        const auto [a, b] = gen_pair<T>(ka, ka);
        const Shape<T> s = *rc::gen::arbitrary<bool>() ? gen_rounding_polygon(a) : a;
        const T top = std::numeric_limits<T>::max();
        const std::vector<T> densities = {T(1),     T(1),    T(0),     T(0.5),   T(7.75),   T(1000),  T(1e-3),
                                          T(1e-30), T(1e30), top / 64, T(1) / 3, T(2.5e-7), T(1) / 7, T(1) / 9};
        const std::vector<T> bad = {-T(1), -std::numeric_limits<T>::denorm_min(), std::numeric_limits<T>::quiet_NaN(),
                                    std::numeric_limits<T>::infinity()};
        const T density = *rc::gen::inRange(0, 16) == 0 ? *rc::gen::elementOf(bad) : *rc::gen::elementOf(densities);
        const Vec2<T> t = gen_translation<T>(scale_of_pair(a, a));
        const Transform<T> x = gen_transform<T>(scale_of_pair(a, a));
        judge<T>(laws::mass_law(s, density, t, x), law, subject, s, std::nullopt, false, [=](laws::Case& c) {
          c.density = density;
          c.tx = t.x();
          c.ty = t.y();
          if (!x.is_identity()) c.transform_a = laws::to_data(x);
        });
      };
    case Law::ContainsShape:
      return [=] {
        const auto [a, b] = gen_nested_pair<T>(ka, kb);
        judge<T>(laws::contains_shape_law(a, b), law, subject, a, b, true);
      };
    case Law::Touching:
      return [=] {
        const auto [a, b] = gen_touching_pair<T>(ka, kb);
        judge<T>(laws::touching(a, b), law, subject, a, b, true);
      };
    case Law::Translation:
      return [=] {
        const auto [a, b] = gen_pair<T>(ka, kb);
        const Vec2<T> t = gen_translation<T>(1.0);
        judge<T>(laws::translation(a, b, t), law, subject, a, b, true, [=](laws::Case& c) {
          c.tx = t.x();
          c.ty = t.y();
        });
      };
    case Law::Rotation:
      return [=] {
        const auto [a, b] = gen_pair<T>(ka, kb);
        const int k = *rc::gen::inRange(0, 4);
        const bool mirror = *rc::gen::arbitrary<bool>();
        judge<T>(laws::rotation(a, b, k, mirror), law, subject, a, b, true, [=](laws::Case& c) {
          c.quarter_turns = k;
          c.mirror = mirror;
        });
      };
    case Law::Hierarchy:
      return [=] {
        // The compound: a's primitives plus up to two more children nearby.
        const auto [a, b] = gen_pair<T>(ka, kb);
        std::vector<typename Compound<T>::Child> children = laws::placed_primitives_of(a);
        const int extra = *rc::gen::inRange(0, 3);
        for (int i = 0; i < extra; ++i) children.push_back({gen_any_primitive<T>(1.0), Transform<T>()});
        const Shape<T> comp =
            with_child_transforms(Shape<T>(Compound<T>::make_placed(std::move(children)).value()), 1.0);
        judge<T>(laws::hierarchy(comp, b), law, subject, comp, b, true);
      };
    case Law::Representation:
      return [=] {
        const auto [a, b] = gen_pair<T>(ka, kb);
        const bool first = *rc::gen::arbitrary<bool>();
        judge<T>(first ? laws::representation(a, b) : laws::representation(b, a), law, subject, first ? a : b,
                 first ? b : a, true);
      };
    case Law::Bounds:
      return [=] {
        const auto [a, b] = gen_pair<T>(ka, ka);
        judge<T>(laws::bounds_law(a), law, subject, a, std::nullopt, false);
      };
    case Law::Raycast:
      return [=] {
        const auto [a, b] = gen_pair<T>(ka, ka);
        // Aim from b's inner point toward a's (hits, grazes along touching pairs), or any direction.
        const Vec2c from = inner_point(b), to = inner_point(a);
        const Vec2<T> origin = from.template cast<T>();
        const bool aimed = *rc::gen::inRange(0, 4) != 0;
        const Vec2<T> dir = aimed ? Vec2<T>((to - from).template cast<T>()) : Vec2<T>(T(grid(-8, 8)), T(grid(-8, 8)));
        const T max_t = *rc::gen::elementOf(std::vector<T>{T(0.5), T(1), T(2), T(1e6)});
        const laws::Verdict v = laws::raycast_law(a, Ray<T>{origin, dir}, max_t);
        judge<T>(v, law, subject, a, std::nullopt, false, [=](laws::Case& c) {
          c.ox = origin.x();
          c.oy = origin.y();
          c.dx = dir.x();
          c.dy = dir.y();
          c.max_t = max_t;
        });
      };
    case Law::RaycastExit:
      return [=] {
        const auto [a, b] = gen_pair<T>(ka, ka);
        // From a's inner point, or from a point near a's boundary (on it, a few ulps either side,
        // at a vertex; now and then outside, NaN or infinite), toward b's inner point (across a
        // compound's children and the pair's contact) or along a grid direction.
        const Vec2<T> near = gen_point_near(a);
        const Vec2<T> origin = *rc::gen::inRange(0, 2) == 0 ? Vec2<T>(inner_point(a).template cast<T>()) : near;
        const Vec2c from = origin.template cast<double>(), to = inner_point(b);
        const bool aimed = *rc::gen::inRange(0, 4) != 0 && to != from;
        const Vec2<T> dir = aimed ? Vec2<T>((to - from).template cast<T>()) : Vec2<T>(T(grid(-8, 8)), T(grid(-8, 8)));
        const T max_t = *rc::gen::elementOf(std::vector<T>{T(0.5), T(1), T(2), T(1e6)});
        const laws::Verdict v = laws::raycast_exit_law(a, Ray<T>{origin, dir}, max_t);
        // Classified by the origin: "contained" (an exit judged) or "separated" (none expected).
        judge<T>(v, law, subject, a, std::nullopt, true, [=](laws::Case& c) {
          c.ox = origin.x();
          c.oy = origin.y();
          c.dx = dir.x();
          c.dy = dir.y();
          c.max_t = max_t;
        });
      };
    case Law::Contains:
      return [=] {
        const auto [a, b] = gen_pair<T>(ka, ka);
        const Vec2<T> p = gen_point_near(a);
        judge<T>(laws::contains_law(a, p), law, subject, a, std::nullopt, false, [=](laws::Case& c) {
          c.px = p.x();
          c.py = p.y();
        });
      };
    case Law::SignedDistance:
      return [=] {
        const auto [a, b] = gen_pair<T>(ka, ka);
        // Near the boundary, inside, nearby, NaN or infinite (gen_point_near); or, one in eight,
        // far out at any magnitude up to T's largest (the distance's rescaling, and its overflow
        // to infinity).
        Vec2<T> p = gen_point_near(a);
        if (*rc::gen::inRange(0, 8) == 0) {
          const double far = std::ldexp(1.0, *rc::gen::inRange(0, std::numeric_limits<T>::max_exponent));
          p = Vec2<T>(T(grid(-8, 8) / 8 * far), T(grid(-8, 8) / 8 * far));
        }
        judge<T>(laws::signed_distance_law(a, p), law, subject, a, std::nullopt, false, [=](laws::Case& c) {
          c.px = p.x();
          c.py = p.y();
        });
      };
    case Law::ClosestPoints:
      return simple(&laws::closest_points_law<T>);
    case Law::Scene:
      return [=] {
        // A scene of up to 8 shapes of any kind placed against each other.
        std::vector<Primitive<T>> all;
        const int pairs = *rc::gen::inRange(1, 5);
        for (int i = 0; i < pairs; ++i) {
          const auto k1 = static_cast<ShapeKind>(*rc::gen::inRange(0, int(kKindCount) - 1));
          const auto k2 = static_cast<ShapeKind>(*rc::gen::inRange(0, int(kKindCount) - 1));
          const auto [a, b] = gen_pair<T>(k1, k2);
          for (const Shape<T>* sh : {&a, &b})
            for (const Primitive<T>& p : laws::primitives_of(*sh)) all.push_back(p);
        }
        const Shape<T> group = Compound<T>(std::move(all));
        judge<T>(laws::scene(group), law, subject, group, std::nullopt, false);
      };
    case Law::Rejection:
      return [=] {
        // Whole vertices or children (up to 5 and 2), or the fixed count plus one value more.
        const laws::KindCodec codec = laws::codec_of(ka);
        const int n = codec.layout == laws::Layout::Vertices   ? 2 * *rc::gen::inRange(0, 6)
                      : codec.layout == laws::Layout::Children ? 3 * *rc::gen::inRange(0, 3)
                                                               : 6;
        std::vector<T> values;
        if (*rc::gen::arbitrary<bool>()) {
          values = gen_aimed_values<T>(ka);
        } else {
          for (int i = 0; i < n; ++i) values.push_back(gen_raw_value<T>());
        }
        const laws::Verdict v = laws::rejection<T>(ka, std::span<const T>(values));
        g_tally.record(v, false);
        RC_TAG(v.account.substr(0, v.account.find(':')));
        if (!v.ok) {
          g_tally.failed = true;
          laws::Case c;
          c.law = law;
          c.scalar = std::is_same_v<T, float> ? "float" : "double";
          c.a.kind = ka;
          c.values.assign(values.begin(), values.end());
          c.expected = v.expected;
          c.got = v.got;
          c.account = v.account;
          c.source = "property " + std::string(laws::name(law)) + " " + subject + " " + c.scalar + " " + seed_text();
          g_tally.counterexample = c;
        }
        if (!v.ok) RC_FAIL(v.account);
      };
    default:
      break;
  }
  return {};
}

/// Registers the test <law>.<subject>_<scalar> (subject: a pair or a kind name).
template <Scalar T>
void register_test(laws::Law law, ShapeKind ka, ShapeKind kb, const std::string& subject) {
  const std::string law_name(laws::name(law));
  const std::string scalar = std::is_same_v<T, float> ? "float" : "double";
  // Pair laws aim at every relation (the touching law at touching only); the others classify none.
  std::vector<laws::Relation> aimed;
  if (law == laws::Law::Touching) {
    aimed = {laws::Relation::Touching};
  } else if (laws::info(law).inputs == laws::LawInputs::Pair) {
    aimed = {laws::Relation::Separated, laws::Relation::Touching, laws::Relation::Overlapping,
             laws::Relation::Contained};
  }
  const std::function<void()> property = property_of<T>(law, ka, kb, subject);
  if (!property) return register_missing_generator(law_name, subject + "_" + scalar);
  ::testing::RegisterTest(law_name.c_str(), (subject + "_" + scalar).c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [=]() -> ::testing::Test* {
                            struct Body : ::testing::Test {
                              std::string law, subject, scalar;
                              std::vector<laws::Relation> aimed;
                              std::function<void()> property;
                              void TestBody() override {
                                g_tally = Tally{};
                                ::rc::detail::checkGTest(property);
                                const std::string what = law + " " + subject + " " + scalar;
                                if (!aimed.empty()) expect_distribution(what, aimed);
                                finish(law, subject, scalar);
                              }
                            };
                            auto* t = new Body;
                            t->law = law_name;
                            t->subject = subject;
                            t->scalar = scalar;
                            t->aimed = aimed;
                            t->property = property;
                            return t;
                          });
}

/// Every law of the Static suite, over what it takes (law_tests.hpp).
void register_all() {
  for_each_law_test(laws::LawSuite::Static,
                    []<Scalar T>(const laws::LawInfo& row, ShapeKind ka, ShapeKind kb, const std::string& subject) {
                      register_test<T>(row.law, ka, kb, subject);
                    });
}

}  // namespace
}  // namespace collide::props

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  collide::props::register_all();
  return RUN_ALL_TESTS();
}
