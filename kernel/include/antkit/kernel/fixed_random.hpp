#pragma once
// Fixed-point and binary-angle uniforms drawn from the keyed streams (DESIGN.md, rule 2).
//
// uniform(stream, a, b) is uniform over the raw values of the closed interval [a, b]: each of the
// (b.raw - a.raw + 1) representable numbers has probability exactly 1 / (b.raw - a.raw + 1).
// "Unbiased to the raw resolution" is meant literally: the integer offset is drawn with Lemire's
// multiply-shift map and rejection (the same function as Stream::below, random.hpp's
// lemire_bounded, at 32 or 64 bits), so no residue of 2^32 or 2^64 modulo the count leaks into the
// result.
//
// Draws: for formats of at most 32 bits each attempt takes one 32-bit word (Stream::next_u32), for
// 64-bit formats one 64-bit word (Stream::next_u64); an attempt is rejected with probability
// (2^w mod count) / 2^w < count / 2^w, so for the spans a robot uses (a step length, an arena
// side) almost every call takes exactly one attempt. How many words a call consumed is a function
// of the stream's contents only, so runs remain reproducible.
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/int_ops.hpp>
#include <antkit/kernel/random.hpp>
#include <cstdint>
#include <stdexcept>
#include <type_traits>

namespace antkit::kernel {

// The offsets use lemire_bounded (random.hpp), the one copy of Lemire's map, whose 32-bit
// instantiation proofs/z3/bounded_u32.cpp proves.

// Uniform raw offset in [0, span] (span + 1 values; span may be the largest word, then every word
// is accepted as it is).
inline std::uint32_t uniform_offset_u32(Stream& stream, std::uint32_t span) noexcept {
  if (span == 0xFFFFFFFFu) return stream.next_u32();
  std::uint32_t out = 0;
  while (!lemire_bounded<std::uint32_t, std::uint64_t>(stream.next_u32(), span + 1u, out)) {
  }
  return out;
}
inline std::uint64_t uniform_offset_u64(Stream& stream, std::uint64_t span) noexcept {
  if (span == ~std::uint64_t{0}) return stream.next_u64();
  std::uint64_t out = 0;
  while (!lemire_bounded<std::uint64_t, uint128>(stream.next_u64(), span + 1u, out)) {
  }
  return out;
}

// Uniform over the representable numbers of [a, b]; throws std::invalid_argument when a > b (a
// programming error: an empty interval has no uniform distribution, and silently swapping the ends
// would hide a sign error in the caller).
template <class Rep, int F>
Fixed<Rep, F> uniform(Stream& stream, Fixed<Rep, F> a, Fixed<Rep, F> b) {
#if defined(__cpp_exceptions)
  if (b < a) throw std::invalid_argument("uniform(a, b) needs a <= b");
#else // freestanding (-fno-exceptions, mcu/): the same programming error stops the program
  if (b < a) __builtin_trap();
#endif
  using URep = typename ops::int_info<Rep>::unsigned_type;
  // b - a as an unsigned count of ulps: exact modulo 2^N, and < 2^N because a <= b.
  const URep span = ops::wrap_sub(ops::as_unsigned(b.raw()), ops::as_unsigned(a.raw()));
  URep offset{};
  if constexpr (ops::int_info<Rep>::bits <= 32) {
    offset = static_cast<URep>(uniform_offset_u32(stream, span));
  } else {
    static_assert(ops::int_info<Rep>::bits == 64, "uniform supports formats of up to 64 bits");
    offset = static_cast<URep>(uniform_offset_u64(stream, span));
  }
  return Fixed<Rep, F>::from_raw(ops::as_signed(ops::wrap_add(ops::as_unsigned(a.raw()), offset)));
}

// Uniform over all 2^32 binary angles (a uniform heading): one 32-bit word.
inline Angle uniform_angle(Stream& stream) noexcept {
  return Angle::from_raw(stream.next_u32());
}

} // namespace antkit::kernel
