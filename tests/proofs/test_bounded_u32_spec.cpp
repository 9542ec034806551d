// A regression test of the shipped antkit::kernel::bounded_u32 against the specification that
// proofs/z3/bounded_u32.cpp proves it meets (accepted <=> the low word of x * n is at least
// 2^32 mod n; the output is the high word; a rejection leaves the output untouched), here computed
// independently in plain 64-bit arithmetic.
//
// Until the shipped function became the template the proof instantiates, this file held a template
// copy to it (the file keeps its old name). The Z3 proof is now about the shipped code itself, so
// this test is not the proof's link any more; it stays because it is cheap and checks the machine
// instantiation (MachineWords) on every edge word, where a slip in the policy would show first.
#include <antkit/kernel/random.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck/catch.h>

namespace {

// Same acceptance as the specification, and the same output (or none) as it.
bool meets_specification(std::uint32_t x, std::uint32_t n) {
  constexpr std::uint32_t kUntouched = 0xDEADBEEFu;
  std::uint32_t out = kUntouched;
  const bool accepted = antkit::kernel::bounded_u32(x, n, out);
  const std::uint64_t m = std::uint64_t{x} * n;
  const std::uint64_t threshold = (std::uint64_t{1} << 32) % n;
  const bool expected = (m & 0xFFFFFFFFu) >= threshold;
  if (accepted != expected) return false;
  return accepted ? out == static_cast<std::uint32_t>(m >> 32) : out == kUntouched;
}

} // namespace

TEST_CASE("bounded_u32 meets its specification", "[proofs][property]") {
  rc::prop("on random words and bounds", [](std::uint32_t x, std::uint32_t n) {
    RC_PRE(n >= 1u);
    RC_ASSERT(meets_specification(x, n));
  });
  rc::prop("near the rejection threshold, where the two branches of the short-circuit differ",
           [](std::uint32_t n, std::uint32_t k) {
             RC_PRE(n >= 1u);
             // x * n lands just below or above 2^32 mod n in its low word for x near k * 2^32 / n.
             const auto x = static_cast<std::uint32_t>((std::uint64_t{k} << 32) / n);
             for (std::uint32_t d = 0; d < 4; ++d) RC_ASSERT(meets_specification(x + d, n));
           });
}

// Exhaustive over the edge words for bounds whose rejection zones differ in shape: n = 1 (nothing
// rejected), powers of two (nothing rejected), 3, 5, 7 (small zones), and n near 2^31 and 2^32
// (zones of nearly half and nearly all the low words). 2^32 words each, so only the low 2^20
// words and the top 2^20 words, where every zone starts and ends for these n.
TEST_CASE("bounded_u32 meets its specification on every edge word for chosen bounds",
          "[proofs][proof]") {
  const std::uint32_t bounds[] = {1u,          2u,          3u,          5u,
                                  7u,          1u << 16,    65535u,      0x80000000u,
                                  0x80000001u, 0xFFFFFFFEu, 0xFFFFFFFFu, 1000000007u};
  for (const std::uint32_t n : bounds) {
    std::uint64_t mismatches = 0;
    for (std::uint32_t x = 0; x < (1u << 20); ++x) {
      mismatches += meets_specification(x, n) ? 0u : 1u;
      mismatches += meets_specification(0xFFFFFFFFu - x, n) ? 0u : 1u;
    }
    INFO("n = " << n);
    CHECK(mismatches == 0);
  }
}
