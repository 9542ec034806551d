#pragma once
// The shared map of the two robots (paper 001, assumption 6) and the update rules 1-5 of
// Section III.B.
//
//   1. A robot's scan assigns S to its free neighbours.       (F, NLOS -> S)
//   2. A scanned LOS cell becomes S+LOS.                       (LOS -> S+LOS)
//   3. With line of sight between the robots, the cells on the line become LOS (F, NLOS -> LOS) or
//      S+LOS (S -> S+LOS).
//   4. Without line of sight, the F cells on the line become NLOS.
//   5. A scanned obstacle becomes O.                           (F, NLOS -> O)
//
// "The cells on the line" are the kernel's exact supercover of the segment between the two robots'
// cell centres, less the two robot cells (antkit/kernel/raster.hpp).
//
// Choices where the paper is silent:
//   * A scan covers the robot's own cell as well as its eight neighbours: the robot stands on it,
//     so it is free by scanning. A partner robot in a neighbouring cell is seen as a robot (the
//     paper's assumption 1), so its cell is free.
//   * Off-grid cells are the environment's edge (assumption 8); they are never stored.
//   * An observation that contradicts what is known (a known-free cell sensed as an obstacle) is
//     ignored: states only move up, and a static world never produces it.
// The map keeps the frontier set of antkit::frontier in step with the states, and counts the
// explored cells, so neither is ever recomputed by a scan of the whole map.
#include <antkit/frontier/frontier_map.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/los/cell_state.hpp>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace antkit::los {

// What a robot's 360-degree scan reports of one neighbouring cell.
enum class Sensed : std::uint8_t { Free = 0, Obstacle = 1, Robot = 2, Outside = 3 };

// One state change, as the rules made it: the cell's row-major index and its new state.
struct Change {
  std::uint32_t index;
  CellState state;
};

class ExplorationMap {
public:
  ExplorationMap() = default;
  ExplorationMap(std::int32_t width, std::int32_t height);

  [[nodiscard]] std::int32_t width() const noexcept { return states_.width(); }
  [[nodiscard]] std::int32_t height() const noexcept { return states_.height(); }
  [[nodiscard]] bool in_bounds(kernel::Cell c) const noexcept { return states_.in_bounds(c); }
  [[nodiscard]] CellState at(kernel::Cell c) const noexcept { return states_[c]; }
  [[nodiscard]] bool known_free(kernel::Cell c) const noexcept {
    return states_.in_bounds(c) && is_known_free(states_[c]);
  }
  [[nodiscard]] const kernel::Grid<CellState>& states() const noexcept { return states_; }
  [[nodiscard]] const frontier::FrontierMap& frontiers() const noexcept { return frontiers_; }
  [[nodiscard]] std::size_t explored() const noexcept { return explored_; }

  // Rules 1, 2 and 5: the robot at `robot` sensed sensed[k] at robot + kNeighbours8[k].
  void scan(kernel::Cell robot, const std::array<Sensed, 8>& sensed);
  // Rules 3 and 4 for the line between the robots at a and b; `seen` is whether they saw each
  // other. Both a and b must be in the grid.
  void sweep_line(kernel::Cell a, kernel::Cell b, bool seen);

  // The changes since the last clear_changes(), in the order the rules made them.
  [[nodiscard]] const std::vector<Change>& changes() const noexcept { return changes_; }
  void clear_changes() noexcept { changes_.clear(); }

private:
  void raise(kernel::Cell c, CellState to);
  void scanned_free(kernel::Cell c);

  kernel::Grid<CellState> states_;
  frontier::FrontierMap frontiers_;
  std::size_t explored_ = 0;
  std::vector<Change> changes_;
};

} // namespace antkit::los
