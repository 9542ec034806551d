// `antkit explore-tables`: paper 001's Tables 2 and 3 (issue 5), ours beside the paper's.
//
//   antkit explore-tables [--out DIR] [--seed S] [--format table|json]
//
// Writes DIR/table2.csv, DIR/table2.md, DIR/table3.csv, DIR/table3.md (atomically) and prints a
// summary. The experiment is documented in experiments/include/antkit/experiments/
// explore_tables.hpp. Under `mpirun` the runs split across the ranks (cli/ranks.hpp) and rank 0
// writes the same files.
#include "commands.hpp"
#include "output.hpp"
#include "ranks.hpp"

#include <antkit/experiments/explore_tables.hpp>
#include <antkit/kernel/hash.hpp>
#include <array>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace {

namespace ex = antkit::experiments;

struct Options {
  std::string out = ".";
  std::uint64_t seed = 1;
  antkit::cli::Format format = antkit::cli::Format::Table;
};

// The summary, on rank 0 (nothing on the other ranks under mpirun).
std::optional<nlohmann::json> run(const Options& o) {
  ex::ExploreTables t;
  std::array<std::filesystem::path, 4> files;
  const int ranks =
      antkit::cli::run_on_ranks(o.out, 1, {}, [&](const antkit::algorithms::Runner& runner) {
        try {
          t = ex::run_explore_tables(o.seed, runner);
        } catch (const std::runtime_error& e) {
          throw antkit::cli::CheckFailed(e.what());
        }
        if (runner.root()) files = ex::write_explore_tables(t, o.out);
      });
  if (ranks == 0) return std::nullopt;

  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t e = 0; e < ex::kExploreEnvironments.size(); ++e) {
    const auto& r = t.runs[e];
    const auto& p = ex::kPaperTable3[e];
    rows.push_back({{"environment", ex::kExploreEnvironments[e].name},
                    {"frontier_steps", ex::mean_of(r[1].steps)},
                    {"frontier_eme", ex::mean_of(r[1].eme)},
                    {"frontier_los_steps", ex::mean_of(r[2].steps)},
                    {"frontier_los_eme", ex::mean_of(r[2].eme)},
                    {"fwf_steps", ex::mean_of(r[0].steps)},
                    {"fwf_eme", ex::mean_of(r[0].eme)},
                    {"paper_sheng_steps", p.sheng_steps},
                    {"paper_fwf_steps", p.fwf_steps},
                    {"paper_fwf_eme", p.fwf_eme}});
  }
  nlohmann::json j;
  j["seed"] = o.seed;
  j["files"] = {files[0].string(), files[1].string(), files[2].string(), files[3].string()};
  j["table3"] = std::move(rows);
  j["hash"] = antkit::kernel::hash_hex(t.hash);
  j["ranks"] = ranks;
  return j;
}

void register_explore_tables(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* sub = app.add_subcommand(
      "explore-tables", "Paper 001's Tables 2 and 3 (fast wall-follow vs the frontier baseline), "
                        "ours beside the paper's, as CSV and Markdown");
  sub->add_option("--out", o->out, "Directory for table2/table3 .csv and .md")->default_val(".");
  sub->add_option("--seed", o->seed, "Seed of the obstacle positions")->default_val(1);
  antkit::cli::add_format_option(*sub, o->format);
  sub->callback([o] {
    if (const auto j = run(*o)) antkit::cli::emit(*j, o->format, std::cout);
  });
}

const antkit::cli::Registration explore_tables_registration{"explore-tables",
                                                            &register_explore_tables};

} // namespace
