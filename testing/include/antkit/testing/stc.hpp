#pragma once
// Checkers for Spanning Tree Coverage tours (issue 3). Each returns a rich result: which invariant
// broke, at which step of the path, at which sub-cell, and why, so that a failing property says
// what went wrong instead of "false".
//
// Invariants (the numbering):
//   1  coverage: exact variants enter every sub-cell of every free cell 4-connected to the start
//      cell exactly once; `full` enters every reachable free sub-cell at least once.
//   2  moves: consecutive positions are 4-adjacent free sub-cells (exact: of free cells).
//   3  return: the tour starts at the start and its last sub-cell is the start or 4-adjacent to it.
//   4  length: an exact tour has 4 x (reachable free cells) positions; `full` reports its repeats
//      right (positions - distinct sub-cells).
// The reachable set is computed here by a breadth-first search of its own, independent of the code
// under test.
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace antkit::testing {

struct StcCheck {
  bool ok = true;
  std::string rule;       // e.g. "1 coverage"
  std::int64_t step = -1; // index into the path, -1 when the rule is about the whole tour
  kernel::Cell subcell{};
  std::string detail;

  explicit operator bool() const noexcept { return ok; }
  [[nodiscard]] std::string describe() const;
};

std::ostream& operator<<(std::ostream& out, const StcCheck& check);

// Reusable buffers, so that an exhaustive run does not allocate per tour.
class StcTourChecker {
public:
  // Invariants 1-4 for offline, online, ant and ant-edge.
  StcCheck check_exact(const kernel::OccupancyGrid& map, kernel::Cell start,
                       std::span<const kernel::Cell> path);
  // Invariants 1-4 as they read for `full`; `reported_repeats` is what the run said.
  StcCheck check_full(const kernel::OccupancyGrid& map, kernel::Cell start,
                      std::span<const kernel::Cell> path, std::int64_t reported_repeats);

  // The number of free cells 4-connected to the start's cell (0 when that cell is not free).
  std::int64_t reachable_cells(const kernel::OccupancyGrid& map, kernel::Cell start);
  // The sub-cells a tour must enter, by the same search: with `whole_cells` every sub-cell of the
  // free cells 4-connected to the start's cell (the exact variants), without it the free
  // sub-cells of the cell area 4-connected to the start (full). `mask` gets one byte per map
  // sub-cell, 1 for those; returns their number.
  std::int64_t reachable_subcells(const kernel::OccupancyGrid& map, kernel::Cell start,
                                  bool whole_cells, std::vector<std::uint8_t>& mask);

private:
  std::vector<std::uint8_t> mark_;
  std::vector<std::uint8_t> seen_;
  std::vector<kernel::Cell> queue_;
};

// Invariant 5: `actual` is `expected`, move for move.
StcCheck check_same_tour(std::span<const kernel::Cell> expected,
                         std::span<const kernel::Cell> actual, const std::string& what);

} // namespace antkit::testing
