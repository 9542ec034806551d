// `antkit explore-tables`: paper 001's Tables 2 and 3 (issue 5), ours beside the paper's.
//
//   antkit explore-tables [--out DIR] [--seed S] [--format table|json]
//
// The environments: 25x25, the robots start at the lower-left corner (0, 24) and its east
// neighbour; empty, 1, 2, 5 and 10 scattered single-cell obstacles, one and two blocks of six;
// 10 repetitions (5 for the blocks), repetition t drawn as `antkit explore --size 25x25
// --obstacles K --seed S --trial t` draws it (so any cell of the tables can be re-run and drawn).
// The same trial number gives nested obstacle sets across columns (the first draws of one keyed
// stream): the columns differ by the obstacles added, not by unrelated layouts.
//
// Writes DIR/table2.csv, DIR/table2.md, DIR/table3.csv, DIR/table3.md (atomically) and prints a
// summary. Table 3's "Sheng et al." is our frontier baseline without line-of-sight sweeping (the
// original method); the frontier baseline with sweeping is shown beside it.
#include "commands.hpp"
#include "output.hpp"

#include <antkit/geometry/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/los/explore.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace los = antkit::los;
using antkit::kernel::Cell;

// One environment column of the tables.
struct Environment {
  const char* name;
  int obstacles; // scattered single cells
  int blocks;    // blocks of six
  int repetitions;
};

constexpr std::array<Environment, 7> kEnvironments{{{"No obstacles", 0, 0, 10},
                                                    {"One obstacle", 1, 0, 10},
                                                    {"Two obstacles", 2, 0, 10},
                                                    {"Five obstacles", 5, 0, 10},
                                                    {"Ten obstacles", 10, 0, 10},
                                                    {"One block (six obstacles)", 0, 1, 5},
                                                    {"Two blocks (six obstacles each)", 0, 2, 5}}};

// Paper 001, Table 2 (fast wall-follow steps per repetition), columns One .. Two blocks; Table 2
// has no empty-room column.
constexpr std::array<std::array<int, 10>, 6> kPaperTable2{{
    {81, 89, 88, 63, 89, 85, 62, 83, 89, 96},
    {94, 107, 80, 122, 81, 102, 99, 109, 95, 92},
    {111, 135, 102, 125, 114, 134, 121, 150, 122, 101},
    {118, 145, 158, 158, 150, 143, 137, 152, 154, 146},
    {96, 84, 83, 84, 92, 0, 0, 0, 0, 0},
    {108, 102, 94, 101, 96, 0, 0, 0, 0, 0},
}};
constexpr std::array<double, 6> kPaperTable2Average{82.5, 98.1, 121.5, 146.1, 87.8, 100.2};
constexpr std::array<double, 6> kPaperTable2Deviation{11.9, 12.7, 15.3, 11.9, 5.8, 5.5};

// Paper 001, Table 3: Sheng et al. 2006 steps, E.M.E; fast wall-follow steps, E.M.E.
struct PaperRow {
  double sheng_steps, sheng_eme, fwf_steps, fwf_eme;
};
constexpr std::array<PaperRow, 7> kPaperTable3{{{158.7, 317.4, 47, 94},
                                                {155.4, 310.8, 82.5, 122.1},
                                                {155.7, 311.4, 98.1, 143.8},
                                                {155.2, 310.4, 121.5, 193.7},
                                                {153.3, 306.6, 146.1, 252.1},
                                                {157.2, 314.4, 87.8, 127.4},
                                                {159.4, 318.8, 100.2, 147.6}}};

struct Runs {
  std::vector<double> steps, eme;
};

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0 : s / static_cast<double>(v.size());
}
// The sample standard deviation (n - 1), which reproduces the paper's Table 2 deviations.
double deviation(const std::vector<double>& v) {
  if (v.size() < 2) return 0;
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}
std::string fixed1(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", x);
  return buf;
}

Runs run_environment(const Environment& env, std::uint64_t seed, los::ExploreOptions options) {
  Runs runs;
  const Cell corner{0, 24};
  for (int t = 1; t <= env.repetitions; ++t) {
    const auto trial = static_cast<std::uint64_t>(t);
    const auto grid = env.blocks > 0
                          ? los::obstacle_blocks(25, 25, env.blocks, seed, trial, corner)
                          : los::scattered_obstacles(25, 25, env.obstacles, seed, trial, corner);
    const auto pair = los::start_pair(grid, corner);
    const auto r = los::explore(grid, pair[0], pair[1], options);
    if (!r.completed || r.explored != r.observable)
      throw antkit::cli::CheckFailed(std::string(env.name) + ", trial " + std::to_string(t) +
                                     ": the exploration did not complete");
    runs.steps.push_back(static_cast<double>(r.steps));
    runs.eme.push_back(static_cast<double>(r.eme));
  }
  return runs;
}

struct Options {
  std::string out = ".";
  std::uint64_t seed = 1;
  antkit::cli::Format format = antkit::cli::Format::Table;
};

nlohmann::json run(const Options& o) {
  std::array<Runs, 7> fwf, sheng, sheng_los;
  for (std::size_t e = 0; e < kEnvironments.size(); ++e) {
    los::ExploreOptions opt;
    opt.algorithm = los::Algorithm::FastWallFollow;
    fwf[e] = run_environment(kEnvironments[e], o.seed, opt);
    opt.algorithm = los::Algorithm::Frontier;
    opt.line_of_sight = false;
    sheng[e] = run_environment(kEnvironments[e], o.seed, opt);
    opt.line_of_sight = true;
    sheng_los[e] = run_environment(kEnvironments[e], o.seed, opt);
  }

  // Table 2: fast wall-follow steps per repetition, ours and the paper's.
  std::ostringstream csv2, md2;
  csv2 << "environment,experiment,ours_steps,paper_steps\n";
  md2 << "# Table 2: steps of fast wall-follow per repetition (ours / paper 001), seed " << o.seed
      << "\n\n| Experiment No. |";
  for (std::size_t e = 1; e < kEnvironments.size(); ++e)
    md2 << ' ' << kEnvironments[e].name << " |";
  md2 << "\n|---|";
  for (std::size_t e = 1; e < kEnvironments.size(); ++e) md2 << "---|";
  md2 << '\n';
  for (int t = 0; t < 10; ++t) {
    md2 << "| " << t + 1 << " |";
    for (std::size_t e = 1; e < kEnvironments.size(); ++e) {
      if (t >= kEnvironments[e].repetitions) {
        md2 << " ----- |";
        continue;
      }
      const double ours = fwf[e].steps[static_cast<std::size_t>(t)];
      const int paper = kPaperTable2[e - 1][static_cast<std::size_t>(t)];
      csv2 << '"' << kEnvironments[e].name << "\"," << t + 1 << ',' << ours << ',' << paper << '\n';
      md2 << ' ' << ours << " / " << paper << " |";
    }
    md2 << '\n';
  }
  md2 << "| Average |";
  for (std::size_t e = 1; e < kEnvironments.size(); ++e)
    md2 << ' ' << fixed1(mean(fwf[e].steps)) << " / " << fixed1(kPaperTable2Average[e - 1]) << " |";
  md2 << "\n| S. Deviation |";
  for (std::size_t e = 1; e < kEnvironments.size(); ++e)
    md2 << ' ' << fixed1(deviation(fwf[e].steps)) << " / " << fixed1(kPaperTable2Deviation[e - 1])
        << " |";
  md2 << '\n';

  // Table 3: averages of steps and E.M.E.
  std::ostringstream csv3, md3;
  csv3 << "environment,repetitions,paper_sheng_steps,paper_sheng_eme,ours_frontier_steps,"
          "ours_frontier_eme,ours_frontier_los_steps,ours_frontier_los_eme,paper_fwf_steps,"
          "paper_fwf_eme,ours_fwf_steps,ours_fwf_eme,fwf_beats_frontier_on_eme,"
          "fwf_beats_frontier_on_steps\n";
  md3 << "# Table 3: averages of steps and Estimated Motor Energy (E.M.E), seed " << o.seed
      << "\n\n| Environment | Sheng et al. (paper) steps | E.M.E | frontier (ours) steps | E.M.E "
         "| frontier + LOS (ours) steps | E.M.E | Fast Wall-Follow (paper) steps | E.M.E | Fast "
         "Wall-Follow (ours) steps | E.M.E | ours: FWF better on E.M.E? | on steps? |\n";
  md3 << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t e = 0; e < kEnvironments.size(); ++e) {
    const auto& p = kPaperTable3[e];
    const double fs = mean(sheng[e].steps), fe = mean(sheng[e].eme);
    const double ls = mean(sheng_los[e].steps), le = mean(sheng_los[e].eme);
    const double ws = mean(fwf[e].steps), we = mean(fwf[e].eme);
    const bool eme_better = we < fe, steps_better = ws < fs;
    csv3 << '"' << kEnvironments[e].name << "\"," << kEnvironments[e].repetitions << ','
         << p.sheng_steps << ',' << p.sheng_eme << ',' << fs << ',' << fe << ',' << ls << ',' << le
         << ',' << p.fwf_steps << ',' << p.fwf_eme << ',' << ws << ',' << we << ','
         << (eme_better ? "yes" : "no") << ',' << (steps_better ? "yes" : "no") << '\n';
    md3 << "| " << kEnvironments[e].name << " | " << fixed1(p.sheng_steps) << " | "
        << fixed1(p.sheng_eme) << " | " << fixed1(fs) << " | " << fixed1(fe) << " | " << fixed1(ls)
        << " | " << fixed1(le) << " | " << fixed1(p.fwf_steps) << " | " << fixed1(p.fwf_eme)
        << " | " << fixed1(ws) << " | " << fixed1(we) << " | " << (eme_better ? "yes" : "no")
        << " | " << (steps_better ? "yes" : "no") << " |\n";
    rows.push_back({{"environment", kEnvironments[e].name},
                    {"frontier_steps", fs},
                    {"frontier_eme", fe},
                    {"frontier_los_steps", ls},
                    {"frontier_los_eme", le},
                    {"fwf_steps", ws},
                    {"fwf_eme", we},
                    {"paper_sheng_steps", p.sheng_steps},
                    {"paper_fwf_steps", p.fwf_steps},
                    {"paper_fwf_eme", p.fwf_eme}});
  }

  const std::filesystem::path dir(o.out);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw antkit::kernel::InputError("--out", "cannot make the directory '" + o.out + "'");
  antkit::geometry::write_file_atomic(dir / "table2.csv", csv2.str());
  antkit::geometry::write_file_atomic(dir / "table2.md", md2.str());
  antkit::geometry::write_file_atomic(dir / "table3.csv", csv3.str());
  antkit::geometry::write_file_atomic(dir / "table3.md", md3.str());

  nlohmann::json j;
  j["seed"] = o.seed;
  j["files"] = {(dir / "table2.csv").string(), (dir / "table2.md").string(),
                (dir / "table3.csv").string(), (dir / "table3.md").string()};
  j["table3"] = std::move(rows);
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
  sub->callback([o] { antkit::cli::emit(run(*o), o->format, std::cout); });
}

const antkit::cli::Registration reg{"explore-tables", &register_explore_tables};

} // namespace
