// The host's writers of the Cortex-M image's Buffon and RS inputs (mcu_encode.hpp).
#include <antkit/algorithms/little_endian.hpp>
#include <antkit/buffon/mcu_digest_input.hpp>
#include <antkit/buffon/mcu_encode.hpp>
#include <antkit/buffon/mcu_input.hpp>
#include <antkit/buffon/pheromone_raster.hpp>
#include <antkit/buffon/rs_mcu_input.hpp>
#include <antkit/kernel/input_error.hpp>
#include <iterator>
#include <string>

namespace antkit::buffon {
namespace {

using algorithms::append_le;
using kernel::InputError;

std::string chip_limit() {
  return "the chip's arena holds " + std::to_string(kMcuArenaBytes) +
         " bytes (112 KiB of the STM32F405's 128 KiB of SRAM)";
}

// The world's buckets as the chip lays them out (WorldCore::plan on the walls the world was built
// from, which succeeds: the world was built), and a refusal of more walls than the input takes.
WorldLayout chip_layout(const World& world) {
  const std::uint64_t walls = world.walls().size();
  if (walls > kMcuArenaBytes / kMcuWallBytes)
    throw InputError("arena", std::to_string(walls) + " walls: more than the chip's input takes (" +
                                  describe(McuBuffonError::Walls) + ")");
  WorldLayout layout;
  (void)WorldCore::plan(world.walls(), world.body(), layout);
  return layout;
}

void append_walls(std::vector<std::uint8_t>& bytes, const World& world) {
  for (const auto& w : world.walls())
    for (const std::int32_t v : {w.a.x.raw(), w.a.y.raw(), w.b.x.raw(), w.b.y.raw()})
      append_le(bytes, static_cast<std::uint32_t>(v), 4);
}

} // namespace

McuInput mcu_buffon_input(const World& world, Fx width, std::uint64_t seed, std::int64_t steps,
                          McuBuffonProgram program) {
  if (steps < 1 || steps > kMcuMaxSteps)
    throw InputError("steps per visit", describe(McuBuffonError::Steps));
  const WorldLayout layout = chip_layout(world);
  RasterCore raster; // its size only: the chip holds the bits, the host needs none
  if (const RasterError e = raster.init(world.lower(), world.upper(), width);
      e != RasterError::None)
    throw InputError("trail width", describe(e)); // as PheromoneRaster refuses it
  const std::uint64_t walls = world.walls().size();
  const FixedTrialPlan plan = plan_fixed_trial(layout, raster, steps);
  const std::uint64_t need = mcu_buffon_bytes(walls, plan);
  if (need > kMcuArenaBytes) {
    const std::uint64_t fixed = mcu_walls_bytes(walls) + plan.trail_at;
    const std::string parts = "walls " + std::to_string(mcu_walls_bytes(walls)) +
                              " B, world buckets " + std::to_string(plan.world) +
                              " B, pheromone raster " + std::to_string(plan.raster) +
                              " B, visit 1's trail " + std::to_string(plan.trail) +
                              " B, crossing index at most " + std::to_string(plan.counter) + " B";
    // 28 bytes per step: 8 of trail, at most 16 of crossing index and 4 of stamp.
    constexpr std::uint64_t per_step = 28;
    if (fixed + 64 * per_step > kMcuArenaBytes)
      throw InputError("arena", "too large for the chip: the trial needs " + std::to_string(need) +
                                    " bytes (" + parts + "); " + chip_limit() +
                                    "; use an arena of fewer walls or a wider trail width");
    const std::uint64_t room = (kMcuArenaBytes - fixed - 4 * 1024) / per_step;
    throw InputError("steps per visit", "too many steps for the chip: the trial needs " +
                                            std::to_string(need) + " bytes (" + parts + "); " +
                                            chip_limit() + "; about " + std::to_string(room) +
                                            " steps per visit fit this arena");
  }
  McuInput in;
  in.plan = need;
  in.walls = walls;
  const char* magic = program == McuBuffonProgram::Digest ? kMcuBuffonDigestMagic : kMcuBuffonMagic;
  in.bytes.assign(magic, magic + 8);
  append_le(in.bytes, seed, 8);
  append_le(in.bytes, static_cast<std::uint64_t>(steps), 8);
  append_le(in.bytes, static_cast<std::uint32_t>(width.raw()), 4);
  append_le(in.bytes, static_cast<std::uint32_t>(world.body().noise.raw()), 4);
  append_le(in.bytes, static_cast<std::uint32_t>(world.body().speed.raw()), 4);
  append_le(in.bytes, walls, 4);
  append_walls(in.bytes, world);
  return in;
}

McuInput mcu_rs_input(const World& world, std::uint64_t seed, std::int64_t steps) {
  if (steps < 1 || steps > kMcuMaxSteps)
    throw InputError("steps", describe_rs(McuBuffonError::Steps));
  const WorldLayout layout = chip_layout(world);
  ByteRasterCore raster;
  if (!raster.init(layout.lower, layout.upper, kRsCellRaw))
    throw InputError("arena", "RS's raster has more than 2^32 cells");
  const std::uint64_t walls = world.walls().size();
  const std::uint64_t need = mcu_rs_bytes(walls, layout, raster.cells());
  if (need > kMcuArenaBytes)
    throw InputError("arena", "too large for the chip: the walk needs " + std::to_string(need) +
                                  " bytes (walls " + std::to_string(mcu_walls_bytes(walls)) +
                                  " B, world buckets " + std::to_string(layout.bytes()) +
                                  " B, RS raster " + std::to_string(raster.cells()) +
                                  " B: one per 0.1 x 0.1 cell); " + chip_limit() +
                                  "; use an arena of fewer walls or a smaller box");
  McuInput in;
  in.plan = need;
  in.walls = walls;
  in.bytes.assign(std::begin(kMcuRsMagic), std::end(kMcuRsMagic));
  append_le(in.bytes, seed, 8);
  append_le(in.bytes, static_cast<std::uint64_t>(steps), 8);
  append_le(in.bytes, static_cast<std::uint32_t>(world.body().noise.raw()), 4);
  append_le(in.bytes, static_cast<std::uint32_t>(world.body().speed.raw()), 4);
  append_le(in.bytes, walls, 4);
  append_le(in.bytes, 0, 4);
  append_walls(in.bytes, world);
  return in;
}

} // namespace antkit::buffon
