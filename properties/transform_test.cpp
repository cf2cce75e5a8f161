/// The transform laws (laws.hpp, law 10), for every pair of kinds from the registry and both
/// scalars, as one GoogleTest test each (suite = law, name = <pair>_<scalar>), checked by
/// RapidCheck. Shapes come from the pair generator (placed against each other in world space),
/// then both are placed by one transform (the pair's relation survives, up to rounding: the
/// boundary cases stay at the boundary) or each by its own; compounds sometimes carry child
/// transforms. A failing case is reported with its values in the failure message.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "collide/laws/laws.hpp"
#include "generators.hpp"
#include "transform_generators.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace collide::props {
namespace {

std::string g_last;  // the failing verdict's account, printed once per test

void judge(const laws::Verdict& v) {
  if (v.disagreement) RC_TAG(std::string("disagreement"));
  RC_CLASSIFY(true, std::string(laws::name(v.relation)));
  if (!v.ok) {
    g_last = v.account;
    RC_FAIL(v.account);
  }
}

/// One GoogleTest test running one property; a failure's account is printed once.
void register_test(const std::string& suite, const std::string& name, std::function<void()> property) {
  ::testing::RegisterTest(suite.c_str(), name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [property]() -> ::testing::Test* {
                            struct Body : ::testing::Test {
                              std::function<void()> property;
                              void TestBody() override {
                                g_last.clear();
                                ::rc::detail::checkGTest(property);
                                if (!g_last.empty()) ADD_FAILURE() << g_last;
                              }
                            };
                            auto* t = new Body;
                            t->property = property;
                            return t;
                          });
}

template <Scalar T>
void register_pair(ShapeKind ka, ShapeKind kb) {
  const std::string pair = std::string(name(make_pair(ka, kb)));
  const std::string scalar = std::is_same_v<T, float> ? "float" : "double";
  // Both placed by one transform, or each by its own.
  const auto placed_pair = [=] {
    auto [a, b] = gen_pair<T>(ka, kb);
    const double s = scale_of_pair(a, b);
    a = with_child_transforms(a, s);
    b = with_child_transforms(b, s);
    const Transform<T> xa = gen_transform<T>(s);
    const Transform<T> xb = *rc::gen::inRange(0, 3) == 0 ? gen_transform<T>(s) : xa;
    return std::tuple{a, xa, b, xb};
  };
  std::vector<std::pair<std::string, std::function<void()>>> laws_of_pair = {
      {"placed_agreement", [=] {
         const auto [a, xa, b, xb] = placed_pair();
         judge(laws::placed_agreement(a, xa, b, xb));
       }},
      {"placed_outputs", [=] {
         const auto [a, xa, b, xb] = placed_pair();
         judge(laws::placed_outputs(a, xa, b, xb));
       }},
      {"placed_resolution", [=] {
         const auto [a, xa, b, xb] = placed_pair();
         judge(laws::placed_resolution(a, xa, b, xb));
       }},
      {"placed_covariance", [=] {
         auto [a, b] = gen_pair<T>(ka, kb);
         judge(laws::placed_covariance(a, b, gen_transform<T>(scale_of_pair(a, b))));
       }},
      {"placed_image", [=] {
         auto [a, b] = gen_pair<T>(ka, kb);
         const double s = scale_of_pair(a, b);
         a = with_child_transforms(a, s);
         judge(laws::placed_image(a, gen_transform<T>(s), b));
       }},
  };
  for (auto& [law, property] : laws_of_pair) register_test(law, pair + "_" + scalar, property);
}

template <Scalar T>
void register_kind(ShapeKind k) {
  const std::string kind = std::string(name(k));
  const std::string scalar = std::is_same_v<T, float> ? "float" : "double";
  const std::function<void()> prop = [=] {
    auto [a, b] = gen_pair<T>(k, k);
    const double s = scale_of_pair(a, b);
    a = with_child_transforms(a, s);
    const Transform<T> x = gen_transform<T>(s);
    const Vec2<T> p = gen_point_near(a);
    const Vec2<T> q(x.apply(widen(p)).template cast<T>());  // near the placed shape, when p is finite
    const Vec2<T> origin(x.apply(inner_point(b)).template cast<T>());
    const Vec2<T> target(x.apply(inner_point(a)).template cast<T>());
    const Vec2<T> dir = *rc::gen::inRange(0, 4) != 0 ? Vec2<T>(target - origin) : Vec2<T>(T(grid(-8, 8)), T(grid(-8, 8)));
    const T max_t = *rc::gen::elementOf(std::vector<T>{T(0.5), T(1), T(2)});
    judge(laws::placed_shape(a, x, p.allFinite() ? q : p, Ray<T>{origin, dir}, max_t));
  };
  register_test("placed_shape", kind + "_" + scalar, prop);
}

/// Raw values for the transform factories: bit patterns, special values, a zero or unit rotation.
template <Scalar T>
std::vector<T> gen_transform_values() {
  std::vector<T> v;
  for (int i = 0; i < 5; ++i) v.push_back(gen_raw_value<T>());
  const int aim = *rc::gen::inRange(0, 4);
  if (aim == 0) v[3] = v[4] = T(0);                        // zero rotation
  if (aim == 1) v[3] = T(0.6), v[4] = T(0.8);              // unit up to rounding: kept
  if (aim == 2) v[0] = max_magnitude<T>(), v[1] = T(1);   // moved() leaves the range
  return v;
}

template <Scalar T>
void register_rejection() {
  const std::string scalar = std::is_same_v<T, float> ? "float" : "double";
  const std::function<void()> prop = [] {
    const std::vector<T> v = gen_transform_values<T>();
    judge(laws::transform_rejection<T>(std::span<const T>(v)));
  };
  register_test("transform_rejection", scalar, prop);
}

/// Every transform law for one scalar: the pairs and kinds from the registry, and the factories.
template <Scalar T>
void register_scalar() {
  for_each_pair([]<ShapeKind A, ShapeKind B>() { register_pair<T>(A, B); });
  for_each_kind([]<ShapeKind K>() { register_kind<T>(K); });
  register_rejection<T>();
}

}  // namespace
}  // namespace collide::props

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  collide::props::register_scalar<float>();
  collide::props::register_scalar<double>();
  return RUN_ALL_TESTS();
}
