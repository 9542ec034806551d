// `antkit cover-experiment`: reproduces Tables 1-4 of paper 004 and writes ours beside the
// paper's (issue 6).
//   antkit cover-experiment [--runs 10] [--size 100x100] [--sensor 5] [--seed 1] [--jobs 1]
//                           [--out DIR] [--format table|json]
// Our tables add coordinated A* and frontier coverage, and how much frontier saves against A*
// and coordinated A*. Writes DIR/uniform_tables.csv and DIR/uniform_tables.md (atomically) and
// prints a summary. The experiment and the choices behind it are documented in
// experiments/include/antkit/experiments/paper_tables.hpp.
#include "commands.hpp"
#include "output.hpp"

#include <antkit/experiments/paper_tables.hpp>
#include <antkit/geometry/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace {

using antkit::cli::Format;
using antkit::kernel::InputError;
namespace uniform = antkit::uniform;
namespace ex = antkit::uniform::experiments;

struct ExperimentOptions {
  std::int64_t runs = 10;
  std::string size = "100x100";
  std::int64_t sensor = 5;
  std::uint64_t seed = 1;
  std::int64_t jobs = 1;
  std::string out = ".";
  Format format = Format::Table;
};

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string csv(const std::vector<ex::TablesRow>& rows, std::uint32_t runs) {
  std::ostringstream s;
  s << "table,density_percent,robots,algorithm,runs,coverage_mean,coverage_min,complete_runs,"
       "movements_mean,moves_mean,paper_coverage,paper_movements\n";
  for (const auto& row : rows)
    for (std::size_t a = 0; a < ex::kTableColumns; ++a) {
      const auto& p = *row.paper;
      s << p.table << ',' << p.density_percent << ',' << p.robots << ','
        << uniform::algorithm_name(ex::kTableAlgorithms[a]) << ',' << runs << ','
        << fixed(row.coverage[a], 2) << ',' << fixed(row.coverage_min[a], 2) << ','
        << row.complete[a] << ',' << fixed(row.movements[a], 1) << ',' << fixed(row.moves[a], 1)
        << ',' << (a < 3 ? fixed(p.coverage[a], 2) : "") << ','
        << (a < 3 ? fixed(p.movements[a], 1) : "") << '\n';
    }
  return s.str();
}

std::string markdown(const std::vector<ex::TablesRow>& rows, const ex::TablesConfig& c) {
  std::ostringstream s;
  s << "# Paper 004, Tables 1-4: ours beside the paper's\n\n"
    << c.width << " x " << c.height << " cells, sensor distance " << c.sensor << ", " << c.runs
    << " runs per row (trials 0.." << c.runs - 1 << ", seed " << c.seed
    << "). Each cell: ours / paper. Coverage in % of viewable free cells, movements in ticks. RW "
       "runs as many ticks as A* took on the same map.\n";
  for (int table = 1; table <= 4; ++table) {
    const ex::TablesRow* first = nullptr;
    for (const auto& r : rows)
      if (r.paper->table == table && !first) first = &r;
    if (!first) continue;
    s << "\n## Table " << table << ": " << first->paper->density_percent
      << " % obstacle density\n\n"
      << "| robots | RW coverage | RW movements | PM coverage | PM movements | A* coverage | A* "
         "movements | coord. A* coverage | coord. A* movements | frontier coverage | frontier "
         "movements |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : rows) {
      if (r.paper->table != table) continue;
      s << "| " << r.paper->robots;
      for (std::size_t a = 0; a < 3; ++a)
        s << " | " << fixed(r.coverage[a], 2) << " / " << fixed(r.paper->coverage[a], 2) << " | "
          << fixed(r.movements[a], 1) << " / " << fixed(r.paper->movements[a], 1);
      for (std::size_t a = 3; a < ex::kTableColumns; ++a)
        s << " | " << fixed(r.coverage[a], 2) << " | " << fixed(r.movements[a], 1);
      s << " |\n";
    }
  }
  const auto saved = [](double base, double v) {
    return base > 0 ? 100.0 * (base - v) / base : 0.0;
  };
  s << "\n## Coordinated A* against A*\n\n"
    << "| density % | robots | A* movements | coord. movements | saved % | A* moves | coord. "
       "moves | saved % |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    s << "| " << r.paper->density_percent << " | " << r.paper->robots << " | "
      << fixed(r.movements[2], 1) << " | " << fixed(r.movements[3], 1) << " | "
      << fixed(saved(r.movements[2], r.movements[3]), 1) << " | " << fixed(r.moves[2], 1) << " | "
      << fixed(r.moves[3], 1) << " | " << fixed(saved(r.moves[2], r.moves[3]), 1) << " |\n";
  }
  // Saved %: (baseline - frontier) / baseline of the means; negative when frontier needs more.
  s << "\n## Frontier against A* and coordinated A*\n\n"
    << "Frontier: Sheng et al.'s g = I - D on the shared viewed map (frontier_coverage.hpp). Saved "
       "% = (baseline - frontier) / baseline, of the means over the runs.\n\n"
    << "| density % | robots | frontier movements | saved vs A* % | saved vs coord. % | frontier "
       "moves | saved vs A* % | saved vs coord. % |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    s << "| " << r.paper->density_percent << " | " << r.paper->robots << " | "
      << fixed(r.movements[4], 1) << " | " << fixed(saved(r.movements[2], r.movements[4]), 1)
      << " | " << fixed(saved(r.movements[3], r.movements[4]), 1) << " | " << fixed(r.moves[4], 1)
      << " | " << fixed(saved(r.moves[2], r.moves[4]), 1) << " | "
      << fixed(saved(r.moves[3], r.moves[4]), 1) << " |\n";
  }
  return s.str();
}

nlohmann::json run_experiment(const ExperimentOptions& o) {
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
  c.jobs = static_cast<unsigned>(o.jobs);
  const std::filesystem::path dir(o.out);
  if (!std::filesystem::is_directory(dir))
    throw InputError("--out", "'" + o.out + "' is not a directory");
  const auto rows = ex::run_tables(c);
  const auto csv_path = dir / "uniform_tables.csv";
  const auto md_path = dir / "uniform_tables.md";
  antkit::geometry::write_file_atomic(csv_path, csv(rows, c.runs));
  antkit::geometry::write_file_atomic(md_path, markdown(rows, c));

  nlohmann::json j;
  j["csv"] = csv_path.string();
  j["markdown"] = md_path.string();
  j["width"] = c.width;
  j["height"] = c.height;
  j["sensor"] = c.sensor;
  j["runs"] = c.runs;
  j["seed"] = c.seed;
  nlohmann::json table = nlohmann::json::array();
  antkit::kernel::TraceHash digest;
  for (const auto& r : rows) {
    digest.add_u64(r.hash);
    nlohmann::json row;
    row["density"] = r.paper->density_percent;
    row["robots"] = r.paper->robots;
    for (std::size_t a = 0; a < ex::kTableColumns; ++a) {
      const std::string name(uniform::algorithm_name(ex::kTableAlgorithms[a]));
      row[name + "_coverage"] = std::stod(fixed(r.coverage[a], 2));
      row[name + "_movements"] = std::stod(fixed(r.movements[a], 1));
      row[name + "_moves"] = std::stod(fixed(r.moves[a], 1));
    }
    table.push_back(row);
  }
  j["rows"] = table;
  j["hash"] = antkit::kernel::hash_hex(digest.finish());
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
  sub->add_option("--jobs", o->jobs, "Threads (default 1); the results do not depend on it");
  sub->add_option("--out", o->out, "Directory for uniform_tables.csv and .md (default .)");
  antkit::cli::add_format_option(*sub, o->format);
  sub->callback([o] { antkit::cli::emit(run_experiment(*o), o->format, std::cout); });
}

const antkit::cli::Registration reg{"cover-experiment", &register_cover_experiment};

} // namespace
