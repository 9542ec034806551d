#pragma once
// Unsigned integers read from little-endian bytes, whatever the host's byte order: the Cortex-M
// inputs of STC and Buffon (stc/mcu_input.hpp, buffon/mcu_input.hpp), read the same by the host
// and the chip. Freestanding: <cstdint> only.
#include <cstdint>

namespace antkit::algorithms {

// The `bytes` (1 to 8) bytes at p, least significant first.
[[nodiscard]] constexpr std::uint64_t load_le(const std::uint8_t* p, int bytes) noexcept {
  std::uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

// A two's-complement 32-bit integer from its 4 little-endian bytes at p.
[[nodiscard]] constexpr std::int32_t load_le_i32(const std::uint8_t* p) noexcept {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(load_le(p, 4)));
}

} // namespace antkit::algorithms
