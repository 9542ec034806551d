// Two-robot LOS exploration (issue 5): the rules' soundness, exhaustively on small grids and by
// properties on larger ones, completion, determinism, and worked examples.
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/los/explore.hpp>
#include <antkit/los/fast_wall_follow.hpp>
#include <antkit/testing/los.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
namespace los = antkit::los;

namespace {

const std::array<los::ExploreOptions, 3> kVariants = [] {
  std::array<los::ExploreOptions, 3> v{};
  v[0].algorithm = los::Algorithm::FastWallFollow;
  v[1].algorithm = los::Algorithm::Frontier;
  v[1].line_of_sight = true;
  v[2].algorithm = los::Algorithm::Frontier;
  v[2].line_of_sight = false;
  return v;
}();

OccupancyGrid random_grid(std::int32_t w, std::int32_t h, std::uint64_t seed, std::uint32_t pct) {
  OccupancyGrid g(w, h, Occupancy::Free);
  antkit::kernel::Stream s(seed, 52, 0, 0, 0);
  for (auto& c : g.cells())
    if (s.below(100) < pct) c = s.chance(1, 8) ? Occupancy::Unknown : Occupancy::Blocked;
  return g;
}

// Every w x h map (each cell free or blocked) and every free start cell with a free neighbour, for
// all three variants: each tick is checked (soundness, states only up, NLOS only from F, the
// frontier set, robots apart on free cells, moves to neighbours) and so is completion
// (observable == explored). Returns the number of runs.
std::size_t check_every_map(std::int32_t w, std::int32_t h) {
  const auto n = static_cast<std::size_t>(w * h);
  std::size_t runs = 0;
  for (std::uint32_t bits = 0; bits < (1u << n); ++bits) {
    OccupancyGrid g(w, h, Occupancy::Free);
    for (std::size_t i = 0; i < n; ++i)
      if (bits >> i & 1u) g.cells()[i] = Occupancy::Blocked;
    for (std::size_t i = 0; i < n; ++i) {
      std::array<Cell, 2> start{};
      try {
        start = los::start_pair(g, g.cell_at(i));
      } catch (const std::invalid_argument&) {
        continue;
      }
      for (const auto& options : kVariants) {
        const std::string err = antkit::testing::check_run(g, start[0], start[1], options);
        ++runs;
        if (!err.empty()) {
          INFO(w << "x" << h << " map bits " << bits << ", start cell " << i << ", algorithm "
                 << static_cast<int>(options.algorithm) << ": " << err);
          REQUIRE(err.empty());
        }
      }
    }
  }
  return runs;
}

} // namespace

TEST_CASE("every 3x3 map and every start: sound and monotone and complete for all three variants",
          "[proof]") {
  CHECK(check_every_map(3, 3) > 2000);
}

TEST_CASE("every 4x3 map and every start: sound and monotone and complete for all three variants",
          "[proof]") {
  CHECK(check_every_map(4, 3) > 50000);
}

TEST_CASE("every 4x4 map and every start: sound and monotone and complete for all three variants",
          "[proof][slow]") {
  CHECK(check_every_map(4, 4) > 1000000);
}

TEST_CASE("random maps up to 40x40: sound and monotone and complete", "[property]") {
  rc::prop("every variant completes soundly", [] {
    const auto w = *rc::gen::inRange(2, 41);
    const auto h = *rc::gen::inRange(2, 41);
    const auto pct = *rc::gen::inRange(0, 45);
    const auto seed = *rc::gen::arbitrary<std::uint32_t>();
    const auto variant = *rc::gen::inRange(0, 3);
    const OccupancyGrid g = random_grid(w, h, seed, static_cast<std::uint32_t>(pct));
    Cell start{};
    try {
      start = los::default_start(g);
    } catch (const std::invalid_argument&) {
      RC_DISCARD("no place for two robots");
    }
    const auto pair = los::start_pair(g, start);
    const std::string err = antkit::testing::check_run(
        g, pair[0], pair[1], kVariants[static_cast<std::size_t>(variant)]);
    RC_ASSERT(err.empty());
  });
}

TEST_CASE("a run is a function of its inputs: same map and start give the same hash",
          "[property]") {
  rc::prop("deterministic", [] {
    const auto seed = *rc::gen::arbitrary<std::uint32_t>();
    const auto variant = *rc::gen::inRange(0, 3);
    const OccupancyGrid g = random_grid(30, 20, seed, 15);
    const auto pair = los::start_pair(g, los::default_start(g));
    const auto& o = kVariants[static_cast<std::size_t>(variant)];
    const auto r1 = los::explore(g, pair[0], pair[1], o);
    const auto r2 = los::explore(g, pair[0], pair[1], o);
    RC_ASSERT(r1.hash == r2.hash);
    RC_ASSERT(r1.steps == r2.steps);
    RC_ASSERT(r1.cells == r2.cells);
  });
}

TEST_CASE("empty 25x25 room: fast wall-follow sweeps it while tracing the walls", "[los]") {
  // Both robots start in the lower-left corner; A traces the walls clockwise, B counter-clockwise.
  // In an empty room the line between them always holds and sweeps the interior, so the run ends
  // before they have each walked half of the 96-move ring of wall cells, both moving every tick.
  const OccupancyGrid g(25, 25, Occupancy::Free);
  const auto pair = los::start_pair(g, los::default_start(g));
  CHECK(pair[0] == Cell{0, 24});
  CHECK(pair[1] == Cell{1, 24});
  const auto r = los::explore(g, pair[0], pair[1], {});
  CHECK(antkit::testing::check_complete(g, r).empty());
  CHECK(r.explored == 625);
  CHECK(r.unobservable == 0);
  CHECK(r.sight_losses == 0);
  CHECK(r.eme == 2 * r.steps);
  CHECK(r.steps <= 48);
  // A went up the west wall first, B east along the south wall.
  CHECK(r.trajectories[0][1] == Cell{0, 23});
  CHECK(r.trajectories[1][1] == Cell{2, 24});
}

TEST_CASE("fast wall-follow: a loss of sight makes both step back and then B looks for the cause",
          "[los]") {
  // One obstacle at (1, 5): A, going up the west wall, loses sight of B at (0, 5) and steps back.
  OccupancyGrid g(25, 25, Occupancy::Free);
  g[{1, 5}] = Occupancy::Blocked;
  los::FastWallFollow ctrl(25, 25);
  los::TwoRobotWorld world(g, {0, 24}, {1, 24});
  bool stepped_back = false, sought = false, followed = false;
  for (int tick = 0; tick < 400; ++tick) {
    const auto obs = world.observe();
    const auto before = ctrl.sight_losses();
    const auto cmd = ctrl.step(obs);
    if (ctrl.sight_losses() > before) {
      stepped_back = true;
      CHECK_FALSE(obs.line_of_sight);
      world.apply(cmd);
      CHECK(world.observe().line_of_sight); // sight is back after the step back
      continue;
    }
    sought = sought || ctrl.trouble_shooter() == los::FastWallFollow::TroubleShooter::Seek;
    followed =
        followed || ctrl.trouble_shooter() == los::FastWallFollow::TroubleShooter::FollowCause;
    if (cmd.finished) break;
    world.apply(cmd);
  }
  CHECK(stepped_back);
  CHECK(sought);
  CHECK(followed);
  CHECK(ctrl.stage() == los::FastWallFollow::Stage::Finished);
}

TEST_CASE("environments: scattered obstacles and blocks of six drawn from the seed", "[los]") {
  const Cell keep{0, 24};
  for (std::uint64_t trial = 1; trial <= 10; ++trial) {
    for (const int k : {1, 2, 5, 10}) {
      const auto g = los::scattered_obstacles(25, 25, k, 7, trial, keep);
      CHECK(std::count(g.cells().begin(), g.cells().end(), Occupancy::Blocked) == k);
      CHECK(g[keep] == Occupancy::Free);
      CHECK(g == los::scattered_obstacles(25, 25, k, 7, trial, keep));
    }
    for (const int k : {1, 2}) {
      const auto g = los::obstacle_blocks(25, 25, k, 7, trial, keep);
      CHECK(std::count(g.cells().begin(), g.cells().end(), Occupancy::Blocked) == 6 * k);
      for (std::int32_t i = 0; i < 25; ++i) { // islands: the edge is free
        CHECK(g[{i, 0}] == Occupancy::Free);
        CHECK(g[{i, 24}] == Occupancy::Free);
        CHECK(g[{0, i}] == Occupancy::Free);
        CHECK(g[{24, i}] == Occupancy::Free);
      }
    }
  }
  CHECK(los::scattered_obstacles(25, 25, 3, 7, 1, keep) !=
        los::scattered_obstacles(25, 25, 3, 7, 2, keep));
  CHECK_THROWS_AS(los::scattered_obstacles(3, 3, 1, 7, 1, {1, 1}), std::invalid_argument);
}

TEST_CASE(
    "start: nearest free cell to the lower-left corner and the partner on its nearest neighbour",
    "[los]") {
  OccupancyGrid g(4, 3, Occupancy::Free);
  g[{0, 2}] = Occupancy::Blocked;
  CHECK(los::default_start(g) == Cell{1, 2}); // distance 1; (0, 1) is as near but higher up
  g[{2, 2}] = Occupancy::Blocked;
  const auto pair = los::start_pair(g, {1, 2});
  CHECK(pair[1] == Cell{1, 1}); // east is blocked: north next
  CHECK_THROWS_AS(los::start_pair(g, {0, 2}), std::invalid_argument);
  CHECK_THROWS_AS(los::start_pair(g, {9, 9}), std::invalid_argument);
}

TEST_CASE("golden trace hashes (change only with a commit that says why)", "[los]") {
  const Cell keep{0, 24};
  const auto g = los::scattered_obstacles(25, 25, 5, 1, 1, keep);
  const auto pair = los::start_pair(g, keep);
  std::array<std::string, 3> hashes;
  for (std::size_t v = 0; v < 3; ++v)
    hashes[v] = antkit::kernel::hash_hex(los::explore(g, pair[0], pair[1], kVariants[v]).hash);
  CHECK(hashes[0] == "98f72a4e55dc3fe3");
  CHECK(hashes[1] == "67f1a70ad305401b");
  CHECK(hashes[2] == "0f51e8514f7093c5");
}
