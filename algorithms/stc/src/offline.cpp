#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/offline.hpp>
#include <string>

namespace antkit::stc {

kernel::Grid<std::uint8_t> free_cells(const kernel::OccupancyGrid& map) {
  const CellGridShape shape = cell_shape(map);
  kernel::Grid<std::uint8_t> out(shape.cells_x, shape.cells_y, 0);
  const auto width = static_cast<std::size_t>(map.width());
  const auto& sub = map.cells();
  auto& cells = out.cells();
  // Row pairs at a time, so that the map is read sequentially.
  for (std::int32_t cy = 0; cy < shape.cells_y; ++cy) {
    const std::size_t top = static_cast<std::size_t>(2 * cy) * width;
    const std::size_t bottom = top + width;
    const std::size_t row = static_cast<std::size_t>(cy) * static_cast<std::size_t>(shape.cells_x);
    for (std::int32_t cx = 0; cx < shape.cells_x; ++cx) {
      const auto x = static_cast<std::size_t>(2 * cx);
      const bool free = sub[top + x] == kernel::Occupancy::Free &&
                        sub[top + x + 1] == kernel::Occupancy::Free &&
                        sub[bottom + x] == kernel::Occupancy::Free &&
                        sub[bottom + x + 1] == kernel::Occupancy::Free;
      cells[row + static_cast<std::size_t>(cx)] = free ? 1 : 0;
    }
  }
  return out;
}

namespace {

void check_start(CellGridShape shape, const kernel::Grid<std::uint8_t>& cells, SubCell start) {
  const Cell c = cell_of(start);
  if (start.x < 0 || start.y < 0 || !shape.in_bounds(c))
    throw kernel::InputError(
        "start", "sub-cell (" + std::to_string(start.x) + ", " + std::to_string(start.y) +
                     ") is outside the map's cells (" + std::to_string(2 * shape.cells_x) + " x " +
                     std::to_string(2 * shape.cells_y) + " sub-cells)");
  if (cells[c] == 0)
    throw kernel::InputError("start", "sub-cell (" + std::to_string(start.x) + ", " +
                                          std::to_string(start.y) + ") lies in cell (" +
                                          std::to_string(c.x) + ", " + std::to_string(c.y) +
                                          "), which is not free (all four sub-cells must be)");
}

} // namespace

SpanningTree::SpanningTree(const kernel::OccupancyGrid& map, SubCell start)
    : SpanningTree(free_cells(map), start) {}

SpanningTree::SpanningTree(kernel::Grid<std::uint8_t> cells, SubCell start)
    : state_(std::move(cells)), root_(cell_of(start)), q0_(quadrant_of(start)) {
  check_start(shape(), state_, start);
  for (auto& b : state_.cells()) b = b ? kFree : std::uint8_t{0};
  build();
}

void SpanningTree::build() {
  const CellGridShape sh = shape();
  // The root's virtual parent is q0 - 1, so that its scan starts at q0 like every other cell's
  // starts after its parent; unlike theirs, the root's scan covers all four directions.
  state_[root_] = static_cast<std::uint8_t>(kFree | kInTree | kRoot | dir_add(q0_, 3));
  tree_cells_ = 1;
  Cell cur = root_;
  int k = 0; // the next scan position of `cur`: direction base + 1 + k
  for (;;) {
    const std::uint8_t here = state_[cur];
    const int base = here & kParentMask;
    const int limit = (here & kRoot) ? 4 : 3;
    bool descended = false;
    for (; k < limit; ++k) {
      const int d = dir_add(base, 1 + k);
      const Cell nb = step(cur, d);
      if (!sh.in_bounds(nb)) continue;
      std::uint8_t& n = state_[nb];
      if ((n & (kFree | kInTree)) != kFree) continue;
      n = static_cast<std::uint8_t>(n | kInTree | opposite(d));
      ++tree_cells_;
      cur = nb;
      k = 0;
      descended = true;
      break;
    }
    if (descended) continue;
    if (here & kRoot) break;
    // Back to the parent; resume its scan after the direction that led here.
    const int e = opposite(base); // from the parent to cur
    cur = step(cur, base);
    const int parent_base = state_[cur] & kParentMask;
    k = dir_add(e, -parent_base - 1) + 1;
  }
}

std::vector<SubCell> SpanningTree::tour() const {
  std::vector<SubCell> path;
  path.reserve(static_cast<std::size_t>(4 * tree_cells_));
  tour([&](SubCell s) { path.push_back(s); });
  return path;
}

} // namespace antkit::stc
