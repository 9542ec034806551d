// The environment of paper 004: obstacle placement, free components, robot starts.
#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/scenario.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <set>

using namespace antkit;
using namespace antkit::uniform;
using kernel::Cell;
using kernel::Occupancy;

namespace {
std::uint64_t count_blocked(const kernel::OccupancyGrid& g) {
  std::uint64_t n = 0;
  for (const auto c : g.cells()) n += c == Occupancy::Blocked;
  return n;
}
} // namespace

TEST_CASE("obstacle_count rounds p*W*H to the nearest integer, halves up", "[uniform]") {
  CHECK(obstacle_count(100, 100, 300'000) == 3000);
  CHECK(obstacle_count(10, 10, 0) == 0);
  CHECK(obstacle_count(10, 10, kPpm) == 100);
  CHECK(obstacle_count(3, 3, 500'000) == 5);             // 4.5 -> 5
  CHECK(obstacle_count(3, 3, 499'999) == 4);             // 4.499991 -> 4
  CHECK(obstacle_count(7, 1, 100'000) == 1);             // 0.7 -> 1
  CHECK(obstacle_count(1024, 1024, 200'000) == 209'715); // 209715.2
}

TEST_CASE("random_obstacles blocks exactly round(p*W*H) cells, the same ones for the same key",
          "[uniform][property]") {
  rc::prop("count and determinism", [] {
    const auto w = *rc::gen::inRange(1, 40);
    const auto h = *rc::gen::inRange(1, 40);
    const auto ppm = *rc::gen::inRange<std::uint32_t>(0, kPpm + 1);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto trial = *rc::gen::inRange<std::uint64_t>(0, 100);
    const auto g = random_obstacles(w, h, ppm, seed, trial);
    RC_ASSERT(g.width() == w);
    RC_ASSERT(g.height() == h);
    RC_ASSERT(count_blocked(g) == obstacle_count(w, h, ppm));
    RC_ASSERT(g == random_obstacles(w, h, ppm, seed, trial));
  });
}

TEST_CASE("random_obstacles rejects a density above 1", "[uniform]") {
  CHECK_THROWS_AS(random_obstacles(4, 4, kPpm + 1, 1, 0), kernel::InputError);
}

TEST_CASE("every 3x3 map: free components are exactly the 4-connected classes",
          "[uniform][proof]") {
  // Exhaustive over all 512 maps: two free cells share a label iff a 4-connected free path joins
  // them (checked by a transitive closure, an oracle independent of the flood fill), labels
  // number components in row-major order of their first cell, and sizes add up.
  for (unsigned bits = 0; bits < 512; ++bits) {
    kernel::OccupancyGrid g(3, 3, Occupancy::Free);
    for (int k = 0; k < 9; ++k)
      if (bits >> k & 1u) g.cells()[static_cast<std::size_t>(k)] = Occupancy::Blocked;
    bool joined[9][9] = {};
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b < 9; ++b) {
        const Cell ca = g.cell_at(static_cast<std::size_t>(a)),
                   cb = g.cell_at(static_cast<std::size_t>(b));
        const int manhattan = std::abs(ca.x - cb.x) + std::abs(ca.y - cb.y);
        joined[a][b] = g[ca] == Occupancy::Free && g[cb] == Occupancy::Free && manhattan <= 1;
      }
    for (int k = 0; k < 9; ++k)
      for (int a = 0; a < 9; ++a)
        for (int b = 0; b < 9; ++b) joined[a][b] = joined[a][b] || (joined[a][k] && joined[k][b]);
    const auto comps = free_components(g);
    std::uint64_t total = 0;
    std::uint32_t next_new = 1;
    for (int a = 0; a < 9; ++a) {
      const auto la = comps.label.cells()[static_cast<std::size_t>(a)];
      REQUIRE((la == 0) == (g.cells()[static_cast<std::size_t>(a)] != Occupancy::Free));
      if (la == next_new) ++next_new;
      REQUIRE(la < next_new); // first cells in row-major order get labels 1, 2, ...
      for (int b = 0; b < 9; ++b)
        if (la != 0)
          REQUIRE((la == comps.label.cells()[static_cast<std::size_t>(b)]) == joined[a][b]);
    }
    for (const auto s : comps.size) total += s;
    REQUIRE(total == 9 - static_cast<std::uint64_t>(__builtin_popcount(bits)));
    REQUIRE(comps.size.size() == next_new);
  }
}

TEST_CASE("place_robots: distinct free cells of one component, bearings 0..7, reproducible",
          "[uniform][property]") {
  rc::prop("starts", [] {
    const auto w = *rc::gen::inRange(1, 30);
    const auto h = *rc::gen::inRange(1, 30);
    const auto ppm = *rc::gen::inRange<std::uint32_t>(0, 400'000);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto g = random_obstacles(w, h, ppm, seed, 0);
    const auto comps = free_components(g);
    std::uint64_t largest = 0;
    for (const auto s : comps.size) largest = std::max(largest, s);
    RC_PRE(largest > 0);
    const auto n = *rc::gen::inRange<std::size_t>(
        1, static_cast<std::size_t>(std::min<std::uint64_t>(largest, 8)) + 1);
    const auto poses = place_robots(g, n, std::nullopt, seed, 3);
    RC_ASSERT(poses.size() == n);
    std::set<std::pair<int, int>> cells;
    for (const auto& p : poses) {
      RC_ASSERT(g[p.cell] == Occupancy::Free);
      RC_ASSERT(p.bearing < 8);
      RC_ASSERT(comps.size[comps.label[p.cell]] == largest);
      RC_ASSERT(comps.label[p.cell] == comps.label[poses[0].cell]);
      cells.insert({p.cell.x, p.cell.y});
    }
    RC_ASSERT(cells.size() == n);
    RC_ASSERT(poses == place_robots(g, n, std::nullopt, seed, 3));
    RC_ASSERT_THROWS_AS(
        place_robots(g, static_cast<std::size_t>(largest) + 1, std::nullopt, seed, 3),
        kernel::InputError);
  });
}

TEST_CASE("place_robots puts robot 0 on the map's start cell and the others in its component",
          "[uniform]") {
  // Two regions split by a wall: the start is in the smaller one.
  kernel::OccupancyGrid g(7, 3, Occupancy::Free);
  for (int y = 0; y < 3; ++y) g[{2, y}] = Occupancy::Blocked;
  const auto poses = place_robots(g, 3, Cell{0, 1}, 5, 0);
  REQUIRE(poses.size() == 3);
  CHECK(poses[0].cell == Cell{0, 1});
  for (const auto& p : poses) CHECK(p.cell.x < 2);
  CHECK_THROWS_AS(place_robots(g, 7, Cell{0, 1}, 5, 0), kernel::InputError);
  CHECK_THROWS_AS(place_robots(g, 1, Cell{2, 1}, 5, 0), kernel::InputError);
  CHECK_THROWS_AS(place_robots(g, 1, Cell{9, 1}, 5, 0), kernel::InputError);
  CHECK_THROWS_AS(
      place_robots(kernel::OccupancyGrid(2, 2, Occupancy::Blocked), 1, std::nullopt, 5, 0),
      kernel::InputError);
}

TEST_CASE("densities parse exactly, as fractions or percentages", "[uniform]") {
  CHECK(parse_density_ppm("0") == 0);
  CHECK(parse_density_ppm("1") == kPpm);
  CHECK(parse_density_ppm("0.2") == 200'000);
  CHECK(parse_density_ppm(".25") == 250'000);
  CHECK(parse_density_ppm("0.000001") == 1);
  CHECK(parse_density_ppm("20%") == 200'000);
  CHECK(parse_density_ppm("12.5%") == 125'000);
  CHECK(parse_density_ppm("100%") == kPpm);
  for (const char* bad : {"", "%", ".", "-0.1", "1.1", "101%", "0.0000001", "0.2.3", "2e-1", "abc",
                          "0,2", "1000000000000000000000"})
    CHECK_THROWS_AS(parse_density_ppm(bad), kernel::InputError);
}

TEST_CASE("sizes parse as WxH within the bounds", "[uniform]") {
  CHECK(parse_size("100x80", 4096) == std::pair<std::int32_t, std::int32_t>{100, 80});
  CHECK(parse_size("1X1", 4096) == std::pair<std::int32_t, std::int32_t>{1, 1});
  for (const char* bad : {"", "x", "100", "100x", "x100", "0x5", "5x0", "-5x5", "5x5x5", "4097x1",
                          "99999999999x1", " 5x5"})
    CHECK_THROWS_AS(parse_size(bad, 4096), kernel::InputError);
}
