#include <antkit/uniform/controllers.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/coverage_ticks.hpp>
#include <antkit/uniform/frontier_coverage.hpp>

namespace antkit::uniform {

static_assert(static_cast<int>(StopReason::Complete) == static_cast<int>(TickStop::Complete) &&
              static_cast<int>(StopReason::NoMove) == static_cast<int>(TickStop::NoMove) &&
              static_cast<int>(StopReason::TimeLimit) == static_cast<int>(TickStop::TimeLimit));

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

// run_ticks' team over a controller that takes an Observation.
template <class Team>
struct ObservedTeam {
  Team& team;
  const CoverageWorld& world;
  Command command(std::size_t i) { return team.step(Observation{i, &world}); }
};

template <class Team>
CoverageResult run_team(CoverageWorld& world, Team& team, Algorithm algorithm, std::uint64_t limit,
                        const TickObserver* observer) {
  CoverageResult out;
  out.algorithm = algorithm;
  out.robots = world.robot_count();
  ObservedTeam<Team> observed{team, world};
  const TickRun run = run_ticks(world, observed, static_cast<std::uint8_t>(algorithm), limit,
                                [&](std::uint64_t tick) {
                                  if (observer) (*observer)(world, tick);
                                });
  out.movements = run.movements;
  out.moves = run.moves;
  out.stop = static_cast<StopReason>(run.stop);
  out.viewed = world.viewed_free();
  out.viewable = world.viewable();
  out.hash = run.hash;
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
