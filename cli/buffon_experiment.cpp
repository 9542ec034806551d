// `antkit buffon-experiment --figure 5|6|7|8|9|14 --out DIR [--trials N] [--steps N] [--seed S]
//                           [--threads T]`: the paper's (000) Figures 5-9 and 14 as CSV and SVG.
//
// Each figure is a list of (series, x, arena spec, trail width); every arena gets `trials` default
// trials (Section 5: 50 000 steps per visit, w = 0.1) and one CSV row with the median and
// interquartile range of nBC (the paper's statistics), the arena's exact area, the median
// closed-form area and the median blocked-step count. Files: DIR/figure<N>.csv and
// DIR/figure<N>.svg (median nBC with IQR bars against x, one colour per series), written
// atomically. Streams: trial t of arena k of figure f uses experiment 4000 + 100 f + k, so every
// arena's trials are independent and reproducible on their own.
//
// Choices where the paper is silent: Figure 5's squares are "square:d=D" (the square of the area of
// the D circle); Figure 6's ellipses have the standard area and e = 0.968, 0.994, 0.998, drawn
// against compactness r1/r2 = 1/sqrt(1 - e^2) (1 for the circle); Figure 7's barrier lengths are
// 10..80 % of the diameter in steps of 10; Figure 9's widths are 0.05, 0.1, 0.2, 0.4 over the ten
// circles. Figure 14: see run_figure14. The plot's colours cycle after eight series.
#include "buffon_options.hpp"
#include "commands.hpp"
#include "output.hpp"
#include "svg.hpp"

#include <antkit/buffon/checkpoints.hpp>
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/experiments/calibration.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/atomic_file.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/kernel/input_error.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace {

using antkit::kernel::InputError;
namespace buffon = antkit::buffon;
namespace geometry = antkit::geometry;

struct ExperimentCommand {
  int figure = 5;
  std::string out;
  std::int64_t trials = 100;
  std::int64_t steps = buffon::kDefaultSteps;
  std::uint64_t seed = 1;
  std::int64_t threads = 2;
};

struct Point {
  std::string series;
  double x;
  std::string spec;
  double width;
};

std::string num(double v) {
  std::ostringstream s;
  s << std::setprecision(10) << v;
  return s.str();
}

std::vector<Point> figure_points(int figure) {
  std::vector<Point> pts;
  const double diameters[] = {10, 20, 30, 40, 50, 60, 70, 80, 90, 100};
  switch (figure) {
  case 5:
    for (double d : diameters) pts.push_back({"circle", d, "circle:d=" + num(d), 0.1});
    for (double d : diameters) pts.push_back({"square", d, "square:d=" + num(d), 0.1});
    break;
  case 6:
    pts.push_back({"standard", 1, "standard", 0.1});
    for (double e : {0.968, 0.994, 0.998})
      pts.push_back({"ellipse", 1 / std::sqrt(1 - e * e), "ellipse:area=7854,e=" + num(e), 0.1});
    break;
  case 7:
    pts.push_back({"none", 0, "standard", 0.1});
    for (int k = 1; k <= 8; ++k) {
      pts.push_back({"barrier-i", 10.0 * k, "barrier-i:len=" + num(0.1 * k), 0.1});
      pts.push_back({"barrier-plus", 10.0 * k, "barrier-plus:len=" + num(0.1 * k), 0.1});
    }
    break;
  case 8: {
    double x = 0;
    for (const char* s : {"standard", "ring", "plus", "obstacles"}) pts.push_back({s, x++, s, 0.1});
    break;
  }
  case 9:
    for (double w : {0.05, 0.1, 0.2, 0.4})
      for (double d : diameters) pts.push_back({"w=" + num(w), d, "circle:d=" + num(d), w});
    break;
  default:
    break;
  }
  return pts;
}

struct Row {
  Point p;
  double area = 0, nbc_median = 0, nbc_q1 = 0, nbc_q3 = 0, closed_form_median = 0, blocked = 0;
};

void write_plot(const std::filesystem::path& path, const std::string& title,
                const std::vector<Row>& rows) {
  double xmin = 1e300, xmax = -1e300, ymax = 0;
  for (const auto& r : rows) {
    xmin = std::min(xmin, r.p.x);
    xmax = std::max(xmax, r.p.x);
    ymax = std::max(ymax, r.nbc_q3);
  }
  if (xmax <= xmin) xmax = xmin + 1;
  if (ymax <= 0) ymax = 1;
  // Plot space: x in [0, 100], y in [0, 60] after scaling, with margins for labels.
  const double W = 100, H = 60;
  antkit::cli::Svg svg(-12, -8, W + 4, H + 6, 8.0, false);
  auto X = [&](double x) { return (x - xmin) / (xmax - xmin) * W; };
  auto Y = [&](double y) { return y / ymax * H; };
  svg.line(0, 0, W, 0, "#000000", 1);
  svg.line(0, 0, 0, H, "#000000", 1);
  for (int k = 0; k <= 4; ++k) {
    svg.text(-11, Y(ymax * k / 4), num(std::round(ymax * k / 4 * 1000) / 1000), 10);
    svg.text(X(xmin + (xmax - xmin) * k / 4) - 2, -4, num(xmin + (xmax - xmin) * k / 4), 10);
  }
  svg.text(20, H + 3, title, 14);
  const char* colours[] = {"#1e5bd8", "#d81e1e", "#1b9e3a", "#e08a00",
                           "#7b3fb5", "#00a0a0", "#a0a000", "#606060"};
  std::vector<std::string> series;
  for (const auto& r : rows)
    if (std::find(series.begin(), series.end(), r.p.series) == series.end())
      series.push_back(r.p.series);
  for (std::size_t s = 0; s < series.size(); ++s) {
    const std::string colour = colours[s % 8];
    std::vector<std::pair<double, double>> line;
    for (const auto& r : rows) {
      if (r.p.series != series[s]) continue;
      svg.line(X(r.p.x), Y(r.nbc_q1), X(r.p.x), Y(r.nbc_q3), colour, 1);
      svg.circle(X(r.p.x), Y(r.nbc_median), 0.6, colour);
      line.emplace_back(X(r.p.x), Y(r.nbc_median));
    }
    svg.polyline(line, colour, 1, 0.6);
    svg.text(W - 25, H - 4 - 4 * static_cast<double>(s), series[s], 12);
    svg.line(W - 29, H - 4.5 - 4 * static_cast<double>(s), W - 26,
             H - 4.5 - 4 * static_cast<double>(s), colour, 2);
  }
  svg.save(path);
}

// Figure 14 (Section 8.1): calibrated Buffon estimates and RS estimates against total trail length
// for the circles of diameter 40, 60, 80, 100, calibrated on 30, 50, 70, 90. Checkpoints every 168
// units of each visit (total 336 k, k = 1..10). The fit uses the calibration arenas' median nBC at
// the same checkpoint; each trial of a test arena then gives one estimate. CSV columns: diameter,
// total_length, area, buffon_median/q1/q3, rs_median/q1/q3, fit_a, fit_b, fit_c. The SVG shows
// estimate / true area (1 is exact): Buffon and RS medians with IQR bars.
void run_figure14(const ExperimentCommand& c) {
  constexpr int K = 10;
  const std::int64_t step_raw = std::int64_t{168} * 65536;
  std::vector<buffon::Figure14Arena> arenas;
  for (int d = 30; d <= 100; d += 10) {
    const auto arena = geometry::build_arena_spec("circle:d=" + std::to_string(d), "figure").arena;
    const buffon::World world(arena.walls_fx());
    buffon::TrialParams params;
    params.seed = c.seed;
    params.experiment = 4000 + 100 * 14 + static_cast<std::uint64_t>(d);
    params.steps = c.steps;
    std::vector<buffon::CheckpointResult> results(static_cast<std::size_t>(c.trials));
    buffon::parallel_for(results.size(), static_cast<unsigned>(c.threads), [&](std::uint64_t t) {
      results[t] = buffon::run_checkpoints(world, params, t, step_raw, K);
    });
    buffon::Figure14Arena a{static_cast<double>(d), arena.area(), {}, {}};
    for (const auto& r : results) buffon::add_checkpoints(a, r);
    arenas.push_back(std::move(a));
    std::cerr << "figure 14: circle d=" << d << " done\n";
  }
  std::ostringstream csv;
  csv << "diameter,total_length,area,buffon_median,buffon_q1,buffon_q3,rs_median,rs_q1,rs_q3,"
         "fit_a,fit_b,fit_c\n";
  std::vector<Row> plot;
  for (std::size_t k = 0; k < K; ++k) {
    const auto fit = buffon::calibrate_at(arenas, k);
    const double total = 2.0 * 168.0 * static_cast<double>(k + 1);
    for (const auto& a : arenas) {
      if (buffon::is_calibration_diameter(a.diameter)) continue;
      const std::vector<double> est = buffon::estimates_at(a, k, fit);
      const double bm = buffon::quantile(est, 0.5), b1 = buffon::quantile(est, 0.25),
                   b3 = buffon::quantile(est, 0.75);
      const double rm = buffon::quantile(a.rs[k], 0.5), r1 = buffon::quantile(a.rs[k], 0.25),
                   r3 = buffon::quantile(a.rs[k], 0.75);
      csv << num(a.diameter) << ',' << num(total) << ',' << num(a.area) << ',' << num(bm) << ','
          << num(b1) << ',' << num(b3) << ',' << num(rm) << ',' << num(r1) << ',' << num(r3) << ','
          << num(fit.a) << ',' << num(fit.b) << ',' << num(fit.c) << '\n';
      const std::string d = num(a.diameter);
      plot.push_back(Row{Point{"buffon d=" + d, total, "", 0.1}, a.area, bm / a.area, b1 / a.area,
                         b3 / a.area, 0, 0});
      plot.push_back(Row{Point{"rs d=" + d, total, "", 0.1}, a.area, rm / a.area, r1 / a.area,
                         r3 / a.area, 0, 0});
    }
  }
  const std::filesystem::path dir(c.out);
  geometry::write_file_atomic(dir / "figure14.csv", csv.str());
  write_plot(dir / "figure14.svg", "Figure 14: estimate / area against total trail length", plot);
  std::cout << (dir / "figure14.csv").string() << '\n' << (dir / "figure14.svg").string() << '\n';
}

void run(const ExperimentCommand& c) {
  const auto points = figure_points(c.figure);
  if (points.empty() && c.figure != 14)
    throw InputError("--figure", "the figure must be 5, 6, 7, 8, 9 or 14");
  antkit::cli::check_buffon_run_size(c.trials, c.steps, c.threads);
  if (c.out.empty()) throw InputError("--out", "give an output directory");
  std::filesystem::create_directories(c.out);
  if (c.figure == 14) return run_figure14(c);

  const auto start = std::chrono::steady_clock::now();
  std::vector<Row> rows;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto& p = points[k];
    const auto arena = geometry::build_arena_spec(p.spec, "figure").arena;
    const buffon::World world(arena.walls_fx());
    buffon::TrialParams params;
    params.seed = c.seed;
    params.experiment = 4000 + 100 * static_cast<std::uint64_t>(c.figure) + k;
    params.steps = c.steps;
    params.width = geometry::fixed_from_double<antkit::kernel::Fx>(p.width, "--width");
    const auto results = buffon::run_trials(world, params, static_cast<std::uint64_t>(c.trials),
                                            static_cast<unsigned>(c.threads));
    std::vector<double> nbc, cf, blocked;
    for (const auto& r : results) {
      const double l1 = static_cast<double>(r.length1_raw) / 65536.0;
      const double l2 = static_cast<double>(r.length2_raw) / 65536.0;
      nbc.push_back(l2 > 0 ? static_cast<double>(r.bc) / l2 : 0.0);
      if (auto a = buffon::closed_form_area(l1, l2, r.crossings_exact).area) cf.push_back(*a);
      blocked.push_back(static_cast<double>(r.blocked));
    }
    Row row{p,
            arena.area(),
            buffon::quantile(nbc, 0.5),
            buffon::quantile(nbc, 0.25),
            buffon::quantile(nbc, 0.75),
            buffon::quantile(cf, 0.5),
            buffon::quantile(blocked, 0.5)};
    rows.push_back(row);
    std::cerr << "figure " << c.figure << ": " << p.spec << " w=" << p.width
              << " nbc median=" << row.nbc_median << '\n';
  }
  std::ostringstream csv;
  csv << "series,x,arena,width,area,trials,nbc_median,nbc_q1,nbc_q3,area_closed_form_median,"
         "blocked_median\n";
  for (const auto& r : rows)
    csv << r.p.series << ',' << num(r.p.x) << ",\"" << r.p.spec << "\"," << num(r.p.width) << ','
        << num(r.area) << ',' << c.trials << ',' << num(r.nbc_median) << ',' << num(r.nbc_q1) << ','
        << num(r.nbc_q3) << ',' << num(r.closed_form_median) << ',' << num(r.blocked) << '\n';
  const std::filesystem::path dir(c.out);
  const std::string stem = "figure" + std::to_string(c.figure);
  geometry::write_file_atomic(dir / (stem + ".csv"), csv.str());
  write_plot(dir / (stem + ".svg"), "Figure " + std::to_string(c.figure) + ": median nBC, IQR bars",
             rows);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "figure " << c.figure << ": " << rows.size() << " arenas x " << c.trials
            << " trials in " << seconds << " s\n";
  std::cout << (dir / (stem + ".csv")).string() << '\n' << (dir / (stem + ".svg")).string() << '\n';
}

void register_buffon_experiment(CLI::App& app) {
  auto options = std::make_shared<ExperimentCommand>();
  auto* sub =
      app.add_subcommand("buffon-experiment", "Paper 000's Figures 5-9 and 14 as CSV and SVG");
  sub->add_option("--figure", options->figure, "5, 6, 7, 8, 9 or 14")->required();
  sub->add_option("--out", options->out, "Output directory")->required();
  sub->add_option("--trials", options->trials, "Trials per arena (default 100)");
  sub->add_option("--steps", options->steps, "Steps per visit (default 50000)");
  sub->add_option("--seed", options->seed, "Seed of the keyed streams (default 1)");
  sub->add_option("--threads", options->threads, "Worker threads (default 2)");
  sub->callback([options] { run(*options); });
}

const antkit::cli::Registration reg{"buffon-experiment", &register_buffon_experiment};

} // namespace
