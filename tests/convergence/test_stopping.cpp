// The online stopping rule's threshold N*(P, phi) (stopping.hpp): exact, least, monotone, and
// equal to the real-valued threshold wherever that is not within rounding of an integer.
#include <antkit/buffon/stopping.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <rapidcheck/catch.h>

namespace buffon = antkit::buffon;

namespace {
// The threshold as a real number: sqrt N >= c (1 + P + sqrt(1 + P)) / P, c = 0.98 sqrt(phi).
long double real_threshold(std::uint32_t p, std::uint32_t m, long double z_half = 0.98L) {
  const long double P = static_cast<long double>(p) / 1000000.0L;
  const long double c = z_half * std::sqrt(static_cast<long double>(m) / 1000.0L);
  const long double r = c * (1 + P + std::sqrt(1 + P)) / P;
  return r * r;
}
} // namespace

TEST_CASE("stop_count is the least count meeting the precision and the real threshold rounded up",
          "[property]") {
  rc::prop("N* = ceil(real threshold); predicate false at N* - 1 and true at N*", [] {
    const auto p = *rc::gen::inRange<std::uint32_t>(1, 1000000);
    const auto m = *rc::gen::inRange<std::uint32_t>(1000, 10001);
    const std::uint64_t n = buffon::stop_count(p, m);
    RC_LOG() << "p = " << p << ", m = " << m << ", N* = " << n;
    RC_ASSERT(buffon::precision_reached(n, p, m));
    RC_ASSERT(!buffon::precision_reached(n - 1, p, m));
    const long double t = real_threshold(p, m);
    // Long double carries 64 bits of mantissa; away from an integer by more than 1e-12 relative
    // the exact and the real threshold must agree.
    if (std::fabs(t - std::nearbyint(t)) > 1e-12L * t)
      RC_ASSERT(static_cast<long double>(n) == std::ceil(t));
    // Teeth: the full-width 1.96 (instead of the half width 0.98) gives 4x the count.
    RC_ASSERT(std::ceil(real_threshold(p, m, 1.96L)) > static_cast<long double>(n) * 3);
  });
}

TEST_CASE("worked example P = 0.1 and phi = 1", "[unit]") {
  // sqrt N >= 0.98 (1.1 + sqrt 1.1) / 0.1 = 21.0583..., N >= 443.45...
  CHECK(buffon::stop_count(100000, 1000) == 444);
  // At N = 444: N / (sqrt N - 0.98)^2 = 1.09994 <= 1.1; at 443: 1.10005 > 1.1.
  CHECK(buffon::precision_reached(444, 100000, 1000));
  CHECK_FALSE(buffon::precision_reached(443, 100000, 1000));
}

TEST_CASE("the predicate is monotone and N* is monotone in P and phi (exhaustive small scope)",
          "[proof]") {
  for (const std::uint32_t m : {1000u, 2500u, 10000u})
    for (const std::uint32_t p : {50000u, 200000u, 999999u}) {
      bool seen = false;
      for (std::uint64_t n = 0; n <= 20000; ++n) {
        const bool now = buffon::precision_reached(n, p, m);
        INFO("n = " << n << ", p = " << p << ", m = " << m);
        REQUIRE((now || !seen)); // once reached, stays reached
        seen = seen || now;
      }
    }
  std::uint64_t previous = UINT64_MAX;
  for (std::uint32_t p = 1000; p < 1000000; p += 1000) {
    const auto n = buffon::stop_count(p, 2500);
    INFO("p = " << p);
    REQUIRE(n <= previous);
    REQUIRE(buffon::stop_count(p, 2600) >= n);
    previous = n;
  }
}

TEST_CASE("extreme parameters stay exact and in range", "[unit]") {
  const auto n = buffon::stop_count(1, 10000); // P = 1e-6, phi = 10: about 3.8e13
  CHECK(n > std::uint64_t{30000000000000});
  CHECK(n < (std::uint64_t{1} << 46));
  CHECK(buffon::stop_count(999999, 1000) >= 1);
  CHECK_THROWS_AS(buffon::stop_count(0, 1000), antkit::kernel::InputError);
  CHECK_THROWS_AS(buffon::stop_count(1000000, 1000), antkit::kernel::InputError);
  CHECK_THROWS_AS(buffon::stop_count(1000, 999), antkit::kernel::InputError);
  CHECK_THROWS_AS(buffon::stop_count(1000, 10001), antkit::kernel::InputError);
}

TEST_CASE("parse_precision reads decimals in (0, 1) exactly", "[unit]") {
  CHECK(buffon::parse_precision("0.05") == 50000);
  CHECK(buffon::parse_precision(".1") == 100000);
  CHECK(buffon::parse_precision("0.000001") == 1);
  CHECK(buffon::parse_precision("0.999999") == 999999);
  for (const char* bad : {"", "0", "0.0", "1", "1.0", "-0.1", "+0.1", "1e-2", "0.0000001", "0.1x",
                          ".", "abc", " 0.1", "00.5.", "2.5"}) {
    INFO("'" << bad << "'");
    CHECK_THROWS_AS(buffon::parse_precision(bad), antkit::kernel::InputError);
  }
}
