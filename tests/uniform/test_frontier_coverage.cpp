// The fourth algorithm, frontier coverage (frontier_coverage.hpp): it views every viewable free
// cell on random small maps without breaking the world's rules, keeps its frontier set equal to the
// definition, never lets two robots share a target, and is reproducible bit for bit.
#include <antkit/algorithms/controller.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/frontier_coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <sstream>
#include <string>

using namespace antkit;
using namespace antkit::uniform;
using kernel::Cell;
using kernel::Occupancy;

static_assert(algorithms::Controller<FrontierCoverage>);

namespace {

// Steps the team like run_coverage and checks, after every robot's turn: robots on distinct Free
// cells, a move goes to a neighbour without cutting a corner, the incremental frontier set equals
// the definition over the communal map, no two robots hold the same target. Returns "" or what
// broke. (tests/support's check_uniform_run dispatches only the paper's algorithms and A*; its
// rules are repeated here for the one it does not know.)
std::string check_frontier_run(CoverageWorld& w, std::uint64_t limit, CoverageResult& out) {
  FrontierCoverage team(9, 2, w);
  kernel::TraceHash hash;
  hash.add_u8(static_cast<std::uint8_t>(Algorithm::Frontier)).add_u64(w.robot_count());
  w.hash_state(hash);
  const auto& map = w.map();
  for (;;) {
    if (w.complete()) {
      out.stop = StopReason::Complete;
      break;
    }
    if (out.movements >= limit) {
      out.stop = StopReason::TimeLimit;
      break;
    }
    bool acted = false;
    for (std::size_t i = 0; i < w.robot_count(); ++i) {
      const Cell before = w.robot(i).cell;
      const Command cmd = team.step({i, &w});
      std::ostringstream where;
      where << "tick " << out.movements << " robot " << i << " at (" << before.x << ", " << before.y
            << "): ";
      if (cmd.action != Action::Step && cmd.action != Action::Wait && cmd.action != Action::Stop)
        return where.str() + "an action other than step, wait or stop";
      if (cmd.action == Action::Step) {
        if (!w.can_step(before, cmd.bearing)) return where.str() + "a step the rules forbid";
        w.move(i, cmd.bearing);
        w.view(i);
        ++out.moves;
      }
      if (cmd.action != Action::Stop) acted = true;
      for (std::size_t j = 0; j < w.robot_count(); ++j) {
        if (map[w.robot(j).cell] != Occupancy::Free) return where.str() + "a robot off free space";
        for (std::size_t k = j + 1; k < w.robot_count(); ++k) {
          if (w.robot(j).cell == w.robot(k).cell) return where.str() + "two robots share a cell";
          if (team.target(j) && team.target(j) == team.target(k))
            return where.str() + "two robots share a target";
        }
      }
    }
    if (!acted) {
      out.stop = StopReason::NoMove;
      break;
    }
    ++out.movements;
    w.hash_state(hash);
    // The incremental set against the definition, over the whole map (after the next refresh,
    // which the controller does at the start of a turn: step robot 0 of a copy would change the
    // run, so compare cells whose knowledge the controller already has).
    const auto& f = team.frontiers();
    for (std::size_t k = 0; k < map.size(); ++k) {
      const Cell c = map.cell_at(k);
      if (f.is_frontier(c) != f.frontier_by_definition(c))
        return "the frontier set differs from its definition";
      if (f.at(c) != frontier::Knowledge::Unexplored && !w.is_viewed(c))
        return "a cell known that was never viewed";
    }
  }
  out.viewed = w.viewed_free();
  out.viewable = w.viewable();
  out.hash = hash.finish();
  return {};
}

} // namespace

TEST_CASE("frontier coverage views every viewable free cell, breaking no rule",
          "[uniform][property]") {
  rc::prop("frontier completes", [] {
    const auto w = *rc::gen::inRange(1, 15);
    const auto h = *rc::gen::inRange(1, 15);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto g = random_obstacles(w, h, *rc::gen::inRange<std::uint32_t>(0, 450'000), seed, 0);
    const auto comps = free_components(g);
    std::uint64_t largest = 0;
    for (const auto s : comps.size) largest = std::max(largest, s);
    RC_PRE(largest > 0);
    const auto n = *rc::gen::inRange<std::size_t>(
        1, static_cast<std::size_t>(std::min<std::uint64_t>(largest, 4)) + 1);
    const auto r = *rc::gen::inRange(1, 5);
    const auto poses = place_robots(g, n, std::nullopt, seed, 1);
    RC_LOG() << w << "x" << h << " seed " << seed << " robots " << n << " sensor " << r << '\n';
    CoverageWorld checked(g, poses, r);
    CoverageResult check;
    const std::string broke = check_frontier_run(checked, 100'000, check);
    if (!broke.empty()) RC_FAIL(broke);
    RC_ASSERT(check.stop == StopReason::Complete);
    RC_ASSERT(check.viewed == check.viewable);
    RC_ASSERT(check.moves <= check.movements * n);
    // run_coverage counts and hashes exactly as the step-by-step check does.
    CoverageWorld plain(g, poses, r);
    const auto res = run_coverage(plain, Algorithm::Frontier, 9, 2, 100'000);
    RC_ASSERT(res.movements == check.movements);
    RC_ASSERT(res.moves == check.moves);
    RC_ASSERT(res.hash == check.hash);
  });
}

TEST_CASE("frontier: a corridor is walked greedily, ties to the kernel's neighbour order",
          "[uniform]") {
  // 9x1, sensor 1, one robot at x = 3: its start views x = 2..4, so x = 2 and x = 4 are frontier
  // cells at distance 1 with I = 1 each. The tie goes to the first met: east (E is the first
  // neighbour). From then on the nearer frontier wins (g = I - D with I = 1): on east to x = 7,
  // which sees x = 8 (4 moves), then back west to x = 1, which sees x = 0 (6 moves).
  CoverageWorld w(kernel::OccupancyGrid(9, 1, Occupancy::Free), {{{3, 0}, 0}}, 1);
  const auto r = run_coverage(w, Algorithm::Frontier, 1, 0, 1000);
  CHECK(r.stop == StopReason::Complete);
  CHECK(r.viewed == 9);
  CHECK(r.moves == r.movements); // one robot, a step every tick, never a wait
  CHECK(r.moves == 10);
  CHECK(w.robot(0).cell == Cell{1, 0});
}

TEST_CASE("frontier refuses a sensor distance of 0", "[uniform]") {
  CoverageWorld w(kernel::OccupancyGrid(4, 4, Occupancy::Free), {{{0, 0}, 0}}, 0);
  CHECK_THROWS_AS(run_coverage(w, Algorithm::Frontier, 1, 0, 10), kernel::InputError);
}

TEST_CASE("frontier runs are reproducible: golden trace hash", "[uniform]") {
  // The map and robots of test_coverage's golden case (32x32, 20 %, 3 robots, sensor 4, seed
  // 2026). Changes only when the model does; a commit that moves it says why.
  const auto g = random_obstacles(32, 32, 200'000, 2026, 0);
  const auto poses = place_robots(g, 3, std::nullopt, 2026, 0);
  CoverageWorld a(g, poses, 4), b(g, poses, 4);
  const auto ra = run_coverage(a, Algorithm::Frontier, 2026, 0, 2000);
  const auto rb = run_coverage(b, Algorithm::Frontier, 2026, 0, 2000);
  CHECK(ra.hash == rb.hash);
  CHECK(ra.moves == rb.moves);
  INFO(ra.movements << " " << ra.moves << " " << ra.viewed << " " << kernel::hash_hex(ra.hash));
  CHECK(ra.stop == StopReason::Complete);
  CHECK(ra.viewed == 814);    // every viewable free cell, as A* views
  CHECK(ra.movements == 111); // A*: 132, coordinated A*: 128 on this map
  CHECK(ra.moves == 327);
  CHECK(kernel::hash_hex(ra.hash) == "7b25bd1bd4b872d5");
  CHECK(parse_algorithm("frontier") == Algorithm::Frontier);
  CHECK(algorithm_name(Algorithm::Frontier) == "frontier");
}
