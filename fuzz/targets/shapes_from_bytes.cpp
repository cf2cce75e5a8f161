// Fuzz target shapes_from_bytes: arbitrary bit patterns (NaN, +-inf, subnormals, +-1e38, values
// beyond max_magnitude) into every shape factory. Each input must give a named rejection or a
// valid shape, never a crash or undefined behaviour, and:
// - make(...) and the throwing constructor with the same arguments agree (same error code and
//   index, or the same stored values);
// - where the values have the layout of law "rejection", that law holds (the first offending
//   value named, in argument order);
// - a valid shape is handled by every query: its bounds contain it (law "bounds"), overlaps() is
//   symmetric against probe shapes, contact/distance/resolve/raycast return finite, consistent
//   values, translated() returns a shape or a named error, and the shape overlaps itself.
//
// - with flags bit 1, a transform follows the shape (px py qx qy): a named error, or a unit
//   rotation that the transform codec rebuilds bit for bit.
//
// Input: flags byte (bit 0: double, bit 1: a transform follows), then one shape (format in
// collide/fuzz/decode.hpp), then the transform's four values.

#include "collide/fuzz/decode.hpp"
#include "collide/fuzz/failure.hpp"
#include "collide/laws/case_file.hpp"
#include "collide/laws/laws.hpp"
#include "collide/oracle/oracle.hpp"
#include "collide/raycast.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <array>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#if defined(COLLIDE_FUZZ_ENGINE)
#include "collide/fuzz/mutator.hpp"
#endif

namespace {

using namespace collide;
using namespace collide::fuzz;

bool same_data(const laws::ShapeData& x, const laws::ShapeData& y) {
  if (x.kind != y.kind || x.values.size() != y.values.size() || x.children.size() != y.children.size()) return false;
  for (std::size_t i = 0; i < x.values.size(); ++i) {
    if (std::memcmp(&x.values[i], &y.values[i], sizeof(double)) != 0) return false;
  }
  for (std::size_t i = 0; i < x.children.size(); ++i) {
    if (!same_data(x.children[i], y.children[i])) return false;
  }
  if (x.placement.has_value() != y.placement.has_value()) return false;
  return !x.placement || std::memcmp(x.placement->values.data(), y.placement->values.data(), 4 * sizeof(double)) == 0;
}

template <Scalar T>
T value_of(const std::uint8_t* data, std::size_t size, const Field& f) {
  unsigned char bytes[sizeof(T)] = {};
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    if (f.offset + i < size) bytes[i] = data[f.offset + i];
  }
  T v;
  std::memcpy(&v, bytes, sizeof(T));
  return v;
}

template <Scalar T>
bool finite(const Vec2<T>& v) {
  return v.allFinite();
}

/// Every query on a valid shape s against probe p.
template <Scalar T>
void check_queries(const Shape<T>& s, const Shape<T>& p, const char* probe) {
  const std::string where = cat(" (against ", probe, ")");
  const bool o = overlaps(s, p);
  if (o != overlaps(p, s)) fail_raw("overlaps(s, p) != overlaps(p, s)", where);
  const auto c = contact(s, p);
  if (c.has_value() != o) fail_raw("contact exists != overlaps", where);
  if (c) {
    if (!finite(c->normal) || !std::isfinite(c->depth) || c->depth < T(0) || c->count < 1 || c->count > 2) {
      fail_raw("contact has a non-finite or negative value", where);
    }
    for (int i = 0; i < c->count; ++i) {
      if (!finite(c->points[static_cast<std::size_t>(i)])) fail_raw("contact point is not finite", where);
    }
  }
  const T d = distance(s, p);
  if (!std::isfinite(d) || d < T(0)) fail_raw("distance is negative or not finite", where);
  if (o && d != T(0)) fail_raw("distance of overlapping shapes is not 0", where);
  const Vec2<T> v = resolve(s, p);
  if (!finite(v)) fail_raw("resolve returned a non-finite vector", where);
  if (!o && v != Vec2<T>::Zero()) fail_raw("resolve of separated shapes is not zero", where);
  static_cast<void>(translated(s, v));  // a shape or a named error; must not crash
}

template <Scalar T>
void check_valid(const Shape<T>& s) {
  require(laws::Law::Bounds, laws::bounds_law(s), s, std::optional<Shape<T>>());
  const Shape<T> probes[] = {
      Shape<T>(Circle<T>(Vec2<T>(0, 0), T(1))),
      Shape<T>(Aabb<T>(Vec2<T>(-1, -1), Vec2<T>(1, 1))),
      Shape<T>(ConvexPolygon<T>({Vec2<T>(0, 0), Vec2<T>(4, 1), Vec2<T>(1, 3)})),
      Shape<T>(Capsule<T>(Vec2<T>(-2, 0), Vec2<T>(2, 0), T(0.5))),
  };
  static constexpr const char* kProbeNames[] = {"unit circle", "box [-1, 1]^2", "triangle", "capsule"};
  for (std::size_t i = 0; i < std::size(probes); ++i) check_queries(s, probes[i], kProbeNames[i]);
  check_queries(s, s, "itself");
  // A shape always overlaps itself (exactly; for a point-sized shape too).
  try {
    if (!overlaps(s, s)) require(laws::Law::Agreement, laws::agreement(s, s), s, std::optional<Shape<T>>(s));
  } catch (const oracle::Unsupported&) {
    // not judged
  }
  // A ray from outside the bounds toward their center.
  const Aabb<T> b = bounds(s);
  const Vec2c lo = widen(b.min()), hi = widen(b.max());
  const Vec2c center = (lo + hi) * 0.5;
  const Vec2c origin(lo.x() - (hi.x() - lo.x()) - 1, center.y() - 0.25 * (hi.y() - lo.y()));
  const Vec2<T> o = origin.template cast<T>(), dir = (center - origin).template cast<T>();
  if (finite(o) && finite(dir)) {
    const auto hit = raycast(s, Ray<T>{o, dir}, T(2));
    if (hit && (!(hit->t >= T(0) && hit->t <= T(2)) || !finite(hit->point))) {
      fail_raw("raycast hit outside [0, max_t] or at a non-finite point");
    }
  }
}

/// A valid shape of a kind (its codec's sample; a compound of the first kind's), to name the
/// kind in a rejection case.
template <Scalar T>
Shape<T> stand_in(ShapeKind kind) {
  auto sample = [](ShapeKind k) {
    const laws::KindCodec c = laws::codec_of(k);
    return laws::ShapeData{k, std::vector<double>(c.sample.begin(), c.sample.end()), {}, {}};
  };
  laws::ShapeData d = sample(kind);
  if (laws::codec_of(kind).layout == laws::Layout::Children) d.children.push_back(sample(kKinds[0]));
  return laws::from_data<T>(d);
}

/// Whether the bytes after the kind byte are exactly the kind's codec values (law "rejection").
bool has_rejection_layout(ShapeKind kind, std::uint8_t form_byte) {
  return visit_kind(kind, [&]<ShapeKind K>() { return Decoder<K, float>::stored_values(form_byte); });
}

/// A transform after the shape (flags bit 1): a named error, or a transform whose position is the
/// input's, whose rotation is unit within 4 eps_T, and which the codec rebuilds bit for bit.
template <Scalar T>
void check_transform(Reader& r) {
  Reader peek = r;
  const std::array<T, 4> x = laws::read_transform_values<T>(peek);
  const Expected<Transform<T>> xf = decode_transform<T>(r);
  if (!xf) {
    const Error e = xf.error().code();
    if (e != Error::NonFinite && e != Error::OutOfRange && e != Error::ZeroRotation)
      fail_raw("transform rejected with ", name(e), " (expected NonFinite, OutOfRange or ZeroRotation)");
    return;
  }
  const Transform<T>& t = xf.value();
  if (!(t.position() == Vec2<T>(x[0], x[1]))) fail_raw("transform position differs from its input");
  const Calc q2 = widen(t.rotation()).squaredNorm();
  if (!(std::fabs(q2 - 1) <= 4 * Calc(std::numeric_limits<T>::epsilon())))
    fail_raw("transform rotation is not unit: |q|^2 = ", format_value(q2));
  try {
    if (!(laws::transform_from_data<T>(laws::to_data(t)) == t)) fail_raw("the codec rebuilt another transform");
  } catch (const laws::CodecError& e) {
    fail_raw("the codec cannot rebuild a valid transform: ", e.what());
  }
}

/// A valid shape's stored values rebuild the same shape through its codec (what a case file
/// relies on): every factory keeps the values it stored.
template <Scalar T>
void check_rebuilt(const Shape<T>& s) {
  try {
    if (!same_data(laws::to_data(laws::from_data<T>(laws::to_data(s))), laws::to_data(s)))
      fail_raw("the codec rebuilt another shape from its stored values");
  } catch (const laws::CodecError& e) {
    fail_raw("the codec cannot rebuild a valid shape: ", e.what());
  }
}

template <Scalar T>
void run(const std::uint8_t* data, std::size_t size) {
  std::vector<Field> fields;
  Reader r(data, size, &fields);
  r.byte();  // flags
  const std::size_t start = r.position();
  const Expected<Shape<T>> made = decode_shape<T>(r, Build::Factory);
  Reader again(data, size);
  again.byte();
  const Expected<Shape<T>> thrown = decode_shape<T>(again, Build::Constructor);

  if (made.has_value() != thrown.has_value()) {
    fail_raw("make() ", made ? "accepted" : "rejected", " what the constructor ", thrown ? "accepted" : "rejected");
  }
  if (!made) {
    const ShapeError& e = made.error();
    if (name(e.code()) == "Unknown") fail_raw("rejection with an unnamed error code");
    if (e.code() != thrown.error().code() || e.index() != thrown.error().index()) {
      fail_raw("make() says ", e.what(), ", the constructor says ", thrown.error().what());
    }
  } else if (!same_data(laws::to_data(made.value()), laws::to_data(thrown.value()))) {
    fail_raw("make() and the constructor stored different values");
  }

  const std::uint8_t kind_byte = start < size ? data[start] : 0;
  const std::uint8_t form_byte = start + 1 < size ? data[start + 1] : 0;
  const ShapeKind kind = kKinds[kind_byte % kKindCount];
  if (has_rejection_layout(kind, form_byte)) {
    std::vector<T> values;
    for (const Field& f : fields) values.push_back(value_of<T>(data, size, f));
    const laws::Verdict v = laws::rejection<T>(kind, values);
    if (!v.ok) {
      // The case holds the raw values; shape a only names the kind (a unit shape of it stands in).
      fail(laws::Law::Rejection, made ? made.value() : stand_in<T>(kind), std::optional<Shape<T>>(), v,
           [&](laws::Case& c) { c.values.assign(values.begin(), values.end()); });
    }
  }
  if (made) {
    check_rebuilt(made.value());
    check_valid(made.value());
  }
  if (size > 0 && (data[0] & 2) != 0) check_transform<T>(r);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  current_input() = {data, size};
  const bool is_double = size > 0 && (data[0] & 1) != 0;
  if (is_double) {
    run<double>(data, size);
  } else {
    run<float>(data, size);
  }
  return 0;
}

#if defined(COLLIDE_FUZZ_ENGINE)
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  auto read_input = [](Reader& r) {
    const bool is_double = (r.byte() & 1) != 0;
    if (is_double) {
      static_cast<void>(decode_shape<double>(r));
    } else {
      static_cast<void>(decode_shape<float>(r));
    }
  };
  return mutate_fields(data, size, max_size, seed, read_input, MutatorOptions{6, false});
}
#endif
