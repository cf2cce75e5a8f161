#pragma once
/// @file decode.hpp
/// Structure-aware decoding of fuzz input into shapes, driven by the registry: a kind byte picks
/// the kind (visit_kind), and Decoder<K, T> reads that kind's values. A kind added to the registry
/// without a Decoder fails to compile here.
///
/// Byte format of one shape (scalars are raw bit patterns, 4 bytes for float, 8 for double):
///   kind byte (value % kKindCount indexes kKinds), then the kind's codec values (codec.hpp, in
///   field order: circle cx cy r; aabb minx miny maxx maxy; capsule ax ay bx by r), except:
///   obb      form byte (% 3): 0 = make(center, half, angle): cx cy hx hy angle
///                             1 = the codec's values:       cx cy hx hy ux uy (make_with_axis)
///                             2 = from_corners:             p0 p1 p2 p3 (x y each)
///   polygon  count byte: low 4 bits = vertex count (0..15), bit 7 = make_hull instead of make;
///            then count points (the codec's x y per vertex)
///   compound count byte (low 7 bits % 5 children; 0 is rejected as EmptyCompound; bit 7: each
///            child is followed by its child transform, px py qx qy as decode_transform reads
///            it); each child is a kind byte (% (kKindCount - 1): every kind but compound) and
///            that kind's values.
/// A transform (decode_transform): px py qx qy through make_with_rotation (codec.hpp).

#include "collide/collide.hpp"
#include "collide/fuzz/reader.hpp"
#include "collide/laws/codec.hpp"

#include <array>
#include <cstdio>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace collide::fuzz {

/// Which entry point builds the shape: the factory make(...) (returns Expected) or the throwing
/// constructor with the same arguments (its ShapeError is caught into an Expected).
enum class Build : std::uint8_t { Factory, Constructor };

namespace detail {
template <class S, class Make, class Construct>
Expected<S> build_with(Build how, Make&& make, Construct&& construct) {
  if (how == Build::Factory) return make();
  try {
    return construct();
  } catch (const ShapeError& e) {
    return e;
  }
}
}  // namespace detail

/// Builds kind K from its codec's stored values, by the factory or the throwing constructor.
template <ShapeKind K, Scalar T>
Expected<ShapeOf<K, T>> build_stored(std::span<const T> values, Build how) {
  return detail::build_with<ShapeOf<K, T>>(
      how, [&] { return laws::Codec<K>::template make<T>(values); },
      [&] { return laws::Codec<K>::template construct<T>(values); });
}

/// Reads the values of one kind K and builds the shape. The primary template reads the codec's
/// stored values (codec.hpp) after its byte prefix; kinds with other entry points specialise it.
/// stored_values(first) says whether an input whose first byte after the kind byte is `first`
/// holds exactly the codec's values (then law "rejection" judges it).
template <ShapeKind K, Scalar T>
struct Decoder {
  static_assert(laws::Codec<K>::layout == laws::Layout::Fixed && laws::Codec<K>::byte_prefix.empty(),
                "a kind with a count or a prefix needs its own Decoder");
  static Expected<ShapeOf<K, T>> decode(Reader& r, Build how) {
    const std::vector<T> x = laws::read_values<K, T>(r);
    return build_stored<K, T>(std::span<const T>(x), how);
  }
  static constexpr bool stored_values(std::uint8_t) { return true; }
};

template <Scalar T>
struct Decoder<ShapeKind::Obb, T> {
  static Expected<Obb<T>> decode(Reader& r, Build how) {
    const int form = r.byte() % 3;
    if (form == 1) {
      const std::vector<T> x = laws::read_values<ShapeKind::Obb, T>(r);
      return build_stored<ShapeKind::Obb, T>(std::span<const T>(x), how);
    }
    if (form == 2) {
      const Vec2<T> p0 = r.point<T>(), p1 = r.point<T>(), p2 = r.point<T>(), p3 = r.point<T>();
      return Obb<T>::from_corners(p0, p1, p2, p3);  // no throwing form exists
    }
    const Vec2<T> c = r.point<T>();
    const T hx = r.scalar<T>(Role::Size);
    const T hy = r.scalar<T>(Role::Size);
    const Vec2<T> half(hx, hy);
    const T angle = r.scalar<T>(Role::Other);
    return detail::build_with<Obb<T>>(
        how, [&] { return Obb<T>::make(c, half, angle); }, [&] { return Obb<T>(c, half, angle); });
  }
  static_assert(laws::Codec<ShapeKind::Obb>::byte_prefix[0] == 1, "form 1 reads the codec's values");
  static constexpr bool stored_values(std::uint8_t form) { return form % 3 == 1; }
};

template <Scalar T>
struct Decoder<ShapeKind::Polygon, T> {
  static constexpr std::size_t kMaxVertices = 15;
  static Expected<ConvexPolygon<T>> decode(Reader& r, Build how) {
    const std::uint8_t head = r.byte();
    const bool hull = !stored_values(head);
    const std::vector<T> x = laws::read_values<ShapeKind::Polygon, T>(r, head & 0x0f);
    if (hull) {
      const std::vector<Vec2<T>> pts = laws::Codec<ShapeKind::Polygon>::points<T>(std::span<const T>(x));
      return ConvexPolygon<T>::make_hull(std::span<const Vec2<T>>(pts));  // no throwing form exists
    }
    return build_stored<ShapeKind::Polygon, T>(std::span<const T>(x), how);
  }
  static constexpr bool stored_values(std::uint8_t head) { return (head & 0x80) == 0; }
};

/// One compound child: any kind but compound.
template <Scalar T>
Expected<Primitive<T>> decode_primitive(Reader& r, Build how) {
  static_assert(kKinds.back() == ShapeKind::Compound, "compound must be the last kind");
  const ShapeKind k = kKinds[r.byte() % (kKindCount - 1)];
  return visit_kind(k, [&]<ShapeKind K>() -> Expected<Primitive<T>> {
    if constexpr (K == ShapeKind::Compound) {
      return ShapeError(Error::EmptyCompound, -1, "unreachable: a compound child cannot be a compound");
    } else {
      auto s = Decoder<K, T>::decode(r, how);
      if (!s) return s.error();
      return Primitive<T>(std::move(s).value());
    }
  });
}

/// A transform's stored values px py qx qy (codec.hpp), through make_with_rotation().
template <Scalar T>
Expected<Transform<T>> decode_transform(Reader& r) {
  const std::array<T, 4> x = laws::read_transform_values<T>(r);
  return laws::TransformCodec::make<T>(std::span<const T, 4>(x));
}

template <Scalar T>
struct Decoder<ShapeKind::Compound, T> {
  static constexpr std::size_t kMaxChildren = 4;
  static Expected<Compound<T>> decode(Reader& r, Build how) {
    const std::uint8_t head = r.byte();
    const std::size_t n = (head & 0x7f) % (kMaxChildren + 1);
    const bool placed = (head & 0x80) != 0;
    std::vector<typename Compound<T>::Child> children;
    children.reserve(n);
    // Read every child even after a rejection, so the bytes after the compound mean the same.
    std::optional<ShapeError> first_error;
    for (std::size_t i = 0; i < n; ++i) {
      Expected<Primitive<T>> c = decode_primitive<T>(r, how);
      const Expected<Transform<T>> x = placed ? decode_transform<T>(r) : Expected<Transform<T>>(Transform<T>());
      if (c && x) {
        children.push_back({std::move(c).value(), x.value()});
      } else if (!first_error) {
        first_error = c ? x.error() : c.error();
      }
    }
    if (first_error) return *first_error;
    if (placed) return Compound<T>::make_placed(std::move(children));  // no throwing form exists
    std::vector<Primitive<T>> shapes;
    for (auto& c : children) shapes.push_back(std::move(c.shape));
    return detail::build_with<Compound<T>>(
        how, [&] { return Compound<T>::make(shapes); }, [&] { return Compound<T>(shapes); });
  }
  static constexpr bool stored_values(std::uint8_t) { return false; }
};

/// Reads a kind byte and that kind's values.
template <Scalar T>
Expected<Shape<T>> decode_shape(Reader& r, Build how = Build::Factory) {
  const ShapeKind k = kKinds[r.byte() % kKindCount];
  return visit_kind(k, [&]<ShapeKind K>() -> Expected<Shape<T>> {
    auto s = Decoder<K, T>::decode(r, how);
    if (!s) return s.error();
    return Shape<T>(std::move(s).value());
  });
}

/// Flags byte at the start of every pair input.
struct PairHeader {
  bool is_double;     ///< bit 0: scalar is double (else float)
  bool placed;        ///< bit 6: a transform follows each shape (targets that place shapes)
  std::uint8_t bits;  ///< the whole byte, for target-specific options in bits 1..5 and 7
};

/// The flags bit of PairHeader::placed.
inline constexpr std::uint8_t kPlacedBit = 0x40;

namespace detail {
/// The one pair decoder: "flags byte, shape a (group 0) [its transform (group 4)], shape b
/// (group 1) [its transform (group 5)]", the transforms read only when `placing` and the flags
/// ask for them (identities otherwise; the mutator's touching moves only groups 0 and 1). Calls
/// f(header, a, xa, b, xb, reader) when every part is valid; returns whether f was called.
template <class F>
bool decode_pair(Reader& r, bool placing, F&& f) {
  const std::uint8_t flags = r.byte();
  const PairHeader header{(flags & 1) != 0, (flags & kPlacedBit) != 0, flags};
  auto run = [&]<Scalar T>() {
    const bool with_transforms = placing && header.placed;
    auto placement = [&](int group) {
      r.set_group(group);
      return with_transforms ? decode_transform<T>(r) : Expected<Transform<T>>(Transform<T>());
    };
    r.set_group(0);
    Expected<Shape<T>> a = decode_shape<T>(r);
    const Expected<Transform<T>> xa = placement(4);
    r.set_group(1);
    Expected<Shape<T>> b = decode_shape<T>(r);
    const Expected<Transform<T>> xb = placement(5);
    r.set_group(2);
    if (!a || !b || !xa || !xb) return false;
    f(header, a.value(), xa.value(), b.value(), xb.value(), r);
    return true;
  };
  return header.is_double ? run.template operator()<double>() : run.template operator()<float>();
}
}  // namespace detail

/// Decodes "flags byte, shape a (group 0), shape b (group 1)" and calls
/// f(header, a, b, reader) with Shape<float> or Shape<double> shapes when both are valid; the
/// reader is left after b for targets that read more. Returns whether f was called.
template <class F>
bool with_pair(Reader& r, F&& f) {
  return detail::decode_pair(
      r, false, [&](const PairHeader& h, const auto& a, const auto&, const auto& b, const auto&, Reader& rest) {
        f(h, a, b, rest);
      });
}

/// As with_pair, for targets that place shapes: with flags bit 6 each shape is followed by its
/// transform (decode_transform; a rejected transform makes the pair invalid), and f is called
/// as f(header, a, xa, b, xb, reader) (identities without bit 6).
template <class F>
bool with_placed_pair(Reader& r, F&& f) {
  return detail::decode_pair(r, true, f);
}

// ---------------------------------------------------------------------------------------------
// Readable accounts of shapes.

/// A value exactly: shortest round-trip decimal and C99 hex float.
inline std::string format_value(double v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.17g (%a)", v, v);
  return buf;
}

inline std::string format_point(const Vec2c& p) {
  // Built by appending: g++ 12 warns falsely (-Wrestrict) on `"(" + std::string(...)`.
  std::string out = "(";
  out += format_value(p.x());
  out += ", ";
  out += format_value(p.y());
  out += ")";
  return out;
}

namespace detail {
/// Appends "label value" pieces to a description.
inline void add(std::string& out, const char* label, const std::string& value) {
  out += label;
  out += value;
}
}  // namespace detail

template <Scalar T>
std::string describe(const Circle<T>& s) {
  std::string out = "circle";
  detail::add(out, " center ", format_point(widen(s.center())));
  detail::add(out, " radius ", format_value(s.radius()));
  return out;
}
template <Scalar T>
std::string describe(const Aabb<T>& s) {
  std::string out = "aabb";
  detail::add(out, " min ", format_point(widen(s.min())));
  detail::add(out, " max ", format_point(widen(s.max())));
  return out;
}
template <Scalar T>
std::string describe(const Obb<T>& s) {
  std::string out = "obb";
  detail::add(out, " center ", format_point(widen(s.center())));
  detail::add(out, " half ", format_point(widen(s.half_extents())));
  detail::add(out, " axis ", format_point(widen(s.axis())));
  return out;
}
template <Scalar T>
std::string describe(const Capsule<T>& s) {
  std::string out = "capsule";
  detail::add(out, " a ", format_point(widen(s.a())));
  detail::add(out, " b ", format_point(widen(s.b())));
  detail::add(out, " radius ", format_value(s.radius()));
  return out;
}
template <Scalar T>
std::string describe(const ConvexPolygon<T>& s) {
  std::string out = "polygon";
  for (const Vec2<T>& p : s.vertices()) detail::add(out, " ", format_point(widen(p)));
  return out;
}
template <Scalar T>
std::string describe(const Transform<T>& x) {
  std::string out = "transform";
  detail::add(out, " position ", format_point(widen(x.position())));
  detail::add(out, " rotation ", format_point(widen(x.rotation())));
  return out;
}
template <Scalar T>
std::string describe(const Compound<T>& s) {
  std::string out = "compound {";
  for (std::size_t i = 0; i < s.children().size(); ++i) {
    detail::add(out, "\n    ", std::visit([](const auto& x) { return describe(x); }, s.children()[i]));
    if (!s.child_transform(i).is_identity()) detail::add(out, " at ", describe(s.child_transform(i)));
  }
  out += "\n  }";
  return out;
}
template <Scalar T>
std::string describe(const Shape<T>& s) {
  return std::visit([](const auto& x) { return describe(x); }, s);
}

template <Scalar T>
constexpr const char* scalar_name() {
  return std::is_same_v<T, float> ? "float" : "double";
}

}  // namespace collide::fuzz
