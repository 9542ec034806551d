// The frontier component: the incremental set against its definition, and the planner against a
// brute-force evaluation of g = w1 I - w2 D + w3 lambda over every reachable frontier cell.
#include <antkit/frontier/frontier_map.hpp>
#include <antkit/frontier/planner.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/testing/los.hpp>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <vector>

using antkit::frontier::FrontierMap;
using antkit::frontier::FrontierPlanner;
using antkit::frontier::Knowledge;
using antkit::frontier::Weights;
using antkit::kernel::Cell;
using antkit::kernel::Grid;
using antkit::kernel::kNeighbours8;
using antkit::kernel::Stream;

namespace {

FrontierMap random_map(std::int32_t w, std::int32_t h, std::uint64_t seed, std::uint32_t free_pct,
                       std::uint32_t occupied_pct) {
  FrontierMap m(w, h);
  Stream s(seed, 51, 0, 0, 0);
  for (std::int32_t y = 0; y < h; ++y)
    for (std::int32_t x = 0; x < w; ++x) {
      const std::uint32_t r = s.below(100);
      if (r < free_pct)
        m.set({x, y}, Knowledge::Free);
      else if (r < free_pct + occupied_pct)
        m.set({x, y}, Knowledge::Occupied);
    }
  return m;
}

// Breadth-first distances through Free cells, never entering `blocked`; -1 unreachable.
Grid<std::int32_t> distances(const FrontierMap& m, Cell from, Cell blocked) {
  Grid<std::int32_t> d(m.width(), m.height(), -1);
  std::vector<Cell> q{from};
  d[from] = 0;
  for (std::size_t i = 0; i < q.size(); ++i)
    for (const Cell k : kNeighbours8) {
      const Cell n = q[i] + k;
      if (m.is_free(n) && d[n] < 0 && n != blocked) {
        d[n] = d[q[i]] + 1;
        q.push_back(n);
      }
    }
  return d;
}

} // namespace

TEST_CASE("frontier set: every 3x3 knowledge grid built cell by cell matches the definition",
          "[proof]") {
  // 3^9 grids; each is built by set() in row order from all-unexplored, and checked after every
  // set() so that every intermediate grid is checked too.
  for (int code = 0; code < 19683; ++code) {
    FrontierMap m(3, 3);
    int rest = code;
    for (int i = 0; i < 9; ++i) {
      m.set({i % 3, i / 3}, static_cast<Knowledge>(rest % 3));
      rest /= 3;
      const std::string err = antkit::testing::check_frontier_set(m);
      if (!err.empty()) {
        INFO("grid code " << code << ": " << err);
        REQUIRE(err.empty());
      }
    }
  }
}

TEST_CASE("frontier set: any sequence of updates keeps the set equal to the definition",
          "[property]") {
  rc::prop("incremental == from scratch", [] {
    const auto w = *rc::gen::inRange(1, 12);
    const auto h = *rc::gen::inRange(1, 12);
    const auto ops = *rc::gen::container<std::vector<std::tuple<int, int, int>>>(
        rc::gen::tuple(rc::gen::inRange(0, w), rc::gen::inRange(0, h), rc::gen::inRange(0, 3)));
    FrontierMap m(w, h);
    for (const auto& [x, y, k] : ops) {
      m.set({x, y}, static_cast<Knowledge>(k));
      const std::string err = antkit::testing::check_frontier_set(m);
      RC_ASSERT(err.empty());
    }
  });
}

TEST_CASE("frontier set: the grid's edge is not unexplored", "[frontier]") {
  FrontierMap m(2, 1);
  m.set({0, 0}, Knowledge::Free);
  CHECK(m.is_frontier({0, 0})); // its neighbour (1, 0) is unexplored
  m.set({1, 0}, Knowledge::Free);
  CHECK(m.frontier_count() == 0); // only off-grid cells around: no frontier
}

TEST_CASE("planner: the chosen frontier has the highest utility and is reached by a shortest path",
          "[property]") {
  rc::prop("plan == brute force", [] {
    const auto w = *rc::gen::inRange(2, 16);
    const auto h = *rc::gen::inRange(2, 16);
    const auto seed = *rc::gen::arbitrary<std::uint32_t>();
    const auto w1 = *rc::gen::inRange(0, 4);
    const auto w2 = *rc::gen::inRange(0, 4);
    const auto w3 = *rc::gen::inRange(-2, 3);
    const auto range = *rc::gen::inRange(0, 3);
    FrontierMap m = random_map(w, h, seed, 55, 15);
    const Cell from{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
    m.set(from, Knowledge::Free);
    Cell other{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
    if (other == from) other.x = (from.x + 1) % w; // robots never share a cell
    const Cell other_target{*rc::gen::inRange(0, w), *rc::gen::inRange(0, h)};
    FrontierPlanner planner(w, h, Weights{w1, w2, w3}, range);
    const std::vector<Cell> blocked{other}, claimed{other, other_target}, partners{other};
    const auto& plan = planner.plan(m, from, blocked, claimed, partners);

    const auto d = distances(m, from, other);
    bool any = false;
    std::int64_t best = 0;
    for (std::int32_t y = 0; y < h; ++y)
      for (std::int32_t x = 0; x < w; ++x) {
        const Cell c{x, y};
        if (!m.is_frontier(c) || d[c] <= 0) continue;
        const std::int64_t g = planner.utility(m, c, d[c], claimed, partners);
        if (!any || g > best) best = g;
        any = true;
      }
    RC_ASSERT(plan.found == any);
    if (!any) return;
    RC_ASSERT(plan.utility == best);
    RC_ASSERT(m.is_frontier(plan.target));
    RC_ASSERT(plan.distance == d[plan.target]);
    RC_ASSERT(plan.path.size() == static_cast<std::size_t>(plan.distance));
    RC_ASSERT(plan.path.back() == plan.target);
    Cell at = from;
    for (const Cell c : plan.path) {
      RC_ASSERT(std::abs(c.x - at.x) <= 1);
      RC_ASSERT(std::abs(c.y - at.y) <= 1);
      RC_ASSERT(m.is_free(c));
      RC_ASSERT(c != other);
      at = c;
    }
  });
}

TEST_CASE("planner: information gain leaves out what the other robot and its target cover",
          "[frontier]") {
  // A 7x3 corridor, all unexplored but the middle row; the robot at the west end.
  FrontierMap m(7, 3);
  for (int x = 0; x < 7; ++x) m.set({x, 1}, Knowledge::Free);
  FrontierPlanner planner(7, 3);
  const std::vector<Cell> none;
  CHECK(planner.information(m, {3, 1}, none) == 6); // the six unexplored cells around it
  const std::vector<Cell> claimed{{4, 1}};
  CHECK(planner.information(m, {3, 1}, claimed) == 2); // x = 3..5 is the other's: only x = 2
  // Without claims the nearest frontier wins (g = 6 - 1 at (1, 1)); claims on the west end
  // sends the robot east instead.
  const auto& plan = planner.plan(m, {0, 1}, none, none, none);
  REQUIRE(plan.found);
  CHECK(plan.target == Cell{1, 1});
  const std::vector<Cell> west{{1, 1}, {2, 1}};
  const auto& plan2 = planner.plan(m, {0, 1}, none, west, none);
  REQUIRE(plan2.found);
  CHECK(plan2.target.x >= 3);
}
