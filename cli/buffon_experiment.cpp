// `antkit buffon-experiment --figure 5|6|7|8|9|14 --out DIR [--trials N] [--steps N] [--seed S]
//                           [--threads T] [--format table|json]`: the paper's (000) Figures 5-9
// and 14 as CSV, SVG and PNG: DIR/figure<N>.csv, .svg and .png, written atomically; under `mpirun`
// the trials split across the ranks (cli/ranks.hpp) and rank 0 writes the same files. The
// experiment, its streams and the choices where the paper is silent are documented in
// experiments/include/antkit/experiments/buffon_figures.hpp.
#include "buffon_options.hpp"
#include "commands.hpp"
#include "output.hpp"
#include "ranks.hpp"

#include <antkit/experiments/buffon_figures.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace {

using antkit::kernel::InputError;
namespace ex = antkit::experiments;

struct ExperimentCommand {
  ex::BuffonFigureParams params;
  std::string out;
  std::int64_t threads = 2;
  antkit::cli::Format format = antkit::cli::Format::Table;
};

void run(const ExperimentCommand& c) {
  if (c.params.figure != 14 && ex::buffon_figure_arenas(c.params.figure).empty())
    throw InputError("--figure", "the figure must be 5, 6, 7, 8, 9 or 14");
  antkit::cli::check_buffon_run_size(c.params.trials, c.params.steps, c.threads);
  if (c.out.empty()) throw InputError("--out", "give an output directory");
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path dir(c.out);
  const std::string stem = "figure" + std::to_string(c.params.figure);
  std::string csv;
  ex::Figure figure;
  std::uint64_t hash = 0;
  const int ranks = antkit::cli::run_on_ranks(
      c.out, static_cast<unsigned>(c.threads), {}, [&](const antkit::algorithms::Runner& runner) {
        if (c.params.figure == 14) {
          const auto f = ex::run_figure14(c.params, runner);
          if (!runner.root()) return;
          csv = ex::figure14_csv(f);
          figure = ex::figure14_plot(f);
          hash = f.hash;
        } else {
          const auto f = ex::run_buffon_figure(c.params, runner);
          if (!runner.root()) return;
          csv = ex::buffon_figure_csv(f);
          figure = ex::buffon_figure_plot(f);
          hash = f.hash;
        }
      });
  if (ranks == 0) return; // another rank than 0: rank 0 writes and prints
  antkit::io::write_file_atomic(dir / (stem + ".csv"), csv);
  ex::save_figure(figure, dir / (stem + ".svg"), dir / (stem + ".png"));
  ex::release_drawing_caches();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "figure " << c.params.figure << ": " << c.params.trials << " trials per arena in "
            << seconds << " s, trace hash " << antkit::kernel::hash_hex(hash) << "\n";
  if (c.format == antkit::cli::Format::Json) {
    nlohmann::json files = nlohmann::json::array();
    for (const char* ext : {".csv", ".svg", ".png"}) files.push_back((dir / (stem + ext)).string());
    antkit::cli::emit({{"figure", c.params.figure},
                       {"files", std::move(files)},
                       {"hash", antkit::kernel::hash_hex(hash)},
                       {"ranks", ranks}},
                      c.format, std::cout);
    return;
  }
  for (const char* ext : {".csv", ".svg", ".png"})
    std::cout << (dir / (stem + ext)).string() << '\n';
}

void register_buffon_experiment(CLI::App& app) {
  auto options = std::make_shared<ExperimentCommand>();
  auto* sub =
      app.add_subcommand("buffon-experiment", "Paper 000's Figures 5-9 and 14 as CSV, SVG and PNG");
  sub->add_option("--figure", options->params.figure, "5, 6, 7, 8, 9 or 14")->required();
  sub->add_option("--out", options->out, "Output directory")->required();
  sub->add_option("--trials", options->params.trials, "Trials per arena (default 100)");
  sub->add_option("--steps", options->params.steps, "Steps per visit (default 50000)");
  sub->add_option("--seed", options->params.seed, "Seed of the keyed streams (default 1)");
  sub->add_option("--threads", options->threads, "Worker threads (default 2)");
  antkit::cli::add_format_option(*sub, options->format);
  sub->callback([options] { run(*options); });
}

// "trials" and "steps per visit" are main.cpp's words every command shows alike.
const antkit::cli::Registration buffon_experiment_registration{
    "buffon-experiment", &register_buffon_experiment, {{"figure", "--figure"}}};

} // namespace
