// `antkit buffon-cost`: the cost of precision (issue 17; algorithms/buffon/precision_cost.hpp).
//
//   antkit buffon-cost --out DIR [--quick] [--trials N] [--seed S] [--threads T]
//                      [--max-steps N]
//
// The median total trail length that Buffon with two markers, Buffon with the online first visit
// and the RS coverage baseline need to reach P = 0.2, 0.1 and 0.05, on circles and squares of
// 314 to 31 416 unit^2 and the other shapes of paper 000's Figure 3 at their standard area, with
// the fitted exponent of trail ~ area^e per method and P (over the circles and squares). Writes
// DIR/precision_cost.csv (one row per arena, P and method: arena, family, area, precision, method,
// trials, reached, median, q1, q3), DIR/precision_cost_fits.csv (method, precision, exponent,
// coefficient, points), DIR/precision_cost.svg and .png (one panel per P, log-log, interquartile
// bars, a legend), and prints the fits. --quick: circles and squares of 314, 1 257 and 5 027 only,
// P = 0.2 and 0.1, 3 trials (for tests and a first look; the full run takes minutes). Progress on
// stderr.
#include "commands.hpp"
#include "output.hpp"

#include <antkit/buffon/precision_cost.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/experiments/plot.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using antkit::kernel::InputError;
namespace buffon = antkit::buffon;
namespace geometry = antkit::geometry;

struct CostCommand {
  std::string out;
  bool quick = false;
  std::int64_t trials = 0; // given with --trials; else 9, or 3 with --quick
  bool trials_given = false;
  std::uint64_t seed = 1;
  std::int64_t threads = 1;
  std::int64_t max_steps = 40000000;
};

std::string num(double v) {
  std::ostringstream s;
  s << std::setprecision(10) << v;
  return s.str();
}

std::string opt(const std::optional<double>& v) {
  return v ? num(*v) : std::string();
}

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

  // Circles d = 20, 40, 80, 120, 200 and squares of the same areas: 314 to 31 416 unit^2.
  std::vector<std::pair<std::string, std::string>> specs;
  const std::vector<int> diameters =
      c.quick ? std::vector<int>{20, 40, 80} : std::vector<int>{20, 40, 80, 120, 200};
  for (const int d : diameters) {
    specs.emplace_back("circle:d=" + std::to_string(d), "circle");
    const double area = 3.14159265358979323846 * d * d / 4;
    specs.emplace_back("square:area=" + num(std::round(area)), "square");
  }
  if (!c.quick)
    for (const char* s : {"ellipse:area=7854,e=0.968", "barrier-i:len=0.4", "barrier-plus:len=0.4",
                          "ring", "plus", "obstacles"})
      specs.emplace_back(s, "figure 3 shape");
  std::vector<std::unique_ptr<buffon::World>> worlds;
  std::vector<buffon::CostArena> arenas;
  for (const auto& [spec, family] : specs) {
    const auto arena = geometry::build_arena_spec(spec, "arena").arena;
    worlds.push_back(std::make_unique<buffon::World>(arena.walls_fx()));
    // The exponent is fitted over the area sweep (circles and squares); the other shapes, all at
    // one area, are drawn beside it.
    arenas.push_back({spec, family, arena.area(), worlds.back().get(), family != "figure 3 shape"});
  }
  buffon::CostParams params;
  params.trials = static_cast<std::uint64_t>(c.trials_given ? c.trials : (c.quick ? 3 : 9));
  params.seed = c.seed;
  params.threads = static_cast<unsigned>(c.threads);
  params.budget = c.max_steps;
  if (c.quick) params.precisions = {200000, 100000};

  const auto start = std::chrono::steady_clock::now();
  const bool tty = ::isatty(2) != 0;
  const auto table =
      buffon::precision_cost(arenas, params, [&](std::size_t done, std::size_t total) {
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double eta = s / static_cast<double>(done) * static_cast<double>(total - done);
        std::cerr << (tty ? "\r" : "") << "buffon-cost: " << done << "/" << total << " points, "
                  << std::fixed << std::setprecision(0) << s << " s, about " << eta << " s left"
                  << std::defaultfloat << std::setprecision(6) << (tty ? "   " : "\n")
                  << std::flush;
      });
  if (tty) std::cerr << '\n';

  std::ostringstream csv, fits;
  csv << "arena,family,area,precision,method,trials,reached,median,q1,q3\n";
  for (const auto& p : table.points)
    csv << '"' << p.arena << "\"," << p.family << ',' << num(p.area) << ','
        << num(p.precision_millionths / 1e6) << ',' << buffon::cost_method_name(p.method) << ','
        << p.trials << ',' << p.reached << ',' << opt(p.median) << ',' << opt(p.q1) << ','
        << opt(p.q3) << '\n';
  fits << "method,precision,exponent,coefficient,points\n";
  for (const auto& f : table.fits)
    fits << buffon::cost_method_name(f.method) << ',' << num(f.precision_millionths / 1e6) << ','
         << num(f.exponent) << ',' << num(f.coefficient) << ',' << f.points << '\n';

  // The figure: one panel per P; per method a line over the circles, a dashed line over the
  // squares and open markers for the other shapes.
  antkit::experiments::Figure figure;
  figure.x_axis = figure.y_axis = antkit::experiments::Axis::Log;
  figure.title = "The cost of precision: median total trail to reach P, against area";
  figure.x_label = "arena area (unit^2, robot diameter = 1)";
  figure.y_label = "median total trail length to reach P (units)";
  figure.caption = std::to_string(params.trials) +
                   " trials per point, bars: interquartile range, exponents fitted on circles and "
                   "squares, seed " +
                   std::to_string(c.seed) +
                   ".\nBuffon stops on its own rule; RS when its estimate is within P of the true "
                   "area (an oracle: RS has no rule).";
  const std::vector<std::pair<buffon::CostMethod, std::string>> colours = {
      {buffon::CostMethod::markers, "#1f5fbf"},
      {buffon::CostMethod::online, "#2a9d3a"},
      {buffon::CostMethod::rs, "#c8321e"}};
  for (const std::uint32_t p : params.precisions) {
    antkit::experiments::PlotPanel panel;
    panel.title = "P = " + num(p / 1e6);
    std::ostringstream note;
    note << "fit trail ~ A^e:";
    for (const auto& f : table.fits)
      if (f.precision_millionths == p)
        note << (f.method == buffon::CostMethod::markers ? " " : ", ")
             << buffon::cost_method_name(f.method) << ' ' << std::fixed << std::setprecision(2)
             << f.exponent;
    panel.note = note.str();
    for (const auto& [method, colour] : colours) {
      for (const char* family : {"circle", "square", "figure 3 shape"}) {
        antkit::experiments::PlotSeries s;
        s.colour = colour;
        s.dashed = std::string(family) == "square";
        s.hollow = std::string(family) == "figure 3 shape";
        s.name = std::string(buffon::cost_method_name(method)) + ": " + family;
        for (const auto& point : table.points)
          if (point.method == method && point.precision_millionths == p && point.family == family &&
              point.median)
            s.points.push_back({point.area, *point.median, point.q1, point.q3});
        if (!s.points.empty()) panel.series.push_back(std::move(s));
      }
    }
    // Colour is the method, style the arena family.
    panel.legend = {{"Buffon, two markers", "#1f5fbf", false, false, {}},
                    {"Buffon, online first visit", "#2a9d3a", false, false, {}},
                    {"RS coverage", "#c8321e", false, false, {}},
                    {"circles (solid)", "#555555", false, false, {}},
                    {"squares (dashed)", "#555555", true, false, {}},
                    {"Figure 3 shapes, 7854 (open)", "#555555", false, true, {}}};
    figure.panels.push_back(std::move(panel));
  }
  const std::filesystem::path dir(c.out);
  try {
    antkit::experiments::save_figure(figure, dir / "precision_cost.svg",
                                     dir / "precision_cost.png");
  } catch (...) {
    antkit::experiments::release_drawing_caches();
    throw;
  }
  antkit::experiments::release_drawing_caches();
  geometry::write_file_atomic(dir / "precision_cost.csv", csv.str());
  geometry::write_file_atomic(dir / "precision_cost_fits.csv", fits.str());

  std::cout << "method   P      exponent  coefficient  points\n";
  for (const auto& f : table.fits)
    std::cout << std::left << std::setw(9) << buffon::cost_method_name(f.method) << std::setw(7)
              << num(f.precision_millionths / 1e6) << std::setw(10)
              << num(std::round(f.exponent * 1000) / 1000) << std::setw(13) << num(f.coefficient)
              << f.points << '\n';
  for (const char* name : {"precision_cost.csv", "precision_cost_fits.csv", "precision_cost.svg",
                           "precision_cost.png"})
    std::cout << (dir / name).string() << '\n';
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
