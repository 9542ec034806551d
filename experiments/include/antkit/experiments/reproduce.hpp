#pragma once
// `antkit reproduce`: every paper's experiments in one run, one report (issue 15).
//
// reproduce() runs the experiments of the papers it is asked for (buffon: paper 000's Figures 4-9
// and 14; los: paper 001's Tables 2-3 and Figures 5-6; stc: paper 002's tours on real and random
// maps, audited, and the marker-noise curve; uniform: paper 004's Tables 1-4 with the line-of-sight
// sensor and with a disk sensor), decides every claim of the papers that the runs can decide, and
// writes into `out`:
//   README.md      the report: the claims table (the verdict, the measured figure with its
//                  interval, why where it does not hold), the rules with the papers' words, each
//                  claim's parts, then per paper each table and figure beside the paper's numbers,
//                  and at the end each experiment's trace hash and the command that reproduces it;
//   claims.json    the same verdicts, parts and intervals for programs;
//   buffon/, los/, stc/, uniform/   the CSV and Markdown tables, and every figure as SVG and PNG.
// Every file is written atomically, and every byte of every file depends only on the options (not
// on the threads, the MPI ranks or the time taken; timings go to the terminal only) and on the
// machine that writes it: its floating point for the reductions, its Cairo and fonts for figures.
//
// Trial counts: --full runs the papers' (100 trials per arena for paper 000, the 10 (5 for the
// blocks) repetitions of paper 001, 10 runs per row for paper 004); --quick runs 20 trials per
// arena and 3 runs per row, fewer maps and noisy trials for paper 002 (paper 001 runs in full at
// both scales: it takes well under a second). The report states the counts it ran.
//
// --decide (issue 44): looks at 1, 2, 4, ... times those counts, each running only what a claim
// still asks for, until every claim settles or the budget ends; alpha spent over an open-ended
// series of looks (0.05 / ((k + 1)(k + 2)) at look k), so a budget (trials, or time converted look
// by look) only says where the looks stop; the report states the trials of the last look and the
// units a time budget stopped before it, and a rerun with those gives the same bytes. The error is
// shown by simulation (sequential.hpp).
//
// The papers are registered entries (papers.hpp): reproduce() loops over them. The claims are
// data too: one table per paper (experiments/src/claims_000.cpp, claims_001.cpp,
// claims_002.cpp, claims_004.cpp; the typed API in claims.hpp), each claim with the paper's words,
// its rule and the experiment it reads; adding a claim touches its paper's file only. Every
// verdict carries its uncertainty (verdict.hpp): each part of a claim is a figure with an interval
// (percentile bootstrap over the trials, 2000 resamples keyed by the seed, the claim and the part;
// Clopper-Pearson for a proportion of runs; none for an exact figure), at a family-wise 95 % per
// claim (Bonferroni over its parts), and a verdict: holds, does not hold, or inconclusive at this
// trial count when the interval contains the rule's threshold. A claim of several parts is partly
// when some part holds and some part does not (verdict.hpp states the convention).
//
// Ids missing on purpose: 000-2 is the trail length of Section 5 (added with issue 29; it was
// once Figure 5(b)'s "most points on y = x", which is 000-1 again); 004-1 would be "RW's movements
// equal A*'s", which the paper's tables show (within 1 %) but which our driver imposes (RW's tick
// limit is A*'s ticks, uniform_tables.hpp), so no run can decide it.
#include <antkit/algorithms/units.hpp>
#include <antkit/experiments/verdict.hpp>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace antkit::experiments {

enum class Scale { Quick, Full };

struct ReproduceOptions {
  Scale scale = Scale::Quick;
  std::vector<std::string> only; // any of buffon, los, stc, uniform; empty: all four
  std::uint64_t seed = 1;
  std::filesystem::path out;
  // The shared maps (paper 002's real maps); empty or missing: random maps only (said in the
  // report).
  std::filesystem::path maps_dir;
  // --decide (issue 44): looks at 1, 2, 4, ... times the scale's trial counts, each deciding what
  // it can, until every claim is settled or the budget is spent. The budget is paper 000's trials
  // per arena at the last look (the other families' counts grow by the same factors); 0: eight
  // times the scale's. Or a time budget: each look's units' times predict the next look's, and a
  // unit stops when its claims' estimated need or its next run does not fit in the time left (the
  // report states the trials and the units stopped, and a rerun with that trial budget and those
  // unit budgets gives the same bytes).
  bool decide = false;
  std::int64_t budget_trials = 0;
  double budget_seconds = 0;
  // --unit-budget UNIT=N: a unit (PaperRun::units(), e.g. "buffon/figure14") runs no look past N
  // (paper 000's trials per arena at that look, as the budget), though its claims still ask. A
  // time budget stops a unit whose next runs it cannot afford; its report lists these caps, and a
  // rerun with them and the budget in trials gives the same bytes.
  std::map<std::string, std::int64_t> unit_budget;
};

// Trials per experiment at a scale.
struct Trials {
  int buffon = 100;      // per arena, Figures 5-9 and 14
  int uniform_runs = 10; // per table row
  int stc_random_maps = 20;
  int stc_noise_trials = 20;
  int stc_floor_boards = 20; // keyed boards of the marker-floor robot, per condition
};
[[nodiscard]] Trials trials_of(Scale scale);

// One test of a claim as the report prints it (claims.hpp's Part, evaluated).
struct ClaimPart {
  std::string label;
  std::string rule;   // "below 5 %", "within +-15 %"
  double value = 0;   // the figure
  Interval ci;        // its interval (value, value for an exact figure)
  double level = 1;   // the interval's level
  std::string method; // "bootstrap", "Clopper-Pearson", "exact"
  std::string figure; // value and interval, formatted
  Verdict verdict = Verdict::Inconclusive;
  Side side = Side::Below; // the rule's side and threshold
  double threshold = 0;
  double miss = 0;         // claims.hpp's miss_of: > 0 past the threshold on the failing side
  std::string miss_text{}; // |miss| in the part's unit
};

struct Claim {
  std::string id;     // e.g. "000-1"
  std::string paper;  // "000"
  std::string source; // where the paper says it, e.g. "Figure 5, section 6.1"
  std::string text;   // the claim, in a sentence
  std::string rule;   // how we decide it
  Verdict verdict = Verdict::DoesNotHold;
  std::string measured;     // the figure that decides it
  std::string why;          // where it does not hold (or only partly): what the runs show
  std::string quote{};      // the paper's own words (empty for a claim of ours beside the paper)
  std::string experiment{}; // the report's file it reads
  std::vector<ClaimPart> parts{}; // its tests, each with its interval and verdict
  // --decide: the look that settled it (or the last that ran), its trial count in words, and for
  // a claim still undecided an estimate of the count that would decide it.
  int look = 0;
  std::string trials{};
  std::string needed{};
};

struct ExperimentRecord {
  std::string name;    // e.g. "paper 000, figure 5"
  std::uint64_t hash;  // trace hash of every trial, in trial order
  std::string command; // a command that reproduces the hash
};

struct ReproduceReport {
  // --decide: the planned looks, and paper 000's trials per arena at the last one (the budget in
  // trials that reproduces this report, after a time budget's conversion); 1 and the scale's
  // count without.
  int looks = 1;
  std::int64_t budget_trials = 0;
  // --decide: the units the budget stopped before the last look, with the look's trials at which
  // each stopped (ReproduceOptions::unit_budget of the rerun that gives the same bytes).
  std::map<std::string, std::int64_t> unit_budget;
  // --decide: the options that reproduce this report's bytes ("--budget N [--unit-budget U=N]").
  std::string rerun;
  std::vector<Claim> claims;
  std::vector<ExperimentRecord> experiments;
  std::vector<std::filesystem::path> files; // written, relative to `out`
};

// Throws kernel::InputError ("families") for an unknown name.
void validate(const ReproduceOptions& options);

// Runs everything asked for. Under MPI every rank calls it (the trials are split across the ranks
// by `runner`); rank 0 reduces, decides, writes the files and returns the report, the other ranks
// return an empty report. Throws kernel::InputError when `out` cannot be written.
[[nodiscard]] ReproduceReport reproduce(const ReproduceOptions& options,
                                        const algorithms::Runner& runner);

// The claims as a Markdown table (the report's first section; `antkit reproduce` prints it).
[[nodiscard]] std::string claims_markdown(const std::vector<Claim>& claims);

// The command line of `antkit reproduce` with these options (the report's reproduction line).
[[nodiscard]] std::string reproduce_command(const ReproduceOptions& options,
                                            const std::vector<std::string>& only);

} // namespace antkit::experiments
