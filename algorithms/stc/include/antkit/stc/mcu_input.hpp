#pragma once
// The input of the Cortex-M image (mcu/, scripts/run-on-mcu.sh): one STC run, as bytes the host
// prepares (`antkit dev stc-mcu-input`) and the chip reads through semihosting. Freestanding: the
// chip's reader is this header; the host's writer is mcu_input() in world.hpp.
//
// Little-endian, 48 bytes of header, then the map:
//   0  char[8] "ANTKMCU1"
//   8  u32     variant: 1 ant (sub-cell marks), 2 ant-edge (lit edges), 3 online
//  12  i32     width, 16 i32 height: the map in sub-cells
//  20  i32     start x, 24 i32 start y
//  28  u32     noise: misread probability in parts per million
//  32  u64     noise seed, 40 u64 noise trial
//  48  the free sub-cells of the cell area, floor_size(width, height).bit_bytes bytes, in the
//      layout of Floor's free_bits (floor.hpp)
// The image keeps its floor in one static array of kMcuFloorBytes (online STC: and its memory of
// the cells seen, FixedCellMemory, in the rest of it); a map whose floor (and memory) needs more
// (mcu_bytes) is refused on the host, with the limit in the message, and again on the chip.
#include <antkit/algorithms/little_endian.hpp>
#include <antkit/stc/floor.hpp>
#include <antkit/stc/online.hpp>
#include <cstddef>
#include <cstdint>

namespace antkit::stc {

inline constexpr char kMcuMagic[8] = {'A', 'N', 'T', 'K', 'M', 'C', 'U', '1'};
inline constexpr std::size_t kMcuHeaderBytes = 48;
// The image's floor arena: the STM32F405's 128 KiB of SRAM less 16 KiB for the stack, the
// image's other data and the input header (mcu/netduinoplus2.ld).
inline constexpr std::size_t kMcuFloorBytes = 112 * 1024;
// The largest map side the input accepts (the map formats' own cap, maps/map_io.hpp, is larger;
// a floor this size would not fit the arena anyway).
inline constexpr std::int32_t kMcuMaxSide = 1 << 14;

enum class McuVariant : std::uint8_t { Ant = 1, AntEdge = 2, Online = 3 };

struct McuRun {
  McuVariant variant = McuVariant::Ant;
  Marker marker = Marker::WholeSubCell; // online: the floor's cells only hold their freedom
  std::int32_t width = 0, height = 0;
  SubCell start{};
  NoiseModel noise{};
};

// Online STC's memory on the chip: room for every tile of 16 x 16 cells the map can touch from any
// start, (cells_x / 16 + 2) x (cells_y / 16 + 2) (FixedCellMemory).
[[nodiscard]] constexpr std::size_t mcu_online_tiles(std::int32_t width,
                                                     std::int32_t height) noexcept {
  const FloorSize s = floor_size(width, height);
  return (static_cast<std::size_t>(s.shape.cells_x) / 16 + 2) *
         (static_cast<std::size_t>(s.shape.cells_y) / 16 + 2);
}

// The arena bytes a run needs: its floor, and for online STC its memory (8-byte aligned after the
// floor).
[[nodiscard]] constexpr std::size_t mcu_bytes(const McuRun& run) noexcept {
  const std::size_t floor = floor_bytes(run.width, run.height, run.marker);
  if (run.variant != McuVariant::Online) return floor;
  return ((floor + 7) & ~std::size_t{7}) +
         FixedCellMemory::bytes_for(mcu_online_tiles(run.width, run.height));
}

enum class McuInputError : std::uint8_t {
  None,
  Short,    // fewer bytes than the header
  Magic,    // not an antkit Cortex-M input
  Variant,  // a variant code other than 1, 2 or 3
  Size,     // width or height out of [2, kMcuMaxSide]
  Start,    // the start outside the cell area
  TooLarge, // the floor (and memory) need more than kMcuFloorBytes
};

[[nodiscard]] constexpr const char* describe(McuInputError e) noexcept {
  switch (e) {
  case McuInputError::None:
    return "ok";
  case McuInputError::Short:
    return "shorter than the 48-byte header";
  case McuInputError::Magic:
    return "not an antkit Cortex-M input (magic ANTKMCU1)";
  case McuInputError::Variant:
    return "variant is not 1 (ant), 2 (ant-edge) or 3 (online)";
  case McuInputError::Size:
    return "width or height outside [2, 16384]";
  case McuInputError::Start:
    return "start outside the map's cells";
  case McuInputError::TooLarge:
    return "the floor (and online STC's memory) need more than the image's 114688 bytes";
  }
  return "?";
}

// Reads the header; the map's bytes follow it (floor_size(width, height).bit_bytes of them).
[[nodiscard]] constexpr McuInputError read_mcu_header(const std::uint8_t* p, std::size_t n,
                                                      McuRun& run) noexcept {
  if (n < kMcuHeaderBytes) return McuInputError::Short;
  for (int i = 0; i < 8; ++i)
    if (p[i] != static_cast<std::uint8_t>(kMcuMagic[i])) return McuInputError::Magic;
  const auto variant = static_cast<std::uint32_t>(algorithms::load_le(p + 8, 4));
  if (variant < 1 || variant > 3) return McuInputError::Variant;
  run.variant = static_cast<McuVariant>(variant);
  run.marker = variant == 2 ? Marker::Edge : Marker::WholeSubCell;
  run.width = algorithms::load_le_i32(p + 12);
  run.height = algorithms::load_le_i32(p + 16);
  if (run.width < 2 || run.height < 2 || run.width > kMcuMaxSide || run.height > kMcuMaxSide)
    return McuInputError::Size;
  run.start = {algorithms::load_le_i32(p + 20), algorithms::load_le_i32(p + 24)};
  const CellGridShape shape{run.width / 2, run.height / 2};
  if (run.start.x < 0 || run.start.y < 0 || !shape.in_bounds(cell_of(run.start)))
    return McuInputError::Start;
  run.noise.ppm = static_cast<std::uint32_t>(algorithms::load_le(p + 28, 4));
  run.noise.seed = algorithms::load_le(p + 32, 8);
  run.noise.trial = algorithms::load_le(p + 40, 8);
  if (mcu_bytes(run) > kMcuFloorBytes) return McuInputError::TooLarge;
  return McuInputError::None;
}

} // namespace antkit::stc
