#pragma once
// 128-bit integers to double, for the reporting side only (DESIGN.md, determinism rule 1: floating
// point appears after the deterministic run, in statistics and reports). The kernel itself has no
// floating point at all, so this conversion lives here, beside the algorithms that report an exact
// 128-bit quantity as a double (the Buffon stopping rule's spreads).
//
// On 64-bit hosts kernel::int128 is the built-in __int128 and converts as the language says. On
// 32-bit targets (armhf, the Cortex-M4) it is kernel::soft::Int, which soft_to_double converts
// correctly rounded, as the built-in conversion does: the value cut to its top 64 bits with every
// bit cut off folded into the lowest one (sticky), which lies at least 11 bits below where a
// double rounds, then scaled by a power of two (exact). tests/kernel/test_int128.cpp holds it
// against __int128's conversion on random operands.
#include <antkit/kernel/int128.hpp>
#include <antkit/kernel/int_ops.hpp>
#include <cstdint>

namespace antkit::algorithms {

template <bool Signed>
[[nodiscard]] constexpr double soft_to_double(kernel::soft::Int<Signed> v) noexcept {
  if constexpr (Signed) {
    if (v < 0) return -soft_to_double(kernel::soft::Int<false>(-v));
  }
  const std::uint64_t hi = v.hi(), lo = v.lo();
  if (hi == 0) return static_cast<double>(lo);
  int s = 64;
  while ((hi >> (s - 1)) == 0) --s; // hi's significant bits: the shift that fits 64 bits
  const std::uint64_t m = s == 64 ? hi : (hi << (64 - s)) | (lo >> s);
  const bool sticky = s == 64 ? lo != 0 : (lo << (64 - s)) != 0;
  double scale = 1;
  for (int i = 0; i < s; ++i) scale *= 2;
  return static_cast<double>(m | (sticky ? 1 : 0)) * scale;
}

// kernel::int128 or kernel::uint128 (whichever type the target has) to the nearest double.
[[nodiscard]] constexpr double to_double(kernel::int128 v) noexcept {
#if defined(__SIZEOF_INT128__)
  return static_cast<double>(v);
#else
  return soft_to_double(v);
#endif
}
[[nodiscard]] constexpr double to_double(kernel::uint128 v) noexcept {
#if defined(__SIZEOF_INT128__)
  return static_cast<double>(v);
#else
  return soft_to_double(v);
#endif
}

} // namespace antkit::algorithms
