// `antkit buffon-cost`: the cost of precision (issue 17; experiments/buffon_cost.hpp, whose
// measurement is algorithms/buffon/precision_cost.hpp).
//
//   antkit buffon-cost --out DIR [--quick] [--trials N] [--seed S] [--threads T]
//                      [--max-steps N] [--format table|json]
//
// Runs the sweep of experiments/buffon_cost.hpp (Buffon with two markers, with the online first
// visit, and RS, to P = 0.2, 0.1 and 0.05 against area) and writes DIR/precision_cost.csv,
// DIR/precision_cost_fits.csv, DIR/precision_cost.svg and .png (the columns and the figure are
// described there), then prints the fits and the four paths (as JSON with --format json: the fits,
// the files and the number of MPI ranks). --quick: circles and squares of 314,
// 1 257 and 5 027 only, P = 0.2 and 0.1, 3 trials (for tests and a first look; the full run takes
// minutes). Progress on stderr.
//
//   mpirun -n K antkit buffon-cost ...   splits the trials across K MPI ranks; rank 0 gathers them
//                                        and writes the same files
#include "commands.hpp"
#include "output.hpp"
#include "ranks.hpp"

#include <antkit/experiments/buffon_cost.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/plot.hpp>
#include <antkit/kernel/input_error.hpp>
#include <array>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

namespace {

using antkit::kernel::InputError;
namespace buffon = antkit::buffon;
namespace ex = antkit::experiments;

struct CostCommand {
  std::string out;
  bool quick = false;
  std::int64_t trials = 0; // given with --trials; else 9, or 3 with --quick
  bool trials_given = false;
  std::uint64_t seed = 1;
  std::int64_t threads = 1;
  std::int64_t max_steps = 40000000;
  antkit::cli::Format format = antkit::cli::Format::Table;
};

void run(const CostCommand& c) {
  if (c.out.empty()) throw InputError("--out", "give an output directory");
  if (c.threads < 1 || c.threads > 256)
    throw InputError("--threads", "the number of threads must be in [1, 256]");
  ex::BuffonCostParams params;
  params.quick = c.quick;
  if (c.trials_given)
    params.trials = static_cast<std::uint64_t>(std::max<std::int64_t>(c.trials, 0));
  params.seed = c.seed;
  params.budget = c.max_steps;
  ex::validate(params); // before the output directory is made

  ex::BuffonCost cost;
  const int ranks = antkit::cli::run_on_ranks(c.out, static_cast<unsigned>(c.threads),
                                              antkit::cli::stage_progress("buffon-cost"),
                                              [&](const antkit::algorithms::Runner& runner) {
                                                cost = ex::run_buffon_cost(params, runner);
                                              });
  if (ranks == 0) return; // another rank than 0: rank 0 writes and prints

  std::array<std::filesystem::path, 4> files;
  try {
    files = ex::write_buffon_cost(cost, c.out);
  } catch (...) {
    ex::release_drawing_caches();
    throw;
  }
  ex::release_drawing_caches();

  if (c.format == antkit::cli::Format::Json) {
    nlohmann::json fits = nlohmann::json::array();
    for (const auto& f : cost.table.fits)
      fits.push_back({{"method", buffon::cost_method_name(f.method)},
                      {"precision", f.precision_millionths / 1e6},
                      {"exponent", f.exponent},
                      {"coefficient", f.coefficient},
                      {"points", f.points}});
    nlohmann::json paths = nlohmann::json::array();
    for (const auto& file : files) paths.push_back(file.string());
    antkit::cli::emit({{"fits", std::move(fits)}, {"files", std::move(paths)}, {"ranks", ranks}},
                      c.format, std::cout);
    return;
  }
  std::cout << "method   P      exponent  coefficient  points\n";
  for (const auto& f : cost.table.fits)
    std::cout << std::left << std::setw(9) << buffon::cost_method_name(f.method) << std::setw(7)
              << ex::number(f.precision_millionths / 1e6) << std::setw(10)
              << ex::number(std::round(f.exponent * 1000) / 1000) << std::setw(13)
              << ex::number(f.coefficient) << f.points << '\n';
  for (const auto& file : files) std::cout << file.string() << '\n';
}

void register_buffon_cost(CLI::App& app) {
  auto options = std::make_shared<CostCommand>();
  auto* sub = app.add_subcommand(
      "buffon-cost", "The cost of precision: trail to reach P against area, Buffon and RS");
  sub->add_option("--out", options->out, "Output directory")->required();
  sub->add_flag("--quick", options->quick,
                "Three circles and squares, P = 0.2 and 0.1, 3 trials (a first look)");
  auto* trials =
      sub->add_option("--trials", options->trials, "Trials per point (default 9, 3 with --quick)");
  sub->add_option("--seed", options->seed, "Seed of the keyed streams (default 1)");
  sub->add_option("--threads", options->threads, "Worker threads (default 1)");
  sub->add_option("--max-steps", options->max_steps,
                  "Step budget of one trial, all trails together (default 40000000)");
  antkit::cli::add_format_option(*sub, options->format);
  sub->callback([options, trials] {
    options->trials_given = trials->count() > 0;
    run(*options);
  });
}

const antkit::cli::Registration buffon_cost_registration{"buffon-cost", &register_buffon_cost};

} // namespace
