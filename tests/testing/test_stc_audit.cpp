// antkit::testing's tour oracle (stc_audit.hpp): antkit's own tours pass it, every kind of damage
// to a tour is caught and counted exactly, and the tour reader reads what it says and refuses the
// rest with a located error.
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/generators.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <catch2/catch.hpp>
#include <limits>
#include <rapidcheck/catch.h>
#include <string>
#include <vector>

namespace {

using namespace antkit;
using kernel::Cell;
using testing::TourRule;
namespace gen = antkit::testing::gen;

std::vector<Cell> offline_tour(const kernel::OccupancyGrid& map, Cell start) {
  return stc::run_stc(map, start, stc::Variant::Offline).path;
}

std::string where_of(const std::string& text) {
  try {
    (void)testing::read_tour(text, "T");
  } catch (const kernel::InputError& e) {
    return e.what();
  }
  return "accepted";
}

} // namespace

TEST_CASE("audit: antkit's exact tours keep every rule, in both forms, counted clean",
          "[testing][property]") {
  rc::prop("offline tours on random maps", [] {
    const auto c = *gen::stc_case({.partial_cells = true});
    auto path = offline_tour(c.map, c.start);
    const auto a = testing::audit_stc_tour(c.map, c.start, path, TourRule::ExactlyOnce);
    RC_ASSERT(a.first.describe() == "ok");
    RC_ASSERT(a.covered == a.reachable && a.missed == 0 && a.repeats == 0);
    RC_ASSERT(a.illegal_moves == 0 && a.off_limits == 0 && a.end_distance == 1);
    RC_ASSERT(a.positions == static_cast<std::int64_t>(path.size()) && !a.closed_form);
    path.push_back(c.start); // the closed form lists the start again
    const auto closed = testing::audit_stc_tour(c.map, c.start, path, TourRule::ExactlyOnce);
    RC_ASSERT(closed.ok() && closed.closed_form && closed.repeats == 0);
  });
}

TEST_CASE("audit: without partly blocked cells an exact tour is also a coverage tour",
          "[testing][property]") {
  rc::prop("coverage rule", [] {
    const auto c = *gen::stc_case({.partial_cells = false, .odd_sizes = false});
    const auto path = offline_tour(c.map, c.start);
    const auto a = testing::audit_stc_tour(c.map, c.start, path, TourRule::Coverage);
    RC_ASSERT(a.first.describe() == "ok");
    RC_ASSERT(a.reachable == static_cast<std::int64_t>(path.size()));
  });
}

TEST_CASE("audit: a dropped, doubled or displaced position is caught and counted exactly",
          "[testing][property]") {
  rc::prop("one damage per tour", [] {
    const auto c = *gen::stc_case({.partial_cells = true});
    const auto tour = offline_tour(c.map, c.start);
    RC_PRE(tour.size() >= 8);
    const auto k = *rc::gen::inRange<std::size_t>(1, tour.size());
    const int kind = *rc::gen::inRange(0, 3);
    auto path = tour;
    if (kind == 0) { // dropped: one sub-cell missed; inside the tour, one jump of two
      path.erase(path.begin() + static_cast<std::ptrdiff_t>(k));
      const auto a = testing::audit_stc_tour(c.map, c.start, path, TourRule::ExactlyOnce);
      RC_ASSERT(!a.ok());
      RC_ASSERT(a.missed == 1 && a.repeats == 0 && a.off_limits == 0);
      RC_ASSERT(a.missed_sample.size() == 1u && a.missed_sample[0] == tour[k]);
      RC_ASSERT(a.illegal_moves == (k + 1 < tour.size() ? 1 : 0));
    } else if (kind == 1) { // doubled: one repeat, one move of length zero
      path.insert(path.begin() + static_cast<std::ptrdiff_t>(k), tour[k]);
      const auto a = testing::audit_stc_tour(c.map, c.start, path, TourRule::ExactlyOnce);
      RC_ASSERT(!a.ok());
      RC_ASSERT(a.repeats == 1 && a.missed == 0 && a.illegal_moves == 1);
      RC_ASSERT(a.first.step == static_cast<std::int64_t>(k) + 1);
    } else { // displaced far off the map: off limits, and the moves into and out of it illegal
      path[k] = {std::numeric_limits<std::int32_t>::min(),
                 std::numeric_limits<std::int32_t>::max()};
      const auto a = testing::audit_stc_tour(c.map, c.start, path, TourRule::ExactlyOnce);
      RC_ASSERT(!a.ok() && a.first.step == static_cast<std::int64_t>(k));
      RC_ASSERT(a.off_limits == 1 && a.missed == 1);
      RC_ASSERT(a.illegal_moves == (k + 1 < tour.size() ? 2 : 1));
    }
  });
}

TEST_CASE("audit: the end of the tour, its distance from the start, and the rule that breaks",
          "[testing]") {
  kernel::OccupancyGrid map(4, 2, kernel::Occupancy::Free); // two cells side by side
  const std::vector<Cell> good{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {2, 1}, {1, 1}, {0, 1}};
  CHECK(testing::audit_stc_tour(map, {0, 0}, good, TourRule::ExactlyOnce).ok());
  // Cut short of the start: the last position three moves away, two sub-cells missed.
  const std::vector<Cell> cut(good.begin(), good.end() - 2);
  const auto a = testing::audit_stc_tour(map, {0, 0}, cut, TourRule::ExactlyOnce);
  CHECK(a.first.rule == "4 length");
  CHECK(a.missed == 2);
  CHECK(a.end_distance == 3);
  // A boustrophedon that covers but ends far away: coverage rule 3.
  const std::vector<Cell> sweep{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {2, 1},
                                {1, 1}, {0, 1}, {1, 1}, {2, 1}, {3, 1}};
  const auto s = testing::audit_stc_tour(map, {0, 0}, sweep, TourRule::Coverage);
  CHECK(s.first.rule == "3 return");
  CHECK(s.repeats == 3);
  CHECK(s.end_distance == 4);
  // A start in a blocked sub-cell: nothing is reachable, and the tour is off limits.
  map[{0, 0}] = kernel::Occupancy::Blocked;
  const auto b = testing::audit_stc_tour(map, {0, 0}, good, TourRule::Coverage);
  CHECK(!b.ok());
  CHECK(b.reachable == 0);
  CHECK(b.off_limits == 8);
}

TEST_CASE("read_tour: JSON arrays, antkit stc's object, CSV - the same positions", "[testing]") {
  const std::vector<Cell> want{{0, 0}, {1, 0}, {-3, 2147483647}, {-2147483647 - 1, 5}};
  const auto a = testing::read_tour("[[0,0],[1, 0] , [-3,2147483647],[-2147483648,5]]", "T");
  CHECK(a.path == want);
  CHECK(!a.start);
  const auto b = testing::read_tour(
      " {\"variant\": \"offline\", \"start\": [1, 0], \"path\": [[0,0],[1,0],[-3,2147483647],"
      "[-2147483648,5]], \"extra\": {\"path\": [[9, 9]], \"k\": [1.5, null]}}",
      "T");
  CHECK(b.path == want);
  REQUIRE(b.start);
  CHECK(*b.start == Cell{1, 0});
  const auto c =
      testing::read_tour("x , y\r\n0,0\r\n\r\n 1 ,\t0\n-3,2147483647\n-2147483648,5", "T");
  CHECK(c.path == want);
  CHECK(testing::read_tour("[]", "T").path.empty());
}

TEST_CASE("read_tour: row,col pairs by header or by order come back as x,y", "[testing]") {
  const std::vector<Cell> want{{0, 0}, {1, 0}, {1, 2}};
  // A header decides for its file, whatever the order asked.
  for (const auto order : {testing::TourOrder::XY, testing::TourOrder::RowCol}) {
    const auto rc = testing::read_tour("row,col\n0,0\n0,1\n2,1\n", "T", order);
    CHECK(rc.path == want);
    CHECK(rc.order == testing::TourOrder::RowCol);
    CHECK(rc.order_from_header);
    CHECK(testing::read_tour(" y , x\r\n0,0\n0,1\n2,1", "T", order).path == want);
    const auto xy = testing::read_tour("x,y\n0,0\n1,0\n1,2\n", "T", order);
    CHECK(xy.path == want);
    CHECK(xy.order == testing::TourOrder::XY);
  }
  // No header: the order asked, in CSV and in JSON (the pairs and the start).
  const auto csv = testing::read_tour("0,0\n0,1\n2,1\n", "T", testing::TourOrder::RowCol);
  CHECK(csv.path == want);
  CHECK_FALSE(csv.order_from_header);
  CHECK(testing::read_tour("0,0\n0,1\n2,1\n", "T").path ==
        std::vector<Cell>{{0, 0}, {0, 1}, {2, 1}});
  const auto json = testing::read_tour("{\"start\": [2, 1], \"path\": [[0,0],[0,1],[2,1]]}", "T",
                                       testing::TourOrder::RowCol);
  CHECK(json.path == want);
  REQUIRE(json.start);
  CHECK(*json.start == Cell{1, 2});
  CHECK(testing::tour_order_name(testing::TourOrder::RowCol) == "rc");
}

TEST_CASE("read_tour: malformed tours are refused with the place", "[testing]") {
  CHECK(where_of("") == "T: empty: no tour");
  CHECK(where_of("[[0,0],\n[1,0,]") == "T:2:6: JSON: syntax error while parsing value - "
                                       "unexpected ']'; expected '[', '{', or a literal");
  CHECK(where_of("[[0,0],[1,0,2]]") == "T: path[1]: expected [x, y], two whole numbers; this "
                                       "array has 3");
  CHECK(where_of("[[0,0],[1]]") == "T: path[1]: expected [x, y], two whole numbers; this array "
                                   "has 1");
  CHECK(where_of("[[0,0.5]]") == "T: path[0]: expected a whole number, not a number that is "
                                 "not whole");
  CHECK(where_of("[[0,\"1\"]]") == "T: path[0]: expected a whole number, not a string");
  CHECK(where_of("[[0,[1]]]") == "T: path[0]: expected a whole number, not an array");
  CHECK(where_of("[7]") == "T: path[0]: expected [x, y], not a number");
  CHECK(where_of("[[0,2147483648]]") == "T: path[0]: 2147483648 is outside [-2^31, 2^31)");
  CHECK(where_of("{\"start\": [0, 0]}") ==
        "T: no \"path\": expected [[x, y], ...] or an object with \"path\", as antkit stc prints "
        "it");
  CHECK(where_of("{\"path\": 3}") == "T: path: expected [[x, y], ...], not a number");
  CHECK(where_of("{\"path\": [], \"path\": []}") == "T: \"path\" appears twice");
  CHECK(where_of("{\"path\": [], \"start\": [1, 2, 3]}") ==
        "T: start: expected [x, y], two whole numbers; this array has 3");
  CHECK(where_of("[[0,0]] x") ==
        "T:1:9: JSON: syntax error while parsing value - invalid literal; last read: '0]] x'; "
        "expected end of input");
  CHECK(where_of("{\"path\": [[0, 0]], \"n\": 4E427}") ==
        "T:1:29: JSON: number overflow parsing '4E427'");
  CHECK(where_of("0,0\n1,zero") == "T:2:3: expected y after the comma");
  CHECK(where_of("0;0") == "T:1:2: expected ','");
  CHECK(where_of("0,0,0") == "T:1:4: unexpected text after x,y");
  CHECK(where_of("x,y\nx,y") == "T:2:1: expected x,y (two whole numbers)");
  CHECK(where_of("0,99999999999") == "T:1:3: a coordinate outside [-2^31, 2^31)");
  CHECK(where_of("0,2147483648") == "T:1:3: a coordinate outside [-2^31, 2^31)");
  CHECK(where_of("-2147483648,-2147483648") == "accepted");
}
