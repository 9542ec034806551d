// `antkit cover`: uniform coverage by paper 004's algorithms (issue 6).
//   antkit cover (--map FILE | --size WxH --density P) [--seed S]
//                --algo rw|pm|astar|astar-coord|frontier
//                [--robots N] [--sensor R] [--limit T] [--trial K] [--format table|json]
//                [--svg FILE] [--png FILE] [--trace FILE] [--mcap FILE.mcap]
// --mcap writes the run for Foxglove from its trace (commands/cover_mcap.hpp): the map, every
// robot's pose each tick, and on /log the run and its trace's check (antkit check cover's).
// Prints {"algo", "robots", "coverage", "viewed", "viewable", "movements", "moves", "hash", ...}.
// Maps: Blocked and Unknown cells both block sight and movement, and only Free cells count for
// coverage. A map's start cell ('S' in ASCII maps) is robot 0's start.
#include "commands.hpp"
#include "cover_options.hpp"
#include "output.hpp"

#include <algorithm>
#include <antkit/commands/cover_mcap.hpp>
#include <antkit/experiments/coverage_run.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/world.hpp>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace {

using antkit::cli::Format;
using antkit::kernel::InputError;
namespace uniform = antkit::uniform;

struct CoverOptions : antkit::cli::CoverMapOptions { // --map or --size and --density, --seed, ...
  std::string algo;
  std::int64_t robots = 1;
  std::string svg, png;
  std::string trace, mcap;
  Format format = Format::Table;
};

nlohmann::json run_cover(const CoverOptions& o) {
  const auto algo = uniform::parse_algorithm(o.algo);
  if (!algo)
    throw InputError("--algo", "unknown algorithm '" + o.algo +
                                   "'; expected rw, pm, astar, astar-coord or frontier");
  antkit::cli::check_cover_options(o, o.robots);
  antkit::cli::CoverGrid grid = antkit::cli::read_cover_grid(o);
  nlohmann::json source;
  if (grid.density_ppm)
    source["density_ppm"] = *grid.density_ppm;
  else
    source["map"] = o.map;
  const auto poses = uniform::place_robots(grid.cells, static_cast<std::size_t>(o.robots),
                                           grid.start, o.seed, o.trial);
  const auto limit = antkit::cli::cover_limit(o, grid.cells);
  uniform::CoverageWorld world(std::move(grid.cells), poses, static_cast<std::int32_t>(o.sensor));
  uniform::CoverageResult r;
  const antkit::kernel::OccupancyGrid start_map = world.map();
  if (o.trace.empty() && o.mcap.empty()) {
    r = uniform::run_coverage(world, *algo, o.seed, o.trial, limit);
  } else {
    // The trace `antkit check cover` reads, streamed into a file that replaces --trace only whole
    // (for --mcap alone, a scratch file beside it, removed after).
    const std::string trace = o.trace.empty() ? o.mcap + ".trace.tmp" : o.trace;
    r = antkit::experiments::run_coverage_traced(world, *algo, o.seed, o.trial, limit, o.sensor,
                                                 trace);
    if (!o.mcap.empty()) {
      const auto removed = [&] {
        if (o.trace.empty()) std::filesystem::remove(trace);
      };
      try {
        (void)antkit::commands::cover_trace_mcap(
            start_map, trace, std::nullopt, nullptr,
            "cover " + o.algo + ", " + std::to_string(o.robots) + " robot(s), sensor " +
                std::to_string(o.sensor) + ", seed " + std::to_string(o.seed) + ", trial " +
                std::to_string(o.trial),
            o.mcap);
      } catch (...) {
        removed();
        throw;
      }
      removed();
    }
  }
  if (!o.svg.empty() || !o.png.empty())
    antkit::experiments::save_coverage_figure(o.algo, world, r, o.sensor, o.svg, o.png);

  nlohmann::json j;
  j["algo"] = std::string(uniform::algorithm_name(r.algorithm));
  j["robots"] = r.robots;
  j["coverage"] = 100.0 * static_cast<double>(r.viewed) / static_cast<double>(r.viewable);
  j["viewed"] = r.viewed;
  j["viewable"] = r.viewable;
  j["movements"] = r.movements;
  j["moves"] = r.moves;
  j["hash"] = antkit::kernel::hash_hex(r.hash);
  j["stop"] = std::string(uniform::stop_reason_name(r.stop));
  j["width"] = world.map().width();
  j["height"] = world.map().height();
  j["sensor"] = o.sensor;
  j["seed"] = o.seed;
  j["trial"] = o.trial;
  j["limit"] = limit;
  for (auto it = source.begin(); it != source.end(); ++it) j[it.key()] = it.value();
  return j;
}

void register_cover(CLI::App& app) {
  auto o = std::make_shared<CoverOptions>();
  auto* sub = app.add_subcommand(
      "cover", "Uniform coverage (paper 004): random wanderer, primary movement, A* with spiral "
               "search, coordinated A*, or frontier (Sheng et al.'s utility), by 1-N robots on a "
               "shared map");
  sub->add_option("--map", o->map, "A map file (.map, .yaml, .txt or .ascii)");
  sub->add_option("--size", o->size, "A generated W x H grid, e.g. 100x100");
  sub->add_option("--density", o->density,
                  "Obstacle density of the generated grid: 0.2 or 20% (exactly round(p*W*H) "
                  "blocked cells)");
  sub->add_option("--seed", o->seed, "Seed of the keyed random streams (default 1)");
  sub->add_option("--trial", o->trial, "Trial number of the keyed random streams (default 0)");
  sub->add_option("--algo", o->algo, "rw, pm, astar, astar-coord or frontier")->required();
  sub->add_option("--robots", o->robots, "Number of robots (default 1)");
  sub->add_option("--sensor", o->sensor, "Sensor distance in cells (default 5)");
  sub->add_option("--limit", o->limit, "Time limit in ticks (default 10 * W * H)");
  sub->add_option("--svg", o->svg,
                  "Write the final state as SVG: viewed and unviewed cells, obstacles, robots, "
                  "legend");
  sub->add_option("--png", o->png, "The same picture as PNG");
  sub->add_option("--trace", o->trace,
                  "Write every robot's pose after every tick as CSV (tick,robot,x,y,bearing), "
                  "with the sensor and the coverage claimed, for antkit check cover");
  sub->add_option("--mcap", o->mcap,
                  "Write the run as MCAP for Foxglove: the map, every robot's pose each tick (10 "
                  "a second), the run's check (at most 2^22 robot-ticks)");
  antkit::cli::add_format_option(*sub, o->format);
  sub->callback([o] { antkit::cli::emit(run_cover(*o), o->format, std::cout); });
}

const antkit::cli::Registration cover_registration{"cover", &register_cover};

} // namespace
