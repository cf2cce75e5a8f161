// The law on shape containment: contains(outer, inner) equals the oracle's exact containment, in
// both argument orders, and a compound outer gives its named error.

#include "support.hpp"

#include <string>
#include <variant>

namespace collide::laws {

using detail::describe;

namespace {

/// inner is a compound with child transforms: the library judges its children's images.
template <Scalar T>
bool imaged(const Shape<T>& inner) {
  const auto* c = std::get_if<Compound<T>>(&inner);
  return c != nullptr && c->has_child_transforms();
}

}  // namespace

template <Scalar T>
Verdict contains_shape_law(const Shape<T>& a, const Shape<T>& b) {
  Verdict v;
  auto fail = [&](const std::string& order, std::string expected, std::string got) {
    v.ok = false;
    v.expected = order + " " + std::move(expected);
    v.got = std::move(got);
    v.account = "expected " + v.expected + "; got " + v.got + "; a = " + describe(a) + "; b = " + describe(b);
  };
  try {
    v.relation = relation(a, b);
    for (int k = 0; k < 2 && v.ok; ++k) {
      const Shape<T>& outer = k == 0 ? a : b;
      const Shape<T>& inner = k == 0 ? b : a;
      const std::string order = k == 0 ? "contains(a, b)" : "contains(b, a)";
      const Expected<bool> got = contains(outer, inner);
      // A compound outer: the named error, never an answer.
      if (std::holds_alternative<Compound<T>>(outer)) {
        if (got || got.error().code() != Error::CompoundOuter)
          fail(order, "Error::CompoundOuter", got ? std::string("an answer") : std::string(got.error().what()));
        v.account += order + " CompoundOuter; ";
        continue;
      }
      if (!got) {
        fail(order, "an answer", got.error().what());
        continue;
      }
      // The concrete outer's bool is the variant's answer, bit for bit.
      const bool direct = std::visit(
          [&](const auto& o) {
            if constexpr (::collide::detail::is_compound_v<decltype(o)>) {
              return !*got;  // unreachable: handled above
            } else {
              return contains(o, inner);
            }
          },
          outer);
      if (direct != *got) fail(order, "the same answer for the concrete outer", "a different one");
      bool expected = oracle::contains(outer, inner);
      v.account += order + " " + detail::yes(*got) + ", exact " + detail::yes(expected) + "; ";
      if (*got != expected && imaged(inner)) {
        // A compound with child transforms is judged on the images the library computed (its
        // contract: within placement_tolerance of the exact answer).
        v.disagreement = true;
        expected = oracle::contains(outer, detail::computed_geometry(inner));
      }
      if (*got != expected) fail(order, detail::yes(expected), detail::yes(*got));
    }
  } catch (const std::exception& e) {
    v.ok = false;
    v.expected = "no exception";
    v.got = e.what();
    v.account = std::string("exception: ") + e.what() + "; a = " + describe(a) + "; b = " + describe(b);
  }
  return v;
}

template Verdict contains_shape_law<float>(const Shape<float>&, const Shape<float>&);
template Verdict contains_shape_law<double>(const Shape<double>&, const Shape<double>&);

}  // namespace collide::laws
