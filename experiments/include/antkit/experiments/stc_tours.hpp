#pragma once
// Paper 002 (`antkit reproduce`): Spanning Tree Coverage on real and random maps, every tour
// audited by antkit::testing (the tour oracle of `antkit check stc`), and the marker-noise curve of
// ant-like STC (the experiment of `antkit stc-noise`).
//
// The maps: every MovingAI map (*.map) of `maps_dir`/movingai in name order when the directory
// exists (the shared maps beside the checkout), then `random_maps` keyed maps of 64 x 64 sub-cells
// with 10 % of the sub-cells blocked (uniform::random_obstacles, trial k); each from the start
// `antkit stc` takes (stc::default_start). Every variant runs on every map; the exact ones
// (offline, online, ant, ant-edge) are audited for "every reachable sub-cell exactly once, moves
// between 4-adjacent free sub-cells, back to the start cell", full for coverage with repeats
// counted.
//
// The noise curve: ant and ant-edge on den312d of the shared maps when present (1920 reachable
// sub-cells: a real map, and one of the larger ones that STC's 2 x 2 cells leave connected), else
// on the first random map, each mark reading misread with probability p, `noise_trials` keyed
// trials per level (trial t of level p uses the noise stream (seed, t)).
#include <antkit/algorithms/units.hpp>
#include <antkit/experiments/plot.hpp>
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace antkit::experiments {

struct StcToursParams {
  std::filesystem::path maps_dir; // the shared maps; empty or missing: random maps only
  int random_maps = 20;
  std::uint64_t seed = 1;
  // Misread probabilities in millionths: 0, then 1 ppm to 10 %, about three per decade (a real
  // map's tour needs thousands of readings, so the curve falls between 10^-5 and 10^-3).
  std::vector<std::uint32_t> noise_ppm = {0, 1, 3, 10, 30, 100, 300, 1000, 3000, 10000, 100000};
  int noise_trials = 20;
};

struct StcTourRow {
  std::string map, variant;
  std::int64_t reachable = 0, positions = 0, covered = 0, repeats = 0;
  bool returned_to_start = false, closed = false;
  bool audit_ok = false;
  std::string audit; // the first broken rule, empty when the tour passes
  std::uint64_t hash = 0;
};

struct StcNoisePoint {
  std::string variant;
  std::uint32_t ppm = 0;
  double coverage = 0, repeats_per_subcell = 0, complete = 0; // means over the trials
  double mean_positions = 0;
};

// The marker-noise curve (`antkit stc-noise`, and paper 002's in reproduce): each variant (ant or
// ant-edge) from `start` at each misread probability (ppm), `trials` runs, trial t with the noise
// stream (seed, t); means in trial order. Points by variant, then level. `reachable` receives the
// reachable sub-cells, `hash` a digest of every run's trace hash in unit order. Throws
// kernel::InputError for a bad start (as run_stc).
[[nodiscard]] std::vector<StcNoisePoint>
run_stc_noise(const kernel::OccupancyGrid& map, kernel::Cell start,
              const std::vector<std::string>& variants, const std::vector<std::uint32_t>& ppm,
              int trials, std::uint64_t seed, const algorithms::Runner& runner,
              std::int64_t* reachable = nullptr, std::uint64_t* hash = nullptr);

struct StcTours {
  StcToursParams params;
  std::vector<std::string> maps; // names, in unit order
  std::vector<StcTourRow> tours; // by map, then variant
  std::string noise_map;
  std::int64_t noise_reachable = 0;
  std::vector<StcNoisePoint> noise; // by variant, then level
  std::uint64_t hash = 0;           // every tour's and noisy run's trace hash, in unit order
};

[[nodiscard]] StcTours run_stc_tours(const StcToursParams& params,
                                     const algorithms::Runner& runner);

// A map of the experiment by name (a shared map's file name, or "random-64-64-10 #k"), for the
// picture of one tour.
[[nodiscard]] kernel::OccupancyGrid stc_experiment_map(const StcToursParams& params,
                                                       const std::string& name);

[[nodiscard]] std::string stc_tours_csv(const StcTours& t);
[[nodiscard]] std::string stc_noise_csv(const StcTours& t);
[[nodiscard]] Figure stc_noise_plot(const StcTours& t);

} // namespace antkit::experiments
