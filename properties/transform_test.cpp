/// The laws of placed shapes (the law table's Placed suite), for every pair of kinds from the
/// registry and both scalars, as one GoogleTest test each (suite = law, name = <pair>_<scalar>),
/// checked by RapidCheck. Shapes come from the pair generator (placed against each other in world
/// space), then both are placed by one transform (the pair's relation survives, up to rounding: the
/// boundary cases stay at the boundary) or each by its own; compounds sometimes carry child
/// transforms (generators.hpp: gen_transform, with_child_transforms). A failing case is reported
/// with its values in the failure message and saved as a case file (law_tests.hpp).

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "collide/laws/laws.hpp"
#include "generators.hpp"
#include "law_tests.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace collide::props {
namespace {

/// A case of a law of placed shapes: the shapes, their transforms and the verdict.
template <Scalar T>
laws::Case placed_case(laws::Law law, const Shape<T>& a, std::optional<Transform<T>> xa,
                       const std::optional<Shape<T>>& b, std::optional<Transform<T>> xb, const laws::Verdict& v,
                       const std::string& test) {
  laws::Case c = laws::make_case<T>(law, a, b, v, "property " + test + " " + seed_text());
  if (xa) c.transform_a = laws::to_data(*xa);
  if (xb) c.transform_b = laws::to_data(*xb);
  return c;
}

/// Raw values for the transform factories: bit patterns, special values, a zero or unit rotation.
template <Scalar T>
std::vector<T> gen_transform_values() {
  std::vector<T> v;
  for (int i = 0; i < 5; ++i) v.push_back(gen_raw_value<T>());
  const int aim = *rc::gen::inRange(0, 4);
  if (aim == 0) v[3] = v[4] = T(0);                      // zero rotation
  if (aim == 1) v[3] = T(0.6), v[4] = T(0.8);            // unit up to rounding: kept
  if (aim == 2) v[0] = max_magnitude<T>(), v[1] = T(1);  // moved() leaves the range
  return v;
}

/// The property of a law of the Placed suite for the kinds ka and kb (kb is ka for placed_shape);
/// empty for a law of another suite.
template <Scalar T>
std::function<void()> property_of(laws::Law law, ShapeKind ka, ShapeKind kb, const std::string& test) {
  using laws::Law;
  // Both placed by one transform, or each by its own. A pair far across the axis it meets along
  // (gen_pair's `across`) gets transforms at its size, which mostly keep it there.
  const auto placed_pair = [=](bool across) {
    auto [a, b] = gen_pair<T>(ka, kb, std::nullopt, across);
    const double s = across ? size_of_pair(a, b) : scale_of_pair(a, b);
    a = with_child_transforms(a, s);
    b = with_child_transforms(b, s);
    const Transform<T> xa = gen_transform<T>(s);
    const Transform<T> xb = *rc::gen::inRange(0, 3) == 0 ? gen_transform<T>(s) : xa;
    return std::tuple{a, xa, b, xb};
  };
  using PairLaw = laws::Verdict (*)(const Shape<T>&, const Transform<T>&, const Shape<T>&, const Transform<T>&);
  const auto pair_law = [=](PairLaw f, bool far_across = false) -> std::function<void()> {
    return [=] {
      const auto [a, xa, b, xb] = placed_pair(far_across && *rc::gen::inRange(0, 4) == 0);
      const laws::Verdict v = f(a, xa, b, xb);
      judge_case(v, [&] { return placed_case<T>(law, a, xa, b, xb, v, test); });
    };
  };
  switch (law) {
    case Law::PlacedAgreement:
      return pair_law(&laws::placed_agreement<T>);
    case Law::PlacedOutputs:
      return pair_law(&laws::placed_outputs<T>);
    case Law::PlacedResolution:
      return pair_law(&laws::placed_resolution<T>, true);
    case Law::PlacedSeparation:
      return pair_law(&laws::placed_separation<T>);
    case Law::PlacedFeatureIds:
      return pair_law(&laws::placed_feature_ids<T>);
    case Law::PlacedSpeculative:
      return pair_law(&laws::placed_speculative<T>);
    case Law::PlacedCovariance:
      return [=] {
        auto [a, b] = gen_pair<T>(ka, kb);
        const Transform<T> x = gen_transform<T>(scale_of_pair(a, b));
        const laws::Verdict v = laws::placed_covariance(a, b, x);
        judge_case(v, [&] { return placed_case<T>(law, a, x, b, std::nullopt, v, test); });
      };
    case Law::PlacedImage:
      return [=] {
        auto [a, b] = gen_pair<T>(ka, kb);
        const double s = scale_of_pair(a, b);
        a = with_child_transforms(a, s);
        const Transform<T> x = gen_transform<T>(s);
        const laws::Verdict v = laws::placed_image(a, x, b);
        judge_case(v, [&] { return placed_case<T>(law, a, x, b, std::nullopt, v, test); });
      };
    case Law::PlacedShape:
      return [=] {
        auto [a, b] = gen_pair<T>(ka, ka);
        const double s = scale_of_pair(a, b);
        a = with_child_transforms(a, s);
        const Transform<T> x = gen_transform<T>(s);
        const Vec2<T> p = gen_point_near(a);
        const Vec2<T> q(x.apply(widen(p)).template cast<T>());  // near the placed shape, when p is finite
        const Vec2<T> point = p.allFinite() ? q : p;
        const Vec2<T> origin(x.apply(inner_point(b)).template cast<T>());
        const Vec2<T> target(x.apply(inner_point(a)).template cast<T>());
        const Vec2<T> dir =
            *rc::gen::inRange(0, 4) != 0 ? Vec2<T>(target - origin) : Vec2<T>(T(grid(-8, 8)), T(grid(-8, 8)));
        const T max_t = *rc::gen::elementOf(std::vector<T>{T(0.5), T(1), T(2)});
        const laws::Verdict v = laws::placed_shape(a, x, point, Ray<T>{origin, dir}, max_t);
        judge_case(v, [&] {
          laws::Case c = placed_case<T>(law, a, x, std::nullopt, std::nullopt, v, test);
          c.px = point.x();
          c.py = point.y();
          c.ox = origin.x();
          c.oy = origin.y();
          c.dx = dir.x();
          c.dy = dir.y();
          c.max_t = max_t;
          return c;
        });
      };
    case Law::TransformRejection:
      return [=] {
        const std::vector<T> values = gen_transform_values<T>();
        const laws::Verdict v = laws::transform_rejection<T>(std::span<const T>(values));
        judge_case(v, [&] {
          laws::Case c;
          c.law = law;
          c.scalar = std::is_same_v<T, float> ? "float" : "double";
          c.values.assign(values.begin(), values.end());
          c.expected = v.expected;
          c.got = v.got;
          c.account = v.account;
          c.source = "property " + test + " " + seed_text();
          return c;
        });
      };
    default:
      break;
  }
  return {};
}

/// Every law of the Placed suite, over what it takes (law_tests.hpp); each test saves its shrunk
/// counterexample as a case file.
void register_all() {
  register_saving_suite(
      laws::LawSuite::Placed,
      []<Scalar T>(laws::Law law, ShapeKind ka, ShapeKind kb, const std::string& test) {
        return property_of<T>(law, ka, kb, test);
      },
      [](const std::function<void()>& property) { ::rc::detail::checkGTest(property); });
}

}  // namespace
}  // namespace collide::props

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  collide::props::register_all();
  return RUN_ALL_TESTS();
}
