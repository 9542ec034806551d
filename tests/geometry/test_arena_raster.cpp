// Rasterization: the scanline rasterizer agrees cell for cell with the brute-force oracle (an
// exact point-in-polygon test of every cell centre), including walls through centres.
#include "arena_generators.hpp"

#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_cgal.hpp>
#include <antkit/geometry/arena_raster.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
#include <sstream>
#include <string>

using namespace antkit::geometry;
using antkit::kernel::Cell;
using antkit::kernel::InputError;
using antkit::kernel::Occupancy;

namespace {

// The exact centre of cell (i, j): ((col0 + i + 1/2) c, (row0 - j - 1/2) c).
ExactPoint centre(const RasterFrame& f, Cell cell) {
  const ExactNumber c(static_cast<long>(f.cell.num()), static_cast<unsigned long>(f.cell.den()));
  return {(ExactNumber(static_cast<long>(f.col0 + cell.x)) + ExactNumber(1, 2)) * c,
          (ExactNumber(static_cast<long>(f.row0 - cell.y)) - ExactNumber(1, 2)) * c};
}

// Where the raster and the oracle disagree, or "" when they agree everywhere.
std::string disagreement(const Arena& arena, const ArenaRaster& r) {
  const auto& polygon = exact_polygon(arena);
  for (std::int32_t y = 0; y < r.grid.height(); ++y)
    for (std::int32_t x = 0; x < r.grid.width(); ++x) {
      const bool free = antkit::test::strictly_inside(polygon, centre(r.frame, {x, y}));
      if (free != (r.grid[{x, y}] == Occupancy::Free)) {
        std::ostringstream s;
        s << "cell (" << x << ", " << y << "): oracle says " << (free ? "free" : "blocked");
        return s.str();
      }
    }
  return "";
}

// The frame rule of arena_raster.hpp, checked against the bounding box.
void check_frame(const Arena& arena, const ArenaRaster& r) {
  const auto box = arena.bbox();
  const double c = r.frame.cell.value();
  CHECK(static_cast<double>(r.frame.col0) * c <= box.xmin);
  CHECK(static_cast<double>(r.frame.col0 + 1) * c > box.xmin);
  CHECK(static_cast<double>(r.frame.row0) * c >= box.ymax);
  CHECK(static_cast<double>(r.frame.row0 - 1) * c < box.ymax);
  CHECK(static_cast<double>(r.frame.col0 + r.grid.width()) * c >= box.xmax);
  CHECK(static_cast<double>(r.frame.row0 - r.grid.height()) * c <= box.ymin);
}

} // namespace

TEST_CASE("cell sizes are read exactly", "[raster]") {
  CHECK(CellSize::parse("0.01", "t").num() == 1);
  CHECK(CellSize::parse("0.01", "t").den() == 100);
  CHECK(CellSize::parse("2.5", "t").num() == 5);
  CHECK(CellSize::parse("2.5", "t").den() == 2);
  CHECK(CellSize::parse("1e-2", "t").den() == 100);
  CHECK(CellSize::parse("300", "t").num() == 300);
  for (const char* bad : {"", "0", "0.0", "-1", "abc", "1x", "1e-9", "1e7", "1e", ".", "nan",
                          "1234567890123456789", "1e--5", "1e+-5", "0x10", " 1"})
    CHECK_THROWS_AS(CellSize::parse(bad, "t"), InputError);
}

TEST_CASE("a worked example: walls through cell centres block those cells", "[raster]") {
  // The square [0.5, 3.5]^2 at cell size 1: its walls pass through the centres (k + 1/2) of the
  // border cells, so only the 2 x 2 cells whose centres are inside are free.
  const Arena a = read_wkt("POLYGON ((0.5 0.5, 3.5 0.5, 3.5 3.5, 0.5 3.5, 0.5 0.5))");
  const auto r = rasterize(a, CellSize(1, 1));
  REQUIRE(r.grid.width() == 4);
  REQUIRE(r.grid.height() == 4);
  CHECK(r.frame.col0 == 0);
  CHECK(r.frame.row0 == 4);
  std::size_t free = 0;
  for (auto c : r.grid.cells()) free += c == Occupancy::Free ? 1 : 0;
  CHECK(free == 4);
  CHECK(r.grid[{1, 1}] == Occupancy::Free);
  CHECK(r.grid[{2, 2}] == Occupancy::Free);
  CHECK(r.grid[{0, 1}] == Occupancy::Blocked);
}

TEST_CASE("a worked example: y goes down", "[raster]") {
  // A triangle with its wide side at the top of the arena: the grid's row 0 is the top.
  const Arena a = read_wkt("POLYGON ((0 10, 0 9, 10 10, 0 10))");
  const auto r = rasterize(a, CellSize(1, 2));
  CHECK(r.grid.height() == 2);
  // The hypotenuse is y = 9 + x / 10; at x = 3.25 it is at 9.325.
  CHECK(r.grid[{6, 0}] == Occupancy::Free);    // centre (3.25, 9.75): above it, inside
  CHECK(r.grid[{6, 1}] == Occupancy::Blocked); // centre (3.25, 9.25): below it, outside
  CHECK(disagreement(a, r).empty());
}

TEST_CASE("vertices and horizontal hole edges on a scanline are walls", "[raster]") {
  // A diamond hole whose top and bottom vertices and left/right vertices sit on cell centres, and a
  // horizontal hole edge along a row of centres.
  const Arena a = read_wkt("POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (5.5 2.5, 7.5 4.5, 5.5 6.5, "
                           "3.5 4.5, 5.5 2.5), (1.5 7.5, 3.5 7.5, 2.5 8.5, 1.5 7.5))");
  const auto r = rasterize(a, CellSize(1, 1));
  INFO(disagreement(a, r));
  CHECK(disagreement(a, r).empty());
  // The diamond's bottom vertex (5.5, 2.5) is the centre of cell (5, 7): a wall point.
  CHECK(r.grid[{5, 7}] == Occupancy::Blocked);
  CHECK(r.grid[{5, 8}] == Occupancy::Free);
}

TEST_CASE("every family rasterizes exactly as the oracle says", "[raster]") {
  const std::vector<std::pair<const char*, Arena>> arenas{
      {"circle 10", make_circle(10)},
      {"square", make_square(7854)},
      {"ellipse", make_ellipse(7854, 0.998)},
      {"barrier |", make_barrier_arena(Barrier::I, 0.9)},
      {"barrier +", make_barrier_arena(Barrier::Plus, 0.4)},
      {"ring", make_ring(7854)},
      {"plus", make_plus(7854)},
      {"obstacles", make_obstacles_arena(7854)},
  };
  for (const auto& [name, arena] : arenas) {
    for (const auto& cell : {CellSize(5, 2), CellSize(1, 1)}) {
      if (std::string(name) != "circle 10" && cell.num() == 1) continue; // keep the oracle quick
      INFO(name << " at cell size " << cell.value());
      const auto r = rasterize(arena, cell);
      check_frame(arena, r);
      const auto where = disagreement(arena, r);
      INFO(where);
      CHECK(where.empty());
    }
  }
  // The barrier arena at one cell per robot diameter keeps its bar.
  const auto r = rasterize(make_barrier_arena(Barrier::I, 0.4), CellSize(1, 1));
  // Cells (x, y) = (col0 + i, row0 - j) in cell units; the bar covers x in [-1/2, 1/2], so the
  // centres (+-1/2, -1/2) beside the origin are on its walls and (3/2, -1/2) is free.
  const auto at = [&](std::int64_t x, std::int64_t y) {
    return r.grid[{static_cast<std::int32_t>(x - r.frame.col0),
                   static_cast<std::int32_t>(r.frame.row0 - y)}];
  };
  CHECK(at(0, 0) == Occupancy::Blocked);
  CHECK(at(-1, 0) == Occupancy::Blocked);
  CHECK(at(1, 0) == Occupancy::Free);
}

TEST_CASE("random arenas and cell sizes rasterize exactly as the oracle says",
          "[raster][property]") {
  rc::prop("scanline == oracle", [] {
    const Arena a = antkit::test::random_arena_with_holes(*rc::gen::inRange(0, 3));
    // Cell sizes from 2 to 10 in steps of 1/4 (some put centres on the decimal vertices); not
    // smaller, to keep the brute-force oracle quick.
    const CellSize cell(*rc::gen::inRange(8, 41), 4);
    RC_CLASSIFY(a.hole_count() > 0, "with holes");
    const auto r = rasterize(a, cell);
    RC_ASSERT(disagreement(a, r).empty());
  });
}

TEST_CASE("a raster too large is bad input", "[raster]") {
  CHECK_THROWS_AS(rasterize(make_circle(100), CellSize(1, 100000), 1u << 20), InputError);
  CHECK_THROWS_AS(rasterize(make_circle(100), CellSize(1, 1), 100), InputError);
}
