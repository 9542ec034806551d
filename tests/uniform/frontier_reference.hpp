#pragma once
// The frontier coverage controller as it was before its search was made fast (issue 31): every
// frontier cell's I computed robot by robot, and the search bounded only by the footprint size.
// It is the oracle the shipped FrontierCoverage must agree with, command for command
// (test_frontier_speed.cpp); it is slow (65 times A* on the 256 x 256 benchmark) and is kept only
// here.
#include <antkit/frontier/frontier_map.hpp>
#include <antkit/frontier/planner.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/uniform/controllers.hpp>
#include <antkit/uniform/frontier_coverage.hpp>
#include <antkit/uniform/world.hpp>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace antkit::uniform::testing {

class FrontierReference {
public:
  FrontierReference(std::uint64_t seed, std::uint64_t trial, const CoverageWorld& world,
                    frontier::Weights weights = {})
      : weights_(weights), map_(world.map().width(), world.map().height()),
        stamp_(world.map().width(), world.map().height(), 0),
        parent_(world.map().width(), world.map().height(), 0) {
    for (std::size_t i = 0; i < world.robot_count(); ++i)
      robots_.push_back({std::nullopt,
                         {},
                         0,
                         0,
                         kernel::Stream(seed, kStreamExperiment, trial, i,
                                        static_cast<std::uint64_t>(StreamPurpose::Unstick)),
                         std::nullopt});
  }

  Command step(const Observation& obs) {
    const CoverageWorld& world = *obs.world;
    const std::size_t i = obs.robot;
    refresh(world);
    if (world.complete()) return {Action::Stop};
    Robot& r = robots_[i];
    const kernel::Cell at = world.robot(i).cell;
    if (r.target && information(world, i, *r.target, false) == 0) r.target.reset();
    if (r.target && r.next < r.path.size() && world.can_step(at, r.path[r.next])) {
      r.waited = 0;
      return {Action::Step, r.path[r.next++]};
    }
    if ((plan(i, world, true) || plan(i, world, false)) && !r.path.empty()) {
      r.waited = 0;
      return {Action::Step, r.path[r.next++]};
    }
    r.target.reset();
    r.path.clear();
    r.next = 0;
    if (++r.waited < FrontierCoverage::kPatience) return {Action::Wait};
    r.waited = 0;
    const auto aside = random_step_aside(world, at, r.unstick);
    if (!aside) return {Action::Wait};
    return {Action::Step, *aside};
  }

  [[nodiscard]] std::optional<kernel::Cell> target(std::size_t robot) const noexcept {
    return robots_[robot].target;
  }

private:
  struct Robot {
    std::optional<kernel::Cell> target;
    std::vector<std::uint8_t> path;
    std::size_t next = 0;
    std::uint32_t waited = 0;
    kernel::Stream unstick;
    std::optional<kernel::Cell> seen_from;
  };

  void refresh(const CoverageWorld& world) {
    const auto& map = world.map();
    for (std::size_t j = 0; j < robots_.size(); ++j) {
      const kernel::Cell at = world.robot(j).cell;
      if (robots_[j].seen_from == at) continue;
      robots_[j].seen_from = at;
      for (const auto& ray : world.footprint().rays()) {
        const kernel::Cell u = at + ray.offset;
        if (!map.in_bounds(u) || !world.is_viewed(u) ||
            map_.at(u) != frontier::Knowledge::Unexplored)
          continue;
        map_.set(u, world.is_free(u) ? frontier::Knowledge::Free : frontier::Knowledge::Occupied);
      }
    }
  }

  std::int32_t information(const CoverageWorld& world, std::size_t robot, kernel::Cell candidate,
                           bool claims) const {
    const auto& fp = world.footprint();
    std::int32_t count = 0;
    for (const auto& ray : fp.rays()) {
      const kernel::Cell u = candidate + ray.offset;
      if (!world.map().in_bounds(u) || world.is_viewed(u) || !world.is_viewable(u)) continue;
      bool claimed = false;
      if (claims)
        for (std::size_t j = 0; j < robots_.size() && !claimed; ++j) {
          if (j == robot) continue;
          claimed = fp.in_range(u - world.robot(j).cell) ||
                    (robots_[j].target && fp.in_range(u - *robots_[j].target));
        }
      if (!claimed && world.in_view(candidate, u)) ++count;
    }
    return count;
  }

  bool plan(std::size_t i, const CoverageWorld& world, bool claims) {
    Robot& r = robots_[i];
    r.target.reset();
    r.path.clear();
    r.next = 0;
    std::vector<kernel::Cell> partners;
    for (std::size_t j = 0; j < robots_.size(); ++j)
      if (j != i) partners.push_back(world.robot(j).cell);
    const std::int64_t w1 = weights_.information, w2 = weights_.distance, w3 = weights_.nearness;
    const bool can_stop = w2 > 0 && w1 >= 0 && w3 >= 0;
    const auto max_info = static_cast<std::int64_t>(world.footprint().rays().size()) - 1;
    ++generation_;
    const kernel::Cell from = world.robot(i).cell;
    std::vector<kernel::Cell> queue{from};
    stamp_[from] = generation_;
    bool found = false;
    kernel::Cell best{};
    std::int64_t best_g = 0;
    std::size_t head = 0;
    for (std::int32_t depth = 0; head < queue.size(); ++depth) {
      if (found && can_stop && w1 * max_info - w2 * depth < best_g) break;
      const std::size_t level_end = queue.size();
      for (; head < level_end; ++head) {
        const kernel::Cell c = queue[head];
        if (depth >= 1 && map_.is_frontier(c)) {
          bool taken = false;
          for (std::size_t j = 0; j < robots_.size(); ++j)
            if (j != i && robots_[j].target == c) taken = true;
          const bool hopeless = found && can_stop && w1 * max_info - w2 * depth <= best_g;
          const std::int32_t info = taken || hopeless ? 0 : information(world, i, c, claims);
          if (info > 0) {
            const std::int64_t g = w1 * info - w2 * depth +
                                   w3 * frontier::FrontierPlanner::nearness(
                                            c, std::span<const kernel::Cell>(partners));
            if (!found || g > best_g) {
              found = true;
              best = c;
              best_g = g;
            }
          }
        }
        for (std::uint8_t b = 0; b < 8; ++b) {
          if (!world.passable_step(c, b)) continue;
          const kernel::Cell n = c + kernel::kNeighbours8[b];
          if (stamp_[n] == generation_ || !world.is_viewed(n) || world.occupant(n) != 0) continue;
          stamp_[n] = generation_;
          parent_[n] = b;
          queue.push_back(n);
        }
      }
    }
    if (!found) return false;
    for (kernel::Cell c = best; c != from;) {
      const std::uint8_t b = parent_[c];
      r.path.push_back(b);
      c = c - kernel::kNeighbours8[b];
    }
    for (std::size_t a = 0, z = r.path.size(); a + 1 < z; ++a, --z)
      std::swap(r.path[a], r.path[z - 1]);
    r.target = best;
    return true;
  }

  frontier::Weights weights_;
  frontier::FrontierMap map_;
  std::vector<Robot> robots_;
  kernel::Grid<std::uint32_t> stamp_;
  kernel::Grid<std::uint8_t> parent_;
  std::uint32_t generation_ = 0;
};

} // namespace antkit::uniform::testing
