#pragma once
// Cell counts and 4-connected components of the free cells of an occupancy grid.
//
// Header-only, integers and the standard library only (no CGAL): it answers the question
// `antkit map info` asks of a map (how much free space is reachable from where) wherever maps may
// be used (the layer table in cmake/AntkitLayers.cmake; the map fuzz targets check their maps with
// it). Unknown cells are not free: a component is a maximal set of Free cells joined through E, N,
// W, S neighbours (kernel::kNeighbours4), and cells outside the grid are blocked.
//
// The search is iterative (an explicit stack of cell indices), so a 1000 x 1000 serpentine corridor
// cannot overflow the call stack, and it visits cells in one fixed order, so labels are the same on
// every run: components are numbered 0, 1, ... in row-major order of their first (top-most, then
// left-most) cell.
#include <algorithm>
#include <antkit/kernel/grid.hpp>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace antkit::maps {

struct CellCounts {
  std::size_t free = 0;
  std::size_t blocked = 0;
  std::size_t unknown = 0;
  friend bool operator==(const CellCounts&, const CellCounts&) = default;
};

inline CellCounts count_cells(const kernel::OccupancyGrid& grid) {
  CellCounts counts;
  for (const auto c : grid.cells()) {
    switch (c) {
    case kernel::Occupancy::Free:
      ++counts.free;
      break;
    case kernel::Occupancy::Blocked:
      ++counts.blocked;
      break;
    case kernel::Occupancy::Unknown:
      ++counts.unknown;
      break;
    }
  }
  return counts;
}

struct FreeComponents {
  static constexpr std::int32_t kNotFree = -1;
  // Same shape as the grid: the component number of each free cell, kNotFree elsewhere.
  kernel::Grid<std::int32_t> label;
  // sizes[k] = number of cells of component k.
  std::vector<std::size_t> sizes;

  [[nodiscard]] std::size_t count() const noexcept { return sizes.size(); }
  // The size of the largest component, 0 when there are no free cells.
  [[nodiscard]] std::size_t largest() const noexcept {
    return sizes.empty() ? 0 : *std::max_element(sizes.begin(), sizes.end());
  }
};

inline FreeComponents free_components(const kernel::OccupancyGrid& grid) {
  FreeComponents result;
  result.label = kernel::Grid<std::int32_t>(grid.width(), grid.height(), FreeComponents::kNotFree);
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < grid.size(); ++seed) {
    if (grid.cells()[seed] != kernel::Occupancy::Free ||
        result.label.cells()[seed] != FreeComponents::kNotFree)
      continue;
    // A grid holds at most kMaxGridSide^2 cells, and a component at least one, so the number of
    // components fits in int32 only if the grid does; maps are capped far below that.
    const auto id = static_cast<std::int32_t>(result.sizes.size());
    std::size_t size = 0;
    result.label.cells()[seed] = id;
    stack.push_back(seed);
    while (!stack.empty()) {
      const auto here = grid.cell_at(stack.back());
      stack.pop_back();
      ++size;
      for (const auto step : kernel::kNeighbours4) {
        const auto next = here + step;
        if (!grid.in_bounds(next) || grid[next] != kernel::Occupancy::Free ||
            result.label[next] != FreeComponents::kNotFree)
          continue;
        // Labelled when pushed, not when popped, so that each cell enters the stack once and the
        // stack never holds more than the grid's cell count.
        result.label[next] = id;
        stack.push_back(grid.index(next));
      }
    }
    result.sizes.push_back(size);
  }
  return result;
}

} // namespace antkit::maps
