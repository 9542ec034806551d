// The batched random draws the Buffon robot uses: Stream::next_u32s and philox4x32_10_x4
// (kernel/random.hpp) and the behaviour's BufferedStream (buffon/exploration.hpp). Each must give
// exactly the words and draws of the plain, one-at-a-time forms, since the trace hashes depend on
// every one of them.
#include <antkit/buffon/exploration.hpp>
#include <antkit/kernel/fixed_random.hpp>
#include <antkit/kernel/random.hpp>
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck/catch.h>
#include <vector>

namespace kernel = antkit::kernel;
using Block = std::array<std::uint32_t, 4>;

namespace {

// The four-block form against four single blocks, at compile time (the scalar rounds).
constexpr bool x4_matches_single(std::array<Block, 4> ctr, std::array<std::uint32_t, 2> key) {
  const auto four = kernel::philox4x32_10_x4(ctr, key);
  for (std::size_t b = 0; b < 4; ++b)
    if (four[b] != kernel::philox4x32_10(ctr[b], key)) return false;
  return true;
}
static_assert(x4_matches_single({Block{0, 0, 0, 0}, Block{1, 0, 0, 0}, Block{2, 0, 0, 0},
                                 Block{3, 0, 0, 0}},
                                {0, 0}));
static_assert(x4_matches_single({Block{0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu},
                                 Block{0x243F6A88u, 0x85A308D3u, 0x13198A2Eu, 0x03707344u},
                                 Block{7, 8, 9, 10}, Block{0x80000000u, 1, 0x80000000u, 1}},
                                {0xA4093822u, 0x299F31D0u}));
// Random123's known answer for Philox4x32-10 on the counter and key of all ones, in lane 2.
static_assert(kernel::philox4x32_10_x4({Block{}, Block{},
                                        Block{0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu},
                                        Block{}},
                                       {0xFFFFFFFFu, 0xFFFFFFFFu})[2] ==
              Block{0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu});

// next_u32s in a constant expression (the scalar rounds): 3 single words, a batch of 37 (the rest
// of a block, two groups of four blocks, a tail), then one more word, against 41 next_u32 calls.
constexpr bool batch_matches_singles() {
  kernel::Stream batched(99, 4, 5, 1, 0), plain(99, 4, 5, 1, 0);
  for (int k = 0; k < 3; ++k)
    if (batched.next_u32() != plain.next_u32()) return false;
  std::array<std::uint32_t, 37> words{};
  batched.next_u32s(words);
  for (std::uint32_t w : words)
    if (w != plain.next_u32()) return false;
  return batched.drawn() == plain.drawn() && batched.next_u32() == plain.next_u32();
}
static_assert(batch_matches_singles());

} // namespace

TEST_CASE("philox4x32_10_x4 at run time equals four philox4x32_10 blocks", "[property]") {
  // At run time on x86-64 this is the SSE2 path; the compile-time checks above cover the scalar
  // one.
  rc::prop("the same four blocks", [] {
    std::array<Block, 4> ctr{};
    for (auto& c : ctr)
      for (auto& w : c) w = *rc::gen::arbitrary<std::uint32_t>();
    const std::array<std::uint32_t, 2> key{*rc::gen::arbitrary<std::uint32_t>(),
                                           *rc::gen::arbitrary<std::uint32_t>()};
    const auto four = kernel::philox4x32_10_x4(ctr, key);
    for (std::size_t b = 0; b < 4; ++b) RC_ASSERT(four[b] == kernel::philox4x32_10(ctr[b], key));
  });
}

TEST_CASE("next_u32s draws the words next_u32 would, and leaves the stream where it would",
          "[property]") {
  rc::prop("batches of any size, mixed with single draws", [] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto trial = *rc::gen::arbitrary<std::uint64_t>();
    kernel::Stream batched(seed, 4, trial, 1, 0), plain(seed, 4, trial, 1, 0);
    const auto sizes =
        *rc::gen::container<std::vector<std::size_t>>(rc::gen::inRange<std::size_t>(0, 70));
    for (std::size_t n : sizes) {
      RC_LOG() << "seed " << seed << " trial " << trial << " batch of " << n << " after "
               << plain.drawn() << " words\n";
      std::vector<std::uint32_t> words(n);
      batched.next_u32s(words);
      for (std::uint32_t w : words) RC_ASSERT(w == plain.next_u32());
      RC_ASSERT(batched.drawn() == plain.drawn());
      // A single draw in between: the two forms mix.
      RC_ASSERT(batched.next_u32() == plain.next_u32());
    }
  });
}

TEST_CASE("BufferedStream draws what kernel::uniform draws from the stream", "[property]") {
  rc::prop("the same values for any interval, including ones with frequent rejections", [] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    kernel::Stream stream(seed, 4, 9, 2, 0);
    antkit::buffon::BufferedStream buffered(stream);
    for (int k = 0; k < 60; ++k) {
      const auto a = *rc::gen::arbitrary<std::int32_t>();
      // Spans up to the whole 32-bit range: spans just above 2^31 reject almost half the words.
      const auto span =
          *rc::gen::oneOf(rc::gen::inRange<std::uint32_t>(0, 70000),
                          rc::gen::inRange<std::uint32_t>(0x80000000u, 0x80001000u),
                          rc::gen::just(0xFFFFFFFFu), rc::gen::arbitrary<std::uint32_t>());
      const auto b = static_cast<std::int32_t>(static_cast<std::uint32_t>(a) + span);
      if (b < a) continue; // uniform needs a <= b
      RC_LOG() << "seed " << seed << " draw " << k << " [" << a << ", " << b << "]\n";
      const auto fa = antkit::kernel::Fx::from_raw(a), fb = antkit::kernel::Fx::from_raw(b);
      RC_ASSERT(buffered.uniform(fa, fb) == kernel::uniform(stream, fa, fb));
    }
  });
}

TEST_CASE("the behaviour's draws: a worked example against the plain stream") {
  // The behaviour draws n in [-0.4, 0.4] then n_bar in [0.3, 1] every step; 1000 steps' worth
  // through the buffer equal the plain draws (this crosses the buffer's refill many times).
  namespace d = antkit::buffon::detail;
  kernel::Stream stream(1, 4, 0, 1, 0);
  antkit::buffon::BufferedStream buffered(stream);
  int mismatches = 0;
  for (int s = 0; s < 1000; ++s) {
    mismatches += buffered.uniform(-d::kNLimit, d::kNLimit) !=
                  kernel::uniform(stream, -d::kNLimit, d::kNLimit);
    mismatches +=
        buffered.uniform(d::kNBarLow, d::kOne) != kernel::uniform(stream, d::kNBarLow, d::kOne);
  }
  CHECK(mismatches == 0);
}
