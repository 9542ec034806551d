// Grids and neighbourhoods (grid.hpp): row-major storage, bounds, checked access, and the fixed
// counter-clockwise neighbour order every scan relies on.
#include <antkit/kernel/grid.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <set>
#include <stdexcept>
#include <utility>

using antkit::kernel::Cell;
using antkit::kernel::Grid;
using antkit::kernel::kMaxGridSide;
using antkit::kernel::kNeighbours4;
using antkit::kernel::kNeighbours8;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;

TEST_CASE("grid sides outside [0, kMaxGridSide] are refused", "[grid]") {
  CHECK_THROWS_AS(Grid<std::uint8_t>(-1, 4), std::length_error);
  CHECK_THROWS_AS(Grid<std::uint8_t>(4, -1), std::length_error);
  CHECK_THROWS_AS(Grid<std::uint8_t>(kMaxGridSide + 1, 1), std::length_error);
  CHECK_NOTHROW(Grid<std::uint8_t>(kMaxGridSide, 1));
  const Grid<std::uint8_t> empty(0, 7);
  CHECK(empty.empty());
  CHECK(!empty.in_bounds({0, 0}));
}

TEST_CASE("grid worked example", "[grid]") {
  OccupancyGrid g(3, 2, Occupancy::Free);
  g[{2, 1}] = Occupancy::Blocked;
  CHECK(g.size() == 6u);
  CHECK(g.index({2, 1}) == 5u); // row-major: y * width + x
  CHECK(g.cells()[5] == Occupancy::Blocked);
  CHECK(g.get_or({3, 1}, Occupancy::Unknown) == Occupancy::Unknown);
  CHECK(g.get_or({2, 1}, Occupancy::Unknown) == Occupancy::Blocked);
  CHECK_THROWS_AS(g.at({-1, 0}), std::out_of_range);
  CHECK_THROWS_AS(g.at({0, 2}), std::out_of_range);
  OccupancyGrid h = g;
  CHECK(h == g);
  h.fill(Occupancy::Free);
  CHECK(h != g);
}

TEST_CASE("grid indexing is a row-major bijection", "[grid][property]") {
  rc::prop("index and cell_at are inverse, in_bounds is the rectangle", [] {
    const auto w = *rc::gen::inRange(1, 200);
    const auto h = *rc::gen::inRange(1, 200);
    const Grid<std::int32_t> g(w, h);
    const std::int32_t x = *rc::gen::inRange(-3, w + 3), y = *rc::gen::inRange(-3, h + 3);
    const Cell c{x, y};
    RC_ASSERT(g.in_bounds(c) == (x >= 0 && y >= 0 && x < w && y < h));
    if (g.in_bounds(c)) {
      RC_ASSERT(g.index(c) == static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                                  static_cast<std::size_t>(x));
      RC_ASSERT(g.cell_at(g.index(c)) == c);
      RC_ASSERT(g.get_or(c, -1) == 0);
    } else {
      RC_ASSERT(g.get_or(c, -1) == -1);
      bool threw = false;
      try {
        (void)g.at(c);
      } catch (const std::out_of_range&) {
        threw = true;
      }
      RC_ASSERT(threw);
    }
  });
  rc::prop("writes land in exactly one cell", [] {
    const auto w = *rc::gen::inRange(1, 40);
    const auto h = *rc::gen::inRange(1, 40);
    Grid<std::int32_t> g(w, h, 0);
    const Cell c{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
    g.at(c) = 7;
    std::int64_t sevens = 0;
    for (std::int32_t v : g.cells()) sevens += v == 7 ? 1 : 0;
    RC_ASSERT(sevens == 1);
    RC_ASSERT(g[c] == 7);
  });
}

TEST_CASE("neighbourhoods: counter-clockwise on screen from east, y down", "[grid][proof]") {
  // Exhaustive over the (finite) neighbourhoods: the 4-neighbourhood is E, N, W, S with north
  // up the screen (y - 1); the 8-neighbourhood's even entries are the 4-neighbourhood, each entry k
  // is one step at bearing k * 45 degrees, and consecutive bearings turn counter-clockwise as drawn
  // (positive cross product once y is flipped to point up).
  CHECK(kNeighbours4[0] == Cell{1, 0});
  CHECK(kNeighbours4[1] == Cell{0, -1});
  CHECK(kNeighbours4[2] == Cell{-1, 0});
  CHECK(kNeighbours4[3] == Cell{0, 1});
  std::set<std::pair<std::int32_t, std::int32_t>> distinct;
  for (std::size_t k = 0; k < 8; ++k) {
    const Cell d = kNeighbours8[k], next = kNeighbours8[(k + 1) % 8];
    distinct.insert({d.x, d.y});
    CHECK(std::max(std::abs(d.x), std::abs(d.y)) == 1);
    if (k % 2 == 0) CHECK(d == kNeighbours4[k / 2]);
    // Diagonals at odd k, axis steps at even k.
    CHECK((std::abs(d.x) + std::abs(d.y) == 2) == (k % 2 == 1));
    const std::int32_t cross_y_up = d.x * (-next.y) - (-d.y) * next.x;
    CHECK(cross_y_up > 0);
  }
  CHECK(distinct.size() == 8u);
}
