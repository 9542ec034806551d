// `antkit stc`: Spanning Tree Coverage of a grid map (issue 3), and `antkit stc-noise`, the
// marker-noise experiment (coverage and repeats against the probability that a mark is misread).
//
//   antkit stc --map FILE --variant offline|online|ant|ant-edge|full [--start X,Y]
//              [--noise P --seed S] [--format table|json] [--path-out FILE.csv|FILE.bin]
//              [--svg FILE] [--png FILE]
//
// At scale (issue 15): the tour is streamed as it is made, never held (unless a picture is asked
// for): `--format json` writes the path into stdout as the run goes, `--path-out` into a file (CSV
// "x,y" lines, or the two-bits-per-move binary of stc/path_format.hpp for a .bin name; written to
// a temporary name and renamed), and the checks the command runs (covered, repeats, return) are
// the run's own counts on one bit per sub-cell. Offline takes the library's fast path. JSON keys,
// in order: variant, width, height, start, path, reachable_subcells, covered, repeats,
// returned_to_start, hash (and noise_ppm, seed with --noise).
//   antkit stc-noise --map FILE [--variant ant|ant-edge] [--start X,Y] [--levels P,P,...]
//              [--trials N] [--seed S] [--format table|json]
//
// Coordinates are in sub-cells (one map cell = one robot-sized sub-cell), x to the right and y
// downward from the file's first row. Exit status: 0, 2 for bad input (a malformed map, no free
// start, a start in an obstacle, an option out of range), 1 when a noise-free tour breaks one of
// its invariants (it never should: that is a failed check, not bad input).
#include "commands.hpp"
#include "output.hpp"

#include <algorithm>
#include <antkit/algorithms/options.hpp>
#include <antkit/experiments/stc_tour.hpp>
#include <antkit/experiments/stc_tours.hpp>
#include <antkit/geometry/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/reports/reports.hpp>
#include <antkit/stc/start.hpp>
#include <antkit/stc/world.hpp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
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
  std::string svg, png, path_out;
  Format format = Format::Table;
};

// What `antkit stc` and `antkit stc-mcu-input` read from the same options, refused the same way:
// the variant, the marker noise, the map and the start.
struct StcRequest {
  Variant variant;
  NoiseModel noise;
  antkit::maps::GridMap map;
  Cell start;
};

StcRequest read_stc_request(const std::string& map_file, const std::string& variant_text,
                            const std::string& start, const std::string& noise,
                            std::uint64_t seed) {
  StcRequest r{antkit::reports::stc_variant(variant_text, "--variant"), {}, {}, {}};
  if (!noise.empty()) r.noise = antkit::reports::stc_noise(r.variant, noise, seed, "--noise");
  r.map = antkit::maps::load_map(map_file);
  r.start = choose_start(r.map.cells, r.variant,
                         start.empty() ? std::nullopt
                                       : std::optional(algorithms::parse_cell("--start", start)),
                         r.map.start, map_file);
  return r;
}

void run_stc_command(const StcOptions& o) {
  const StcRequest request = read_stc_request(o.map, o.variant, o.start, o.noise, o.seed);
  const Variant variant = request.variant;
  const auto& map = request.map;
  const Cell start = request.start;
  // Every bad input is refused before the first byte of output: the path file's name is checked
  // here, the file opened (write_file_atomic) before the run, and the start checked before the
  // first position, which writes the JSON's head (experiments/stc_tour.hpp).
  const auto ext = std::filesystem::path(o.path_out).extension();
  if (!o.path_out.empty() && ext != ".csv" && ext != ".bin")
    throw InputError("--path-out", "'" + o.path_out + "': give a .csv or a .bin file name");
  const bool json = o.format == Format::Json;
  antkit::experiments::StcTourOutput out;
  out.json = json ? &std::cout : nullptr;
  out.path_file = o.path_out;
  out.binary_path = ext == ".bin";
  out.keep_path = !o.svg.empty() || !o.png.empty();
  if (!o.noise.empty()) out.seed = o.seed;
  out.start_where = o.start.empty() ? o.map : "--start"; // the option or the file it came from
  const RunResult r =
      antkit::experiments::write_stc_tour(map.cells, start, variant, request.noise, out);
  if (!o.svg.empty() || !o.png.empty())
    antkit::experiments::save_stc_tour_figure(
        map.cells, r, std::filesystem::path(o.map).filename().string(), o.svg, o.png);
  if (!json) {
    nlohmann::json j = antkit::reports::stc_json(
        r, map.cells.width(), map.cells.height(), start,
        o.noise.empty()
            ? std::nullopt
            : std::optional(antkit::reports::StcNoiseFields{request.noise.ppm, o.seed}));
    j["path"] = "(" + std::to_string(r.positions) + " items; use --format json)";
    antkit::cli::emit(j, o.format, std::cout);
  }
  if (o.noise.empty() || request.noise.ppm == 0) {
    if (!keeps_invariants(r))
      throw antkit::cli::CheckFailed(
          "the " + std::string(variant_name(variant)) + " tour broke an invariant (covered " +
          std::to_string(r.covered) + " of " + std::to_string(r.reachable_subcells) + ", repeats " +
          std::to_string(r.repeats) + ")");
  }
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
  const Variant variant = antkit::reports::stc_variant(o.variant, "--variant");
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
  const Cell start = choose_start(
      map.cells, variant,
      o.start.empty() ? std::nullopt : std::optional(algorithms::parse_cell("--start", o.start)),
      map.start, o.map);
  std::vector<std::uint32_t> ppm;
  for (const auto& level : levels) ppm.push_back(level.second);
  std::int64_t reachable = 0;
  std::vector<antkit::experiments::StcNoisePoint> points;
  try {
    // Trials run in order, each with its own keyed stream (trial = its index): the curve does
    // not depend on anything but the seed (experiments/stc_tours.hpp).
    points = antkit::experiments::run_stc_noise(map.cells, start, {o.variant}, ppm, o.trials,
                                                o.seed, antkit::algorithms::Runner{}, &reachable);
  } catch (const InputError& e) {
    throw InputError(o.start.empty() ? o.map : "--start", e.message());
  }
  nlohmann::json curve = nlohmann::json::array();
  for (std::size_t k = 0; k < points.size(); ++k)
    curve.push_back({{"noise", levels[k].first},
                     {"coverage", points[k].coverage},
                     {"repeats_per_subcell", points[k].repeats_per_subcell},
                     {"complete_tours", points[k].complete},
                     {"mean_positions", points[k].mean_positions}});
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

struct McuInputOptions {
  std::string map, variant, start, noise, out;
  std::uint64_t seed = 0;
};

// The Cortex-M image's input (stc/mcu_input.hpp) for scripts/run-on-mcu.sh: the same options, the
// same start and the same refusals as `antkit stc`, and a map too large for the chip refused.
void run_mcu_input_command(const McuInputOptions& o) {
  const StcRequest r = read_stc_request(o.map, o.variant, o.start, o.noise, o.seed);
  const Cell start = r.start;
  std::vector<std::uint8_t> bytes;
  try {
    bytes = mcu_input(r.map.cells, start, r.variant, r.noise);
  } catch (const InputError& e) {
    const std::string where = e.where() == "variant" ? "--variant"
                              : e.where() == "map"   ? o.map
                              : o.start.empty()      ? o.map
                                                     : "--start";
    throw InputError(where, e.message());
  }
  antkit::geometry::write_file_atomic(
      o.out, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  std::cout << o.out << ": " << bytes.size() << " bytes, start " << start.x << "," << start.y
            << "\n";
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
  cmd->add_option("--svg", o->svg,
                  "Write a picture (SVG): obstacles, spanning tree, the tour coloured along its "
                  "length, legend (keeps the path in memory)");
  cmd->add_option("--png", o->png, "The same picture as PNG");
  cmd->add_option("--path-out", o->path_out,
                  "Stream the tour into FILE.csv (x,y lines) or FILE.bin (two bits per move, "
                  "stc/path_format.hpp); antkit check stc reads both");
  antkit::cli::add_format_option(*cmd, o->format);
  cmd->callback([o] { run_stc_command(*o); });

  auto m = std::make_shared<McuInputOptions>();
  auto* mcu = app.add_subcommand("stc-mcu-input",
                                 "Write one ant or ant-edge STC run as the Cortex-M image's input "
                                 "(scripts/run-on-mcu.sh runs it under QEMU; stc/mcu_input.hpp)");
  mcu->add_option("--map", m->map, "The map (.map, .yaml or .txt)")->required();
  mcu->add_option("--variant", m->variant, "ant or ant-edge")->required();
  mcu->add_option("--start", m->start, "Start sub-cell X,Y (default as for `antkit stc`)");
  mcu->add_option("--noise", m->noise, "Mark misread probability (as for `antkit stc`)");
  mcu->add_option("--seed", m->seed, "Seed of the keyed noise stream (default 0)");
  mcu->add_option("--out", m->out, "The input file to write")->required();
  mcu->callback([m] { run_mcu_input_command(*m); });

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
