// `antkit dev wanderer-mcu-input` (plumbing for scripts/run-on-mcu.sh wanderer, issue 27): one
// step-turn wanderer run's input for the Cortex-M image (uniform/wanderer_mcu_input.hpp), with
// `antkit cover --algo rw --robots 1`'s options: the map is checked and read (or generated) by
// `antkit cover`'s own code (cover_options.hpp: exit 2, located), the robot placed and the world
// built as `antkit cover` does; the viewable cells (the robot's 4-connected free component) and
// the sensor's footprint (SensorFootprint) are encoded with the map's Free cells as bits by
// uniform::mcu_wanderer_input, which refuses a run whose bits and footprint exceed the chip's
// arena (the sizes and the limit in the message).
//
//   antkit dev wanderer-mcu-input (--map FILE | --size WxH --density P) [--seed S] [--trial K]
//                                 [--sensor R] [--limit T] --out FILE
#include "commands.hpp"
#include "cover_options.hpp"

#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/wanderer_mcu_encode.hpp>
#include <antkit/uniform/wanderer_mcu_input.hpp>
#include <antkit/uniform/world.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>

namespace {

using antkit::kernel::InputError;
namespace uniform = antkit::uniform;

struct WandererInputCommand {
  antkit::cli::CoverMapOptions map;
  std::string out;
};

void run(const WandererInputCommand& c) {
  const antkit::cli::CoverMapOptions& o = c.map;
  antkit::cli::check_cover_options(o, 1);
  const antkit::cli::CoverGrid grid = antkit::cli::read_cover_grid(o);
  const auto poses = uniform::place_robots(grid.cells, 1, grid.start, o.seed, o.trial);
  const auto limit = antkit::cli::cover_limit(o, grid.cells);
  const uniform::CoverageWorld world(grid.cells, poses, static_cast<std::int32_t>(o.sensor));
  uniform::McuWandererInput in;
  try {
    in = uniform::mcu_wanderer_input(world, o.seed, o.trial, limit);
  } catch (const InputError& e) {
    if (e.where() != "map") throw;
    throw InputError(o.map.empty() ? "--size" : o.map, e.message());
  }
  const auto& bytes = in.bytes;
  antkit::io::write_file_atomic(
      c.out, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  std::cout << c.out << ": " << bytes.size() << " bytes, " << grid.cells.width() << " x "
            << grid.cells.height() << " cells, plan " << in.plan << " of "
            << uniform::kMcuWandererArenaBytes << " bytes\n";
}

void register_wanderer_mcu_input(CLI::App& app) {
  auto c = std::make_shared<WandererInputCommand>();
  antkit::cli::CoverMapOptions* o = &c->map;
  auto* sub = app.add_subcommand(
      "wanderer-mcu-input", "One step-turn wanderer run's input for the Cortex-M image "
                            "(scripts/run-on-mcu.sh wanderer; uniform/wanderer_mcu_input.hpp)");
  sub->add_option("--map", o->map, "A map file (.map, .yaml, .txt or .ascii)");
  sub->add_option("--size", o->size, "A generated W x H grid, e.g. 100x100");
  sub->add_option("--density", o->density, "Obstacle density of the generated grid");
  sub->add_option("--seed", o->seed, "Seed of the keyed random streams (default 1)");
  sub->add_option("--trial", o->trial, "Trial number of the keyed random streams (default 0)");
  sub->add_option("--sensor", o->sensor, "Sensor distance in cells (default 5)");
  sub->add_option("--limit", o->limit, "Time limit in ticks (default 10 * W * H)");
  sub->add_option("--out", c->out, "The input file to write")->required();
  sub->callback([c] { run(*c); });
}

const antkit::cli::DevRegistration dev_wanderer_mcu_input_registration{
    "wanderer-mcu-input", &register_wanderer_mcu_input};

} // namespace
