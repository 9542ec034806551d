#include <antkit/uniform/controllers.hpp>

namespace antkit::uniform {

using kernel::Cell;

namespace {
kernel::Stream robot_stream(std::uint64_t seed, std::uint64_t trial, std::size_t robot,
                            StreamPurpose purpose) {
  return kernel::Stream(seed, kStreamExperiment, trial, robot, static_cast<std::uint64_t>(purpose));
}
} // namespace

// ---- Random Wanderer ----

RandomWanderer::RandomWanderer(std::uint64_t seed, std::uint64_t trial, std::size_t robots) {
  streams_.reserve(robots);
  for (std::size_t i = 0; i < robots; ++i)
    streams_.push_back(robot_stream(seed, trial, i, StreamPurpose::RandomWanderer));
}

// step_turn.hpp's keys are this family's (it cannot include scenario.hpp's containers).
static_assert(kWandererExperiment == kStreamExperiment);
static_assert(kWandererPurpose == static_cast<std::uint64_t>(StreamPurpose::RandomWanderer));

Command RandomWanderer::step(const Observation& obs) {
  return wander_decide(streams_[obs.robot], [&obs] {
    const Pose& p = obs.world->robot(obs.robot);
    return obs.world->can_step(p.cell, p.bearing);
  });
}

StepTurnWanderer::StepTurnWanderer(std::uint64_t seed, std::uint64_t trial, std::size_t robot)
    : core_(seed, trial, robot) {}

Command StepTurnWanderer::step(const Observation& obs) {
  return core_.step(obs.front_free); // RandomWanderer::step's draw and meaning
}

// ---- Primary Movement ----

PrimaryMovement::PrimaryMovement(std::size_t robots) : turns_(robots, 0) {}

Command PrimaryMovement::step(const Observation& obs) {
  std::uint8_t& turns = turns_[obs.robot];
  if (turns >= 8) { // a full turn without a forward move: cease operation
    turns = 9;
    return {Action::Stop};
  }
  const CoverageWorld& w = *obs.world;
  const Pose& p = w.robot(obs.robot);
  if (w.can_step(p.cell, p.bearing) && w.would_view_new(p.cell + kernel::kNeighbours8[p.bearing])) {
    turns = 0;
    return {Action::Forward};
  }
  ++turns;
  return {Action::TurnLeft};
}

std::optional<std::uint8_t> random_step_aside(const CoverageWorld& world, Cell at,
                                              kernel::Stream& stream) {
  std::uint8_t options[8];
  std::uint32_t count = 0;
  for (std::uint8_t b = 0; b < 8; ++b)
    if (world.can_step(at, b)) options[count++] = b;
  if (count == 0) return std::nullopt;
  return options[stream.below(count)];
}

// ---- A* with spiral iteration ----

AStarCoverage::AStarCoverage(std::uint64_t seed, std::uint64_t trial, std::size_t robots,
                             bool coordinated)
    : coordinated_(coordinated) {
  robots_.reserve(robots);
  for (std::size_t i = 0; i < robots; ++i)
    robots_.push_back(
        {std::nullopt, {}, 0, 0, robot_stream(seed, trial, i, StreamPurpose::Unstick), {}, 0});
}

bool AStarCoverage::choose_goal(std::size_t i, const CoverageWorld& world) {
  Robot& r = robots_[i];
  const Cell at = world.robot(i).cell;
  const std::uint8_t bearing = world.robot(i).bearing;
  const std::uint32_t own = world.component()[at];
  const auto& map = world.map();
  const auto chebyshev = [](Cell a, Cell b) {
    const std::int32_t dx = a.x > b.x ? a.x - b.x : b.x - a.x;
    const std::int32_t dy = a.y > b.y ? a.y - b.y : b.y - a.y;
    return dx > dy ? dx : dy;
  };
  const std::int32_t skip = r.clear_rings - chebyshev(at, r.clear_centre);
  // The ring of the first unviewed cell the scan meets (excluded by coordination or not).
  std::int32_t first_unviewed = -1;
  const auto unexplored = [&](Cell c) {
    ++spiral_cells_;
    if (world.component()[c] != own || world.is_viewed(c)) return false;
    if (first_unviewed < 0) first_unviewed = chebyshev(c, at);
    return true;
  };
  std::optional<Cell> goal;
  if (coordinated_ && robots_.size() > 1) {
    goal = spiral_find(
        at, bearing, map.width(), map.height(),
        [&](Cell c) {
          if (!unexplored(c)) return false;
          for (std::size_t j = 0; j < robots_.size(); ++j)
            if (j != i && robots_[j].goal && world.footprint().in_range(c - *robots_[j].goal))
              return false;
          return true;
        },
        skip);
  }
  if (!goal && coordinated_) {
    // Nothing outside the others' sensor reach of their goals: any cell that is not itself
    // another robot's goal.
    goal = spiral_find(
        at, bearing, map.width(), map.height(),
        [&](Cell c) {
          if (!unexplored(c)) return false;
          for (std::size_t j = 0; j < robots_.size(); ++j)
            if (j != i && robots_[j].goal == c) return false;
          return true;
        },
        skip);
  }
  // Every unviewed cell left is another robot's goal (or this is plain A*): chase the nearest.
  // (A coordinated robot that idled instead could stand in the others' way for good.)
  if (!goal) goal = spiral_find(at, bearing, map.width(), map.height(), unexplored, skip);
  if (first_unviewed >= 0) {
    r.clear_centre = at;
    r.clear_rings = first_unviewed;
  }
  r.goal = goal;
  r.path.clear();
  r.next = 0;
  return goal.has_value();
}

bool AStarCoverage::plan(std::size_t i, const CoverageWorld& world, bool around_robots) {
  Robot& r = robots_[i];
  const Cell goal = *r.goal;
  const std::int32_t range = world.footprint().range();
  ++plans_;
  r.next = 0;
  const auto step_ok = [&](Cell c, std::uint8_t b) {
    return around_robots ? world.can_step(c, b) : world.passable_step(c, b);
  };
  const auto reached = [&](Cell c) { return world.in_view(c, goal); };
  const auto heuristic = [&](Cell c) {
    const std::int32_t dx = c.x > goal.x ? c.x - goal.x : goal.x - c.x;
    const std::int32_t dy = c.y > goal.y ? c.y - goal.y : goal.y - c.y;
    const std::int32_t cheb = dx > dy ? dx : dy;
    return cheb > range ? cheb - range : 0;
  };
  return search_.find(world.map().width(), world.map().height(), world.robot(i).cell,
                      world.robot(i).bearing, step_ok, reached, heuristic, r.path,
                      around_robots ? kDetourBudget : ~std::uint64_t{0});
}

Command AStarCoverage::step(const Observation& obs) {
  const CoverageWorld& world = *obs.world;
  const std::size_t i = obs.robot;
  Robot& r = robots_[i];
  if (r.goal && world.is_viewed(*r.goal)) r.goal.reset();
  if (!r.goal) {
    if (!choose_goal(i, world)) return {Action::Stop}; // nothing left to view
  }
  if (r.next >= r.path.size()) {
    // No path yet (or the last one was abandoned): plan on the map alone.
    if (!plan(i, world, false) || r.path.empty()) {
      // Unreachable cannot happen for a goal in the robot's own component, and an empty path
      // would mean the goal is in view already; either way, drop it and look again next tick.
      r.goal.reset();
      return {Action::Wait};
    }
  }
  const Cell at = world.robot(i).cell;
  if (world.can_step(at, r.path[r.next])) {
    r.waited = 0;
    return {Action::Step, r.path[r.next++]};
  }
  // The way is held by a robot: go round the robots as they stand, if there is a way.
  if (plan(i, world, true) && !r.path.empty()) {
    r.waited = 0;
    return {Action::Step, r.path[r.next++]};
  }
  r.path.clear();
  r.next = 0;
  if (++r.waited < kPatience) return {Action::Wait};
  // A standoff: step aside at random and replan next tick.
  r.waited = 0;
  const auto aside = random_step_aside(world, at, r.unstick);
  if (!aside) return {Action::Wait};
  ++unsticks_;
  return {Action::Step, *aside};
}

} // namespace antkit::uniform
