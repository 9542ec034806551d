// The marker-floor robot under trouble (experiments/stc_floor.hpp).
#include <antkit/devices/stc_floor/floor.hpp>
#include <antkit/devices/stc_floor/pilot.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/plot.hpp>
#include <antkit/experiments/stc_floor.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/uniform/scenario.hpp>
#include <sstream>

namespace antkit::experiments {

namespace {

namespace sf = devices::stc_floor;
using kernel::OccupancyGrid;

// A board of cells x cells cells with `percent` % of its sub-cells blocked (exactly that many,
// uniform::random_obstacles: the keyed maps of paper 004 and of paper 002's tours).
OccupancyGrid board(std::int32_t cells, std::uint32_t percent, std::uint64_t seed,
                    std::uint64_t trial) {
  return uniform::random_obstacles(2 * cells, 2 * cells, percent * 10000, seed, trial);
}

struct RunOutcome {
  std::int64_t reachable = 0, covered = 0, repeats = 0, max_offset = 0, clock_ms = 0;
  bool exact = false;
  std::uint64_t hash = 0;
};

RunOutcome run_one(const OccupancyGrid& map, const sf::FloorOptions& f, bool calibrate) {
  RunOutcome out;
  const auto start = stc::default_start(map, stc::Variant::AntEdge);
  if (!start) return out;
  out.reachable = stc::reachable_subcells(map, *start, stc::Variant::AntEdge);
  sf::FloorWorld world(map, *start, 1, f);
  sf::SimulatedRobot robot(world);
  static const sf::Calibration calibration = sf::ideal_calibration();
  static const sf::View view(calibration, sf::default_view(calibration));
  sf::PilotOptions o;
  o.start = *start;
  o.max_steps = 4 * out.reachable + 16;
  if (!calibrate) o.tolerance = std::int64_t{1} << 40;
  const auto r = sf::run_pilot(robot, view, o);
  out.covered = world.covered();
  out.repeats = world.repeats();
  out.max_offset = world.max_offset();
  out.clock_ms = world.clock_ms();
  out.exact = r.closed && out.covered == out.reachable && out.repeats == 0;
  out.hash = stc::tour_hash(map.width(), map.height(), world.path());
  return out;
}

struct Level {
  std::string factor;
  std::int64_t level;
};

} // namespace

FloorCurves run_floor_curves(const FloorParams& p, const algorithms::Runner& runner) {
  FloorCurves c;
  c.params = p;
  std::vector<Level> levels;
  for (const auto v : p.noise) levels.push_back({"noise", v});
  for (const auto v : p.fade_s) levels.push_back({"fade", v});
  for (const auto v : p.drift) levels.push_back({"drift", v});
  for (const auto v : p.drift) levels.push_back({"drift-uncalibrated", v});
  const auto trials = static_cast<std::uint64_t>(p.trials);
  const auto payloads = algorithms::run_units(
      runner, "stc floor curves", levels.size() * trials, [&](std::uint64_t unit) {
        const Level& l = levels[unit / trials];
        const std::uint64_t t = unit % trials;
        sf::FloorOptions f;
        f.seed = p.seed + t;
        if (l.factor == "noise") f.noise = static_cast<std::int32_t>(l.level);
        if (l.factor == "fade") f.fade_half_life_ms = 1000 * l.level;
        if (l.factor.rfind("drift", 0) == 0)
          f.drift_ppm_per_minute = static_cast<std::int32_t>(l.level);
        const auto r = run_one(board(p.cells, 10, p.seed, t), f, l.factor != "drift-uncalibrated");
        algorithms::Payload out;
        out.put_i(r.reachable);
        out.put_i(r.covered);
        out.put_i(r.repeats);
        out.put_i(r.max_offset);
        out.put(r.exact ? 1 : 0);
        out.put(r.hash);
        return out;
      });
  // Board sizes: each unit one (fade, n); n from 2 to max_board, decided in order afterwards.
  const auto sizes = static_cast<std::uint64_t>(std::max(0, p.max_board - 1));
  const auto boards = algorithms::run_units(
      runner, "stc floor boards", p.board_fade_s.size() * sizes, [&](std::uint64_t unit) {
        sf::FloorOptions f;
        f.seed = p.seed;
        f.fade_half_life_ms = 1000 * p.board_fade_s[unit / sizes];
        const auto n = static_cast<std::int32_t>(2 + unit % sizes);
        const auto r = run_one(board(n, 0, p.seed, 0), f, true);
        algorithms::Payload out;
        out.put(r.exact ? 1 : 0);
        out.put_i(r.clock_ms);
        out.put(r.hash);
        return out;
      });
  // Both runs above are collective under MPI; only rank 0 holds the results.
  if (!runner.root()) return c;
  kernel::TraceHash h;
  for (std::size_t li = 0; li < levels.size(); ++li) {
    FloorPoint pt;
    pt.factor = levels[li].factor;
    pt.level = levels[li].level;
    for (std::uint64_t t = 0; t < trials; ++t) {
      algorithms::Payload w = payloads[li * trials + t];
      const auto reachable = static_cast<double>(w.get_i());
      const auto covered = static_cast<double>(w.get_i());
      const auto repeats = static_cast<double>(w.get_i());
      const auto offset = static_cast<double>(w.get_i()) / 65536.0;
      const bool exact = w.get() == 1;
      h.add_u64(w.get());
      pt.coverage += reachable > 0 ? covered / reachable : 0;
      pt.repeats_per_subcell += reachable > 0 ? repeats / reachable : 0;
      pt.exact += exact ? 1 : 0;
      pt.max_offset += offset;
      pt.coverage_runs.push_back(reachable > 0 ? covered / reachable : 0);
    }
    const double n = static_cast<double>(trials);
    pt.coverage /= n;
    pt.repeats_per_subcell /= n;
    pt.exact /= n;
    pt.max_offset /= n;
    if (pt.factor == "drift" && pt.exact < 1 && c.off_grid_drift < 0) c.off_grid_drift = pt.level;
    c.points.push_back(pt);
  }
  for (std::size_t fi = 0; fi < p.board_fade_s.size(); ++fi) {
    FloorBoard b;
    b.fade_s = p.board_fade_s[fi];
    for (std::uint64_t k = 0; k < sizes; ++k) {
      algorithms::Payload w = boards[fi * sizes + k];
      const bool exact = w.get() == 1;
      const auto ms = w.get_i();
      h.add_u64(w.get());
      if (!exact) break;
      b.largest = static_cast<std::int32_t>(2 + k);
      b.tour_minutes = static_cast<double>(ms) / 60000.0;
      b.capped = b.largest == p.max_board;
    }
    c.boards.push_back(b);
  }
  c.hash = h.finish();
  return c;
}

std::string floor_curves_csv(const FloorCurves& c) {
  std::ostringstream csv;
  csv << "factor,level,coverage,repeats_per_subcell,exact,max_offset_subcells\n";
  for (const auto& p : c.points)
    csv << p.factor << ',' << p.level << ',' << fixed(p.coverage, 4) << ','
        << fixed(p.repeats_per_subcell, 4) << ',' << fixed(p.exact, 3) << ','
        << fixed(p.max_offset, 3) << '\n';
  return csv.str();
}

std::string floor_boards_csv(const FloorCurves& c) {
  std::ostringstream boards;
  boards << "fade_half_life_s,largest_exact_board_cells,tour_minutes,capped\n";
  for (const auto& b : c.boards)
    boards << b.fade_s << ',' << b.largest << ',' << fixed(b.tour_minutes, 1) << ','
           << (b.capped ? "yes" : "no") << '\n';
  return boards.str();
}

void write_floor_curves(const FloorCurves& c, const std::filesystem::path& dir) {
  io::write_file_atomic(dir / "floor_curves.csv", floor_curves_csv(c));
  io::write_file_atomic(dir / "floor_boards.csv", floor_boards_csv(c));

  struct Panel {
    const char* file;
    const char* factor;
    const char* x_label;
    const char* title;
  };
  const Panel panels[] = {
      {"floor_noise", "noise", "camera noise: uniform +- this per channel (0-255)",
       "Marker-floor STC against camera noise"},
      {"floor_fade", "fade", "half-life of the marks' glow (s; none: no fading)",
       "Marker-floor STC against the marks' fading"},
      {"floor_drift", "drift", "turn rate falling by ppm a minute (a weakening battery)",
       "Marker-floor STC against rotation drift"}};
  for (const auto& pn : panels) {
    Figure fig;
    fig.title = pn.title;
    fig.x_label = pn.x_label;
    fig.y_label = "fraction (repeats: per reachable sub-cell)";
    fig.y_from_zero = true;
    PlotPanel panel;
    PlotSeries cov{"coverage (truth)", "#1f77b4", false, false, {}};
    PlotSeries exact{"exact runs", "#2ca02c", false, false, {}};
    PlotSeries rep{"repeats per sub-cell", "#d62728", true, false, {}};
    PlotSeries unc{"exact runs, calibration off", "#7f7f7f", true, false, {}};
    double x = 0;
    for (const auto& p : c.points) {
      if (p.factor != pn.factor) continue;
      fig.x_categories.push_back(
          pn.factor == std::string("fade") && p.level == 0 ? "none" : std::to_string(p.level));
      cov.points.push_back({x, p.coverage, {}, {}});
      exact.points.push_back({x, p.exact, {}, {}});
      rep.points.push_back({x, p.repeats_per_subcell, {}, {}});
      for (const auto& u : c.points)
        if (u.factor == "drift-uncalibrated" && u.level == p.level)
          unc.points.push_back({x, u.exact, {}, {}});
      x += 1;
    }
    panel.series = {cov, exact, rep};
    if (pn.factor == std::string("drift")) panel.series.push_back(unc);
    fig.panels.push_back(panel);
    fig.caption = "Ant-edge STC through the rendered camera of paper 002's robot; means of " +
                  std::to_string(c.params.trials) + " keyed boards\nof " +
                  std::to_string(c.params.cells) + " x " + std::to_string(c.params.cells) +
                  " cells (10 % of sub-cells blocked) per level. Exact: the tour closed with "
                  "every\nreachable sub-cell entered once. Coverage and repeats count the body's "
                  "own sub-cells;\na run is cut off after 4 moves per reachable sub-cell.";
    save_figure(fig, dir / (std::string(pn.file) + ".svg"), dir / (std::string(pn.file) + ".png"));
  }
}

} // namespace antkit::experiments
