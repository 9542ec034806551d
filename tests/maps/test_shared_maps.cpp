// Every map in data/maps loads, and gives the counts data/maps/README.md publishes for it
// (width x height, free / blocked / unknown cells, 4-connected components of free cells and the
// largest one). The README's counts were made independently of this reader, so they are the oracle.
#include "run_antkit.hpp"

#include <antkit/maps/components.hpp>
#include <antkit/maps/map_io.hpp>
#include <catch2/catch.hpp>

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::maps::GridMap;
using antkit::test::shared_map;

namespace {

struct Expected {
  std::int32_t width, height;
  std::size_t free, blocked, unknown, components, largest;
};

GridMap check_shared_map(const std::string& relative, const Expected& e) {
  INFO(relative);
  const auto map = antkit::maps::load_map(shared_map(relative));
  CHECK(map.cells.width() == e.width);
  CHECK(map.cells.height() == e.height);
  const auto counts = antkit::maps::count_cells(map.cells);
  CHECK(counts.free == e.free);
  CHECK(counts.blocked == e.blocked);
  CHECK(counts.unknown == e.unknown);
  const auto components = antkit::maps::free_components(map.cells);
  CHECK(components.count() == e.components);
  CHECK(components.largest() == e.largest);
  CHECK_FALSE(map.start.has_value()); // neither format has a start ('S' in MovingAI is swamp)
  return map;
}

std::size_t free_in_row(const GridMap& m, std::int32_t y) {
  std::size_t n = 0;
  for (std::int32_t x = 0; x < m.cells.width(); ++x) n += m.cells[{x, y}] == Occupancy::Free;
  return n;
}
std::size_t free_in_column(const GridMap& m, std::int32_t x) {
  std::size_t n = 0;
  for (std::int32_t y = 0; y < m.cells.height(); ++y) n += m.cells[{x, y}] == Occupancy::Free;
  return n;
}

void check_movingai_metadata(const GridMap& m) {
  CHECK(m.resolution == 1.0);
  CHECK(m.origin_x == 0.0);
  CHECK(m.origin_y == 0.0);
  CHECK(m.origin_yaw == 0.0);
}

} // namespace

// ---- MovingAI (README section 2)
// -----------------------------------------------------------------

TEST_CASE("shared map movingai/empty-32-32.map", "[maps][shared]") {
  check_movingai_metadata(
      check_shared_map("movingai/empty-32-32.map", {32, 32, 1024, 0, 0, 1, 1024}));
}
TEST_CASE("shared map movingai/random-32-32-10.map", "[maps][shared]") {
  check_shared_map("movingai/random-32-32-10.map", {32, 32, 922, 102, 0, 1, 922});
}
TEST_CASE("shared map movingai/random-32-32-20.map", "[maps][shared]") {
  const auto m = check_shared_map("movingai/random-32-32-20.map", {32, 32, 819, 205, 0, 1, 819});
  // Its one `T` (row 17, column 30) is blocked like the `@` cells.
  CHECK(m.cells[Cell{30, 17}] == Occupancy::Blocked);
}
TEST_CASE("shared map movingai/room-32-32-4.map", "[maps][shared]") {
  check_shared_map("movingai/room-32-32-4.map", {32, 32, 682, 342, 0, 1, 682});
}
TEST_CASE("shared map movingai/maze-32-32-2.map", "[maps][shared]") {
  check_shared_map("movingai/maze-32-32-2.map", {32, 32, 666, 358, 0, 1, 666});
}
TEST_CASE("shared map movingai/room-64-64-8.map", "[maps][shared]") {
  check_shared_map("movingai/room-64-64-8.map", {64, 64, 3232, 864, 0, 1, 3232});
}
TEST_CASE("shared map movingai/den312d.map", "[maps][shared]") {
  check_shared_map("movingai/den312d.map", {65, 81, 2445, 255 + 2565, 0, 1, 2445});
}
TEST_CASE("shared map movingai/warehouse-10-20-10-2-1.map", "[maps][shared]") {
  const auto m =
      check_shared_map("movingai/warehouse-10-20-10-2-1.map", {161, 63, 5699, 4444, 0, 1, 5699});
  // "1-cell wall border": closed at the edge.
  CHECK(free_in_row(m, 0) == 0);
  CHECK(free_in_row(m, 62) == 0);
  CHECK(free_in_column(m, 0) == 0);
  CHECK(free_in_column(m, 160) == 0);
}
TEST_CASE("shared map movingai/ht_chantry.map", "[maps][shared]") {
  check_shared_map("movingai/ht_chantry.map", {162, 141, 7461, 13750 + 1631, 0, 1, 7461});
}
TEST_CASE("shared map movingai/lak303d.map", "[maps][shared]") {
  check_shared_map("movingai/lak303d.map", {194, 194, 14784, 14165 + 8687, 0, 1, 14784});
}
TEST_CASE("shared map movingai/Berlin_1_256.map", "[maps][shared]") {
  check_shared_map("movingai/Berlin_1_256.map", {256, 256, 47540, 17996, 0, 10, 46880});
}
TEST_CASE("shared map movingai/Boston_0_256.map", "[maps][shared]") {
  check_shared_map("movingai/Boston_0_256.map", {256, 256, 47768, 17768, 0, 28, 47651});
}
TEST_CASE("shared map movingai/brc202d.map", "[maps][shared]") {
  check_shared_map("movingai/brc202d.map", {530, 481, 43151, 193896 + 17883, 0, 1, 43151});
}

// ---- ROS map_server (README section 3), each under its own yaml's thresholds --------------------

TEST_CASE("shared map ros/willow-2010-02-18-0.10.yaml", "[maps][shared]") {
  const auto m = check_shared_map("ros/willow-2010-02-18-0.10.yaml",
                                  {566, 608, 109207, 544, 234377, 187, 108671});
  CHECK(m.resolution == 0.1);
  CHECK(m.origin_x == 0.0);
  CHECK(m.origin_y == 0.0);
  CHECK(m.origin_yaw == 0.0);
  // "34 free cells lie on the image border (28 on the bottom edge, 6 on the left)": this pins the
  // orientation, row 0 is the top of the image.
  CHECK(free_in_row(m, 607) == 28);
  CHECK(free_in_column(m, 0) == 6);
  CHECK(free_in_row(m, 0) == 0);
  CHECK(free_in_column(m, 565) == 0);
}
TEST_CASE("shared map ros/lab.yaml (free_thresh 0.25: 205 reads free)", "[maps][shared]") {
  const auto m = check_shared_map("ros/lab.yaml", {210, 200, 40037, 1963, 0, 13, 39206});
  CHECK(m.resolution == 0.05);
  CHECK(m.origin_x == -7.09);
  CHECK(m.origin_y == -4.64);
  CHECK(m.origin_yaw == 0.0);
  // "675 free cells lie on the image border". That figure is the sum over the four edges, the
  // four (free) corners counted twice; 671 distinct cells.
  const std::size_t edges =
      free_in_row(m, 0) + free_in_row(m, 199) + free_in_column(m, 0) + free_in_column(m, 209);
  CHECK(edges == 675);
  for (const Cell corner : {Cell{0, 0}, Cell{209, 0}, Cell{0, 199}, Cell{209, 199}})
    CHECK(m.cells[corner] == Occupancy::Free);
}
TEST_CASE("shared map ros/map_office_raw.yaml", "[maps][shared]") {
  const auto m =
      check_shared_map("ros/map_office_raw.yaml", {384, 384, 57377, 4596, 85483, 132, 56937});
  CHECK(m.resolution == 0.05);
  CHECK(m.origin_x == -10.0);
  CHECK(m.origin_y == -10.0);
  CHECK(free_in_row(m, 0) + free_in_row(m, 383) + free_in_column(m, 0) + free_in_column(m, 383) ==
        0);
}
TEST_CASE("shared map ros/turtlebot3_world.yaml", "[maps][shared]") {
  const auto m =
      check_shared_map("ros/turtlebot3_world.yaml", {384, 384, 7903, 870, 138683, 6, 7895});
  CHECK(m.resolution == 0.05);
  CHECK(m.origin_x == -10.0);
  CHECK(m.origin_y == -10.0);
}

TEST_CASE("a shared map survives MovingAI -> ASCII -> MovingAI unchanged", "[maps][shared]") {
  for (const char* name : {"movingai/Berlin_1_256.map", "movingai/den312d.map"}) {
    INFO(name);
    const auto m = antkit::maps::load_map(shared_map(name));
    const auto ascii = antkit::maps::parse_ascii(antkit::maps::write_ascii(m), "ascii");
    CHECK(ascii.cells == m.cells);
    const auto back = antkit::maps::parse_movingai(antkit::maps::write_movingai(ascii), "back");
    CHECK(back.cells == m.cells);
  }
}
