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
// decision (DESIGN.md determinism rule 3). On a microcontroller the same controller runs over
// FixedCellMemory, the table in a buffer the caller provides (issue 27).
#include <antkit/kernel/random.hpp>
#include <antkit/stc/subcell.hpp>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace antkit::stc {

// What online STC senses: bit d set when the neighbour cell in direction d is free (all four of
// its sub-cells free and inside the map).
struct CellObservation {
  std::uint8_t free_neighbours = 0;
};

// The cells seen, by position relative to the start cell; the host's memory, which grows.
class CellMemory {
public:
  static constexpr std::uint8_t kVisited = 0x04; // low two bits: direction of the parent
  static constexpr int kTileBits = 4;            // 16 x 16 cells per tile

  CellMemory();
  // 0 when the cell was never visited.
  [[nodiscard]] std::uint8_t get(Cell c);
  // Always true: the table grows (set's result is for FixedCellMemory, which can be full).
  bool set(Cell c, std::uint8_t value);
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

// The same table in a buffer the caller provides, for a robot's microcontroller (freestanding: no
// heap, no exceptions): `capacity` tiles and twice as many slots (so the load factor stays at most
// 1/2, as CellMemory's), laid out in bytes_for(capacity) bytes. A robot that sees more cells than
// the tiles cover cannot remember them: set() returns false, and the controller stops (OnlineStc's
// overflowed()). A tile covers 16 x 16 cells; a map of W x H cells needs at most
// (W / 16 + 2) x (H / 16 + 2) of them, wherever the robot starts.
class FixedCellMemory {
public:
  static constexpr std::uint8_t kVisited = CellMemory::kVisited;
  static constexpr int kTileBits = CellMemory::kTileBits;
  static constexpr std::size_t kTileBytes = 256;
  // Bytes for `capacity` tiles (and 2 x capacity slots rounded up to a power of two, 12 bytes
  // each), 8-byte aligned.
  [[nodiscard]] static constexpr std::size_t slots_for(std::size_t capacity) noexcept {
    std::size_t n = 2;
    while (n < 2 * capacity) n *= 2;
    return n;
  }
  [[nodiscard]] static constexpr std::size_t bytes_for(std::size_t capacity) noexcept {
    return capacity * kTileBytes + slots_for(capacity) * 12;
  }
  // The most tiles `bytes` bytes hold.
  [[nodiscard]] static constexpr std::size_t capacity_for(std::size_t bytes) noexcept {
    std::size_t c = 0;
    while (bytes_for(c + 1) <= bytes) ++c;
    return c;
  }

  FixedCellMemory() = default;
  // `buffer` (8-byte aligned) of `bytes` bytes: as many tiles as fit.
  FixedCellMemory(void* buffer, std::size_t bytes) noexcept {
    capacity_ = capacity_for(bytes);
    slots_ = slots_for(capacity_);
    auto* base = static_cast<std::uint8_t*>(buffer);
    keys_ = reinterpret_cast<std::uint64_t*>(base);
    index_ = reinterpret_cast<std::uint32_t*>(base + 8 * slots_);
    tiles_ = base + 12 * slots_;
    for (std::size_t i = 0; i < slots_; ++i) index_[i] = kEmpty;
  }

  [[nodiscard]] std::uint8_t get(Cell c) noexcept {
    const std::uint8_t* tile = tile_for(c, false);
    return tile ? tile[offset_in_tile(c)] : std::uint8_t{0};
  }
  bool set(Cell c, std::uint8_t value) noexcept {
    std::uint8_t* tile = tile_for(c, true);
    if (!tile) return false;
    tile[offset_in_tile(c)] = value;
    return true;
  }
  [[nodiscard]] std::size_t tiles() const noexcept { return used_; }
  [[nodiscard]] std::size_t capacity() const noexcept { return capacity_; }
  [[nodiscard]] std::size_t bytes() const noexcept { return bytes_for(capacity_); }

private:
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  static constexpr std::size_t offset_in_tile(Cell c) noexcept {
    constexpr std::int32_t m = (1 << kTileBits) - 1;
    return static_cast<std::size_t>(((c.y & m) << kTileBits) | (c.x & m));
  }
  std::uint8_t* tile_for(Cell c, bool create) noexcept {
    const auto tx = static_cast<std::uint32_t>(c.x >> kTileBits);
    const auto ty = static_cast<std::uint32_t>(c.y >> kTileBits);
    const std::uint64_t key = (std::uint64_t{tx} << 32) | ty;
    if (key == last_key_) return last_tile_;
    if (slots_ == 0) return nullptr;
    const std::size_t mask = slots_ - 1;
    std::size_t i = static_cast<std::size_t>(kernel::mix64(key)) & mask;
    while (index_[i] != kEmpty) {
      if (keys_[i] == key) {
        last_key_ = key;
        last_tile_ = tiles_ + kTileBytes * index_[i];
        return last_tile_;
      }
      i = (i + 1) & mask;
    }
    if (!create || used_ == capacity_) return nullptr;
    keys_[i] = key;
    index_[i] = static_cast<std::uint32_t>(used_);
    std::uint8_t* tile = tiles_ + kTileBytes * used_++;
    for (std::size_t k = 0; k < kTileBytes; ++k) tile[k] = 0;
    last_key_ = key;
    last_tile_ = tile;
    return tile;
  }

  std::uint64_t* keys_ = nullptr;
  std::uint32_t* index_ = nullptr; // tile index per slot, kEmpty when the slot is free
  std::uint8_t* tiles_ = nullptr;
  std::size_t slots_ = 0, capacity_ = 0, used_ = 0;
  std::uint64_t last_key_ = ~std::uint64_t{0};
  std::uint8_t* last_tile_ = nullptr;
};

// The controller, over either memory: the host's OnlineStc (CellMemory, which grows) and the
// microcontroller's BasicOnlineStc<FixedCellMemory> take the same decisions while the fixed memory
// has room (lookups only: the tables' layouts cannot influence a decision).
template <class Memory>
class BasicOnlineStc {
public:
  using Observation = CellObservation;
  using Command = stc::Command;

  // `start_quadrant` is the quadrant (SE 0, NE 1, NW 2, SW 3) of the sub-cell the robot starts in.
  explicit BasicOnlineStc(int start_quadrant, Memory memory = Memory())
      : memory_(static_cast<Memory&&>(memory)), q_(start_quadrant & 3), q0_(start_quadrant & 3) {
    if (!memory_.set(cell_, static_cast<std::uint8_t>(Memory::kVisited | dir_add(q0_, 3))))
      overflowed_ = done_ = true;
  }

  Command step(const Observation& seen) {
    if (done_) return {};
    const int d = q_;
    const Cell nb = stc::step(cell_, d);
    // A new cell: free and never visited. It becomes a child of the current cell.
    if (((seen.free_neighbours >> d) & 1) != 0 && memory_.get(nb) == 0) {
      if (!memory_.set(nb, static_cast<std::uint8_t>(Memory::kVisited | opposite(d)))) {
        overflowed_ = done_ = true; // out of memory: stop rather than forget where it has been
        return {};
      }
      cell_ = nb;
      parent_ = opposite(d);
      q_ = dir_add(d, 3);
      return {move_towards(d), false};
    }
    if (parent_ == d) {
      const int arrive = dir_add(d, 3);
      const bool nb_is_root = nb == Cell{0, 0};
      if (nb_is_root && arrive == q0_) {
        done_ = true;
        return {};
      }
      cell_ = nb;
      q_ = arrive;
      parent_ = nb_is_root ? -1 : (memory_.get(nb) & 3);
      return {move_towards(d), false};
    }
    q_ = dir_add(q_, 1);
    if (q_ == q0_ && cell_ == Cell{0, 0}) {
      done_ = true;
      return {};
    }
    return {move_towards(q_), false};
  }

  [[nodiscard]] const Memory& memory() const noexcept { return memory_; }
  // The memory was full when the robot reached a new cell: it stopped there.
  [[nodiscard]] bool overflowed() const noexcept { return overflowed_; }

private:
  Memory memory_;
  Cell cell_{0, 0}; // relative to the start cell
  int q_;
  int q0_;
  int parent_ = -1; // direction of the current cell's parent, -1 at the root
  bool done_ = false;
  bool overflowed_ = false;
};

using OnlineStc = BasicOnlineStc<CellMemory>;
extern template class BasicOnlineStc<CellMemory>; // instantiated in online.cpp

} // namespace antkit::stc
