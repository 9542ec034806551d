// The Coq model of the ant-like STC rules (proofs/coq/AntStc.v) and the shipped code
// (algorithms/stc: ant_decide, covered_from_edges), held to each other: proof.coq.AntStc requires
// coqc's `Compute` output to equal proofs/golden/AntStc.out, and this test requires the shipped
// code to give the same answer on every input of both rules. Tested correspondence between the
// model and the code, not a proof about the C++ code itself.
#include "coq_golden.hpp"
#include "test_paths.hpp"

#include <antkit/stc/ant.hpp>
#include <catch2/catch.hpp>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace antkit::stc;

Command decide(int cur, std::uint8_t here, unsigned free_neighbours) {
  int q = cur;
  bool done = false;
  return ant_decide(q, done, static_cast<std::uint8_t>(free_neighbours), here, {0, 0, 0, 0});
}

// Step 1 of ant_decide (w = Parent(x)) is internal, so it is read back from the decisions, which
// depend on w only through the order of the neighbour scan (w + 1, ..., w + 3, w) and the target:
//   * no free neighbour: the target is w, so the robot walks on around the cell when w != cur and
//     stops (no way back) when w == cur;
//   * otherwise w is one of cur + 1, cur + 2, cur + 3: with exactly two new neighbours, cur and a,
//     the robot crosses side cur iff cur comes before a in the scan. That holds for n of the three
//     a != cur, and w = cur + n (w = cur + 1: only a = cur + 1; w = cur + 2: a = cur + 1, cur + 2;
//     w = cur + 3 = cur - 1: all three).
int observed_parent(int cur, std::uint8_t here) {
  if (decide(cur, here, 0).move == Move::Stop) return cur;
  int n = 0;
  for (int k = 1; k <= 3; ++k) {
    const int a = dir_add(cur, k);
    if (decide(cur, here, (1u << cur) | (1u << a)).move == move_towards(cur)) ++n;
  }
  return dir_add(cur, n);
}

} // namespace

TEST_CASE("the shipped parent-from-marks rule equals the Coq model's golden table, every input",
          "[proofs][stc]") {
  const auto vectors =
      antkit::test::coq_golden_vectors(antkit::test::source_path("proofs/golden/AntStc.out"));
  REQUIRE(vectors.size() >= 2);
  const std::vector<int>& table = vectors[0]; // current quadrant 0..3 x here-mask 0..15
  REQUIRE(table.size() == 64);
  for (int cur = 0; cur < 4; ++cur)
    for (int here = 0; here < 16; ++here) {
      INFO("quadrant " << cur << ", here " << here);
      CHECK(observed_parent(cur, static_cast<std::uint8_t>(here)) ==
            table[static_cast<std::size_t>(cur * 16 + here)]);
    }
}

TEST_CASE("the reading of ant_decide's step 1 can fail: a walk where w == cur is told apart",
          "[proofs][stc]") {
  // The black-box reading above is only worth something if it distinguishes the four answers:
  // the first entry of a pass (robot on w + 1, nothing marked) reads w, and the last (robot on w,
  // the other three marked) reads w == cur, for every w.
  for (int w = 0; w < 4; ++w) {
    INFO("parent direction " << w);
    CHECK(observed_parent(dir_add(w, 1), 0) == w);
    const auto others = static_cast<std::uint8_t>(0x0F & ~(1u << w));
    CHECK(observed_parent(w, others) == w);
  }
}

TEST_CASE("the shipped edge rule equals the Coq model's golden table for every 12-bit mask",
          "[proofs][stc]") {
  const auto vectors =
      antkit::test::coq_golden_vectors(antkit::test::source_path("proofs/golden/AntStc.out"));
  REQUIRE(vectors.size() >= 2);
  const std::vector<int>& table = vectors[1];
  REQUIRE(table.size() == 4096);
  for (unsigned edges = 0; edges < 4096; ++edges) {
    INFO("edges " << edges);
    CHECK(covered_from_edges(static_cast<std::uint16_t>(edges)) == table[edges]);
  }
}

TEST_CASE("the shipped paper rule and five boxes equal the Coq model's golden tables",
          "[proofs][stc]") {
  const auto vectors =
      antkit::test::coq_golden_vectors(antkit::test::source_path("proofs/golden/AntStc.out"));
  REQUIRE(vectors.size() >= 4);
  const std::vector<int>& rule = vectors[2]; // paper_rule, box states 0..31
  REQUIRE(rule.size() == 32);
  for (unsigned boxes = 0; boxes < 32; ++boxes) {
    INFO("boxes " << boxes);
    CHECK(paper_rule(static_cast<std::uint8_t>(boxes)) == rule[boxes]);
  }
  const std::vector<int>& single = vectors[3]; // paper_boxes(1 << b, entry), 12 * entry + b
  REQUIRE(single.size() == 48);
  for (int entry = 0; entry < 4; ++entry)
    for (unsigned edges = 0; edges < 4096; ++edges) {
      // The model's paper_boxes of a mask is the OR of its single-edge values (each box reads one
      // edge), so the golden single-edge table gives the model's value on every mask.
      unsigned want = 0;
      for (int b = 0; b < 12; ++b)
        if (((edges >> b) & 1u) != 0)
          want |= static_cast<unsigned>(single[static_cast<std::size_t>(12 * entry + b)]);
      INFO("entry " << entry << ", edges " << edges);
      CHECK(paper_boxes(static_cast<std::uint16_t>(edges), entry) == want);
    }
}
