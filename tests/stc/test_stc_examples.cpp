// Worked examples, errors and golden hashes of the STC variants (issue 3).
#include "stc_test_maps.hpp"

#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/ant.hpp>
#include <antkit/stc/full.hpp>
#include <antkit/stc/offline.hpp>
#include <antkit/stc/online.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/stc.hpp>
#include <catch2/catch.hpp>

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using namespace antkit::stc;
using antkit::stc::testing::from_rows;

namespace {
const std::vector<Variant> kExact{Variant::Offline, Variant::Online, Variant::Ant,
                                  Variant::AntEdge};
}

TEST_CASE("one free cell: the tour is its four sub-cells counter-clockwise from the start",
          "[stc]") {
  const OccupancyGrid map(2, 2, Occupancy::Free);
  for (Variant v : kExact) {
    INFO(variant_name(v));
    // NW (0,0) -> SW (0,1) -> SE (1,1) -> NE (1,0): counter-clockwise as drawn, y down.
    const RunResult r = run_stc(map, {0, 0}, v);
    CHECK(r.path == std::vector<Cell>{{0, 0}, {0, 1}, {1, 1}, {1, 0}});
    CHECK(r.closed);
    CHECK(r.returned_to_start);
    CHECK(r.covered == 4);
    CHECK(r.repeats == 0);
    CHECK(r.reachable_subcells == 4);
  }
}

TEST_CASE("two cells side by side: into the east child from SE - back into NE", "[stc]") {
  const OccupancyGrid map(4, 2, Occupancy::Free);
  const std::vector<Cell> expected{{0, 0}, {0, 1}, {1, 1}, {2, 1}, {3, 1}, {3, 0}, {2, 0}, {1, 0}};
  for (Variant v : kExact) {
    INFO(variant_name(v));
    CHECK(run_stc(map, {0, 0}, v).path == expected);
  }
}

TEST_CASE("a child in the start's last direction: the tour ends outside the start cell - next to "
          "the start sub-cell",
          "[stc]") {
  // Start SE (1,1) of the west cell: q0 = SE = 0, its virtual parent is q0 - 1 = S... the east
  // cell is scanned first. Start NE (1,0) instead: q0 = 1, scan N, W, S, then E last.
  const OccupancyGrid map(4, 2, Occupancy::Free);
  const std::vector<Cell> expected{{1, 0}, {0, 0}, {0, 1}, {1, 1}, {2, 1}, {3, 1}, {3, 0}, {2, 0}};
  for (Variant v : kExact) {
    INFO(variant_name(v));
    const RunResult r = run_stc(map, {1, 0}, v);
    CHECK(r.path == expected);
    CHECK(r.returned_to_start); // (2,0) is 4-adjacent to (1,0)
  }
}

TEST_CASE("an odd width or height: the last column or row belongs to no cell and is never entered",
          "[stc]") {
  const OccupancyGrid map(5, 7, Occupancy::Free); // 2 x 3 cells, column 4 and row 6 left over
  antkit::testing::StcTourChecker checker;
  for (Variant v : kExact) {
    INFO(variant_name(v));
    const RunResult r = run_stc(map, {2, 2}, v);
    CHECK(r.path.size() == 24);
    for (Cell s : r.path) CHECK((s.x < 4 && s.y < 6));
    const auto check = checker.check_exact(map, {2, 2}, r.path);
    CHECK(check.ok);
    INFO(check);
  }
  const RunResult full = run_stc(map, {2, 2}, Variant::Full);
  for (Cell s : full.path) CHECK((s.x < 4 && s.y < 6));
  CHECK(full.covered == 24);
  // A start on the remainder is outside the cells.
  CHECK_THROWS_AS(run_stc(map, {4, 0}, Variant::Offline), antkit::kernel::InputError);
  CHECK_THROWS_AS(run_stc(map, {0, 6}, Variant::Full), antkit::kernel::InputError);
}

TEST_CASE("bad starts are input errors that say why", "[stc]") {
  const OccupancyGrid map = from_rows({"..##", "...#", "....", "...."});
  // (2,0) blocked; (2,1) free but its cell (1,0) has blocked sub-cells.
  for (Variant v : kExact) {
    CHECK_THROWS_WITH(run_stc(map, {2, 0}, v), Catch::Contains("inside an obstacle"));
    CHECK_THROWS_WITH(run_stc(map, {2, 1}, v), Catch::Contains("blocked sub-cell"));
    CHECK_THROWS_WITH(run_stc(map, {-1, 0}, v), Catch::Contains("outside"));
    CHECK_THROWS_WITH(run_stc(map, {0, 4}, v), Catch::Contains("outside"));
  }
  CHECK_THROWS_WITH(run_stc(map, {3, 1}, Variant::Full), Catch::Contains("inside an obstacle"));
  CHECK_NOTHROW(run_stc(map, {2, 1}, Variant::Full));
}

TEST_CASE("full covers the free sub-cells of partially blocked cells and counts its repeats",
          "[stc]") {
  // The exact variants see one free cell here (the NW one); full also enters the free sub-cells of
  // the three partial cells.
  const OccupancyGrid map = from_rows({"...#", "..#.", "....", "#..."});
  const RunResult exact = run_stc(map, {0, 0}, Variant::Offline);
  CHECK(exact.reachable_subcells == 4);
  const RunResult full = run_stc(map, {0, 0}, Variant::Full);
  antkit::testing::StcTourChecker checker;
  const auto check = checker.check_full(map, {0, 0}, full.path, full.repeats);
  INFO(check);
  CHECK(check.ok);
  CHECK(full.reachable_subcells == 13);
  CHECK(full.covered == 13);
  CHECK(full.repeats == static_cast<std::int64_t>(full.path.size()) - 13);
}

TEST_CASE("full on a map without partial cells is the exact tour (plus the step home when the "
          "start's last neighbour is a child)",
          "[stc]") {
  const OccupancyGrid map = from_rows({"......", "......", "..##..", "..##..", "......", "......"});
  for (const Cell start : {Cell{0, 0}, Cell{5, 5}, Cell{1, 4}}) {
    const RunResult exact = run_stc(map, start, Variant::Offline);
    const RunResult full = run_stc(map, start, Variant::Full);
    CHECK(full.repeats <= 1);
    const std::vector<Cell> head(
        full.path.begin(), full.path.begin() + static_cast<std::ptrdiff_t>(exact.path.size()));
    CHECK(head == exact.path);
  }
}

TEST_CASE("online memory grows with the cells seen - not with the map", "[stc]") {
  // A 2-cell corridor in a huge map: the robot sees a handful of cells.
  OccupancyGrid map(4096, 4096, Occupancy::Blocked);
  for (std::int32_t x = 0; x < 8; ++x)
    for (std::int32_t y = 2000; y < 2002; ++y) map[{x + 1000, y}] = Occupancy::Free;
  OnlineStc online(quadrant_of({1000, 2000}));
  StcWorld world(map, {1000, 2000});
  int moves = 0;
  for (;;) {
    const Command c = online.step(world.observe_cells());
    if (c.move == Move::Stop) break;
    REQUIRE(world.apply(c));
    ++moves;
  }
  CHECK(moves == 15);
  CHECK(online.memory().tiles() <= 2);
  CHECK(online.memory().bytes() < 4096);
}

TEST_CASE("a deep spanning tree does not recurse: a serpentine of 128 x 128 cells", "[stc]") {
  // Walls between rows of cells, alternately open at the east and west ends: the tree is one
  // path of 16384 cells, depth 16384.
  const int n = 128;
  OccupancyGrid map(2 * n, 4 * n - 2, Occupancy::Free);
  for (int row = 0; row + 1 < n; ++row) {
    const std::int32_t wall = 4 * row + 2; // a blocked row of cells between cell rows
    const std::int32_t gap = (row % 2 == 0) ? n - 1 : 0;
    for (std::int32_t cx = 0; cx < n; ++cx)
      if (cx != gap)
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) map[{2 * cx + dx, wall + dy}] = Occupancy::Blocked;
  }
  antkit::testing::StcTourChecker checker;
  const SpanningTree tree(map, {0, 0});
  CHECK(tree.cells() == n * n + (n - 1));
  const std::vector<Cell> path = tree.tour();
  const auto check = checker.check_exact(map, {0, 0}, path);
  INFO(check);
  CHECK(check.ok);
  const RunResult ant = run_stc(map, {0, 0}, Variant::Ant);
  CHECK(ant.path == path);
}

TEST_CASE("golden trace hashes: a fixed map - every exact variant the same tour and hash",
          "[stc][golden]") {
  // Changing a golden value is a deliberate, explained commit (DESIGN.md rule 5).
  const OccupancyGrid map = from_rows({
      "..........##",
      "..........##",
      "..##....#...",
      "..##........",
      "......##....",
      "......##....",
      "##..........",
      "##......#...",
  });
  const Cell start{4, 2};
  const RunResult reference = run_stc(map, start, Variant::Offline);
  CHECK(antkit::kernel::hash_hex(reference.hash) == "15d1eeecc39f20c4");
  for (Variant v : kExact) {
    INFO(variant_name(v));
    const RunResult r = run_stc(map, start, v);
    CHECK(r.hash == reference.hash);
    CHECK(r.path == reference.path);
  }
  CHECK(antkit::kernel::hash_hex(run_stc(map, start, Variant::Full).hash) == "53591074493a58c0");
}

TEST_CASE("marker noise is reproducible: the same seed gives the same run - noise 0 the exact tour",
          "[stc][noise]") {
  const OccupancyGrid map = from_rows({
      "........",
      "........",
      "..##....",
      "..##....",
      "........",
      "........",
  });
  const RunResult exact = run_stc(map, {0, 0}, Variant::Offline);
  for (Variant v : {Variant::Ant, Variant::AntEdge}) {
    INFO(variant_name(v));
    RunOptions quiet;
    quiet.noise = {0, 7, 0};
    CHECK(run_stc(map, {0, 0}, v, quiet).path == exact.path);
    RunOptions noisy;
    noisy.noise = {200'000, 7, 0}; // one reading in five misread
    const RunResult a = run_stc(map, {0, 0}, v, noisy);
    const RunResult b = run_stc(map, {0, 0}, v, noisy);
    CHECK(a.path == b.path);
    CHECK(a.hash == b.hash);
    CHECK(a.covered <= a.reachable_subcells);
    CHECK(a.covered + a.repeats == a.positions); // the start is covered, not a repeat
    // Across trials the noise differs, and at this rate it does change some tour.
    bool any_differs = false;
    for (std::uint64_t trial = 1; trial <= 8; ++trial) {
      noisy.noise.trial = trial;
      any_differs = any_differs || run_stc(map, {0, 0}, v, noisy).path != exact.path;
    }
    CHECK(any_differs);
  }
}
