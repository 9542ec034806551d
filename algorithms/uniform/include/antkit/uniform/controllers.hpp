#pragma once
// The three team controllers of paper 004, and the coordinated A* that goes beyond it. Each is one
// team controller in the sense of DESIGN.md: it is stepped once per robot per tick, in robot index
// order, with an Observation that names the robot and lets it read the shared world (the true map,
// the communal map of viewed cells and every robot's pose), and it answers with one Command.
//
// Random Wanderer (RW): a draw of 0, 1 or 2 from the robot's own keyed stream: 0 turns left 45
// degrees, 2 turns right 45 degrees, 1 moves forward one cell if that cell is free and unoccupied
// (otherwise the robot stays put this tick).
//
// Primary Movement (PM): forward when the cell ahead can be entered and standing there would view
// at least one cell not yet viewed; otherwise turn left 45 degrees. After eight left turns in a row
// (a full turn) without a forward move the robot ceases operation for good.
//
// A* (the paper's "A* path finding"): a robot without a goal takes, by spiral iteration from its
// cell, the first free cell of its own component that has not been viewed, and runs A-Star (see
// planner.hpp) on the true map to the nearest cell from which that goal is in sensor view, then
// walks the path, one cell per tick; the goal is dropped and a new one found once it has been
// viewed, by this robot or any other (chasing a cell that is already viewed buys nothing). In the
// coordinated variant a robot skips every candidate within sensor range of another robot's current
// goal (that robot will view it on arrival) unless nothing else is left, and then every candidate
// that is another robot's goal; only when every unviewed cell of its component is some robot's
// goal does it chase one of those (the nearest) rather than idle, because an idle robot can stand
// in a corridor that the others need for good.
//
// Choices where the paper is silent, for A*:
//   * Paths are planned on the map alone. When the next cell of the path holds a robot, the robot
//     replans at once around the robots as they stand (giving up after kDetourBudget cells); when
//     there is no way round it waits, and
//     after kPatience ticks of waiting it steps to a random enterable neighbour (its own keyed
//     stream, purpose Unstick) and replans next tick. Without that, two robots that need to pass
//     each other in a one-cell corridor would wait for each other for ever.
//   * A step along the path turns the robot to face it for free: A*'s moves are its steps.
#include <antkit/kernel/random.hpp>
#include <antkit/uniform/planner.hpp>
#include <antkit/uniform/step_turn.hpp>
#include <antkit/uniform/world.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace antkit::uniform {

struct Observation {
  std::size_t robot = 0;
  const CoverageWorld* world = nullptr;
};

class RandomWanderer {
public:
  using Observation = uniform::Observation;
  using Command = uniform::Command;
  RandomWanderer(std::uint64_t seed, std::uint64_t trial, std::size_t robots);
  Command step(const Observation& obs);

private:
  std::vector<kernel::Stream> streams_;
};

// The Random Wanderer for one robot that only steps and turns and sees only whether the cell ahead
// is free: a real robot (devices/record_loop.hpp), whose own sensors answer that question, and
// whose body turns a command into a 45-degree turn or a step of one cell. Its draws are
// RandomWanderer's for robot `robot` (the same keyed stream, purpose RandomWanderer), so fed the
// front-free flags the simulated robot would see, it emits the simulated robot's commands.
class StepTurnWanderer {
public:
  struct Observation {
    bool front_free = false;
  };
  using Command = uniform::Command;
  StepTurnWanderer(std::uint64_t seed, std::uint64_t trial, std::size_t robot = 0);
  Command step(const Observation& obs);
  // Draws taken from the stream so far (with the last command, the controller's whole state).
  [[nodiscard]] std::uint64_t steps() const noexcept { return core_.steps(); }

private:
  StepTurnCore core_;
};

class PrimaryMovement {
public:
  using Observation = uniform::Observation;
  using Command = uniform::Command;
  explicit PrimaryMovement(std::size_t robots);
  Command step(const Observation& obs);
  [[nodiscard]] bool ceased(std::size_t robot) const noexcept { return turns_[robot] > 8; }

private:
  std::vector<std::uint8_t> turns_; // left turns since the last forward move; 9 = ceased
};

// Breaking a standoff (A* and frontier): a step to a random enterable neighbour of `at`, drawn from
// the robot's own keyed stream, or no step when every neighbour is closed.
std::optional<std::uint8_t> random_step_aside(const CoverageWorld& world, kernel::Cell at,
                                              kernel::Stream& stream);

class AStarCoverage {
public:
  using Observation = uniform::Observation;
  using Command = uniform::Command;
  static constexpr std::uint32_t kPatience = 3;
  // A replan around the robots gives up after this many cells: a way round that A-Star cannot
  // find within it is treated as no way round (wait), so that a robot boxed in by others does
  // not flood the whole map every tick.
  static constexpr std::uint64_t kDetourBudget = 4096;

  AStarCoverage(std::uint64_t seed, std::uint64_t trial, std::size_t robots, bool coordinated);
  Command step(const Observation& obs);

  [[nodiscard]] std::optional<kernel::Cell> goal(std::size_t robot) const noexcept {
    return robots_[robot].goal;
  }
  // Counters for reports and benchmarks.
  [[nodiscard]] std::uint64_t plans() const noexcept { return plans_; }
  [[nodiscard]] std::uint64_t spiral_cells() const noexcept { return spiral_cells_; }
  [[nodiscard]] std::uint64_t expanded() const noexcept { return search_.expanded(); }
  [[nodiscard]] std::uint64_t unsticks() const noexcept { return unsticks_; }

private:
  struct Robot {
    std::optional<kernel::Cell> goal;
    std::vector<std::uint8_t> path; // bearings of the steps still to take, from path[next]
    std::size_t next = 0;
    std::uint32_t waited = 0;
    kernel::Stream unstick;
    // What the last spiral learned: no unviewed cell of the robot's component lies at Chebyshev
    // distance below clear_rings from clear_centre. Cells never become unviewed again, so this
    // stays true, and a later spiral from c may skip rings below clear_rings - dist(c,
    // clear_centre): the same first hit, found without rescanning the explored disc.
    kernel::Cell clear_centre;
    std::int32_t clear_rings = 0;
  };
  bool choose_goal(std::size_t i, const CoverageWorld& world);
  bool plan(std::size_t i, const CoverageWorld& world, bool around_robots);

  std::vector<Robot> robots_;
  bool coordinated_;
  PathSearch search_;
  std::uint64_t plans_ = 0;
  std::uint64_t spiral_cells_ = 0;
  std::uint64_t unsticks_ = 0;
};

} // namespace antkit::uniform
