#pragma once
// The marker-floor robot of paper 002 under trouble (issue 14): the rendered robot (devices/
// stc_floor) running ant-edge STC through its camera, against camera noise, the marks' fading and
// a weakening battery's rotation drift; and how large a board each fading time allows.
//
// The curves: each level runs `trials` keyed boards (trial t: a random board of `cells` x `cells`
// cells with 10 % of its sub-cells blocked, uniform::random_obstacles(..., seed, t)), the robot
// from stc::default_start heading north; the camera noise stream seeded seed + t). Measured on the
// floor's truth: the sub-cells the body entered over those reachable (coverage), repeats per
// reachable sub-cell, and whether the run was exact (the tour closed, every reachable sub-cell
// entered exactly once). The drift curve also runs with the calibration off (tolerance beyond any
// turn), to show what the paper's calibration buys; its "off grid" level is the first drift at
// which some calibrated run is not exact.
//
// The board sizes: for each fading half-life, open boards of n x n cells, n = 2, 3, ..., up to
// `max_board`; the largest n up to the first that is not exact, with the tour's duration on the
// floor's clock. The default times (floor.hpp: 2 s of LEDs and 1 s of driving a move, 1.5 s a
// quarter turn, 0.1 s a frame) make a move about 3.5 s.
#include <antkit/algorithms/units.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace antkit::experiments {

struct FloorParams {
  std::int32_t cells = 8; // the curves' boards
  int trials = 6;
  std::uint64_t seed = 1;
  std::vector<std::int32_t> noise = {0, 20, 40, 60, 80, 100, 120, 140};           // +- per channel
  std::vector<std::int64_t> fade_s = {0, 240, 120, 60, 30, 15, 8};                // 0: none
  std::vector<std::int32_t> drift = {0, 2000, 5000, 10000, 20000, 50000, 100000}; // ppm / minute
  std::vector<std::int64_t> board_fade_s = {15, 30, 60, 120, 240};
  std::int32_t max_board = 16;
};

struct FloorPoint {
  std::string factor; // "noise", "fade", "drift", "drift-uncalibrated"
  std::int64_t level = 0;
  double coverage = 0, repeats_per_subcell = 0, exact = 0; // means over the trials
  double max_offset = 0; // mean of each run's largest distance from a sub-cell's centre
  // The fraction covered per trial, in trial order (the claims' intervals).
  std::vector<double> coverage_runs;
};

struct FloorBoard {
  std::int64_t fade_s = 0;
  std::int32_t largest = 0; // cells a side; 0: not even 2 x 2
  double tour_minutes = 0;  // the exact tour's duration at that size
  bool capped = false;      // max_board itself was exact
};

struct FloorCurves {
  FloorParams params;
  std::vector<FloorPoint> points; // by factor, then level
  std::vector<FloorBoard> boards;
  std::int64_t off_grid_drift = -1; // ppm / minute; -1: every level stayed exact
  std::uint64_t hash = 0;           // every run's tour hash and counts, in unit order
};

[[nodiscard]] FloorCurves run_floor_curves(const FloorParams& params,
                                           const algorithms::Runner& runner);

// The two tables: floor_curves.csv (a row per factor and level) and floor_boards.csv (a row per
// fading half-life).
[[nodiscard]] std::string floor_curves_csv(const FloorCurves& c);
[[nodiscard]] std::string floor_boards_csv(const FloorCurves& c);

// floor_curves.csv, floor_boards.csv, floor_{noise,fade,drift}.{svg,png} in `dir` (which exists).
void write_floor_curves(const FloorCurves& c, const std::filesystem::path& dir);

} // namespace antkit::experiments
