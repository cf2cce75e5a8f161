#pragma once
/// @file reader.hpp
/// Reads fuzz input bytes as raw bit patterns, and records where every scalar came from so the
/// custom mutator can change coordinates in place.
///
/// Scalars are taken bit for bit (memcpy from the input), so NaN, infinities, subnormals and huge
/// magnitudes all reach the shape factories. Past the end of the input every read yields zero
/// bytes: any byte string decodes, and a truncated input is a valid (shorter) case.

#include "collide/config.hpp"
#include "collide/laws/codec.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace collide::fuzz {

/// What a scalar means, for the mutator: the codec's roles (positions move with their shape,
/// sizes do not; Other also covers angles and ray parameters).
using Role = laws::Role;

/// One scalar of the input: its byte offset and width (4 = float, 8 = double), its role and the
/// index of the shape (group) it belongs to.
struct Field {
  std::size_t offset;
  std::uint8_t width;
  Role role;
  int group;
};

/// Sequential reader over the input bytes.
class Reader {
 public:
  /// log, when given, receives one Field per scalar read.
  Reader(const std::uint8_t* data, std::size_t size, std::vector<Field>* log = nullptr) noexcept
      : data_(data), size_(size), log_(log) {}

  /// Next byte, or 0 past the end.
  std::uint8_t byte() noexcept {
    const std::uint8_t b = pos_ < size_ ? data_[pos_] : 0;
    ++pos_;
    return b;
  }

  /// Next sizeof(T) bytes as the bit pattern of a T (little-endian as stored; missing bytes zero).
  template <Scalar T>
  T scalar(Role role) noexcept {
    unsigned char bytes[sizeof(T)] = {};
    for (std::size_t i = 0; i < sizeof(T); ++i) {
      if (pos_ + i < size_) bytes[i] = data_[pos_ + i];
    }
    if (log_ != nullptr) log_->push_back(Field{pos_, static_cast<std::uint8_t>(sizeof(T)), role, group_});
    pos_ += sizeof(T);
    T v;
    std::memcpy(&v, bytes, sizeof(T));
    return v;
  }

  template <Scalar T>
  Vec2<T> point() noexcept {
    const T x = scalar<T>(Role::X);
    const T y = scalar<T>(Role::Y);
    return Vec2<T>(x, y);
  }

  /// Scalars read from now on belong to shape (group) g.
  void set_group(int g) noexcept { group_ = g; }
  int group() const noexcept { return group_; }

  /// Bytes consumed so far (may exceed size() once reads ran past the end).
  std::size_t position() const noexcept { return pos_; }
  std::size_t size() const noexcept { return size_; }
  /// True once every input byte has been read.
  bool exhausted() const noexcept { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::vector<Field>* log_;
  int group_ = 0;
};

}  // namespace collide::fuzz
