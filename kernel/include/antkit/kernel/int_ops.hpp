#pragma once
// The integer policy the kernel's arithmetic is written against (DESIGN.md, rule 6). Every
// arithmetic kernel (fixed.hpp, angle.hpp) is a function template over its integer types and
// touches them only through the operations below, never through a raw `+` or `*` that could
// overflow. For the machine integers (std::int8_t ... std::int64_t, their unsigned partners and the
// 128-bit pair) this header gives each operation a definition that
//   * in a normal build wraps modulo 2^bits (two's complement, like a bit-vector; never undefined
//     behaviour, and the same bits on every compiler and CPU), and
//   * with ANTKIT_CHECKED_ARITHMETIC=1 (the `debug` preset) throws ArithmeticRangeError when the
//     exact result does not fit, so that leaving a documented range is detected instead of wrapped.
// How a symbolic integer plugs in (for the Z3 proofs of issue 7). The kernels call the operations
// unqualified (after `using ops::add, ...`), so for a type S that is not a machine integer two
// routes exist, and they can be mixed:
//   1. Nothing to write but S itself: the generic definitions at the end of this header map each
//      operation onto S's own C++ operators and conversions (add -> a + b, shl -> a << k,
//      widen<To> / narrow<To> / truncate<To> -> To(v), lookup -> a chain of select). A type written
//      like a C++ integer whose operators record C++'s undefined-behaviour conditions (signed
//      overflow, division by zero, min / -1, a left shift that loses the value) as obligations, as
//      antkit::proofs::Int<N, Signed> (proofs/z3/z3_int.hpp) does, then carries exactly the
//      obligations that the checked machine build checks. S must provide, in its namespace:
//      == != < <= > >= returning its boolean type B (a z3 boolean); select(B, S, S), z3::ite (every
//      branch in a kernel goes through select: both arms are evaluated, no control flow depends on
//      data); require(B, what), which records B as an obligation (a precondition of the documented
//      domain, or from narrow "the value fits the narrower type"); S(integer constant), explicit
//      S(other width/signedness) with C++ conversion semantics (sign- or zero-extension by the
//      source's signedness, low bits when narrowing); and a static `bits` (for max/min_value).
//   2. Overloads of any operation in S's namespace, found by argument-dependent lookup and
//      preferred to the generic ones (they are templates constrained to non-machine types): e.g. a
//      lookup that reads a z3 array instead of building a 1026-way ite chain.
// wrap_add / wrap_sub / wrap_mul are used only on unsigned angle types, where C++ (and a
// bit-vector) wraps without an obligation. Kernels hold intermediate results in `auto` or S
// variables, never in bool or constexpr variables, so that a symbolic boolean flows through them.
// Proving "no overflow inside the domain" is then: assert the domain, run the kernel template on S,
// and ask Z3 for a model of (domain and not every obligation); rounding claims are asserted over
// the result the same way. Loops in the kernels have trip counts fixed by the type (never by data),
// so the symbolic run unrolls them. tests/kernel/test_fixed.cpp runs the kernels through route 1
// with a counting stand-in for S and checks that obligations fail exactly outside the domains.
#if defined(__SIZEOF_INT128__) // The 128-bit pair: __int128, a GCC/Clang extension of 64-bit
#define ANTKIT_INT128 __int128 // targets; 32-bit targets lack it and get soft::Int (int128.hpp).
#define ANTKIT_UINT128 unsigned __int128 // As macros so that segment.hpp and the Buffon world
#else                                    // name the type too; elsewhere use kernel::int128 and
#include <antkit/kernel/int128.hpp>      // kernel::uint128 (below). Helper functions are written
#define ANTKIT_INT128 ::antkit::kernel::soft::Int128   // so that a kernel never calls a
#define ANTKIT_UINT128 ::antkit::kernel::soft::UInt128 // machine-only facility: no __builtin_clz,
#endif // no std::bit_width, no early return on data.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace antkit::kernel {

// __extension__ keeps -Wpedantic quiet about __int128 (the macros above; nothing on 32-bit).
__extension__ using int128 = ANTKIT_INT128;
__extension__ using uint128 = ANTKIT_UINT128;

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
#if defined(__cpp_exceptions) // freestanding (mcu/, -fno-exceptions): a checked build traps
[[noreturn]] inline void range_failure(const char* what) {
  throw ArithmeticRangeError(what);
}
#else // clang-format off
[[noreturn]] inline void range_failure(const char*) { __builtin_trap(); }
#endif // clang-format on
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

// ---------------------------------------------------------------------------------------------
// Every other integer-like type: the policy operations map onto the type's own operators and
// conversions, so a symbolic type written like a C++ integer -- antkit::proofs::Int<N, Signed> of
// proofs/z3/z3_int.hpp, whose operators record C++'s undefined-behaviour conditions as obligations
// -- instantiates the kernels without an adapter. Such a type must provide, in its namespace:
// select(B, S, S) and require(B, const char*) (the latter records a domain precondition or a
// narrowing's "the value fits" as an obligation); lookup() below builds an ite chain through
// select, which a type may replace with its own overload (e.g. a z3 array).

template <class T>
concept PolicyInt = !MachineInt<T>;

template <PolicyInt T>
T add(const T& a, const T& b) {
  return a + b;
}
template <PolicyInt T>
T sub(const T& a, const T& b) {
  return a - b;
}
template <PolicyInt T>
T mul(const T& a, const T& b) {
  return a * b;
}
template <PolicyInt T>
T neg(const T& a) {
  return T(0) - a;
}
template <PolicyInt T>
T wrap_add(const T& a, const T& b) {
  return a + b;
}
template <PolicyInt T>
T wrap_sub(const T& a, const T& b) {
  return a - b;
}
template <PolicyInt T>
T wrap_mul(const T& a, const T& b) {
  return a * b;
}
template <PolicyInt T>
T shl(const T& a, int k) {
  return a << k;
}
template <PolicyInt T>
T shr(const T& a, int k) {
  return a >> k;
}
template <PolicyInt T>
T band(const T& a, const T& b) {
  return a & b;
}
template <PolicyInt T>
T bor(const T& a, const T& b) {
  return a | b;
}
template <PolicyInt T>
T div(const T& a, const T& b) {
  return a / b;
}
template <PolicyInt T>
T rem(const T& a, const T& b) {
  return a % b;
}
template <class To, PolicyInt From>
To widen(const From& v) {
  return To(v);
}
template <class To, PolicyInt From>
To truncate(const From& v) {
  return To(v);
}
template <class To, PolicyInt From>
To narrow(const From& v) {
  const To r(v);
  // Found by argument-dependent lookup in the type's namespace.
  require(From(r) == v && ((r < To(0)) == (v < From(0))), "integer narrowing loses the value");
  return r;
}
// A table read as a chain of selects; the entries must be representable in the index type (the
// kernel's tables hold non-negative values below 2^31).
template <class Table, PolicyInt I>
I lookup(const Table& table, const I& index) {
  I result(table[0]);
  for (std::size_t i = 1; i < table.size(); ++i)
    result = select(index == I(i), I(table[i]), result);
  return result;
}

// The extreme values of a signed type, written with operations that cannot overflow so that they
// also exist for a policy type (whose std::numeric_limits would silently be zero).
template <class T>
constexpr T max_value() {
  if constexpr (MachineInt<T>) {
    return std::numeric_limits<T>::max();
  } else {
    const T quarter = shl(T(1), T::bits - 2);
    return add(sub(quarter, T(1)), quarter); // 2^(N-1) - 1
  }
}
template <class T>
constexpr T min_value() {
  if constexpr (MachineInt<T>) {
    return std::numeric_limits<T>::min();
  } else {
    return sub(neg(max_value<T>()), T(1));
  }
}

} // namespace ops
} // namespace antkit::kernel
