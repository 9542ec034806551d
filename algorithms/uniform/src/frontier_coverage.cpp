#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/frontier_coverage.hpp>
#include <span>

namespace antkit::uniform {

using kernel::Cell;
using kernel::kNeighbours8;

FrontierCoverage::FrontierCoverage(std::uint64_t seed, std::uint64_t trial,
                                   const CoverageWorld& world, frontier::Weights weights)
    : weights_(weights), map_(world.map().width(), world.map().height()),
      stamp_(world.map().width(), world.map().height(), 0),
      parent_(world.map().width(), world.map().height(), 0) {
  if (world.footprint().range() < 1)
    throw kernel::InputError("--sensor", "the frontier algorithm needs a sensor distance of at "
                                         "least 1 cell (with 0 no frontier cell sees a new one)");
  robots_.reserve(world.robot_count());
  for (std::size_t i = 0; i < world.robot_count(); ++i)
    robots_.push_back({std::nullopt,
                       {},
                       0,
                       0,
                       kernel::Stream(seed, kStreamExperiment, trial, i,
                                      static_cast<std::uint64_t>(StreamPurpose::Unstick)),
                       std::nullopt});
  queue_.reserve(world.map().size());
  partners_.reserve(world.robot_count());
}

void FrontierCoverage::refresh(const CoverageWorld& world) {
  // Cells are viewed only from where a robot stands, and a robot's cell changes only in its own
  // turn; this runs before every turn, so reading the footprint of each robot that has moved
  // since the last look records every newly viewed cell, without scanning the map.
  const auto& map = world.map();
  for (std::size_t j = 0; j < robots_.size(); ++j) {
    const Cell at = world.robot(j).cell;
    if (robots_[j].seen_from == at) continue;
    robots_[j].seen_from = at;
    for (const auto& ray : world.footprint().rays()) {
      const Cell u = at + ray.offset;
      if (!map.in_bounds(u) || !world.is_viewed(u) || map_.at(u) != frontier::Knowledge::Unexplored)
        continue;
      map_.set(u, world.is_free(u) ? frontier::Knowledge::Free : frontier::Knowledge::Occupied);
    }
  }
}

std::int32_t FrontierCoverage::information(const CoverageWorld& world, std::size_t robot,
                                           Cell candidate, bool claims) const {
  const auto& fp = world.footprint();
  std::int32_t count = 0;
  for (const auto& ray : fp.rays()) {
    const Cell u = candidate + ray.offset;
    if (!world.map().in_bounds(u) || world.is_viewed(u) || !world.is_viewable(u)) continue;
    bool claimed = false;
    if (claims)
      for (std::size_t j = 0; j < robots_.size() && !claimed; ++j) {
        if (j == robot) continue;
        claimed = fp.in_range(u - world.robot(j).cell) ||
                  (robots_[j].target && fp.in_range(u - *robots_[j].target));
      }
    // Line of sight last: it is the dearest test (a scan of the ray's cells).
    if (!claimed && world.in_view(candidate, u)) ++count;
  }
  return count;
}

bool FrontierCoverage::plan(std::size_t i, const CoverageWorld& world, bool claims) {
  Robot& r = robots_[i];
  ++plans_;
  r.target.reset();
  r.path.clear();
  r.next = 0;
  partners_.clear();
  for (std::size_t j = 0; j < robots_.size(); ++j)
    if (j != i) partners_.push_back(world.robot(j).cell);
  const std::span<const Cell> partners(partners_);
  const std::int64_t w1 = weights_.information, w2 = weights_.distance, w3 = weights_.nearness;
  // The bound that lets the search stop early (see the header); only valid for these signs.
  const bool can_stop = w2 > 0 && w1 >= 0 && w3 >= 0;
  const auto max_info = static_cast<std::int64_t>(world.footprint().rays().size()) - 1;

  if (++generation_ == 0) { // wrapped: clear the stamps once every 2^32 searches
    stamp_.fill(0);
    generation_ = 1;
  }
  const Cell from = world.robot(i).cell;
  queue_.clear();
  queue_.push_back(from);
  stamp_[from] = generation_;
  bool found = false;
  Cell best{};
  std::int64_t best_g = 0;
  std::size_t head = 0;
  for (std::int32_t depth = 0; head < queue_.size(); ++depth) {
    if (found && can_stop && w1 * max_info - w2 * depth < best_g) break;
    const std::size_t level_end = queue_.size();
    for (; head < level_end; ++head) {
      const Cell c = queue_[head];
      ++expanded_;
      if (depth >= 1 && map_.is_frontier(c)) {
        bool taken = false;
        for (std::size_t j = 0; j < robots_.size(); ++j)
          if (j != i && robots_[j].target == c) taken = true;
        // A cell that cannot beat the best even with the largest I is not worth evaluating.
        const bool hopeless = found && can_stop && w1 * max_info - w2 * depth <= best_g;
        const std::int32_t info = taken || hopeless ? 0 : information(world, i, c, claims);
        if (info > 0) {
          const std::int64_t g =
              w1 * info - w2 * depth + w3 * frontier::FrontierPlanner::nearness(c, partners);
          if (!found || g > best_g) {
            found = true;
            best = c;
            best_g = g;
          }
        }
      }
      for (std::uint8_t b = 0; b < 8; ++b) {
        if (!world.passable_step(c, b)) continue;
        const Cell n = c + kNeighbours8[b];
        if (stamp_[n] == generation_ || !world.is_viewed(n) || world.occupant(n) != 0) continue;
        stamp_[n] = generation_;
        parent_[n] = b;
        queue_.push_back(n);
      }
    }
  }
  if (!found) return false;
  for (Cell c = best; c != from;) {
    const std::uint8_t b = parent_[c];
    r.path.push_back(b);
    c = c - kNeighbours8[b];
  }
  for (std::size_t a = 0, z = r.path.size(); a + 1 < z; ++a, --z)
    std::swap(r.path[a], r.path[z - 1]);
  r.target = best;
  return true;
}

Command FrontierCoverage::step(const Observation& obs) {
  const CoverageWorld& world = *obs.world;
  const std::size_t i = obs.robot;
  refresh(world);
  if (world.complete()) return {Action::Stop};
  Robot& r = robots_[i];
  const Cell at = world.robot(i).cell;
  if (r.target && information(world, i, *r.target, false) == 0) r.target.reset();
  if (r.target && r.next < r.path.size() && world.can_step(at, r.path[r.next])) {
    r.waited = 0;
    return {Action::Step, r.path[r.next++]};
  }
  // No target, path used up, or the way is held by a robot: search again around the robots.
  if ((plan(i, world, true) || plan(i, world, false)) && !r.path.empty()) {
    r.waited = 0;
    return {Action::Step, r.path[r.next++]};
  }
  r.target.reset();
  r.path.clear();
  r.next = 0;
  if (++r.waited < kPatience) return {Action::Wait};
  // Boxed in by the others: step aside at random and search again next tick.
  r.waited = 0;
  const auto aside = random_step_aside(world, at, r.unstick);
  if (!aside) return {Action::Wait};
  ++unsticks_;
  return {Action::Step, *aside};
}

} // namespace antkit::uniform
