#pragma once
// The input of the Cortex-M image for one Buffon trial (mcu/, scripts/run-on-mcu.sh buffon), as
// bytes the host prepares (`antkit dev buffon-mcu-input`: the arena built with CGAL and turned into
// its Q15.16 walls, as `antkit buffon` does) and the chip reads through semihosting. Freestanding:
// the chip's reader and the memory plan are this header; the host writes the same layout.
//
// Little-endian, 40 bytes of header, then the walls:
//   0  char[8] "ANTKBUF1"
//   8  u64     seed
//  16  i64     steps per visit
//  24  i32     trail width, raw Q15.16
//  28  i32     IR noise amplitude, raw Q15.16
//  32  i32     speed per step, raw Q15.16
//  36  u32     walls
//  40  walls x (ax, ay, bx, by), i32 raw Q15.16 each
// The trial is trial 0 of experiment kExperiment (what `antkit buffon --trials 1` runs).
//
// Memory (mcu_buffon_bytes): the image keeps everything of the trial in one arena of
// kMcuArenaBytes (the STC floor's, stc/mcu_input.hpp): the walls, then run_fixed_trial's plan
// (fixed_trial.hpp: the world's buckets, the pheromone raster, visit 1's trail and the bound of
// the crossing index over it). A run that needs more is refused, by the host before QEMU starts
// and again by the chip.
#include <antkit/algorithms/little_endian.hpp>
#include <antkit/buffon/fixed_trial.hpp>
#include <antkit/buffon/world.hpp>
#include <cstddef>
#include <cstdint>
#include <span>

namespace antkit::buffon {

inline constexpr char kMcuBuffonMagic[8] = {'A', 'N', 'T', 'K', 'B', 'U', 'F', '1'};
inline constexpr std::size_t kMcuBuffonHeaderBytes = 40;
inline constexpr std::size_t kMcuWallBytes = 16;
// The image's arena: the STM32F405's 128 KiB of SRAM less 16 KiB for the stack and the image's
// other data (the STC floor's arena, the same buffer; mcu/src/main.cpp checks they agree).
inline constexpr std::size_t kMcuArenaBytes = 112 * 1024;
// The most steps (per visit for a trial, of the walk for RS) an input may ask for: antkit buffon's.
inline constexpr std::int64_t kMcuMaxSteps = 10000000;

struct McuBuffonRun {
  std::uint64_t seed = 1;
  std::int64_t steps = 0;
  BodyParams body{};
  Fx width{};
  std::uint32_t walls = 0;
};

enum class McuBuffonError : std::uint8_t {
  None,
  Short, // fewer bytes than the header
  Magic, // not an antkit Buffon Cortex-M input
  Steps, // steps per visit outside [1, 10000000] (antkit buffon's range)
  Walls, // no wall, or more than the arena could hold
};

[[nodiscard]] constexpr const char* describe(McuBuffonError e) noexcept {
  switch (e) {
  case McuBuffonError::None:
    return "ok";
  case McuBuffonError::Short:
    return "shorter than the 40-byte header";
  case McuBuffonError::Magic:
    return "not an antkit Buffon Cortex-M input (magic ANTKBUF1)";
  case McuBuffonError::Steps:
    return "the steps per visit must be in [1, 10000000]";
  case McuBuffonError::Walls:
    return "the wall count must be in [1, 7168] (the arena's bytes over 16 per wall)";
  }
  return "unknown error";
}

[[nodiscard]] constexpr McuBuffonError
read_mcu_buffon_header(const std::uint8_t* bytes, std::size_t size, McuBuffonRun& run) noexcept {
  if (size < kMcuBuffonHeaderBytes) return McuBuffonError::Short;
  for (std::size_t i = 0; i < 8; ++i)
    if (bytes[i] != static_cast<std::uint8_t>(kMcuBuffonMagic[i])) return McuBuffonError::Magic;
  run.seed = algorithms::load_le(bytes + 8, 8);
  run.steps = static_cast<std::int64_t>(algorithms::load_le(bytes + 16, 8));
  run.width = Fx::from_raw(algorithms::load_le_i32(bytes + 24));
  run.body.noise = Fx::from_raw(algorithms::load_le_i32(bytes + 28));
  run.body.speed = Fx::from_raw(algorithms::load_le_i32(bytes + 32));
  run.walls = static_cast<std::uint32_t>(algorithms::load_le(bytes + 36, 4));
  if (run.steps < 1 || run.steps > kMcuMaxSteps) return McuBuffonError::Steps;
  if (run.walls < 1 || run.walls > kMcuArenaBytes / kMcuWallBytes) return McuBuffonError::Walls;
  return McuBuffonError::None;
}

// Wall i of the input's wall bytes.
[[nodiscard]] constexpr FxSegment read_mcu_wall(const std::uint8_t* walls, std::size_t i) noexcept {
  const std::uint8_t* p = walls + i * kMcuWallBytes;
  return {{Fx::from_raw(algorithms::load_le_i32(p)), Fx::from_raw(algorithms::load_le_i32(p + 4))},
          {Fx::from_raw(algorithms::load_le_i32(p + 8)),
           Fx::from_raw(algorithms::load_le_i32(p + 12))}};
}

// The arena bytes a trial needs on the chip: its walls (as FxSegment, at the arena's start), then
// the trial's plan (fixed_trial.hpp) from the next 8-byte boundary.
[[nodiscard]] constexpr std::uint64_t mcu_walls_bytes(std::uint64_t walls) noexcept {
  return (walls * sizeof(FxSegment) + 7) & ~std::uint64_t{7};
}
[[nodiscard]] constexpr std::uint64_t mcu_buffon_bytes(std::uint64_t walls,
                                                       const FixedTrialPlan& plan) noexcept {
  return mcu_walls_bytes(walls) + plan.total;
}

} // namespace antkit::buffon
