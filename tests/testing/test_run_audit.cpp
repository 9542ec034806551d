// antkit::testing's run oracles (run_audit.hpp): antkit's own exploration and coverage runs pass
// them on generated maps, damage is caught and counted, and the readers read what they say and
// refuse the rest with a located error.
#include <antkit/kernel/input_error.hpp>
#include <antkit/los/explore.hpp>
#include <antkit/testing/generators.hpp>
#include <antkit/testing/run_audit.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/world.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
#include <stdexcept>
#include <string>

namespace {

using namespace antkit;
using kernel::Cell;
using kernel::Occupancy;
namespace gen = antkit::testing::gen;

// A coverage run on `map` recorded as a trace, and its own result.
std::pair<testing::CoverTrace, uniform::CoverageResult>
traced_run(const kernel::OccupancyGrid& map, uniform::Algorithm algo, std::size_t robots,
           std::int32_t sensor, std::uint64_t seed) {
  const auto poses = uniform::place_robots(map, robots, std::nullopt, seed, 0);
  uniform::CoverageWorld world(map, poses, sensor);
  testing::CoverTrace t;
  t.robots = static_cast<std::int32_t>(robots);
  const uniform::TickObserver observer = [&t](const uniform::CoverageWorld& w, std::uint64_t) {
    t.cells.emplace_back();
    t.bearings.emplace_back();
    for (std::size_t i = 0; i < w.robot_count(); ++i) {
      t.cells.back().push_back(w.robot(i).cell);
      t.bearings.back().push_back(w.robot(i).bearing);
    }
  };
  const auto r = uniform::run_coverage(world, algo, seed, 0, 300, observer);
  return {std::move(t), r};
}

std::string refusal(const std::string& text) {
  try {
    (void)testing::read_cover_trace(text, "T");
  } catch (const kernel::InputError& e) {
    return e.what();
  }
  return "accepted";
}

std::string cells_refusal(const std::string& text) {
  try {
    (void)testing::read_los_cells(text, "C");
  } catch (const kernel::InputError& e) {
    return e.what();
  }
  return "accepted";
}

} // namespace

TEST_CASE("cover audit: every algorithm's run is legal and covers what it reports",
          "[testing][property]") {
  rc::prop("runs on random grids, mazes, rooms and combs", [] {
    const auto map =
        *gen::any_grid_map({.min_width = 2, .max_width = 16, .min_height = 2, .max_height = 16});
    std::int64_t free = 0;
    for (const auto o : map.cells()) free += o == Occupancy::Free;
    RC_PRE(free >= 3);
    const auto algo =
        *rc::gen::element(uniform::Algorithm::RandomWanderer, uniform::Algorithm::PrimaryMovement,
                          uniform::Algorithm::AStar, uniform::Algorithm::CoordinatedAStar,
                          uniform::Algorithm::Frontier);
    const auto sensor = *rc::gen::inRange(1, 5);
    std::pair<testing::CoverTrace, uniform::CoverageResult> run;
    try {
      run = traced_run(map, algo, 2, sensor, *rc::gen::inRange<std::uint64_t>(1, 1000));
    } catch (const kernel::InputError&) {
      RC_DISCARD("the largest free component holds fewer than two cells");
    }
    const auto& [trace, r] = run;
    const auto a = testing::audit_cover_trace(map, trace, sensor);
    RC_ASSERT(a.first == "");
    RC_ASSERT(a.viewed == r.viewed && a.viewable == r.viewable);
    RC_ASSERT(a.ticks == static_cast<std::int64_t>(r.movements) + 1);
    RC_ASSERT(a.moves + a.turns <= static_cast<std::int64_t>(r.moves));
  });
}

TEST_CASE("cover audit: a teleport, a cut corner, a collision and a false claim are caught",
          "[testing]") {
  const kernel::OccupancyGrid map(6, 6, Occupancy::Free);
  testing::CoverTrace t;
  t.robots = 2;
  t.cells = {{{0, 0}, {5, 5}}, {{1, 0}, {5, 4}}, {{1, 1}, {5, 3}}};
  t.bearings = {{0, 2}, {0, 2}, {6, 2}};
  CHECK(testing::audit_cover_trace(map, t, 1).ok());
  auto teleport = t;
  teleport.cells[2][1] = {2, 2};
  const auto a = testing::audit_cover_trace(map, teleport, 1);
  CHECK(a.illegal_moves == 1);
  CHECK(a.first == "tick 2, robot 1 at (2, 2): moved from (5, 4), not one of its eight neighbours");
  auto collide = t;
  collide.cells[2][1] = {1, 1};
  collide.cells[1][1] = {2, 1};
  collide.bearings[2][1] = 4;
  collide.bearings[1][1] = 3;
  // (5, 5) -> (2, 1) is a teleport too; the collision at tick 2 is counted as well.
  const auto c = testing::audit_cover_trace(map, collide, 1);
  CHECK(c.collisions == 1);
  auto blocked = map;
  blocked[{1, 0}] = Occupancy::Blocked; // robot 0 now stands on a wall, then cuts its corner
  const auto b = testing::audit_cover_trace(blocked, t, 1);
  CHECK(b.first == "tick 1, robot 0 at (1, 0): not on a free cell of the map");
  CHECK(b.illegal_moves == 1);
  auto claims = t;
  claims.claim_viewed = 999;
  const auto f = testing::audit_cover_trace(map, claims, 1);
  CHECK(!f.claims_match);
  CHECK(f.first.rfind("the run claims 999 viewed free cells; its poses view ", 0) == 0);
  auto turn = t;
  turn.bearings[1][0] = 4; // moved east but faces west
  CHECK(testing::audit_cover_trace(map, turn, 1).bad_turns == 1);
}

TEST_CASE("read_cover_trace: the trace antkit cover writes, and refusals with the place",
          "[testing]") {
  const auto t = testing::read_cover_trace("# antkit cover trace\n# sensor: 3\n"
                                           "tick,robot,x,y,bearing\r\n0,0,1,2,3\n0,1,4,5,6\n\n"
                                           "1, 0, 1, 3, 6\n1,1,4,5,5\n# claim viewed: 7\n"
                                           "# claim viewable: 12\n",
                                           "T");
  CHECK(t.robots == 2);
  REQUIRE(t.cells.size() == 2u);
  CHECK(t.cells[1][0] == Cell{1, 3});
  CHECK(t.bearings[1][1] == 5);
  CHECK(t.sensor == 3);
  CHECK(t.claim_viewed == 7u);
  CHECK(t.claim_viewable == 12u);
  CHECK(testing::read_cover_trace("0,0,0,0,0\n", "T").robots == 1);
  CHECK(refusal("") == "T: no poses: expected tick,robot,x,y,bearing lines");
  CHECK(refusal("1,0,0,0,0\n") == "T:1:1: the trace must begin with tick 0");
  CHECK(refusal("0,0,0,0,0\n0,2,0,0,0\n") ==
        "T:2:1: expected tick 0, robot 1 (ticks count up from 0, each listing its robots in "
        "order), not tick 0, robot 2");
  CHECK(refusal("0,0,0,0,0\n0,1,0,0,0\n1,0,0,0,0\n2,0,0,0,0\n") ==
        "T:4:1: expected tick 1, robot 1 (ticks count up from 0, each listing its robots in "
        "order), not tick 2, robot 0");
  CHECK(refusal("0,0,0,0,0\n0,1,0,0,0\n1,0,0,0,0\n") == "T: the last tick lists 1 of 2 robots");
  CHECK(refusal("0,0,0,0,8\n") == "T:1:9: a bearing 8 is outside [0, 7]");
  CHECK(refusal("0,0,0,x,1\n") == "T:1:7: expected y");
  CHECK(refusal("0,0,0;0,1\n") == "T:1:6: expected ',' (tick,robot,x,y,bearing)");
  CHECK(refusal("0,0,0,0,1,9\n") == "T:1:10: unexpected text after the bearing");
  CHECK(refusal("# sensor: 256\n") == "T:1:11: the sensor range 256 is outside [0, 255]");
  CHECK(refusal("0,0,99999999999,0,1\n") == "T:1:5: x 99999999999 is outside [-2147483648, "
                                            "2147483647]");
}

TEST_CASE("LOS audit: both algorithms' states are sound, and a wrong cell is caught and counted",
          "[testing][property]") {
  rc::prop("explore on generated maps", [] {
    const auto map =
        *gen::any_grid_map({.min_width = 2, .max_width = 14, .min_height = 2, .max_height = 14});
    std::array<Cell, 2> start{};
    try {
      start = los::start_pair(map, los::default_start(map));
    } catch (const std::invalid_argument&) {
      RC_DISCARD("no two neighbouring free cells");
    }
    los::ExploreOptions options;
    options.algorithm = *rc::gen::element(los::Algorithm::FastWallFollow, los::Algorithm::Frontier);
    const auto r = los::explore(map, start[0], start[1], options);
    const auto a = testing::audit_los_cells(map, r.cells);
    RC_ASSERT(a.first == "");
    RC_ASSERT(a.known_free <= a.free_cells);
    // A blocked cell marked S, or a free cell marked O: caught, and counted once.
    auto wrong = r.cells;
    for (std::size_t i = 0; i < wrong.size(); ++i) {
      const bool free = map.cells()[i] == Occupancy::Free;
      wrong.cells()[i] = free ? los::CellState::O : los::CellState::S;
      const auto w = testing::audit_los_cells(map, wrong);
      RC_ASSERT(!w.ok());
      RC_ASSERT(w.known_free_not_free + w.obstacle_but_free == 1);
      wrong.cells()[i] = r.cells.cells()[i];
    }
  });
}

TEST_CASE("read_los_cells: explore's JSON, a JSON array, text rows - and refusals with the place",
          "[testing]") {
  const auto a =
      testing::read_los_cells("{\"algo\": \"frontier\", \"cells\": [\"FSL\", \"BNO\"]}", "C");
  const auto b = testing::read_los_cells("[\"FSL\", \"BNO\"]", "C");
  const auto c = testing::read_los_cells("\nFSL\r\nBNO\n\n", "C");
  CHECK(a.cells() == b.cells());
  CHECK(a.cells() == c.cells());
  CHECK(a[{2, 0}] == los::CellState::LOS);
  CHECK(a[{0, 1}] == los::CellState::S_LOS);
  CHECK(cells_refusal("") == "C: empty: no cell states");
  CHECK(cells_refusal("FS\nF\n") == "C:2:1: row 1 has 1 cells, the first row 2");
  CHECK(cells_refusal("FS\nFQ\n") == "C:2:2: 'Q' is not a cell state (F S L B N O)");
  CHECK(cells_refusal("{\"cells\": [\"FS\", 3]}") == "C: cells[1]: expected a row string");
  CHECK(cells_refusal("[\"FS\", \"Fx\"]") ==
        "C: cells[1]: column 2: 'x' is not a cell state (F S L B N O)");
  CHECK(cells_refusal("{\"algo\": 1}") ==
        "C: no \"cells\": expected an array of rows or an object with \"cells\", as antkit "
        "explore prints it");
  CHECK(cells_refusal("{\"cells\": [\"F\"], \"n\": 4E427}") ==
        "C: JSON: number overflow parsing '4E427'");
  CHECK(cells_refusal("[\"FS\",\n \"F") ==
        "C:2:4: JSON: syntax error while parsing value - invalid string: missing closing quote; "
        "last read: '\"F'");
}
