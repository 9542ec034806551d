// antkit::testing's Buffon trial check (buffon.hpp): real trials on generated arenas pass it, and
// a result with a wrong count, a point outside or a visit beyond its budget is caught by its rule.
#include <antkit/buffon/measurement.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/testing/buffon.hpp>
#include <antkit/testing/generators.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

namespace {

using namespace antkit;

buffon::TrialParams params(std::int64_t steps, std::uint64_t seed) {
  buffon::TrialParams p;
  p.seed = seed;
  p.steps = steps;
  p.keep_trails = true;
  return p;
}

} // namespace

TEST_CASE("buffon check: trials on generated arenas with holes pass", "[testing][property]") {
  rc::prop("check_buffon_trial", [] {
    const auto c = *testing::gen::arena_with_holes();
    const auto steps = *rc::gen::inRange<std::int64_t>(10, 600);
    const buffon::World world(c.arena.walls_fx());
    buffon::TrialResult r;
    try {
      r = buffon::run_trial(world, params(steps, *rc::gen::inRange<std::uint64_t>(1, 99)), 0);
    } catch (const kernel::InputError&) {
      RC_DISCARD("the paper's start is not clear in this arena");
    }
    RC_ASSERT(testing::check_buffon_trial(world, r, {steps, steps, 0}).describe() == "ok");
  });
}

TEST_CASE("buffon check: a wrong count, a point outside, a visit too long", "[testing]") {
  const auto arena = geometry::read_wkt("POLYGON ((0 0, 20 0, 20 20, 0 20, 0 0))");
  const buffon::World world(arena.walls_fx());
  auto r = buffon::run_trial(world, params(3000, 4), 0);
  REQUIRE(testing::check_buffon_trial(world, r, {3000, 3000, 0}).ok);
  REQUIRE(r.crossings_exact > 0);
  auto wrong = r;
  ++wrong.crossings_exact;
  CHECK(testing::check_buffon_trial(world, wrong, {3000, 3000, 0}).describe() ==
        "rule 1 crossings: crossings_exact is " + std::to_string(r.crossings_exact + 1) +
            ", the loop over every pair of segments counts " + std::to_string(r.crossings_exact));
  auto outside = r;
  outside.trail1.push_back({kernel::Fx::from_int(25), kernel::Fx::from_int(5)});
  outside.crossings_exact = 0; // recounted below so that rule 1 holds
  for (std::size_t i = 1; i < outside.trail1.size(); ++i)
    for (std::size_t j = 1; j < outside.trail2.size(); ++j)
      outside.crossings_exact += kernel::properly_cross({outside.trail1[i - 1], outside.trail1[i]},
                                                        {outside.trail2[j - 1], outside.trail2[j]});
  const auto o = testing::check_buffon_trial(world, outside, {3000, 3000, 0});
  CHECK(o.rule == "2 body");
  CHECK(o.visit == 1);
  CHECK(o.point == static_cast<std::int64_t>(outside.trail1.size()) - 1);
  CHECK(testing::check_buffon_trial(world, r, {2999, 3000, 0}).rule == "3 budget");
  CHECK(testing::check_buffon_trial(world, r, {0, 0, r.steps1 + r.steps2}).ok);
  CHECK(!testing::check_buffon_trial(world, r, {0, 0, r.steps1 + r.steps2 - 1}).ok);
  // inside_walls on the square with a hole: the even-odd rule.
  const auto holed =
      geometry::read_wkt("POLYGON ((0 0, 20 0, 20 20, 0 20, 0 0), (5 5, 5 10, 10 10, 10 5, 5 5))");
  const auto walls = holed.walls_fx();
  CHECK(testing::inside_walls(walls, {kernel::Fx::from_int(2), kernel::Fx::from_int(2)}));
  CHECK(!testing::inside_walls(walls, {kernel::Fx::from_int(7), kernel::Fx::from_int(7)}));
  CHECK(!testing::inside_walls(walls, {kernel::Fx::from_int(-1), kernel::Fx::from_int(7)}));
  CHECK(testing::inside_walls(walls, {kernel::Fx::from_int(12), kernel::Fx::from_int(7)}));
}
