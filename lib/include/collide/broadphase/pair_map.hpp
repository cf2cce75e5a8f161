#pragma once
/// @file broadphase/pair_map.hpp
/// A map from a pair of slot indices to a 32-bit value, for the World's contacts: one flat array
/// probed linearly, so a step that finds a million new contacts makes a few dozen allocations
/// (the array doubling) instead of one per contact, and a lookup reads one or two cache lines.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace collide::detail {

/// Pair (a, b) of slot indices, a < b, as one key (both indices are below 2^32 - 1, so no key
/// equals kNoKey).
inline std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) noexcept {
  if (a > b) {
    const std::uint32_t t = a;
    a = b;
    b = t;
  }
  return (std::uint64_t(a) << 32) | b;
}

/// Open addressing with linear probing and backward-shift deletion (no tombstones, so a long
/// run of inserts and erases never slows the lookups). The table is kept at most half full.
class PairMap {
 public:
  /// Number of keys held.
  std::size_t size() const noexcept { return size_; }

  /// The value of key k, or nullptr.
  const std::uint32_t* find(std::uint64_t k) const noexcept {
    if (table_.empty()) return nullptr;
    for (std::size_t i = home(k);; i = (i + 1) & mask_) {
      if (table_[i].key == k) return &table_[i].value;
      if (table_[i].key == kNoKey) return nullptr;
    }
  }
  /// The value of key k, or nullptr.
  std::uint32_t* find(std::uint64_t k) noexcept {
    return const_cast<std::uint32_t*>(static_cast<const PairMap*>(this)->find(k));
  }

  /// Adds k -> v; k must be absent. Allocates only when the table doubles.
  void insert(std::uint64_t k, std::uint32_t v) {
    if (2 * (size_ + 1) > table_.size()) grow();
    std::size_t i = home(k);
    while (table_[i].key != kNoKey) i = (i + 1) & mask_;
    table_[i] = {k, v};
    ++size_;
  }

  /// Removes k; returns whether it was there, and its value in *v.
  bool erase(std::uint64_t k, std::uint32_t* v) noexcept {
    if (table_.empty()) return false;
    std::size_t i = home(k);
    while (table_[i].key != k) {
      if (table_[i].key == kNoKey) return false;
      i = (i + 1) & mask_;
    }
    *v = table_[i].value;
    // Backward shift: move up every later entry of the run whose home does not lie in (i, j].
    for (std::size_t j = (i + 1) & mask_; table_[j].key != kNoKey; j = (j + 1) & mask_) {
      const std::size_t h = home(table_[j].key);
      const bool stays = i <= j ? (i < h && h <= j) : (i < h || h <= j);
      if (stays) continue;
      table_[i] = table_[j];
      i = j;
    }
    table_[i].key = kNoKey;
    --size_;
    return true;
  }

 private:
  static constexpr std::uint64_t kNoKey = std::numeric_limits<std::uint64_t>::max();
  struct Entry {
    std::uint64_t key = kNoKey;
    std::uint32_t value = 0;
  };

  /// Fibonacci hashing: the top bits of k times 2^64 / phi spread consecutive pairs apart.
  std::size_t home(std::uint64_t k) const noexcept { return std::size_t((k * 0x9E3779B97F4A7C15ull) >> shift_); }

  void grow() {
    std::vector<Entry> old;
    old.swap(table_);
    const std::size_t n = old.empty() ? 16 : 2 * old.size();
    table_.assign(n, Entry{});
    mask_ = n - 1;
    shift_ = 64;
    for (std::size_t m = n; m > 1; m >>= 1) --shift_;
    size_ = 0;
    for (const Entry& e : old)
      if (e.key != kNoKey) insert(e.key, e.value);
  }

  std::vector<Entry> table_;
  std::size_t size_ = 0;
  std::size_t mask_ = 0;
  unsigned shift_ = 64;
};

}  // namespace collide::detail
