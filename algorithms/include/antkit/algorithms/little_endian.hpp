#pragma once
// Unsigned integers as little-endian bytes, whatever the host's byte order: the Cortex-M inputs
// (stc/mcu_input.hpp, buffon/mcu_input.hpp, buffon/rs_mcu_input.hpp,
// uniform/wanderer_mcu_input.hpp), written by the host (append_le) and read the same by the host
// and the chip (load_le). Freestanding: <cstdint> only.
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

// Appends the `bytes` (1 to 8) low bytes of v to out, least significant first. Bytes is any
// container of std::uint8_t with push_back (the host's std::vector).
template <class Bytes>
constexpr void append_le(Bytes& out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

} // namespace antkit::algorithms
