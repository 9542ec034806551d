#pragma once
// Maps for the STC tests, built in code.
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace antkit::stc::testing {

// A sub-cell map from rows of '.' (free) and '#' (blocked).
inline kernel::OccupancyGrid from_rows(const std::vector<std::string>& rows) {
  kernel::OccupancyGrid g(static_cast<std::int32_t>(rows.front().size()),
                          static_cast<std::int32_t>(rows.size()));
  for (std::int32_t y = 0; y < g.height(); ++y)
    for (std::int32_t x = 0; x < g.width(); ++x)
      g[{x, y}] = rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] == '#'
                      ? kernel::Occupancy::Blocked
                      : kernel::Occupancy::Free;
  return g;
}

// A sub-cell map whose cells are free or blocked by the bits of `mask` (bit cy * cw + cx set =
// cell blocked), plus `extra_x` / `extra_y` free sub-cells of odd remainder.
inline void cell_mask_map(kernel::OccupancyGrid& g, int cw, int ch, std::uint32_t mask) {
  for (std::int32_t y = 0; y < g.height(); ++y)
    for (std::int32_t x = 0; x < g.width(); ++x) {
      const int cx = x / 2, cy = y / 2;
      const bool blocked = cx < cw && cy < ch && ((mask >> (cy * cw + cx)) & 1u);
      g[{x, y}] = blocked ? kernel::Occupancy::Blocked : kernel::Occupancy::Free;
    }
}

} // namespace antkit::stc::testing
