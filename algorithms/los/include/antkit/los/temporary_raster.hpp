#pragma once
// TEMPORARY: a private stand-in for <antkit/kernel/raster.hpp> (supercover and line of sight),
// written to the same contract, until the kernel's raster.hpp is committed. Replace every use with
// the kernel's functions then, and delete this file.
//
// Supercover of the segment between the centres of a and b: every cell whose closed square the
// closed segment touches; at an exact corner crossing both side cells are included (the x-side
// one first), then the diagonal cell. Decision variable, with the segment reflected to run from
// (0, 0) to (dx, dy), dx, dy >= 0, at local cell (i, j): e = dy (2i + 1) - dx (2j + 1); e < 0
// steps x, e > 0 steps y, e == 0 is the corner. 64-bit, so any two int32 cells are safe.
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <vector>

namespace antkit::los::temporary {

// Calls f(Cell) for every supercover cell from a to b in order, a and b included.
template <class F>
void for_each_supercover_cell(kernel::Cell a, kernel::Cell b, F&& f) {
  const std::int64_t ddx = std::int64_t{b.x} - a.x, ddy = std::int64_t{b.y} - a.y;
  const std::int64_t sx = ddx < 0 ? -1 : 1, sy = ddy < 0 ? -1 : 1;
  const std::int64_t dx = ddx < 0 ? -ddx : ddx, dy = ddy < 0 ? -ddy : ddy;
  auto cell = [&](std::int64_t i, std::int64_t j) {
    return kernel::Cell{static_cast<std::int32_t>(a.x + sx * i),
                        static_cast<std::int32_t>(a.y + sy * j)};
  };
  f(a);
  std::int64_t i = 0, j = 0;
  while (i < dx || j < dy) {
    const std::int64_t e = dy * (2 * i + 1) - dx * (2 * j + 1);
    if (e < 0) {
      ++i;
    } else if (e > 0) {
      ++j;
    } else {
      f(cell(i + 1, j));
      f(cell(i, j + 1));
      ++i;
      ++j;
    }
    f(cell(i, j));
  }
}

inline std::vector<kernel::Cell> supercover(kernel::Cell a, kernel::Cell b) {
  std::vector<kernel::Cell> out;
  for_each_supercover_cell(a, b, [&out](kernel::Cell c) { out.push_back(c); });
  return out;
}

// True when every supercover cell other than a and b is in the grid and Free.
inline bool line_of_sight(const kernel::OccupancyGrid& grid, kernel::Cell a, kernel::Cell b) {
  bool clear = true;
  for_each_supercover_cell(a, b, [&](kernel::Cell c) {
    if (c == a || c == b) return;
    if (grid.get_or(c, kernel::Occupancy::Blocked) != kernel::Occupancy::Free) clear = false;
  });
  return clear;
}

} // namespace antkit::los::temporary
