// MovingAI .map reading and writing: worked examples, the README's pitfalls (CRLF, W/T/@, 'S' is
// swamp), and one error per way a file can be wrong, each at its LINE:COL.
#include "map_test_support.hpp"

#include <antkit/maps/map_io.hpp>
#include <catch2/catch.hpp>

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::maps::parse_movingai;
using antkit::maps::test::contains;
using antkit::maps::test::error_of;

namespace {
const std::string kHeader3x2 = "type octile\nheight 2\nwidth 3\nmap\n";
}

TEST_CASE("MovingAI: a worked example, x right and y down from the first row", "[maps][movingai]") {
  const auto m = parse_movingai(kHeader3x2 + ".@T\nGSW\n", "ex.map");
  REQUIRE(m.cells.width() == 3);
  REQUIRE(m.cells.height() == 2);
  CHECK(m.cells[Cell{0, 0}] == Occupancy::Free);
  CHECK(m.cells[Cell{1, 0}] == Occupancy::Blocked);
  CHECK(m.cells[Cell{2, 0}] == Occupancy::Blocked); // T, trees
  CHECK(m.cells[Cell{0, 1}] == Occupancy::Free);    // G
  CHECK(m.cells[Cell{1, 1}] == Occupancy::Free);    // S is swamp, passable
  CHECK(m.cells[Cell{2, 1}] == Occupancy::Blocked); // W, water: the safe choice
  CHECK_FALSE(m.start.has_value());                 // 'S' is not a start in this format
  CHECK(m.resolution == 1.0);
}

TEST_CASE("MovingAI: CRLF, width before height, blank lines at the end are all accepted",
          "[maps][movingai]") {
  const auto lf = parse_movingai(kHeader3x2 + "..@\n@O.\n", "lf.map");
  const auto crlf =
      parse_movingai("type octile\r\nheight 2\r\nwidth 3\r\nmap\r\n..@\r\n@O.\r\n\r\n", "crlf.map");
  const auto swapped = parse_movingai("type octile\nwidth 3\nheight 2\nmap\n..@\n@O.", "sw.map");
  const auto spaced =
      parse_movingai("type  octile\nheight\t2\nwidth 3 \nmap \n..@\n@O.\n\n\n", "s");
  CHECK(crlf == lf);
  CHECK(swapped == lf);
  CHECK(spaced == lf);
}

TEST_CASE("MovingAI: writing gives the benchmark's own layout", "[maps][movingai]") {
  antkit::maps::GridMap m;
  m.cells = antkit::kernel::OccupancyGrid(3, 2, Occupancy::Free);
  m.cells[Cell{1, 0}] = Occupancy::Blocked;
  m.cells[Cell{2, 1}] = Occupancy::Unknown; // no unknown in MovingAI: written blocked
  m.start = Cell{0, 1};                     // no start in MovingAI: not written
  CHECK(antkit::maps::write_movingai(m) == kHeader3x2 + ".@.\n..@\n");
}

TEST_CASE("MovingAI: every malformed file is an InputError at its line and column",
          "[maps][movingai]") {
  struct Case {
    std::string text;
    std::size_t line, column;
    std::string says;
  };
  const std::vector<Case> cases{
      {"", 1, 1, "ends inside the header"},
      {"type octile\nheight 2\n", 3, 1, "ends inside the header"},
      {"kind octile\n", 1, 1, "expected `type octile`"},
      {"type hex\nheight 1\nwidth 1\nmap\n.\n", 1, 6, "not supported"},
      {"type octile\nHeight 1\nwidth 1\nmap\n.\n", 2, 1, "lower case"},
      {"type octile\nheight 1\nheight 1\nmap\n.\n", 3, 1, "second `height`"},
      {"type octile\nheight -1\nwidth 1\nmap\n.\n", 2, 8, "bad height"},
      {"type octile\nheight 1x\nwidth 1\nmap\n.\n", 2, 8, "bad height"},
      {"type octile\nheight 1 2\nwidth 1\nmap\n.\n", 2, 10, "one whole number"},
      {"type octile\nheight 0\nwidth 1\nmap\n", 3, 1, "outside the supported range"},
      {"type octile\nheight 2000000\nwidth 1\nmap\n", 3, 1, "outside the supported range"},
      {"type octile\nheight 99999999999999999999999\nwidth 1\nmap\n", 2, 8, "bad height"},
      {"type octile\nheight 20000\nwidth 20000\nmap\n", 3, 1, "over the cap"},
      {"type octile\nheight 1\nwidth 1\nmaps\n.\n", 4, 1, "expected `map`"},
      {"type octile\nheight 1\nwidth 1\nmap x\n.\n", 4, 1, "expected `map`"},
      {kHeader3x2 + "...\n", 6, 1, "ends after 1 rows"},
      {kHeader3x2 + "...\n..\n", 6, 3, "has 2 cells; expected 3"},
      {kHeader3x2 + "...\n....\n", 6, 4, "has 4 cells; expected 3"},
      {kHeader3x2 + "...\n.#.\n", 6, 2, "unexpected cell '#'"},
      {kHeader3x2 + "...\n.\x01.\n", 6, 2, "unexpected cell '\\x01'"},
      {kHeader3x2 + "...\n.\r.\n", 6, 2, "unexpected cell '\\x0d'"},
      {kHeader3x2 + "...\n...\n...\n", 7, 1, "after the 2 rows"},
  };
  for (const auto& c : cases) {
    INFO(c.text);
    const auto e = error_of([&] { (void)parse_movingai(c.text, "bad.map"); });
    REQUIRE(e.thrown);
    CHECK(e.line == c.line);
    CHECK(e.column == c.column);
    CHECK(contains(e.what, c.says));
    CHECK(e.what.rfind("bad.map:" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": ",
                       0) == 0);
  }
}

TEST_CASE("MovingAI: read(write(grid)) is the grid for any free/blocked grid",
          "[maps][movingai][property]") {
  rc::prop("round trip", [] {
    antkit::maps::GridMap m;
    m.cells = *antkit::maps::test::gen_two_valued_grid();
    RC_ASSERT(parse_movingai(antkit::maps::write_movingai(m), "rt.map") == m);
  });
  rc::prop("unknown is written blocked, everything else kept", [] {
    antkit::maps::GridMap m;
    m.cells = *antkit::maps::test::gen_three_valued_grid();
    const auto back = parse_movingai(antkit::maps::write_movingai(m), "rt.map");
    RC_ASSERT(back.cells.width() == m.cells.width());
    RC_ASSERT(back.cells.height() == m.cells.height());
    for (std::size_t i = 0; i < m.cells.size(); ++i) {
      const auto want =
          m.cells.cells()[i] == Occupancy::Unknown ? Occupancy::Blocked : m.cells.cells()[i];
      RC_ASSERT(back.cells.cells()[i] == want);
    }
  });
}
