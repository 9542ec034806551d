// kernel::soft::Int, the 128-bit integers of 32-bit targets (int128.hpp), against the built-in
// __int128 of this 64-bit host: every operator and conversion on random operands of every
// magnitude (a word, two words, around zero and the extremes), bit for bit. With them, the
// reporting side's conversion to double (antkit/algorithms/wide_to_double.hpp: the kernel has no
// floating point), against the built-in conversion.
#include <antkit/algorithms/wide_to_double.hpp>
#include <antkit/kernel/int128.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck/catch.h>

namespace {

using antkit::kernel::soft::Int128;
using antkit::kernel::soft::UInt128;
__extension__ using native = __int128;
__extension__ using unative = unsigned __int128;

// A 128-bit pattern: both words random, or small, or near a power of two.
rc::Gen<unative> pattern() {
  return rc::gen::oneOf(
      rc::gen::map(
          rc::gen::pair(rc::gen::arbitrary<std::uint64_t>(), rc::gen::arbitrary<std::uint64_t>()),
          [](auto p) { return (unative{p.first} << 64) | p.second; }),
      rc::gen::map(rc::gen::arbitrary<std::int64_t>(),
                   [](std::int64_t v) { return static_cast<unative>(native{v}); }),
      rc::gen::map(rc::gen::pair(rc::gen::inRange(0, 128), rc::gen::inRange(-3, 4)), [](auto p) {
        return (unative{1} << p.first) + static_cast<unative>(native{p.second});
      }));
}

template <class Soft, class Native>
bool same(Soft s, Native n) {
  const auto u = static_cast<unative>(n);
  return s.hi() == static_cast<std::uint64_t>(u >> 64) && s.lo() == static_cast<std::uint64_t>(u);
}

template <class Soft, class Native>
void check_all(unative pa, unative pb, int shift) {
  const auto a = static_cast<Native>(pa), b = static_cast<Native>(pb);
  const auto sa =
      Soft::from_words(static_cast<std::uint64_t>(pa >> 64), static_cast<std::uint64_t>(pa));
  const auto sb =
      Soft::from_words(static_cast<std::uint64_t>(pb >> 64), static_cast<std::uint64_t>(pb));
  RC_ASSERT(same(sa + sb, static_cast<Native>(pa + pb)));
  RC_ASSERT(same(sa - sb, static_cast<Native>(pa - pb)));
  RC_ASSERT(same(sa * sb, static_cast<Native>(pa * pb)));
  RC_ASSERT(same(-sa, static_cast<Native>(0 - pa)));
  RC_ASSERT(same(~sa, static_cast<Native>(~pa)));
  RC_ASSERT(same(sa & sb, a & b));
  RC_ASSERT(same(sa | sb, a | b));
  RC_ASSERT(same(sa ^ sb, a ^ b));
  RC_ASSERT(same(sa << shift, static_cast<Native>(pa << shift)));
  RC_ASSERT(same(sa >> shift, a >> shift));
  RC_ASSERT((sa == sb) == (a == b));
  RC_ASSERT((sa < sb) == (a < b));
  RC_ASSERT((sa <= sb) == (a <= b));
  RC_ASSERT((sa > sb) == (a > b));
  // Division: not by zero, and not the signed minimum by -1 (undefined for the built-in type).
  const bool min_by_minus_one =
      std::is_signed_v<Native> && pa == (unative{1} << 127) && b == static_cast<Native>(-1);
  if (b != 0 && !min_by_minus_one) {
    RC_ASSERT(same(sa / sb, a / b));
    RC_ASSERT(same(sa % sb, a % b));
  }
  RC_ASSERT(static_cast<std::int64_t>(sa) == static_cast<std::int64_t>(a));
  RC_ASSERT(static_cast<std::uint32_t>(sa) == static_cast<std::uint32_t>(a));
  RC_ASSERT(static_cast<std::int8_t>(sa) == static_cast<std::int8_t>(a));
  RC_ASSERT(static_cast<bool>(sa) == static_cast<bool>(a));
  RC_ASSERT(antkit::algorithms::soft_to_double(sa) == static_cast<double>(a));
}

} // namespace

TEST_CASE("soft 128-bit integers equal __int128 for every operator and conversion",
          "[kernel][property]") {
  rc::prop("signed",
           [] { check_all<Int128, native>(*pattern(), *pattern(), *rc::gen::inRange(0, 128)); });
  rc::prop("unsigned",
           [] { check_all<UInt128, unative>(*pattern(), *pattern(), *rc::gen::inRange(0, 128)); });
  rc::prop("from and to machine integers", [] {
    const auto v = *rc::gen::arbitrary<std::int64_t>();
    const auto u = *rc::gen::arbitrary<std::uint64_t>();
    RC_ASSERT(same(Int128(v), native{v}));
    RC_ASSERT(same(Int128(u), native{u}));
    RC_ASSERT(same(UInt128(v), static_cast<unative>(v)));
    RC_ASSERT(same(Int128(static_cast<std::int32_t>(v)), native{static_cast<std::int32_t>(v)}));
    // Mixed signed and unsigned operands convert to unsigned, as the built-in types do.
    RC_ASSERT(same(Int128(v) + UInt128(u), static_cast<unative>(native{v}) + unative{u}));
    RC_ASSERT((Int128(v) < 0) == (v < 0));
  });
}

TEST_CASE("soft 128-bit integers: worked values at the edges", "[kernel]") {
  const Int128 min = Int128::from_words(std::uint64_t{1} << 63, 0);
  CHECK(min < 0);
  CHECK(min - 1 > 0); // wraps to the maximum
  CHECK((Int128(-7) / 2) == -3);
  CHECK((Int128(-7) % 2) == -1);
  CHECK((Int128(1) << 127) == min);
  CHECK((min >> 127) == -1);
  CHECK((UInt128(min) >> 127) == 1);
  using antkit::algorithms::soft_to_double;
  CHECK(soft_to_double(min) == -1.7014118346046923e38);
  // 2^64 + 1 and 2^100 + 2^47 + 1 round as the built-in conversion does.
  CHECK(soft_to_double(UInt128::from_words(1, 1)) == 18446744073709551616.0);
  CHECK(soft_to_double((UInt128(1) << 100) + (UInt128(1) << 47) + 1) ==
        static_cast<double>((unative{1} << 100) + (unative{1} << 47) + 1));
}
