// `antkit stc-floor-experiment`: the marker-floor robot of paper 002 under camera noise, fading
// marks and rotation drift, and the board size each fading time allows (issue 14;
// experiments/stc_floor.hpp).
//   antkit stc-floor-experiment [--quick] [--threads T] [--seed S] --out DIR [--format table|json]
// Writes DIR/floor_curves.csv, DIR/floor_boards.csv and the figures DIR/floor_{noise,fade,drift}
// .{svg,png}; prints the board sizes and the drift at which the calibrated robot first leaves the
// grid. --quick: 2 boards per level and boards up to 10 x 10 cells (the default: 6 and 16).
#include "commands.hpp"
#include "output.hpp"
#include "ranks.hpp"

#include <antkit/experiments/stc_floor.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <iostream>
#include <memory>

namespace {

namespace ex = antkit::experiments;
using antkit::cli::Format;
using antkit::kernel::InputError;

struct FloorExperimentCommand {
  bool quick = false;
  std::int64_t threads = 2;
  std::uint64_t seed = 1;
  std::string out;
  Format format = Format::Table;
};

void run(const FloorExperimentCommand& c) {
  if (c.threads < 1 || c.threads > 256) throw InputError("--threads", "expected 1 to 256 threads");
  ex::FloorParams p;
  p.seed = c.seed;
  if (c.quick) {
    p.trials = 2;
    p.max_board = 10;
  }
  ex::FloorCurves curves;
  const int ranks = antkit::cli::run_on_ranks(c.out, static_cast<unsigned>(c.threads),
                                              antkit::cli::stage_progress("stc-floor-experiment"),
                                              [&](const antkit::algorithms::Runner& runner) {
                                                curves = ex::run_floor_curves(p, runner);
                                                if (runner.root())
                                                  ex::write_floor_curves(curves, c.out);
                                              });
  if (ranks == 0) return; // another rank than 0: rank 0 prints
  nlohmann::json j;
  j["out"] = c.out;
  j["trials_per_level"] = p.trials;
  j["off_grid_drift_ppm_per_minute"] =
      curves.off_grid_drift >= 0 ? nlohmann::json(curves.off_grid_drift) : nlohmann::json(nullptr);
  nlohmann::json boards = nlohmann::json::array();
  for (const auto& b : curves.boards)
    boards.push_back({{"fade_half_life_s", b.fade_s},
                      {"largest_exact_board_cells", b.largest},
                      {"tour_minutes", b.tour_minutes},
                      {"capped", b.capped}});
  j["boards"] = std::move(boards);
  j["hash"] = antkit::kernel::hash_hex(curves.hash);
  j["ranks"] = ranks;
  antkit::cli::emit(j, c.format, std::cout);
}

void register_floor_experiment(CLI::App& app) {
  auto c = std::make_shared<FloorExperimentCommand>();
  auto* sub = app.add_subcommand(
      "stc-floor-experiment",
      "Paper 002's marker-floor robot through its rendered camera against camera noise, fading "
      "marks and rotation drift (CSV and figures), and the board size each fading time allows");
  sub->add_flag("--quick", c->quick, "2 boards per level, boards up to 10 x 10 cells");
  sub->add_option("--threads", c->threads, "Threads (default 2)");
  sub->add_option("--seed", c->seed, "Seed of the boards and the camera noise (default 1)");
  sub->add_option("--out", c->out, "The directory to write (created)")->required();
  antkit::cli::add_format_option(*sub, c->format);
  sub->callback([c] { run(*c); });
}

const antkit::cli::Registration stc_floor_experiment_registration{"stc-floor-experiment",
                                                                  &register_floor_experiment};

} // namespace
