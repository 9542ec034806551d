// The simulated world: the sensor footprint, line of sight, viewing and movement rules.
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/raster.hpp>
#include <antkit/testing/uniform.hpp>
#include <antkit/uniform/world.hpp>
#include <catch2/catch.hpp>
#include <climits>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

using namespace antkit;
using namespace antkit::uniform;
using kernel::Cell;
using kernel::Occupancy;

TEST_CASE("the footprint holds exactly the offsets within distance r, with the kernel's "
          "supercover between",
          "[uniform][proof]") {
  for (std::int32_t r = 0; r <= 12; ++r) {
    const SensorFootprint fp(r);
    std::size_t expected = 0;
    for (std::int32_t dy = -r; dy <= r; ++dy)
      for (std::int32_t dx = -r; dx <= r; ++dx) expected += dx * dx + dy * dy <= r * r;
    REQUIRE(fp.rays().size() == expected);
    REQUIRE(fp.rays().front().offset == Cell{0, 0});
    std::int32_t last = -1;
    for (const auto& ray : fp.rays()) {
      const Cell d = ray.offset;
      REQUIRE(fp.in_range(d));
      REQUIRE(&fp.ray(d) == &ray);
      REQUIRE(d.x * d.x + d.y * d.y >= last); // nearest first
      last = d.x * d.x + d.y * d.y;
      auto cover = kernel::supercover({0, 0}, d);
      std::vector<Cell> between(fp.between().begin() + ray.first,
                                fp.between().begin() + ray.first + ray.count);
      if (d != Cell{0, 0})
        cover = std::vector<Cell>(cover.begin() + 1, cover.end() - 1);
      else
        cover.clear();
      REQUIRE(between == cover);
    }
  }
  CHECK_THROWS_AS(SensorFootprint(-1), kernel::InputError);
  CHECK_THROWS_AS(SensorFootprint(kMaxSensorRange + 1), kernel::InputError);
}

TEST_CASE("every 4x4 map: in_view is 'within r and kernel::line_of_sight'", "[uniform][proof]") {
  // All 2^16 maps, every ordered pair of cells, sensor distance 3 (the 4x4 square's diagonal is
  // longer, so the range test is exercised too).
  for (unsigned bits = 0; bits < (1u << 16); ++bits) {
    kernel::OccupancyGrid g(4, 4, Occupancy::Free);
    for (std::size_t k = 0; k < 16; ++k)
      if (bits >> k & 1u) g.cells()[k] = Occupancy::Blocked;
    const CoverageWorld w(g, {}, 3);
    for (std::size_t a = 0; a < 16; ++a)
      for (std::size_t b = 0; b < 16; ++b) {
        const Cell ca = g.cell_at(a), cb = g.cell_at(b);
        const Cell d = cb - ca;
        const bool expected = d.x * d.x + d.y * d.y <= 9 && kernel::line_of_sight(g, ca, cb);
        if (w.in_view(ca, cb) != expected) FAIL("map " << bits << " from " << a << " to " << b);
      }
  }
}

TEST_CASE("every 3x3 map: a step is allowed iff the target is free and no corner is cut",
          "[uniform][proof]") {
  for (unsigned bits = 0; bits < 512; ++bits) {
    kernel::OccupancyGrid g(3, 3, Occupancy::Free);
    for (std::size_t k = 0; k < 9; ++k)
      if (bits >> k & 1u) g.cells()[k] = Occupancy::Blocked;
    if (g[{1, 1}] != Occupancy::Free) continue;
    const CoverageWorld w(g, {{{1, 1}, 0}}, 2);
    for (std::uint8_t b = 0; b < 8; ++b) {
      const Cell d = kernel::kNeighbours8[b];
      bool expected = g[Cell{1, 1} + d] == Occupancy::Free;
      if (d.x != 0 && d.y != 0)
        expected =
            expected && g[{1 + d.x, 1}] == Occupancy::Free && g[{1, 1 + d.y}] == Occupancy::Free;
      REQUIRE(w.passable_step({1, 1}, b) == expected);
      // The same rule as sight: a step is allowed iff the target is free and in view.
      REQUIRE(expected ==
              (g[Cell{1, 1} + d] == Occupancy::Free && w.in_view({1, 1}, Cell{1, 1} + d)));
    }
  }
}

TEST_CASE("the first views are the union of brute-force views, and viewable is the robots' "
          "components",
          "[uniform][property]") {
  rc::prop("initial view", [] {
    const auto w = *rc::gen::inRange(1, 24);
    const auto h = *rc::gen::inRange(1, 24);
    const auto ppm = *rc::gen::inRange<std::uint32_t>(0, 450'000);
    const auto r = *rc::gen::inRange(0, 7);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    auto g = random_obstacles(w, h, ppm, seed, 0);
    if (*rc::gen::inRange(0, 4) == 0) // sometimes Unknown cells, which block like obstacles
      for (auto& c : g.cells())
        if (c == Occupancy::Blocked) c = Occupancy::Unknown;
    const auto comps = free_components(g);
    std::uint64_t largest = 0;
    for (const auto s : comps.size) largest = std::max(largest, s);
    RC_PRE(largest > 0);
    const auto n = *rc::gen::inRange<std::size_t>(
        1, static_cast<std::size_t>(std::min<std::uint64_t>(largest, 4)) + 1);
    const auto poses = place_robots(g, n, std::nullopt, seed, 0);
    const CoverageWorld world(g, poses, r);
    kernel::Grid<std::uint8_t> expected(w, h, 0);
    for (const auto& p : poses) {
      const auto v = testing::brute_force_view(g, p.cell, r);
      for (std::size_t k = 0; k < g.size(); ++k) expected.cells()[k] |= v.cells()[k];
    }
    RC_ASSERT(world.viewed() == expected);
    RC_ASSERT(world.viewable() == largest);
    std::uint64_t free_viewed = 0;
    for (std::size_t k = 0; k < g.size(); ++k)
      free_viewed += expected.cells()[k] && g.cells()[k] == Occupancy::Free;
    RC_ASSERT(world.viewed_free() == free_viewed);
  });
}

TEST_CASE("the world refuses robots off free cells or on one cell", "[uniform]") {
  kernel::OccupancyGrid g(3, 1, Occupancy::Free);
  g[{2, 0}] = Occupancy::Blocked;
  CHECK_THROWS_AS(CoverageWorld(g, {{{2, 0}, 0}}, 1), kernel::InputError);
  CHECK_THROWS_AS(CoverageWorld(g, {{{5, 0}, 0}}, 1), kernel::InputError);
  CHECK_THROWS_AS(CoverageWorld(g, {{{0, 0}, 0}, {{0, 0}, 1}}, 1), kernel::InputError);
  CoverageWorld ok(g, {{{0, 0}, 0}, {{1, 0}, 4}}, 1);
  CHECK_FALSE(ok.move(0, 0)); // occupied
  CHECK_FALSE(ok.move(1, 0)); // blocked
  CHECK(ok.robot(1).bearing == 4);
  CHECK(ok.turn(1, -1));
  CHECK(ok.robot(1).bearing == 3);
  // Cells far off the map are simply not in view (and their difference is never formed).
  CHECK_FALSE(ok.in_view({INT32_MIN, 0}, {INT32_MAX, 0}));
  CHECK_FALSE(ok.in_view({0, 0}, {INT32_MAX, INT32_MIN}));
  CHECK_FALSE(ok.would_view_new({INT32_MAX, 0}));
}
