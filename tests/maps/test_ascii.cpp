// ASCII maps: `.` free, `#` blocked, `S` start, `?` unknown. Worked examples, errors at their
// LINE:COL, and round trips between ASCII and MovingAI.
#include "map_test_support.hpp"

#include <antkit/maps/map_io.hpp>
#include <catch2/catch.hpp>

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::maps::GridMap;
using antkit::maps::parse_ascii;
using antkit::maps::write_ascii;
using antkit::maps::test::contains;
using antkit::maps::test::error_of;

TEST_CASE("ASCII: a worked example with a start and an unknown cell", "[maps][ascii]") {
  const auto m = parse_ascii("#.S\n?..\n", "ex.txt");
  REQUIRE(m.cells.width() == 3);
  REQUIRE(m.cells.height() == 2);
  CHECK(m.cells[Cell{0, 0}] == Occupancy::Blocked);
  CHECK(m.cells[Cell{1, 0}] == Occupancy::Free);
  CHECK(m.cells[Cell{2, 0}] == Occupancy::Free); // the start is a free cell
  CHECK(m.cells[Cell{0, 1}] == Occupancy::Unknown);
  REQUIRE(m.start.has_value());
  CHECK(*m.start == Cell{2, 0});
  CHECK(write_ascii(m) == "#.S\n?..\n");
}

TEST_CASE("ASCII: CRLF, a missing final newline and trailing blank lines read the same",
          "[maps][ascii]") {
  const auto lf = parse_ascii("..#\n#S.\n", "a.txt");
  CHECK(parse_ascii("..#\r\n#S.\r\n", "a.txt") == lf);
  CHECK(parse_ascii("..#\n#S.", "a.txt") == lf);
  CHECK(parse_ascii("..#\n#S.\n\n\r\n", "a.txt") == lf);
}

TEST_CASE("ASCII: every malformed file is an InputError at its line and column", "[maps][ascii]") {
  struct Case {
    std::string text;
    std::size_t line, column;
    std::string says;
  };
  const std::vector<Case> cases{
      {"", 1, 1, "empty"},
      {"\n\n", 1, 1, "empty"},
      {"\n..\n", 1, 1, "blank line inside"},
      {"..\n\n..\n", 2, 1, "blank line inside"},
      {"...\n..\n", 2, 3, "has 2 cells; expected 3"},
      {"..\n...\n", 2, 3, "has 3 cells; expected 2"},
      {"..\n.@\n", 2, 2, "unexpected cell '@'"},
      {"S.\n.S\n", 2, 2, "second start cell S (the first is at 1:1)"},
      {". \n", 1, 2, "unexpected cell ' '"},
      {std::string(2000000, '.') + "\n", 1, 1, "outside the supported range"},
  };
  for (const auto& c : cases) {
    INFO(c.text.substr(0, 40));
    const auto e = error_of([&] { (void)parse_ascii(c.text, "bad.txt"); });
    REQUIRE(e.thrown);
    CHECK(e.line == c.line);
    CHECK(e.column == c.column);
    CHECK(contains(e.what, c.says));
  }
}

TEST_CASE("ASCII: a map over the total-cell cap is refused at the row that crosses it",
          "[maps][ascii]") {
  // 16384 x 16385 cells is one row over kMaxMapCells = 16384 x 16384.
  const std::string row = std::string(16384, '.') + "\n";
  std::string text;
  text.reserve(row.size() * 16385);
  for (int i = 0; i < 16385; ++i) text += row;
  const auto e = error_of([&] { (void)parse_ascii(text, "big.txt"); });
  REQUIRE(e.thrown);
  CHECK(e.line == 16385);
  CHECK(contains(e.what, "over the cap of 268435456 cells"));
  text.resize(row.size() * 16384);
  CHECK(parse_ascii(text, "big.txt").cells.size() == 16384u * 16384u);
}

TEST_CASE("ASCII: writing refuses what it cannot represent", "[maps][ascii]") {
  GridMap empty;
  CHECK_THROWS_AS(write_ascii(empty), std::invalid_argument);
  GridMap m;
  m.cells = antkit::kernel::OccupancyGrid(2, 2, Occupancy::Blocked);
  m.start = Cell{0, 0}; // on a blocked cell
  CHECK_THROWS_AS(write_ascii(m), std::invalid_argument);
  m.start = Cell{5, 0}; // off the grid
  CHECK_THROWS_AS(write_ascii(m), std::invalid_argument);
}

namespace {
// A map with an optional start on one of its free cells.
rc::Gen<GridMap> gen_map_with_start(bool with_unknown) {
  const auto grids = with_unknown ? antkit::maps::test::gen_three_valued_grid()
                                  : antkit::maps::test::gen_two_valued_grid();
  return rc::gen::mapcat(grids, [](antkit::kernel::OccupancyGrid g) {
    std::vector<Cell> free;
    for (std::size_t i = 0; i < g.size(); ++i)
      if (g.cells()[i] == Occupancy::Free) free.push_back(g.cell_at(i));
    return rc::gen::map(rc::gen::inRange<std::size_t>(0, free.size() + 1),
                        [g, free](std::size_t k) {
                          GridMap m;
                          m.cells = g;
                          if (k < free.size()) m.start = free[k];
                          return m;
                        });
  });
}
} // namespace

TEST_CASE("ASCII: round trips", "[maps][ascii][property]") {
  rc::prop("read(write(map)) is the map, start and unknown cells included", [] {
    const auto m = *gen_map_with_start(true);
    RC_ASSERT(parse_ascii(write_ascii(m), "rt.txt") == m);
  });
  rc::prop("ASCII -> MovingAI -> ASCII keeps a free/blocked grid (the start is dropped)", [] {
    const auto m = *gen_map_with_start(false);
    const auto movingai = antkit::maps::parse_movingai(antkit::maps::write_movingai(m), "rt.map");
    RC_ASSERT(movingai.cells == m.cells);
    RC_ASSERT(!movingai.start.has_value());
    const auto back = parse_ascii(write_ascii(movingai), "rt.txt");
    RC_ASSERT(back.cells == m.cells);
  });
  rc::prop("MovingAI -> ASCII -> MovingAI gives the same file", [] {
    GridMap m;
    m.cells = *antkit::maps::test::gen_two_valued_grid();
    const auto file = antkit::maps::write_movingai(m);
    const auto ascii = parse_ascii(write_ascii(antkit::maps::parse_movingai(file, "a.map")), "a");
    RC_ASSERT(antkit::maps::write_movingai(ascii) == file);
  });
}
