// The link between the Z3 proof of Lemire's rejection (proofs/z3/bounded_u32.cpp) and the shipped
// antkit::kernel::bounded_u32: the proof is about a template copy, and this test holds the copy to
// the shipped function. It is tested correspondence, not a proof (proofs/PROOFS.md says so).
#include "../../proofs/z3/bounded_u32_template.hpp"

#include <antkit/kernel/random.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck/catch.h>

namespace {

using antkit::proofs::bounded_u32_t;
using antkit::proofs::MachineWords;

// Same acceptance, and the same output whenever the shipped function accepts.
bool agree(std::uint32_t x, std::uint32_t n) {
  std::uint32_t shipped_out = 0xDEADBEEFu;
  const bool shipped = antkit::kernel::bounded_u32(x, n, shipped_out);
  const auto [copy, copy_out] = bounded_u32_t<MachineWords>(x, n);
  return shipped == copy && (!shipped || shipped_out == copy_out);
}

} // namespace

TEST_CASE("the proved template copy of bounded_u32 equals the shipped one", "[proofs][property]") {
  rc::prop("on random words and bounds", [](std::uint32_t x, std::uint32_t n) {
    RC_PRE(n >= 1u);
    RC_ASSERT(agree(x, n));
  });
  rc::prop("near the rejection threshold, where the two branches of the short-circuit differ",
           [](std::uint32_t n, std::uint32_t k) {
             RC_PRE(n >= 1u);
             // x * n lands just below or above 2^32 mod n in its low word for x near k * 2^32 / n.
             const auto x = static_cast<std::uint32_t>((std::uint64_t{k} << 32) / n);
             for (std::uint32_t d = 0; d < 4; ++d) RC_ASSERT(agree(x + d, n));
           });
}

// Exhaustive over the words for bounds whose rejection zones differ in shape: n = 1 (nothing
// rejected), powers of two (nothing rejected), 3, 5, 7 (small zones), and n near 2^31 and 2^32
// (zones of nearly half and nearly all the low words). 2^32 words each, so only the low 2^20
// words and the top 2^20 words, where every zone starts and ends for these n.
TEST_CASE("the copy equals the shipped function on every edge word for chosen bounds",
          "[proofs][proof]") {
  const std::uint32_t bounds[] = {1u,          2u,          3u,          5u,
                                  7u,          1u << 16,    65535u,      0x80000000u,
                                  0x80000001u, 0xFFFFFFFEu, 0xFFFFFFFFu, 1000000007u};
  for (const std::uint32_t n : bounds) {
    std::uint64_t mismatches = 0;
    for (std::uint32_t x = 0; x < (1u << 20); ++x) {
      mismatches += agree(x, n) ? 0u : 1u;
      mismatches += agree(0xFFFFFFFFu - x, n) ? 0u : 1u;
    }
    INFO("n = " << n);
    CHECK(mismatches == 0);
  }
}
