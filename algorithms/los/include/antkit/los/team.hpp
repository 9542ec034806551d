#pragma once
// The two-robot model of paper 001 (Section III.A) as a controller contract and a simulated body.
//
// One tick: each robot scans its eight neighbours, the pair tries line of sight, each robot moves
// to one of its eight neighbours (or stays). The observation carries the scans and the line of
// sight at the robots' current cells; the command carries the two moves.
//
// Choices where the paper is silent, documented here:
//   * Robots move to any of the 8 neighbours that is free, diagonals included even past a corner
//     (the paper: "move to any neighbouring cell"; NetLogo turtles do the same). Line of sight is
//     stricter: a line through a diagonal gap between two blocked cells is blocked (the kernel's
//     supercover corner rule).
//   * Unknown cells of a map (ROS) are treated as obstacles: the scan reports them as obstacles,
//     they block moves and line of sight.
//   * The line is blocked "by an obstacle or by another robot on it": with two robots the only
//     robots are the line's own ends, so only obstacles block it.
//   * Robots never share a cell: moves are carried out in the fixed order A then B, and a move into
//     a blocked cell, off the grid, or into the cell the other robot occupies at that moment is
//     refused (the robot stays). The controllers never ask for such a move.
#include <antkit/kernel/grid.hpp>
#include <antkit/los/exploration_map.hpp>
#include <array>
#include <cstdint>
#include <vector>

namespace antkit::los {

inline constexpr std::int8_t kStay = -1;

struct RobotObservation {
  kernel::Cell position{};
  std::array<Sensed, 8> neighbours{}; // kernel::kNeighbours8 order
};

struct TeamObservation {
  std::array<RobotObservation, 2> robots{}; // A (wall follower), B (trouble shooter)
  bool line_of_sight = false;
};

struct TeamCommand {
  std::array<std::int8_t, 2> move{kStay, kStay}; // neighbour index 0..7, or kStay
  bool finished = false; // exploration complete: nothing left that can be observed
};

// The neighbour index of a unit step d (|dx|, |dy| <= 1, not both 0), or -1.
constexpr int direction_of(kernel::Cell d) noexcept {
  for (int k = 0; k < 8; ++k)
    if (kernel::kNeighbours8[static_cast<std::size_t>(k)] == d) return k;
  return -1;
}

// The simulated body: the true map and the two robots on it.
class TwoRobotWorld {
public:
  // a and b must be distinct free cells of `truth` (throws std::invalid_argument otherwise).
  TwoRobotWorld(const kernel::OccupancyGrid& truth, kernel::Cell a, kernel::Cell b);

  [[nodiscard]] TeamObservation observe() const;
  void apply(const TeamCommand& command);

  [[nodiscard]] const kernel::OccupancyGrid& truth() const noexcept { return *truth_; }
  [[nodiscard]] kernel::Cell position(int robot) const noexcept {
    return position_[static_cast<std::size_t>(robot)];
  }
  [[nodiscard]] std::uint64_t moves(int robot) const noexcept {
    return moves_[static_cast<std::size_t>(robot)];
  }
  [[nodiscard]] const std::vector<kernel::Cell>& trajectory(int robot) const noexcept {
    return trajectory_[static_cast<std::size_t>(robot)];
  }
  [[nodiscard]] bool free(kernel::Cell c) const noexcept {
    return truth_->get_or(c, kernel::Occupancy::Blocked) == kernel::Occupancy::Free;
  }

private:
  const kernel::OccupancyGrid* truth_;
  std::array<kernel::Cell, 2> position_;
  std::array<std::uint64_t, 2> moves_{0, 0};
  std::array<std::vector<kernel::Cell>, 2> trajectory_;
};

} // namespace antkit::los
