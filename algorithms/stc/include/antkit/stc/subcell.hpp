#pragma once
// The geometry of Spanning Tree Coverage (Gabriely & Rimon; paper 002): the map is given at
// sub-cell resolution (one map cell = one robot-sized sub-cell of size D); each 2x2 block of
// sub-cells is a cell of size 2D.
//
// Conventions shared by every STC variant (x to the right, y downward, as in the kernel's grids):
//
//   * Cell (cx, cy) holds the sub-cells (2cx + dx, 2cy + dy), dx, dy in {0, 1}.
//   * Odd sizes: a map W sub-cells wide has W / 2 cell columns; when W is odd, the last sub-cell
//     column belongs to no cell and is never entered (likewise the last row for an odd H). The
//     issue leaves this open; dropping the remainder keeps every cell a full 2x2 block, which is
//     what the tour's geometry needs, and a robot of size D could not turn around in a strip of
//     width D anyway.
//   * Unknown sub-cells (ROS maps) count as blocked: the robot never drives where it has not seen
//     the floor.
//   * Directions are the kernel's 4-neighbourhood order, counter-clockwise as drawn on screen:
//     0 = E, 1 = N (up, y - 1), 2 = W, 3 = S (down, y + 1).
//   * A sub-cell's quadrant q names its place in its cell, also counter-clockwise as drawn:
//     0 = SE, 1 = NE, 2 = NW, 3 = SW. With these numberings the whole tour is arithmetic mod 4:
//       - sub-cell q has its two exterior edges in directions q and q - 1;
//       - sub-cells d and d + 1 share the exterior edge in direction d (the side of the cell that
//         faces the neighbour in direction d);
//       - the robot walks around its cell counter-clockwise, q -> q + 1, which is one move in
//         direction q + 1;
//       - it leaves towards the neighbour in direction d from sub-cell d, moving in direction d,
//         and arrives in that neighbour's sub-cell d + 3 (= d - 1); coming back, it arrives in
//         sub-cell d + 1 of the cell it left.
//     So the robot keeps the spanning tree on its left, and scanning the neighbours
//     counter-clockwise starting after the parent is the same as walking around the cell.
#include <antkit/kernel/grid.hpp>
#include <array>
#include <cstdint>

namespace antkit::stc {

using kernel::Cell;

// One robot-sized square of the map.
using SubCell = Cell;

inline constexpr int kDirections = 4;

// Offsets of quadrant q inside its cell: SE, NE, NW, SW.
inline constexpr std::array<Cell, 4> kQuadrantOffset{{{1, 1}, {1, 0}, {0, 0}, {0, 1}}};

[[nodiscard]] constexpr int dir_add(int d, int k) noexcept {
  return (d + k) & 3;
}
[[nodiscard]] constexpr int opposite(int d) noexcept {
  return (d + 2) & 3;
}

[[nodiscard]] constexpr Cell cell_of(SubCell s) noexcept {
  return {s.x >> 1, s.y >> 1};
}

// The quadrant of a sub-cell (from the parity of its coordinates).
[[nodiscard]] constexpr int quadrant_of(SubCell s) noexcept {
  const int dx = s.x & 1, dy = s.y & 1;
  // (1,1) SE 0, (1,0) NE 1, (0,0) NW 2, (0,1) SW 3
  return dx ? (dy ? 0 : 1) : (dy ? 3 : 2);
}

[[nodiscard]] constexpr SubCell subcell_of(Cell cell, int q) noexcept {
  return {2 * cell.x + kQuadrantOffset[static_cast<std::size_t>(q)].x,
          2 * cell.y + kQuadrantOffset[static_cast<std::size_t>(q)].y};
}

[[nodiscard]] constexpr Cell step(Cell c, int d) noexcept {
  return c + kernel::kNeighbours4[static_cast<std::size_t>(d)];
}

// What a controller asks its body to do: drive one sub-cell in a direction, or stop (the tour is
// closed). `mark` leaves the variant's marker on the sub-cell being left (a sub-cell mark for
// `ant`; for `ant-edge` the robot's back LEDs light the edge behind it, the one opposite `move`).
enum class Move : std::uint8_t { East = 0, North = 1, West = 2, South = 3, Stop = 4 };

struct Command {
  Move move = Move::Stop;
  bool mark = false;
  friend constexpr bool operator==(Command, Command) = default;
};

[[nodiscard]] constexpr Move move_towards(int d) noexcept {
  return static_cast<Move>(d & 3);
}

// The cell grid of a sub-cell map: dimensions and the "free cell" test (all four sub-cells Free).
struct CellGridShape {
  std::int32_t cells_x = 0;
  std::int32_t cells_y = 0;
  [[nodiscard]] constexpr bool in_bounds(Cell c) const noexcept {
    return c.x >= 0 && c.y >= 0 && c.x < cells_x && c.y < cells_y;
  }
};

[[nodiscard]] inline CellGridShape cell_shape(const kernel::OccupancyGrid& map) noexcept {
  return {map.width() / 2, map.height() / 2};
}

// Every sub-cell of the cell is Free (Unknown and Blocked both block).
[[nodiscard]] inline bool cell_free(const kernel::OccupancyGrid& map, Cell c) noexcept {
  if (!cell_shape(map).in_bounds(c)) return false;
  for (int q = 0; q < 4; ++q)
    if (map[subcell_of(c, q)] != kernel::Occupancy::Free) return false;
  return true;
}

// The 0/1 grid of free cells (1 byte per cell).
kernel::Grid<std::uint8_t> free_cells(const kernel::OccupancyGrid& map);

} // namespace antkit::stc
