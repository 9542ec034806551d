#include <algorithm>
#include <antkit/frontier/planner.hpp>
#include <cstdlib>
#include <stdexcept>

namespace antkit::frontier {

using kernel::Cell;

namespace {

std::int32_t chebyshev(Cell a, Cell b) {
  return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y));
}

bool contains(std::span<const Cell> cells, Cell c) {
  return std::find(cells.begin(), cells.end(), c) != cells.end();
}

} // namespace

FrontierPlanner::FrontierPlanner(std::int32_t width, std::int32_t height, Weights weights,
                                 std::int32_t sensor_range)
    : weights_(weights), range_(sensor_range), stamp_(width, height, 0), depth_(width, height, 0),
      parent_(width, height, 0) {
  if (sensor_range < 0 || sensor_range > 64)
    throw std::invalid_argument("frontier sensor range must be in [0, 64]");
  queue_.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
}

std::int32_t FrontierPlanner::information(const FrontierMap& map, Cell candidate,
                                          std::span<const Cell> claimed) const {
  std::int32_t gain = 0;
  for (std::int32_t dy = -range_; dy <= range_; ++dy)
    for (std::int32_t dx = -range_; dx <= range_; ++dx) {
      const Cell c{candidate.x + dx, candidate.y + dy};
      if (!map.is_unexplored(c)) continue;
      bool taken = false;
      for (const Cell o : claimed)
        if (chebyshev(o, c) <= range_) {
          taken = true;
          break;
        }
      if (!taken) ++gain;
    }
  return gain;
}

std::int64_t FrontierPlanner::nearness(Cell candidate, std::span<const Cell> partners) {
  if (partners.empty()) return 0;
  std::int32_t best = chebyshev(candidate, partners.front());
  for (const Cell p : partners) best = std::min(best, chebyshev(candidate, p));
  return -static_cast<std::int64_t>(best);
}

std::int64_t FrontierPlanner::utility(const FrontierMap& map, Cell candidate, std::int32_t distance,
                                      std::span<const Cell> claimed,
                                      std::span<const Cell> partners) const {
  return weights_.information * information(map, candidate, claimed) -
         weights_.distance * distance + weights_.nearness * nearness(candidate, partners);
}

const Plan& FrontierPlanner::plan(const FrontierMap& map, Cell from, std::span<const Cell> blocked,
                                  std::span<const Cell> claimed, std::span<const Cell> partners) {
  plan_.found = false;
  plan_.path.clear();
  if (!map.in_bounds(from) || map.frontier_count() == 0) return plan_;
  if (++generation_ == 0) { // the stamps wrapped: clear them once every 2^32 searches
    stamp_.fill(0);
    generation_ = 1;
  }
  const std::int64_t footprint = (2 * std::int64_t{range_} + 1) * (2 * std::int64_t{range_} + 1);
  const bool can_stop_early =
      weights_.distance > 0 && weights_.information >= 0 && weights_.nearness >= 0;

  queue_.clear();
  queue_.push_back(from);
  stamp_[from] = generation_;
  depth_[from] = 0;
  std::size_t head = 0;
  std::int64_t best = 0;
  Cell best_cell{};
  std::int32_t best_depth = 0;
  while (head < queue_.size()) {
    const Cell c = queue_[head++];
    const std::int32_t d = depth_[c];
    if (plan_.found && can_stop_early &&
        weights_.information * footprint - weights_.distance * d <= best)
      break; // nothing at this depth or deeper can beat the best
    if (d > 0 && map.is_frontier(c)) {
      const std::int64_t g = utility(map, c, d, claimed, partners);
      if (!plan_.found || g > best) {
        plan_.found = true;
        best = g;
        best_cell = c;
        best_depth = d;
      }
    }
    for (std::size_t k = 0; k < kernel::kNeighbours8.size(); ++k) {
      const Cell n = c + kernel::kNeighbours8[k];
      if (!map.is_free(n) || stamp_[n] == generation_ || contains(blocked, n)) continue;
      stamp_[n] = generation_;
      depth_[n] = d + 1;
      parent_[n] = static_cast<std::uint8_t>(k);
      queue_.push_back(n);
    }
  }
  if (!plan_.found) return plan_;
  plan_.target = best_cell;
  plan_.utility = best;
  plan_.distance = best_depth;
  plan_.information = information(map, best_cell, claimed);
  plan_.path.resize(static_cast<std::size_t>(best_depth));
  Cell c = best_cell;
  for (std::int32_t i = best_depth - 1; i >= 0; --i) {
    plan_.path[static_cast<std::size_t>(i)] = c;
    c = c - kernel::kNeighbours8[parent_[c]];
  }
  return plan_;
}

} // namespace antkit::frontier
