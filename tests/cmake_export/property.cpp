// What a user of the installed package writes: a rapidcheck property over antkit::testing's
// generators and checkers, here against a toy coverage planner of the consumer's own (a
// depth-first walk over the free sub-cells that backtracks along its own trail), checked as a
// Full-STC-style tour ("every reachable free sub-cell at least once, repeats counted").
#include <antkit/testing/generators.hpp>
#include <antkit/testing/stc.hpp>
#include <cstdio>
#include <rapidcheck.h>
#include <vector>

namespace {

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;

// The consumer's planner: depth-first, neighbours in the order E, N, W, S, stepping back along the
// stack when stuck, so that the walk ends where it began. Only the cell area (whole 2 x 2 cells)
// is walked, as antkit's STC maps say.
std::vector<Cell> toy_tour(const OccupancyGrid& map, Cell start) {
  const std::int32_t w = map.width() / 2 * 2, h = map.height() / 2 * 2;
  std::vector<std::uint8_t> seen(map.size(), 0);
  std::vector<Cell> path{start}, stack{start};
  seen[map.index(start)] = 1;
  while (!stack.empty()) {
    const Cell c = stack.back();
    bool moved = false;
    for (const Cell d : {Cell{1, 0}, Cell{0, -1}, Cell{-1, 0}, Cell{0, 1}}) {
      const Cell n{c.x + d.x, c.y + d.y};
      if (n.x < 0 || n.y < 0 || n.x >= w || n.y >= h || map[n] != Occupancy::Free ||
          seen[map.index(n)])
        continue;
      seen[map.index(n)] = 1;
      stack.push_back(n);
      path.push_back(n);
      moved = true;
      break;
    }
    if (!moved) {
      stack.pop_back();
      if (!stack.empty()) path.push_back(stack.back());
    }
  }
  if (path.size() > 1) path.pop_back(); // the last step back lands on the start: stop next to it
  return path;
}

} // namespace

bool consumer_property() {
  namespace gen = antkit::testing::gen;
  return rc::check("the consumer's planner covers every reachable free sub-cell", [] {
    const auto c = *gen::stc_case({.max_cells_x = 8, .max_cells_y = 8, .partial_cells = true});
    const auto path = toy_tour(c.map, c.start);
    std::int64_t distinct = 0;
    std::vector<std::uint8_t> seen(c.map.size(), 0);
    for (const Cell s : path) distinct += seen[c.map.index(s)]++ == 0;
    antkit::testing::StcTourChecker checker;
    const auto check =
        checker.check_full(c.map, c.start, path, static_cast<std::int64_t>(path.size()) - distinct);
    RC_ASSERT(check.describe() == "ok");
  });
}
