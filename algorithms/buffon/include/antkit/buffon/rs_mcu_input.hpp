#pragma once
// The input of the Cortex-M image for one Randomized Search walk (mcu/src/rs_run.cpp,
// scripts/run-on-mcu.sh rs), as bytes the host prepares (`antkit dev rs-mcu-input`: the arena built
// with CGAL and sent as its Q15.16 walls, as for Buffon, mcu_input.hpp) and the chip reads through
// semihosting. Freestanding.
//
// Little-endian, 40 bytes of header, then the walls (mcu_input.hpp's 16 bytes each):
//   0  char[8] "ANTKRS01"
//   8  u64     seed
//  16  i64     steps
//  24  i32     IR noise amplitude, raw Q15.16
//  28  i32     speed per step, raw Q15.16
//  32  u32     walls
//  36  u32     0 (reserved)
// The walk is trial 0's RS walk (checkpoints.hpp run_rs, randomized_search.hpp run_fixed_rs).
//
// Memory (mcu_rs_bytes): in the image's one arena of kMcuArenaBytes, the walls, then
// run_fixed_rs's plan (the world's buckets and RS's raster, a byte per 0.1 x 0.1 cell of the
// walls' box). Nothing grows with the steps. A walk that needs more is refused, by the host
// before QEMU starts and again by the chip.
#include <antkit/algorithms/little_endian.hpp>
#include <antkit/buffon/mcu_input.hpp>
#include <antkit/buffon/randomized_search.hpp>
#include <cstddef>
#include <cstdint>

namespace antkit::buffon {

inline constexpr char kMcuRsMagic[8] = {'A', 'N', 'T', 'K', 'R', 'S', '0', '1'};
inline constexpr std::size_t kMcuRsHeaderBytes = 40;
static_assert(kMcuRsHeaderBytes == kMcuBuffonHeaderBytes); // the image reads one header's bytes

struct McuRsRun {
  std::uint64_t seed = 1;
  std::int64_t steps = 0;
  BodyParams body{};
  std::uint32_t walls = 0;
};

// McuBuffonError's meanings (Short, Magic, Steps: "the steps must be in [1, 10000000]", Walls).
[[nodiscard]] constexpr const char* describe_rs(McuBuffonError e) noexcept {
  switch (e) {
  case McuBuffonError::Short:
    return "shorter than the 40-byte header";
  case McuBuffonError::Magic:
    return "not an antkit RS Cortex-M input (magic ANTKRS01)";
  case McuBuffonError::Steps:
    return "the steps must be in [1, 10000000]";
  default:
    return describe(e);
  }
}

[[nodiscard]] constexpr McuBuffonError
read_mcu_rs_header(const std::uint8_t* bytes, std::size_t size, McuRsRun& run) noexcept {
  if (size < kMcuRsHeaderBytes) return McuBuffonError::Short;
  for (std::size_t i = 0; i < 8; ++i)
    if (bytes[i] != static_cast<std::uint8_t>(kMcuRsMagic[i])) return McuBuffonError::Magic;
  run.seed = algorithms::load_le(bytes + 8, 8);
  run.steps = static_cast<std::int64_t>(algorithms::load_le(bytes + 16, 8));
  run.body.noise = Fx::from_raw(algorithms::load_le_i32(bytes + 24));
  run.body.speed = Fx::from_raw(algorithms::load_le_i32(bytes + 28));
  run.walls = static_cast<std::uint32_t>(algorithms::load_le(bytes + 32, 4));
  if (run.steps < 1 || run.steps > kMcuMaxSteps) return McuBuffonError::Steps;
  if (run.walls < 1 || run.walls > kMcuArenaBytes / kMcuWallBytes) return McuBuffonError::Walls;
  return McuBuffonError::None;
}

// The arena bytes a walk needs on the chip: its walls, then run_fixed_rs's plan.
[[nodiscard]] constexpr std::uint64_t mcu_rs_bytes(std::uint64_t walls, const WorldLayout& world,
                                                   std::uint64_t raster_cells) noexcept {
  return mcu_walls_bytes(walls) + fixed_rs_bytes(world, raster_cells);
}

} // namespace antkit::buffon
