#pragma once
/// @file error.hpp
/// Named errors for rejected shapes, and Expected<V>, the non-throwing result of every factory.

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>
#include <utility>
#include <variant>

namespace collide {

/// Why a shape was rejected. Every factory documents which of these it can return.
enum class Error : std::uint8_t {
  NonFinite,          ///< a value is NaN or infinite
  OutOfRange,         ///< a value's magnitude exceeds max_magnitude<T>() (2^125 for float, 2^500 for double),
                      ///< or a mass property exceeds T's largest finite value
  NegativeRadius,     ///< circle or capsule radius < 0
  NegativeExtent,     ///< OBB half extent < 0
  MinGreaterThanMax,  ///< AABB min exceeds max on an axis (index() names the axis: 0 = x, 1 = y)
  ZeroAxis,           ///< OBB rotation given as a zero vector
  TooFewVertices,     ///< fewer than 3 distinct polygon vertices, or too few chain points (chain.hpp)
  Collinear,          ///< all polygon vertices lie on one line: the polygon has no area
  NonConvex,          ///< polygon turns the wrong way, doubles back or winds more than once at index()
  NotARectangle,      ///< four corners given to an OBB do not form a rectangle
  EmptyCompound,      ///< a compound with no children
  ZeroRotation,       ///< a transform's rotation given as the zero vector
  NegativeDensity,    ///< mass_properties() given a density < 0
  CompoundOuter,      ///< contains(outer, inner) given a compound outer: containment in a union is not decided
  ZeroLengthSegment,  ///< two consecutive chain points coincide
  FoldedChain,        ///< a chain turns straight back on itself at index()
};

/// Stable name of an error, e.g. "NonConvex".
constexpr std::string_view name(Error e) noexcept {
  switch (e) {
    case Error::NonFinite:
      return "NonFinite";
    case Error::OutOfRange:
      return "OutOfRange";
    case Error::NegativeRadius:
      return "NegativeRadius";
    case Error::NegativeExtent:
      return "NegativeExtent";
    case Error::MinGreaterThanMax:
      return "MinGreaterThanMax";
    case Error::ZeroAxis:
      return "ZeroAxis";
    case Error::TooFewVertices:
      return "TooFewVertices";
    case Error::Collinear:
      return "Collinear";
    case Error::NonConvex:
      return "NonConvex";
    case Error::NotARectangle:
      return "NotARectangle";
    case Error::EmptyCompound:
      return "EmptyCompound";
    case Error::ZeroRotation:
      return "ZeroRotation";
    case Error::NegativeDensity:
      return "NegativeDensity";
    case Error::CompoundOuter:
      return "CompoundOuter";
    case Error::ZeroLengthSegment:
      return "ZeroLengthSegment";
    case Error::FoldedChain:
      return "FoldedChain";
  }
  return "Unknown";
}

/// Thrown by the throwing constructors; carried by a failed Expected.
/// index() is the offending input index (vertex, axis, value or child), or -1 when none applies.
/// The message is kept in a fixed buffer, so building, copying and returning a ShapeError never
/// allocates (factories run every frame); a message longer than the buffer is cut.
class ShapeError : public std::exception {
 public:
  /// `what` is a short account of the problem; the message reads "<name>: <what> (index <i>)".
  ShapeError(Error code, long index, std::string_view what) noexcept : code_(code), index_(index) {
    std::size_t n = 0;
    const auto put = [&](std::string_view part) {
      const std::size_t k = std::min(part.size(), kMessageCapacity - 1 - n);
      part.copy(message_.data() + n, k);
      n += k;
    };
    put(name(code));
    put(": ");
    put(what);
    if (index >= 0) {
      std::array<char, 24> digits{};
      const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), index).ptr;
      put(" (index ");
      put(std::string_view(digits.data(), std::size_t(end - digits.data())));
      put(")");
    }
    message_[n] = '\0';
  }
  /// The named error.
  Error code() const noexcept { return code_; }
  /// The offending input index, or -1.
  long index() const noexcept { return index_; }
  /// "<name>: <what> (index <i>)", e.g. "NonConvex: polygon turns the wrong way (index 3)".
  const char* what() const noexcept override { return message_.data(); }

 private:
  static constexpr std::size_t kMessageCapacity = 96;
  std::array<char, kMessageCapacity> message_{};
  Error code_;
  long index_;
};

/// A valid value or the ShapeError that rejected it. value() throws the error.
template <class V>
class Expected {
 public:
  /// Holds a value.
  Expected(V v) : data_(std::move(v)) {}  // NOLINT(google-explicit-constructor)
  /// Holds the error that rejected the value.
  Expected(ShapeError e) : data_(std::move(e)) {}  // NOLINT(google-explicit-constructor)
  /// True when a value is held.
  bool has_value() const noexcept { return data_.index() == 0; }
  /// Same as has_value().
  explicit operator bool() const noexcept { return has_value(); }
  /// The value; throws the held ShapeError when there is none.
  const V& value() const& {
    if (!has_value()) throw std::get<1>(data_);
    return std::get<0>(data_);
  }
  /// The value, moved out; throws the held ShapeError when there is none.
  V&& value() && {
    if (!has_value()) throw std::get<1>(data_);
    return std::get<0>(std::move(data_));
  }
  /// The value. Precondition: has_value() (checked by std::get: throws std::bad_variant_access).
  const V& operator*() const& { return std::get<0>(data_); }
  /// The value, moved out. Precondition: has_value().
  V&& operator*() && { return std::get<0>(std::move(data_)); }
  /// Member access to the value. Precondition: has_value().
  const V* operator->() const { return &std::get<0>(data_); }
  /// The value, or `fallback` when there is none.
  V value_or(V fallback) const& { return has_value() ? std::get<0>(data_) : std::move(fallback); }
  /// The value moved out, or `fallback` when there is none.
  V value_or(V fallback) && { return has_value() ? std::get<0>(std::move(data_)) : std::move(fallback); }
  /// The error. Precondition: !has_value().
  const ShapeError& error() const { return std::get<1>(data_); }

 private:
  std::variant<V, ShapeError> data_;
};

}  // namespace collide
