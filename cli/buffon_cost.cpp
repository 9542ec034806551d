// `antkit buffon-cost`: the cost of precision (issue 17; experiments/buffon_cost.hpp, whose
// measurement is algorithms/buffon/precision_cost.hpp).
//
//   antkit buffon-cost --out DIR [--quick] [--trials N] [--seed S] [--threads T]
//                      [--max-steps N]
//
// Runs the sweep of experiments/buffon_cost.hpp (Buffon with two markers, with the online first
// visit, and RS, to P = 0.2, 0.1 and 0.05 against area) and writes DIR/precision_cost.csv,
// DIR/precision_cost_fits.csv, DIR/precision_cost.svg and .png (the columns and the figure are
// described there), then prints the fits and the four paths. --quick: circles and squares of 314,
// 1 257 and 5 027 only, P = 0.2 and 0.1, 3 trials (for tests and a first look; the full run takes
// minutes). Progress on stderr.
#include "commands.hpp"

#include <antkit/experiments/buffon_cost.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/plot.hpp>
#include <antkit/kernel/input_error.hpp>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <unistd.h>

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
};

void run(const CostCommand& c) {
  if (c.out.empty()) throw InputError("--out", "give an output directory");
  if (c.trials_given && (c.trials < 1 || c.trials > 100000))
    throw InputError("--trials", "the number of trials must be in [1, 100000]");
  if (c.threads < 1 || c.threads > 256)
    throw InputError("--threads", "the number of threads must be in [1, 256]");
  if (c.max_steps < 2 || c.max_steps > 100000000)
    throw InputError("--max-steps", "the budget per trial must be in [2, 100000000]");
  std::error_code ec;
  std::filesystem::create_directories(c.out, ec);
  if (ec || !std::filesystem::is_directory(c.out))
    throw InputError("--out", "cannot create the directory '" + c.out + "'");
  if (::access(c.out.c_str(), W_OK) != 0)
    throw InputError("--out", "cannot write into the directory '" + c.out + "'");

  ex::BuffonCostParams params;
  params.quick = c.quick;
  if (c.trials_given) params.trials = static_cast<std::uint64_t>(c.trials);
  params.seed = c.seed;
  params.threads = static_cast<unsigned>(c.threads);
  params.budget = c.max_steps;

  const auto start = std::chrono::steady_clock::now();
  const bool tty = ::isatty(2) != 0;
  const auto cost = ex::run_buffon_cost(params, [&](std::size_t done, std::size_t total) {
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double eta = s / static_cast<double>(done) * static_cast<double>(total - done);
    std::cerr << (tty ? "\r" : "") << "buffon-cost: " << done << "/" << total << " points, "
              << std::fixed << std::setprecision(0) << s << " s, about " << eta << " s left"
              << std::defaultfloat << std::setprecision(6) << (tty ? "   " : "\n") << std::flush;
  });
  if (tty) std::cerr << '\n';

  std::array<std::filesystem::path, 4> files;
  try {
    files = ex::write_buffon_cost(cost, c.out);
  } catch (...) {
    ex::release_drawing_caches();
    throw;
  }
  ex::release_drawing_caches();

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
  sub->callback([options, trials] {
    options->trials_given = trials->count() > 0;
    run(*options);
  });
}

const antkit::cli::Registration reg{"buffon-cost", &register_buffon_cost};

} // namespace
