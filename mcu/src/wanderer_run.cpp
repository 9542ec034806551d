// One step-turn wanderer run on the robot's own processor (issue 27): what `antkit cover --algo rw
// --robots 1` runs on the host, with the controller, the world's ticks and the trace hash on the
// chip. The host sends the map's Free cells as bits, the start it placed, the viewable cells it
// counted and the sensor's footprint (uniform/wanderer_mcu_input.hpp); the chip runs the C API's
// wanderer (antkit_step_turn_wanderer: StepTurnCore, uniform/step_turn.hpp) in StepTurnWorld
// (uniform/step_turn_world.hpp: the host's coverage_rules.hpp and coverage_ticks.hpp over bits in
// the arena) and prints the numbers `antkit cover --format json` prints.
#include "buffon_run.hpp"
#include "semihost.hpp"
#include "text.hpp"
#include "ticks.hpp"

#include <antkit/c/antkit.h>
#include <antkit/uniform/wanderer_mcu_input.hpp>

namespace antkit::mcu {

using namespace antkit::uniform;

namespace {

// The C API's wanderer as run_step_turn's controller.
struct CWanderer {
  antkit_step_turn_wanderer state;
  CWanderer(std::uint64_t seed, std::uint64_t trial) noexcept {
    antkit_step_turn_wanderer_init(&state, seed, trial, 0);
  }
  Command step(bool front_free) noexcept {
    return {static_cast<Action>(antkit_step_turn_wanderer_step(&state, front_free ? 1 : 0))};
  }
};

// The run (kept out of line so that the map file shows the step path's size).
[[gnu::noinline]] StepTurnResult wander(StepTurnWorld& world, CWanderer& wanderer,
                                        std::uint64_t limit) {
  return run_step_turn(world, wanderer, limit);
}

// Reads `count` records of `size` bytes from `file` and hands each to put(i, bytes).
template <class Put>
bool read_records(std::int32_t file, std::uint32_t count, std::size_t size, Put put) {
  std::uint8_t piece[64 * 12];
  std::uint32_t done = 0;
  while (done < count) {
    const std::uint32_t n = count - done < 64 ? count - done : 64;
    if (mcu::read(file, piece, n * size) != n * size) return false;
    for (std::uint32_t i = 0; i < n; ++i) put(done + i, piece + i * size);
    done += n;
  }
  return true;
}

} // namespace

int run_wanderer(const char* path, std::int32_t file, std::int32_t size, const std::uint8_t* head,
                 std::size_t got, std::uint8_t* arena, std::size_t bytes) {
  std::uint8_t header[kMcuWandererHeaderBytes];
  for (std::size_t k = 0; k < got && k < sizeof header; ++k) header[k] = head[k];
  if (got < sizeof header &&
      mcu::read(file, header + got, sizeof header - got) != sizeof header - got)
    return refuse(path, describe(McuWandererError::Short));
  McuWandererRun run;
  if (const McuWandererError e = read_mcu_wanderer_header(header, sizeof header, run);
      e != McuWandererError::None)
    return refuse(path, describe(e));
  if (size < 0 || static_cast<std::uint64_t>(size) != mcu_wanderer_file_bytes(run))
    return refuse(path, "its length is not the header, the map's bits and the footprint");
  const McuWandererPlan plan = plan_mcu_wanderer(run);
  if (plan.total > bytes) return refuse(path, describe(McuWandererError::Arena));
  const std::uint64_t bits = StepTurnWorld::bytes(run.width, run.height);
  if (mcu::read(file, arena + plan.free_at, bits) != bits)
    return refuse(path, "ends inside the map");
  auto* rays = reinterpret_cast<StepTurnRay*>(arena + plan.rays_at);
  auto* between = reinterpret_cast<StepTurnOffset*>(arena + plan.between_at);
  if (!read_records(file, run.rays, kMcuRayBytes,
                    [rays](std::uint32_t i, const std::uint8_t* p) { rays[i] = read_mcu_ray(p); }))
    return refuse(path, "ends inside the sensor's rays");
  if (!read_records(
          file, run.between, kMcuOffsetBytes,
          [between](std::uint32_t i, const std::uint8_t* p) { between[i] = read_mcu_offset(p); }))
    return refuse(path, "ends inside the cells between");
  mcu::close(file);
  const auto* free_bits = arena + plan.free_at;
  if (const char* why =
          check_mcu_wanderer_records(run, free_bits, {rays, run.rays}, {between, run.between}))
    return refuse(path, why);
  mcu::ticks_start();
  static StepTurnWorld world;
  world.init(run.width, run.height, free_bits, arena + plan.viewed_at, {rays, run.rays},
             {between, run.between}, run.start, run.bearing, run.viewable);
  CWanderer wanderer(run.seed, run.trial);
  const StepTurnResult result = wander(world, wanderer, run.limit);
  const std::uint64_t ticks = mcu::ticks_now();
  Text t;
  t << "{\"algo\": \"rw\", \"robots\": 1, \"viewed\": ";
  t.u64(result.viewed) << ", \"viewable\": ";
  t.u64(result.viewable) << ", \"movements\": ";
  t.u64(result.movements) << ", \"moves\": ";
  t.u64(result.moves) << ", \"hash\": \"";
  t.hex(result.hash) << "\", \"stop\": \""
                     << (result.stop == StepTurnStop::Complete ? "complete" : "time-limit")
                     << "\", \"width\": " << std::int64_t{run.width}
                     << ", \"height\": " << std::int64_t{run.height}
                     << ", \"sensor\": " << std::int64_t{run.sensor} << ", \"seed\": ";
  t.u64(run.seed) << ", \"trial\": ";
  t.u64(run.trial) << ", \"limit\": ";
  t.u64(run.limit) << ", \"draws\": ";
  t.u64(antkit_step_turn_wanderer_steps(&wanderer.state))
      << ", \"arena_bytes\": " << static_cast<std::int64_t>(plan.total)
      << ", \"arena_limit\": " << static_cast<std::int64_t>(bytes)
      << ", \"ticks\": " << static_cast<std::int64_t>(ticks) << "}\n";
  t.flush();
  return 0;
}

} // namespace antkit::mcu
