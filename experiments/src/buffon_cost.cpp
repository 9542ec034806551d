// The cost of precision: the sweep, its tables and its figure (buffon_cost.hpp).
#include <antkit/buffon/world.hpp>
#include <antkit/experiments/buffon_cost.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>
#include <utility>

namespace antkit::experiments {

std::vector<BuffonCostArena> buffon_cost_arenas(bool quick) {
  // Circles d = 20, 40, 80, 120, 200 and squares of the same areas: 314 to 31 416 unit^2.
  std::vector<BuffonCostArena> arenas;
  const std::vector<int> diameters =
      quick ? std::vector<int>{20, 40, 80} : std::vector<int>{20, 40, 80, 120, 200};
  for (const int d : diameters) {
    arenas.push_back({"circle:d=" + std::to_string(d), "circle"});
    const double area = 3.14159265358979323846 * d * d / 4;
    arenas.push_back({"square:area=" + number(std::round(area)), "square"});
  }
  if (!quick)
    for (const char* s : {"ellipse:area=7854,e=0.968", "barrier-i:len=0.4", "barrier-plus:len=0.4",
                          "ring", "plus", "obstacles"})
      arenas.push_back({s, "figure 3 shape"});
  return arenas;
}

void validate(const BuffonCostParams& params) {
  if (params.trials && (*params.trials < 1 || *params.trials > 100000))
    throw kernel::InputError("trials", "the number of trials must be in [1, 100000]");
  if (params.budget < 2 || params.budget > 100000000)
    throw kernel::InputError("step budget", "the budget per trial must be in [2, 100000000]");
}

BuffonCost run_buffon_cost(const BuffonCostParams& params, const algorithms::Runner& runner) {
  validate(params);
  std::vector<std::unique_ptr<buffon::World>> worlds;
  std::vector<buffon::CostArena> arenas;
  for (const auto& [spec, family] : buffon_cost_arenas(params.quick)) {
    const auto arena = geometry::build_arena_spec(spec, "arena").arena;
    worlds.push_back(std::make_unique<buffon::World>(arena.walls_fx()));
    // The exponent is fitted over the area sweep (circles and squares); the other shapes, all at
    // one area, are drawn beside it.
    arenas.push_back({spec, family, arena.area(), worlds.back().get(), family != "figure 3 shape"});
  }
  BuffonCost out;
  out.params = params;
  out.run.trials = params.trials ? *params.trials : (params.quick ? 3 : 9);
  out.run.seed = params.seed;
  out.run.budget = params.budget;
  if (params.quick) out.run.precisions = {200000, 100000};
  out.table = buffon::precision_cost(arenas, out.run, runner);
  return out;
}

namespace {
std::string optional_number(const std::optional<double>& v) {
  return v ? number(*v) : std::string();
}
} // namespace

std::string buffon_cost_csv(const BuffonCost& c) {
  std::ostringstream csv;
  csv << "arena,family,area,precision,method,trials,reached,median,q1,q3\n";
  for (const auto& p : c.table.points)
    csv << '"' << p.arena << "\"," << p.family << ',' << number(p.area) << ','
        << number(p.precision_millionths / 1e6) << ',' << buffon::cost_method_name(p.method) << ','
        << p.trials << ',' << p.reached << ',' << optional_number(p.median) << ','
        << optional_number(p.q1) << ',' << optional_number(p.q3) << '\n';
  return csv.str();
}

std::string buffon_cost_fits_csv(const BuffonCost& c) {
  std::ostringstream fits;
  fits << "method,precision,exponent,coefficient,points\n";
  for (const auto& f : c.table.fits)
    fits << buffon::cost_method_name(f.method) << ',' << number(f.precision_millionths / 1e6) << ','
         << number(f.exponent) << ',' << number(f.coefficient) << ',' << f.points << '\n';
  return fits.str();
}

Figure buffon_cost_plot(const BuffonCost& c) {
  Figure figure;
  figure.x_axis = figure.y_axis = Axis::Log;
  figure.title = "The cost of precision: median total trail to reach P, against area";
  figure.x_label = "arena area (unit^2, robot diameter = 1)";
  figure.y_label = "median total trail length to reach P (units)";
  figure.caption = std::to_string(c.run.trials) +
                   " trials per point, bars: interquartile range, exponents fitted on circles and "
                   "squares, seed " +
                   std::to_string(c.params.seed) +
                   ".\nBuffon stops on its own rule; RS when its estimate is within P of the true "
                   "area (an oracle: RS has no rule).";
  const std::vector<std::pair<buffon::CostMethod, std::string>> colours = {
      {buffon::CostMethod::markers, "#1f5fbf"},
      {buffon::CostMethod::online, "#2a9d3a"},
      {buffon::CostMethod::rs, "#c8321e"}};
  for (const std::uint32_t p : c.run.precisions) {
    PlotPanel panel;
    panel.title = "P = " + number(p / 1e6);
    std::ostringstream note;
    note << "fit trail ~ A^e:";
    for (const auto& f : c.table.fits)
      if (f.precision_millionths == p)
        note << (f.method == buffon::CostMethod::markers ? " " : ", ")
             << buffon::cost_method_name(f.method) << ' ' << std::fixed << std::setprecision(2)
             << f.exponent;
    panel.note = note.str();
    for (const auto& [method, colour] : colours) {
      for (const char* family : {"circle", "square", "figure 3 shape"}) {
        PlotSeries s;
        s.colour = colour;
        s.dashed = std::string(family) == "square";
        s.hollow = std::string(family) == "figure 3 shape";
        s.name = std::string(buffon::cost_method_name(method)) + ": " + family;
        for (const auto& point : c.table.points)
          if (point.method == method && point.precision_millionths == p && point.family == family &&
              point.median)
            s.points.push_back({point.area, *point.median, point.q1, point.q3});
        if (!s.points.empty()) panel.series.push_back(std::move(s));
      }
    }
    figure.panels.push_back(std::move(panel));
  }
  // One legend for the panels: colour is the method, style the arena family (filled column by
  // column, two rows: the methods on the first, the families on the second).
  figure.legend = {{"Buffon, two markers", "#1f5fbf", false, false, {}},
                   {"circles (solid)", "#555555", false, false, {}},
                   {"Buffon, online first visit", "#2a9d3a", false, false, {}},
                   {"squares (dashed)", "#555555", true, false, {}},
                   {"RS coverage", "#c8321e", false, false, {}},
                   {"Figure 3 shapes, 7854 (open)", "#555555", false, true, {}}};
  return figure;
}

std::array<std::filesystem::path, 4> write_buffon_cost(const BuffonCost& c,
                                                       const std::filesystem::path& dir) {
  const std::array<std::filesystem::path, 4> files = {
      dir / "precision_cost.csv", dir / "precision_cost_fits.csv", dir / "precision_cost.svg",
      dir / "precision_cost.png"};
  save_figure(buffon_cost_plot(c), files[2], files[3]);
  io::write_file_atomic(files[0], buffon_cost_csv(c));
  io::write_file_atomic(files[1], buffon_cost_fits_csv(c));
  return files;
}

} // namespace antkit::experiments
