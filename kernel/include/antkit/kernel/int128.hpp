#pragma once
// 128-bit integers on every target. GCC and Clang give 64-bit targets __int128; 32-bit ones (the
// Cortex-M4 of issue 27, 32-bit ARM Linux) have none, so there kernel::int128 and kernel::uint128
// (int_ops.hpp) are soft::Int<Signed>, a two's-complement pair of 64-bit words with the built-in
// type's semantics: the usual conversions (from any integer, implicit; to any integer, explicit and
// truncating; signed to unsigned implicit, as the arithmetic conversions would), wrap-around + - *
// and shifts, division truncating toward zero, comparisons. The kernel's results are therefore the
// same bits on both: tests/kernel holds soft::Int against __int128 on random operands for every
// operator, and the determinism matrix's armhf and cortex-m4 configurations run the golden
// scenarios through it.
//
// It is deliberately simple rather than fast (division is shift-and-subtract when the operands do
// not fit 64 bits): on 64-bit hosts it is not used at all (int_ops.hpp includes it on 32-bit
// targets only).
#include <compare>
#include <cstdint>
#include <type_traits>

namespace antkit::kernel {

namespace soft {

template <bool Signed>
class Int {
public:
  constexpr Int() noexcept = default;
  // From any integer (sign-extended when the source is signed), as the built-in conversion.
  template <class T>
  requires std::is_integral_v<T>
  constexpr Int(T v) noexcept // NOLINT(google-explicit-constructor): as __int128 converts
      : lo_(static_cast<std::uint64_t>(v)), hi_(0) {
    if constexpr (std::is_signed_v<T>)
      if (v < 0) hi_ = ~std::uint64_t{0};
  }
  // Signed to unsigned implicitly (the arithmetic conversions), unsigned to signed explicitly.
  template <bool S>
  requires(S != Signed) constexpr explicit(Signed) Int(Int<S> v) noexcept
      : lo_(v.lo()), hi_(v.hi()) {}

  [[nodiscard]] static constexpr Int from_words(std::uint64_t hi, std::uint64_t lo) noexcept {
    Int r;
    r.hi_ = hi;
    r.lo_ = lo;
    return r;
  }
  [[nodiscard]] constexpr std::uint64_t lo() const noexcept { return lo_; }
  [[nodiscard]] constexpr std::uint64_t hi() const noexcept { return hi_; }

  template <class T>
  requires std::is_integral_v<T>
  constexpr explicit operator T() const noexcept {
    if constexpr (std::is_same_v<T, bool>)
      return (lo_ | hi_) != 0;
    else
      return static_cast<T>(lo_);
  }
  friend constexpr Int operator+(Int a, Int b) noexcept {
    const std::uint64_t lo = a.lo_ + b.lo_;
    return from_words(a.hi_ + b.hi_ + (lo < a.lo_ ? 1 : 0), lo);
  }
  friend constexpr Int operator-(Int a, Int b) noexcept {
    return from_words(a.hi_ - b.hi_ - (a.lo_ < b.lo_ ? 1 : 0), a.lo_ - b.lo_);
  }
  constexpr Int operator-() const noexcept { return Int{0} - *this; }
  constexpr Int operator+() const noexcept { return *this; }
  constexpr Int operator~() const noexcept { return from_words(~hi_, ~lo_); }
  constexpr bool operator!() const noexcept { return (lo_ | hi_) == 0; }
  friend constexpr Int operator*(Int a, Int b) noexcept {
    Int r = mul64(a.lo_, b.lo_);
    r.hi_ += a.lo_ * b.hi_ + a.hi_ * b.lo_;
    return r;
  }
  friend constexpr Int operator/(Int a, Int b) noexcept { return divmod(a, b, false); }
  friend constexpr Int operator%(Int a, Int b) noexcept { return divmod(a, b, true); }
  friend constexpr Int operator&(Int a, Int b) noexcept {
    return from_words(a.hi_ & b.hi_, a.lo_ & b.lo_);
  }
  friend constexpr Int operator|(Int a, Int b) noexcept {
    return from_words(a.hi_ | b.hi_, a.lo_ | b.lo_);
  }
  friend constexpr Int operator^(Int a, Int b) noexcept {
    return from_words(a.hi_ ^ b.hi_, a.lo_ ^ b.lo_);
  }
  // Shifts by 0 to 127 (the built-in type's defined range).
  friend constexpr Int operator<<(Int a, int s) noexcept {
    if (s == 0) return a;
    if (s >= 64) return from_words(a.lo_ << (s - 64), 0);
    return from_words((a.hi_ << s) | (a.lo_ >> (64 - s)), a.lo_ << s);
  }
  friend constexpr Int operator>>(Int a, int s) noexcept {
    if (s == 0) return a;
    const std::uint64_t fill = Signed && a.negative() ? ~std::uint64_t{0} : 0;
    if (s >= 64)
      return from_words(fill, s == 64 ? a.hi_ : (a.hi_ >> (s - 64)) | (fill << (128 - s)));
    return from_words((a.hi_ >> s) | (fill << (64 - s)), (a.lo_ >> s) | (a.hi_ << (64 - s)));
  }
  friend constexpr bool operator==(Int a, Int b) noexcept {
    return a.lo_ == b.lo_ && a.hi_ == b.hi_;
  }
  friend constexpr std::strong_ordering operator<=>(Int a, Int b) noexcept {
    if (a.hi_ != b.hi_) {
      if constexpr (Signed)
        return static_cast<std::int64_t>(a.hi_) <=> static_cast<std::int64_t>(b.hi_);
      else
        return a.hi_ <=> b.hi_;
    }
    return a.lo_ <=> b.lo_;
  }

  constexpr Int& operator+=(Int b) noexcept { return *this = *this + b; }
  constexpr Int& operator-=(Int b) noexcept { return *this = *this - b; }
  constexpr Int& operator*=(Int b) noexcept { return *this = *this * b; }
  constexpr Int& operator/=(Int b) noexcept { return *this = *this / b; }
  constexpr Int& operator%=(Int b) noexcept { return *this = *this % b; }
  constexpr Int& operator&=(Int b) noexcept { return *this = *this & b; }
  constexpr Int& operator|=(Int b) noexcept { return *this = *this | b; }
  constexpr Int& operator^=(Int b) noexcept { return *this = *this ^ b; }
  constexpr Int& operator<<=(int s) noexcept { return *this = *this << s; }
  constexpr Int& operator>>=(int s) noexcept { return *this = *this >> s; }
  constexpr Int& operator++() noexcept { return *this += 1; }
  constexpr Int& operator--() noexcept { return *this -= 1; }
  constexpr Int operator++(int) noexcept {
    const Int old = *this;
    ++*this;
    return old;
  }
  constexpr Int operator--(int) noexcept {
    const Int old = *this;
    --*this;
    return old;
  }

private:
  [[nodiscard]] constexpr bool negative() const noexcept { return Signed && (hi_ >> 63) != 0; }
  // The full product of two 64-bit words, from 32-bit halves.
  static constexpr Int mul64(std::uint64_t a, std::uint64_t b) noexcept {
    const std::uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32, b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
    const std::uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    const std::uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    return from_words(p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32),
                      (mid << 32) | (p00 & 0xFFFFFFFFu));
  }
  // Unsigned division of magnitudes, then the signs: the quotient truncated toward zero and the
  // remainder with the dividend's sign, as for built-in integers. (Division by zero, and the
  // signed minimum by -1, are undefined for the built-in type; here they give some value.)
  static constexpr Int divmod(Int a, Int b, bool remainder) noexcept {
    const bool na = a.negative(), nb = b.negative();
    const Int<false> ua(na ? -a : a), ub(nb ? -b : b);
    Int<false> q, r;
    if (ua.hi() == 0 && ub.hi() == 0) {
      if (ub.lo() != 0) {
        q = Int<false>(ua.lo() / ub.lo());
        r = Int<false>(ua.lo() % ub.lo());
      }
    } else if (ub != Int<false>(0)) {
      for (int i = 127; i >= 0; --i) {
        r = (r << 1) | Int<false>((ua >> i).lo() & 1);
        if (r >= ub) {
          r -= ub;
          q |= Int<false>(1) << i;
        }
      }
    }
    if (remainder) {
      const Int v = static_cast<Int>(r);
      return na ? -v : v;
    }
    const Int v = static_cast<Int>(q);
    return na != nb ? -v : v;
  }

  std::uint64_t lo_ = 0;
  std::uint64_t hi_ = 0;
};

using Int128 = Int<true>;
using UInt128 = Int<false>;

} // namespace soft

} // namespace antkit::kernel
