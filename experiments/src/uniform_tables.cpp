#include <algorithm>
#include <antkit/experiments/uniform_tables.hpp>
#include <antkit/io/atomic_file.hpp>
#include <cstdio>
#include <sstream>

namespace antkit::experiments::uniform_tables {

std::vector<TablesRow> run_tables(const TablesConfig& c, const algorithms::Runner& runner) {
  const std::size_t per_row = c.runs;
  const auto payloads = algorithms::run_units(
      runner,
      c.sensor_model == SensorModel::Disk ? "paper 004, tables 1-4, disk sensor"
                                          : "paper 004, tables 1-4",
      kPaperTables.size() * per_row, [&](std::uint64_t k) {
        const auto t = detail::run_trial(c, kPaperTables[k / per_row],
                                         static_cast<std::uint32_t>(k % per_row));
        algorithms::Payload p;
        for (std::size_t a = 0; a < table_columns(c); ++a) {
          const auto& r = t.result[a];
          p.put(r.viewed);
          p.put(r.viewable);
          p.put(r.movements);
          p.put(r.moves);
          p.put(r.hash);
        }
        return p;
      });
  std::vector<TablesRow> rows;
  if (!runner.root()) return rows;
  for (std::size_t r = 0; r < kPaperTables.size(); ++r) {
    TablesRow row;
    row.paper = &kPaperTables[r];
    kernel::TraceHash digest;
    for (std::size_t a = 0; a < kTableColumns; ++a) row.coverage_min[a] = 100.0;
    for (std::size_t run = 0; run < per_row; ++run) {
      algorithms::Payload p = payloads[r * per_row + run];
      for (std::size_t a = 0; a < table_columns(c); ++a) {
        const auto viewed = p.get(), viewable = p.get(), movements = p.get(), moves = p.get(),
                   hash = p.get();
        const double cov =
            viewable == 0 ? 100.0
                          : 100.0 * static_cast<double>(viewed) / static_cast<double>(viewable);
        row.coverage[a] += cov;
        row.coverage_min[a] = std::min(row.coverage_min[a], cov);
        row.movements[a] += static_cast<double>(movements);
        row.moves[a] += static_cast<double>(moves);
        row.complete[a] += viewed == viewable;
        row.coverage_runs[a].push_back(cov);
        row.movements_runs[a].push_back(static_cast<double>(movements));
        digest.add_u64(hash);
      }
    }
    for (std::size_t a = 0; a < kTableColumns; ++a) {
      row.coverage[a] /= static_cast<double>(per_row);
      row.movements[a] /= static_cast<double>(per_row);
      row.moves[a] /= static_cast<double>(per_row);
    }
    row.hash = digest.finish();
    rows.push_back(row);
  }
  return rows;
}

std::string tables_csv(const std::vector<TablesRow>& rows, const TablesConfig& c) {
  const std::uint32_t runs = c.runs;
  std::ostringstream s;
  s << "table,density_percent,robots,algorithm,runs,coverage_mean,coverage_min,complete_runs,"
       "movements_mean,moves_mean,paper_coverage,paper_movements\n";
  for (const auto& row : rows)
    for (std::size_t a = 0; a < table_columns(c); ++a) {
      const auto& p = *row.paper;
      s << p.table << ',' << p.density_percent << ',' << p.robots << ','
        << algorithm_name(kTableAlgorithms[a]) << ',' << runs << ',' << fixed(row.coverage[a], 2)
        << ',' << fixed(row.coverage_min[a], 2) << ',' << row.complete[a] << ','
        << fixed(row.movements[a], 1) << ',' << fixed(row.moves[a], 1) << ','
        << (a < 3 ? fixed(p.coverage[a], 2) : "") << ',' << (a < 3 ? fixed(p.movements[a], 1) : "")
        << '\n';
    }
  return s.str();
}

std::string tables_markdown(const std::vector<TablesRow>& rows, const TablesConfig& c) {
  std::ostringstream s;
  s << "# Paper 004, Tables 1-4: ours beside the paper's\n\n"
    << c.width << " x " << c.height << " cells, sensor distance " << c.sensor << ", " << c.runs
    << " runs per row (trials 0.." << c.runs - 1 << ", seed " << c.seed
    << "). Each cell: ours / paper. Coverage in % of viewable free cells, movements in ticks. RW "
       "runs as many ticks as A* took on the same map.\n";
  if (c.sensor_model == SensorModel::Disk)
    s << "\nSensor model: disk (every cell within the sensor distance is viewed, through walls; "
         "not the paper's model, a test of it).\n";
  for (int table = 1; table <= 4; ++table) {
    const TablesRow* first = nullptr;
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
      for (std::size_t a = 3; a < kTableColumns; ++a)
        s << " | " << (a < table_columns(c) ? fixed(r.coverage[a], 2) : "not run") << " | "
          << (a < table_columns(c) ? fixed(r.movements[a], 1) : "not run");
      s << " |\n";
    }
  }
  if (table_columns(c) < kTableColumns) return s.str();
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

Figure tables_plot(const std::vector<TablesRow>& rows, const TablesConfig& c) {
  Figure fig;
  fig.title = "Paper 004: coverage against movements, RW, PM and A*";
  fig.x_label = "movements (ticks, log axis)";
  // Movements span 100 to 5 000: on a log axis PM's short runs are not crowded into one corner.
  fig.x_axis = Axis::Log;
  fig.y_label = "coverage, % of viewable free cells";
  fig.y_from_zero = true;
  fig.caption = "Filled, joined: ours, mean of " + std::to_string(c.runs) + " runs per point (" +
                std::to_string(c.width) + " x " + std::to_string(c.height) + " cells, sensor " +
                std::to_string(c.sensor) +
                "); open: the paper's Tables 1-4.\nThe number beside a point is its robot count "
                "(1-4; more robots, fewer movements each).";
  // Four panels in two rows, one legend for all of them.
  fig.columns = 2;
  const char* colours[] = {"#d81e1e", "#1b9e3a", "#1e5bd8"};
  const char* names[] = {"RW", "PM", "A*"};
  for (std::size_t a = 0; a < 3; ++a) {
    fig.legend.push_back({std::string(names[a]) + " (ours)", colours[a], false, false, {}});
    fig.legend.push_back({std::string(names[a]) + " (paper)", colours[a], false, true, {}});
  }
  for (const int density : {30, 20, 10, 0}) {
    PlotPanel panel;
    panel.title = std::to_string(density) + " % obstacles";
    for (std::size_t a = 0; a < 3; ++a) {
      PlotSeries ours{std::string(names[a]) + " (ours)", colours[a], false, false, {}};
      PlotSeries paper{std::string(names[a]) + " (paper)", colours[a], false, true, {}};
      for (const auto& r : rows) {
        if (r.paper->density_percent != density) continue;
        const std::string robots = std::to_string(r.paper->robots);
        ours.points.push_back({r.movements[a], r.coverage[a], std::nullopt, std::nullopt, robots});
        paper.points.push_back(
            {r.paper->movements[a], r.paper->coverage[a], std::nullopt, std::nullopt, robots});
      }
      panel.series.push_back(std::move(ours));
      panel.series.push_back(std::move(paper));
    }
    fig.panels.push_back(std::move(panel));
  }
  return fig;
}

TablesSummary tables_summary(const std::vector<TablesRow>& rows, const TablesConfig& c) {
  TablesSummary s;
  kernel::TraceHash digest;
  for (const auto& r : rows) {
    digest.add_u64(r.hash);
    TablesSummaryRow row;
    row.density_percent = r.paper->density_percent;
    row.robots = r.paper->robots;
    for (std::size_t a = 0; a < table_columns(c); ++a)
      row.columns.push_back({kTableAlgorithms[a], std::stod(fixed(r.coverage[a], 2)),
                             std::stod(fixed(r.movements[a], 1)), std::stod(fixed(r.moves[a], 1))});
    s.rows.push_back(std::move(row));
  }
  s.hash = digest.finish();
  return s;
}

TablesSummary write_tables(const std::vector<TablesRow>& rows, const TablesConfig& c,
                           const std::filesystem::path& dir) {
  const auto csv = dir / "uniform_tables.csv";
  const auto md = dir / "uniform_tables.md";
  io::write_file_atomic(csv, tables_csv(rows, c));
  io::write_file_atomic(md, tables_markdown(rows, c));
  TablesSummary s = tables_summary(rows, c);
  s.csv = csv;
  s.markdown = md;
  return s;
}

} // namespace antkit::experiments::uniform_tables
