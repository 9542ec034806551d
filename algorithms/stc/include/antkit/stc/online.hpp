#pragma once
// Online STC (Gabriely & Rimon, as paper 002 recalls it): the map is unknown; the robot senses
// which of the four neighbour cells of its current cell are free, builds the spanning tree
// depth-first as it goes, scanning counter-clockwise from the parent, and remembers the cells it
// has seen. Its position is dead-reckoned in cells relative to the start cell, which is (0, 0): the
// robot knows nothing of the map's size or origin.
//
// Memory is proportional to the cells seen: a hash table of 16 x 16 tiles of cells, one byte per
// cell (visited, direction of the parent), a tile allocated when the robot first enters a cell of
// it. Tiles rather than single cells because consecutive moves touch neighbouring cells, so the
// last tile used answers almost every question without hashing; a tile costs 256 bytes, a constant
// factor per cell seen. Lookups only (never iteration), so the table's layout cannot influence a
// decision (DESIGN.md determinism rule 3).
#include <antkit/stc/subcell.hpp>
#include <array>
#include <cstdint>
#include <vector>

namespace antkit::stc {

// What online STC senses: bit d set when the neighbour cell in direction d is free (all four of
// its sub-cells free and inside the map).
struct CellObservation {
  std::uint8_t free_neighbours = 0;
};

// The cells seen, by position relative to the start cell.
class CellMemory {
public:
  static constexpr std::uint8_t kVisited = 0x04; // low two bits: direction of the parent
  static constexpr int kTileBits = 4;            // 16 x 16 cells per tile

  CellMemory();
  // 0 when the cell was never visited.
  [[nodiscard]] std::uint8_t get(Cell c);
  void set(Cell c, std::uint8_t value);
  [[nodiscard]] std::size_t tiles() const noexcept { return tiles_.size(); }
  [[nodiscard]] std::size_t bytes() const noexcept;

private:
  std::uint8_t* tile_for(Cell c, bool create);

  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> slots_; // tile index per key, kEmpty when the slot is free
  std::vector<std::array<std::uint8_t, 256>> tiles_;
  std::uint64_t last_key_ = ~std::uint64_t{0};
  std::uint8_t* last_tile_ = nullptr;
};

class OnlineStc {
public:
  using Observation = CellObservation;
  using Command = stc::Command;

  // `start_quadrant` is the quadrant (SE 0, NE 1, NW 2, SW 3) of the sub-cell the robot starts in.
  explicit OnlineStc(int start_quadrant);

  Command step(const Observation& seen);

  [[nodiscard]] const CellMemory& memory() const noexcept { return memory_; }

private:
  CellMemory memory_;
  Cell cell_{0, 0}; // relative to the start cell
  int q_;
  int q0_;
  int parent_ = -1; // direction of the current cell's parent, -1 at the root
  bool done_ = false;
};

} // namespace antkit::stc
