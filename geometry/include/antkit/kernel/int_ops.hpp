#pragma once
// The integer policy the kernel's arithmetic is written against (DESIGN.md, rule 6).
//
// Every arithmetic kernel (fixed.hpp, angle.hpp) is a function template over its integer types and
// touches them only through the operations below, never through a raw `+` or `*` that could
// overflow. For the machine integers (std::int8_t ... std::int64_t, their unsigned partners and the
// 128-bit pair) this header gives each operation a definition that
//   * in a normal build wraps modulo 2^bits (two's complement, like a bit-vector; never undefined
//     behaviour, and the same bits on every compiler and CPU), and
//   * with ANTKIT_CHECKED_ARITHMETIC=1 (the `debug` preset) throws ArithmeticRangeError when the
//     exact result does not fit, so that leaving a documented range is detected instead of wrapped.
//
// How a symbolic integer plugs in (for the Z3 proofs of issue 7). A symbolic type S -- a wrapper
// around a z3::expr bit-vector of fixed width and signedness, with a boolean partner B wrapping a
// z3 boolean -- provides, in its own namespace so that argument-dependent lookup finds them:
//   add, sub, mul, neg, shl, div, rem      the bit-vector operation (bvadd, bvmul, bvsdiv, ...),
//   and
//                                          it records the operation's no-overflow side condition
//                                          (e.g. bvadd_no_overflow / bvadd_no_underflow) as a proof
//                                          obligation, exactly where the machine policy checks;
//   shr, band, bor, bxor                   bvashr / bvlshr, bvand, ... (these never overflow);
//   == != < <= > >=                        returning B;
//   select(B, S, S)                        z3::ite -- every branch in a kernel goes through select,
//                                          so both arms are evaluated and no control flow depends
//                                          on data;
//   widen<To>(S), narrow<To>(S)            sign/zero extension, and extraction with the obligation
//                                          that the value fits;
//   truncate<To>(S)                        extraction without an obligation (wrapping intended);
//   wrap_add, wrap_sub, wrap_mul           modular arithmetic where wrapping is the meaning (binary
//                                          angles), with no obligation;
//   as_unsigned(S), as_signed(S)           the same bits, other signedness;
//   lookup(table, S)                       a table read: an ite chain or a z3 array constant;
//   require(B, what)                       a precondition of the operation's documented domain,
//                                          recorded as an obligation.
// S must also be constructible from an integer constant (W{1}, U{0} in the kernels) and, where a
// kernel saturates, have std::numeric_limits<S>::min()/max(); kernels hold intermediate results in
// `auto`/S variables, never in bool or in constexpr variables, so that a symbolic boolean can flow
// through them.
// Then proving "no overflow inside the domain" is: assert the domain, instantiate the kernel
// template with S, and ask Z3 for a model of (domain and not all obligations); rounding claims are
// asserted over the result the same way. Loops in the kernels have trip counts fixed by the type
// (never by data), so the symbolic instantiation unrolls them.
//
// Helper functions are written so that a kernel never calls a machine-only facility: no
// __builtin_clz, no std::bit_width, no early return on a data value.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace antkit::kernel {

// 128-bit integers are a GCC/Clang extension; __extension__ keeps -Wpedantic quiet about them.
__extension__ using int128 = __int128;
__extension__ using uint128 = unsigned __int128;

// Thrown in ANTKIT_CHECKED_ARITHMETIC builds when a kernel operation leaves its documented range
// (a bug in the caller, not bad input, which is why it is not an InputError).
class ArithmeticRangeError : public std::range_error {
public:
  using std::range_error::range_error;
};

#if defined(ANTKIT_CHECKED_ARITHMETIC) && ANTKIT_CHECKED_ARITHMETIC
inline constexpr bool kCheckedArithmetic = true;
#else
inline constexpr bool kCheckedArithmetic = false;
#endif

namespace ops {

// Machine integers, 128-bit ones included (std::is_integral does not know them in strict mode).
template <class T>
struct int_info {
  static constexpr bool known = std::is_integral_v<T> && !std::is_same_v<T, bool>;
  static constexpr bool is_signed = std::is_signed_v<T>;
  static constexpr int bits = static_cast<int>(sizeof(T)) * 8;
  using unsigned_type = std::make_unsigned_t<std::conditional_t<known, T, int>>;
  using signed_type = std::make_signed_t<std::conditional_t<known, T, int>>;
};
template <>
struct int_info<int128> {
  static constexpr bool known = true;
  static constexpr bool is_signed = true;
  static constexpr int bits = 128;
  using unsigned_type = uint128;
  using signed_type = int128;
};
template <>
struct int_info<uint128> {
  static constexpr bool known = true;
  static constexpr bool is_signed = false;
  static constexpr int bits = 128;
  using unsigned_type = uint128;
  using signed_type = int128;
};

template <class T>
concept MachineInt = int_info<T>::known;

// The type twice as wide, used for products and shifted dividends.
template <class T>
struct wide_of;
template <>
struct wide_of<std::int8_t> {
  using type = std::int16_t;
};
template <>
struct wide_of<std::int16_t> {
  using type = std::int32_t;
};
template <>
struct wide_of<std::int32_t> {
  using type = std::int64_t;
};
template <>
struct wide_of<std::int64_t> {
  using type = int128;
};
template <>
struct wide_of<std::uint8_t> {
  using type = std::uint16_t;
};
template <>
struct wide_of<std::uint16_t> {
  using type = std::uint32_t;
};
template <>
struct wide_of<std::uint32_t> {
  using type = std::uint64_t;
};
template <>
struct wide_of<std::uint64_t> {
  using type = uint128;
};
template <class T>
using wide_t = typename wide_of<T>::type;

[[noreturn]] inline void range_failure(const char* what) {
  throw ArithmeticRangeError(what);
}

// A precondition of an operation's documented domain: checked in ANTKIT_CHECKED_ARITHMETIC builds,
// free otherwise (the operation then still returns a defined, documented value).
constexpr void require([[maybe_unused]] bool holds, [[maybe_unused]] const char* what) {
  if constexpr (kCheckedArithmetic) {
    if (!holds) range_failure(what);
  }
}

// Branch-free choice; both arms have already been evaluated by the caller.
template <MachineInt T>
constexpr T select(bool cond, T if_true, T if_false) noexcept {
  return cond ? if_true : if_false;
}

// Unsigned arithmetic at least as wide as `unsigned int`: a std::uint16_t would otherwise be
// promoted to (signed) int, whose products can overflow.
template <MachineInt T>
using uarith_t = std::common_type_t<typename int_info<T>::unsigned_type, unsigned>;

template <MachineInt T>
constexpr T from_bits(uarith_t<T> bits) noexcept {
  // Conversion to a signed type is modulo 2^bits since C++20.
  return static_cast<T>(static_cast<typename int_info<T>::unsigned_type>(bits));
}
template <MachineInt T>
constexpr uarith_t<T> to_bits(T v) noexcept {
  return static_cast<uarith_t<T>>(static_cast<typename int_info<T>::unsigned_type>(v));
}

template <MachineInt T>
constexpr T add(T a, T b) {
  if constexpr (kCheckedArithmetic) {
    T r{};
    if (__builtin_add_overflow(a, b, &r)) range_failure("integer addition overflows");
    return r;
  } else {
    return from_bits<T>(to_bits(a) + to_bits(b));
  }
}

template <MachineInt T>
constexpr T sub(T a, T b) {
  if constexpr (kCheckedArithmetic) {
    T r{};
    if (__builtin_sub_overflow(a, b, &r)) range_failure("integer subtraction overflows");
    return r;
  } else {
    return from_bits<T>(to_bits(a) - to_bits(b));
  }
}

template <MachineInt T>
constexpr T mul(T a, T b) {
  if constexpr (kCheckedArithmetic) {
    T r{};
    if (__builtin_mul_overflow(a, b, &r)) range_failure("integer multiplication overflows");
    return r;
  } else {
    return from_bits<T>(to_bits(a) * to_bits(b));
  }
}

template <MachineInt T>
constexpr T neg(T a) {
  return sub(T{0}, a);
}

// Modular arithmetic where wrapping is the meaning (binary angles are integers mod 2^bits): never
// checked, and the symbolic policy records no obligation for them.
template <MachineInt T>
constexpr T wrap_add(T a, T b) noexcept {
  return from_bits<T>(to_bits(a) + to_bits(b));
}
template <MachineInt T>
constexpr T wrap_sub(T a, T b) noexcept {
  return from_bits<T>(to_bits(a) - to_bits(b));
}
template <MachineInt T>
constexpr T wrap_mul(T a, T b) noexcept {
  return from_bits<T>(to_bits(a) * to_bits(b));
}

// a * 2^k, 0 <= k < bits.
template <MachineInt T>
constexpr T shl(T a, int k) {
  const T r = from_bits<T>(to_bits(a) << k);
  if constexpr (kCheckedArithmetic) {
    if ((r >> k) != a) range_failure("integer left shift overflows");
  }
  return r;
}

// floor(a / 2^k), 0 <= k < bits (an arithmetic shift for signed types; defined since C++20).
template <MachineInt T>
constexpr T shr(T a, int k) noexcept {
  return static_cast<T>(a >> k);
}

template <MachineInt T>
constexpr T band(T a, T b) noexcept {
  return static_cast<T>(a & b);
}
template <MachineInt T>
constexpr T bor(T a, T b) noexcept {
  return static_cast<T>(a | b);
}

// Truncating division and its remainder (C++ and bvsdiv/bvsrem agree). The divisor is made safe
// before the machine division so that no input reaches undefined behaviour: a zero divisor, or
// min / -1, is reported in checked builds and gives a defined (meaningless) value otherwise.
// Callers keep these out of their domains.
template <MachineInt T>
constexpr T div(T a, T b) {
  bool bad = b == T{0};
  if constexpr (int_info<T>::is_signed)
    bad = bad || (a == std::numeric_limits<T>::min() && b == T(-1));
  require(!bad, "integer division by zero or overflow");
  return bad ? T{0} : static_cast<T>(a / b);
}
template <MachineInt T>
constexpr T rem(T a, T b) {
  bool bad = b == T{0};
  if constexpr (int_info<T>::is_signed)
    bad = bad || (a == std::numeric_limits<T>::min() && b == T(-1));
  require(!bad, "integer remainder by zero or overflow");
  return bad ? T{0} : static_cast<T>(a % b);
}

// Value-preserving conversion to a type at least as wide (sign- or zero-extension).
template <MachineInt To, MachineInt From>
constexpr To widen(From v) noexcept {
  static_assert(int_info<To>::bits >= int_info<From>::bits, "widen only widens");
  return static_cast<To>(v);
}

// Conversion to a narrower (or differently signed) type: the low bits (wrapping), and in checked
// builds an ArithmeticRangeError when the value does not fit.
template <MachineInt To, MachineInt From>
constexpr To narrow(From v) {
  const To r = static_cast<To>(v);
  if constexpr (kCheckedArithmetic) {
    if (static_cast<From>(r) != v || ((r < To{0}) != (v < From{0})))
      range_failure("integer narrowing loses the value");
  }
  return r;
}

// The low bits of v, modulo 2^bits of To, where wrapping is the meaning (binary angles); never
// checked.
template <MachineInt To, MachineInt From>
constexpr To truncate(From v) noexcept {
  return static_cast<To>(v);
}

// The same bits read with the other signedness (no check: a bit-level reinterpretation).
template <MachineInt T>
constexpr typename int_info<T>::unsigned_type as_unsigned(T v) noexcept {
  return static_cast<typename int_info<T>::unsigned_type>(v);
}
template <MachineInt T>
constexpr typename int_info<T>::signed_type as_signed(T v) noexcept {
  return static_cast<typename int_info<T>::signed_type>(v);
}

// A table read; the index is in range by the caller's construction (checked in checked builds).
template <class Table, MachineInt I>
constexpr auto lookup(const Table& table, I index) {
  require(index >= I{0} && static_cast<std::size_t>(index) < table.size(),
          "table index out of range");
  return table[static_cast<std::size_t>(index)];
}

} // namespace ops
} // namespace antkit::kernel
