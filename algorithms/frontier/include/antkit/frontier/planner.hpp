#pragma once
// The target choice of Sheng et al. (2006), as paper 001 (Section IV, eq. 2) states it: a robot
// goes to the frontier cell i of highest utility
//
//     g_i = w1 * I_i - w2 * D_i + w3 * lambda_i
//
//   I_i       information gain: the unexplored cells within the robot's sensor range of i that are
//             not within sensor range of another robot or of another robot's target;
//   D_i       the shortest travelling distance to i (moves through known-free cells, 8-connected,
//             each move costs 1: the paper's step);
//   lambda_i  the nearness measure. The paper only says it keeps the robots close; we take
//             lambda_i = -(Chebyshev distance from i to the nearest partner robot), so that it is
//             larger when nearer and never positive (0 when there is no partner).
//
// Defaults w1 = w2 = 1, w3 = 0 (paper 001: "w1 and w2 are set to 1 as recommended", w3 ignored).
// All arithmetic is 64-bit integer: weights are integers.
//
// Choices where the papers are silent, documented here:
//   * The sensor range is a Chebyshev radius (1: the 3x3 block, the eight neighbours of the paper's
//     360-degree scan). It is a parameter so that other families can use a longer sensor.
//   * The robot's own cell is never a candidate (D = 0 gains nothing: it was scanned on arrival).
//   * Ties in g go to the cell met first by the breadth-first search, which expands neighbours in
//     the kernel's fixed order (E, NE, N, NW, W, SW, S, SE): nearer first, then that order.
//   * Cells in `blocked` (other robots) are never entered, so a plan never collides.
//   * The search stops early once no deeper cell can beat the best utility found: with w2 > 0,
//     w1 >= 0 and w3 >= 0 a cell at distance D has g <= w1 * ((2r+1)^2 - 1) - w2 * D, because I
//     counts unexplored cells of the sensor footprint other than the (free) frontier cell itself,
//     and lambda <= 0. This keeps planning local on large maps without changing the choice.
#include <antkit/frontier/frontier_map.hpp>
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <span>
#include <vector>

namespace antkit::frontier {

struct Weights {
  std::int64_t information = 1; // w1
  std::int64_t distance = 1;    // w2
  std::int64_t nearness = 0;    // w3
};

struct Plan {
  bool found = false;
  kernel::Cell target{};
  std::int64_t utility = 0;
  std::int32_t information = 0;
  std::int32_t distance = 0;
  // The cells to move through, first step first, ending at target (the start is not included).
  std::vector<kernel::Cell> path;
};

class FrontierPlanner {
public:
  FrontierPlanner() = default;
  // Scratch buffers are sized once here, so that planning does not allocate after warm-up.
  FrontierPlanner(std::int32_t width, std::int32_t height, Weights weights = {},
                  std::int32_t sensor_range = 1);

  [[nodiscard]] const Weights& weights() const noexcept { return weights_; }
  [[nodiscard]] std::int32_t sensor_range() const noexcept { return range_; }

  // The frontier cell of highest utility reachable from `from` through Free cells without entering
  // a cell of `blocked`. `claimed`: the centres of the sensor footprints that others already cover
  // (other robots' positions and targets); `partners`: the robots lambda is measured to.
  // The returned reference stays valid until the next call.
  const Plan& plan(const FrontierMap& map, kernel::Cell from, std::span<const kernel::Cell> blocked,
                   std::span<const kernel::Cell> claimed, std::span<const kernel::Cell> partners);

  // I_i of the definition above.
  [[nodiscard]] std::int32_t information(const FrontierMap& map, kernel::Cell candidate,
                                         std::span<const kernel::Cell> claimed) const;
  // lambda_i of the definition above.
  [[nodiscard]] static std::int64_t nearness(kernel::Cell candidate,
                                             std::span<const kernel::Cell> partners);
  // g_i.
  [[nodiscard]] std::int64_t utility(const FrontierMap& map, kernel::Cell candidate,
                                     std::int32_t distance, std::span<const kernel::Cell> claimed,
                                     std::span<const kernel::Cell> partners) const;

private:
  Weights weights_{};
  std::int32_t range_ = 1;
  kernel::Grid<std::uint32_t> stamp_; // == generation_: visited in the current search
  kernel::Grid<std::uint8_t> parent_; // the neighbour index of the move that reached the cell
  std::uint32_t generation_ = 0;
  std::vector<kernel::Cell> queue_;
  Plan plan_;
};

} // namespace antkit::frontier
