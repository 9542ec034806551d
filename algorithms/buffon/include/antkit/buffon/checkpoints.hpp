#pragma once
// Section 8.1 of paper 000: Buffon counts at growing trail lengths, and the Randomized Search (RS)
// area-coverage baseline, for Figure 14.
//
// Buffon at checkpoints: one pair of visits serves every checkpoint k = 1..K of trail length
// k * step per visit. Each raster cell remembers the first checkpoint whose prefix of visit 1
// marked it (one byte), so visit 2 runs once with K detectors; detector k sees cell c as marked
// iff first_checkpoint(c) <= k and counts only while visit 2's length is within k * step.
// Total trail length at checkpoint k is 2 k * step (both visits).
//
// RS (Section 8.1: "the robot can sense and mark the whole region underneath its body ... mark
// only the unmarked areas ... the amount of marker used is the area estimate"): the same
// behaviour (visit 3 of the trial's streams) runs for the total length of both visits; every step
// marks the raster cells (side 0.1, a choice: 1/10 of the body) whose centre lies under the body
// (within 0.5 of the centre); the estimate at checkpoint k is the marked cell count times the
// cell's area after a trail of length 2 k * step. The raster and the marking rule are
// randomized_search.hpp's freestanding core, which the Cortex-M image runs too (issue 27).
#include <antkit/buffon/measurement.hpp>
#include <cstdint>
#include <span>
#include <vector>

namespace antkit::buffon {

struct CheckpointResult {
  std::vector<std::uint64_t> bc;         // per checkpoint
  std::vector<std::int64_t> length2_raw; // visit 2's length at each checkpoint (raw Q15.16)
  std::vector<std::uint64_t> rs_cells;   // RS: marked cells at each total length 2 k * step
  std::int64_t rs_cell_raw = 0;          // RS cell side, raw Q15.16
};

// `step_raw` is the checkpoint spacing per visit (raw Q15.16; 168 units in the paper), `count` the
// number of checkpoints (at most 250). Visits run until their length reaches count * step_raw
// or 1.3 times the steps that takes at the default mean step, whichever is first.
CheckpointResult run_checkpoints(const World& world, const TrialParams& params, std::uint64_t trial,
                                 std::int64_t step_raw, int count);

// RS's marked area along a finished trail (a robot's logged one, devices/odometry.hpp): the cells
// of side 0.1 whose centre lies within the body's radius of a point of the trail, marked by the
// rule run_checkpoints applies as it walks, over the trail's bounding box grown by the radius. The
// estimate is cells * cell^2.
struct Footprint {
  std::uint64_t cells = 0;
  std::int64_t cell_raw = 0; // side, raw Q15.16
};
Footprint rs_footprint(std::span<const FxPoint> trail);

// RS's cost of a precision (issue 17, the cost-of-precision table): the same walk as
// run_checkpoints' RS (visit 3 of the trial's streams, cells of side 0.1 under the body), run
// until its estimate cells * cell^2 is within a relative P of `area`, i.e. at least (1 - P) area
// (RS only ever under-estimates: it marks what the body has covered), or for `max_steps` steps.
// RS has no stopping rule of its own, so this is an oracle stop, the most favourable reading of
// RS: the trail length at which its estimate first meets P. Throws InputError("precision") for
// P outside (0, 1).
struct RsCost {
  std::int64_t length_raw = 0; // the walk's length when it stopped
  bool reached = false;        // false: max_steps ran out first
};
RsCost rs_cost_to_precision(const World& world, const TrialParams& params, std::uint64_t trial,
                            double area, std::uint32_t precision_millionths,
                            std::int64_t max_steps);

// RS for a fixed number of steps (issue 27): visit 3 of `trial`'s streams for params.steps steps
// (from the start: params.steps + 1 positions), marking as run_checkpoints does; the cells marked,
// the walk's length and blocked steps, and its trace hash (randomized_search.hpp). What `antkit dev
// rs-mcu-input --host` prints, and what the Cortex-M image's run_fixed_rs must reproduce.
struct RsRun {
  std::uint64_t cells = 0;
  std::int64_t cell_raw = 0; // side, raw Q15.16
  std::int64_t length_raw = 0;
  std::uint64_t blocked = 0;
  std::uint64_t hash = 0;
};
RsRun run_rs(const World& world, const TrialParams& params, std::uint64_t trial);

} // namespace antkit::buffon
