// `antkit dev buffon-mcu-input` (plumbing for scripts/run-on-mcu.sh buffon, issue 27): one Buffon
// trial's input for the Cortex-M image (buffon/mcu_input.hpp). The arena is read and built here,
// with CGAL, as `antkit buffon` builds it, and travels as its Q15.16 walls; the options are checked
// by `antkit buffon`'s own checks (buffon_options.hpp: exit 2, located), and a trial whose memory
// plan exceeds the chip's arena is refused with the plan and the limit in the message.
//
//   antkit dev buffon-mcu-input --arena SPEC|FILE.wkt --steps N [--seed S] [--width W]
//                               [--noise X] --out FILE
#include "buffon_options.hpp"
#include "commands.hpp"

#include <antkit/buffon/mcu_encode.hpp>
#include <antkit/buffon/mcu_input.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/io/atomic_file.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace {

using antkit::kernel::InputError;
namespace buffon = antkit::buffon;

struct McuInputCommand {
  std::string arena, out;
  std::int64_t steps = buffon::kDefaultSteps;
  std::uint64_t seed = 1;
  double width = 0.1, noise = 0.0;
};

void run(const McuInputCommand& c) {
  antkit::cli::check_buffon_run_size(1, c.steps, 1);
  antkit::cli::check_buffon_body(c.width, c.noise);
  const antkit::geometry::Arena arena = antkit::cli::read_buffon_arena(c.arena);
  const buffon::World world = antkit::cli::buffon_world(arena, c.noise);
  const auto width = antkit::geometry::fixed_from_double<antkit::kernel::Fx>(c.width, "--width");
  buffon::McuInput in;
  try {
    in = buffon::mcu_buffon_input(world, width, c.seed, c.steps);
  } catch (const InputError& e) {
    if (e.where() != "arena") throw;
    throw InputError(c.arena, e.message());
  }
  const auto& bytes = in.bytes;
  antkit::io::write_file_atomic(
      c.out, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  std::cout << c.out << ": " << bytes.size() << " bytes, " << in.walls << " walls, plan " << in.plan
            << " of " << buffon::kMcuArenaBytes << " bytes\n";
}

void register_buffon_mcu_input(CLI::App& app) {
  auto c = std::make_shared<McuInputCommand>();
  auto* sub = app.add_subcommand("buffon-mcu-input",
                                 "One Buffon trial's input for the Cortex-M image "
                                 "(scripts/run-on-mcu.sh buffon; buffon/mcu_input.hpp)");
  sub->add_option("--arena", c->arena, "A named arena spec (circle:d=10, ...) or FILE.wkt")
      ->required();
  sub->add_option("--steps", c->steps, "Steps per visit")->required();
  sub->add_option("--seed", c->seed, "Seed of the keyed streams (default 1)");
  sub->add_option("--width", c->width, "Pheromone trail width in robot diameters (0.1)");
  sub->add_option("--noise", c->noise, "IR sensor noise amplitude in [0, 1] (default 0)");
  sub->add_option("--out", c->out, "The input file to write")->required();
  sub->callback([c] { run(*c); });
}

const antkit::cli::DevRegistration dev_buffon_mcu_input_registration{"buffon-mcu-input",
                                                                     &register_buffon_mcu_input};

} // namespace
