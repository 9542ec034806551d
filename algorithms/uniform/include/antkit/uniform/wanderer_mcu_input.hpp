#pragma once
// The input of the Cortex-M image for one step-turn wanderer run (mcu/src/wanderer_run.cpp,
// scripts/run-on-mcu.sh wanderer), as bytes the host prepares (`antkit dev wanderer-mcu-input`:
// the map read or generated, the robot placed and the world checked as `antkit cover --algo rw
// --robots 1` does, the viewable cells counted and the sensor's footprint computed by
// SensorFootprint) and the chip reads through semihosting. Freestanding.
//
// Little-endian, 72 bytes of header, then the map's Free cells as bits (row-major, LSB first,
// StepTurnWorld::bytes), the rays (12 bytes each: i16 dx, i16 dy, u32 first, u32 count) and the
// cells between (4 bytes each: i16 dx, i16 dy):
//   0  char[8] "ANTKWAN1"
//   8  u64     seed            16  u64  trial          24  u64  limit (ticks)
//  32  u64     viewable cells  40  u32  width          44  u32  height
//  48  i32     start x         52  i32  start y        56  u32  start bearing (0..7)
//  60  u32     sensor range    64  u32  rays           68  u32  cells between
//
// Memory (mcu_wanderer_bytes): in the image's one arena of kMcuWandererArenaBytes (the STC floor's
// 112 KiB), the Free bits, the viewed bits, the rays and the cells between, each part 8-byte
// aligned. A run that needs more is refused, by the host before QEMU starts and by the chip.
#include <antkit/algorithms/little_endian.hpp>
#include <antkit/uniform/step_turn_world.hpp>
#include <cstddef>
#include <cstdint>
#include <span>

namespace antkit::uniform {

inline constexpr char kMcuWandererMagic[8] = {'A', 'N', 'T', 'K', 'W', 'A', 'N', '1'};
inline constexpr std::size_t kMcuWandererHeaderBytes = 72;
inline constexpr std::size_t kMcuRayBytes = 12;
inline constexpr std::size_t kMcuOffsetBytes = 4;
// The image's arena (mcu/src/main.cpp checks that it is the STC floor's).
inline constexpr std::size_t kMcuWandererArenaBytes = 112 * 1024;

struct McuWandererRun {
  std::uint64_t seed = 1, trial = 0, limit = 0, viewable = 0;
  std::int32_t width = 0, height = 0;
  kernel::Cell start{};
  std::uint8_t bearing = 0;
  std::uint32_t sensor = 0, rays = 0, between = 0;
};

// Byte offsets of the parts in the arena, and the total.
struct McuWandererPlan {
  std::uint64_t free_at = 0, viewed_at = 0, rays_at = 0, between_at = 0, total = 0;
};
[[nodiscard]] constexpr McuWandererPlan plan_mcu_wanderer(const McuWandererRun& r) noexcept {
  const auto align8 = [](std::uint64_t n) { return (n + 7) & ~std::uint64_t{7}; };
  McuWandererPlan p;
  const std::uint64_t bits = StepTurnWorld::bytes(r.width, r.height);
  p.viewed_at = align8(bits);
  p.rays_at = align8(p.viewed_at + bits);
  p.between_at = align8(p.rays_at + std::uint64_t{r.rays} * sizeof(StepTurnRay));
  p.total = p.between_at + std::uint64_t{r.between} * sizeof(StepTurnOffset);
  return p;
}
// The input file's length: the header, the Free bits, the rays and the cells between.
[[nodiscard]] constexpr std::uint64_t mcu_wanderer_file_bytes(const McuWandererRun& r) noexcept {
  return kMcuWandererHeaderBytes + StepTurnWorld::bytes(r.width, r.height) +
         std::uint64_t{r.rays} * kMcuRayBytes + std::uint64_t{r.between} * kMcuOffsetBytes;
}

enum class McuWandererError : std::uint8_t {
  None,
  Short,  // fewer bytes than the header
  Magic,  // not an antkit wanderer Cortex-M input
  Size,   // width or height outside [1, 32767]
  Start,  // the start off the map or its bearing above 7
  Sensor, // the sensor range above 255, no ray, or a ray count that is not the range's
  Arena,  // the plan exceeds the arena
};

[[nodiscard]] constexpr const char* describe(McuWandererError e) noexcept {
  switch (e) {
  case McuWandererError::None:
    return "ok";
  case McuWandererError::Short:
    return "shorter than the 72-byte header";
  case McuWandererError::Magic:
    return "not an antkit wanderer Cortex-M input (magic ANTKWAN1)";
  case McuWandererError::Size:
    return "the map's width and height must be in [1, 32767]";
  case McuWandererError::Start:
    return "the start must lie on the map with a bearing in [0, 7]";
  case McuWandererError::Sensor:
    return "the sensor range must be in [0, 255] with at least one ray";
  case McuWandererError::Arena:
    return "the map's bits and the sensor's footprint exceed the chip's arena of 114688 bytes";
  }
  return "unknown error";
}

[[nodiscard]] constexpr McuWandererError
read_mcu_wanderer_header(const std::uint8_t* b, std::size_t size, McuWandererRun& r) noexcept {
  if (size < kMcuWandererHeaderBytes) return McuWandererError::Short;
  for (std::size_t i = 0; i < 8; ++i)
    if (b[i] != static_cast<std::uint8_t>(kMcuWandererMagic[i])) return McuWandererError::Magic;
  r.seed = algorithms::load_le(b + 8, 8);
  r.trial = algorithms::load_le(b + 16, 8);
  r.limit = algorithms::load_le(b + 24, 8);
  r.viewable = algorithms::load_le(b + 32, 8);
  const std::uint64_t w = algorithms::load_le(b + 40, 4), h = algorithms::load_le(b + 44, 4);
  if (w < 1 || h < 1 || w > 32767 || h > 32767) return McuWandererError::Size;
  r.width = static_cast<std::int32_t>(w), r.height = static_cast<std::int32_t>(h);
  r.start = {algorithms::load_le_i32(b + 48), algorithms::load_le_i32(b + 52)};
  const std::uint64_t bearing = algorithms::load_le(b + 56, 4);
  if (r.start.x < 0 || r.start.y < 0 || r.start.x >= r.width || r.start.y >= r.height ||
      bearing > 7)
    return McuWandererError::Start;
  r.bearing = static_cast<std::uint8_t>(bearing);
  r.sensor = static_cast<std::uint32_t>(algorithms::load_le(b + 60, 4));
  r.rays = static_cast<std::uint32_t>(algorithms::load_le(b + 64, 4));
  r.between = static_cast<std::uint32_t>(algorithms::load_le(b + 68, 4));
  if (r.sensor > 255 || r.rays < 1) return McuWandererError::Sensor;
  if (plan_mcu_wanderer(r).total > kMcuWandererArenaBytes) return McuWandererError::Arena;
  return McuWandererError::None;
}

// Ray i and offset i of the input's bytes.
[[nodiscard]] constexpr StepTurnRay read_mcu_ray(const std::uint8_t* p) noexcept {
  return {static_cast<std::int16_t>(algorithms::load_le(p, 2)),
          static_cast<std::int16_t>(algorithms::load_le(p + 2, 2)),
          static_cast<std::uint32_t>(algorithms::load_le(p + 4, 4)),
          static_cast<std::uint32_t>(algorithms::load_le(p + 8, 4))};
}
[[nodiscard]] constexpr StepTurnOffset read_mcu_offset(const std::uint8_t* p) noexcept {
  return {static_cast<std::int16_t>(algorithms::load_le(p, 2)),
          static_cast<std::int16_t>(algorithms::load_le(p + 2, 2))};
}

// The checks the chip makes on an input's records once it has read them, before the run: each ray
// lies within the sensor's range and its cells between within the list and within the box of the
// robot and the ray's target, which keeps every read of the run on the map (coverage_rules.hpp's
// ray_clear); and the start lies on a free cell. SensorFootprint's footprint always passes. Null
// when the records pass, else the reason.
[[nodiscard]] constexpr const char*
check_mcu_wanderer_records(const McuWandererRun& run, const std::uint8_t* free_bits,
                           std::span<const StepTurnRay> rays,
                           std::span<const StepTurnOffset> between) noexcept {
  const auto r = static_cast<std::int32_t>(run.sensor);
  for (const StepTurnRay& ray : rays) {
    if (ray.dx < -r || ray.dx > r || ray.dy < -r || ray.dy > r ||
        std::uint64_t{ray.first} + ray.count > between.size())
      return "a sensor ray lies outside the sensor's range or its list";
    for (std::uint32_t k = 0; k < ray.count; ++k) {
      const StepTurnOffset d = between[ray.first + k];
      const bool in_x = ray.dx < 0 ? d.dx >= ray.dx && d.dx <= 0 : d.dx >= 0 && d.dx <= ray.dx;
      const bool in_y = ray.dy < 0 ? d.dy >= ray.dy && d.dy <= 0 : d.dy >= 0 && d.dy <= ray.dy;
      if (!in_x || !in_y) return "a cell between lies outside its ray's box";
    }
  }
  const std::uint64_t s =
      static_cast<std::uint64_t>(run.start.y) * static_cast<std::uint64_t>(run.width) +
      static_cast<std::uint64_t>(run.start.x);
  if (((free_bits[s / 8] >> (s % 8)) & 1u) == 0) return "the start does not lie on a free cell";
  return nullptr;
}

} // namespace antkit::uniform
