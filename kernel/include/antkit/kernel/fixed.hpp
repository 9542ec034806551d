#pragma once
// Fixed-point numbers: Fixed<Rep, F> is the real number raw * 2^-F held in the signed integer raw
// of type Rep (two's complement, N = bits of Rep).
//
//   range       [-2^(N-1-F), 2^(N-1-F) - 2^-F]
//   resolution  2^-F (one "ulp"; every result below is stated in these)
//
// The default Fx = Fixed<std::int32_t, 16> is Q15.16: range [-32768, 32768 - 2^-16], resolution
// 2^-16 (about 1.53e-5). A robot of diameter 1 in an arena 400 across with steps of 0.03 uses a
// small part of that range; products such as x*y of two arena coordinates (160000) do not fit and
// belong in a wider format (Fixed<std::int64_t, 32> also works) or in the integer predicates.
//
// Operations, their documented domains, rounding and error (x, y are values, ulp = 2^-F):
//
//   x + y, x - y, -x   domain: the exact result is in range.             exact.
//   x * y              domain: the rounded result is in range.           round to nearest, ties
//                      toward +infinity (round half up): raw = floor((a*b + 2^(F-1)) / 2^F).
//                      error <= 1/2 ulp.
//   x / y              domain: y != 0 and the rounded result in range.   round half up:
//                      raw = floor(a*2^F / b + 1/2). error <= 1/2 ulp. Outside the domain, y == 0
//                      gives max() for x >= 0 and min() for x < 0 (so that no input divides by
//                      zero); checked builds throw instead.
//   sqrt(x)            domain: x >= 0 (every such x).                     round to nearest; a tie
//                      cannot occur (n and r*r + r are integers, (r + 1/2)^2 is not), so the
//                      error is < 1/2 ulp. sqrt of a negative x is 0 (checked builds throw).
//   from_int(v)        domain: v in [-2^(N-1-F), 2^(N-1-F) - 1].           exact.
//   from_ratio(p, q)   domain: q != 0 and the rounded result in range.   p/q rounded half up,
//                      error <= 1/2 ulp (the same kernel as x / y: p/q = (p*2^F / q) * 2^-F).
//   x * k (integer k)  domain: the exact result is in range.             exact.
//   floor(), ceil()    every x.                                          exact floor / ceiling.
//   round()            every x.                                          half up to an integer.
//   fixed_cast<To>(x)  domain: the rounded result is in To's range.      more fraction bits: exact;
//                      fewer: round half up, error <= 1/2 ulp of To.
//   comparisons        every x, y.                                       exact.
//
// Why round half up: it is one add and one arithmetic shift, branch-free, so the proof obligation
// is a single linear inequality; its bias (a tie is rounded up) shows only when the discarded bits
// are exactly one half, which for products of data happens once in 2^F, and it never exceeds half
// an ulp.
//
// Outside a domain a normal build returns the value wrapped modulo 2^N (defined behaviour, the same
// bits on every compiler), and a build with ANTKIT_CHECKED_ARITHMETIC=1 (the `debug` preset) throws
// antkit::kernel::ArithmeticRangeError at the first operation whose result does not fit.
//
// Every operation is first a function template over the integer types -- fx_mul_raw<I, W, F> etc.,
// I the representation and W an integer twice as wide -- written only with the policy operations of
// int_ops.hpp and select() instead of branches, so that the Z3 proofs instantiate the very same
// source with bit-vector integers (see int_ops.hpp for how a symbolic type plugs in). The class
// Fixed is a thin wrapper that instantiates them with machine integers.
#include <antkit/kernel/int_ops.hpp>
#include <compare>
#include <cstdint>
#include <limits>

namespace antkit::kernel {

// ---------------------------------------------------------------------------------------------
// The kernels, over an integer policy. I: representation, W: twice as wide, F: fraction bits.

// floor(n / d + 1/2) for d != 0: division rounded to nearest, ties toward +infinity. The sign of d
// is moved to n so that the rounding is a floor division by the positive 2|d|.
template <class W>
constexpr W div_round_half_up(W n, W d) {
  using ops::add, ops::sub, ops::neg, ops::shl, ops::div, ops::rem, ops::select;
  const auto negative = d < W{0};
  const W dp = select(negative, neg(d), d);
  const W np = select(negative, neg(n), n);
  const W t = add(shl(np, 1), dp);
  const W d2 = shl(dp, 1);
  const W q = div(t, d2); // truncates toward zero; correct it to a floor below
  const W r = rem(t, d2);
  return select(r < W{0}, sub(q, W{1}), q);
}

template <class I, int F>
constexpr I fx_from_int_raw(I v) {
  using ops::shl;
  return shl(v, F);
}

template <class I>
constexpr I fx_add_raw(I a, I b) {
  using ops::add;
  return add(a, b);
}
template <class I>
constexpr I fx_sub_raw(I a, I b) {
  using ops::sub;
  return sub(a, b);
}
template <class I>
constexpr I fx_neg_raw(I a) {
  using ops::neg;
  return neg(a);
}

// raw = floor((a*b + 2^(F-1)) / 2^F). The product of two N-bit numbers always fits in 2N bits, so
// the only obligation is the final narrowing.
template <class I, class W, int F>
constexpr I fx_mul_raw(I a, I b) {
  using ops::add, ops::mul, ops::shl, ops::shr, ops::widen, ops::narrow;
  const W p = mul(widen<W>(a), widen<W>(b));
  const W half = shl(W{1}, F - 1);
  return narrow<I>(shr(add(p, half), F));
}

// raw = floor(a*2^F / b + 1/2); b == 0 saturates (see the table at the top).
template <class I, class W, int F>
constexpr I fx_div_raw(I a, I b) {
  using ops::require;
  using ops::shl, ops::widen, ops::narrow, ops::select;
  require(b != I{0}, "fixed-point division by zero");
  const auto by_zero = b == I{0};
  const W n = shl(widen<W>(a), F);
  const W d = widen<W>(select(by_zero, I{1}, b));
  const W q = div_round_half_up(n, d);
  const I saturated = select(a < I{0}, ops::min_value<I>(), ops::max_value<I>());
  // In the zero case q is a*2^F, whose narrowing is not needed; pick the saturated value instead.
  return select(by_zero, saturated, narrow<I>(select(by_zero, W{0}, q)));
}

// The square root of n >= 0, rounded down, by the digit-by-digit method with a trip count fixed by
// the bound: `top` is an even exponent with n < 4 * 2^top. Returns r with r*r <= n < (r+1)^2 and
// leaves n - r*r in `rest`.
//
// The method decides one binary digit of the root per iteration, from the top. Its state is split
// out (isqrt_start, isqrt_step) so that the Z3 proof (proofs/z3/fixed_sqrt_step.cpp) can run ONE
// iteration on a symbolic state instead of all of them unrolled. With bit = 4^k before an iteration
// and y the root's digits decided so far (y = floor(sqrt(n / 4^(k+1)))), the state satisfies
//     r = y * 4^(k+1),   remaining = n - y^2 * 4^(k+1),   0 <= remaining < 2 r + 4^(k+1);
// the iteration decides the digit of weight 2^k (take: (2y+1)^2 4^k <= n, i.e. remaining >= r +
// bit) and leaves the same with y' = 2y + take and k - 1. After the last iteration (k = 0) the
// scale 4^(k+1) is 1: r = y, remaining = n - r^2 < 2r + 1.
template <class W>
struct IsqrtState {
  W r;         // y * 4^(k+1)
  W remaining; // n - y^2 * 4^(k+1)
  W bit;       // 4^k
};

// Before the first iteration: no digit decided (y = 0), k = top / 2.
template <class W, int Top>
constexpr IsqrtState<W> isqrt_start(W n) {
  using ops::shl;
  static_assert(Top % 2 == 0 && Top >= 0);
  return IsqrtState<W>{W{0}, n, shl(W{1}, Top)};
}

// One iteration: decides the digit of weight 2^k and moves to k - 1 (bit / 4; 0 after k = 0).
template <class W>
constexpr void isqrt_step(IsqrtState<W>& s) {
  using ops::add, ops::sub, ops::shr, ops::select;
  const W trial = add(s.r, s.bit);
  const auto take = s.remaining >= trial;
  s.remaining = select(take, sub(s.remaining, trial), s.remaining);
  s.r = select(take, add(shr(s.r, 1), s.bit), shr(s.r, 1));
  s.bit = shr(s.bit, 2);
}

template <class W, int Top>
constexpr W isqrt_floor(W n, W& rest) {
  IsqrtState<W> s = isqrt_start<W, Top>(n);
  for (int i = 0; i <= Top / 2; ++i) isqrt_step(s);
  rest = s.remaining;
  return s.r;
}

// raw = the nearest integer to sqrt(a * 2^F); a < 0 gives 0.
template <class I, class W, int F, int N>
constexpr I fx_sqrt_raw(I a) {
  using ops::add, ops::shl, ops::widen, ops::narrow, ops::select;
  using ops::require;
  require(a >= I{0}, "fixed-point square root of a negative number");
  const I clamped = select(a < I{0}, I{0}, a);
  const W n = shl(widen<W>(clamped), F); // < 2^(N-1+F)
  constexpr int top = ((N - 2 + F) / 2) * 2;
  W rest{0};
  const W r = isqrt_floor<W, top>(n, rest);
  // sqrt(n) > r + 1/2  <=>  n > r*r + r  <=>  rest > r (all integers, so never a tie).
  return narrow<I>(select(rest > r, add(r, W{1}), r));
}

// floor(a / 2^F), ceil(a / 2^F) and floor(a / 2^F + 1/2) as integers of type I (each fits: their
// magnitude is at most 2^(N-1-F)); the sums are formed in W so that ceil(max) cannot overflow.
template <class I, class W, int F>
constexpr I fx_floor_int(I a) {
  using ops::shr;
  return shr(a, F);
}
template <class I, class W, int F>
constexpr I fx_ceil_int(I a) {
  using ops::add, ops::shl, ops::shr, ops::widen, ops::sub, ops::narrow;
  return narrow<I>(shr(add(widen<W>(a), sub(shl(W{1}, F), W{1})), F));
}
template <class I, class W, int F>
constexpr I fx_round_int(I a) {
  using ops::add, ops::shl, ops::shr, ops::widen, ops::narrow;
  return narrow<I>(shr(add(widen<W>(a), shl(W{1}, F - 1)), F));
}

// Re-scale from F1 to F2 fraction bits: exact when F2 >= F1, else rounded half up.
template <class I1, class W1, int F1, class I2, int F2>
constexpr I2 fx_rescale_raw(I1 a) {
  using ops::add, ops::shl, ops::shr, ops::widen, ops::narrow;
  if constexpr (F2 >= F1) {
    using Wide = std::conditional_t<(ops::int_info<W1>::bits >= ops::int_info<I2>::bits), W1,
                                    ops::wide_t<I2>>;
    return narrow<I2>(shl(widen<Wide>(a), F2 - F1));
  } else {
    const W1 w = widen<W1>(a);
    return narrow<I2>(shr(add(w, shl(W1{1}, F1 - F2 - 1)), F1 - F2));
  }
}

// ---------------------------------------------------------------------------------------------
// The number type.

template <class Rep, int FracBits>
class Fixed {
  static_assert(ops::int_info<Rep>::known && ops::int_info<Rep>::is_signed,
                "Fixed needs a signed machine integer");
  static_assert(FracBits >= 1 && FracBits <= ops::int_info<Rep>::bits - 2,
                "Fixed needs 1 <= FracBits <= bits - 2 (an integer part of at least one bit)");

public:
  using rep = Rep;
  using wide = ops::wide_t<Rep>;
  static constexpr int frac_bits = FracBits;
  static constexpr int bits = ops::int_info<Rep>::bits;
  static constexpr Rep one_raw = Rep{1} << FracBits;

  constexpr Fixed() = default;
  static constexpr Fixed from_raw(Rep raw) noexcept {
    Fixed f;
    f.raw_ = raw;
    return f;
  }
  // Exact; v must be in [-2^(N-1-F), 2^(N-1-F) - 1].
  static constexpr Fixed from_int(std::int32_t v) {
    const Rep r = ops::narrow<Rep>(static_cast<std::int64_t>(v));
    return from_raw(fx_from_int_raw<Rep, FracBits>(r));
  }
  // num / den rounded to nearest, ties toward +infinity; den != 0. Example: from_ratio(3, 100) is
  // the step length 0.03 (raw 1966 in Q15.16, 0.0299987...).
  static constexpr Fixed from_ratio(Rep num, Rep den) {
    return from_raw(fx_div_raw<Rep, wide, FracBits>(num, den));
  }

  static constexpr Fixed max() noexcept { return from_raw(std::numeric_limits<Rep>::max()); }
  static constexpr Fixed min() noexcept { return from_raw(std::numeric_limits<Rep>::min()); }
  // The resolution, one ulp.
  static constexpr Fixed epsilon() noexcept { return from_raw(Rep{1}); }
  static constexpr Fixed one() noexcept { return from_raw(one_raw); }

  [[nodiscard]] constexpr Rep raw() const noexcept { return raw_; }

  // Integer parts (a cell coordinate is floor()).
  [[nodiscard]] constexpr Rep floor() const { return fx_floor_int<Rep, wide, FracBits>(raw_); }
  [[nodiscard]] constexpr Rep ceil() const { return fx_ceil_int<Rep, wide, FracBits>(raw_); }
  [[nodiscard]] constexpr Rep round() const { return fx_round_int<Rep, wide, FracBits>(raw_); }

  friend constexpr bool operator==(Fixed, Fixed) = default;
  friend constexpr auto operator<=>(Fixed, Fixed) = default;

  friend constexpr Fixed operator+(Fixed a, Fixed b) {
    return from_raw(fx_add_raw<Rep>(a.raw_, b.raw_));
  }
  friend constexpr Fixed operator-(Fixed a, Fixed b) {
    return from_raw(fx_sub_raw<Rep>(a.raw_, b.raw_));
  }
  friend constexpr Fixed operator-(Fixed a) { return from_raw(fx_neg_raw<Rep>(a.raw_)); }
  friend constexpr Fixed operator*(Fixed a, Fixed b) {
    return from_raw(fx_mul_raw<Rep, wide, FracBits>(a.raw_, b.raw_));
  }
  friend constexpr Fixed operator/(Fixed a, Fixed b) {
    return from_raw(fx_div_raw<Rep, wide, FracBits>(a.raw_, b.raw_));
  }
  // Exact multiples: a step length times a step count.
  friend constexpr Fixed operator*(Fixed a, std::int32_t k) {
    return from_raw(ops::mul(a.raw_, ops::narrow<Rep>(static_cast<std::int64_t>(k))));
  }
  friend constexpr Fixed operator*(std::int32_t k, Fixed a) { return a * k; }

  constexpr Fixed& operator+=(Fixed b) { return *this = *this + b; }
  constexpr Fixed& operator-=(Fixed b) { return *this = *this - b; }
  constexpr Fixed& operator*=(Fixed b) { return *this = *this * b; }
  constexpr Fixed& operator/=(Fixed b) { return *this = *this / b; }

private:
  Rep raw_ = 0;
};

// The kernel's default number: Q15.16 in 32 bits (range [-32768, 32768), resolution 2^-16).
using Fx = Fixed<std::int32_t, 16>;

template <class Rep, int F>
constexpr Fixed<Rep, F> sqrt(Fixed<Rep, F> x) {
  return Fixed<Rep, F>::from_raw(
      fx_sqrt_raw<Rep, ops::wide_t<Rep>, F, ops::int_info<Rep>::bits>(x.raw()));
}

// |x|; x != min().
template <class Rep, int F>
constexpr Fixed<Rep, F> abs(Fixed<Rep, F> x) {
  return Fixed<Rep, F>::from_raw(ops::select(x.raw() < Rep{0}, ops::neg(x.raw()), x.raw()));
}

// Conversion between formats, e.g. fixed_cast<Fixed<std::int64_t, 32>>(x).
template <class To, class Rep, int F>
constexpr To fixed_cast(Fixed<Rep, F> x) {
  return To::from_raw(
      fx_rescale_raw<Rep, ops::wide_t<Rep>, F, typename To::rep, To::frac_bits>(x.raw()));
}

} // namespace antkit::kernel
