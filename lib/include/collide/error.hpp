#pragma once
/// @file error.hpp
/// Named errors for rejected shapes, and Expected<V>, the non-throwing result of every factory.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace collide {

/// Why a shape was rejected. Every factory documents which of these it can return.
enum class Error : std::uint8_t {
  NonFinite,          ///< a value is NaN or infinite
  OutOfRange,         ///< a value's magnitude exceeds max_magnitude<T>() (2^125 for float, 2^500 for double)
  NegativeRadius,     ///< circle or capsule radius < 0
  NegativeExtent,     ///< OBB half extent < 0
  MinGreaterThanMax,  ///< AABB min exceeds max on an axis (index() names the axis: 0 = x, 1 = y)
  ZeroAxis,           ///< OBB rotation given as a zero vector
  TooFewVertices,     ///< fewer than 3 distinct polygon vertices
  Collinear,          ///< all polygon vertices lie on one line: the polygon has no area
  NonConvex,          ///< polygon turns the wrong way, doubles back or winds more than once at index()
  NotARectangle,      ///< four corners given to an OBB do not form a rectangle
  EmptyCompound,      ///< a compound with no children
};

/// Stable name of an error, e.g. "NonConvex".
constexpr std::string_view name(Error e) noexcept {
  switch (e) {
    case Error::NonFinite: return "NonFinite";
    case Error::OutOfRange: return "OutOfRange";
    case Error::NegativeRadius: return "NegativeRadius";
    case Error::NegativeExtent: return "NegativeExtent";
    case Error::MinGreaterThanMax: return "MinGreaterThanMax";
    case Error::ZeroAxis: return "ZeroAxis";
    case Error::TooFewVertices: return "TooFewVertices";
    case Error::Collinear: return "Collinear";
    case Error::NonConvex: return "NonConvex";
    case Error::NotARectangle: return "NotARectangle";
    case Error::EmptyCompound: return "EmptyCompound";
  }
  return "Unknown";
}

/// Thrown by the throwing constructors; carried by a failed Expected.
/// index() is the offending input index (vertex, axis, value or child), or -1 when none applies.
class ShapeError : public std::invalid_argument {
 public:
  ShapeError(Error code, long index, std::string_view what)
      : std::invalid_argument(std::string(name(code)) + ": " + std::string(what) +
                              (index >= 0 ? " (index " + std::to_string(index) + ")" : "")),
        code_(code),
        index_(index) {}
  Error code() const noexcept { return code_; }
  long index() const noexcept { return index_; }

 private:
  Error code_;
  long index_;
};

/// A valid value or the ShapeError that rejected it. value() throws the error.
template <class V>
class Expected {
 public:
  Expected(V v) : data_(std::move(v)) {}                    // NOLINT(google-explicit-constructor)
  Expected(ShapeError e) : data_(std::move(e)) {}           // NOLINT(google-explicit-constructor)
  bool has_value() const noexcept { return data_.index() == 0; }
  explicit operator bool() const noexcept { return has_value(); }
  const V& value() const& {
    if (!has_value()) throw std::get<1>(data_);
    return std::get<0>(data_);
  }
  V&& value() && {
    if (!has_value()) throw std::get<1>(data_);
    return std::get<0>(std::move(data_));
  }
  /// Precondition: !has_value().
  const ShapeError& error() const { return std::get<1>(data_); }

 private:
  std::variant<V, ShapeError> data_;
};

}  // namespace collide
