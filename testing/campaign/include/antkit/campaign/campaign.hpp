#pragma once
// Property campaigns longer than a ctest run (issue 18, `antkit campaign`): generate cases with
// antkit::testing's generators, run every variant of a family on each, check every invariant with
// antkit::testing's checkers, and shrink any failing case to a minimal map.
//
// Determinism. Case i is drawn from rapidcheck's generator seeded by the keyed stream (seed,
// experiment 18, trial i, robot 0, purpose = the family): case i is case i whatever runs it (any
// thread count, any MPI rank, a campaign started at --first i). Cases run as units of the one
// engine (antkit/algorithms/units.hpp) on the threads and ranks of its Runner and the results are
// reduced in case order, so the outputs depend on the options only. The one exception
// is a time limit, which stops at a case boundary: then how many cases ran depends on the machine
// (the summary says so and how many ran; the cases that ran are always the first ones).
//
// Shrinking is rapidcheck's: a failing case is replaced by the first of its shrinks that still
// fails (the same variant breaking any rule), until none does.
#include <antkit/algorithms/units.hpp>
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::campaign {

enum class Family : std::uint8_t { Stc = 1, Los = 2, Uniform = 3, Buffon = 4 };

[[nodiscard]] std::optional<Family> parse_family(std::string_view name) noexcept;
[[nodiscard]] std::string_view family_name(Family family) noexcept;
// Every variant of a family, in the order they run: stc offline, online, ant, ant-edge, full;
// los fast-wall-follow, frontier, frontier-nolos; uniform rw, pm, astar, astar-coord, frontier;
// buffon fixed, precision, online (two visits of a drawn length; visit 2 on the stopping rule at
// P = 0.2; visit 1 deciding its own length too).
[[nodiscard]] std::vector<std::string> family_variants(Family family);

struct Options {
  Family family = Family::Stc;
  std::uint64_t cases = 1000;
  std::uint64_t first = 0; // the case indices are first, first + 1, ..., first + cases - 1
  std::uint64_t seed = 1;
  // The largest map: stc in cells (each 2 x 2 sub-cells), los and uniform in grid cells; buffon's
  // arenas are antkit::testing's arenas with holes (radius 60 to 100 units) whatever this says.
  std::int32_t max_width = 32, max_height = 32;
  std::vector<std::string> variants; // empty: all of the family's
  double time_limit_s = 0;           // 0: none
  // An extra rule every case must keep (empty string: it holds): a planted failure, to see the
  // shrinking and the failure outputs at work (tests; `--plant max-width=N` of the command).
  std::function<std::string(const kernel::OccupancyGrid&)> extra_rule;
  std::string extra_rule_name; // what the summary calls it (empty: none)
};

// Throws kernel::InputError naming the option for a value out of range or an unknown variant:
// "cases", "first case", "largest map", "time limit" or "variants".
void validate(const Options& options);

struct Failure {
  std::uint64_t case_index = 0;
  std::string variant;       // the variant that broke a rule
  std::string rule;          // what the checker said, on the shrunk case
  kernel::OccupancyGrid map; // the shrunk case's map (stc: sub-cells; empty for buffon)
  std::string arena_wkt;     // buffon: the shrunk case's arena
  kernel::Cell start{};
  std::string command; // the antkit command that reproduces it; {MAP} stands for the map
  std::uint64_t shrink_steps = 0;
};

struct Result {
  std::uint64_t cases_run = 0;
  bool stopped_by_time = false;
  // The work checked: sub-cell moves of every tour (stc), robot ticks of every run (los, uniform).
  std::uint64_t moves = 0;
  std::uint64_t vacuous = 0;     // cases with no room to run (no free cell for a start)
  std::vector<Failure> failures; // in case order
};

// Runs the campaign on `runner`'s threads and ranks (a plain Runner: one thread, one process;
// under mpirun, the one cli/ranks.hpp's run_on_ranks makes). The cases run in batches of
// 64 x threads per rank: rank r checks the cases whose index, counted from `first`, is r modulo
// ranks, and after each batch the runner's gather brings every rank's verdicts to rank 0, which
// shrinks the failures; with a time limit every rank calls the runner's any at every batch
// boundary, so that they stop together. Rank 0 returns the whole campaign's result, the same for
// any number of threads and ranks; the other ranks return only cases_run and stopped_by_time. On
// rank 0, runner.progress("cases", done, total) is called from the calling thread a few times a
// second and at the end. Throws std::logic_error for a rank out of range or several ranks without
// a gather.
[[nodiscard]] Result run(const Options& options, const algorithms::Runner& runner = {});

// A failure as one line of text and back (summary.json's lines; tests).
[[nodiscard]] std::string serialize(const Failure& failure);
[[nodiscard]] Failure deserialize(std::string_view text);

// Writes DIR/summary.json and, for each failure, DIR/case-<i>.map (MovingAI) with its command in
// the summary; every file atomically. The files hold nothing but what the options determine (no
// time, no thread count). Returns the summary's text.
std::string write_outputs(const Options& options, const Result& result,
                          const std::filesystem::path& dir);

} // namespace antkit::campaign
