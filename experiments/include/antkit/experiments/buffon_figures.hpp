#pragma once
// Paper 000's Figures 5-9 and 14 (`antkit buffon-experiment`, `antkit reproduce`).
//
// Figures 5-9: a list of (series, x, arena spec, trail width); every arena gets `trials` trials of
// the paper's Section 5 settings (50 000 steps per visit, w = 0.1 unless the figure varies w) and
// one row with the median and interquartile range of nBC (the paper's statistics), the arena's
// exact area, the median closed-form area and the median blocked-step count. Trial t of arena k of
// figure f uses experiment 4000 + 100 f + k of the keyed streams, so every arena's trials are
// independent and reproducible on their own.
//
// Choices where the paper is silent: Figure 5's squares are "square:d=D" (the square of the area of
// the D circle); Figure 6's ellipses have the standard area and e = 0.968, 0.994, 0.998, drawn
// against compactness r1/r2 = 1/sqrt(1 - e^2) (1 for the circle); Figure 7's barrier lengths are
// 10..80 % of the diameter in steps of 10; Figure 9's widths are 0.05, 0.1, 0.2, 0.4 over the ten
// circles.
//
// Figure 14 (Section 8.1): calibrated Buffon estimates and RS estimates against total trail length
// for the circles of diameter 40, 60, 80, 100, calibrated on 30, 50, 70, 90; checkpoints every 168
// units of each visit (total 336 k, k = 1..10); circle d uses experiment 5400 + d. The fit uses the
// calibration arenas' median nBC at the same checkpoint; each trial of a test arena then gives one
// estimate.
#include <antkit/algorithms/units.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/experiments/calibration.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/plot.hpp>
#include <antkit/geometry/arena.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace antkit::experiments {

struct BuffonFigureParams {
  int figure = 5;             // 5, 6, 7, 8, 9 or 14
  std::int64_t trials = 100;  // per arena
  std::int64_t steps = 50000; // per visit
  std::uint64_t seed = 1;
};

struct BuffonArena {
  std::string series;
  double x = 0;
  std::string spec; // antkit arena spec
  double width = 0.1;
};

// The arenas of a figure in row order; empty for a figure other than 5-9.
[[nodiscard]] std::vector<BuffonArena> buffon_figure_arenas(int figure);

struct BuffonFigureRow {
  BuffonArena arena;
  double area = 0, nbc_median = 0, nbc_q1 = 0, nbc_q3 = 0, closed_form_median = 0,
         blocked_median = 0;
  // The row's trials: the figure's count, or under `reproduce --decide` the arena's own (a look
  // extends only the arenas a claim still asks for).
  std::int64_t trials = 0;
  // Not in the CSV: the median length of visit 1, and Buffon's efficiency nBC pi area / (2 L1)
  // at the medians (1 for an ideal needle count; below 1 where trails blend).
  double length1_median = 0, efficiency = 0;
  // Not in the CSV: every trial's nBC, visit-1 length and Buffon count, in trial order (the
  // claims' bootstrap intervals resample them).
  std::vector<double> nbc_trials{}, length1_trials{}, bc_trials{};
};

struct BuffonFigure {
  BuffonFigureParams params;
  std::vector<BuffonFigureRow> rows;
  std::uint64_t hash = 0; // every trial's trace hash, in arena then trial order
};

// Throws kernel::InputError("figure" / "trials" / "steps per visit") for parameters out of range.
[[nodiscard]] BuffonFigure run_buffon_figure(const BuffonFigureParams& params,
                                             const algorithms::Runner& runner);

// A figure's trials, added batch by batch (`antkit reproduce --decide`). Trial t of an arena is
// keyed by t alone, so extend(a, ...) then extend(b, ...) then finish() gives the very figure
// (rows, per-trial samples and hash) that run_buffon_figure gives at b trials: run_buffon_figure
// is extend once, then finish. params.trials is ignored; extend() throws as run_buffon_figure
// does for a count out of range. Under MPI every rank calls extend() (a collective); finish() is
// rank 0's.
class BuffonFigureTrials {
public:
  explicit BuffonFigureTrials(const BuffonFigureParams& params);
  // Runs trials [trials(), trials) of every arena (none when trials <= trials()).
  void extend(std::int64_t trials, const algorithms::Runner& runner);
  // Runs trials [trials(k), trials) of the arenas k whose flag is set (one flag per arena, in row
  // order; std::invalid_argument otherwise): `reproduce --decide` extends only the arenas its
  // undecided claims read. Every arena's trials are keyed by their index alone, so an arena
  // extended to n trials holds what one run of n gives it; finish()'s rows then carry their own
  // counts (BuffonFigureRow::trials) and params.trials is the largest.
  void extend(std::int64_t trials, const std::vector<bool>& arenas,
              const algorithms::Runner& runner);
  [[nodiscard]] std::int64_t trials() const noexcept; // the most any arena has
  [[nodiscard]] std::size_t arenas() const noexcept { return arenas_.size(); }
  [[nodiscard]] BuffonFigure finish() const;

private:
  BuffonFigureParams params_;
  std::vector<BuffonArena> arenas_;
  std::vector<double> areas_;
  std::vector<std::vector<algorithms::Payload>> payloads_; // [arena][trial], rank 0
  std::vector<std::int64_t> have_;                         // per arena
};
[[nodiscard]] std::string buffon_figure_csv(const BuffonFigure& f);
[[nodiscard]] Figure buffon_figure_plot(const BuffonFigure& f);
// Figure 5b: each square's median nBC against the circle's of the same area, with y = x.
[[nodiscard]] Figure buffon_figure5b_plot(const BuffonFigure& figure5);

// One trial's two trails over its arena (`antkit buffon --svg/--png`), like the paper's Figure 4:
// `name` titles the panel (with the arena's area), `steps` is the visits' length when the trial
// does not say (TrialResult::steps1/steps2 are 0 for two fixed visits). The trails are thinned to
// every 4th point, keeping both ends of every jump longer than a unit (the pieces of a marker's
// trail), so that no chord is drawn across the arena. Throws kernel::InputError for a file that
// cannot be written.
void save_trial_trails_figure(const std::string& name, const geometry::Arena& arena,
                              const buffon::TrialResult& trial, std::int64_t steps,
                              const std::filesystem::path& svg, const std::filesystem::path& png);

struct Figure14Row {
  double diameter = 0, total_length = 0, area = 0;
  double buffon_median = 0, buffon_q1 = 0, buffon_q3 = 0, rs_median = 0, rs_q1 = 0, rs_q3 = 0;
  double fit_a = 0, fit_b = 0, fit_c = 0;
};

struct Figure14 {
  BuffonFigureParams params;
  std::vector<Figure14Row> rows; // by checkpoint, then test diameter
  std::uint64_t hash = 0;        // a digest of every trial's checkpoint counts
  // Not in the CSV: every circle's per-trial nBC and RS estimates at each checkpoint (calibration
  // and test circles, by diameter), from which the claims' bootstrap refits the calibration.
  std::vector<Figure14Arena> arenas{};
};

[[nodiscard]] Figure14 run_figure14(const BuffonFigureParams& params,
                                    const algorithms::Runner& runner);

// Figure 14's trials, added batch by batch, as BuffonFigureTrials for Figures 5-9.
class Figure14Trials {
public:
  explicit Figure14Trials(const BuffonFigureParams& params);
  void extend(std::int64_t trials, const algorithms::Runner& runner);
  [[nodiscard]] std::int64_t trials() const noexcept { return have_; }
  [[nodiscard]] Figure14 finish() const;

private:
  BuffonFigureParams params_;
  std::vector<int> diameters_;
  std::vector<double> areas_;
  std::vector<std::vector<algorithms::Payload>> payloads_; // [circle][trial], rank 0
  std::int64_t have_ = 0;
};
[[nodiscard]] std::string figure14_csv(const Figure14& f);
[[nodiscard]] Figure figure14_plot(const Figure14& f);

} // namespace antkit::experiments
