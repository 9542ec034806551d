// The Coq model of the supercover walk (proofs/coq/Supercover.v) and the shipped
// antkit::kernel::supercover, held to each other: proof.coq.Supercover requires coqc's `Compute`
// output to equal proofs/golden/Supercover.out, and this test requires the shipped code to emit
// the same cells, in the same order, for those walks (and their reflections and translations,
// which RasterFrame maps onto the same local walk). Tested correspondence between the model and
// the code on these vectors, not a proof about the C++ code itself.
#include "coq_golden.hpp"
#include "test_paths.hpp"

#include <antkit/kernel/raster.hpp>
#include <array>
#include <catch2/catch.hpp>
#include <cctype>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using antkit::kernel::Cell;

// The walks Supercover.v computes, in its order: b - a = (dx, dy).
constexpr std::array<std::pair<int, int>, 9> kWalks{
    {{0, 0}, {3, 5}, {5, 3}, {4, 2}, {3, 3}, {3, 1}, {0, 4}, {6, 0}, {7, 3}}};

} // namespace

TEST_CASE("the shipped supercover emits the Coq model's golden walks, cell by cell",
          "[proofs][raster]") {
  const auto vectors =
      antkit::test::coq_golden_vectors(antkit::test::source_path("proofs/golden/Supercover.out"));
  REQUIRE(vectors.size() == kWalks.size());
  // The model's local walk from (0, 0) to (dx, dy) is the shipped walk from a to
  // a + (sx dx, sy dy) with each cell mapped by a + (sx i, sy j): check all four reflections at
  // two origins.
  const std::array<Cell, 2> origins{{{0, 0}, {-7, 11}}};
  for (std::size_t k = 0; k < kWalks.size(); ++k) {
    const auto [dx, dy] = kWalks[k];
    const std::vector<int>& want = vectors[k];
    REQUIRE(want.size() % 2 == 0);
    for (const Cell a : origins)
      for (const int sx : {1, -1})
        for (const int sy : {1, -1}) {
          INFO("walk " << k << ": a = (" << a.x << ", " << a.y << "), b - a = (" << sx * dx << ", "
                       << sy * dy << ")");
          const std::vector<Cell> got =
              antkit::kernel::supercover(a, {a.x + sx * dx, a.y + sy * dy});
          REQUIRE(got.size() * 2 == want.size());
          for (std::size_t c = 0; c < got.size(); ++c) {
            const Cell expect{a.x + sx * want[2 * c], a.y + sy * want[2 * c + 1]};
            INFO("cell " << c);
            CHECK(got[c] == expect);
          }
        }
  }
}
