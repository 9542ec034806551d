#include <antkit/kernel/raster.hpp>
#include <antkit/los/team.hpp>
#include <stdexcept>

namespace antkit::los {

using kernel::Cell;

TwoRobotWorld::TwoRobotWorld(const kernel::OccupancyGrid& truth, Cell a, Cell b)
    : truth_(&truth), position_{a, b} {
  if (!free(a) || !free(b) || a == b)
    throw std::invalid_argument("the two robots need two distinct free cells");
  trajectory_[0].push_back(a);
  trajectory_[1].push_back(b);
}

TeamObservation TwoRobotWorld::observe() const {
  TeamObservation o;
  for (std::size_t r = 0; r < 2; ++r) {
    o.robots[r].position = position_[r];
    for (std::size_t k = 0; k < kernel::kNeighbours8.size(); ++k) {
      const Cell c = position_[r] + kernel::kNeighbours8[k];
      Sensed s = Sensed::Obstacle;
      if (!truth_->in_bounds(c))
        s = Sensed::Outside;
      else if (c == position_[1 - r])
        s = Sensed::Robot;
      else if ((*truth_)[c] == kernel::Occupancy::Free)
        s = Sensed::Free;
      o.robots[r].neighbours[k] = s;
    }
  }
  o.line_of_sight = kernel::line_of_sight(*truth_, position_[0], position_[1]);
  return o;
}

void TwoRobotWorld::apply(const TeamCommand& command) {
  for (std::size_t r = 0; r < 2; ++r) {
    const std::int8_t k = command.move[r];
    if (k < 0 || k > 7) continue;
    const Cell to = position_[r] + kernel::kNeighbours8[static_cast<std::size_t>(k)];
    if (!free(to) || to == position_[1 - r]) continue; // refused: the robot stays
    position_[r] = to;
    ++moves_[r];
    trajectory_[r].push_back(to);
  }
}

} // namespace antkit::los
