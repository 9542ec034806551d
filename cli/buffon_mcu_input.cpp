// `antkit buffon-mcu-input` (plumbing for scripts/run-on-mcu.sh buffon, issue 27): one Buffon
// trial's input for the Cortex-M image (buffon/mcu_input.hpp). The arena is read and built here,
// with CGAL, as `antkit buffon` builds it, and travels as its Q15.16 walls; the options are checked
// as `antkit buffon` checks them (exit 2, located), and a trial whose memory plan exceeds the
// chip's arena is refused with the plan and the limit in the message.
//
//   antkit buffon-mcu-input --arena SPEC|FILE.wkt --steps N [--seed S] [--width W] [--noise X]
//                           --out FILE
#include "buffon_options.hpp"
#include "commands.hpp"

#include <antkit/buffon/mcu_input.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/geometry/atomic_file.hpp>
#include <antkit/geometry/fixed_convert.hpp>
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

void put(std::vector<std::uint8_t>& bytes, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) bytes.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

void run(const McuInputCommand& c) {
  antkit::cli::check_buffon_run_size(1, c.steps, 1);
  antkit::cli::check_buffon_body(c.width, c.noise);
  const antkit::geometry::Arena arena = antkit::cli::read_buffon_arena(c.arena);
  buffon::BodyParams body;
  body.noise = antkit::geometry::fixed_from_double<antkit::kernel::Fx>(c.noise, "--noise");
  const auto width = antkit::geometry::fixed_from_double<antkit::kernel::Fx>(c.width, "--width");
  const buffon::World world(arena.walls_fx(), body); // refuses as `antkit buffon` does
  buffon::PheromoneRaster raster(world.lower(), world.upper(), width);
  buffon::WorldLayout layout;
  (void)buffon::WorldCore::plan(world.walls(), body, layout); // None: the world was built
  const std::uint64_t walls = world.walls().size();
  if (walls > buffon::kMcuArenaBytes / buffon::kMcuWallBytes)
    throw InputError(c.arena, std::to_string(walls) + " walls: more than the chip's input takes (" +
                                  buffon::describe(buffon::McuBuffonError::Walls) + ")");
  const buffon::FixedTrialPlan plan = buffon::plan_fixed_trial(layout, raster, c.steps);
  const std::uint64_t need = buffon::mcu_buffon_bytes(walls, plan);
  if (need > buffon::kMcuArenaBytes) {
    const std::uint64_t fixed = buffon::mcu_walls_bytes(walls) + plan.trail_at;
    const std::string parts = "walls " + std::to_string(buffon::mcu_walls_bytes(walls)) +
                              " B, world buckets " + std::to_string(plan.world) +
                              " B, pheromone raster " + std::to_string(plan.raster) +
                              " B, visit 1's trail " + std::to_string(plan.trail) +
                              " B, crossing index at most " + std::to_string(plan.counter) + " B";
    const std::string limit = "the chip's arena holds " + std::to_string(buffon::kMcuArenaBytes) +
                              " bytes (112 KiB of the STM32F405's 128 KiB of SRAM)";
    // 28 bytes per step: 8 of trail, at most 16 of crossing index and 4 of stamp.
    constexpr std::uint64_t per_step = 28;
    if (fixed + 64 * per_step > buffon::kMcuArenaBytes)
      throw InputError(c.arena, "too large for the chip: the trial needs " + std::to_string(need) +
                                    " bytes (" + parts + "); " + limit +
                                    "; use an arena of fewer walls or a wider --width");
    const std::uint64_t room = (buffon::kMcuArenaBytes - fixed - 4 * 1024) / per_step;
    throw InputError("--steps", "too many steps for the chip: the trial needs " +
                                    std::to_string(need) + " bytes (" + parts + "); " + limit +
                                    "; about " + std::to_string(room) +
                                    " steps per visit fit this arena");
  }
  std::vector<std::uint8_t> bytes(std::begin(buffon::kMcuBuffonMagic),
                                  std::end(buffon::kMcuBuffonMagic));
  put(bytes, c.seed, 8);
  put(bytes, static_cast<std::uint64_t>(c.steps), 8);
  put(bytes, static_cast<std::uint32_t>(width.raw()), 4);
  put(bytes, static_cast<std::uint32_t>(body.noise.raw()), 4);
  put(bytes, static_cast<std::uint32_t>(body.speed.raw()), 4);
  put(bytes, walls, 4);
  for (const auto& w : world.walls())
    for (const std::int32_t v : {w.a.x.raw(), w.a.y.raw(), w.b.x.raw(), w.b.y.raw()})
      put(bytes, static_cast<std::uint32_t>(v), 4);
  antkit::geometry::write_file_atomic(
      c.out, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  std::cout << c.out << ": " << bytes.size() << " bytes, " << walls << " walls, plan " << need
            << " of " << buffon::kMcuArenaBytes << " bytes\n";
}

void register_buffon_mcu_input(CLI::App& app) {
  auto c = std::make_shared<McuInputCommand>();
  auto* sub = app.add_subcommand("buffon-mcu-input",
                                 "Plumbing: one Buffon trial's input for the Cortex-M image "
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

const antkit::cli::Registration reg{"buffon-mcu-input", &register_buffon_mcu_input};

} // namespace
