#pragma once
// One blind area measurement of paper 000 as `antkit buffon` runs it: a number of keyed trials
// over one world (run_trial, or run_two_marker_trial under the markers rule), each reduced to its
// lengths, nBC, closed-form area and, with a precision, the rule's interval and the erosion
// correction (estimate.hpp); and their summary (medians, quartiles, how many trials reached the
// precision, the chained hash). The deterministic part is the trials; everything in the trials'
// and the summary's doubles is the reporting side (DESIGN.md, rule 1). No file format: the command
// names the fields (cli/buffon.cpp documents its JSON keys).
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/buffon/world.hpp>
#include <cstdint>
#include <optional>
#include <vector>

namespace antkit::buffon {

// The budget of both visits (or both markers) together under the markers and online rules when
// the caller gives none: generous (P = 0.05 on a 31 416-unit^2 circle took a median 1.8 M steps
// online and 0.8 M with two markers, results/precision_cost), so that asking for P gets P.
inline constexpr std::int64_t kDefaultPrecisionBudget = 20000000;

struct AreaMeasurementParams {
  std::uint64_t trials = 1; // trials 0 .. trials-1
  unsigned threads = 1;     // workers (at least 1); the result does not depend on them
  std::uint64_t seed = 1;
  std::int64_t steps = kDefaultSteps; // per visit (fixed rule, and without a precision)
  Fx width = kDefaultWidth;
  // 0: no precision, both visits run `steps`. Else the relative precision P in millionths
  // (parse_precision) and how the trail is laid.
  std::uint32_t precision_millionths = 0;
  PrecisionRule rule = PrecisionRule::markers;
  std::int64_t visit2_steps = 0;  // fixed rule: visit 2's cap (0: `steps`)
  std::int64_t total_steps = 0;   // markers and online: both visits' budget (0: the default)
  bool keep_first_trails = false; // keep trial 0's trails (a figure)
};

// Why a trial of the markers or online rule stopped.
enum class TrialStop { precision, visit1_cap, visit2_cap, budget };

struct AreaTrial {
  TrialResult run;        // the deterministic trial (trails only for trial 0 when kept)
  double length1 = 0;     // units
  double length2 = 0;     // units
  double nbc = 0;         // bc / length2 (0 when visit 2 has no length)
  ClosedForm closed_form; // from pair_share length1, length2 and the exact crossings
  std::optional<PrecisionEstimate> precision; // with a precision: the rule's interval, erosion
  std::optional<TrialStop> stopped;           // markers and online
  std::optional<double> area_pilot; // online: length1^2 / (pi S); absent when S = 0 or not online
};

struct AreaSummary {
  double nbc_median = 0, nbc_q1 = 0, nbc_q3 = 0;
  std::optional<double> area_closed_form_median; // over the trials with an estimate
  // With a precision.
  std::uint64_t reached_precision = 0; // trials that reached it
  double length2_median = 0;
  std::optional<double> area_corrected_median;
  // Markers and online.
  double length1_median = 0, length_total_median = 0;
  std::uint64_t out_of_steps = 0; // trials that ran out of steps before reaching P
  // Online.
  std::uint64_t first_visit_reached = 0;
  std::uint64_t hash = 0; // the trials' hashes chained in trial order, seeded with the seed
};

struct AreaMeasurement {
  std::vector<AreaTrial> trials; // in trial order
  AreaSummary summary;
};

// Whether `params` asks for a precision under a rule whose budget covers both visits.
[[nodiscard]] inline bool budgeted(const AreaMeasurementParams& params) noexcept {
  return params.precision_millionths != 0 && params.rule != PrecisionRule::fixed;
}

// Runs the trials on `world` and reduces them. Throws kernel::InputError (the trial runners'
// own names: "steps per visit", "step budget", ...) for parameters out of range.
[[nodiscard]] AreaMeasurement measure_area(const World& world, const AreaMeasurementParams& params);

} // namespace antkit::buffon
