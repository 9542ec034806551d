#pragma once
// Paper 001's Tables 2 and 3 (`antkit explore-tables`, `antkit reproduce`): fast wall-follow
// against the frontier baseline, ours beside the paper's, and the Figures 5-6 style plot of steps
// and energy against the obstacles.
//
// The environments: 25x25, the robots start at the lower-left corner (0, 24) and its east
// neighbour; empty, 1, 2, 5 and 10 scattered single-cell obstacles, one and two blocks of six; 10
// repetitions (5 for the blocks), repetition t drawn as `antkit explore --size 25x25 --obstacles K
// --seed S --trial t` draws it (so any cell of the tables can be re-run and drawn). The same trial
// number gives nested obstacle sets across columns (the first draws of one keyed stream): the
// columns differ by the obstacles added, not by unrelated layouts.
//
// Table 3's "Sheng et al." is our frontier baseline (Sheng et al.'s g = w1 I - w2 D + w3 lambda
// with w1 = w2 = 1, w3 = 0) without line-of-sight sweeping, the original method; the same
// baseline with sweeping is run beside it.
#include <antkit/algorithms/units.hpp>
#include <antkit/experiments/plot.hpp>
#include <antkit/los/explore.hpp>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace antkit::experiments {

struct ExploreEnvironment {
  const char* name;
  int obstacles;   // scattered single cells
  int blocks;      // blocks of six
  int repetitions; // the paper's
};

inline constexpr std::array<ExploreEnvironment, 7> kExploreEnvironments{
    {{"No obstacles", 0, 0, 10},
     {"One obstacle", 1, 0, 10},
     {"Two obstacles", 2, 0, 10},
     {"Five obstacles", 5, 0, 10},
     {"Ten obstacles", 10, 0, 10},
     {"One block (six obstacles)", 0, 1, 5},
     {"Two blocks (six obstacles each)", 0, 2, 5}}};

// Paper 001, Table 2 (fast wall-follow steps per repetition), columns One .. Two blocks (Table 2
// has no empty-room column), then its averages and sample deviations.
inline constexpr std::array<std::array<int, 10>, 6> kPaperTable2{{
    {81, 89, 88, 63, 89, 85, 62, 83, 89, 96},
    {94, 107, 80, 122, 81, 102, 99, 109, 95, 92},
    {111, 135, 102, 125, 114, 134, 121, 150, 122, 101},
    {118, 145, 158, 158, 150, 143, 137, 152, 154, 146},
    {96, 84, 83, 84, 92, 0, 0, 0, 0, 0},
    {108, 102, 94, 101, 96, 0, 0, 0, 0, 0},
}};
inline constexpr std::array<double, 6> kPaperTable2Average{82.5, 98.1, 121.5, 146.1, 87.8, 100.2};
inline constexpr std::array<double, 6> kPaperTable2Deviation{11.9, 12.7, 15.3, 11.9, 5.8, 5.5};

// Paper 001, Table 3: Sheng et al. 2006 steps and E.M.E; fast wall-follow steps and E.M.E.
struct PaperExploreRow {
  double sheng_steps, sheng_eme, fwf_steps, fwf_eme;
};
inline constexpr std::array<PaperExploreRow, 7> kPaperTable3{{{158.7, 317.4, 47, 94},
                                                              {155.4, 310.8, 82.5, 122.1},
                                                              {155.7, 311.4, 98.1, 143.8},
                                                              {155.2, 310.4, 121.5, 193.7},
                                                              {153.3, 306.6, 146.1, 252.1},
                                                              {157.2, 314.4, 87.8, 127.4},
                                                              {159.4, 318.8, 100.2, 147.6}}};

// The methods run: fast wall-follow, the frontier baseline without and with sweeping.
enum class ExploreMethod { FastWallFollow = 0, Frontier = 1, FrontierLos = 2 };
inline constexpr std::size_t kExploreMethods = 3;

struct ExploreRuns {
  std::vector<double> steps, eme; // per repetition
};

struct ExploreTables {
  std::uint64_t seed = 1;
  // [environment][method]
  std::array<std::array<ExploreRuns, kExploreMethods>, kExploreEnvironments.size()> runs;
  std::uint64_t hash = 0; // every run's trace hash, in environment, method, repetition order
};

// Throws std::runtime_error when a run does not complete (it never should). repetitions_factor
// multiplies the paper's repetitions (`antkit reproduce --decide`; 1 to 1000): repetition t is
// keyed by t alone, so the first runs are the same at every factor and the tables print the
// paper's first 10 (5); the averages and the claims use them all.
[[nodiscard]] ExploreTables run_explore_tables(std::uint64_t seed, const algorithms::Runner& runner,
                                               int repetitions_factor = 1);

[[nodiscard]] double mean_of(const std::vector<double>& v);
// The sample standard deviation (n - 1), which reproduces the paper's Table 2 deviations.
[[nodiscard]] double sample_deviation(const std::vector<double>& v);

// The files: Table 2 (CSV, Markdown), Table 3 (CSV, Markdown).
[[nodiscard]] std::string table2_csv(const ExploreTables& t);
[[nodiscard]] std::string table2_markdown(const ExploreTables& t);
[[nodiscard]] std::string table3_csv(const ExploreTables& t);
[[nodiscard]] std::string table3_markdown(const ExploreTables& t);

// Makes `dir` and writes table2.csv, table2.md, table3.csv and table3.md into it, each atomically;
// returns their paths in that order. Throws kernel::InputError(dir, ...) when the directory cannot
// be made or a file cannot be written.
std::array<std::filesystem::path, 4> write_explore_tables(const ExploreTables& t,
                                                          const std::filesystem::path& dir);
// Figures 5-6 of the paper as one figure: mean steps and mean E.M.E per environment, ours and the
// paper's.
[[nodiscard]] Figure explore_plot(const ExploreTables& t);

// The paper's Figure 4, stages of one run: fast wall-follow in the 25 x 25 room with five
// obstacles (repetition 1 of Table 2's column), the shared map at 20, 40, 60, 80 and 100 % of its
// ticks, drawn to svg and png (drawing.hpp).
void explore_stages_figure(std::uint64_t seed, const std::filesystem::path& svg,
                           const std::filesystem::path& png);

// One exploration's picture (`antkit explore --svg/--png`): the final shared map with Table 1's
// colours (exploration_legend), both robots' trails, and a caption with the size, steps, E.M.E and
// cells explored; `algorithm` titles it as the caller names it. Throws kernel::InputError for a
// file that cannot be written.
void save_exploration_figure(const std::string& algorithm, const los::ExploreResult& result,
                             const std::filesystem::path& svg, const std::filesystem::path& png);

} // namespace antkit::experiments
