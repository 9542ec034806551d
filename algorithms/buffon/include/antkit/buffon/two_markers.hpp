#pragma once
// Two distinguishable markers (issue 17's alternative to the online first visit): one robot lays
// two trails, A and B, in a single walk, switching marker every kSwitchSteps steps (paper 000's
// Hemisson experiment drew its two visits in two pen colours; here the colours alternate within one
// run). Each new segment of one trail is tested against the other trail so far (GrowingTrailIndex),
// so the crossing count N of the pair is known online, and the closed form 2 L_A L_B / (pi N)
// estimates the area as for two visits. The stopping rule is the visit-2 rule of stopping.hpp on
// the pair's two-way table: rows are A's runs, columns B's runs (both trails cut into
// kBatches equal runs of kSwitchSteps-step pieces at a check); checks come every 2 kBatches
// pieces (every 20 000 steps), when each trail has a whole number of pieces per run.
//
// Choices, the paper being silent on all of them:
//  * kSwitchSteps = 1000, the block of the visit-2 rule: a piece is a row or column cell of the
//    table. Shorter pieces make the two trails less independent (the robot crosses the piece it
//    just left more often than a distant one); longer pieces make the first check later.
//  * Streams: the walk is visit 3 of the trial (Stream(seed, experiment, trial, 3, purpose)), so it
//    shares no draw with the two-visit runs of the same trial.
//  * No pheromone detector: the count is the exact crossing count of the two centre lines (bc is
//    0). A robot with two colour sensors would count what the detector counts for one.
//  * The junction of two pieces shares an end point, which is not a proper crossing.
//  * Pieces close in time are near each other in space, so they cross more often than the
//    independent law says when a piece is short against the time the walk needs to forget where it
//    was (large arenas): counted, they made the estimate low. Measured on the 60 random polygons
//    of tests/convergence/test_first_visit_stats.cpp at P = 0.1 (erosion-corrected estimates):
//    counting every pair, mean error -2.6 % and -5.1 % on the 12 polygons above 8 000 unit^2,
//    worst trial 13.9 % off. So crossings between pieces at most kNearPieces apart in walk order
//    are not counted, and the length product leaves their pairs out (pair_share): with
//    kNearPieces = 1, -0.3 % and -1.7 %, worst 11.5 %; with 3, +0.5 % and -0.4 %, worst 10.5 %;
//    the median trail is the same within 0.1 %. 3 it is.
#include <antkit/buffon/measurement.hpp>

namespace antkit::buffon {

inline constexpr std::int64_t kSwitchSteps = 1000;
// Crossings between pieces at most this far apart in walk order (k and k + 1, ...) are not
// counted, and the estimate's length product leaves their pairs out (TrialResult::pair_share).
inline constexpr std::int64_t kNearPieces = 3;

// One two-marker trial. Uses params.precision_millionths (required: throws InputError
// "precision" when 0), params.total_steps (the walk's cap; 0: 2 params.steps), seed, experiment,
// keep_trails. The result's visit fields describe the trails: length1_raw, steps1, trail1 are A's
// (pieces 0, 2, 4, ...), length2_raw, steps2, trail2 B's (each piece's points from its first, the
// pieces one after another, so a jump separates two pieces of one marker),
// crossings_exact the pair's N (pieces far enough apart), pair_share the share of L_A L_B those
// pairs make (the estimate is 2 pair_share L_A L_B / (pi N)), reached_precision the rule,
// variance_visit1 / variance_visit2 A's and B's shares, wall_encounters the walk's. Deterministic:
// the result depends on the parameters and the trial only.
TrialResult run_two_marker_trial(const World& world, const TrialParams& params,
                                 std::uint64_t trial);

} // namespace antkit::buffon
