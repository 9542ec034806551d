#pragma once
// The error of `antkit reproduce --decide`, shown by simulation (issue 44): claims whose truth is
// set by construction, decided look after look exactly as --decide decides a part (a percentile
// bootstrap interval of the sample median at 1 - alpha_k at look k, look_alpha below, the trials
// doubling from look to look, a part frozen at the look that decides it), and the share of them
// that end with a false verdict.
//
// The model: trials are exponential with mean 1 (skewed, as Buffon's per-trial counts are), the
// figure is their median (ln 2 in truth) and the rule is "below t" with t = ln 2 (1 + margin):
// margin > 0 makes the claim true (holds is right), margin < 0 false (does not hold is right), and
// margin = 0 puts the truth on the threshold, where any decided verdict is false: the worst case,
// whose false rate --decide promises to keep at or below alpha. Replication r draws its trials
// from kernel::Stream(seed, kSequentialExperiment, r), so the figures are the same on every run.
#include <antkit/experiments/verdict.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace antkit::experiments {

inline constexpr std::uint64_t kSequentialExperiment = 44000;

// --decide's alpha spending: look k (from 0) is spent alpha / ((k + 1)(k + 2)), a series that sums
// to alpha over any number of looks (1/2, 1/6, 1/12, ... of it), so that no look count is planned.
[[nodiscard]] double look_alpha(double alpha, int look);

// --decide's time budget (reproduce.cpp): a unit (a figure of paper 000, or another paper) still
// asked for after a look, with its next run's predicted time and its likeliest claim's estimate
// (the times this look's trials that would settle it, >= 1).
struct UnitForecast {
  std::string unit;
  double next_seconds = 0;
  double need = 1;
};

// The units that run the next look within `left` seconds, in name order: a unit whose need cannot
// fit (next_seconds x (need - 1) > left: the runs double, so settling costs at least that) stops;
// then, while the others' next runs together exceed `left`, the costliest stops (of equal costs,
// the first by name). The rest are kept.
[[nodiscard]] std::vector<std::string> fit_next_look(std::vector<UnitForecast> open, double left);

struct SequentialSimulation {
  double margin = 0;     // the truth's distance from the threshold, relative (see above)
  int looks = 4;         // K
  int first_trials = 20; // trials at the first look (doubling after)
  int replications = 400;
  double alpha = 0.05; // spent over the looks: look k's interval at 1 - look_alpha(alpha, k)
  bool spend = true;   // false: every look at 1 - alpha (no spending: the naive repeated look)
  std::uint64_t seed = 1;
  int resamples = 1000; // bootstrap resamples per interval

  // Results.
  std::uint64_t decided = 0, false_verdicts = 0;
  double mean_trials = 0; // trials used until the verdict (or the last look's), on average
  Interval false_rate_ci; // Clopper-Pearson 95 % for the false-verdict rate
  [[nodiscard]] double false_rate() const {
    return replications > 0 ? static_cast<double>(false_verdicts) / replications : 0.0;
  }
};

// Runs the simulation `s` describes, its replications on `threads` threads (the results do not
// depend on them), and returns it with its results filled in.
[[nodiscard]] SequentialSimulation simulate_sequential(SequentialSimulation s,
                                                       unsigned threads = 1);

} // namespace antkit::experiments
