// `antkit stc`: Spanning Tree Coverage of a grid map (issue 3), and `antkit stc-noise`, the
// marker-noise experiment (coverage and repeats against the probability that a mark is misread).
//
//   antkit stc --map FILE --variant offline|online|ant|ant-edge|full [--start X,Y]
//              [--noise P --seed S] [--format table|json] [--svg FILE]
//   antkit stc-noise --map FILE [--variant ant|ant-edge] [--start X,Y] [--levels P,P,...]
//              [--trials N] [--seed S] [--format table|json]
//
// Coordinates are in sub-cells (one map cell = one robot-sized sub-cell), x to the right and y
// downward from the file's first row. Exit status: 0, 2 for bad input (a malformed map, no free
// start, a start in an obstacle, an option out of range), 1 when a noise-free tour breaks one of
// its invariants (it never should: that is a failed check, not bad input).
#include "commands.hpp"
#include "output.hpp"
#include "svg.hpp"

#include <algorithm>
#include <antkit/algorithms/options.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

using antkit::cli::Format;
namespace algorithms = antkit::algorithms;
using antkit::kernel::Cell;
using antkit::kernel::InputError;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using namespace antkit::stc;

struct StcOptions {
  std::string map;
  std::string variant;
  std::string start;
  std::string noise;
  std::uint64_t seed = 0;
  std::string svg;
  Format format = Format::Table;
};

Variant parse_variant_option(const std::string& name) {
  if (const auto v = parse_variant(name)) return *v;
  throw InputError("--variant", "'" + name +
                                    "' is not a variant: expected offline, online, ant, "
                                    "ant-edge or full");
}

// The start: --start if given, else the map's own start ('S' in an ASCII map), else
// stc::default_start (the largest region's first place).
Cell choose_start(const antkit::maps::GridMap& map, Variant variant, const std::string& option,
                  const std::string& file) {
  if (!option.empty()) return algorithms::parse_cell("--start", option);
  if (map.start) return *map.start;
  if (const auto start = default_start(map.cells, variant)) return *start;
  throw InputError(file, is_exact(variant)
                             ? "the map has no free cell (2 x 2 free sub-cells) to start in"
                             : "the map has no free sub-cell to start in");
}

void draw_svg(const std::string& file, const OccupancyGrid& map, const RunResult& r) {
  const double side = std::max(map.width(), map.height());
  const double scale = std::clamp(1200.0 / side, 2.0, 24.0);
  antkit::cli::Svg svg(0, 0, map.width(), map.height(), scale, true);
  svg.rect(0, 0, map.width(), map.height(), "#ffffff");
  svg.grid_cells(map, "#333333", "#999999");
  // The spanning tree: an edge between the centres of two cells each time the tour first crosses
  // between them.
  std::set<std::pair<Cell, Cell>> edges;
  for (std::size_t i = 1; i < r.path.size(); ++i) {
    const Cell a = cell_of(r.path[i - 1]), b = cell_of(r.path[i]);
    if (a == b || !edges.insert({std::min(a, b), std::max(a, b)}).second) continue;
    svg.line(2 * a.x + 1, 2 * a.y + 1, 2 * b.x + 1, 2 * b.y + 1, "#2e7d32", 0.25);
  }
  std::vector<std::pair<double, double>> points;
  points.reserve(r.path.size());
  for (const Cell s : r.path) points.emplace_back(s.x + 0.5, s.y + 0.5);
  svg.polyline(points, "#1565c0", 0.12);
  if (!r.path.empty()) svg.circle(r.path.front().x + 0.5, r.path.front().y + 0.5, 0.35, "#c62828");
  svg.save(file);
}

void run_stc_command(const StcOptions& o) {
  const Variant variant = parse_variant_option(o.variant);
  RunOptions run;
  if (!o.noise.empty()) {
    if (variant != Variant::Ant && variant != Variant::AntEdge)
      throw InputError("--noise", "marker noise applies to the variants that read marks, ant and "
                                  "ant-edge, not " +
                                      std::string(variant_name(variant)));
    run.noise = {algorithms::parse_probability_ppm("--noise", o.noise), o.seed, 0};
  }
  const auto map = antkit::maps::load_map(o.map);
  const Cell start = choose_start(map, variant, o.start, o.map);
  RunResult r;
  try {
    r = run_stc(map.cells, start, variant, run);
  } catch (const InputError& e) { // name the option or the file the start came from
    throw InputError(o.start.empty() ? o.map : "--start", e.message());
  }
  if (o.noise.empty() || run.noise.ppm == 0) {
    const bool ok = r.closed && r.returned_to_start && r.covered == r.reachable_subcells &&
                    (variant == Variant::Full || r.repeats == 0);
    if (!ok)
      throw antkit::cli::CheckFailed(
          "the " + std::string(variant_name(variant)) + " tour broke an invariant (covered " +
          std::to_string(r.covered) + " of " + std::to_string(r.reachable_subcells) + ", repeats " +
          std::to_string(r.repeats) + ")");
  }
  if (!o.svg.empty()) draw_svg(o.svg, map.cells, r);
  nlohmann::json j;
  j["variant"] = std::string(variant_name(variant));
  j["width"] = map.cells.width();
  j["height"] = map.cells.height();
  j["start"] = {start.x, start.y};
  nlohmann::json path = nlohmann::json::array();
  for (const Cell s : r.path) path.push_back({s.x, s.y});
  j["path"] = std::move(path);
  j["reachable_subcells"] = r.reachable_subcells;
  j["covered"] = r.covered;
  j["repeats"] = r.repeats;
  j["returned_to_start"] = r.returned_to_start;
  j["hash"] = antkit::kernel::hash_hex(r.hash);
  if (!o.noise.empty()) {
    j["noise_ppm"] = run.noise.ppm;
    j["seed"] = o.seed;
  }
  antkit::cli::emit(j, o.format, std::cout);
}

struct NoiseOptions {
  std::string map;
  std::string variant = "ant";
  std::string start;
  std::string levels = "0,0.0001,0.001,0.005,0.01,0.02,0.05,0.1,0.2";
  std::int32_t trials = 20;
  std::uint64_t seed = 1;
  Format format = Format::Table;
};

void run_noise_command(const NoiseOptions& o) {
  const Variant variant = parse_variant_option(o.variant);
  if (variant != Variant::Ant && variant != Variant::AntEdge)
    throw InputError("--variant", "marker noise applies to ant and ant-edge only");
  if (o.trials < 1 || o.trials > 100000)
    throw InputError("--trials", std::to_string(o.trials) + " is outside [1, 100000]");
  std::vector<std::pair<std::string, std::uint32_t>> levels;
  std::size_t from = 0;
  while (from <= o.levels.size()) {
    const auto comma = std::min(o.levels.find(',', from), o.levels.size());
    const std::string item = o.levels.substr(from, comma - from);
    levels.emplace_back(item, algorithms::parse_probability_ppm("--levels", item));
    from = comma + 1;
  }
  const auto map = antkit::maps::load_map(o.map);
  const Cell start = choose_start(map, variant, o.start, o.map);
  StcWorld world;
  nlohmann::json curve = nlohmann::json::array();
  std::int64_t reachable = 0;
  for (const auto& [text, ppm] : levels) {
    // Trials run in order, each with its own keyed stream (trial = its index): the curve does not
    // depend on anything but the seed. Means are computed on the reporting side.
    double coverage = 0, repeats = 0, complete = 0, moves = 0;
    for (std::int32_t t = 0; t < o.trials; ++t) {
      RunOptions run;
      run.noise = {ppm, o.seed, static_cast<std::uint64_t>(t)};
      run.record_path = false;
      RunResult r;
      try {
        r = run_stc(world, map.cells, start, variant, run);
      } catch (const InputError& e) {
        throw InputError(o.start.empty() ? o.map : "--start", e.message());
      }
      reachable = r.reachable_subcells;
      coverage += static_cast<double>(r.covered) / static_cast<double>(r.reachable_subcells);
      repeats += static_cast<double>(r.repeats) / static_cast<double>(r.reachable_subcells);
      complete += (r.covered == r.reachable_subcells && r.returned_to_start) ? 1 : 0;
      moves += static_cast<double>(r.positions);
    }
    const double n = o.trials;
    curve.push_back({{"noise", text},
                     {"coverage", coverage / n},
                     {"repeats_per_subcell", repeats / n},
                     {"complete_tours", complete / n},
                     {"mean_positions", moves / n}});
  }
  nlohmann::json j;
  j["variant"] = std::string(variant_name(variant));
  j["map"] = o.map;
  j["start"] = {start.x, start.y};
  j["reachable_subcells"] = reachable;
  j["trials"] = o.trials;
  j["seed"] = o.seed;
  j["curve"] = std::move(curve);
  antkit::cli::emit(j, o.format, std::cout);
}

void register_stc(CLI::App& app) {
  auto o = std::make_shared<StcOptions>();
  auto* cmd = app.add_subcommand(
      "stc", "Spanning Tree Coverage of a grid map (each map cell is a robot-sized sub-cell; "
             "2 x 2 sub-cells make a cell; an odd last row or column is not covered)");
  cmd->add_option("--map", o->map, "The map (.map, .yaml or .txt)")->required();
  cmd->add_option("--variant", o->variant, "offline, online, ant, ant-edge or full")->required();
  cmd->add_option("--start", o->start,
                  "Start sub-cell X,Y (x right, y down from the file's first row). Default: the "
                  "map's S if it has one, else the NW sub-cell of the first free cell (row-major) "
                  "of the largest 4-connected region of free cells (full: the first free "
                  "sub-cell of the largest region of free sub-cells)");
  cmd->add_option("--noise", o->noise,
                  "Probability that one mark reading is misread, missed or phantom (ant and "
                  "ant-edge), a decimal with at most six places");
  cmd->add_option("--seed", o->seed, "Seed of the keyed noise stream (default 0)");
  cmd->add_option("--svg", o->svg, "Write a picture: obstacles, spanning tree, tour");
  antkit::cli::add_format_option(*cmd, o->format);
  cmd->callback([o] { run_stc_command(*o); });

  auto n = std::make_shared<NoiseOptions>();
  auto* noise = app.add_subcommand(
      "stc-noise", "Marker noise experiment: coverage and repeats of ant-like STC against the "
                   "probability that a mark is misread, averaged over keyed trials");
  noise->add_option("--map", n->map, "The map (.map, .yaml or .txt)")->required();
  noise->add_option("--variant", n->variant, "ant (default) or ant-edge");
  noise->add_option("--start", n->start, "Start sub-cell X,Y (default as for `antkit stc`)");
  noise->add_option("--levels", n->levels, "Comma-separated misread probabilities")
      ->default_str(n->levels);
  noise->add_option("--trials", n->trials, "Trials per level (default 20)");
  noise->add_option("--seed", n->seed, "Seed of the keyed noise streams (default 1)");
  antkit::cli::add_format_option(*noise, n->format);
  noise->callback([n] { run_noise_command(*n); });
}

const antkit::cli::Registration reg_stc{"stc", &register_stc};

} // namespace
