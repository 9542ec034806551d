// `antkit cover-experiment`: reproduces Tables 1-4 of paper 004 and writes ours beside the
// paper's (issue 6).
//   antkit cover-experiment [--runs 10] [--size 100x100] [--sensor 5] [--seed 1] [--jobs 1]
//                           [--sensor-model line-of-sight|disk] [--out DIR] [--format table|json]
// Our tables add coordinated A* and frontier coverage, and how much frontier saves against A*
// and coordinated A*. Writes DIR/uniform_tables.csv and DIR/uniform_tables.md (atomically) and
// prints a summary. The experiment and the choices behind it are documented in
// experiments/include/antkit/experiments/uniform_tables.hpp. Under `mpirun` the runs split across
// the ranks (cli/ranks.hpp) and rank 0 writes the same files.
#include "commands.hpp"
#include "output.hpp"
#include "ranks.hpp"

#include <antkit/experiments/uniform_tables.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace {

using antkit::cli::Format;
using antkit::kernel::InputError;
namespace uniform = antkit::uniform;
namespace ex = antkit::experiments::uniform_tables;

struct ExperimentOptions {
  std::int64_t runs = 10;
  std::string size = "100x100";
  std::int64_t sensor = 5;
  std::uint64_t seed = 1;
  std::int64_t jobs = 1;
  std::string sensor_model = "line-of-sight";
  std::string out = ".";
  Format format = Format::Table;
};

// The summary, on rank 0 (nothing on the other ranks under mpirun).
std::optional<nlohmann::json> run_experiment(const ExperimentOptions& o) {
  if (o.runs < 1 || o.runs > 1000)
    throw InputError("--runs", "expected 1 to 1000 runs, not " + std::to_string(o.runs));
  if (o.sensor < 0 || o.sensor > uniform::kMaxSensorRange)
    throw InputError("--sensor", "expected a sensor distance in [0, " +
                                     std::to_string(uniform::kMaxSensorRange) + "] cells");
  if (o.jobs < 1 || o.jobs > 256)
    throw InputError("--jobs", "expected 1 to 256 threads, not " + std::to_string(o.jobs));
  ex::TablesConfig c;
  const auto [w, h] = uniform::parse_size(o.size, 2048);
  c.width = w;
  c.height = h;
  c.sensor = static_cast<std::int32_t>(o.sensor);
  c.runs = static_cast<std::uint32_t>(o.runs);
  c.seed = o.seed;
  if (o.sensor_model == "disk")
    c.sensor_model = uniform::SensorModel::Disk;
  else if (o.sensor_model != "line-of-sight")
    throw InputError("--sensor-model",
                     "'" + o.sensor_model +
                         "' is not a sensor model: expected line-of-sight or disk");
  const std::filesystem::path dir(o.out);
  if (!std::filesystem::is_directory(dir))
    throw InputError("--out", "'" + o.out + "' is not a directory");
  ex::TablesSummary summary;
  const int ranks = antkit::cli::run_on_ranks(o.out, static_cast<unsigned>(o.jobs), {},
                                              [&](const antkit::algorithms::Runner& runner) {
                                                auto rows = ex::run_tables(c, runner);
                                                if (runner.root())
                                                  summary = ex::write_tables(rows, c, dir);
                                              });
  if (ranks == 0) return std::nullopt;

  nlohmann::json j;
  j["csv"] = summary.csv.string();
  j["markdown"] = summary.markdown.string();
  j["width"] = c.width;
  j["height"] = c.height;
  j["sensor"] = c.sensor;
  j["runs"] = c.runs;
  j["seed"] = c.seed;
  j["sensor_model"] = o.sensor_model;
  nlohmann::json table = nlohmann::json::array();
  for (const auto& r : summary.rows) {
    nlohmann::json row;
    row["density"] = r.density_percent;
    row["robots"] = r.robots;
    for (const auto& column : r.columns) {
      const std::string name(uniform::algorithm_name(column.algorithm));
      row[name + "_coverage"] = column.coverage;
      row[name + "_movements"] = column.movements;
      row[name + "_moves"] = column.moves;
    }
    table.push_back(row);
  }
  j["rows"] = table;
  j["hash"] = antkit::kernel::hash_hex(summary.hash);
  j["ranks"] = ranks;
  return j;
}

void register_cover_experiment(CLI::App& app) {
  auto o = std::make_shared<ExperimentOptions>();
  auto* sub = app.add_subcommand("cover-experiment",
                                 "Reproduce Tables 1-4 of paper 004 (uniform coverage) and write "
                                 "ours beside the paper's as CSV and Markdown");
  sub->add_option("--runs", o->runs, "Runs per table row (default 10, as in the paper)");
  sub->add_option("--size", o->size, "Environment W x H (default 100x100)");
  sub->add_option("--sensor", o->sensor, "Sensor distance in cells (default 5)");
  sub->add_option("--seed", o->seed, "Seed of the keyed random streams (default 1)");
  sub->add_option("--sensor-model", o->sensor_model,
                  "line-of-sight (default) or disk (views every cell in range, through walls)");
  sub->add_option("--jobs", o->jobs, "Threads (default 1); the results do not depend on it");
  sub->add_option("--out", o->out, "Directory for uniform_tables.csv and .md (default .)");
  antkit::cli::add_format_option(*sub, o->format);
  sub->callback([o] {
    if (const auto j = run_experiment(*o)) antkit::cli::emit(*j, o->format, std::cout);
  });
}

const antkit::cli::Registration cover_experiment_registration{"cover-experiment",
                                                              &register_cover_experiment};

} // namespace
