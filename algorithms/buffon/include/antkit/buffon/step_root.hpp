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

// Whether r = floor(sqrt(n)), by the definition r^2 <= n < (r + 1)^2; false for r >= 2^32 - 1,
// whose squares could wrap (no such r is a root of an n below 2^64 - 2^33 + 1 anyway).
constexpr bool is_step_root(std::uint64_t n, std::uint64_t r) noexcept {
  return r < (std::uint64_t{1} << 32) - 1 && r * r <= n && n < (r + 1) * (r + 1);
}

// floor(sqrt(n)): `guess` when it is the root; else, below 2^48 (every step's squared length),
// two of Newton's steps from the guess, g <- (g + n / g) / 2, which from any g > 0 stay at or above
// the root and come within one of it from a guess near it (a previous step's length, which the
// checkpoints' and two markers' walks pass): that g or g - 1, when it is the root; else
// isqrt_proved(n). Every answer is checked by the definition, so none differs from the loop's.
inline std::uint64_t step_root(std::uint64_t n, std::uint64_t guess) noexcept {
  if (is_step_root(n, guess)) return guess;
  if (n < (std::uint64_t{1} << 48) && guess > 0 && guess < (std::uint64_t{1} << 32)) {
    std::uint64_t g = (guess + n / guess) / 2; // < 2^48: no wrap
    if (g > 0) g = (g + n / g) / 2;
    if (is_step_root(n, g)) return g;
    if (g > 0 && is_step_root(n, g - 1)) return g - 1;
  }
  return isqrt_proved(n);
}

} // namespace antkit::buffon
