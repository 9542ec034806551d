#pragma once
// The one integer square root of the Buffon family: a step's exact length, floor(sqrt(n)) of its
// squared length in raw Q15.16 units. The root itself is the kernel's proved digit-by-digit loop
// (kernel/fixed.hpp isqrt_floor; proofs/z3/fixed_sqrt_step.cpp proves its invariant and the
// end state r^2 <= n < (r + 1)^2). The fast path only saves running it: a guess the caller already
// has (the commanded step length, or the previous step's length, which a robot repeats on most
// steps) is taken when it IS the root, which is checked by the definition itself, r^2 <= n <
// (r + 1)^2; floor(sqrt(n)) is the one integer with that property, so the fast path cannot give
// another answer than the loop. Freestanding (the chip runs it too).
#include <antkit/kernel/fixed.hpp>
#include <cstdint>

namespace antkit::buffon {

// floor(sqrt(n)) by the proved loop: the Q15.16 instantiation (int64, Top 46) below 2^48, the
// Q31.32 one (int128, Top 94) above; both are the instantiations the proofs cover.
inline std::uint64_t isqrt_proved(std::uint64_t n) noexcept {
  if (n < (std::uint64_t{1} << 48)) {
    std::int64_t rest = 0;
    return static_cast<std::uint64_t>(
        kernel::isqrt_floor<std::int64_t, 46>(static_cast<std::int64_t>(n), rest));
  }
  kernel::int128 rest{0};
  return kernel::ops::narrow<std::uint64_t>(
      kernel::isqrt_floor<kernel::int128, 94>(kernel::ops::widen<kernel::int128>(n), rest));
}

// floor(sqrt(n)): `guess` when guess^2 <= n < (guess + 1)^2, else isqrt_proved(n). The squares are
// formed only for guess < 2^32 - 1, where neither wraps.
inline std::uint64_t step_root(std::uint64_t n, std::uint64_t guess) noexcept {
  if (guess < (std::uint64_t{1} << 32) - 1 && guess * guess <= n && n < (guess + 1) * (guess + 1))
    return guess;
  return isqrt_proved(n);
}

} // namespace antkit::buffon
