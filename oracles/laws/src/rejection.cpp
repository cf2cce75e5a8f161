// Law rejection: every invalid input is rejected with its named error; valid input gives a shape.

#include "collide/laws/codec.hpp"
#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace collide::laws {

using detail::num;

namespace {

/// The error the value checks must give: the first value (in argument order) that is NaN or
/// infinite (NonFinite) or larger than max_magnitude<T>() (OutOfRange).
template <Scalar T>
std::optional<std::pair<Error, long>> value_error(std::span<const T> values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) return std::pair{Error::NonFinite, long(i)};
    if (std::fabs(values[i]) > max_magnitude<T>()) return std::pair{Error::OutOfRange, long(i)};
  }
  return std::nullopt;
}

template <Scalar T>
std::string list(std::span<const T> values) {
  std::string out;
  for (T x : values) {
    if (!out.empty()) out += ' ';
    out += detail::hex(double(x));
  }
  return out;
}

/// Builds the shape both ways (factory and throwing constructor); the outcome of make() plus a
/// note when the two ways disagree.
struct Built {
  bool ok = false;
  Error code = Error::NonFinite;
  long index = -1;
  std::string what;
  std::string mismatch;  // the constructor behaved differently from make()
};

template <class S, class Make, class Ctor>
Built build(Make&& make, Ctor&& ctor) {
  Built out;
  const Expected<S> r = make();
  out.ok = r.has_value();
  if (!out.ok) {
    out.code = r.error().code();
    out.index = r.error().index();
    out.what = r.error().what();
  }
  try {
    ctor();
    if (!out.ok) out.mismatch = "constructor accepted what make() rejected";
  } catch (const ShapeError& e) {
    if (out.ok)
      out.mismatch = std::string("constructor threw ") + e.what() + " where make() accepted";
    else if (e.code() != out.code)
      out.mismatch = std::string("constructor threw ") + e.what();
  }
  return out;
}

/// Builds kind `kind` from its codec's values (a compound: one circle child per three values).
template <Scalar T>
Built build_kind(ShapeKind kind, std::span<const T> x, std::string& shape_error) {
  return visit_kind(kind, [&]<ShapeKind K>() -> Built {
    if constexpr (Codec<K>::layout == Layout::Children) {
      // Children: one circle per three values; their errors come first, then EmptyCompound.
      using Child = Codec<ShapeKind::Circle>;
      std::vector<Primitive<T>> children;
      for (std::size_t i = 0; i + 2 < x.size(); i += 3) {
        const auto c = Child::make<T>(x.subspan(i, 3));
        if (!c) return Built{false, c.error().code(), c.error().index(), c.error().what(), {}};
        children.emplace_back(c.value());
      }
      return build<ShapeOf<K, T>>([&] { return ShapeOf<K, T>::make(children); },
                                  [&] { (void)ShapeOf<K, T>(children); });
    } else {
      Built b = build<ShapeOf<K, T>>([&] { return Codec<K>::template make<T>(x); },
                                     [&] { (void)Codec<K>::template construct<T>(x); });
      if constexpr (K == ShapeKind::Polygon) {
        if (b.ok) {
          // An accepted polygon must be strictly convex and counter-clockwise, made of input points.
          const std::vector<Vec2<T>> pts = Codec<K>::template points<T>(x);
          const ConvexPolygon<T> p = Codec<K>::template make<T>(x).value();
          const std::size_t n = p.size();
          for (std::size_t i = 0; i < n; ++i) {
            if (orient(widen(p[i]), widen(p[(i + 1) % n]), widen(p[(i + 2) % n])) <= 0)
              shape_error = "accepted polygon is not strictly convex counter-clockwise at vertex " + std::to_string(i);
            if (std::find(pts.begin(), pts.end(), p[i]) == pts.end())
              shape_error = "accepted polygon has a vertex not in the input";
          }
        }
      }
      return b;
    }
  });
}

/// The values `kind` takes from `given` (a compound: whole circles of three values).
std::size_t arity(ShapeKind kind, std::size_t given) {
  if (codec_of(kind).layout == Layout::Children) return given - given % Codec<ShapeKind::Circle>::fields.size();
  return value_count(kind, given);
}

/// What the kind's own rules say of finite, in-range values (its codec's rule()).
template <Scalar T>
Rule rule_of(ShapeKind kind, std::span<const T> x) {
  return visit_kind(kind, [&]<ShapeKind K>() -> Rule {
    if constexpr (Codec<K>::layout == Layout::Children) {
      return {};  // judged child by child in rejection()
    } else {
      return Codec<K>::template rule<T>(x);
    }
  });
}

std::string one_of(const std::vector<Error>& errors) {
  std::string out;
  for (std::size_t i = 0; i < errors.size(); ++i) {
    if (i > 0) out += i + 1 == errors.size() ? " or " : ", ";
    out += name(errors[i]);
  }
  return out;
}

}  // namespace

template <Scalar T>
Verdict rejection(ShapeKind kind, std::span<const T> all_values) {
  Verdict v;
  const std::size_t n = arity(kind, all_values.size());
  if (all_values.size() < n) {
    v.ok = false;
    v.account = "rejection law: " + std::to_string(all_values.size()) + " values, " + std::string(name(kind)) +
                " needs " + std::to_string(n);
    v.expected = "enough values";
    v.got = v.account;
    return v;
  }
  const std::span<const T> x = all_values.first(n);
  std::string shape_error;
  Built b;
  try {
    b = build_kind<T>(kind, x, shape_error);
  } catch (const std::exception& e) {
    v.ok = false;
    v.expected = "make() never throws";
    v.got = std::string("threw ") + e.what();
    v.account = v.got + "; " + std::string(name(kind)) + " " + list(x);
    return v;
  }
  const std::string outcome = b.ok ? "accepted" : "rejected: " + b.what;
  v.account = std::string(name(kind)) + " " + outcome;
  auto fail = [&](std::string expected) {
    v.ok = false;
    v.expected = std::move(expected);
    v.got = outcome;
    v.account = "expected " + v.expected + "; got " + outcome + "; " + std::string(name(kind)) + " values " + list(x);
  };
  if (!b.mismatch.empty()) return fail("constructor and make() agree (" + b.mismatch + ")"), v;
  if (!shape_error.empty()) return fail(shape_error), v;
  if (codec_of(kind).layout == Layout::Children) {
    // Child by child (one circle per three values): its value errors, then its radius.
    for (std::size_t i = 0; i + 2 < n; i += 3) {
      const auto child = x.subspan(i, 3);
      const auto ce = value_error<T>(child);
      if (ce) {
        if (b.ok || b.code != ce->first || b.index != ce->second)
          fail(std::string(name(ce->first)) + " at index " + std::to_string(ce->second) + " of child " +
               std::to_string(i / 3));
        return v;
      }
      if (!Codec<ShapeKind::Circle>::rule<T>(child).may_be_valid) {
        if (b.ok || b.code != Error::NegativeRadius) fail("NegativeRadius of child " + std::to_string(i / 3));
        return v;
      }
    }
    if (n == 0 && (b.ok || b.code != Error::EmptyCompound)) fail("EmptyCompound");
    if (n > 0 && !b.ok) fail("a valid compound");
    return v;
  }
  const std::optional<std::pair<Error, long>> ve = value_error<T>(x);
  if (ve) {
    if (b.ok || b.code != ve->first)
      return fail(std::string(name(ve->first)) + " for value " + std::to_string(ve->second)), v;
    const long want = ve->second;
    if (b.index != want) return fail(std::string(name(ve->first)) + " at index " + std::to_string(want)), v;
    return v;
  }
  const Rule rule = rule_of<T>(kind, x);
  const bool named = std::find(rule.errors.begin(), rule.errors.end(), b.code) != rule.errors.end();
  if (!b.ok && !named) {
    fail(rule.errors.empty() ? std::string("a valid shape") : one_of(rule.errors));
  } else if (b.ok && !rule.may_be_valid) {
    fail(one_of(rule.errors));
  } else if (!b.ok && b.code == Error::NonConvex && (b.index < 0 || std::size_t(b.index) >= n / 2)) {
    fail("NonConvex with the index of an input vertex");
  }
  return v;
}

template Verdict rejection<float>(ShapeKind, std::span<const float>);
template Verdict rejection<double>(ShapeKind, std::span<const double>);

}  // namespace collide::laws
