#include <algorithm>
#include <antkit/frontier/planner.hpp>
#include <array>
#include <cstddef>
#include <cstdlib>
#include <stdexcept>

namespace antkit::frontier {

using kernel::Cell;

namespace {

std::int32_t chebyshev(Cell a, Cell b) {
  return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y));
}

} // namespace

FrontierPlanner::FrontierPlanner(std::int32_t width, std::int32_t height, Weights weights,
                                 std::int32_t sensor_range)
    : weights_(weights), range_(sensor_range), stamp_(width, height, 0), parent_(width, height, 0) {
  if (sensor_range < 0 || sensor_range > 64)
    throw std::invalid_argument("frontier sensor range must be in [0, 64]");
  queue_.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
}

std::int32_t FrontierPlanner::information(const FrontierMap& map, Cell candidate,
                                          std::span<const Cell> claimed) const {
  std::int32_t gain = 0;
  const Knowledge* known = map.knowledge().cells().data();
  const auto width = static_cast<std::size_t>(map.width());
  const std::int32_t y0 = std::max(candidate.y - range_, 0);
  const std::int32_t y1 = std::min(candidate.y + range_, map.height() - 1);
  const std::int32_t x0 = std::max(candidate.x - range_, 0);
  const std::int32_t x1 = std::min(candidate.x + range_, map.width() - 1);
  for (std::int32_t y = y0; y <= y1; ++y)
    for (std::int32_t x = x0; x <= x1; ++x) {
      if (known[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)] !=
          Knowledge::Unexplored)
        continue;
      const Cell c{x, y};
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
  // A zero weight skips its term's work (the default w3 = 0 never measures nearness).
  std::int64_t g = -weights_.distance * distance;
  if (weights_.information != 0) g += weights_.information * information(map, candidate, claimed);
  if (weights_.nearness != 0) g += weights_.nearness * nearness(candidate, partners);
  return g;
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
  // A frontier cell is itself free, so at most footprint - 1 cells around it are unexplored.
  const std::int64_t footprint = (2 * std::int64_t{range_} + 1) * (2 * std::int64_t{range_} + 1);
  const std::int64_t max_information = footprint - 1;
  const bool can_stop_early =
      weights_.distance > 0 && weights_.information >= 0 && weights_.nearness >= 0;

  // The search walks row-major indices; cells away from the edge need no bounds checks.
  const std::int32_t w = map.width(), h = map.height();
  const auto width = static_cast<std::ptrdiff_t>(w);
  std::array<std::ptrdiff_t, 8> step{};
  for (std::size_t k = 0; k < 8; ++k)
    step[k] = kernel::kNeighbours8[k].y * width + kernel::kNeighbours8[k].x;
  const Knowledge* known = map.knowledge().cells().data();
  std::uint32_t* stamp = stamp_.cells().data();
  std::uint8_t* parent = parent_.cells().data();
  const std::uint32_t gen = generation_;
  for (const Cell b : blocked) // never entered: as if already visited
    if (map.in_bounds(b) && b != from) stamp[stamp_.index(b)] = gen;

  queue_.clear();
  const std::size_t start = stamp_.index(from);
  queue_.push_back(from);
  stamp[start] = gen;
  std::size_t head = 0;
  std::int64_t best = 0;
  std::size_t best_index = 0;
  std::int32_t best_depth = 0;
  // Level by level: queue_[level_begin, level_end) holds the cells at distance d.
  std::int32_t d = 0;
  std::size_t level_end = 1;
  while (head < queue_.size()) {
    if (head == level_end) {
      ++d;
      level_end = queue_.size();
      if (plan_.found && can_stop_early &&
          weights_.information * max_information - weights_.distance * d <= best)
        break; // nothing at this distance or beyond can beat the best
    }
    const Cell c = queue_[head++];
    const std::size_t i =
        static_cast<std::size_t>(c.y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(c.x);
    if (d > 0 && map.is_frontier_at(i)) {
      const std::int64_t g = utility(map, c, d, claimed, partners);
      if (!plan_.found || g > best) {
        plan_.found = true;
        best = g;
        best_index = i;
        best_depth = d;
      }
    }
    const bool interior = c.x > 0 && c.y > 0 && c.x < w - 1 && c.y < h - 1;
    for (std::size_t k = 0; k < 8; ++k) {
      std::size_t n = 0;
      if (interior) {
        n = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + step[k]);
      } else {
        const Cell nc = c + kernel::kNeighbours8[k];
        if (!map.in_bounds(nc)) continue;
        n = stamp_.index(nc);
      }
      if (known[n] != Knowledge::Free || stamp[n] == gen) continue;
      stamp[n] = gen;
      parent[n] = static_cast<std::uint8_t>(k);
      queue_.push_back(c + kernel::kNeighbours8[k]);
    }
  }
  if (!plan_.found) return plan_;
  const Cell target = stamp_.cell_at(best_index);
  plan_.target = target;
  plan_.utility = best;
  plan_.distance = best_depth;
  plan_.information = information(map, target, claimed);
  plan_.path.resize(static_cast<std::size_t>(best_depth));
  Cell c = target;
  for (std::int32_t k = best_depth - 1; k >= 0; --k) {
    plan_.path[static_cast<std::size_t>(k)] = c;
    c = c - kernel::kNeighbours8[parent_[c]];
  }
  return plan_;
}

} // namespace antkit::frontier
