#pragma once
// The driver that reproduces Tables 1-4 of paper 004 (Tyler & Hettiarachchi) and sets our numbers
// beside the paper's. Not part of antkit::algorithms (it uses threads and reports in floating
// point); `antkit cover-experiment` and `antkit reproduce` call it. The runner is in
// experiments/src/uniform_tables.cpp.
//
// The experiment (paper: "obstacle density of 0%, 10%, 20% and 30% ... 1 to 4 robots ... averaged
// over 10 independent runs"). The paper gives neither the environment size, the sensor distance
// nor the time limit; our choices and why:
//   * 100 x 100 cells and sensor distance 5: with these, one A* robot on an empty map needs about
//     1500 ticks and about 2800 at 20 % obstacles, the magnitude of the paper's 1621 and 2227
//     (Tables 4 and 2), and 100 x 100 is the round size a user of the paper's tool would type.
//   * Run k (k = 0..runs-1) uses trial k of the keyed streams for every density and robot count:
//     the obstacle sample is a prefix of one shuffle, so the 10 % map's obstacles are among the
//     20 % map's (common random numbers: differences between rows are not map noise), and the
//     first robots' starts are shared between robot counts when they fall in the same component.
//   * Time limit: 10 * W * H ticks for A* and PM (never reached: A* completes and PM ceases long
//     before). RW never stops by itself, and the paper's RW movement counts match its A* counts
//     within 1 % in every row of every table, which says the three ran side by side and stopped
//     together; so RW's limit in run k is the number of ticks A* took in run k.
//   * Coordinated A* and frontier coverage ("go beyond the paper") run on the same maps and
//     starts, with the same 10 * W * H limit.
#include <algorithm>
#include <antkit/algorithms/units.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/plot.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace antkit::experiments::uniform_tables {

// The uniform-coverage family this experiment runs (algorithms/uniform).
using uniform::Algorithm;
using uniform::algorithm_name;
using uniform::CoverageResult;
using uniform::CoverageWorld;
using uniform::kPpm;
using uniform::place_robots;
using uniform::random_obstacles;
using uniform::run_coverage;
using uniform::SensorModel;

// The paper's numbers: Tables 1-4 of paper 004, coverage % and movements, RW, PM and A*, 1-4
// robots.
struct PaperRow {
  int table;           // 1..4
  int density_percent; // 30, 20, 10, 0
  int robots;          // 1..4
  double coverage[3];  // RW, PM, A*
  double movements[3]; // RW, PM, A*
};
inline constexpr std::array<PaperRow, 16> kPaperTables{{
    // Table 1: 30 % obstacle density.
    {1, 30, 1, {15.30, 34.96, 100.0}, {2760.7, 468.9, 2757.2}},
    {1, 30, 2, {14.55, 43.40, 100.0}, {1405.5, 394.6, 1395.2}},
    {1, 30, 3, {26.65, 48.24, 100.0}, {1027.2, 300.8, 1016.4}},
    {1, 30, 4, {24.49, 56.92, 100.0}, {758.3, 268.8, 701.4}},
    // Table 2: 20 %.
    {2, 20, 1, {14.48, 45.67, 100.0}, {2235.1, 583.3, 2227.0}},
    {2, 20, 2, {20.04, 52.87, 100.0}, {1187.1, 442.2, 1178.4}},
    {2, 20, 3, {28.24, 60.20, 100.0}, {895.9, 346.6, 888.4}},
    {2, 20, 4, {26.59, 71.12, 100.0}, {726.0, 303.0, 716.1}},
    // Table 3: 10 %.
    {3, 10, 1, {17.47, 52.21, 100.0}, {1888.9, 640.7, 1883.2}},
    {3, 10, 2, {23.51, 54.64, 100.0}, {1086.3, 456.9, 1081.0}},
    {3, 10, 3, {28.83, 70.76, 100.0}, {757.2, 398.3, 753.0}},
    {3, 10, 4, {36.82, 82.82, 100.0}, {684.9, 370.8, 674.3}},
    // Table 4: 0 %.
    {4, 0, 1, {15.24, 100.0, 100.0}, {1622.6, 1603.0, 1621.0}},
    {4, 0, 2, {31.13, 97.53, 100.0}, {958.1, 959.2, 957.0}},
    {4, 0, 3, {37.38, 100.0, 100.0}, {753.5, 566.0, 749.0}},
    {4, 0, 4, {38.76, 100.0, 100.0}, {562.9, 421.0, 553.0}},
}};

inline constexpr std::array<Algorithm, 5> kTableAlgorithms{
    Algorithm::RandomWanderer, Algorithm::PrimaryMovement, Algorithm::AStar,
    Algorithm::CoordinatedAStar, Algorithm::Frontier};
inline constexpr std::size_t kTableColumns = kTableAlgorithms.size();

struct TablesConfig {
  std::int32_t width = 100;
  std::int32_t height = 100;
  std::int32_t sensor = 5;
  std::uint32_t runs = 10;
  std::uint64_t seed = 1;
  // Disk: the hypothesis test of issue 15 (does a sensor that sees through walls give the paper's
  // PM numbers?). Only the paper's RW, PM and A* run with it: our frontier coverage does not end
  // when it views cells it cannot reach (a disk views through walls), and the test needs only the
  // paper's three.
  SensorModel sensor_model = SensorModel::LineOfSight;
};

// The algorithms a configuration runs: the first table_columns(c) of kTableAlgorithms.
inline std::size_t table_columns(const TablesConfig& c) {
  return c.sensor_model == SensorModel::Disk ? 3 : kTableColumns;
}

// One (density, robots) cell of our tables: means over the runs, per algorithm (kTableAlgorithms
// order).
struct TablesRow {
  const PaperRow* paper = nullptr;
  double coverage[kTableColumns] = {}; // mean %
  double coverage_min[kTableColumns] = {};
  double movements[kTableColumns] = {};       // mean ticks
  double moves[kTableColumns] = {};           // mean total moves
  std::uint32_t complete[kTableColumns] = {}; // runs that reached 100 %
  std::uint64_t hash = 0;                     // a digest of every run's trace hash, in run order
  // Not in the files: every run's coverage % and movements, in run order (the claims' bootstrap
  // resamples them; run k of every algorithm shares map and starts, so they are paired).
  std::vector<double> coverage_runs[kTableColumns] = {}, movements_runs[kTableColumns] = {};
};

namespace detail {
struct TrialOut {
  CoverageResult result[kTableColumns];
};

inline TrialOut run_trial(const TablesConfig& c, const PaperRow& row, std::uint32_t run) {
  TrialOut out;
  const auto ppm = static_cast<std::uint32_t>(row.density_percent) * (kPpm / 100);
  const auto map = random_obstacles(c.width, c.height, ppm, c.seed, run);
  const auto poses =
      place_robots(map, static_cast<std::size_t>(row.robots), std::nullopt, c.seed, run);
  const std::uint64_t limit = std::uint64_t{10} * static_cast<std::uint64_t>(c.width) *
                              static_cast<std::uint64_t>(c.height);
  // A* first: its ticks are RW's limit.
  for (const std::size_t k :
       {std::size_t{2}, std::size_t{3}, std::size_t{4}, std::size_t{1}, std::size_t{0}}) {
    if (k >= table_columns(c)) continue;
    CoverageWorld world(map, poses, c.sensor, c.sensor_model);
    const std::uint64_t lim = k == 0 ? out.result[2].movements : limit;
    out.result[k] = run_coverage(world, kTableAlgorithms[k], c.seed, run, lim);
  }
  return out;
}
} // namespace detail

// Runs every (density, robots, run) as a unit of `runner` and reduces in that order; on MPI
// ranks other than 0 the result is empty.
std::vector<TablesRow> run_tables(const TablesConfig& c, const algorithms::Runner& runner);

// The files of `antkit cover-experiment`: the rows as CSV, and the four tables (ours / paper's)
// with the coordinated-A* and frontier comparisons as Markdown.
std::string tables_csv(const std::vector<TablesRow>& rows, const TablesConfig& c);
std::string tables_markdown(const std::vector<TablesRow>& rows, const TablesConfig& c);
// What `antkit cover-experiment` reports of a run besides its files: per row the obstacle density,
// the robot count and each algorithm's mean coverage (%), movements and moves rounded as the
// Markdown tables print them (2, 1 and 1 decimals), and a digest of the rows' hashes in row order.
struct TablesSummaryColumn {
  Algorithm algorithm = Algorithm::RandomWanderer;
  double coverage = 0, movements = 0, moves = 0;
};
struct TablesSummaryRow {
  int density_percent = 0;
  int robots = 0;
  std::vector<TablesSummaryColumn> columns; // table_columns(c) of kTableAlgorithms, in order
};
struct TablesSummary {
  std::filesystem::path csv, markdown; // the files written
  std::vector<TablesSummaryRow> rows;
  std::uint64_t hash = 0;
};
[[nodiscard]] TablesSummary tables_summary(const std::vector<TablesRow>& rows,
                                           const TablesConfig& c);
// Writes dir/uniform_tables.csv and dir/uniform_tables.md (tables_csv, tables_markdown), each whole
// or not at all (io::write_file_atomic; InputError(the file) when one cannot be written), and
// returns the summary with their paths.
TablesSummary write_tables(const std::vector<TablesRow>& rows, const TablesConfig& c,
                           const std::filesystem::path& dir);

// Coverage against movements, one panel per obstacle density, RW, PM and A* (ours: filled, the
// paper's: open markers), one point per robot count.
Figure tables_plot(const std::vector<TablesRow>& rows, const TablesConfig& c);

} // namespace antkit::experiments::uniform_tables
