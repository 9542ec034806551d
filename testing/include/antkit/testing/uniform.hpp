#pragma once
// Rich checkers for the uniform-coverage family: they replay a run one robot action at a time and
// say which rule broke, where and when.
#include <antkit/kernel/grid.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/world.hpp>
#include <cstdint>
#include <string>

namespace antkit::testing {

struct UniformRunCheck {
  bool ok = true;
  std::string what; // the first rule that broke, with the tick, robot and cell
  uniform::CoverageResult result;
  std::uint64_t goal_clashes = 0; // ticks on which two A* robots shared a goal cell
  // ... of which ticks on which some unviewed viewable cell was nobody's goal: coordinated A* may
  // share a goal only when every unviewed cell is taken.
  std::uint64_t unjustified_clashes = 0;
};

// Runs `algorithm` in `world` like uniform::run_coverage and, after every robot's action, checks:
//   * every robot stands on a distinct Free cell; a move goes to one of the eight neighbours and
//     never cuts a corner; a turn changes the bearing by exactly one eighth and nothing else;
//   * no viewed cell becomes unviewed; the world's counts of viewed free cells equals a recount;
//     viewed free cells are viewable;
//   * every cell a robot stands on has been viewed, and so has every cell in view of it.
// The run is run_coverage's own tick loop (uniform/coverage_ticks.hpp's run_ticks) with the checks
// after every action, so the result (movements, moves, hash, stop) is run_coverage's for the same
// world, algorithm, seed and trial: the checker checks the rules of the run users get, not of a
// copy of its loop.
UniformRunCheck check_uniform_run(uniform::CoverageWorld& world, uniform::Algorithm algorithm,
                                  std::uint64_t seed, std::uint64_t trial, std::uint64_t limit);

// The cells in view of `from` by brute force: kernel::line_of_sight on the map for every cell of
// the map within Euclidean distance r.
kernel::Grid<std::uint8_t> brute_force_view(const kernel::OccupancyGrid& map, kernel::Cell from,
                                            std::int32_t range);

} // namespace antkit::testing
