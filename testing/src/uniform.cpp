#include <antkit/kernel/raster.hpp>
#include <antkit/testing/uniform.hpp>
#include <antkit/uniform/controllers.hpp>
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

template <class Team>
UniformRunCheck check_team(CoverageWorld& world, Team& team, Algorithm algorithm,
                           std::uint64_t limit) {
  UniformRunCheck out;
  auto& res = out.result;
  res.algorithm = algorithm;
  res.robots = world.robot_count();
  kernel::TraceHash hash;
  hash.add_u8(static_cast<std::uint8_t>(algorithm)).add_u64(world.robot_count());
  world.hash_state(hash);
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
  check_world(0, 0);
  for (;;) {
    if (world.complete()) {
      res.stop = StopReason::Complete;
      break;
    }
    if (res.movements >= limit) {
      res.stop = StopReason::TimeLimit;
      break;
    }
    bool acted = false;
    for (std::size_t i = 0; i < world.robot_count(); ++i) {
      const Pose before = world.robot(i);
      const Command cmd = team.step(Observation{i, &world});
      bool done = false;
      switch (cmd.action) {
      case Action::TurnLeft:
        done = world.turn(i, 1);
        break;
      case Action::TurnRight:
        done = world.turn(i, -1);
        break;
      case Action::Forward:
        done = world.move(i, world.robot(i).bearing);
        if (done) world.view(i);
        break;
      case Action::Step:
        done = world.move(i, cmd.bearing);
        if (done) world.view(i);
        break;
      default:
        break;
      }
      const Pose after = world.robot(i);
      if (done) ++res.moves;
      if (cmd.action != Action::Stop) acted = true;
      if (after.cell != before.cell) {
        const Cell d = after.cell - before.cell;
        if (d != kernel::kNeighbours8[after.bearing])
          fail(where(res.movements, i, after.cell) + "moved other than one step along its bearing");
        if (d.x != 0 && d.y != 0 &&
            (!world.is_free({before.cell.x + d.x, before.cell.y}) ||
             !world.is_free({before.cell.x, before.cell.y + d.y})))
          fail(where(res.movements, i, after.cell) + "cut a corner");
      } else if (after.bearing != before.bearing) {
        const int turn = (after.bearing - before.bearing + 8) % 8;
        if (turn != 1 && turn != 7) fail(where(res.movements, i, after.cell) + "turned too far");
      }
      check_world(res.movements, i);
    }
    if constexpr (std::is_same_v<Team, AStarCoverage>) {
      bool clash = false;
      for (std::size_t i = 0; i < world.robot_count(); ++i)
        for (std::size_t j = i + 1; j < world.robot_count(); ++j)
          clash = clash || (team.goal(i) && team.goal(i) == team.goal(j));
      if (clash) {
        ++out.goal_clashes;
        bool all_taken = true;
        for (std::size_t k = 0; k < world.map().size() && all_taken; ++k) {
          const Cell c = world.map().cell_at(k);
          if (!world.is_viewable(c) || world.is_viewed(c)) continue;
          bool taken = false;
          for (std::size_t i = 0; i < world.robot_count(); ++i) taken = taken || team.goal(i) == c;
          all_taken = taken;
        }
        if (!all_taken) ++out.unjustified_clashes;
      }
    }
    if (!acted) {
      res.stop = StopReason::NoMove;
      break;
    }
    ++res.movements;
    world.hash_state(hash);
  }
  res.viewed = world.viewed_free();
  res.viewable = world.viewable();
  res.hash = hash.finish();
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
