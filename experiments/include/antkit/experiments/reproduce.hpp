#pragma once
// `antkit reproduce`: every paper's experiments in one run, one report (issue 15).
//
// reproduce() runs the experiments of the papers it is asked for (buffon: paper 000's Figures 4-9
// and 14; los: paper 001's Tables 2-3 and Figures 5-6; stc: paper 002's tours on real and random
// maps, audited, and the marker-noise curve; uniform: paper 004's Tables 1-4 with the line-of-sight
// sensor and with a disk sensor), decides every claim of the papers that the runs can decide, and
// writes into `out`:
//   README.md      the report: the claims table (holds / partly / does not hold, the measured
//   figure
//                  that decides it, why where it does not hold), then per paper each table and
//                  figure beside the paper's numbers, and at the end each experiment's trace hash
//                  and the command that reproduces it;
//   claims.json    the same verdicts for programs;
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
// The thresholds that turn a measurement into a verdict are in reproduce.cpp beside each claim
// (e.g. "agree" is a difference of medians of at most 5 %); the report prints each claim's rule.
#include <antkit/experiments/run.hpp>
#include <cstdint>
#include <filesystem>
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
};

// Trials per experiment at a scale.
struct Trials {
  int buffon = 100;      // per arena, Figures 5-9 and 14
  int uniform_runs = 10; // per table row
  int stc_random_maps = 20;
  int stc_noise_trials = 20;
};
[[nodiscard]] Trials trials_of(Scale scale);

enum class Verdict { Holds, Partly, DoesNotHold };
[[nodiscard]] const char* verdict_text(Verdict v);

struct Claim {
  std::string id;     // e.g. "000-1"
  std::string paper;  // "000"
  std::string source; // where the paper says it, e.g. "Figure 5, section 6.1"
  std::string text;   // the claim, in a sentence
  std::string rule;   // how we decide it
  Verdict verdict = Verdict::DoesNotHold;
  std::string measured; // the figure that decides it
  std::string why;      // where it does not hold (or only partly): what the runs show
  std::string quote{};  // the paper's own words (empty for a claim of ours beside the paper)
};

struct ExperimentRecord {
  std::string name;    // e.g. "paper 000, figure 5"
  std::uint64_t hash;  // trace hash of every trial, in trial order
  std::string command; // a command that reproduces the hash
};

struct ReproduceReport {
  std::vector<Claim> claims;
  std::vector<ExperimentRecord> experiments;
  std::vector<std::filesystem::path> files; // written, relative to `out`
};

// Throws kernel::InputError ("--only") for an unknown name.
void validate(const ReproduceOptions& options);

// Runs everything asked for. Under MPI every rank calls it (the trials are split across the ranks
// by `runner`); rank 0 reduces, decides, writes the files and returns the report, the other ranks
// return an empty report. Throws kernel::InputError when `out` cannot be written.
[[nodiscard]] ReproduceReport reproduce(const ReproduceOptions& options, const Runner& runner);

// The claims as a Markdown table (the report's first section; `antkit reproduce` prints it).
[[nodiscard]] std::string claims_markdown(const std::vector<Claim>& claims);

// The command line of `antkit reproduce` with these options (the report's reproduction line).
[[nodiscard]] std::string reproduce_command(const ReproduceOptions& options,
                                            const std::vector<std::string>& only);

} // namespace antkit::experiments
