#pragma once
/// @file law_tests.hpp
/// The tests of one property suite, from the law table: for each law of the suite, what it takes
/// (law_table.inc's inputs) gives its tests — each unordered pair of kinds, each kind, the one
/// scene (named after the compound that holds it), or once (transform values) — for both scalars.
/// Test names are <law>.<subject>_<scalar>, or <law>.<scalar> for laws taken once.

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "collide/laws/case_file.hpp"
#include "collide/laws/laws.hpp"

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <string>

namespace collide::props {

/// Calls add(row, ka, kb, subject) for float and for double (add is a generic lambda taking the
/// scalar as its first template argument: add.template operator()<T>(...)) per test of each law
/// of `suite`. For laws of one shape kb is ka; for laws taken once the subject is empty.
template <class Add>
void for_each_law_test(laws::LawSuite suite, Add&& add) {
  for (const laws::LawInfo& row : laws::kLaws) {
    if (row.suite != suite) continue;
    auto both = [&](ShapeKind ka, ShapeKind kb, const std::string& subject) {
      add.template operator()<float>(row, ka, kb, subject);
      add.template operator()<double>(row, ka, kb, subject);
    };
    switch (row.inputs) {
      case laws::LawInputs::Pair:
        for (const KindPair p : kPairs) both(p.first, p.second, name(p));
        break;
      case laws::LawInputs::Shape:
      case laws::LawInputs::Values:
        for (const ShapeKind k : kKinds) both(k, k, std::string(name(k)));
        break;
      case laws::LawInputs::Scene:
        both(ShapeKind::Compound, ShapeKind::Compound, "compound");
        break;
      case laws::LawInputs::TransformValues:
        both(ShapeKind::Circle, ShapeKind::Circle, "");
        break;
      case laws::LawInputs::Chain:  // the chain suite registers its own tests, once per law
        both(ShapeKind::Capsule, ShapeKind::Capsule, "");
        break;
    }
  }
}

/// The test name of a subject and scalar: "<subject>_<scalar>", or "<scalar>" for laws taken once.
inline std::string test_name(const std::string& subject, const std::string& scalar) {
  return subject.empty() ? scalar : subject + "_" + scalar;
}

/// Registers the GoogleTest test suite.name whose body is `body`.
inline void register_function_test(const std::string& suite, const std::string& name, std::function<void()> body) {
  ::testing::RegisterTest(suite.c_str(), name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [body]() -> ::testing::Test* {
                            struct Body : ::testing::Test {
                              std::function<void()> body;
                              void TestBody() override { body(); }
                            };
                            auto* t = new Body;
                            t->body = body;
                            return t;
                          });
}

/// Registers law.name as a test that fails and names the law: a law of the table whose suite has
/// no generator for it.
inline void register_missing_generator(const std::string& law, const std::string& name) {
  register_function_test(law, name, [law] {
    ADD_FAILURE() << "law '" << law << "' is in the law table but its suite has no generator for it";
  });
}

/// Registers the tests of every law of `suite` (for_each_law_test): property.template
/// operator()<T>(law, ka, kb, test) gives a law's property, test being "<law> <name>"; run(p) is
/// the body of each test. A law of the suite without a property (empty function) registers a test
/// that fails and names it: a law added to the table but not to its suite's generators.
template <class Property, class Run>
void register_suite(laws::LawSuite suite, Property property, Run run) {
  for_each_law_test(
      suite, [&]<Scalar T>(const laws::LawInfo& row, ShapeKind ka, ShapeKind kb, const std::string& subject) {
        const std::string law(row.name), name = test_name(subject, std::is_same_v<T, float> ? "float" : "double");
        std::function<void()> p = property.template operator()<T>(row.law, ka, kb, law + " " + name);
        if (!p) return register_missing_generator(law, name);
        register_function_test(law, name, [p, run] { run(p); });
      });
}

/// The environment variable `key`, or `fallback` when unset or empty.
inline std::string env_or(const char* key, const std::string& fallback) {
  const char* v = std::getenv(key);
  return v != nullptr && *v != '\0' ? std::string(v) : fallback;
}

/// The seed RapidCheck runs with (from RC_PARAMS), for a case file's source line.
inline std::string seed_text() {
  const std::string params = env_or("RC_PARAMS", "");
  const auto at = params.find("seed=");
  if (at == std::string::npos) return "seed random";
  const auto end = params.find(' ', at);
  return "seed " + params.substr(at + 5, end == std::string::npos ? std::string::npos : end - at - 5);
}

/// Saves a counterexample as a case file + SVG under COLLIDE_CASES_DIR (default: the source tree's
/// tests/regressions, COLLIDE_REGRESSIONS_DIR) and returns its path; a failure to save is a test
/// failure.
inline std::string save_counterexample(const laws::Case& c) {
  try {
    const std::filesystem::path dir = env_or("COLLIDE_CASES_DIR", COLLIDE_REGRESSIONS_DIR);
    const std::string saved = laws::save_case(dir, c).string();
    std::cout << "counterexample saved: " << saved << std::endl;
    return saved;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "could not save the counterexample: " << e.what();
    return "";
  }
}

/// The running test's last failing input (after shrinking, the smallest), set by judge_case().
inline std::optional<laws::Case>& failing_case() {
  static std::optional<laws::Case> c;
  return c;
}

/// Fails the property with the verdict's account (every value in round-trip decimal), keeping its
/// input as a case (make()); tags in-band disagreements and classifies by relation.
inline void judge_case(const laws::Verdict& v, const std::function<laws::Case()>& make) {
  RC_CLASSIFY(true, std::string(laws::name(v.relation)));
  if (v.disagreement) RC_TAG(std::string("disagreement"));
  if (!v.ok) {
    failing_case() = make();
    RC_FAIL(v.account);
  }
}

/// register_suite() whose tests run their property by check(p) (RapidCheck with the suite's depth)
/// and save the shrunk counterexample judge_case() kept.
template <class Property, class Check>
void register_saving_suite(laws::LawSuite suite, Property property, Check check) {
  register_suite(suite, property, [check](const std::function<void()>& p) {
    failing_case().reset();
    check(p);
    if (failing_case()) save_counterexample(*failing_case());
  });
}

}  // namespace collide::props
