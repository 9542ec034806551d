#include <antkit/los/frontier_team.hpp>

namespace antkit::los {

using kernel::Cell;

FrontierCompletion::FrontierCompletion(std::int32_t width, std::int32_t height,
                                       frontier::Weights weights)
    : planner_(width, height, weights, 1) {}

std::array<std::int8_t, 2> FrontierCompletion::decide(const ExplorationMap& map,
                                                      const std::array<Cell, 2>& positions) {
  std::array<std::int8_t, 2> moves{kStay, kStay};
  std::array<Cell, 2> next = positions;
  for (std::size_t r = 0; r < 2; ++r) {
    const std::size_t o = 1 - r;
    // A (deciding first) must not enter B's cell; B must not enter the cell A moves into.
    const Cell taken = r == 0 ? positions[1] : next[0];
    Pilot& p = pilots_[r];
    const bool valid = p.has_target && p.expected == positions[r] && p.next < p.path.size() &&
                       map.frontiers().is_frontier(p.target) && p.path[p.next] != taken;
    if (!valid) {
      std::array<Cell, 2> claimed{positions[o], pilots_[o].target};
      const std::size_t n_claimed = pilots_[o].has_target ? 2 : 1;
      const std::array<Cell, 1> blocked{taken};
      const std::array<Cell, 1> partners{positions[o]};
      const frontier::Plan& plan = planner_.plan(map.frontiers(), positions[r], blocked,
                                                 {claimed.data(), n_claimed}, partners);
      p.has_target = plan.found;
      if (plan.found) {
        p.target = plan.target;
        p.path.assign(plan.path.begin(), plan.path.end());
        p.next = 0;
      }
    }
    if (!p.has_target || p.next >= p.path.size()) {
      p.has_target = false;
      continue;
    }
    const Cell step = p.path[p.next++];
    moves[r] = static_cast<std::int8_t>(direction_of(step - positions[r]));
    next[r] = step;
    p.expected = step;
  }
  return moves;
}

FrontierTeam::FrontierTeam(std::int32_t width, std::int32_t height, FrontierTeamOptions options)
    : options_(options), map_(width, height), completion_(width, height, options.weights) {}

TeamCommand FrontierTeam::step(const TeamObservation& obs) {
  for (const auto& robot : obs.robots) map_.scan(robot.position, robot.neighbours);
  if (options_.line_of_sight)
    map_.sweep_line(obs.robots[0].position, obs.robots[1].position, obs.line_of_sight);
  TeamCommand cmd;
  if (map_.frontiers().frontier_count() == 0) {
    cmd.finished = true;
    return cmd;
  }
  cmd.move = completion_.decide(map_, {obs.robots[0].position, obs.robots[1].position});
  return cmd;
}

} // namespace antkit::los
