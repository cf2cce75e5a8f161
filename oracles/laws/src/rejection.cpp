// Law 9: every invalid input is rejected with its named error; valid input gives a shape.

#include "support.hpp"

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
    if (out.ok) out.mismatch = std::string("constructor threw ") + e.what() + " where make() accepted";
    else if (e.code() != out.code) out.mismatch = std::string("constructor threw ") + e.what();
  }
  return out;
}

template <Scalar T>
Built build_kind(ShapeKind kind, std::span<const T> x, std::string& shape_error) {
  using V = Vec2<T>;
  switch (kind) {
    case ShapeKind::Circle:
      return build<Circle<T>>([&] { return Circle<T>::make(V(x[0], x[1]), x[2]); },
                              [&] { (void)Circle<T>(V(x[0], x[1]), x[2]); });
    case ShapeKind::Aabb:
      return build<Aabb<T>>([&] { return Aabb<T>::make(V(x[0], x[1]), V(x[2], x[3])); },
                            [&] { (void)Aabb<T>(V(x[0], x[1]), V(x[2], x[3])); });
    case ShapeKind::Obb:
      return build<Obb<T>>([&] { return Obb<T>::make_with_axis(V(x[0], x[1]), V(x[2], x[3]), V(x[4], x[5])); },
                           [&] { (void)Obb<T>::make_with_axis(V(x[0], x[1]), V(x[2], x[3]), V(x[4], x[5])).value(); });
    case ShapeKind::Capsule:
      return build<Capsule<T>>([&] { return Capsule<T>::make(V(x[0], x[1]), V(x[2], x[3]), x[4]); },
                               [&] { (void)Capsule<T>(V(x[0], x[1]), V(x[2], x[3]), x[4]); });
    case ShapeKind::Polygon: {
      std::vector<V> pts;
      for (std::size_t i = 0; i + 1 < x.size(); i += 2) pts.emplace_back(x[i], x[i + 1]);
      Built b = build<ConvexPolygon<T>>([&] { return ConvexPolygon<T>::make(std::span<const V>(pts)); },
                                        [&] { (void)ConvexPolygon<T>(std::span<const V>(pts)); });
      if (b.ok) {
        // An accepted polygon must be strictly convex and counter-clockwise, made of input points.
        const ConvexPolygon<T> p = ConvexPolygon<T>::make(std::span<const V>(pts)).value();
        const std::size_t n = p.size();
        for (std::size_t i = 0; i < n; ++i) {
          if (orient(widen(p[i]), widen(p[(i + 1) % n]), widen(p[(i + 2) % n])) <= 0)
            shape_error = "accepted polygon is not strictly convex counter-clockwise at vertex " + std::to_string(i);
          if (std::find(pts.begin(), pts.end(), p[i]) == pts.end())
            shape_error = "accepted polygon has a vertex not in the input";
        }
      }
      return b;
    }
    case ShapeKind::Compound: {
      // Children: one circle per three values; their errors come first, then EmptyCompound.
      std::vector<Primitive<T>> children;
      for (std::size_t i = 0; i + 2 < x.size(); i += 3) {
        const auto c = Circle<T>::make(V(x[i], x[i + 1]), x[i + 2]);
        if (!c) return Built{false, c.error().code(), c.error().index(), c.error().what(), {}};
        children.emplace_back(c.value());
      }
      return build<Compound<T>>([&] { return Compound<T>::make(children); }, [&] { (void)Compound<T>(children); });
    }
  }
  return {};
}

std::size_t arity(ShapeKind kind, std::size_t given) {
  switch (kind) {
    case ShapeKind::Circle: return 3;
    case ShapeKind::Aabb: return 4;
    case ShapeKind::Obb: return 6;
    case ShapeKind::Capsule: return 5;
    case ShapeKind::Polygon: return given - given % 2;
    case ShapeKind::Compound: return given - given % 3;
  }
  return 0;
}

/// The error the kind's own rules give for finite, in-range values; nullopt when valid.
/// Polygons are not predicted here (their error is checked to be one of the polygon errors).
template <Scalar T>
std::optional<Error> rule_error(ShapeKind kind, std::span<const T> x) {
  switch (kind) {
    case ShapeKind::Circle: return x[2] < 0 ? std::optional(Error::NegativeRadius) : std::nullopt;
    case ShapeKind::Aabb:
      return x[0] > x[2] || x[1] > x[3] ? std::optional(Error::MinGreaterThanMax) : std::nullopt;
    case ShapeKind::Obb:
      if (x[2] < 0 || x[3] < 0) return Error::NegativeExtent;
      return x[4] == 0 && x[5] == 0 ? std::optional(Error::ZeroAxis) : std::nullopt;
    case ShapeKind::Capsule: return x[4] < 0 ? std::optional(Error::NegativeRadius) : std::nullopt;
    case ShapeKind::Compound: {
      for (std::size_t i = 2; i < x.size(); i += 3) {
        if (x[i] < 0) return Error::NegativeRadius;
      }
      return x.empty() ? std::optional(Error::EmptyCompound) : std::nullopt;
    }
    case ShapeKind::Polygon: break;
  }
  return std::nullopt;
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
  if (kind == ShapeKind::Compound) {
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
      if (child[2] < 0) {
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
    if (b.ok || b.code != ve->first) return fail(std::string(name(ve->first)) + " for value " + std::to_string(ve->second)), v;
    const long want = ve->second;
    if (b.index != want) return fail(std::string(name(ve->first)) + " at index " + std::to_string(want)), v;
    return v;
  }
  if (kind == ShapeKind::Polygon) {
    if (!b.ok && b.code != Error::TooFewVertices && b.code != Error::Collinear && b.code != Error::NonConvex)
      fail("TooFewVertices, Collinear or NonConvex");
    if (!b.ok && b.code == Error::NonConvex && (b.index < 0 || std::size_t(b.index) >= n / 2))
      fail("NonConvex with the index of an input vertex");
    return v;
  }
  const std::optional<Error> re = rule_error<T>(kind, x);
  if (re) {
    if (b.ok || b.code != *re) fail(std::string(name(*re)));
  } else if (!b.ok) {
    fail("a valid shape");
  }
  return v;
}

template Verdict rejection<float>(ShapeKind, std::span<const float>);
template Verdict rejection<double>(ShapeKind, std::span<const double>);

}  // namespace collide::laws
