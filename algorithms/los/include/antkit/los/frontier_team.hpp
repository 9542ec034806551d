#pragma once
// Frontier exploration for the pair on a shared map: the baseline of Sheng et al. (2006) as paper
// 001 compares against it (Section IV), with or without line-of-sight sweeping, and the frontier
// completion of fast wall-follow (step 7), which is the same with sweeping.
//
// Each robot holds a target frontier cell and a shortest path to it through known-free cells
// (antkit::frontier::FrontierPlanner: g = w1 I - w2 D + w3 lambda). Choices where the papers are
// silent:
//   * A robot keeps its target until it is no longer a frontier cell (reached and scanned, or swept
//     by the line of sight) or the next cell of its path is taken; then it plans again. Sheng et
//     al. re-bid when a target is reached; re-planning every tick would let the two robots' choices
//     oscillate.
//   * The robots decide in the fixed order A then B. A never enters B's cell; B never enters the
//     cell A is about to occupy. I excludes the cells within sensor range of the other robot and of
//     its target (the paper's "not in the range of other robots or target cells for other robots").
//   * A robot that has no reachable frontier stays where it is.
#include <antkit/frontier/planner.hpp>
#include <antkit/los/exploration_map.hpp>
#include <antkit/los/team.hpp>
#include <array>
#include <cstddef>
#include <vector>

namespace antkit::los {

class FrontierCompletion {
public:
  FrontierCompletion() = default;
  FrontierCompletion(std::int32_t width, std::int32_t height, frontier::Weights weights);

  // The two moves for robots at `positions` on `map`.
  std::array<std::int8_t, 2> decide(const ExplorationMap& map,
                                    const std::array<kernel::Cell, 2>& positions);
  // The current target of a robot, if it has one.
  [[nodiscard]] bool has_target(int robot) const noexcept {
    return pilots_[static_cast<std::size_t>(robot)].has_target;
  }
  [[nodiscard]] kernel::Cell target(int robot) const noexcept {
    return pilots_[static_cast<std::size_t>(robot)].target;
  }

private:
  struct Pilot {
    bool has_target = false;
    kernel::Cell target{};
    kernel::Cell expected{}; // where the robot should be when it is next asked
    std::vector<kernel::Cell> path;
    std::size_t next = 0;
  };
  frontier::FrontierPlanner planner_;
  std::array<Pilot, 2> pilots_;
};

struct FrontierTeamOptions {
  frontier::Weights weights{};
  bool line_of_sight = true; // sweep the line between the robots each tick (rules 3 and 4)
};

// The baseline as a team controller (DESIGN.md contract).
class FrontierTeam {
public:
  using Observation = TeamObservation;
  using Command = TeamCommand;

  FrontierTeam(std::int32_t width, std::int32_t height, FrontierTeamOptions options = {});
  TeamCommand step(const TeamObservation& observation);

  [[nodiscard]] const ExplorationMap& map() const noexcept { return map_; }
  void clear_changes() noexcept { map_.clear_changes(); }

private:
  FrontierTeamOptions options_;
  ExplorationMap map_;
  FrontierCompletion completion_;
};

} // namespace antkit::los
