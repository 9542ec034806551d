// Supercover and Bresenham rasterization, held against an exact oracle written here independently
// of raster.hpp: a separating-axis test of the closed segment against each closed cell square.
#include "raster_oracle.hpp"

#include <algorithm>
#include <antkit/kernel/raster.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <deque>
#include <numeric>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <set>
#include <utility>
#include <vector>

using antkit::kernel::bresenham;
using antkit::kernel::Cell;
using antkit::kernel::for_each_bresenham_cell;
using antkit::kernel::for_each_supercover_cell;
using antkit::kernel::kMaxGridSide;
using antkit::kernel::supercover;
using antkit::kernel::SupercoverStep;
using antkit::kernel::SupercoverWalk;
using antkit::test::oracle_touches;

namespace {

// Every cell the oracle says the segment touches; only cells in the bounding box of a and b can be
// touched (a square outside it is separated by the x or y axis), sorted.
std::vector<Cell> oracle_cells(Cell a, Cell b) {
  std::vector<Cell> out;
  // 64-bit loop counters: the last cell may be INT32_MAX.
  for (std::int64_t y = std::min(a.y, b.y); y <= std::max(a.y, b.y); ++y)
    for (std::int64_t x = std::min(a.x, b.x); x <= std::max(a.x, b.x); ++x) {
      const Cell c{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
      if (oracle_touches(a, b, c)) out.push_back(c);
    }
  std::sort(out.begin(), out.end()); // Cell's order (x, then y), as the tests sort the cover
  return out;
}

std::vector<Cell> sorted(std::vector<Cell> v) {
  std::sort(v.begin(), v.end());
  return v;
}

bool adjacent4(Cell p, Cell q) {
  const std::int64_t d = std::abs(std::int64_t{p.x} - q.x) + std::abs(std::int64_t{p.y} - q.y);
  return d == 1;
}

bool connected4(const std::vector<Cell>& cells) {
  if (cells.empty()) return false;
  const std::set<Cell> all(cells.begin(), cells.end());
  std::set<Cell> seen{cells.front()};
  std::deque<Cell> todo{cells.front()};
  while (!todo.empty()) {
    const Cell c = todo.front();
    todo.pop_front();
    for (Cell d : antkit::kernel::kNeighbours4)
      if (all.count(c + d) != 0 && seen.insert(c + d).second) todo.push_back(c + d);
  }
  return seen.size() == all.size();
}

// The corners (half-integer points) a segment from (0, 0) to (dx, dy) passes through: with
// g = gcd(dx, dy), there are g of them when dx / g and dy / g are both odd, none otherwise.
std::int64_t corner_count(std::int64_t dx, std::int64_t dy) {
  dx = std::abs(dx);
  dy = std::abs(dy);
  const std::int64_t g = std::gcd(dx, dy);
  if (g == 0) return 0;
  return ((dx / g) % 2 == 1 && (dy / g) % 2 == 1) ? g : 0;
}

// A cell in [-40, 40]^2: long enough segments for many corners, small enough for the oracle.
// Drawn as two ints so that a counterexample prints them (no printer for Cell is defined here: a
// second definition in another test file of the same executable would break the ODR).
Cell small_cell() {
  const auto x = *rc::gen::inRange(-40, 41);
  const auto y = *rc::gen::inRange(-40, 41);
  return {x, y};
}

using P = std::vector<std::pair<std::int32_t, std::int32_t>>;

// Cells as pairs, which Catch and rapidcheck know how to print.
P pairs(const std::vector<Cell>& cells) {
  P out;
  for (Cell c : cells) out.emplace_back(c.x, c.y);
  return out;
}

} // namespace

TEST_CASE("supercover worked examples", "[raster]") {
  // A horizontal segment: just the row.
  CHECK(pairs(supercover({0, 0}, {3, 0})) == P{{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  // A single cell.
  CHECK(pairs(supercover({5, -2}, {5, -2})) == P{{5, -2}});
  // The diagonal passes through the corner (1/2, 1/2): both side cells, x-side first.
  CHECK(pairs(supercover({0, 0}, {1, 1})) == P{{0, 0}, {1, 0}, {0, 1}, {1, 1}});
  // The same set backwards, in the reverse direction's own order (x-side first again).
  CHECK(pairs(supercover({1, 1}, {0, 0})) == P{{1, 1}, {0, 1}, {1, 0}, {0, 0}});
  // (0,0)-(2,1) crosses x = 1/2 at y = 1/4 and y = 1/2 at x = 1: no corner; 4 cells.
  CHECK(pairs(supercover({0, 0}, {2, 1})) == P{{0, 0}, {1, 0}, {1, 1}, {2, 1}});
  // (0,0)-(3,1) passes through the corner (3/2, 1/2).
  CHECK(pairs(supercover({0, 0}, {3, 1})) == P{{0, 0}, {1, 0}, {2, 0}, {1, 1}, {2, 1}, {3, 1}});
}

TEST_CASE("supercover: the cells the exact oracle says the segment touches", "[raster][property]") {
  rc::prop("same set as the oracle, each cell once, from a to b", [] {
    const Cell a = small_cell();
    const Cell b = small_cell();
    const std::vector<Cell> cover = supercover(a, b);
    RC_ASSERT(cover.front() == a);
    RC_ASSERT(cover.back() == b);
    const std::vector<Cell> s = sorted(cover);
    RC_ASSERT(std::adjacent_find(s.begin(), s.end()) == s.end());
    RC_ASSERT(pairs(s) == pairs(oracle_cells(a, b)));
  });
  rc::prop("4-connected, and each cell is 4-adjacent to one of the two before it", [] {
    const Cell a = small_cell();
    const Cell b = small_cell();
    const std::vector<Cell> cover = supercover(a, b);
    RC_ASSERT(connected4(cover));
    for (std::size_t k = 1; k < cover.size(); ++k)
      RC_ASSERT(adjacent4(cover[k], cover[k - 1]) || (k >= 2 && adjacent4(cover[k], cover[k - 2])));
  });
  rc::prop("the same set from b to a", [] {
    const Cell a = small_cell();
    const Cell b = small_cell();
    RC_ASSERT(pairs(sorted(supercover(a, b))) == pairs(sorted(supercover(b, a))));
  });
  rc::prop("|dx| + |dy| + 1 cells plus one per corner passed", [] {
    const Cell a = small_cell();
    const Cell b = small_cell();
    const std::int64_t dx = std::int64_t{b.x} - a.x, dy = std::int64_t{b.y} - a.y;
    RC_ASSERT(static_cast<std::int64_t>(supercover(a, b).size()) ==
              std::abs(dx) + std::abs(dy) + 1 + corner_count(dx, dy));
  });
  rc::prop("a bool callback stops the walk where it returns false", [] {
    const Cell a = small_cell();
    const Cell b = small_cell();
    const std::vector<Cell> all = supercover(a, b);
    const auto stop = *rc::gen::inRange<std::size_t>(0, all.size());
    std::vector<Cell> seen;
    for_each_supercover_cell(a, b, [&](Cell c) {
      seen.push_back(c);
      return seen.size() <= stop;
    });
    RC_ASSERT(pairs(seen) ==
              pairs(std::vector<Cell>(all.begin(), all.begin() + static_cast<long>(stop) + 1)));
  });
}

TEST_CASE("supercover at the ends of the int32 range", "[raster]") {
  // Differences need 33 bits here; the walk is in 64 bits and must not overflow (UBSan in the
  // debug preset). Only the first and last cells are checked against the oracle's view.
  const Cell lo{INT32_MIN, INT32_MIN}, hi{INT32_MAX, INT32_MIN + 2};
  std::size_t n = 0;
  Cell first{}, last{};
  for_each_supercover_cell(lo, hi, [&](Cell c) {
    if (n == 0) first = c;
    last = c;
    ++n;
    return n < 5; // the full walk is 2^32 cells; stop early
  });
  CHECK(first == lo);
  CHECK(n == 5);
  CHECK(oracle_touches(lo, hi, last));
  // A short segment next to the edge of the range, walked to the end.
  const Cell p{INT32_MAX - 3, INT32_MAX}, q{INT32_MAX, INT32_MAX - 2};
  CHECK(pairs(sorted(supercover(p, q))) == pairs(oracle_cells(p, q)));
}

TEST_CASE("the supercover decision variable stays in [-2dx, 2dy]", "[raster][property]") {
  // The range argument of raster.hpp, checked on the walk itself for segments as long as a grid
  // side allows (first steps only: the bound is per step, and the per-step check is what matters).
  rc::prop("invariant on the first 4096 steps", [] {
    const auto dx = *rc::gen::inRange<std::int64_t>(0, kMaxGridSide);
    const auto dy = *rc::gen::inRange<std::int64_t>(0, kMaxGridSide);
    SupercoverWalk<std::int64_t> w(dx, dy);
    for (int step = 0; step < 4096 && !w.done(); ++step) {
      RC_ASSERT(w.e >= -2 * dx);
      RC_ASSERT(w.e <= 2 * dy);
      RC_ASSERT(w.e == dy * (2 * w.i + 1) - dx * (2 * w.j + 1));
      w.advance();
    }
  });
}

TEST_CASE("a 32-bit walk equals the 64-bit walk for the longest grid segments", "[raster]") {
  // The bound |e| < 2^21 for grid sides up to kMaxGridSide means the walk can run in int32.
  // Walk the longest diagonal and near-diagonals of the largest grid in both widths.
  const std::int32_t m = kMaxGridSide - 1;
  for (auto [dx, dy] : {std::pair{m, m}, std::pair{m, m - 1}, std::pair{m, 1}, std::pair{1, m},
                        std::pair{m - 2, m}}) {
    SupercoverWalk<std::int32_t> narrow(dx, dy);
    SupercoverWalk<std::int64_t> wide(dx, dy);
    std::int64_t steps = 0;
    bool same = true;
    std::int64_t max_abs_e = 0;
    while (!wide.done()) {
      same = same && narrow.advance() == wide.advance() && narrow.i == wide.i &&
             narrow.j == wide.j && narrow.e == wide.e;
      max_abs_e = std::max(max_abs_e, std::abs(wide.e));
      ++steps;
    }
    CHECK(same);
    CHECK(narrow.done());
    CHECK(max_abs_e < (std::int64_t{1} << 21));
    CHECK(steps == dx + dy - corner_count(dx, dy));
  }
}

TEST_CASE("every segment between cell centres in a 32x32 grid matches the oracle",
          "[raster][proof]") {
  // Exhaustive small scope: all 1024 x 1024 ordered pairs of cells (both directions, a == b
  // included). For each, the supercover's cells, sorted, must equal the oracle's cell set.
  constexpr std::int32_t n = 32;
  std::int64_t checked = 0, mismatches = 0;
  std::vector<Cell> cover;
  for (std::int32_t ay = 0; ay < n; ++ay)
    for (std::int32_t ax = 0; ax < n; ++ax)
      for (std::int32_t by = 0; by < n; ++by)
        for (std::int32_t bx = 0; bx < n; ++bx) {
          const Cell a{ax, ay}, b{bx, by};
          cover.clear();
          for_each_supercover_cell(a, b, [&](Cell c) { cover.push_back(c); });
          std::sort(cover.begin(), cover.end());
          if (cover != oracle_cells(a, b)) {
            if (mismatches == 0)
              INFO("first mismatch: " << ax << "," << ay << " -> " << bx << "," << by);
            ++mismatches;
          }
          ++checked;
        }
  CHECK(checked == std::int64_t{n} * n * n * n);
  CHECK(mismatches == 0);
}

TEST_CASE("bresenham worked examples", "[raster]") {
  CHECK(pairs(bresenham({0, 0}, {4, 0})) == P{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}});
  CHECK(pairs(bresenham({0, 0}, {2, 2})) == P{{0, 0}, {1, 1}, {2, 2}});
  // (0,0)-(4,1): at x = 2 the line is at y = 1/2, a tie, which moves away from a.
  CHECK(pairs(bresenham({0, 0}, {4, 1})) == P{{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 1}});
  // Backwards, the tie again moves away from the start, so it is not the reverse.
  CHECK(pairs(bresenham({4, 1}, {0, 0})) == P{{4, 1}, {3, 1}, {2, 0}, {1, 0}, {0, 0}});
  CHECK(pairs(bresenham({0, 0}, {-1, -3})) == P{{0, 0}, {0, -1}, {-1, -2}, {-1, -3}});
}

TEST_CASE("bresenham: nearest cell per major step, ties away from a", "[raster][property]") {
  rc::prop("matches the rounding oracle, 8-connected, inside the supercover", [] {
    const Cell a = small_cell();
    const Cell b = small_cell();
    const std::vector<Cell> line = bresenham(a, b);
    const std::int64_t dx = std::int64_t{b.x} - a.x, dy = std::int64_t{b.y} - a.y;
    const bool x_major = std::abs(dx) >= std::abs(dy);
    const std::int64_t dmaj = x_major ? std::abs(dx) : std::abs(dy);
    const std::int64_t dmin = x_major ? std::abs(dy) : std::abs(dx);
    const std::int64_t smaj = (x_major ? dx : dy) < 0 ? -1 : 1;
    const std::int64_t smin = (x_major ? dy : dx) < 0 ? -1 : 1;
    RC_ASSERT(static_cast<std::int64_t>(line.size()) == dmaj + 1);
    for (std::int64_t k = 0; k <= dmaj; ++k) {
      // round(k * dmin / dmaj) with halves rounded up (away from a): floor((2 k dmin + dmaj) /
      // 2dmaj).
      const std::int64_t m = dmaj == 0 ? 0 : (2 * k * dmin + dmaj) / (2 * dmaj);
      const std::int64_t mx = x_major ? k * smaj : m * smin, my = x_major ? m * smin : k * smaj;
      const Cell want{static_cast<std::int32_t>(a.x + mx), static_cast<std::int32_t>(a.y + my)};
      RC_ASSERT(line[static_cast<std::size_t>(k)] == want);
    }
    for (std::size_t k = 1; k < line.size(); ++k)
      RC_ASSERT(
          std::max(std::abs(line[k].x - line[k - 1].x), std::abs(line[k].y - line[k - 1].y)) == 1);
    const std::vector<Cell> cover = sorted(supercover(a, b));
    for (Cell c : line) RC_ASSERT(std::binary_search(cover.begin(), cover.end(), c));
  });
  rc::prop("a bool callback stops Bresenham too", [] {
    const Cell a = small_cell();
    const Cell b = small_cell();
    std::size_t seen = 0;
    for_each_bresenham_cell(a, b, [&](Cell) { return ++seen < 2; });
    RC_ASSERT(seen == std::min<std::size_t>(2, bresenham(a, b).size()));
  });
}
