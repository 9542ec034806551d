// `antkit stc`: Spanning Tree Coverage of a grid map (issue 3). The marker-noise experiment is
// `antkit stc-noise` (stc_noise.cpp); the Cortex-M image's input, `antkit dev stc-mcu-input`.
//
//   antkit stc --map FILE --variant offline|online|ant|ant-edge|full [--start X,Y]
//              [--noise P --seed S] [--format table|json] [--path-out FILE.csv|FILE.bin]
//              [--svg FILE] [--png FILE] [--mcap FILE.mcap]
//
// --mcap writes the tour for Foxglove (commands/stc_mcap.hpp: the map, the spanning tree, the pose
// step by step, the verdict on /log); it keeps the path in memory, so maps up to 2^22 sub-cells.
//
// At scale (issue 15): the tour is streamed as it is made, never held (unless a picture is asked
// for): `--format json` writes the path into stdout as the run goes, `--path-out` into a file (CSV
// "x,y" lines, or the two-bits-per-move binary of stc/path_format.hpp for a .bin name; written to
// a temporary name and renamed), and the checks the command runs (covered, repeats, return) are
// the run's own counts on one bit per sub-cell. Offline takes the library's fast path. JSON keys,
// in order: variant, width, height, start, path, reachable_subcells, covered, repeats,
// returned_to_start, hash (and noise_ppm, seed with --noise).
//
// Coordinates are in sub-cells (one map cell = one robot-sized sub-cell), x to the right and y
// downward from the file's first row. Exit status: 0, 2 for bad input (a malformed map, no free
// start, a start in an obstacle, an option out of range), 1 when a noise-free tour breaks one of
// its invariants (it never should: that is a failed check, not bad input).
#include "commands.hpp"
#include "output.hpp"
#include "stc_options.hpp"

#include <antkit/commands/json.hpp>
#include <antkit/commands/stc_mcap.hpp>
#include <antkit/experiments/stc_tour.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/world.hpp>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace {

using antkit::cli::Format;
using antkit::kernel::Cell;
using antkit::kernel::InputError;
using namespace antkit::stc;

struct StcOptions {
  std::string map;
  std::string variant;
  std::string start;
  std::string noise;
  std::uint64_t seed = 0;
  std::string svg, png, path_out, mcap;
  Format format = Format::Table;
};

void run_stc_command(const StcOptions& o) {
  const auto request = antkit::cli::read_stc_request(o.map, o.variant, o.start, o.noise, o.seed);
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
  out.keep_path = !o.svg.empty() || !o.png.empty() || !o.mcap.empty();
  if (!o.mcap.empty()) antkit::commands::check_stc_mcap_size(map.cells);
  if (!o.noise.empty()) out.seed = o.seed;
  out.start_where = o.start.empty() ? o.map : "--start"; // the option or the file it came from
  const RunResult r =
      antkit::experiments::write_stc_tour(map.cells, start, variant, request.noise, out);
  if (!o.svg.empty() || !o.png.empty())
    antkit::experiments::save_stc_tour_figure(
        map.cells, r, std::filesystem::path(o.map).filename().string(), o.svg, o.png);
  if (!o.mcap.empty())
    (void)antkit::commands::write_stc_mcap(map, r, std::filesystem::path(o.map).filename().string(),
                                           o.mcap);
  if (!json) {
    nlohmann::json j = antkit::commands::stc_json(
        r, map.cells.width(), map.cells.height(), start,
        o.noise.empty()
            ? std::nullopt
            : std::optional(antkit::commands::StcNoiseFields{request.noise.ppm, o.seed}));
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
  cmd->add_option("--mcap", o->mcap,
                  "Write the tour as MCAP for Foxglove: the map, the spanning tree, the pose at "
                  "each step (10 a second), the verdict (maps up to 2^22 sub-cells)");
  antkit::cli::add_format_option(*cmd, o->format);
  cmd->callback([o] { run_stc_command(*o); });
}

const antkit::cli::Registration stc_registration{"stc", &register_stc};

} // namespace
