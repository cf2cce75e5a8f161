#pragma once
/// @file hash.hpp
/// The one FNV-1a (32 bit) of the C++ side: case file stems and raw fuzz input names. Its
/// Python twin is scripts/collide_tools.py's fnv1a(); both must give the same names.

#include <cstdint>
#include <span>
#include <string_view>

namespace collide::laws {

/// FNV-1a, 32 bit, of the bytes.
constexpr std::uint32_t fnv1a(std::span<const std::uint8_t> bytes) noexcept {
  std::uint32_t h = 2166136261u;
  for (const std::uint8_t b : bytes) h = (h ^ b) * 16777619u;
  return h;
}

/// FNV-1a, 32 bit, of the characters' bytes.
constexpr std::uint32_t fnv1a(std::string_view text) noexcept {
  std::uint32_t h = 2166136261u;
  for (const char ch : text) h = (h ^ static_cast<unsigned char>(ch)) * 16777619u;
  return h;
}

}  // namespace collide::laws
