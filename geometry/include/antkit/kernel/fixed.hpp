#pragma once
// Fixed-point numbers. (Shape only; the arithmetic, its documentation and its tests are being
// written in this file next.)
#include <cstdint>

namespace antkit::kernel {

template <class Rep, int FracBits>
class Fixed {
public:
  using rep = Rep;
  static constexpr int frac_bits = FracBits;
  static constexpr Rep one_raw = Rep{1} << FracBits;

  constexpr Fixed() = default;
  static constexpr Fixed from_raw(Rep raw) noexcept {
    Fixed f;
    f.raw_ = raw;
    return f;
  }
  static constexpr Fixed from_int(std::int32_t v) noexcept {
    return from_raw(static_cast<Rep>(static_cast<Rep>(v) * one_raw));
  }
  [[nodiscard]] constexpr Rep raw() const noexcept { return raw_; }
  friend constexpr bool operator==(Fixed, Fixed) = default;
  friend constexpr auto operator<=>(Fixed, Fixed) = default;

private:
  Rep raw_ = 0;
};

// The kernel's default number: Q15.16 in 32 bits (range [-32768, 32768), resolution 2^-16).
using Fx = Fixed<std::int32_t, 16>;

} // namespace antkit::kernel
