// `antkit dev rs-mcu-input` (plumbing for scripts/run-on-mcu.sh rs, issue 27): one Randomized
// Search walk (paper 000, Section 8.1; buffon/checkpoints.hpp) for the Cortex-M image
// (buffon/rs_mcu_input.hpp). The arena is read and built here, with CGAL, as `antkit buffon`
// builds it, and travels as its Q15.16 walls; the options are checked by `antkit buffon`'s own
// checks (buffon_options.hpp: exit 2, located; the steps against the chip's bound), and a walk
// whose memory plan exceeds the chip's arena is refused with the plan and the limit in the message.
//
//   antkit dev rs-mcu-input --arena SPEC|FILE.wkt --steps N [--seed S] [--noise X] --out FILE
//   antkit dev rs-mcu-input --arena SPEC|FILE.wkt --steps N [--seed S] [--noise X] --host
//
// With --host it writes no input and runs the same walk on the host instead
// (buffon::run_rs: run_visit over the host's World, the raster in a vector), printing
// {"steps", "seed", "cells", "cell_raw", "area", "length_raw", "blocked", "hash"}: the numbers the
// chip's JSON must repeat. (RS has no command of its own; this is the host side of the check.)
#include "buffon_options.hpp"
#include "commands.hpp"
#include "output.hpp"

#include <antkit/buffon/checkpoints.hpp>
#include <antkit/buffon/mcu_encode.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/rs_mcu_input.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/hash.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace {

using antkit::kernel::InputError;
namespace buffon = antkit::buffon;

struct RsInputCommand {
  std::string arena, out;
  std::int64_t steps = 0;
  std::uint64_t seed = 1;
  double noise = 0.0;
  bool host = false;
};

void run(const RsInputCommand& c) {
  if (c.steps < 1 || c.steps > buffon::kMcuMaxSteps) // --host too, so before the writer's check
    throw InputError("--steps", buffon::describe_rs(buffon::McuBuffonError::Steps));
  antkit::cli::check_buffon_noise(c.noise);
  if (c.host == !c.out.empty())
    throw InputError("--out", "give either --out FILE (the chip's input) or --host");
  const antkit::geometry::Arena arena = antkit::cli::read_buffon_arena(c.arena);
  const buffon::World world = antkit::cli::buffon_world(arena, c.noise);
  if (c.host) {
    buffon::TrialParams params;
    params.seed = c.seed;
    params.steps = c.steps;
    const buffon::RsRun r = buffon::run_rs(world, params, 0);
    nlohmann::json j;
    j["steps"] = c.steps;
    j["seed"] = c.seed;
    j["cells"] = r.cells;
    j["cell_raw"] = r.cell_raw;
    const double cell = static_cast<double>(r.cell_raw) / 65536.0;
    j["area"] = static_cast<double>(r.cells) * cell * cell;
    j["length_raw"] = r.length_raw;
    j["blocked"] = r.blocked;
    j["hash"] = antkit::kernel::hash_hex(r.hash);
    antkit::cli::emit(j, antkit::cli::Format::Json, std::cout);
    return;
  }
  buffon::McuInput in;
  try {
    in = buffon::mcu_rs_input(world, c.seed, c.steps);
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

void register_rs_mcu_input(CLI::App& app) {
  auto c = std::make_shared<RsInputCommand>();
  auto* sub = app.add_subcommand("rs-mcu-input",
                                 "One Randomized Search walk's input for the Cortex-M "
                                 "image (scripts/run-on-mcu.sh rs; buffon/rs_mcu_input.hpp), or "
                                 "with --host the same walk run on the host");
  sub->add_option("--arena", c->arena, "A named arena spec (square:area=25, ...) or FILE.wkt")
      ->required();
  sub->add_option("--steps", c->steps, "Steps of the walk")->required();
  sub->add_option("--seed", c->seed, "Seed of the keyed streams (default 1)");
  sub->add_option("--noise", c->noise, "IR sensor noise amplitude in [0, 1] (default 0)");
  sub->add_option("--out", c->out, "The input file to write");
  sub->add_flag("--host", c->host, "Run the walk on the host and print its JSON instead");
  sub->callback([c] { run(*c); });
}

const antkit::cli::DevRegistration dev_rs_mcu_input_registration{"rs-mcu-input",
                                                                 &register_rs_mcu_input};

} // namespace
