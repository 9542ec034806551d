// Spiral iteration and the A-Star search of paper 004's A* algorithm.
#include <antkit/uniform/planner.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/world.hpp>
#include <catch2/catch.hpp>
#include <deque>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

using namespace antkit;
using namespace antkit::uniform;
using kernel::Cell;
using kernel::Occupancy;

namespace {
std::int32_t chebyshev(Cell a, Cell b) {
  return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y));
}
} // namespace

TEST_CASE("spiral ring 1 is the eight neighbours, starting along the bearing, counter-clockwise",
          "[uniform][proof]") {
  for (std::uint8_t b = 0; b < 8; ++b) {
    std::vector<Cell> seen;
    spiral_find({5, 5}, b, 11, 11, [&](Cell c) {
      seen.push_back(c);
      return seen.size() == 9;
    });
    REQUIRE(seen.size() == 9);
    CHECK(seen[0] == Cell{5, 5});
    for (std::size_t s = 0; s < 8; ++s)
      CHECK(seen[s + 1] == Cell{5, 5} + kernel::kNeighbours8[(b + s) & 7u]);
  }
}

TEST_CASE("spiral iteration visits every grid cell once, ring by ring, each ring from the "
          "bearing",
          "[uniform][property]") {
  rc::prop("spiral order", [] {
    const auto w = *rc::gen::inRange(1, 20);
    const auto h = *rc::gen::inRange(1, 20);
    const Cell centre{*rc::gen::inRange(-4, w + 4), *rc::gen::inRange(-4, h + 4)};
    const auto b = *rc::gen::inRange<std::uint8_t>(0, 8);
    const auto first_ring = *rc::gen::inRange(0, 4);
    kernel::Grid<std::uint8_t> count(w, h, 0);
    std::int32_t ring = -1;
    std::size_t visited = 0;
    const auto hit = spiral_find(
        centre, b, w, h,
        [&](Cell c) {
          RC_ASSERT(c.x >= 0 && c.y >= 0 && c.x < w && c.y < h);
          const auto d = chebyshev(c, centre);
          RC_ASSERT(d >= ring); // rings never go back
          RC_ASSERT(d >= first_ring);
          if (d > ring) {
            ring = d;
            // A ring starts at the cell d steps along the bearing whenever that cell is on the
            // grid.
            const Cell ahead{centre.x + d * kernel::kNeighbours8[b].x,
                             centre.y + d * kernel::kNeighbours8[b].y};
            if (ahead.x >= 0 && ahead.y >= 0 && ahead.x < w && ahead.y < h) RC_ASSERT(c == ahead);
          }
          ++count[c];
          ++visited;
          return false;
        },
        first_ring);
    RC_ASSERT(!hit.has_value());
    for (std::int32_t y = 0; y < h; ++y)
      for (std::int32_t x = 0; x < w; ++x)
        RC_ASSERT((count[Cell{x, y}] == (chebyshev(Cell{x, y}, centre) >= first_ring ? 1 : 0)));
  });
}

TEST_CASE("the spiral's first hit is nearest in Chebyshev distance", "[uniform][property]") {
  rc::prop("nearest", [] {
    const auto w = *rc::gen::inRange(1, 20);
    const auto h = *rc::gen::inRange(1, 20);
    const Cell centre{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
    const auto targets = *rc::gen::container<std::vector<std::pair<int, int>>>(
        rc::gen::pair(rc::gen::inRange(0, w), rc::gen::inRange(0, h)));
    const auto is_target = [&](Cell c) {
      return std::find(targets.begin(), targets.end(), std::pair{c.x, c.y}) != targets.end();
    };
    const auto hit = spiral_find(centre, 3, w, h, is_target);
    RC_ASSERT(hit.has_value() == !targets.empty());
    for (const auto& [x, y] : targets)
      RC_ASSERT((chebyshev(*hit, centre) <= chebyshev(Cell{x, y}, centre)));
  });
}

TEST_CASE("A-Star finds a shortest path (BFS is the oracle), with or without a heuristic",
          "[uniform][property]") {
  rc::prop("shortest", [] {
    const auto w = *rc::gen::inRange(1, 24);
    const auto h = *rc::gen::inRange(1, 24);
    const auto g = random_obstacles(w, h, *rc::gen::inRange<std::uint32_t>(0, 450'000),
                                    *rc::gen::arbitrary<std::uint64_t>(), 0);
    const Cell start{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
    const Cell target{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
    RC_PRE(g[start] == Occupancy::Free);
    const CoverageWorld world(g, {{start, 0}}, 1);
    const auto step_ok = [&](Cell c, std::uint8_t b) { return world.passable_step(c, b); };
    // Breadth-first distances from start over the same steps.
    kernel::Grid<std::int32_t> dist(w, h, -1);
    std::deque<Cell> queue{start};
    dist[start] = 0;
    while (!queue.empty()) {
      const Cell c = queue.front();
      queue.pop_front();
      for (std::uint8_t b = 0; b < 8; ++b)
        if (step_ok(c, b) && dist[c + kernel::kNeighbours8[b]] < 0) {
          dist[c + kernel::kNeighbours8[b]] = dist[c] + 1;
          queue.push_back(c + kernel::kNeighbours8[b]);
        }
    }
    PathSearch search;
    for (const bool informed : {false, true}) {
      std::vector<std::uint8_t> path;
      const bool found = search.find(
          w, h, start, *rc::gen::inRange<std::uint8_t>(0, 8), step_ok,
          [&](Cell c) { return c == target; },
          [&](Cell c) { return informed ? chebyshev(c, target) : 0; }, path);
      RC_ASSERT(found == (dist[target] >= 0));
      if (!found) continue;
      RC_ASSERT(static_cast<std::int32_t>(path.size()) == dist[target]);
      Cell at = start;
      for (const auto b : path) {
        RC_ASSERT(step_ok(at, b));
        at = at + kernel::kNeighbours8[b];
      }
      RC_ASSERT(at == target);
    }
  });
}

TEST_CASE("A-Star gives up after its budget", "[uniform]") {
  kernel::OccupancyGrid g(50, 1, Occupancy::Free);
  const CoverageWorld world(g, {{{0, 0}, 0}}, 1);
  PathSearch search;
  std::vector<std::uint8_t> path;
  const auto step_ok = [&](Cell c, std::uint8_t b) { return world.passable_step(c, b); };
  const auto reached = [](Cell c) { return c == Cell{49, 0}; };
  const auto zero = [](Cell) { return 0; };
  CHECK_FALSE(search.find(50, 1, {0, 0}, 0, step_ok, reached, zero, path, 10));
  CHECK(search.find(50, 1, {0, 0}, 0, step_ok, reached, zero, path, 50));
  CHECK(path.size() == 49);
}
