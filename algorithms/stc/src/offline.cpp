#include <algorithm>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/offline.hpp>
#include <cstring>
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

SpanningTree::SpanningTree(const kernel::OccupancyGrid& map, SubCell start, Prepare)
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
  constexpr std::size_t tile = std::size_t{1} << (2 * kTileBits);
  const std::size_t tile_row = tiles_x_ * tile;
  steps_.leave = {tile - 63, 63 * 64 - tile_row, 0 - (tile - 63), tile_row - 63 * 64};
  state_.assign((tiles_x_ * tiles_y) << (2 * kTileBits), 0);
  mark_free_cells(map, open_);
}

SpanningTree::SpanningTree(const kernel::OccupancyGrid& map, SubCell start)
    : SpanningTree(map, start, Prepare{}) {
  NoVisit none;
  search(none);
}

namespace {

// Row cy of the cell grid: out[cx + 1] = 1 when cell (cx, cy) is free, 0 otherwise, and 0 at
// out[0] and out[cells_x + 1]. A cell is free when its four sub-cells are Free (0): the two
// sub-cells of each of its map rows are read as one 16-bit word and the two words must OR to zero
// (no branch per sub-cell; the loop vectorises).
void free_row(const kernel::OccupancyGrid& map, std::int32_t cells_x, std::int32_t cy,
              std::vector<std::uint8_t>& out) {
  static_assert(static_cast<int>(kernel::Occupancy::Free) == 0 && sizeof(kernel::Occupancy) == 1);
  const auto width = static_cast<std::size_t>(map.width());
  const auto* top = reinterpret_cast<const unsigned char*>(map.cells().data()) +
                    static_cast<std::size_t>(2 * cy) * width;
  const unsigned char* bottom = top + width;
  std::uint8_t* o = out.data() + 1;
  for (std::size_t cx = 0; cx < static_cast<std::size_t>(cells_x); ++cx) {
    std::uint16_t t = 0, b = 0;
    std::memcpy(&t, top + 2 * cx, 2);
    std::memcpy(&b, bottom + 2 * cx, 2);
    o[cx] = (t | b) == 0 ? 1 : 0;
  }
}

} // namespace

// The new-neighbour masks of every free cell (0 for the others and the border), two map rows at a
// time so that the map is read sequentially, from three rows of free flags (above, the row,
// below), and a tile row's run of cells at a time so that the masks are written sequentially.
void SpanningTree::mark_free_cells(const kernel::OccupancyGrid& map,
                                   std::vector<std::uint8_t>& open) {
  open.assign(state_.size(), 0);
  const std::int32_t cx_end = shape_.cells_x;
  const auto row_size = static_cast<std::size_t>(cx_end) + 2;
  std::vector<std::uint8_t> above(row_size, 0), row(row_size, 0), below(row_size, 0);
  if (shape_.cells_y > 0) free_row(map, cx_end, 0, row);
  constexpr std::int32_t side = std::int32_t{1} << kTileBits;
  for (std::int32_t cy = 0; cy < shape_.cells_y; ++cy) {
    if (cy + 1 < shape_.cells_y)
      free_row(map, cx_end, cy + 1, below);
    else
      std::fill(below.begin(), below.end(), std::uint8_t{0});
    for (std::int32_t cx = 0; cx < cx_end;) {
      // Stored x is cx + 1: the run ends at the tile's last column.
      const std::int32_t run = std::min(cx_end - cx, side - ((cx + 1) & (side - 1)));
      std::uint8_t* out = open.data() + index({cx, cy});
      const std::uint8_t* r = row.data() + cx; // r[j + 1] is cell cx + j
      const std::uint8_t* up = above.data() + cx + 1;
      const std::uint8_t* down = below.data() + cx + 1;
      for (std::int32_t j = 0; j < run; ++j) {
        const unsigned mask = static_cast<unsigned>(r[j + 2]) | static_cast<unsigned>(up[j]) << 1 |
                              static_cast<unsigned>(r[j]) << 2 |
                              static_cast<unsigned>(down[j]) << 3;
        out[j] = static_cast<std::uint8_t>(r[j + 1] != 0 ? mask : 0u);
      }
      cx += run;
    }
    std::swap(above, row);
    std::swap(row, below);
  }
}

std::vector<SubCell> SpanningTree::tour() const {
  std::vector<SubCell> path;
  path.reserve(static_cast<std::size_t>(4 * tree_cells_));
  tour([&](SubCell s) { path.push_back(s); });
  return path;
}

} // namespace antkit::stc
