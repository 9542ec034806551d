// Statistical checks of the keyed streams: Pearson chi-square goodness of fit on fixed seeds.
//
// Each check bins draws from a fixed stream and compares the counts with their expectation. The
// statistic X^2 = sum (O - E)^2 / E is computed exactly in integers and compared with a critical
// value c, scaled to thousandths and rounded up: the check passes when 1000 sum (O - E)^2 <=
// c_milli E. c is the upper 1e-7 quantile of the chi-square distribution with the check's degrees
// of freedom (computed from the regularized incomplete gamma function), so a correct generator
// fails any one check with probability below 1e-7, and all eight checks of this file together
// (union bound) with probability below 1e-6. Expected counts are at least 4096 per bin, where the
// chi-square approximation of the multinomial is accurate far beyond that tail.
//
// The seeds are fixed, so the outcome is deterministic: the probability statement is about
// choosing the seed, i.e. how unlikely it is that a correct generator lands on a failing seed.
// The last test shows the checks have teeth: the same statistic rejects a biased map.
#include <antkit/kernel/random.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <vector>

using antkit::kernel::Stream;

namespace {

// Upper 1e-7 quantiles of chi-square, in thousandths, rounded up.
constexpr std::int64_t kCrit1 = 28374;    // 1 degree of freedom (28.37399)
constexpr std::int64_t kCrit9 = 50172;    // 9 degrees of freedom (50.17180)
constexpr std::int64_t kCrit255 = 390243; // 255 degrees of freedom (390.24207)

constexpr std::uint64_t kSeed = 20261121;

// 1000 * sum (O - E)^2 for equal expectations E = total / bins (total a multiple of bins).
std::int64_t scaled_sum_sq(const std::vector<std::int64_t>& counts, std::int64_t expected) {
  std::int64_t sum = 0;
  for (std::int64_t o : counts) sum += (o - expected) * (o - expected);
  return 1000 * sum;
}

// The check is lhs <= rhs; X^2 itself is lhs / (1000 E).
struct ChiSquare {
  std::int64_t lhs; // 1000 sum (O - E)^2
  std::int64_t rhs; // c_milli E
};

ChiSquare uniform_fit(const std::vector<std::int64_t>& counts, std::int64_t total,
                      std::int64_t crit_milli) {
  const auto bins = static_cast<std::int64_t>(counts.size());
  REQUIRE(total % bins == 0);
  const std::int64_t expected = total / bins;
  return {scaled_sum_sq(counts, expected), crit_milli * expected};
}

} // namespace

TEST_CASE("chi-square: the top and low bytes of next_u32 are uniform", "[random]") {
  constexpr std::int64_t n = std::int64_t{1} << 20; // 4096 expected per bin
  Stream s(kSeed, 1, 0, 0, 0);
  std::vector<std::int64_t> top(256, 0), low(256, 0);
  for (std::int64_t k = 0; k < n; ++k) {
    const std::uint32_t w = s.next_u32();
    ++top[w >> 24];
    ++low[w & 0xFF];
  }
  const ChiSquare t = uniform_fit(top, n, kCrit255), l = uniform_fit(low, n, kCrit255);
  INFO("top byte X^2 * 1000 * E = " << t.lhs << ", limit " << t.rhs);
  CHECK(t.lhs <= t.rhs);
  INFO("low byte X^2 * 1000 * E = " << l.lhs << ", limit " << l.rhs);
  CHECK(l.lhs <= l.rhs);
}

TEST_CASE("chi-square: below(n) is uniform for a small and a large n", "[random]") {
  constexpr std::int64_t n = 1'000'000; // 100000 expected per bin
  {
    Stream s(kSeed, 2, 0, 0, 0);
    std::vector<std::int64_t> counts(10, 0);
    for (std::int64_t k = 0; k < n; ++k) ++counts[s.below(10)];
    const ChiSquare c = uniform_fit(counts, n, kCrit9);
    INFO("below(10): " << c.lhs << " <= " << c.rhs);
    CHECK(c.lhs <= c.rhs);
  }
  {
    // n = 3e9 rejects almost a third of the words; its ten equal tenths must still be uniform.
    Stream s(kSeed, 2, 0, 0, 1);
    std::vector<std::int64_t> counts(10, 0);
    for (std::int64_t k = 0; k < n; ++k) ++counts[s.below(3'000'000'000u) / 300'000'000u];
    const ChiSquare c = uniform_fit(counts, n, kCrit9);
    INFO("below(3e9) in tenths: " << c.lhs << " <= " << c.rhs);
    CHECK(c.lhs <= c.rhs);
  }
}

TEST_CASE("chi-square: chance(1, 3) comes up a third of the time", "[random]") {
  constexpr std::int64_t n = 3'000'000;
  Stream s(kSeed, 3, 0, 0, 0);
  std::int64_t hits = 0;
  for (std::int64_t k = 0; k < n; ++k) hits += s.chance(1, 3) ? 1 : 0;
  // Two bins with E = n/3 and 2n/3: X^2 = d^2 (3/n + 3/(2n)) = 9 d^2 / (2n), d = hits - n/3.
  const std::int64_t d = hits - n / 3;
  INFO("hits " << hits << " of " << n);
  CHECK(1000 * 9 * d * d <= kCrit1 * 2 * n);
}

TEST_CASE("chi-square: consecutive words are independent (serial pairs)", "[random]") {
  // The top four bits of two consecutive words index one of 256 cells.
  constexpr std::int64_t n = std::int64_t{1} << 20;
  Stream s(kSeed, 4, 0, 0, 0);
  std::vector<std::int64_t> counts(256, 0);
  for (std::int64_t k = 0; k < n; ++k) {
    const std::uint32_t hi = s.next_u32() >> 28;
    const std::uint32_t lo = s.next_u32() >> 28;
    ++counts[hi * 16 + lo];
  }
  const ChiSquare c = uniform_fit(counts, n, kCrit255);
  INFO(c.lhs << " <= " << c.rhs);
  CHECK(c.lhs <= c.rhs);
}

TEST_CASE("chi-square: neighbouring stream names give independent first words", "[random]") {
  // The first word of the streams of trials 0, 1, 2, ... (the keyed layout of an experiment) and of
  // seeds 0, 1, 2, ...: uniform in the top byte across streams.
  constexpr std::int64_t n = std::int64_t{1} << 20;
  std::vector<std::int64_t> by_trial(256, 0), by_seed(256, 0);
  for (std::int64_t k = 0; k < n; ++k) {
    ++by_trial[Stream(kSeed, 5, static_cast<std::uint64_t>(k), 0, 0).next_u32() >> 24];
    ++by_seed[Stream(static_cast<std::uint64_t>(k), 5, 0, 0, 0).next_u32() >> 24];
  }
  const ChiSquare t = uniform_fit(by_trial, n, kCrit255), s = uniform_fit(by_seed, n, kCrit255);
  INFO("by trial " << t.lhs << " <= " << t.rhs);
  CHECK(t.lhs <= t.rhs);
  INFO("by seed " << s.lhs << " <= " << s.rhs);
  CHECK(s.lhs <= s.rhs);
}

TEST_CASE("chi-square rejects a biased map (the checks have teeth)", "[random]") {
  // x mod 3e9 instead of Lemire's map: values below 2^32 - 3e9 come twice as often. The same
  // statistic as above must reject it by a wide margin.
  constexpr std::int64_t n = 1'000'000;
  Stream s(kSeed, 2, 0, 0, 1);
  std::vector<std::int64_t> counts(10, 0);
  for (std::int64_t k = 0; k < n; ++k) ++counts[(s.next_u32() % 3'000'000'000u) / 300'000'000u];
  const ChiSquare c = uniform_fit(counts, n, kCrit9);
  CHECK(c.lhs > 100 * c.rhs);
}
