// Fixed-point numbers against exact integer oracles (__int128 rationals): every result is the
// documented rounding of the exact value, hence within its stated error.
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <rapidcheck/catch.h>
#include <sstream>
#include <string>

namespace {

using antkit::kernel::ArithmeticRangeError;
using antkit::kernel::Fixed;
using antkit::kernel::fixed_cast;
using antkit::kernel::Fx;
using antkit::kernel::int128;
using antkit::kernel::kCheckedArithmetic;
using F64 = Fixed<std::int64_t, 32>;

// floor(n / d), d > 0.
int128 floor_div(int128 n, int128 d) {
  int128 q = n / d;
  if (n % d != 0 && n < 0) --q;
  return q;
}
// The exact value n/d rounded half up (ties toward +infinity), d != 0.
int128 round_half_up(int128 n, int128 d) {
  if (d < 0) {
    n = -n;
    d = -d;
  }
  return floor_div(2 * n + d, 2 * d);
}
template <class T>
bool fits(int128 v) {
  return v >= std::numeric_limits<T>::min() && v <= std::numeric_limits<T>::max();
}
std::string str(int128 v) {
  if (v == 0) return "0";
  std::string s;
  const bool neg = v < 0;
  while (v != 0) {
    const int digit = static_cast<int>(v % 10);
    s.insert(s.begin(), static_cast<char>('0' + (digit < 0 ? -digit : digit)));
    v /= 10;
  }
  return neg ? "-" + s : s;
}

// A raw value whose magnitude is spread over every scale, from 0 to the whole range, so that
// properties see both small numbers and numbers at the edge of the range.
template <class Rep>
Rep any_scale_raw() {
  constexpr int bits = static_cast<int>(sizeof(Rep)) * 8;
  const int scale = *rc::gen::inRange(0, bits);
  const auto bound =
      static_cast<Rep>((scale >= bits - 1) ? std::numeric_limits<Rep>::max() : (Rep{1} << scale));
  return *rc::gen::inRange<Rep>(static_cast<Rep>(-bound), bound);
}

// The rounded exact results, as the oracle sees them.
template <class Rep, int F>
int128 exact_mul(Rep a, Rep b) {
  return floor_div(int128{a} * b + (int128{1} << (F - 1)), int128{1} << F);
}
template <class Rep, int F>
int128 exact_div(Rep a, Rep b) {
  return round_half_up(int128{a} << F, int128{b});
}

template <class Rep, int F>
void check_mul_property() {
  using X = Fixed<Rep, F>;
  const Rep a = any_scale_raw<Rep>();
  const Rep b = any_scale_raw<Rep>();
  const int128 want = exact_mul<Rep, F>(a, b);
  RC_PRE(fits<Rep>(want));
  const Rep got = (X::from_raw(a) * X::from_raw(b)).raw();
  RC_ASSERT(str(got) == str(want));
  // The stated error: |got - a*b/2^F| <= 1/2 ulp, i.e. |got*2^F - a*b| <= 2^(F-1).
  const int128 err = int128{got} * (int128{1} << F) - int128{a} * b;
  RC_ASSERT(err <= (int128{1} << (F - 1)));
  RC_ASSERT(-err <= (int128{1} << (F - 1)));
}

template <class Rep, int F>
void check_div_property() {
  using X = Fixed<Rep, F>;
  const Rep a = any_scale_raw<Rep>();
  const Rep b = any_scale_raw<Rep>();
  RC_PRE(b != 0);
  const int128 want = exact_div<Rep, F>(a, b);
  RC_PRE(fits<Rep>(want));
  const Rep got = (X::from_raw(a) / X::from_raw(b)).raw();
  RC_ASSERT(str(got) == str(want));
  // |got - a*2^F/b| <= 1/2, i.e. |2*(got*b - a*2^F)| <= |b|.
  int128 err = 2 * (int128{got} * b - (int128{a} << F));
  if (err < 0) err = -err;
  RC_ASSERT(err <= (b < 0 ? -int128{b} : int128{b}));
}

template <class Rep, int F>
void check_sqrt_property() {
  using X = Fixed<Rep, F>;
  Rep a = any_scale_raw<Rep>();
  if (a < 0) a = static_cast<Rep>(-(a + 1));
  const int128 n = int128{a} << F; // sqrt(a * 2^-F) * 2^F = sqrt(n)
  const int128 r = sqrt(X::from_raw(a)).raw();
  // Nearest: (r - 1/2)^2 < n < (r + 1/2)^2, i.e. (2r - 1)^2 < 4n < (2r + 1)^2.
  RC_ASSERT(r >= 0);
  RC_ASSERT((2 * r - 1) * (2 * r - 1) < 4 * n || r == 0);
  RC_ASSERT(4 * n < (2 * r + 1) * (2 * r + 1));
}

} // namespace

TEST_CASE("Fx is Q15.16: its range and resolution", "[fixed]") {
  CHECK(Fx::one().raw() == 65536);
  CHECK(Fx::epsilon().raw() == 1);
  CHECK(Fx::from_int(32767).raw() == 32767 * 65536);
  CHECK(Fx::from_int(-32768) == Fx::min());
  CHECK(Fx::max().raw() == std::numeric_limits<std::int32_t>::max());
  CHECK(F64::one().raw() == std::int64_t{1} << 32);
}

TEST_CASE("worked examples with values known from arithmetic", "[fixed]") {
  // 0.03 * 65536 = 1966.08: the paper's step length, rounded to nearest.
  CHECK(Fx::from_ratio(3, 100).raw() == 1966);
  // sqrt(2) * 65536 = 92681.900..., sqrt(2) * 2^32 = 6074000999.95...
  CHECK(sqrt(Fx::from_int(2)).raw() == 92682);
  CHECK(sqrt(F64::from_int(2)).raw() == 6074001000);
  CHECK(sqrt(Fx::from_int(16)) == Fx::from_int(4));
  // 65536 / 3 = 21845.33...
  CHECK((Fx::one() / Fx::from_int(3)).raw() == 21845);
  CHECK((-Fx::one() / Fx::from_int(3)).raw() == -21845);
  CHECK((Fx::from_int(3) * Fx::from_ratio(1, 2)) == Fx::from_ratio(3, 2));
  // Ties round toward +infinity: 2^-16 * 1/2 is half an ulp.
  CHECK((Fx::epsilon() * Fx::from_ratio(1, 2)).raw() == 1);
  CHECK((-Fx::epsilon() * Fx::from_ratio(1, 2)).raw() == 0);
  CHECK(Fx::from_ratio(-7, 2).floor() == -4);
  CHECK(Fx::from_ratio(-7, 2).ceil() == -3);
  CHECK(Fx::from_ratio(-7, 2).round() == -3);
  CHECK(Fx::from_ratio(7, 2).round() == 4);
  CHECK(Fx::max().ceil() == 32768);
  CHECK(Fx::from_ratio(3, 100) * 400 == Fx::from_raw(1966 * 400));
  CHECK(abs(Fx::from_int(-5)) == Fx::from_int(5));
}

TEST_CASE("add, subtract and multiply by an integer are exact", "[fixed][property]") {
  rc::prop("a + b and a - b are the exact sums", [](std::int32_t a, std::int32_t b) {
    RC_PRE(fits<std::int32_t>(int128{a} + b) && fits<std::int32_t>(int128{a} - b));
    RC_ASSERT((Fx::from_raw(a) + Fx::from_raw(b)).raw() == a + b);
    RC_ASSERT((Fx::from_raw(a) - Fx::from_raw(b)).raw() == a - b);
  });
  rc::prop("x * k is exact", [](std::int16_t k) {
    // Every x with |x * k| in range: the whole domain of the operation for this k.
    const std::int32_t bound =
        std::numeric_limits<std::int32_t>::max() / (k == 0 ? 1 : std::abs(k));
    const auto a = *rc::gen::inRange(-bound, bound);
    RC_ASSERT(int128{(Fx::from_raw(a) * k).raw()} == int128{a} * k);
  });
}

TEST_CASE("multiply rounds the exact product half up, within 1/2 ulp", "[fixed][property]") {
  rc::prop("Q15.16", [] { check_mul_property<std::int32_t, 16>(); });
  rc::prop("Q31.32", [] { check_mul_property<std::int64_t, 32>(); });
  rc::prop("Q7.24", [] { check_mul_property<std::int32_t, 24>(); });
}

TEST_CASE("divide rounds the exact quotient half up, within 1/2 ulp", "[fixed][property]") {
  rc::prop("Q15.16", [] { check_div_property<std::int32_t, 16>(); });
  rc::prop("Q31.32", [] { check_div_property<std::int64_t, 32>(); });
  rc::prop("from_ratio(p, q) is p/q rounded half up", [](std::int32_t p, std::int32_t q) {
    RC_PRE(q != 0);
    const int128 want = round_half_up(int128{p} << 16, int128{q});
    RC_PRE(fits<std::int32_t>(want));
    RC_ASSERT(int128{Fx::from_ratio(p, q).raw()} == want);
  });
}

TEST_CASE("sqrt is the nearest representable root", "[fixed][property]") {
  rc::prop("Q15.16", [] { check_sqrt_property<std::int32_t, 16>(); });
  rc::prop("Q31.32", [] { check_sqrt_property<std::int64_t, 32>(); });
}

TEST_CASE("integer parts and format conversions", "[fixed][property]") {
  rc::prop("floor, ceil and round against the exact quotient", [](std::int32_t a) {
    const Fx x = Fx::from_raw(a);
    RC_ASSERT(int128{x.floor()} == floor_div(a, 65536));
    RC_ASSERT(int128{x.ceil()} == -floor_div(-int128{a}, 65536));
    RC_ASSERT(int128{x.round()} == floor_div(int128{a} + 32768, 65536));
  });
  rc::prop("Fx -> Q31.32 is exact and Q31.32 -> Fx rounds half up",
           [](std::int32_t hi, std::uint16_t lo) {
             const Fx x = Fx::from_raw(hi);
             RC_ASSERT(fixed_cast<F64>(x).raw() == std::int64_t{hi} * 65536);
             RC_ASSERT(fixed_cast<Fx>(fixed_cast<F64>(x)) == x);
             // A Q31.32 value near the Fx range, with arbitrary low bits below Fx's resolution.
             const std::int64_t a = std::int64_t{hi} * 65536 + lo;
             const int128 want = floor_div(int128{a} + 32768, 65536);
             RC_PRE(fits<std::int32_t>(want));
             RC_ASSERT(int128{fixed_cast<Fx>(F64::from_raw(a)).raw()} == want);
           });
  rc::prop("from_int is exact in its domain", [] {
    const auto v = *rc::gen::inRange(-32768, 32768);
    RC_ASSERT(int128{Fx::from_int(v).raw()} == int128{v} * 65536);
  });
}

// The same templates instantiated at 8 bits can be checked on every input: each operation returns
// the oracle's rounding whenever that is in range, and otherwise (the checked build) throws, or
// (the normal build) returns the oracle's value modulo 2^8.
template <int F>
std::string exhaustive_small_scope() {
  using X = Fixed<std::int8_t, F>;
  std::ostringstream bad;
  int reported = 0;
  auto expect = [&](const char* op, int a, int b, int128 want, auto compute) {
    bool threw = false;
    int got = 0;
    try {
      got = compute();
    } catch (const ArithmeticRangeError&) {
      threw = true;
    }
    const bool in_range = fits<std::int8_t>(want);
    bool ok = false;
    if (in_range)
      ok = !threw && got == want;
    else if (kCheckedArithmetic)
      ok = threw;
    else
      ok = !threw && static_cast<std::int8_t>(static_cast<std::uint8_t>(want & 0xFF)) == got;
    if (!ok && reported++ < 5)
      bad << op << "(" << a << ", " << b << ") F=" << F << ": got " << got
          << (threw ? " (threw)" : "") << ", want " << str(want) << "\n";
  };
  for (int a = -128; a < 128; ++a) {
    const auto ra = static_cast<std::int8_t>(a);
    for (int b = -128; b < 128; ++b) {
      const auto rb = static_cast<std::int8_t>(b);
      expect("add", a, b, int128{a + b}, [&] { return (X::from_raw(ra) + X::from_raw(rb)).raw(); });
      expect("sub", a, b, int128{a - b}, [&] { return (X::from_raw(ra) - X::from_raw(rb)).raw(); });
      expect("mul", a, b, exact_mul<std::int8_t, F>(ra, rb),
             [&] { return (X::from_raw(ra) * X::from_raw(rb)).raw(); });
      if (b != 0)
        expect("div", a, b, exact_div<std::int8_t, F>(ra, rb),
               [&] { return (X::from_raw(ra) / X::from_raw(rb)).raw(); });
    }
    if (a >= 0) {
      const int128 n = int128{a} << F;
      int128 r = 0;
      while ((2 * r + 1) * (2 * r + 1) < 4 * n) ++r; // the nearest root, by counting
      expect("sqrt", a, 0, r, [&] { return sqrt(X::from_raw(ra)).raw(); });
    }
    expect("from_int", a, 0, int128{a} << F, [&] { return X::from_int(a).raw(); });
  }
  return bad.str();
}

TEST_CASE("every 8-bit input: results are the documented rounding or are detected",
          "[fixed][proof]") {
  CHECK(exhaustive_small_scope<1>() == "");
  CHECK(exhaustive_small_scope<4>() == "");
  CHECK(exhaustive_small_scope<6>() == "");
}

TEST_CASE("every non-negative 16-bit input: sqrt is the nearest root", "[fixed][proof]") {
  using X = Fixed<std::int16_t, 8>;
  int wrong = 0;
  for (int a = 0; a < 32768; ++a) {
    const int128 n = int128{a} << 8;
    const int128 r = sqrt(X::from_raw(static_cast<std::int16_t>(a))).raw();
    if (!((r == 0 || (2 * r - 1) * (2 * r - 1) < 4 * n) && 4 * n < (2 * r + 1) * (2 * r + 1)))
      ++wrong;
  }
  CHECK(wrong == 0);
}

// The digit-by-digit loop invariant that proofs/z3/fixed_sqrt_step.cpp proves for one symbolic
// iteration, checked along whole runs of the shipped isqrt_start / isqrt_step: before the iteration
// with bit = 4^k, r = y 4^(k+1) and remaining = n - y^2 4^(k+1) with 0 <= remaining < 2r + 4^(k+1)
// (y = r / 4^(k+1), the root digits so far); after the last, isqrt_floor's r and rest.
template <class W, int Top>
void check_isqrt_invariant(W n) {
  using antkit::kernel::isqrt_start;
  using antkit::kernel::isqrt_step;
  auto st = isqrt_start<W, Top>(n);
  for (int k = Top / 2; k >= -1; --k) {
    const int128 scale = int128{1} << (2 * k + 2); // 4^(k+1)
    const int128 r = st.r, rem = st.remaining;
    RC_ASSERT(r % scale == 0);
    const int128 y = r / scale;
    RC_ASSERT(rem == int128{n} - y * y * scale);
    RC_ASSERT(rem >= 0);
    RC_ASSERT(rem < 2 * r + scale);
    RC_ASSERT(int128{st.bit} == (k >= 0 ? scale / 4 : 0));
    if (k >= 0) isqrt_step(st);
  }
  W rest{0};
  const W root = antkit::kernel::isqrt_floor<W, Top>(n, rest);
  RC_ASSERT(root == st.r);
  RC_ASSERT(rest == st.remaining);
}

TEST_CASE("the square root's loop keeps its invariant at every iteration", "[fixed][property]") {
  rc::prop("isqrt_floor<int64, 46> (Fx), n in [0, 2^48)", [] {
    const int scale = *rc::gen::inRange(0, 49);
    const std::int64_t n = *rc::gen::inRange<std::int64_t>(0, std::int64_t{1} << scale);
    check_isqrt_invariant<std::int64_t, 46>(n);
  });
  rc::prop("isqrt_floor<int128, 94> (Q31.32), n in [0, 2^96)", [] {
    const int hi_bits = *rc::gen::inRange(0, 33);
    const std::uint64_t lo = *rc::gen::arbitrary<std::uint64_t>();
    const std::int64_t hi = *rc::gen::inRange<std::int64_t>(0, std::int64_t{1} << hi_bits);
    check_isqrt_invariant<int128, 94>((int128{hi} << 64) | lo);
  });
}

TEST_CASE("outside the documented domains: detected when checked, defined otherwise", "[fixed]") {
  const Fx big = Fx::from_int(30000);
  if constexpr (kCheckedArithmetic) {
    CHECK_THROWS_AS(big + big, ArithmeticRangeError);
    CHECK_THROWS_AS(big * big, ArithmeticRangeError);
    CHECK_THROWS_AS(big / Fx::epsilon(), ArithmeticRangeError);
    CHECK_THROWS_AS(Fx::one() / Fx{}, ArithmeticRangeError);
    CHECK_THROWS_AS(sqrt(-Fx::one()), ArithmeticRangeError);
    CHECK_THROWS_AS(Fx::from_int(40000), ArithmeticRangeError);
    CHECK_THROWS_AS(-Fx::min(), ArithmeticRangeError);
  } else {
    // Wrapped modulo 2^32, the same bits on every compiler.
    CHECK((big + big).raw() == static_cast<std::int32_t>(std::uint32_t{60000} << 16));
    CHECK(Fx::one() / Fx{} == Fx::max());
    CHECK(-Fx::one() / Fx{} == Fx::min());
    CHECK(Fx{} / Fx{} == Fx::max());
    CHECK(sqrt(-Fx::one()) == Fx{});
    CHECK(-Fx::min() == Fx::min());
  }
}

TEST_CASE("conversions for reporting", "[fixed][property]") {
  using antkit::geometry::fixed_from_double;
  using antkit::geometry::to_double;
  rc::prop("to_double is exact for Fx and fixed_from_double inverts it", [](std::int32_t a) {
    const Fx x = Fx::from_raw(a);
    RC_ASSERT(to_double(x) * 65536.0 == static_cast<double>(a));
    RC_ASSERT(fixed_from_double<Fx>(to_double(x)) == x);
  });
  CHECK(fixed_from_double<Fx>(0.03) == Fx::from_ratio(3, 100));
  CHECK(fixed_from_double<Fx>(-1.5) == Fx::from_ratio(-3, 2));
  CHECK_THROWS_AS(fixed_from_double<Fx>(40000.0, "--width"), antkit::kernel::InputError);
  CHECK_THROWS_AS(fixed_from_double<Fx>(std::numeric_limits<double>::quiet_NaN(), "--width"),
                  antkit::kernel::InputError);
}

// ---------------------------------------------------------------------------------------------
// The kernels are written once over an integer policy (int_ops.hpp). This stand-in for the Z3
// bit-vector integer is a C++-like integer type that is not a machine integer: it goes through the
// policy's generic path, wraps like a bit-vector and counts, instead of proving, the obligations
// (signed overflow, division by zero, narrowing that loses the value, domain preconditions). The
// kernels must compute the machine results with no obligation violated inside their documented
// domains, and must violate one outside -- what the Z3 proofs will establish for all inputs.
namespace policy_test {

int violations = 0;

struct Bool {
  bool b;
  friend Bool operator&&(Bool x, Bool y) { return {x.b && y.b}; }
  friend Bool operator==(Bool x, Bool y) { return {x.b == y.b}; }
  friend Bool operator!=(Bool x, Bool y) { return {x.b != y.b}; }
};
inline void require(Bool c, const char*) {
  if (!c.b) ++violations;
}

template <int N, bool Signed>
struct Int {
  static constexpr int bits = N;
  using M = std::conditional_t<
      N == 128, std::conditional_t<Signed, antkit::kernel::int128, antkit::kernel::uint128>,
      std::conditional_t<N == 64, std::conditional_t<Signed, std::int64_t, std::uint64_t>,
                         std::conditional_t<Signed, std::int32_t, std::uint32_t>>>;
  M v{};
  Int() = default;
  template <class T>
  requires std::is_integral_v<T> Int(T x) : v(static_cast<M>(x)) {}
  template <int K, bool S>
  explicit Int(Int<K, S> o) : v(static_cast<M>(o.v)) {}

  friend Int operator+(Int a, Int b) { return checked(__builtin_add_overflow(a.v, b.v, &a.v), a); }
  friend Int operator-(Int a, Int b) { return checked(__builtin_sub_overflow(a.v, b.v, &a.v), a); }
  friend Int operator*(Int a, Int b) { return checked(__builtin_mul_overflow(a.v, b.v, &a.v), a); }
  friend Int operator/(Int a, Int b) {
    return b.v == 0 || (Signed && b.v == M(-1)) ? bad() : wrap(a.v / b.v);
  }
  friend Int operator%(Int a, Int b) {
    return b.v == 0 || (Signed && b.v == M(-1)) ? bad() : wrap(a.v % b.v);
  }
  friend Int operator&(Int a, Int b) { return wrap(a.v & b.v); }
  friend Int operator|(Int a, Int b) { return wrap(a.v | b.v); }
  friend Int operator<<(Int a, int k) {
    const Int r = wrap(static_cast<M>(a.v << k));
    if (Signed && (r.v >> k) != a.v) ++violations;
    return r;
  }
  friend Int operator>>(Int a, int k) { return wrap(static_cast<M>(a.v >> k)); }
  friend Bool operator==(Int a, Int b) { return {a.v == b.v}; }
  friend Bool operator!=(Int a, Int b) { return {a.v != b.v}; }
  friend Bool operator<(Int a, Int b) { return {a.v < b.v}; }
  friend Bool operator<=(Int a, Int b) { return {a.v <= b.v}; }
  friend Bool operator>(Int a, Int b) { return {a.v > b.v}; }
  friend Bool operator>=(Int a, Int b) { return {a.v >= b.v}; }
  friend Int select(Bool c, Int a, Int b) { return c.b ? a : b; }

private:
  static Int wrap(M m) {
    Int r;
    r.v = m;
    return r;
  }
  static Int bad() {
    ++violations;
    return wrap(0);
  }
  static Int checked(bool overflowed, Int r) {
    if (overflowed && Signed) ++violations;
    return r;
  }
};
using I32 = Int<32, true>;
using U32 = Int<32, false>;
using I64 = Int<64, true>;

} // namespace policy_test

TEST_CASE("the kernels run unchanged on a non-machine integer policy", "[fixed][property]") {
  using namespace antkit::kernel;
  using policy_test::I32;
  using policy_test::I64;
  using policy_test::U32;
  using policy_test::violations;
  rc::prop("mul, div, sqrt: same results, obligations exactly outside the domain", [] {
    const std::int32_t a = any_scale_raw<std::int32_t>(), b = any_scale_raw<std::int32_t>();
    violations = 0;
    const I32 m = fx_mul_raw<I32, I64, 16>(I32(a), I32(b));
    const bool mul_in = fits<std::int32_t>(exact_mul<std::int32_t, 16>(a, b));
    RC_ASSERT((violations == 0) == mul_in);
    if (mul_in) RC_ASSERT((m.v == fx_mul_raw<std::int32_t, std::int64_t, 16>(a, b)));
    violations = 0;
    const I32 q = fx_div_raw<I32, I64, 16>(I32(a), I32(b));
    const bool div_in = b != 0 && fits<std::int32_t>(exact_div<std::int32_t, 16>(a, b));
    RC_ASSERT((violations == 0) == div_in);
    if (div_in) RC_ASSERT((q.v == fx_div_raw<std::int32_t, std::int64_t, 16>(a, b)));
    violations = 0;
    const I32 r = fx_sqrt_raw<I32, I64, 16, 32>(I32(a));
    RC_ASSERT((violations == 0) == (a >= 0));
    if (a >= 0) RC_ASSERT((r.v == fx_sqrt_raw<std::int32_t, std::int64_t, 16, 32>(a)));
  });
  rc::prop("sin, cos, atan2, bearings: same results, no obligation",
           [](std::uint32_t angle, std::int32_t y, std::int32_t x) {
             violations = 0;
             RC_ASSERT((sin_raw<I32, I64, 16>(U32(angle)).v ==
                        sin_raw<std::int32_t, std::int64_t, 16>(angle)));
             RC_ASSERT((cos_raw<I32, I64, 16>(U32(angle)).v ==
                        cos_raw<std::int32_t, std::int64_t, 16>(angle)));
             RC_ASSERT((atan2_raw<I32, I64, U32>(I32(y), I32(x)).v ==
                        atan2_raw<std::int32_t, std::int64_t, std::uint32_t>(y, x)));
             RC_ASSERT(nearest_bearing_raw(U32(angle)).v == nearest_bearing_raw(angle));
             RC_ASSERT(violations == 0);
           });
}
