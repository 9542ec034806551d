// The host's writer of the Cortex-M image's step-turn wanderer input (wanderer_mcu_encode.hpp).
#include <antkit/algorithms/little_endian.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/wanderer_mcu_encode.hpp>
#include <antkit/uniform/wanderer_mcu_input.hpp>
#include <iterator>
#include <string>

namespace antkit::uniform {

McuWandererInput mcu_wanderer_input(const CoverageWorld& world, std::uint64_t seed,
                                    std::uint64_t trial, std::uint64_t limit) {
  using algorithms::append_le;
  if (world.robot_count() != 1)
    throw kernel::InputError("robots", "the Cortex-M image runs one wanderer, not " +
                                           std::to_string(world.robot_count()));
  const kernel::OccupancyGrid& grid = world.map();
  const auto& rays = world.footprint().rays();
  const auto& between = world.footprint().between();
  McuWandererRun run;
  run.width = grid.width(), run.height = grid.height();
  run.rays = static_cast<std::uint32_t>(rays.size());
  run.between = static_cast<std::uint32_t>(between.size());
  const McuWandererPlan plan = plan_mcu_wanderer(run);
  if (grid.width() > 32767 || grid.height() > 32767 || plan.total > kMcuWandererArenaBytes)
    throw kernel::InputError(
        "map", "too large for the chip: the run needs " + std::to_string(plan.total) +
                   " bytes (the map's free cells and the viewed cells, " +
                   std::to_string(StepTurnWorld::bytes(run.width, run.height)) + " B each for " +
                   std::to_string(grid.width()) + " x " + std::to_string(grid.height()) +
                   " cells; the sensor's " + std::to_string(rays.size()) + " rays and " +
                   std::to_string(between.size()) +
                   " cells between, 12 and 4 B each); the chip's arena holds " +
                   std::to_string(kMcuWandererArenaBytes) +
                   " bytes (112 KiB of the STM32F405's 128 KiB of SRAM)");
  McuWandererInput in;
  in.plan = plan.total;
  std::vector<std::uint8_t>& bytes = in.bytes;
  bytes.assign(std::begin(kMcuWandererMagic), std::end(kMcuWandererMagic));
  const Pose& pose = world.robot(0);
  append_le(bytes, seed, 8);
  append_le(bytes, trial, 8);
  append_le(bytes, limit, 8);
  append_le(bytes, world.viewable(), 8);
  append_le(bytes, static_cast<std::uint32_t>(grid.width()), 4);
  append_le(bytes, static_cast<std::uint32_t>(grid.height()), 4);
  append_le(bytes, static_cast<std::uint32_t>(pose.cell.x), 4);
  append_le(bytes, static_cast<std::uint32_t>(pose.cell.y), 4);
  append_le(bytes, pose.bearing, 4);
  append_le(bytes, static_cast<std::uint32_t>(world.footprint().range()), 4);
  append_le(bytes, rays.size(), 4);
  append_le(bytes, between.size(), 4);
  const std::size_t at = bytes.size();
  bytes.resize(at + StepTurnWorld::bytes(run.width, run.height), 0);
  for (std::size_t k = 0; k < grid.size(); ++k)
    if (grid.cells()[k] == kernel::Occupancy::Free)
      bytes[at + k / 8] = static_cast<std::uint8_t>(bytes[at + k / 8] | (1u << (k % 8)));
  for (const auto& ray : rays) {
    append_le(bytes, static_cast<std::uint16_t>(ray.offset.x), 2);
    append_le(bytes, static_cast<std::uint16_t>(ray.offset.y), 2);
    append_le(bytes, ray.first, 4);
    append_le(bytes, ray.count, 4);
  }
  for (const auto& c : between) {
    append_le(bytes, static_cast<std::uint16_t>(c.x), 2);
    append_le(bytes, static_cast<std::uint16_t>(c.y), 2);
  }
  return in;
}

} // namespace antkit::uniform
