#pragma once
// Grids of cells and their neighbourhoods.
//
// Coordinates: x is the column (to the right), y the row (downward, row 0 is the first row of a map
// file). A grid is stored row-major. Neighbourhoods come in one fixed order, counter-clockwise as
// drawn on screen (y down) starting east, so that every algorithm that scans them is deterministic:
//   4-neighbourhood: E, N, W, S
//   8-neighbourhood: E, NE, N, NW, W, SW, S, SE   (index k is the bearing k * 45 degrees)
#include <algorithm>
#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace antkit::kernel {

struct Cell {
  std::int32_t x = 0;
  std::int32_t y = 0;
  friend constexpr bool operator==(Cell, Cell) = default;
  friend constexpr auto operator<=>(Cell, Cell) = default;
  friend constexpr Cell operator+(Cell a, Cell b) noexcept { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Cell operator-(Cell a, Cell b) noexcept { return {a.x - b.x, a.y - b.y}; }
};

inline constexpr std::array<Cell, 4> kNeighbours4{{{1, 0}, {0, -1}, {-1, 0}, {0, 1}}};
inline constexpr std::array<Cell, 8> kNeighbours8{
    {{1, 0}, {1, -1}, {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}, {0, 1}, {1, 1}}};

// The largest grid side the kernel supports. Rasterization and line of sight are proved free of
// overflow for coordinates in [0, kMaxGridSide) (proofs/PROOFS.md).
inline constexpr std::int32_t kMaxGridSide = 1 << 20;

template <class T>
class Grid {
  static_assert(!std::is_same_v<T, bool>, "use std::uint8_t: std::vector<bool> is not a container");

public:
  Grid() = default;
  Grid(std::int32_t width, std::int32_t height, T fill = T{})
      : width_(checked_side(width)), height_(checked_side(height)),
        cells_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), fill) {}

  [[nodiscard]] std::int32_t width() const noexcept { return width_; }
  [[nodiscard]] std::int32_t height() const noexcept { return height_; }
  [[nodiscard]] std::size_t size() const noexcept { return cells_.size(); }
  [[nodiscard]] bool empty() const noexcept { return cells_.empty(); }

  [[nodiscard]] bool in_bounds(Cell c) const noexcept {
    return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_;
  }
  [[nodiscard]] std::size_t index(Cell c) const noexcept {
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(c.x);
  }
  [[nodiscard]] Cell cell_at(std::size_t index) const noexcept {
    const auto w = static_cast<std::size_t>(width_);
    return {static_cast<std::int32_t>(index % w), static_cast<std::int32_t>(index / w)};
  }

  // Unchecked access: the caller guarantees in_bounds(c).
  T& operator[](Cell c) noexcept { return cells_[index(c)]; }
  const T& operator[](Cell c) const noexcept { return cells_[index(c)]; }

  // Checked access: throws std::out_of_range outside the grid.
  T& at(Cell c) { return cells_[checked_index(c)]; }
  const T& at(Cell c) const { return cells_[checked_index(c)]; }

  // The value at c, or `outside` when c is off the grid (cells outside a map are blocked).
  [[nodiscard]] T get_or(Cell c, T outside) const noexcept {
    return in_bounds(c) ? cells_[index(c)] : outside;
  }

  void fill(T value) { std::fill(cells_.begin(), cells_.end(), value); }

  [[nodiscard]] std::vector<T>& cells() noexcept { return cells_; }
  [[nodiscard]] const std::vector<T>& cells() const noexcept { return cells_; }

  friend bool operator==(const Grid&, const Grid&) = default;

private:
  static std::int32_t checked_side(std::int32_t side) {
    if (side < 0 || side > kMaxGridSide)
      throw std::length_error("grid side " + std::to_string(side) + " is outside [0, " +
                              std::to_string(kMaxGridSide) + "]");
    return side;
  }
  std::size_t checked_index(Cell c) const {
    if (!in_bounds(c))
      throw std::out_of_range("cell (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                              ") is outside the " + std::to_string(width_) + "x" +
                              std::to_string(height_) + " grid");
    return index(c);
  }

  std::int32_t width_ = 0;
  std::int32_t height_ = 0;
  std::vector<T> cells_;
};

// What a map says of a cell. Unknown comes from ROS maps (between the thresholds); algorithms that
// need a two-valued map decide how to treat it and say so.
enum class Occupancy : std::uint8_t { Free = 0, Blocked = 1, Unknown = 2 };
using OccupancyGrid = Grid<Occupancy>;

} // namespace antkit::kernel
