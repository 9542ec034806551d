// Line of sight on grids: symmetric, and exactly "no blocking cell among those the segment touches
// other than its two ends", with the touch test an exact oracle in tests/support/raster_oracle.hpp
// (not raster.hpp).
#include "raster_oracle.hpp"

#include <algorithm>
#include <antkit/kernel/raster.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <vector>

using antkit::kernel::Cell;
using antkit::kernel::line_of_sight;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using antkit::test::oracle_touches;

namespace {

// Line of sight by definition: every touched cell other than a and b is on the grid and Free.
bool oracle_los(const OccupancyGrid& g, Cell a, Cell b) {
  for (std::int64_t y = std::min(a.y, b.y); y <= std::max(a.y, b.y); ++y)
    for (std::int64_t x = std::min(a.x, b.x); x <= std::max(a.x, b.x); ++x) {
      const Cell c{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
      if (c == a || c == b || !oracle_touches(a, b, c)) continue;
      if (g.get_or(c, Occupancy::Blocked) != Occupancy::Free) return false;
    }
  return true;
}

// A w x h grid, each cell Blocked with probability about density/8 and Unknown about 1/16.
OccupancyGrid random_grid(std::int32_t w, std::int32_t h, int density) {
  OccupancyGrid g(w, h);
  for (auto& v : g.cells()) {
    const int r = *rc::gen::inRange(0, 16);
    v = r < 2 * density ? Occupancy::Blocked : r == 15 ? Occupancy::Unknown : Occupancy::Free;
  }
  return g;
}

// A cell in or just around a w x h grid (up to 2 cells off each side).
Cell near_grid(std::int32_t w, std::int32_t h) {
  const auto x = *rc::gen::inRange(-2, w + 2);
  const auto y = *rc::gen::inRange(-2, h + 2);
  return {x, y};
}

OccupancyGrid from_ascii(const std::vector<const char*>& rows) {
  OccupancyGrid g(static_cast<std::int32_t>(std::string(rows[0]).size()),
                  static_cast<std::int32_t>(rows.size()));
  for (std::int32_t y = 0; y < g.height(); ++y)
    for (std::int32_t x = 0; x < g.width(); ++x) {
      const char ch = rows[static_cast<std::size_t>(y)][x];
      g[{x, y}] = ch == '#' ? Occupancy::Blocked : ch == '?' ? Occupancy::Unknown : Occupancy::Free;
    }
  return g;
}

} // namespace

TEST_CASE("line of sight worked examples", "[los]") {
  const OccupancyGrid g = from_ascii({
      ".....", //
      ".#...", //
      "..#..", //
      "...?.", //
      ".....", //
  });
  CHECK(line_of_sight(g, {0, 0}, {4, 0}));  // along the free top row
  CHECK(!line_of_sight(g, {0, 0}, {4, 4})); // through the blocked diagonal
  CHECK(line_of_sight(g, {1, 1}, {2, 2}));  // the ends themselves never block
  CHECK(line_of_sight(g, {0, 0}, {0, 0}));  // a cell sees itself
  CHECK(!line_of_sight(g, {4, 2}, {2, 4})); // (3, 3) is Unknown, which blocks
  CHECK(line_of_sight(g, {4, 1}, {4, 4}));
  // A diagonal gap between two blocked cells that touch at a corner lets nothing through: the
  // segment (1,2)-(2,1) passes through their shared corner, so it touches both.
  const OccupancyGrid gap = from_ascii({
      "...", //
      ".#.", //
      "#..", //
  });
  CHECK(!line_of_sight(gap, {0, 1}, {1, 2}));
  CHECK(!line_of_sight(gap, {2, 0}, {0, 2}));
  // Off the grid: the cells between are off the grid too, and block; the ends do not.
  CHECK(!line_of_sight(g, {-2, 0}, {1, 0}));
  CHECK(line_of_sight(g, {-1, 0}, {1, 0}));
  CHECK(line_of_sight(g, {-1, 0}, {-1, 0}));
}

TEST_CASE("line of sight is the oracle's, and symmetric", "[los][property]") {
  rc::prop("grid LOS equals the definition, both ways", [] {
    const auto w = *rc::gen::inRange(1, 14);
    const auto h = *rc::gen::inRange(1, 14);
    const OccupancyGrid g = random_grid(w, h, *rc::gen::inRange(0, 4));
    const Cell a = near_grid(w, h), b = near_grid(w, h);
    const bool los = line_of_sight(g, a, b);
    RC_ASSERT(los == line_of_sight(g, b, a));
    RC_ASSERT(los == oracle_los(g, a, b));
  });
  rc::prop("the predicate form sees exactly the interior cells, each once", [] {
    const Cell a{*rc::gen::inRange(-30, 31), *rc::gen::inRange(-30, 31)};
    const Cell b{*rc::gen::inRange(-30, 31), *rc::gen::inRange(-30, 31)};
    std::vector<Cell> asked;
    const bool los = line_of_sight(a, b, [&](Cell c) {
      asked.push_back(c);
      return false;
    });
    RC_ASSERT(los);
    std::vector<Cell> want;
    for (std::int32_t y = std::min(a.y, b.y); y <= std::max(a.y, b.y); ++y)
      for (std::int32_t x = std::min(a.x, b.x); x <= std::max(a.x, b.x); ++x)
        if (Cell{x, y} != a && Cell{x, y} != b && oracle_touches(a, b, {x, y}))
          want.push_back({x, y});
    std::sort(asked.begin(), asked.end());
    std::sort(want.begin(), want.end());
    RC_ASSERT(asked.size() == want.size());
    RC_ASSERT(std::equal(asked.begin(), asked.end(), want.begin()));
  });
  rc::prop("the predicate form stops at the first blocking cell", [] {
    const Cell a{*rc::gen::inRange(-30, 31), *rc::gen::inRange(-30, 31)};
    const Cell b{*rc::gen::inRange(-30, 31), *rc::gen::inRange(-30, 31)};
    int calls = 0;
    const bool los = line_of_sight(a, b, [&](Cell) { return ++calls == 1; });
    RC_ASSERT(los == (calls == 0));
    RC_ASSERT(calls <= 1);
  });
}

TEST_CASE("every pair of cells of a 12x12 grid, and a ring around it: LOS equals the definition",
          "[los][proof]") {
  // Exhaustive small scope: cells from -1 to 12 in each axis (196 cells, 38416 ordered pairs) on
  // a fixed 12 x 12 grid with a deterministic mix of Free, Blocked and Unknown cells (two cells
  // in eleven block). For every pair: LOS equals the oracle's definition and is symmetric.
  OccupancyGrid g(12, 12);
  for (std::int32_t y = 0; y < 12; ++y)
    for (std::int32_t x = 0; x < 12; ++x) {
      const std::int32_t h = (x * 7 + y * 13 + x * y) % 11;
      g[{x, y}] = h == 0 ? Occupancy::Blocked : h == 5 ? Occupancy::Unknown : Occupancy::Free;
    }
  std::int64_t pairs = 0, mismatches = 0, visible = 0;
  for (std::int32_t ay = -1; ay <= 12; ++ay)
    for (std::int32_t ax = -1; ax <= 12; ++ax)
      for (std::int32_t by = -1; by <= 12; ++by)
        for (std::int32_t bx = -1; bx <= 12; ++bx) {
          const Cell a{ax, ay}, b{bx, by};
          const bool los = line_of_sight(g, a, b);
          mismatches += (los != oracle_los(g, a, b) || los != line_of_sight(g, b, a)) ? 1 : 0;
          visible += los ? 1 : 0;
          ++pairs;
        }
  CHECK(pairs == 196 * 196);
  CHECK(mismatches == 0);
  // Both answers occur often enough for the check to mean something.
  CHECK(visible > pairs / 10);
  CHECK(visible < pairs * 9 / 10);
}
