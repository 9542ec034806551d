#pragma once
// One Buffon trial in a buffer the caller gives (issue 27): what run_trial (measurement.hpp) does
// for trial `trial` without --precision, freestanding, so that the Cortex-M image runs it
// (mcu/src/buffon_run.cpp) and the host's tests hold it to run_trial. The world's buckets
// (WorldCore), the pheromone raster (RasterCore), visit 1's trail and the crossing index over it
// (CrossingCounterCore) are laid out in the buffer; the visits are visit.hpp's steps, so the hash,
// BC, the blocked steps and the exact crossing count are run_trial's. The exact count is taken
// online in visit 2 (CrossingCounterCore, whose total is count_proper_crossings of the two trails),
// so visit 2's trail is not kept.
//
// Memory (FixedTrialPlan): the crossing index's words are only known after visit 1, so the plan
// counts their bound: a step is at most 0.0625 units (speed <= 0.25, forward <= speed / 4),
// shorter than the index's buckets (0.5 units), so a segment covers at most 2 x 2 of them, over at
// most the walls' box. A buffer that holds the plan always holds the trial.
#include <antkit/buffon/pheromone_raster.hpp>
#include <antkit/buffon/world.hpp>
#include <cstddef>
#include <cstdint>
#include <span>

namespace antkit::buffon {

// Byte offsets in the buffer (8-byte aligned) and the bytes of each part.
struct FixedTrialPlan {
  std::uint64_t world = 0, raster = 0, trail = 0, counter = 0; // bytes (counter: its bound)
  std::uint64_t start_at = 0, members_at = 0, raster_at = 0, trail_at = 0, counter_at = 0;
  std::uint64_t total = 0;
};

// The plan for a world of layout `world`, a raster initialised over its box, `steps` per visit.
[[nodiscard]] FixedTrialPlan plan_fixed_trial(const WorldLayout& world, const RasterCore& raster,
                                              std::int64_t steps) noexcept;

struct FixedTrialResult {
  std::uint64_t bc = 0, crossings_exact = 0, blocked = 0, hash = 0;
  std::int64_t length1_raw = 0, length2_raw = 0;
  std::uint64_t bytes = 0; // of the buffer used
};

// Runs trial `trial` (seed, experiment kExperiment) of `steps` steps per visit over `walls` with
// `body` and trail width `width`, in `buffer` (8-byte aligned; the walls are read, not copied, and
// may lie outside it). Returns null, or why it cannot run (an invalid world, body, width, start, or
// a plan larger than the buffer: the message names it).
[[nodiscard]] const char* run_fixed_trial(std::span<const FxSegment> walls, BodyParams body,
                                          Fx width, std::uint64_t seed, std::uint64_t trial,
                                          std::int64_t steps, std::span<std::uint8_t> buffer,
                                          FixedTrialResult& result) noexcept;

} // namespace antkit::buffon
