#include <algorithm>
#include <antkit/buffon/estimate.hpp>
#include <antkit/experiments/drawing.hpp>
#include <antkit/experiments/explore_tables.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/los/explore.hpp>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace antkit::experiments {

namespace los = antkit::los;

namespace {

los::ExploreOptions method_options(std::size_t m) {
  los::ExploreOptions opt;
  opt.algorithm = m == 0 ? los::Algorithm::FastWallFollow : los::Algorithm::Frontier;
  opt.line_of_sight = m != 1;
  return opt;
}

} // namespace

double mean_of(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0 : s / static_cast<double>(v.size());
}

double sample_deviation(const std::vector<double>& v) {
  if (v.size() < 2) return 0;
  const double m = mean_of(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}

ExploreTables run_explore_tables(std::uint64_t seed, const algorithms::Runner& runner,
                                 int repetitions_factor) {
  if (repetitions_factor < 1 || repetitions_factor > 1000)
    throw kernel::InputError("repetitions", "the factor must be in [1, 1000]");
  struct WorkUnit {
    std::size_t env, method;
    int trial;
  };
  std::vector<WorkUnit> units;
  for (std::size_t e = 0; e < kExploreEnvironments.size(); ++e)
    for (std::size_t m = 0; m < kExploreMethods; ++m)
      for (int t = 1; t <= kExploreEnvironments[e].repetitions * repetitions_factor; ++t)
        units.push_back({e, m, t});
  const kernel::Cell corner{0, 24};
  const auto payloads =
      algorithms::run_units(runner, "paper 001, tables 2-3", units.size(), [&](std::uint64_t u) {
        const WorkUnit& unit = units[u];
        const auto& env = kExploreEnvironments[unit.env];
        const auto trial = static_cast<std::uint64_t>(unit.trial);
        const auto grid =
            env.blocks > 0 ? los::obstacle_blocks(25, 25, env.blocks, seed, trial, corner)
                           : los::scattered_obstacles(25, 25, env.obstacles, seed, trial, corner);
        const auto pair = los::start_pair(grid, corner);
        const auto r = los::explore(grid, pair[0], pair[1], method_options(unit.method));
        if (!r.completed || r.explored != r.observable)
          throw std::runtime_error(std::string(env.name) + ", trial " + std::to_string(unit.trial) +
                                   ": the exploration did not complete");
        algorithms::Payload p;
        p.put(r.steps);
        p.put(r.eme);
        p.put(r.hash);
        return p;
      });
  ExploreTables out;
  out.seed = seed;
  if (!runner.root()) return out;
  kernel::TraceHash digest;
  for (std::size_t u = 0; u < units.size(); ++u) {
    algorithms::Payload p = payloads[u];
    auto& runs = out.runs[units[u].env][units[u].method];
    runs.steps.push_back(static_cast<double>(p.get()));
    runs.eme.push_back(static_cast<double>(p.get()));
    digest.add_u64(p.get());
  }
  out.hash = digest.finish();
  return out;
}

std::string table2_csv(const ExploreTables& t) {
  std::ostringstream csv;
  csv << "environment,experiment,ours_steps,paper_steps\n";
  for (int k = 0; k < 10; ++k)
    for (std::size_t e = 1; e < kExploreEnvironments.size(); ++e)
      if (k < kExploreEnvironments[e].repetitions)
        csv << '"' << kExploreEnvironments[e].name << "\"," << k + 1 << ','
            << t.runs[e][0].steps[static_cast<std::size_t>(k)] << ','
            << kPaperTable2[e - 1][static_cast<std::size_t>(k)] << '\n';
  return csv.str();
}

std::string table2_markdown(const ExploreTables& t) {
  std::ostringstream md;
  md << "# Table 2: steps of fast wall-follow per repetition (ours / paper 001), seed " << t.seed
     << "\n\n| Experiment No. |";
  for (std::size_t e = 1; e < kExploreEnvironments.size(); ++e)
    md << ' ' << kExploreEnvironments[e].name << " |";
  md << "\n|---|";
  for (std::size_t e = 1; e < kExploreEnvironments.size(); ++e) md << "---|";
  md << '\n';
  for (int k = 0; k < 10; ++k) {
    md << "| " << k + 1 << " |";
    for (std::size_t e = 1; e < kExploreEnvironments.size(); ++e) {
      if (k >= kExploreEnvironments[e].repetitions) {
        md << " ----- |";
        continue;
      }
      md << ' ' << t.runs[e][0].steps[static_cast<std::size_t>(k)] << " / "
         << kPaperTable2[e - 1][static_cast<std::size_t>(k)] << " |";
    }
    md << '\n';
  }
  md << "| Average |";
  for (std::size_t e = 1; e < kExploreEnvironments.size(); ++e)
    md << ' ' << fixed(mean_of(t.runs[e][0].steps), 1) << " / "
       << fixed(kPaperTable2Average[e - 1], 1) << " |";
  md << "\n| S. Deviation |";
  for (std::size_t e = 1; e < kExploreEnvironments.size(); ++e)
    md << ' ' << fixed(sample_deviation(t.runs[e][0].steps), 1) << " / "
       << fixed(kPaperTable2Deviation[e - 1], 1) << " |";
  md << '\n';
  return md.str();
}

std::string table3_csv(const ExploreTables& t) {
  std::ostringstream csv;
  csv << "environment,repetitions,paper_sheng_steps,paper_sheng_eme,ours_frontier_steps,"
         "ours_frontier_eme,ours_frontier_los_steps,ours_frontier_los_eme,paper_fwf_steps,"
         "paper_fwf_eme,ours_fwf_steps,ours_fwf_eme,fwf_beats_frontier_on_eme,"
         "fwf_beats_frontier_on_steps\n";
  for (std::size_t e = 0; e < kExploreEnvironments.size(); ++e) {
    const auto& p = kPaperTable3[e];
    const auto& r = t.runs[e];
    const double fs = mean_of(r[1].steps), fe = mean_of(r[1].eme);
    const double ws = mean_of(r[0].steps), we = mean_of(r[0].eme);
    csv << '"' << kExploreEnvironments[e].name << "\"," << kExploreEnvironments[e].repetitions
        << ',' << p.sheng_steps << ',' << p.sheng_eme << ',' << fs << ',' << fe << ','
        << mean_of(r[2].steps) << ',' << mean_of(r[2].eme) << ',' << p.fwf_steps << ',' << p.fwf_eme
        << ',' << ws << ',' << we << ',' << (we < fe ? "yes" : "no") << ','
        << (ws < fs ? "yes" : "no") << '\n';
  }
  return csv.str();
}

std::string table3_markdown(const ExploreTables& t) {
  std::ostringstream md;
  md << "# Table 3: averages of steps and Estimated Motor Energy (E.M.E), seed " << t.seed
     << "\n\n| Environment | Sheng et al. (paper) steps | E.M.E | frontier (ours) steps | E.M.E "
        "| frontier + LOS (ours) steps | E.M.E | Fast Wall-Follow (paper) steps | E.M.E | Fast "
        "Wall-Follow (ours) steps | E.M.E | ours: FWF better on E.M.E? | on steps? |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t e = 0; e < kExploreEnvironments.size(); ++e) {
    const auto& p = kPaperTable3[e];
    const auto& r = t.runs[e];
    const double fs = mean_of(r[1].steps), fe = mean_of(r[1].eme);
    const double ws = mean_of(r[0].steps), we = mean_of(r[0].eme);
    md << "| " << kExploreEnvironments[e].name << " | " << fixed(p.sheng_steps, 1) << " | "
       << fixed(p.sheng_eme, 1) << " | " << fixed(fs, 1) << " | " << fixed(fe, 1) << " | "
       << fixed(mean_of(r[2].steps), 1) << " | " << fixed(mean_of(r[2].eme), 1) << " | "
       << fixed(p.fwf_steps, 1) << " | " << fixed(p.fwf_eme, 1) << " | " << fixed(ws, 1) << " | "
       << fixed(we, 1) << " | " << (we < fe ? "yes" : "no") << " | " << (ws < fs ? "yes" : "no")
       << " |\n";
  }
  return md.str();
}

Figure explore_plot(const ExploreTables& t) {
  Figure fig;
  fig.title = "Paper 001, Figures 5-6: steps and motor energy against the obstacles";
  fig.x_label = "environment (25 x 25 cells)";
  fig.y_label = "mean over the repetitions";
  fig.y_from_zero = true;
  fig.x_categories = {"none", "1", "2", "5", "10", "1 block", "2 blocks"};
  fig.caption = "Ours: seed " + std::to_string(t.seed) +
                ", 10 repetitions (5 for the blocks), bars: interquartile range. Paper: Table 3 "
                "means.\n\"Sheng et al.\" (ours) is our frontier baseline without line-of-sight "
                "sweeping.";
  const auto series = [&](const char* name, const char* colour, bool dashed, std::size_t method,
                          bool eme) {
    PlotSeries s{name, colour, dashed, false, {}};
    for (std::size_t e = 0; e < kExploreEnvironments.size(); ++e) {
      const auto& v = eme ? t.runs[e][method].eme : t.runs[e][method].steps;
      s.points.push_back({static_cast<double>(e), mean_of(v), buffon::quantile(v, 0.25),
                          buffon::quantile(v, 0.75)});
    }
    return s;
  };
  const auto paper = [&](const char* name, const char* colour, bool fwf, bool eme) {
    PlotSeries s{name, colour, true, true, {}};
    for (std::size_t e = 0; e < kPaperTable3.size(); ++e) {
      const auto& p = kPaperTable3[e];
      s.points.push_back(
          {static_cast<double>(e),
           fwf ? (eme ? p.fwf_eme : p.fwf_steps) : (eme ? p.sheng_eme : p.sheng_steps),
           std::nullopt, std::nullopt});
    }
    return s;
  };
  for (const bool eme : {false, true}) {
    PlotPanel panel;
    panel.title = eme ? "Estimated Motor Energy (E.M.E)" : "Steps";
    panel.series = {series("fast wall-follow (ours)", "#1e5bd8", false, 0, eme),
                    series("Sheng et al. (ours, no sweeping)", "#d81e1e", false, 1, eme),
                    series("frontier + sweeping (ours)", "#1b9e3a", false, 2, eme),
                    paper("fast wall-follow (paper)", "#1e5bd8", true, eme),
                    paper("Sheng et al. (paper)", "#d81e1e", false, eme)};
    fig.panels.push_back(std::move(panel));
  }
  fig.legend = fig.panels.front().series; // the same five series in both panels: one legend
  return fig;
}

void explore_stages_figure(std::uint64_t seed, const std::filesystem::path& svg,
                           const std::filesystem::path& png) {
  const kernel::Cell corner{0, 24};
  const auto grid = los::scattered_obstacles(25, 25, 5, seed, 1, corner);
  const auto pair = los::start_pair(grid, corner);
  const auto options = method_options(0);
  const auto total = los::explore(grid, pair[0], pair[1], options).steps;
  std::vector<std::uint64_t> at;
  for (std::uint64_t k = 1; k <= 5; ++k)
    at.push_back(std::max<std::uint64_t>(1, (total * k + 4) / 5));
  std::vector<GridPanel> panels;
  std::uint64_t tick = 0;
  const auto snapshot = [&](const los::TwoRobotWorld& world, const los::ExplorationMap& map) {
    GridPanel p;
    const char* stage = "ABCDE";
    p.title = std::string(1, stage[panels.size()]) + ": tick " + std::to_string(tick) + " of " +
              std::to_string(total);
    p.states = kernel::Grid<std::uint8_t>(map.states().width(), map.states().height(), 0);
    for (std::int32_t y = 0; y < p.states.height(); ++y)
      for (std::int32_t x = 0; x < p.states.width(); ++x)
        p.states[{x, y}] = static_cast<std::uint8_t>(map.at({x, y}));
    p.trails.resize(2);
    for (int r = 0; r < 2; ++r)
      for (const kernel::Cell c : world.trajectory(r))
        p.trails[static_cast<std::size_t>(r)].emplace_back(c.x + 0.5, c.y + 0.5);
    panels.push_back(std::move(p));
  };
  (void)los::explore(grid, pair[0], pair[1], options,
                     [&](const los::TwoRobotWorld& world, const los::ExplorationMap& map,
                         const los::TeamObservation&, const los::TeamCommand&) {
                       ++tick;
                       if (panels.size() < at.size() && tick == at[panels.size()])
                         snapshot(world, map);
                     });
  save_grid_figure(
      "Paper 001, Figure 4: fast wall-follow, stage by stage",
      "25 x 25 cells, five obstacles (Table 2, repetition 1, seed " + std::to_string(seed) +
          "); the shared map after 20, 40, 60, 80 and 100 % of the " + std::to_string(total) +
          " ticks.\nThe robots trace the walls first, then a frontier search with line-of-sight "
          "sweeping explores what is left.",
      panels, exploration_legend(), svg, png);
}

void save_exploration_figure(const std::string& algorithm, const los::ExploreResult& r,
                             const std::filesystem::path& svg, const std::filesystem::path& png) {
  GridPanel p;
  p.title = "after " + std::to_string(r.steps) + " steps";
  p.states = kernel::Grid<std::uint8_t>(r.cells.width(), r.cells.height(), 0);
  for (std::int32_t y = 0; y < r.cells.height(); ++y)
    for (std::int32_t x = 0; x < r.cells.width(); ++x)
      p.states[{x, y}] = static_cast<std::uint8_t>(r.cells[{x, y}]);
  p.trails.resize(2);
  for (std::size_t robot = 0; robot < 2; ++robot)
    for (const kernel::Cell cell : r.trajectories[robot])
      p.trails[robot].emplace_back(cell.x + 0.5, cell.y + 0.5);
  save_grid_figure(algorithm + " exploration (paper 001)",
                   std::to_string(r.cells.width()) + " x " + std::to_string(r.cells.height()) +
                       " cells; " + std::to_string(r.steps) + " steps, E.M.E " +
                       std::to_string(r.eme) + ", " + std::to_string(r.explored) +
                       " cells explored.",
                   {p}, exploration_legend(), svg, png);
}

std::array<std::filesystem::path, 4> write_explore_tables(const ExploreTables& t,
                                                          const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw kernel::InputError(dir.string(), "cannot make the directory");
  const std::array<std::filesystem::path, 4> files{dir / "table2.csv", dir / "table2.md",
                                                   dir / "table3.csv", dir / "table3.md"};
  io::write_file_atomic(files[0], table2_csv(t));
  io::write_file_atomic(files[1], table2_markdown(t));
  io::write_file_atomic(files[2], table3_csv(t));
  io::write_file_atomic(files[3], table3_markdown(t));
  return files;
}

} // namespace antkit::experiments
