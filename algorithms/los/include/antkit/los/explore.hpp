#pragma once
// A whole exploration run of the pair, its metrics (paper 001, Section IV), and the environments
// of Tables 2-3.
//
// Metrics:
//   steps  ticks to completion: the number of ticks in which the controller commanded moves,
//          i.e. the tick whose observation completes the map is not counted;
//   eme    Estimated Motor Energy: the moves both robots made (paper: "the sum of the number of
//          steps taken by each robot");
//   moves  the moves of each robot.
// Termination: the controller reports `finished` when no frontier cell is left, which is exactly
// when every cell that can be observed from the free space the robots can reach is explored
// (a reachable free cell is always known free, and a known-free cell with an unexplored neighbour
// is a frontier). The cells that cannot be observed are counted, not waited for.
//
// Trace hash (DESIGN.md rule 5): per tick, the canonical serialisation of what the tick did to the
// state: tick number (u32), the robots' cells (4 x i32), the line of sight (bool), the number of
// cell changes (u32) and each change (cell index u32, new state u8) in the order the rules made
// them, the two moves (2 x i8) and `finished` (bool). The initial state (all F, the start cells) is
// fixed by the map and the start, so this stream determines the whole state after every tick
// without writing the whole map each tick.
#include <antkit/frontier/planner.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/los/cell_state.hpp>
#include <antkit/los/team.hpp>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace antkit::los {

enum class Algorithm : std::uint8_t { FastWallFollow = 0, Frontier = 1 };

struct ExploreOptions {
  Algorithm algorithm = Algorithm::FastWallFollow;
  bool line_of_sight = true; // the frontier baseline with or without sweeping (fast wall-follow
                             // always sweeps)
  frontier::Weights weights{};
  std::uint64_t max_ticks = 0; // 0: 8 * W * H + 1024, far above any complete run
};

struct ExploreResult {
  bool completed = false; // false only if max_ticks ran out
  std::uint64_t steps = 0;
  std::uint64_t eme = 0;
  std::array<std::uint64_t, 2> moves{0, 0};
  std::size_t explored = 0;     // cells in S, LOS, S+LOS or O
  std::size_t observable = 0;   // cells observable from the reachable free space
  std::size_t unobservable = 0; // the other cells of the grid
  kernel::Grid<CellState> cells;
  std::uint64_t hash = 0;
  std::array<std::vector<kernel::Cell>, 2> trajectories;
  // Fast wall-follow only: the events of its wall stage and when it ended.
  std::uint32_t sight_losses = 0, causes_found = 0, meetings = 0;
  std::uint64_t wall_stage_ticks = 0;
};

// Called after every tick with the world and the controller's map (for checks in tests).
using TickHook = std::function<void(const TwoRobotWorld&, const ExplorationMap&,
                                    const TeamObservation&, const TeamCommand&)>;

// Runs the pair from cells a (A, the wall follower) and b (B) to completion on `truth`.
ExploreResult explore(const kernel::OccupancyGrid& truth, kernel::Cell a, kernel::Cell b,
                      const ExploreOptions& options, const TickHook& hook = {});

// The free cell nearest the lower-left corner (0, H - 1) (squared Euclidean distance; ties: the
// smaller x, then the larger y) that has a free neighbour. Throws std::invalid_argument if none.
kernel::Cell default_start(const kernel::OccupancyGrid& truth);
// The start pair: `start` and its nearest free neighbour (the four orthogonal ones first, in the
// kernel's order E N W S, then the diagonals NE NW SW SE). Throws std::invalid_argument if `start`
// is off the grid, not free, or has no free neighbour.
std::array<kernel::Cell, 2> start_pair(const kernel::OccupancyGrid& truth, kernel::Cell start);

// The cells observable from the free space reachable (8-connected, through Free cells) from a and
// b: the reachable cells and their in-grid neighbours. 1 marks observable.
kernel::Grid<std::uint8_t> observable_cells(const kernel::OccupancyGrid& truth, kernel::Cell a,
                                            kernel::Cell b);

// The environments of Tables 2-3, positions drawn from the keyed stream
// Stream(seed, kExperiment, trial, 0, purpose). No obstacle is put on `keep_free` or its eight
// neighbours, so the start pair is always free.
inline constexpr std::uint64_t kExperiment = 5; // issue 5
// k scattered single-cell obstacles, anywhere else in the grid.
kernel::OccupancyGrid scattered_obstacles(std::int32_t width, std::int32_t height, std::int32_t k,
                                          std::uint64_t seed, std::uint64_t trial,
                                          kernel::Cell keep_free);
// k blocks of six obstacles (3 x 2 or 2 x 3, orientation drawn with the position), each an island:
// not touching the grid's edge, another block, or the kept cells. Throws std::invalid_argument if
// they do not fit after many draws.
kernel::OccupancyGrid obstacle_blocks(std::int32_t width, std::int32_t height, std::int32_t k,
                                      std::uint64_t seed, std::uint64_t trial,
                                      kernel::Cell keep_free);

} // namespace antkit::los
