#pragma once
/// @file codec.hpp
/// One codec per shape kind, beside the registry: the kind's stored values (names, meaning,
/// count), shape -> values, values -> shape through the factory (returning its named error), and
/// values <-> text (case files) and <-> bytes (fuzz inputs, corpus seeds). A codec for
/// Transform<T> carries an optional placement per shape the same way.
///
/// It lives with the laws, not in the library: a game never needs the stored layout, while case
/// files, the rejection law, the fuzz decoders and the corpus script (through collide_describe)
/// all read and write it here. A kind added to the registry without a Codec<K> specialisation
/// fails to compile in every one of them (for_each_kind / visit_kind instantiate Codec<K>).

#include "collide/collide.hpp"
#include "collide/transform.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <istream>
#include <optional>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace collide::laws {

/// Stored values that do not make the shape (or transform) they claim to: wrong count, not
/// representable in the scalar, rejected by the factory, or rebuilt with other bits.
class CodecError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What a stored value means: positions move with their shape, sizes do not.
enum class Role : std::uint8_t {
  X,     ///< x coordinate of a defining point (centre, corner, segment end, vertex, position)
  Y,     ///< y coordinate of such a point
  Size,  ///< radius or half extent
  Other  ///< axis or rotation component
};

/// "x", "y", "size", "other".
constexpr std::string_view name(Role r) noexcept {
  constexpr std::array<std::string_view, 4> names = {"x", "y", "size", "other"};
  return names[static_cast<std::size_t>(r)];
}

/// One stored value: its name in the layout and its role.
struct Field {
  std::string_view name;  ///< e.g. "cx"
  Role role;              ///< what it means
};

/// How a kind's values are laid out.
enum class Layout : std::uint8_t {
  Fixed,     ///< exactly the fields, once
  Vertices,  ///< the fields repeated per vertex; text and bytes store the vertex count first
  Children,  ///< no values: child shapes (every kind but the compound); the count first
};

/// "fixed", "vertices", "children".
constexpr std::string_view name(Layout l) noexcept {
  constexpr std::array<std::string_view, 3> names = {"fixed", "vertices", "children"};
  return names[static_cast<std::size_t>(l)];
}

/// What a kind's own validity rules (beyond finite, in-range values) say of some values, stated
/// independently of the factory: the rejection law checks the factory against it.
struct Rule {
  bool may_be_valid = true;   ///< the values may make a shape (false: one of `errors` is required)
  std::vector<Error> errors;  ///< the errors a rejection may name (empty with may_be_valid: valid)
};

/// A transform as raw stored values: px py qx qy (position, rotation as cosine and sine).
struct TransformData {
  std::array<double, 4> values{};  ///< px, py, qx, qy
  /// Same stored values.
  friend bool operator==(const TransformData&, const TransformData&) = default;
};

/// A shape as raw stored values, independent of the scalar (values as exact doubles).
struct ShapeData {
  ShapeKind kind = ShapeKind::Circle;      ///< the kind
  std::vector<double> values;              ///< in the kind's field order (Vertices: per vertex)
  std::vector<ShapeData> children;         ///< a compound's children
  std::optional<TransformData> placement;  ///< a compound child's transform (absent: the identity)
};

/// Per kind: Layout, fields, sample values (a shape of size about 1 around the origin, exact in
/// float; the corpus script moves and scales it by the fields' roles), values(), make(),
/// construct() and rule(). Bytes: `byte_prefix` (fixed bytes written before the values: the
/// fuzz decoder's form byte for stored OBB values) then, for Vertices and Children, a count byte.
template <ShapeKind K>
struct Codec;

/// @cond COLLIDE_SPECIALISATIONS
template <>
struct Codec<ShapeKind::Circle> {
  static constexpr Layout layout = Layout::Fixed;
  static constexpr std::array<Field, 3> fields = {{{"cx", Role::X}, {"cy", Role::Y}, {"r", Role::Size}}};
  static constexpr std::array<double, 3> sample = {0, 0, 1};
  static constexpr std::array<std::uint8_t, 0> byte_prefix = {};
  template <Scalar T>
  static std::vector<T> values(const Circle<T>& s) {
    return {s.center().x(), s.center().y(), s.radius()};
  }
  template <Scalar T>
  static Expected<Circle<T>> make(std::span<const T> x) {
    return Circle<T>::make(Vec2<T>(x[0], x[1]), x[2]);
  }
  template <Scalar T>
  static Circle<T> construct(std::span<const T> x) {
    return Circle<T>(Vec2<T>(x[0], x[1]), x[2]);
  }
  template <Scalar T>
  static Rule rule(std::span<const T> x) {
    return x[2] < 0 ? Rule{false, {Error::NegativeRadius}} : Rule{};
  }
};

template <>
struct Codec<ShapeKind::Aabb> {
  static constexpr Layout layout = Layout::Fixed;
  static constexpr std::array<Field, 4> fields = {
      {{"minx", Role::X}, {"miny", Role::Y}, {"maxx", Role::X}, {"maxy", Role::Y}}};
  static constexpr std::array<double, 4> sample = {-1, -1, 1, 1};
  static constexpr std::array<std::uint8_t, 0> byte_prefix = {};
  template <Scalar T>
  static std::vector<T> values(const Aabb<T>& s) {
    return {s.min().x(), s.min().y(), s.max().x(), s.max().y()};
  }
  template <Scalar T>
  static Expected<Aabb<T>> make(std::span<const T> x) {
    return Aabb<T>::make(Vec2<T>(x[0], x[1]), Vec2<T>(x[2], x[3]));
  }
  template <Scalar T>
  static Aabb<T> construct(std::span<const T> x) {
    return Aabb<T>(Vec2<T>(x[0], x[1]), Vec2<T>(x[2], x[3]));
  }
  template <Scalar T>
  static Rule rule(std::span<const T> x) {
    return x[0] > x[2] || x[1] > x[3] ? Rule{false, {Error::MinGreaterThanMax}} : Rule{};
  }
};

/// Stored values: centre, half extents and the stored unit axis, which make_with_axis() keeps
/// bit for bit.
template <>
struct Codec<ShapeKind::Obb> {
  static constexpr Layout layout = Layout::Fixed;
  static constexpr std::array<Field, 6> fields = {{{"cx", Role::X},
                                                   {"cy", Role::Y},
                                                   {"hx", Role::Size},
                                                   {"hy", Role::Size},
                                                   {"ux", Role::Other},
                                                   {"uy", Role::Other}}};
  static constexpr std::array<double, 6> sample = {0, 0, 1, 0.5, 0, 1};
  /// The fuzz decoder's form byte: 1 = make_with_axis from these values (0 and 2 are its other
  /// entry points, by angle and by corners).
  static constexpr std::array<std::uint8_t, 1> byte_prefix = {1};
  template <Scalar T>
  static std::vector<T> values(const Obb<T>& s) {
    return {s.center().x(), s.center().y(), s.half_extents().x(), s.half_extents().y(), s.axis().x(), s.axis().y()};
  }
  template <Scalar T>
  static Expected<Obb<T>> make(std::span<const T> x) {
    return Obb<T>::make_with_axis(Vec2<T>(x[0], x[1]), Vec2<T>(x[2], x[3]), Vec2<T>(x[4], x[5]));
  }
  template <Scalar T>
  static Obb<T> construct(std::span<const T> x) {
    return make<T>(x).value();  // make_with_axis has no throwing constructor: value() throws its error
  }
  template <Scalar T>
  static Rule rule(std::span<const T> x) {
    if (x[2] < 0 || x[3] < 0) return {false, {Error::NegativeExtent}};
    return x[4] == 0 && x[5] == 0 ? Rule{false, {Error::ZeroAxis}} : Rule{};
  }
};

template <>
struct Codec<ShapeKind::Capsule> {
  static constexpr Layout layout = Layout::Fixed;
  static constexpr std::array<Field, 5> fields = {
      {{"ax", Role::X}, {"ay", Role::Y}, {"bx", Role::X}, {"by", Role::Y}, {"r", Role::Size}}};
  static constexpr std::array<double, 5> sample = {-0.5, 0, 0.5, 0, 0.5};
  static constexpr std::array<std::uint8_t, 0> byte_prefix = {};
  template <Scalar T>
  static std::vector<T> values(const Capsule<T>& s) {
    return {s.a().x(), s.a().y(), s.b().x(), s.b().y(), s.radius()};
  }
  template <Scalar T>
  static Expected<Capsule<T>> make(std::span<const T> x) {
    return Capsule<T>::make(Vec2<T>(x[0], x[1]), Vec2<T>(x[2], x[3]), x[4]);
  }
  template <Scalar T>
  static Capsule<T> construct(std::span<const T> x) {
    return Capsule<T>(Vec2<T>(x[0], x[1]), Vec2<T>(x[2], x[3]), x[4]);
  }
  template <Scalar T>
  static Rule rule(std::span<const T> x) {
    return x[4] < 0 ? Rule{false, {Error::NegativeRadius}} : Rule{};
  }
};

/// Stored values: the vertices counter-clockwise as stored (make() keeps a polygon in normal
/// form unchanged).
template <>
struct Codec<ShapeKind::Polygon> {
  static constexpr Layout layout = Layout::Vertices;
  static constexpr std::array<Field, 2> fields = {{{"x", Role::X}, {"y", Role::Y}}};
  /// A pentagon with vertices on a 1/64 grid near the unit circle.
  static constexpr std::array<double, 10> sample = {1,        0,       0.3125,    0.953125, -0.8125,
                                                    0.578125, -0.8125, -0.578125, 0.3125,   -0.953125};
  static constexpr std::array<std::uint8_t, 0> byte_prefix = {};
  template <Scalar T>
  static std::vector<T> values(const ConvexPolygon<T>& s) {
    std::vector<T> out;
    for (const Vec2<T>& q : s.vertices()) {
      out.push_back(q.x());
      out.push_back(q.y());
    }
    return out;
  }
  template <Scalar T>
  static std::vector<Vec2<T>> points(std::span<const T> x) {
    std::vector<Vec2<T>> pts;
    for (std::size_t i = 0; i + 1 < x.size(); i += 2) pts.emplace_back(x[i], x[i + 1]);
    return pts;
  }
  template <Scalar T>
  static Expected<ConvexPolygon<T>> make(std::span<const T> x) {
    const std::vector<Vec2<T>> pts = points(x);
    return ConvexPolygon<T>::make(std::span<const Vec2<T>>(pts));
  }
  template <Scalar T>
  static ConvexPolygon<T> construct(std::span<const T> x) {
    const std::vector<Vec2<T>> pts = points(x);
    return ConvexPolygon<T>(std::span<const Vec2<T>>(pts));
  }
  /// Not predicted here (convexity is the factory's exact test): any of the polygon errors.
  template <Scalar T>
  static Rule rule(std::span<const T>) {
    return {true, {Error::TooFewVertices, Error::Collinear, Error::NonConvex}};
  }
};

/// No values: its children, each a shape of another kind with its own codec.
template <>
struct Codec<ShapeKind::Compound> {
  static constexpr Layout layout = Layout::Children;
  static constexpr std::array<Field, 0> fields = {};
  static constexpr std::array<double, 0> sample = {};
  static constexpr std::array<std::uint8_t, 0> byte_prefix = {};
};
/// @endcond

/// Every kind has a codec, and only the compound has children (the byte and text forms of a
/// child name its kind among the others).
static_assert(kKinds.back() == ShapeKind::Compound, "the compound must be the last kind");

/// The codec of a kind known at run time, without its types: layout, field names and roles,
/// sample values, byte prefix.
struct KindCodec {
  ShapeKind kind;                             ///< the kind
  Layout layout;                              ///< how its values are laid out
  std::span<const Field> fields;              ///< the stored fields (per vertex for Vertices)
  std::span<const double> sample;             ///< a sample shape's values
  std::span<const std::uint8_t> byte_prefix;  ///< bytes before the values in the byte form
};

/// The codec of kind k.
inline KindCodec codec_of(ShapeKind k) {
  return visit_kind(k, []<ShapeKind K>() {
    return KindCodec{K, Codec<K>::layout, Codec<K>::fields, Codec<K>::sample, Codec<K>::byte_prefix};
  });
}

/// The number of values `kind` takes from `given` values: the field count for Fixed, whole
/// vertices for Vertices, 0 for Children.
inline std::size_t value_count(ShapeKind kind, std::size_t given) {
  const KindCodec c = codec_of(kind);
  switch (c.layout) {
    case Layout::Fixed:
      return c.fields.size();
    case Layout::Vertices:
      return given - given % c.fields.size();
    case Layout::Children:
      return 0;
  }
  return 0;
}

/// The codec of Transform<T>: px py qx qy; values -> transform through make_with_rotation(),
/// which keeps a stored rotation bit for bit.
struct TransformCodec {
  static constexpr std::array<Field, 4> fields = {
      {{"px", Role::X}, {"py", Role::Y}, {"qx", Role::Other}, {"qy", Role::Other}}};
  /// The values of the identity.
  static constexpr std::array<double, 4> identity = {0, 0, 1, 0};
  template <Scalar T>
  static TransformData values(const Transform<T>& xf) {
    return {{xf.position().x(), xf.position().y(), xf.rotation().x(), xf.rotation().y()}};
  }
  template <Scalar T>
  static Expected<Transform<T>> make(std::span<const T, 4> x) {
    return Transform<T>::make_with_rotation(Vec2<T>(x[0], x[1]), Vec2<T>(x[2], x[3]));
  }
};

// ---------------------------------------------------------------------------------------------
// Shape <-> stored values.

namespace codec_detail {

/// Hex float: every bit.
inline std::string hex(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

/// The value as T, exactly, or a CodecError.
template <Scalar T>
T narrow(double v) {
  const T t = static_cast<T>(v);
  if (!(double(t) == v) && !(std::isnan(v) && std::isnan(t)))
    throw CodecError("value " + hex(v) + " is not exactly representable as the case's scalar");
  return t;
}

template <Scalar T>
std::vector<T> narrow_all(const std::vector<double>& values) {
  std::vector<T> x;
  x.reserve(values.size());
  for (double v : values) x.push_back(narrow<T>(v));
  return x;
}

inline void check_count(ShapeKind kind, std::size_t got) {
  const KindCodec c = codec_of(kind);
  const std::size_t per = c.fields.size();
  const bool ok = c.layout == Layout::Fixed ? got == per : c.layout == Layout::Vertices ? got % per == 0 : got == 0;
  if (!ok)
    throw CodecError(std::string(name(kind)) + " needs " +
                     (c.layout == Layout::Fixed ? std::to_string(per) + " values"
                                                : "a multiple of " + std::to_string(per) + " values") +
                     ", got " + std::to_string(got));
}

template <class S>
S valid(Expected<S> r) {
  if (!r) throw CodecError(std::string("stored values rejected: ") + r.error().what());
  return std::move(r).value();
}

}  // namespace codec_detail

/// The stored values of a transform.
template <Scalar T>
TransformData to_data(const Transform<T>& xf) {
  return TransformCodec::values(xf);
}

/// Rebuilds the transform with exactly the stored bits; CodecError when a value is not
/// representable, rejected (NonFinite, OutOfRange, ZeroRotation), or the rotation is not kept
/// (not unit within make_with_rotation()'s tolerance).
template <Scalar T>
Transform<T> transform_from_data(const TransformData& d) {
  std::array<T, 4> x{};
  for (std::size_t i = 0; i < 4; ++i) x[i] = codec_detail::narrow<T>(d.values[i]);
  const Transform<T> xf = codec_detail::valid(TransformCodec::make<T>(std::span<const T, 4>(x)));
  if (TransformCodec::values(xf).values != d.values)
    throw CodecError("stored transform rotation is not kept by make_with_rotation (not a unit vector)");
  return xf;
}

/// The stored values of a primitive or of any shape (a compound: its children's).
template <Scalar T>
ShapeData to_data(const Shape<T>& s) {
  return std::visit(
      [](const auto& x) -> ShapeData {
        constexpr ShapeKind K = kind_of_v<std::remove_cvref_t<decltype(x)>>;
        ShapeData d;
        d.kind = K;
        if constexpr (Codec<K>::layout == Layout::Children) {
          for (std::size_t i = 0; i < x.children().size(); ++i) {
            d.children.push_back(to_data(to_shape(x.children()[i])));
            const Transform<T> placement = x.child_transform(i);
            if (!placement.is_identity()) d.children.back().placement = TransformCodec::values(placement);
          }
        } else {
          for (T v : Codec<K>::template values<T>(x)) d.values.push_back(double(v));
        }
        return d;
      },
      s);
}

/// Rebuilds the shape with exactly the stored bits through the kind's factory. Throws
/// CodecError when the values do not make that shape: a wrong count, a value not representable
/// in T, the factory's named error, or a shape whose stored values differ from the given ones
/// (an OBB axis that is not unit, a polygon not in normal form).
template <Scalar T>
Shape<T> from_data(const ShapeData& d) {
  return visit_kind(d.kind, [&]<ShapeKind K>() -> Shape<T> {
    using codec_detail::valid;
    codec_detail::check_count(K, d.values.size());
    if constexpr (Codec<K>::layout == Layout::Children) {
      if (d.children.empty()) throw CodecError(std::string(name(K)) + " needs at least one child");
      if (d.placement) throw CodecError(std::string("a ") + std::string(name(K)) + " has no placement of its own");
      std::vector<typename ShapeOf<K, T>::Child> children;
      for (const ShapeData& c : d.children) {
        if (c.kind == K) throw CodecError(std::string("a ") + std::string(name(K)) + " cannot be a child");
        ShapeData local = c;
        local.placement.reset();
        const Transform<T> placement = c.placement ? transform_from_data<T>(*c.placement) : Transform<T>();
        std::visit(
            [&](const auto& x) {
              if constexpr (std::is_constructible_v<Primitive<T>, decltype(x)>) children.push_back({x, placement});
            },
            from_data<T>(local));
      }
      return valid(ShapeOf<K, T>::make_placed(std::move(children)));
    } else {
      if (d.placement) throw CodecError("only a compound child has a placement");
      const std::vector<T> x = codec_detail::narrow_all<T>(d.values);
      const ShapeOf<K, T> s = valid(Codec<K>::template make<T>(std::span<const T>(x)));
      if (Codec<K>::template values<T>(s) != x) {
        std::string stored;
        for (T v : Codec<K>::template values<T>(s)) {
          stored += ' ';
          stored += codec_detail::hex(double(v));
        }
        throw CodecError(std::string("stored ") + std::string(name(K)) +
                         " values are not kept by its factory (rebuilt as" + stored + ")");
      }
      return s;
    }
  });
}

// ---------------------------------------------------------------------------------------------
// Stored values <-> text: "<kind> [count] values..." with hex floats; a compound is
// "compound N" followed by N lines "<child_key> <kind> values...".

/// Writes `head <kind> ...` and, for a compound, its child lines (`child <kind> ...`, ending in
/// `at px py qx qy` for a child placed by a transform other than the identity).
inline void write_text(std::ostream& out, std::string_view head, const ShapeData& d) {
  const KindCodec c = codec_of(d.kind);
  out << head << ' ' << name(d.kind);
  if (c.layout == Layout::Children) {
    out << ' ' << d.children.size() << '\n';
    for (const ShapeData& child : d.children) write_text(out, "child", child);
    return;
  }
  if (c.layout == Layout::Vertices) out << ' ' << d.values.size() / c.fields.size();
  for (double v : d.values) out << ' ' << codec_detail::hex(v);
  if (d.placement) {
    out << " at";
    for (double v : d.placement->values) out << ' ' << codec_detail::hex(v);
  }
  out << '\n';
}

/// A number in a text form: hex or decimal floats, "nan", "inf".
inline double parse_value(const std::string& tok) {
  char* end = nullptr;
  const double v = std::strtod(tok.c_str(), &end);
  if (end == tok.c_str() || *end != '\0') throw CodecError("not a number: '" + tok + "'");
  return v;
}

/// The kind named by a token.
inline ShapeKind parse_kind(const std::string& tok) {
  const auto k = kind_from_name(tok);
  if (!k) throw CodecError("unknown shape kind '" + tok + "'");
  return *k;
}

/// Reads "px py qx qy"; the line must end there.
inline TransformData read_transform_text(std::istream& in) {
  TransformData d;
  std::string tok;
  for (double& v : d.values) {
    if (!(in >> tok)) throw CodecError("a transform needs px py qx qy");
    v = parse_value(tok);
  }
  if (in >> tok) throw CodecError("extra value '" + tok + "'");
  return d;
}

/// Reads the values of `kind` after its name from a line (Vertices: the vertex count first;
/// Children: the child count, returned in `children` for the caller to read that many lines).
/// A child line (no `children` pointer) may end in `at px py qx qy`, its placement. The line
/// must end there.
inline ShapeData read_text(std::istream& in, ShapeKind kind, std::size_t* children = nullptr) {
  const KindCodec c = codec_of(kind);
  ShapeData d;
  d.kind = kind;
  std::size_t n = c.fields.size();
  if (c.layout != Layout::Fixed) {
    std::size_t count = 0;
    if (!(in >> count)) throw CodecError(std::string(name(kind)) + " needs a count");
    if (c.layout == Layout::Children) {
      if (count == 0) throw CodecError(std::string(name(kind)) + " needs a child count >= 1");
      if (children == nullptr) throw CodecError(std::string("a ") + std::string(name(kind)) + " cannot be a child");
      *children = count;
      n = 0;
    } else {
      n = count * c.fields.size();
    }
  }
  std::string tok;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(in >> tok)) throw CodecError("too few values");
    if (tok == "at") throw CodecError("too few values before 'at'");
    d.values.push_back(parse_value(tok));
  }
  if (in >> tok) {
    if (tok != "at" || children != nullptr) throw CodecError("extra value '" + tok + "'");
    d.placement = read_transform_text(in);
  }
  return d;
}

/// "px py qx qy" in hex.
inline void write_text(std::ostream& out, std::string_view head, const TransformData& d) {
  out << head;
  for (double v : d.values) out << ' ' << codec_detail::hex(v);
  out << '\n';
}

// ---------------------------------------------------------------------------------------------
// Bytes -> stored values (the fuzz input format of collide/fuzz/decode.hpp): a kind byte (index
// in kKinds; a compound's child: the same index, the compound being last), the kind's
// byte_prefix, a count byte for Vertices and Children, then each value as the raw bits of T.
// The corpus script writes this form from collide_describe's account of the codecs.

/// Reads `count` values of kind K (Vertices: count vertices; Fixed: count is ignored) from a
/// source with `T scalar<T>(Role)` (the fuzz Reader), in field order with the fields' roles.
template <ShapeKind K, Scalar T, class Source>
std::vector<T> read_values(Source& source, std::size_t count = 1) {
  static_assert(Codec<K>::layout != Layout::Children, "a compound's children are read one by one");
  const std::size_t groups = Codec<K>::layout == Layout::Vertices ? count : 1;
  std::vector<T> out;
  out.reserve(groups * Codec<K>::fields.size());
  for (std::size_t g = 0; g < groups; ++g) {
    for (const Field& f : Codec<K>::fields) out.push_back(source.template scalar<T>(f.role));
  }
  return out;
}

/// Reads a transform's four values from such a source.
template <Scalar T, class Source>
std::array<T, 4> read_transform_values(Source& source) {
  std::array<T, 4> out{};
  for (std::size_t i = 0; i < 4; ++i) out[i] = source.template scalar<T>(TransformCodec::fields[i].role);
  return out;
}

}  // namespace collide::laws
