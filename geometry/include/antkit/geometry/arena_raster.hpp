#pragma once
// Rasterization of an arena into a kernel occupancy grid, by an exact rule.
//
// The rule: a cell is Free iff its centre lies strictly inside the arena (inside the outer
// boundary and outside every hole, not on any wall); every other cell is Blocked. "Strictly" makes
// a wall that passes exactly through a centre block that cell, so a grid never shows a gap in a
// wall that the exact arena does not have at that centre. Decided with exact rational arithmetic.
//
// The mapping (y of the grid goes down, y of the arena goes up): with cell size c and the arena's
// bounding box [xmin, xmax] x [ymin, ymax], the grid's edges are snapped outward to multiples of c:
//     col0 = floor(xmin / c),  row0 = ceil(ymax / c),
//     width = ceil(xmax / c) - col0,  height = row0 - floor(ymin / c),
// and cell (x = i, y = j) is the square [(col0 + i) c, (col0 + i + 1) c] x
// [(row0 - j - 1) c, (row0 - j) c], with centre ((col0 + i + 1/2) c, (row0 - j - 1/2) c).
// Snapping to multiples of c makes the arena's origin a cell corner, so the same arena rasterized
// twice at the same size gives the same cells whatever its extent, and cells of two arenas line up.
// Cells along the snapped border are outside the arena and hence Blocked.
#include <antkit/geometry/arena.hpp>
#include <antkit/kernel/grid.hpp>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace antkit::geometry {

// A positive cell size, exactly num / den.
class CellSize {
public:
  // num > 0, den > 0 (throws std::invalid_argument otherwise); kept in lowest terms.
  CellSize(std::int64_t num, std::int64_t den);
  // A positive decimal such as `1`, `0.25` or `1e-2`, read exactly; at most 18 significant digits
  // and a value in [1e-6, 1e6]. Errors are kernel::InputError(where, ...).
  static CellSize parse(std::string_view text, const std::string& where);

  [[nodiscard]] std::int64_t num() const noexcept { return num_; }
  [[nodiscard]] std::int64_t den() const noexcept { return den_; }
  [[nodiscard]] double value() const noexcept;

private:
  std::int64_t num_;
  std::int64_t den_;
};

struct RasterFrame {
  CellSize cell{1, 1};
  std::int64_t col0 = 0; // floor(xmin / c)
  std::int64_t row0 = 0; // ceil(ymax / c)
  // The centre of cell (i, j) in arena coordinates (rounded to double; for reports and plots).
  [[nodiscard]] std::array<double, 2> centre(kernel::Cell cell) const;
};

struct ArenaRaster {
  kernel::OccupancyGrid grid;
  RasterFrame frame;
};

// The most cells a raster may have (the grid is one byte per cell): 2^28, a 256 MiB grid, which
// holds the standard arena at cell size 0.006 and the most eccentric paper ellipse at 0.01.
inline constexpr std::size_t kMaxRasterCells = std::size_t{1} << 28;

// Throws kernel::InputError(where, ...) when the grid would exceed max_cells or a side would
// exceed kernel::kMaxGridSide.
[[nodiscard]] ArenaRaster rasterize(const Arena& arena, CellSize cell,
                                    std::size_t max_cells = kMaxRasterCells,
                                    const std::string& where = "--raster");

} // namespace antkit::geometry
