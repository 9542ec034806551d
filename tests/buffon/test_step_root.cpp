// step_root.hpp: the Buffon family's one integer square root. The root is the kernel's proved loop;
// the fast path takes a guess only when it is the root. Checked against the definition
// (r^2 <= n < (r + 1)^2, in 128 bits) for any n and any guess, exhaustively near the squares.
#include <antkit/buffon/step_root.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck/catch.h>

namespace {

bool is_root(std::uint64_t n, std::uint64_t r) {
  const auto r2 = static_cast<antkit::kernel::uint128>(r) * r;
  const auto next = static_cast<antkit::kernel::uint128>(r + 1) * (r + 1);
  return r2 <= n && n < next;
}

} // namespace

TEST_CASE("step_root is the floor square root whatever the guess", "[property]") {
  rc::prop("isqrt_proved(n) is the root, below and above 2^48", [] {
    const std::uint64_t n = *rc::gen::oneOf(rc::gen::inRange<std::uint64_t>(0, 1ull << 48),
                                            rc::gen::arbitrary<std::uint64_t>());
    RC_ASSERT(is_root(n, antkit::buffon::isqrt_proved(n)));
  });
  rc::prop("step_root(n, guess) is the root for any guess, near or far", [] {
    const std::uint64_t n = *rc::gen::arbitrary<std::uint64_t>();
    const std::uint64_t root = antkit::buffon::isqrt_proved(n);
    const std::uint64_t guess =
        *rc::gen::oneOf(rc::gen::arbitrary<std::uint64_t>(),
                        rc::gen::map(rc::gen::inRange<int>(-3, 4), [root](int d) {
                          return root + static_cast<std::uint64_t>(static_cast<std::int64_t>(d));
                        }));
    RC_ASSERT(antkit::buffon::step_root(n, guess) == root);
  });
}

TEST_CASE("step_root from guesses a step's length away, as the walks pass them", "[property]") {
  // The Newton path: the guess up to a few thousand raw units from the root (a previous step's
  // length against this one's), and every guess for every n below 2^12.
  rc::prop("guesses near the root, below 2^48", [] {
    const std::uint64_t n = *rc::gen::inRange<std::uint64_t>(0, 1ull << 48);
    const std::uint64_t root = antkit::buffon::isqrt_proved(n);
    const auto d = *rc::gen::inRange<std::int64_t>(-5000, 5001);
    const std::uint64_t guess =
        d < 0 && root < static_cast<std::uint64_t>(-d) ? 0 : root + static_cast<std::uint64_t>(d);
    RC_ASSERT(antkit::buffon::step_root(n, guess) == root);
  });
  for (std::uint64_t n = 0; n < 4096; ++n)
    for (std::uint64_t guess = 0; guess < 128; ++guess)
      REQUIRE(antkit::buffon::step_root(n, guess) == antkit::buffon::isqrt_proved(n));
}

TEST_CASE("step_root near every square up to 2^12 and at the ends of the range") {
  for (std::uint64_t r = 0; r < 4096; ++r)
    for (const std::uint64_t n : {r * r, r * r + r, r * r + 2 * r}) // the first, middle, last n
      for (std::uint64_t guess = r >= 2 ? r - 2 : 0; guess <= r + 2; ++guess) {
        REQUIRE(antkit::buffon::step_root(n, guess) == r);
        REQUIRE(antkit::buffon::isqrt_proved(n) == r);
      }
  for (const std::uint64_t n : {(1ull << 48) - 1, 1ull << 48, ~0ull, ~0ull - 1}) {
    CHECK(is_root(n, antkit::buffon::isqrt_proved(n)));
    CHECK(antkit::buffon::step_root(n, 0xFFFFFFFFull) == antkit::buffon::isqrt_proved(n));
  }
  CHECK(antkit::buffon::isqrt_proved(~0ull) == 0xFFFFFFFFull);
}
