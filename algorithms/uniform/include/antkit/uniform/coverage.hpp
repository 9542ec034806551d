#pragma once
// One run of a coverage algorithm in a CoverageWorld, its metrics and its trace hash.
//
// A tick steps every robot once, in index order; a robot's move, and what it views from its new
// cell, are in the world before the next robot is stepped. The run ends
//   * Complete:  all viewable free cells have been viewed (checked before every tick, so a run
//                whose first views already cover everything takes 0 ticks);
//   * NoMove:    every robot answered Stop in one tick (that tick is not counted);
//   * TimeLimit: `limit` ticks have run.
// Metrics (issue 6): `movements` is the number of ticks (the paper's "movements", time in the
// environment); `moves` is the total over robots of actions carried out: rotations and forward
// moves for RW and PM (a rotation counts as a move), steps for A* and frontier; a blocked forward
// or a wait is not a move.
//
// Trace hash: TraceHash(0) over the algorithm's number, the robot count, then the world's
// canonical state (CoverageWorld::hash_state) before the first tick and after every tick.
#include <antkit/uniform/world.hpp>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

namespace antkit::uniform {

enum class Algorithm : std::uint8_t {
  RandomWanderer = 0,
  PrimaryMovement = 1,
  AStar = 2,
  CoordinatedAStar = 3,
  Frontier = 4, // frontier_coverage.hpp: beyond the paper, after Sheng et al. (paper 001)
};

// "rw", "pm", "astar", "astar-coord", "frontier".
[[nodiscard]] std::string_view algorithm_name(Algorithm a) noexcept;
[[nodiscard]] std::optional<Algorithm> parse_algorithm(std::string_view name) noexcept;

enum class StopReason : std::uint8_t { Complete, NoMove, TimeLimit };
[[nodiscard]] std::string_view stop_reason_name(StopReason r) noexcept;

struct CoverageResult {
  Algorithm algorithm = Algorithm::RandomWanderer;
  std::size_t robots = 0;
  std::uint64_t viewed = 0;   // viewed free cells
  std::uint64_t viewable = 0; // viewable free cells
  std::uint64_t movements = 0;
  std::uint64_t moves = 0;
  std::uint64_t hash = 0;
  StopReason stop = StopReason::TimeLimit;
};

// Runs `algorithm` in `world` (whose robots have already viewed their start) for at most `limit`
// ticks. `seed` and `trial` key the controllers' streams.
CoverageResult run_coverage(CoverageWorld& world, Algorithm algorithm, std::uint64_t seed,
                            std::uint64_t trial, std::uint64_t limit);

// The same, calling `observer` with the starting poses (tick 0) and after every tick (1, 2, ...):
// what `antkit cover --trace` writes. The run and its hash are the same as without it.
using TickObserver = std::function<void(const CoverageWorld& world, std::uint64_t tick)>;
CoverageResult run_coverage(CoverageWorld& world, Algorithm algorithm, std::uint64_t seed,
                            std::uint64_t trial, std::uint64_t limit, const TickObserver& observer);

} // namespace antkit::uniform
