// `antkit dev wanderer-mcu-input` (plumbing for scripts/run-on-mcu.sh wanderer, issue 27): one
// step-turn wanderer run's input for the Cortex-M image (uniform/wanderer_mcu_input.hpp), with
// `antkit cover --algo rw --robots 1`'s options: the map is read (or generated), the robot placed
// and the world built and checked here as `antkit cover` does (exit 2, located); the viewable
// cells (the robot's 4-connected free component) and the sensor's footprint (SensorFootprint) are
// encoded with the map's Free cells as bits by uniform::mcu_wanderer_input, which refuses a run
// whose bits and footprint exceed the chip's arena (the sizes and the limit in the message).
//
//   antkit dev wanderer-mcu-input (--map FILE | --size WxH --density P) [--seed S] [--trial K]
//                                 [--sensor R] [--limit T] --out FILE
#include "commands.hpp"

#include <antkit/geometry/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/wanderer_mcu_encode.hpp>
#include <antkit/uniform/wanderer_mcu_input.hpp>
#include <antkit/uniform/world.hpp>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace {

using antkit::kernel::InputError;
namespace uniform = antkit::uniform;

// `antkit cover`'s bounds for generated maps.
constexpr std::int32_t kMaxSide = 8192;
constexpr std::int64_t kMaxCells = std::int64_t{1} << 26;

struct WandererInputCommand {
  std::string map, size, density, out;
  std::uint64_t seed = 1, trial = 0;
  std::int64_t sensor = 5;
  std::int64_t limit = -1; // default: 10 * W * H
};

void run(const WandererInputCommand& o) {
  if (o.map.empty() == o.size.empty())
    throw InputError("", "give either --map FILE or --size WxH --density P");
  if (!o.map.empty() && !o.density.empty())
    throw InputError("--density", "a map file has its own obstacles; --density goes with --size");
  if (!o.size.empty() && o.density.empty())
    throw InputError("--density", "--size needs an obstacle density, such as --density 0.2");
  if (o.sensor < 0 || o.sensor > uniform::kMaxSensorRange)
    throw InputError("--sensor", "expected a sensor distance in [0, " +
                                     std::to_string(uniform::kMaxSensorRange) + "] cells, not " +
                                     std::to_string(o.sensor));
  if (o.limit < -1) throw InputError("--limit", "expected a number of ticks >= 0");
  antkit::kernel::OccupancyGrid grid;
  std::optional<antkit::kernel::Cell> start;
  if (!o.map.empty()) {
    auto loaded = antkit::maps::load_map(o.map);
    grid = std::move(loaded.cells);
    start = loaded.start;
  } else {
    const auto [w, h] = uniform::parse_size(o.size, kMaxSide);
    if (std::int64_t{w} * h > kMaxCells)
      throw InputError("--size", "at most " + std::to_string(kMaxCells) + " cells, not " +
                                     std::to_string(std::int64_t{w} * h));
    grid = uniform::random_obstacles(w, h, uniform::parse_density_ppm(o.density), o.seed, o.trial);
  }
  const auto poses = uniform::place_robots(grid, 1, start, o.seed, o.trial);
  const std::int64_t cells = std::int64_t{grid.width()} * grid.height();
  const auto limit = static_cast<std::uint64_t>(o.limit >= 0 ? o.limit : 10 * cells);
  const uniform::CoverageWorld world(grid, poses, static_cast<std::int32_t>(o.sensor));
  uniform::McuWandererInput in;
  try {
    in = uniform::mcu_wanderer_input(world, o.seed, o.trial, limit);
  } catch (const InputError& e) {
    if (e.where() != "map") throw;
    throw InputError(o.map.empty() ? "--size" : o.map, e.message());
  }
  const auto& bytes = in.bytes;
  antkit::geometry::write_file_atomic(
      o.out, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  std::cout << o.out << ": " << bytes.size() << " bytes, " << grid.width() << " x " << grid.height()
            << " cells, plan " << in.plan << " of " << uniform::kMcuWandererArenaBytes
            << " bytes\n";
}

void register_wanderer_mcu_input(CLI::App& app) {
  auto o = std::make_shared<WandererInputCommand>();
  auto* sub = app.add_subcommand(
      "wanderer-mcu-input", "Plumbing: one step-turn wanderer run's input for the Cortex-M image "
                            "(scripts/run-on-mcu.sh wanderer; uniform/wanderer_mcu_input.hpp)");
  sub->add_option("--map", o->map, "A map file (.map, .yaml, .txt or .ascii)");
  sub->add_option("--size", o->size, "A generated W x H grid, e.g. 100x100");
  sub->add_option("--density", o->density, "Obstacle density of the generated grid");
  sub->add_option("--seed", o->seed, "Seed of the keyed random streams (default 1)");
  sub->add_option("--trial", o->trial, "Trial number of the keyed random streams (default 0)");
  sub->add_option("--sensor", o->sensor, "Sensor distance in cells (default 5)");
  sub->add_option("--limit", o->limit, "Time limit in ticks (default 10 * W * H)");
  sub->add_option("--out", o->out, "The input file to write")->required();
  sub->callback([o] { run(*o); });
}

const antkit::cli::DevRegistration reg{"wanderer-mcu-input", &register_wanderer_mcu_input};

} // namespace
