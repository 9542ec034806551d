// The cost of precision (issue 17; precision_cost.hpp): the power-law fit on exact data, and the
// table's bookkeeping on small arenas (every method reaches a loose P, the quartiles are ordered,
// a budget too small leaves the point unreached, threads do not change the result).
#include <antkit/buffon/precision_cost.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

namespace buffon = antkit::buffon;

TEST_CASE("fit_power_law recovers an exact power law and refuses a single area") {
  const std::vector<double> x{314, 1257, 5027, 11310, 31416};
  std::vector<double> y;
  for (const double a : x) y.push_back(3.5 * std::pow(a, 0.5));
  const auto f = buffon::fit_power_law(x, y);
  CHECK(f.points == 5);
  CHECK(f.exponent == Approx(0.5).epsilon(1e-12));
  CHECK(f.coefficient == Approx(3.5).epsilon(1e-9));
  // Non-positive values are left out; one distinct area gives no exponent.
  const std::vector<double> x2{100, 100, -1}, y2{5, 7, 3};
  const auto g = buffon::fit_power_law(x2, y2);
  CHECK(g.points == 2);
  CHECK(g.coefficient == 0);
}

TEST_CASE("precision_cost: two small circles, every method reaches P = 0.2") {
  const auto a20 = antkit::geometry::build_arena_spec("circle:d=20").arena;
  const auto a40 = antkit::geometry::build_arena_spec("circle:d=40").arena;
  const buffon::World w20(a20.walls_fx()), w40(a40.walls_fx());
  const std::vector<buffon::CostArena> arenas{{"circle:d=20", "circle", a20.area(), &w20, true},
                                              {"circle:d=40", "circle", a40.area(), &w40, true}};
  buffon::CostParams params;
  params.precisions = {200000};
  params.trials = 3;
  std::size_t calls = 0;
  antkit::algorithms::Runner runner;
  runner.progress = [&](std::string_view stage, std::uint64_t done, std::uint64_t n) {
    ++calls;
    CHECK(stage == "trials");
    CHECK(done == calls);
    CHECK(n == 18); // every trial of every point is a unit
  };
  const auto table = buffon::precision_cost(arenas, params, runner);
  CHECK(calls == 18);
  REQUIRE(table.points.size() == 6); // 2 arenas x 1 precision x 3 methods
  for (const auto& p : table.points) {
    INFO(p.arena << " " << buffon::cost_method_name(p.method));
    CHECK(p.reached == 3);
    REQUIRE(p.median);
    CHECK(*p.q1 <= *p.median);
    CHECK(*p.median <= *p.q3);
    CHECK(*p.median > 0);
  }
  // The bigger arena costs more trail for every method.
  for (std::size_t m = 0; m < 3; ++m) CHECK(*table.points[3 + m].median > *table.points[m].median);
  REQUIRE(table.fits.size() == 3);
  for (const auto& f : table.fits) CHECK(f.points == 2);
  // Threads change nothing.
  antkit::algorithms::Runner two;
  two.threads = 2;
  const auto again = buffon::precision_cost(arenas, params, two);
  for (std::size_t i = 0; i < table.points.size(); ++i)
    CHECK(*again.points[i].median == *table.points[i].median);
  // A budget too small: no method reaches P, every median is absent and no fit is made.
  params.budget = 5000;
  const auto starved = buffon::precision_cost(arenas, params);
  for (const auto& p : starved.points) {
    CHECK(p.reached == 0);
    CHECK_FALSE(p.median);
  }
  CHECK(starved.fits.empty());
  // Bad parameters are located errors.
  params.budget = 40000000;
  params.precisions = {0};
  CHECK_THROWS_AS(buffon::precision_cost(arenas, params), antkit::kernel::InputError);
  params.precisions = {200000};
  params.trials = 0;
  CHECK_THROWS_AS(buffon::precision_cost(arenas, params), antkit::kernel::InputError);
  CHECK_THROWS_AS(buffon::precision_cost({}, buffon::CostParams{}), antkit::kernel::InputError);
}
