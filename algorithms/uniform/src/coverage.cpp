#include <antkit/uniform/controllers.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/frontier_coverage.hpp>

namespace antkit::uniform {

std::string_view algorithm_name(Algorithm a) noexcept {
  switch (a) {
  case Algorithm::RandomWanderer:
    return "rw";
  case Algorithm::PrimaryMovement:
    return "pm";
  case Algorithm::AStar:
    return "astar";
  case Algorithm::CoordinatedAStar:
    return "astar-coord";
  case Algorithm::Frontier:
    return "frontier";
  }
  return "?";
}

std::optional<Algorithm> parse_algorithm(std::string_view name) noexcept {
  for (const Algorithm a : {Algorithm::RandomWanderer, Algorithm::PrimaryMovement, Algorithm::AStar,
                            Algorithm::CoordinatedAStar, Algorithm::Frontier})
    if (algorithm_name(a) == name) return a;
  return std::nullopt;
}

std::string_view stop_reason_name(StopReason r) noexcept {
  switch (r) {
  case StopReason::Complete:
    return "complete";
  case StopReason::NoMove:
    return "no-move";
  case StopReason::TimeLimit:
    return "time-limit";
  }
  return "?";
}

namespace {

template <class Team>
CoverageResult run_team(CoverageWorld& world, Team& team, Algorithm algorithm, std::uint64_t limit,
                        const TickObserver* observer) {
  CoverageResult out;
  out.algorithm = algorithm;
  out.robots = world.robot_count();
  kernel::TraceHash hash;
  hash.add_u8(static_cast<std::uint8_t>(algorithm)).add_u64(world.robot_count());
  world.hash_state(hash);
  if (observer) (*observer)(world, 0);
  for (;;) {
    if (world.complete()) {
      out.stop = StopReason::Complete;
      break;
    }
    if (out.movements >= limit) {
      out.stop = StopReason::TimeLimit;
      break;
    }
    bool acted = false;
    for (std::size_t i = 0; i < world.robot_count(); ++i) {
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
      case Action::Wait:
      case Action::Stop:
        break;
      }
      if (done) ++out.moves;
      if (cmd.action != Action::Stop) acted = true;
    }
    if (!acted) {
      out.stop = StopReason::NoMove;
      break;
    }
    ++out.movements;
    world.hash_state(hash);
    if (observer) (*observer)(world, out.movements);
  }
  out.viewed = world.viewed_free();
  out.viewable = world.viewable();
  out.hash = hash.finish();
  return out;
}

} // namespace

namespace {

CoverageResult run_with(CoverageWorld& world, Algorithm algorithm, std::uint64_t seed,
                        std::uint64_t trial, std::uint64_t limit, const TickObserver* observer) {
  switch (algorithm) {
  case Algorithm::RandomWanderer: {
    RandomWanderer team(seed, trial, world.robot_count());
    return run_team(world, team, algorithm, limit, observer);
  }
  case Algorithm::PrimaryMovement: {
    PrimaryMovement team(world.robot_count());
    return run_team(world, team, algorithm, limit, observer);
  }
  case Algorithm::AStar:
  case Algorithm::CoordinatedAStar: {
    AStarCoverage team(seed, trial, world.robot_count(), algorithm == Algorithm::CoordinatedAStar);
    return run_team(world, team, algorithm, limit, observer);
  }
  case Algorithm::Frontier: {
    FrontierCoverage team(seed, trial, world);
    return run_team(world, team, algorithm, limit, observer);
  }
  }
  return {};
}

} // namespace

CoverageResult run_coverage(CoverageWorld& world, Algorithm algorithm, std::uint64_t seed,
                            std::uint64_t trial, std::uint64_t limit) {
  return run_with(world, algorithm, seed, trial, limit, nullptr);
}

CoverageResult run_coverage(CoverageWorld& world, Algorithm algorithm, std::uint64_t seed,
                            std::uint64_t trial, std::uint64_t limit,
                            const TickObserver& observer) {
  return run_with(world, algorithm, seed, trial, limit, observer ? &observer : nullptr);
}

} // namespace antkit::uniform
