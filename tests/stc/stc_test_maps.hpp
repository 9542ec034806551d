#pragma once
// Maps for the STC tests, built in code.
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <rapidcheck.h>
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

// A random sub-cell map: blocked_per_mille of its cells fully blocked and partial_per_mille of
// its sub-cells blocked on their own; odd widths and heights happen.
struct RandomMap {
  kernel::OccupancyGrid map;
  kernel::Cell start;
};

inline rc::Gen<RandomMap> random_map(bool partial_cells, bool start_in_free_cell) {
  return rc::gen::exec([=] {
    const int cw = *rc::gen::inRange(1, 11);
    const int ch = *rc::gen::inRange(1, 11);
    const int odd_x = *rc::gen::inRange(0, 2), odd_y = *rc::gen::inRange(0, 2);
    const int cell_density = *rc::gen::inRange(0, 60);
    const int sub_density = partial_cells ? *rc::gen::inRange(0, 40) : 0;
    kernel::OccupancyGrid g(2 * cw + odd_x, 2 * ch + odd_y, kernel::Occupancy::Free);
    for (int cy = 0; cy < ch; ++cy)
      for (int cx = 0; cx < cw; ++cx) {
        const bool blocked = *rc::gen::inRange(0, 100) < cell_density;
        for (int q = 0; q < 4; ++q) {
          const kernel::Cell s{2 * cx + (q & 1), 2 * cy + (q >> 1)};
          const bool sub_blocked = sub_density > 0 && *rc::gen::inRange(0, 100) < sub_density;
          if (blocked || sub_blocked) g[s] = kernel::Occupancy::Blocked;
        }
      }
    if (odd_x || odd_y) // the remainder holds anything: it must never be entered
      for (std::int32_t y = 0; y < g.height(); ++y)
        for (std::int32_t x = 0; x < g.width(); ++x)
          if (x >= 2 * cw || y >= 2 * ch)
            g[{x, y}] =
                *rc::gen::inRange(0, 2) ? kernel::Occupancy::Free : kernel::Occupancy::Blocked;
    // Candidate starts: free sub-cells (of free cells when asked).
    std::vector<kernel::Cell> starts;
    for (std::int32_t y = 0; y < 2 * ch; ++y)
      for (std::int32_t x = 0; x < 2 * cw; ++x) {
        if (g[{x, y}] != kernel::Occupancy::Free) continue;
        if (start_in_free_cell) {
          bool all = true;
          for (int q = 0; q < 4; ++q)
            all = all &&
                  g[{2 * (x / 2) + (q & 1), 2 * (y / 2) + (q >> 1)}] == kernel::Occupancy::Free;
          if (!all) continue;
        }
        starts.push_back({x, y});
      }
    if (starts.empty()) { // make one: free the first cell
      for (int q = 0; q < 4; ++q) g[{q & 1, q >> 1}] = kernel::Occupancy::Free;
      starts.push_back({0, 0});
    }
    const auto pick = *rc::gen::inRange<std::size_t>(0, starts.size());
    return RandomMap{std::move(g), starts[pick]};
  });
}

} // namespace antkit::stc::testing
