#include <antkit/kernel/raster.hpp>
#include <antkit/testing/uniform.hpp>
#include <antkit/uniform/controllers.hpp>
#include <antkit/uniform/coverage_ticks.hpp>
#include <antkit/uniform/frontier_coverage.hpp>
#include <sstream>
#include <vector>

namespace antkit::testing {

using kernel::Cell;
using kernel::Occupancy;
using namespace antkit::uniform;

kernel::Grid<std::uint8_t> brute_force_view(const kernel::OccupancyGrid& map, Cell from,
                                            std::int32_t range) {
  kernel::Grid<std::uint8_t> out(map.width(), map.height(), 0);
  for (std::int32_t y = 0; y < map.height(); ++y)
    for (std::int32_t x = 0; x < map.width(); ++x) {
      const std::int64_t dx = x - from.x, dy = y - from.y;
      if (dx * dx + dy * dy <= std::int64_t{range} * range &&
          kernel::line_of_sight(map, from, {x, y}))
        out[{x, y}] = 1;
    }
  return out;
}

namespace {

std::string where(std::uint64_t tick, std::size_t robot, Cell c) {
  std::ostringstream s;
  s << "tick " << tick << ", robot " << robot << " at (" << c.x << ", " << c.y << "): ";
  return s.str();
}

// run_ticks' team (as run_coverage's) over a controller that takes an Observation, which also
// keeps the pose robot i had before its command, for after_action to compare with.
template <class Team>
struct WatchedTeam {
  Team& team;
  const CoverageWorld& world;
  Pose before{};
  Command command(std::size_t i) {
    before = world.robot(i);
    return team.step(Observation{i, &world});
  }
};

// The run is run_coverage's own loop (coverage_ticks.hpp's run_ticks), so the counts and the hash
// are the run's by construction; the checks hang on its after_action hook.
template <class Team>
UniformRunCheck check_team(CoverageWorld& world, Team& team, Algorithm algorithm,
                           std::uint64_t limit) {
  UniformRunCheck out;
  auto& res = out.result;
  res.algorithm = algorithm;
  res.robots = world.robot_count();
  std::vector<std::uint8_t> viewed_before = world.viewed().cells();
  const auto fail = [&](const std::string& what) {
    if (out.ok) {
      out.ok = false;
      out.what = what;
    }
  };
  const auto check_world = [&](std::uint64_t tick, std::size_t robot) {
    const auto& map = world.map();
    std::uint64_t free_viewed = 0;
    for (std::size_t k = 0; k < map.size(); ++k) {
      const Cell c = map.cell_at(k);
      if (viewed_before[k] && !world.viewed().cells()[k]) fail(where(tick, robot, c) + "unviewed");
      if (world.viewed().cells()[k] && map.cells()[k] == Occupancy::Free) {
        ++free_viewed;
        if (!world.is_viewable(c)) fail(where(tick, robot, c) + "viewed but not viewable");
      }
    }
    if (free_viewed != world.viewed_free()) fail(where(tick, robot, {}) + "viewed count is off");
    viewed_before = world.viewed().cells();
    for (std::size_t i = 0; i < world.robot_count(); ++i) {
      const Cell c = world.robot(i).cell;
      if (!world.is_free(c)) fail(where(tick, i, c) + "not on a free cell");
      if (world.occupant(c) != i + 1) fail(where(tick, i, c) + "shares its cell");
      const auto seen = brute_force_view(map, c, world.footprint().range());
      for (std::size_t k = 0; k < map.size(); ++k)
        if (seen.cells()[k] && !world.viewed().cells()[k])
          fail(where(tick, i, c) + "a cell in view is not viewed");
    }
  };
  // Robot i has acted in tick `tick` (counted from 0).
  WatchedTeam<Team> watched{team, world};
  const auto after_action = [&](std::uint64_t tick, std::size_t i) {
    const Pose before = watched.before;
    const Pose after = world.robot(i);
    if (after.cell != before.cell) {
      const Cell d = after.cell - before.cell;
      if (d != kernel::kNeighbours8[after.bearing])
        fail(where(tick, i, after.cell) + "moved other than one step along its bearing");
      if (d.x != 0 && d.y != 0 &&
          (!world.is_free({before.cell.x + d.x, before.cell.y}) ||
           !world.is_free({before.cell.x, before.cell.y + d.y})))
        fail(where(tick, i, after.cell) + "cut a corner");
    } else if (after.bearing != before.bearing) {
      const int turn = (after.bearing - before.bearing + 8) % 8;
      if (turn != 1 && turn != 7) fail(where(tick, i, after.cell) + "turned too far");
    }
    check_world(tick, i);
    if constexpr (std::is_same_v<Team, AStarCoverage>) {
      if (i + 1 != world.robot_count()) return; // the goals once a tick, after the last robot
      bool clash = false;
      for (std::size_t a = 0; a < world.robot_count(); ++a)
        for (std::size_t b = a + 1; b < world.robot_count(); ++b)
          clash = clash || (team.goal(a) && team.goal(a) == team.goal(b));
      if (clash) {
        ++out.goal_clashes;
        bool all_taken = true;
        for (std::size_t k = 0; k < world.map().size() && all_taken; ++k) {
          const Cell c = world.map().cell_at(k);
          if (!world.is_viewable(c) || world.is_viewed(c)) continue;
          bool taken = false;
          for (std::size_t a = 0; a < world.robot_count(); ++a) taken = taken || team.goal(a) == c;
          all_taken = taken;
        }
        if (!all_taken) ++out.unjustified_clashes;
      }
    }
  };
  check_world(0, 0);
  const TickRun run = run_ticks(world, watched, static_cast<std::uint8_t>(algorithm), limit,
                                after_action, [](std::uint64_t) {});
  res.movements = run.movements;
  res.moves = run.moves;
  res.stop = static_cast<StopReason>(run.stop);
  res.viewed = world.viewed_free();
  res.viewable = world.viewable();
  res.hash = run.hash;
  return out;
}

} // namespace

UniformRunCheck check_uniform_run(CoverageWorld& world, Algorithm algorithm, std::uint64_t seed,
                                  std::uint64_t trial, std::uint64_t limit) {
  switch (algorithm) {
  case Algorithm::RandomWanderer: {
    RandomWanderer team(seed, trial, world.robot_count());
    return check_team(world, team, algorithm, limit);
  }
  case Algorithm::PrimaryMovement: {
    PrimaryMovement team(world.robot_count());
    return check_team(world, team, algorithm, limit);
  }
  case Algorithm::AStar:
  case Algorithm::CoordinatedAStar: {
    AStarCoverage team(seed, trial, world.robot_count(), algorithm == Algorithm::CoordinatedAStar);
    return check_team(world, team, algorithm, limit);
  }
  case Algorithm::Frontier: {
    FrontierCoverage team(seed, trial, world);
    return check_team(world, team, algorithm, limit);
  }
  }
  return {};
}

} // namespace antkit::testing
