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

SpanningTree::SpanningTree(const kernel::OccupancyGrid& map, SubCell start)
    : shape_(cell_shape(map)),
      tiles_x_((static_cast<std::size_t>(shape_.cells_x) + 2 + 63) >> kTileBits),
      root_(cell_of(start)), q0_(quadrant_of(start)) {
  if (start.x < 0 || start.y < 0 || !shape_.in_bounds(root_))
    throw kernel::InputError(
        "start", "sub-cell (" + std::to_string(start.x) + ", " + std::to_string(start.y) +
                     ") is outside the map's cells (" + std::to_string(2 * shape_.cells_x) + " x " +
                     std::to_string(2 * shape_.cells_y) + " sub-cells)");
  if (!cell_free(map, root_))
    throw kernel::InputError("start", "sub-cell (" + std::to_string(start.x) + ", " +
                                          std::to_string(start.y) + ") lies in cell (" +
                                          std::to_string(root_.x) + ", " + std::to_string(root_.y) +
                                          "), which is not free (all four sub-cells must be)");
  const std::size_t tiles_y = (static_cast<std::size_t>(shape_.cells_y) + 2 + 63) >> kTileBits;
  state_.assign((tiles_x_ * tiles_y) << (2 * kTileBits), 0);
  // Free cells, two map rows at a time so that the map is read sequentially.
  const auto width = static_cast<std::size_t>(map.width());
  const auto& sub = map.cells();
  for (std::int32_t cy = 0; cy < shape_.cells_y; ++cy) {
    const std::size_t top = static_cast<std::size_t>(2 * cy) * width, bottom = top + width;
    for (std::int32_t cx = 0; cx < shape_.cells_x; ++cx) {
      const auto x = static_cast<std::size_t>(2 * cx);
      const bool free = sub[top + x] == kernel::Occupancy::Free &&
                        sub[top + x + 1] == kernel::Occupancy::Free &&
                        sub[bottom + x] == kernel::Occupancy::Free &&
                        sub[bottom + x + 1] == kernel::Occupancy::Free;
      state_[index({cx, cy})] = free ? kFreeCell : std::uint8_t{0};
    }
  }
  build();
}

void SpanningTree::build() {
  std::uint8_t* s = state_.data();
  // The root's virtual parent is q0 - 1, so that its scan starts at q0 like every other cell's
  // starts after its parent; unlike theirs, the root's scan covers all four directions.
  Cell cur = root_;
  std::size_t at = index(cur);
  s[at] = static_cast<std::uint8_t>(kInTree | kRoot | dir_add(q0_, 3));
  tree_cells_ = 1;
  int k = 0; // the next scan position of `cur`: direction base + 1 + k
  for (;;) {
    const std::uint8_t here = s[at];
    const int base = here & kParentMask;
    const int limit = (here & kRoot) ? 4 : 3;
    bool descended = false;
    for (; k < limit; ++k) {
      const int d = dir_add(base, 1 + k);
      const Cell nb = step(cur, d);
      const std::size_t n = index(nb);
      if (s[n] != kFreeCell) continue; // blocked, border, or already in the tree
      s[n] = static_cast<std::uint8_t>(kInTree | opposite(d));
      s[at] = static_cast<std::uint8_t>(s[at] | (1u << (kChildShift + d)));
      ++tree_cells_;
      cur = nb;
      at = n;
      k = 0;
      descended = true;
      break;
    }
    if (descended) continue;
    if (here & kRoot) break;
    // Back to the parent; resume its scan after the direction that led here.
    const int e = opposite(base); // from the parent to cur
    cur = step(cur, base);
    at = index(cur);
    const int parent_base = s[at] & kParentMask;
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
