#include <antkit/kernel/random.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

using antkit::kernel::philox4x32_10;
using antkit::kernel::Stream;

// Known-answer vectors published with Random123 (kat_vectors, philox4x32 with 10 rounds).
TEST_CASE("philox4x32-10 matches the Random123 known answers", "[random]") {
  using A4 = std::array<std::uint32_t, 4>;
  CHECK(philox4x32_10({0, 0, 0, 0}, {0, 0}) == A4{0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8});
  CHECK(philox4x32_10({0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff}, {0xffffffff, 0xffffffff}) ==
        A4{0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd});
  CHECK(philox4x32_10({0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344}, {0xa4093822, 0x299f31d0}) ==
        A4{0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1});
}

TEST_CASE("a stream depends only on its name and on how much was drawn", "[random][property]") {
  rc::prop("same name, same draws", [](std::uint64_t seed, std::uint64_t e, std::uint64_t t) {
    Stream a(seed, e, t, 1, 2), b(seed, e, t, 1, 2);
    for (int i = 0; i < 9; ++i) RC_ASSERT(a.next_u32() == b.next_u32());
    RC_ASSERT(a.drawn() == 9u);
  });
  rc::prop("below(n) stays below n", [](std::uint64_t seed, std::uint32_t n) {
    RC_PRE(n > 0u);
    Stream s(seed);
    for (int i = 0; i < 16; ++i) RC_ASSERT(s.below(n) < n);
  });
}
