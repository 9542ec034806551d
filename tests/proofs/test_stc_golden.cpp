// The Coq model of the STC tour (proofs/coq/StcTour.v, where every tour of the model is proved to
// visit each sub-cell of the spanned cells exactly once and to be closed) and the shipped offline
// STC (antkit::stc::SpanningTree), held to each other: proof.coq.StcTour requires coqc's `Compute`
// output to equal proofs/golden/StcTour.out, and this test requires the shipped code to walk the
// same tours. Tested correspondence on four trees (an L, a T, a plus, a 2 x 3 block), not a proof
// about the C++ code. A second test transcribes the model's `tour` recursion over the shipped
// spanning tree and requires SpanningTree::advance to walk the same tour on every cell map of up
// to 12 cells (4 x 3, 3 x 4 and smaller) from every start sub-cell.
#include "coq_golden.hpp"
#include "test_paths.hpp"

#include <algorithm>
#include <antkit/stc/offline.hpp>
#include <catch2/catch.hpp>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using antkit::stc::SpanningTree;

// The sub-cell lists of each `Compute` result of the golden file, in order: a result runs from its
// "=" to its " : " type line and is a list of (x, y) pairs. Coq breaks lines inside a pair, so only
// the integers (with their signs) are read, two at a time.
std::vector<std::vector<Cell>> golden_tours(const std::string& path) {
  std::vector<std::vector<Cell>> out;
  for (const std::vector<int>& numbers : antkit::test::coq_golden_vectors(path)) {
    REQUIRE(numbers.size() % 2 == 0);
    std::vector<Cell> tour;
    for (std::size_t k = 0; k < numbers.size(); k += 2)
      tour.push_back({numbers[k], numbers[k + 1]});
    out.push_back(std::move(tour));
  }
  return out;
}

// The shipped tour over exactly the cells the model's tour passes through, from its first
// sub-cell. The map has one blocked cell of margin beyond the largest coordinates, so the cells
// free in the map are exactly the model's cells (the model's vectors use no negative coordinate).
std::vector<Cell> shipped_tour(const std::vector<Cell>& model, std::int64_t& cells) {
  std::set<std::pair<int, int>> cell_set;
  int max_x = 0, max_y = 0;
  for (Cell s : model) {
    REQUIRE(s.x >= 0);
    REQUIRE(s.y >= 0);
    cell_set.insert({s.x / 2, s.y / 2});
    max_x = std::max(max_x, s.x / 2);
    max_y = std::max(max_y, s.y / 2);
  }
  OccupancyGrid map(2 * (max_x + 2), 2 * (max_y + 2), Occupancy::Blocked);
  for (auto [cx, cy] : cell_set)
    for (int q = 0; q < 4; ++q) map[antkit::stc::subcell_of({cx, cy}, q)] = Occupancy::Free;
  const SpanningTree tree(map, model.front());
  cells = static_cast<std::int64_t>(cell_set.size());
  REQUIRE(tree.cells() == cells);
  return tree.tour();
}

// StcTour.v's `tour`, transcribed: entering cell c whose parent lies in direction p, the sub-cell
// p + 1; then for each side d = p + 1, p + 2, p + 3 the child's tour (if the shipped tree has a
// child in direction d) and the sub-cell d + 1. The parent's slot is never read.
void model_tour(const SpanningTree& tree, Cell c, int p, std::vector<Cell>& out) {
  using namespace antkit::stc;
  out.push_back(subcell_of(c, dir_add(p, 1)));
  for (int k = 1; k <= 3; ++k) {
    const int d = dir_add(p, k);
    if ((tree.children(c) >> d) & 1u) model_tour(tree, step(c, d), opposite(d), out);
    out.push_back(subcell_of(c, dir_add(d, 1)));
  }
}

// StcTour.v's `stc_tour`: the root's tour with the virtual parent p = q0 - 1, then the tour of
// the root's child in direction p, if any.
std::vector<Cell> model_stc_tour(const SpanningTree& tree) {
  using namespace antkit::stc;
  std::vector<Cell> out;
  const Cell root = tree.root();
  const int p = dir_add(quadrant_of(tree.start()), 3);
  model_tour(tree, root, p, out);
  if ((tree.children(root) >> p) & 1u) model_tour(tree, step(root, p), opposite(p), out);
  return out;
}

} // namespace

TEST_CASE("every cell map of up to 12 cells in a 4 x 4 box - every start: the shipped tour is the "
          "Coq model's "
          "tour of the shipped tree",
          "[proofs][stc][proof]") {
  std::int64_t pairs = 0;
  for (int cw = 1; cw <= 4; ++cw)
    for (int ch = 1; ch <= 4; ++ch) {
      if (cw * ch > 12) continue; // 4 x 4 is test_stc_exhaustive's (slow) job
      OccupancyGrid map(2 * cw, 2 * ch, Occupancy::Blocked);
      for (std::uint32_t mask = 0; mask < (1u << (cw * ch)); ++mask) {
        // Bit i of the mask: cell (i % cw, i / cw) is free.
        for (int i = 0; i < cw * ch; ++i)
          for (int q = 0; q < 4; ++q)
            map[antkit::stc::subcell_of({i % cw, i / cw}, q)] =
                ((mask >> i) & 1u) ? Occupancy::Free : Occupancy::Blocked;
        for (int i = 0; i < cw * ch; ++i) {
          if (((mask >> i) & 1u) == 0) continue;
          for (int q = 0; q < 4; ++q) {
            const Cell start = antkit::stc::subcell_of({i % cw, i / cw}, q);
            const SpanningTree tree(map, start);
            const std::vector<Cell> shipped = tree.tour();
            const std::vector<Cell> model = model_stc_tour(tree);
            if (shipped != model) {
              INFO("map " << cw << " x " << ch << " cells, free mask " << mask << ", start ("
                          << start.x << ", " << start.y << "): shipped " << shipped.size()
                          << " positions, model " << model.size());
              REQUIRE(shipped == model);
            }
            ++pairs;
          }
        }
      }
    }
  CHECK(pairs > 0);
}

TEST_CASE("the shipped offline STC tour equals the Coq model's golden tours - an L a T a plus and "
          "a 2 x 3 block",
          "[proofs][stc]") {
  const auto tours = golden_tours(antkit::test::source_path("proofs/golden/StcTour.out"));
  REQUIRE(tours.size() == 4);
  for (std::size_t i = 0; i < tours.size(); ++i) {
    const std::vector<Cell>& model = tours[i];
    REQUIRE_FALSE(model.empty());
    std::int64_t cells = 0;
    const std::vector<Cell> shipped = shipped_tour(model, cells);
    INFO("golden tour " << i << " of proofs/golden/StcTour.out, start (" << model.front().x << ", "
                        << model.front().y << "), " << cells << " cells");
    // Invariant 4 on the vector itself (the model's theorem says 4 x cells).
    CHECK(static_cast<std::int64_t>(model.size()) == 4 * cells);
    REQUIRE(shipped.size() == model.size());
    for (std::size_t k = 0; k < model.size(); ++k) {
      INFO("position " << k);
      CHECK(shipped[k] == model[k]);
    }
  }
}
