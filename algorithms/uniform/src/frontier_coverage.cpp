#include <algorithm>
#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/frontier_coverage.hpp>
#include <array>
#include <bit>
#include <cstdlib>
#include <span>

namespace antkit::uniform {
namespace {

// Floor of a / b for b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

} // namespace

using kernel::Cell;
using kernel::kNeighbours8;

FrontierCoverage::FrontierCoverage(std::uint64_t seed, std::uint64_t trial,
                                   const CoverageWorld& world, frontier::Weights weights)
    : weights_(weights), map_(world.map().width(), world.map().height()),
      stamp_(world.map().width(), world.map().height(), 0),
      parent_(world.map().width(), world.map().height(), 0),
      unseen_(world.map().width(), world.map().height(), 0),
      bound_(world.map().width(), world.map().height(), 0),
      exact_(world.map().width(), world.map().height(), 0),
      bound_cells_(world.footprint().rays().size() + 1),
      bound_slot_(world.map().width(), world.map().height(), 0),
      scan_cursor_(world.footprint().rays().size() + 1, 0),
      scan_search_(world.footprint().rays().size() + 1, 0),
      claimed_(world.map().width(), world.map().height(), 0),
      viewable_(world.map().width(), world.map().height(), 0) {
  if (world.footprint().range() < 1)
    throw kernel::InputError("sensor distance",
                             "the frontier algorithm needs a sensor distance of at "
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
  for (std::size_t k = 0; k < viewable_.size(); ++k)
    viewable_.cells()[k] = world.is_viewable(viewable_.cell_at(k)) ? 1 : 0;
  const std::ptrdiff_t width = world.map().width();
  for (const auto& ray : world.footprint().rays())
    ray_step_.push_back(static_cast<std::ptrdiff_t>(ray.offset.y) * width + ray.offset.x);
}

template <class F>
void FrontierCoverage::for_each_footprint_cell(const CoverageWorld& world, Cell centre,
                                               F&& f) const {
  const auto& map = world.map();
  const std::int32_t r = world.footprint().range();
  const std::ptrdiff_t at = static_cast<std::ptrdiff_t>(centre.y) * map.width() + centre.x;
  if (centre.x >= r && centre.y >= r && centre.x < map.width() - r && centre.y < map.height() - r) {
    for (const std::ptrdiff_t d : ray_step_) f(static_cast<std::uint32_t>(at + d));
    return;
  }
  for (const auto& ray : world.footprint().rays()) {
    const Cell u = centre + ray.offset;
    if (map.in_bounds(u)) f(static_cast<std::uint32_t>(map.index(u)));
  }
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
      // u leaves the unexplored cells: one fewer unseen cell for every Free cell that has u in
      // its footprint, i.e. (the footprint is symmetric) every Free cell of u's footprint. Read
      // before u itself is set, so u is not yet one of them. Their bounds stay bounds (I only
      // falls as cells are viewed) but may no longer be exact; none stays above unseen.
      if (viewable_[u]) {
        const frontier::Knowledge* known = map_.knowledge().cells().data();
        std::uint32_t* unseen = unseen_.cells().data();
        std::uint8_t* exact = exact_.cells().data();
        const std::uint32_t* bound = bound_.cells().data();
        for_each_footprint_cell(world, u, [&](std::uint32_t c) {
          if (known[c] != frontier::Knowledge::Free) return;
          exact[c] = 0;
          if (bound[c] > --unseen[c]) set_bound(c, unseen[c]);
        });
      }
      const bool free = world.is_free(u);
      map_.set(u, free ? frontier::Knowledge::Free : frontier::Knowledge::Occupied);
      if (free) track(world, static_cast<std::uint32_t>(map.index(u)), u);
    }
  }
}

void FrontierCoverage::track(const CoverageWorld& world, std::uint32_t index, Cell c) {
  std::uint32_t n = 0;
  const frontier::Knowledge* known = map_.knowledge().cells().data();
  const std::uint8_t* viewable = viewable_.cells().data();
  for_each_footprint_cell(world, c, [&](std::uint32_t u) {
    n +=
        static_cast<std::uint32_t>(viewable[u] != 0 && known[u] == frontier::Knowledge::Unexplored);
  });
  unseen_.cells()[index] = n;
  bound_.cells()[index] = n;
  exact_.cells()[index] = 0;
  bound_slot_.cells()[index] = static_cast<std::uint32_t>(bound_cells_[n].size());
  bound_cells_[n].push_back(index);
  if (n > bound_top_) bound_top_ = n;
}

void FrontierCoverage::set_bound(std::uint32_t index, std::uint32_t n) {
  std::uint32_t& value = bound_.cells()[index];
  std::uint32_t& slot = bound_slot_.cells()[index];
  auto& list = bound_cells_[value];
  // Out of its list, keeping the list's first `cursor` cells the ones this search has ruled out
  // (none outside a search, or in a list it has not scanned): a cell before the cursor is
  // replaced by the last ruled-out one, whose place the last cell takes.
  std::uint32_t none = 0;
  std::uint32_t& cursor = searching_ && scan_search_[value] == search_ ? scan_cursor_[value] : none;
  const auto move_to = [&](std::uint32_t from, std::uint32_t to) {
    list[to] = list[from];
    bound_slot_.cells()[list[to]] = to;
  };
  const std::uint32_t s = slot;
  if (s < cursor) {
    --cursor;
    move_to(cursor, s);
    move_to(static_cast<std::uint32_t>(list.size() - 1), cursor);
  } else {
    move_to(static_cast<std::uint32_t>(list.size() - 1), s);
  }
  list.pop_back();
  value = n;
  slot = static_cast<std::uint32_t>(bound_cells_[n].size());
  bound_cells_[n].push_back(index);
}

std::int32_t FrontierCoverage::measure(const CoverageWorld& world, std::uint32_t index, Cell c,
                                       bool claims, std::int32_t& claimed_out) {
  std::int32_t all = 0, unclaimed = 0;
  for (const auto& ray : world.footprint().rays()) {
    const Cell u = c + ray.offset;
    if (!world.map().in_bounds(u) || world.is_viewed(u) || !world.is_viewable(u) ||
        !world.in_view(c, u))
      continue;
    ++all;
    if (!(claims && claimed_[u] == claim_generation_)) ++unclaimed;
  }
  claimed_out = unclaimed;
  exact_.cells()[index] = 1;
  if (static_cast<std::uint32_t>(all) != bound_.cells()[index])
    set_bound(index, static_cast<std::uint32_t>(all));
  return all;
}

std::int32_t FrontierCoverage::stamped_information(const CoverageWorld& world, Cell candidate,
                                                   bool claims, std::uint32_t unseen,
                                                   std::int64_t need) const {
  // `possible` bounds the final count: the candidate's unseen cells not yet found wanting. A cell
  // I counts is viewable and not viewed, so unexplored here: one of the unseen ones.
  std::int32_t count = 0;
  auto possible = static_cast<std::int64_t>(unseen);
  for (const auto& ray : world.footprint().rays()) {
    if (possible < need) return count; // cannot reach `need`: the caller only compares
    const Cell u = candidate + ray.offset;
    if (!world.map().in_bounds(u) || !world.is_viewable(u) ||
        map_.at(u) != frontier::Knowledge::Unexplored)
      continue; // not one of the unseen cells, so not counted either
    if (!world.is_viewed(u) && !(claims && claimed_[u] == claim_generation_) &&
        world.in_view(candidate, u))
      ++count;
    else
      --possible;
  }
  return count;
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
  // The largest I any candidate can have: the largest bound of a Free cell (bounds only fall, so
  // the top is lowered lazily).
  while (bound_top_ > 0 && bound_cells_[bound_top_].empty()) --bound_top_;
  const auto max_info = static_cast<std::int64_t>(bound_top_);
  ++search_; // every list's cursor starts at 0 when the search first scans it
  searching_ = true;

  // The claims of the other robots, stamped once: the cells within range of a robot's cell or
  // of its target (what information() tests robot by robot).
  if (claims) {
    if (++claim_generation_ == 0) {
      claimed_.fill(0);
      claim_generation_ = 1;
    }
    auto stamp = [&](Cell centre) {
      for (const auto& ray : world.footprint().rays()) {
        const Cell u = centre + ray.offset;
        if (world.map().in_bounds(u)) claimed_[u] = claim_generation_;
      }
    };
    for (std::size_t j = 0; j < robots_.size(); ++j) {
      if (j == i) continue;
      stamp(world.robot(j).cell);
      if (robots_[j].target) stamp(*robots_[j].target);
    }
  }

  if (++generation_ == 0) { // wrapped: clear the stamps once every 2^32 searches
    stamp_.fill(0);
    generation_ = 1;
  }
  const Cell from = world.robot(i).cell;
  // The search walks cell indices (the neighbour at bearing b is index + step[b]); a cell is
  // turned back into coordinates only when it is a frontier cell to evaluate.
  const auto width = static_cast<std::ptrdiff_t>(world.map().width());
  const std::array<std::ptrdiff_t, 8> step{1,  1 - width, -width, -1 - width,
                                           -1, width - 1, width,  width + 1};
  const std::uint8_t* exits = world.exits().cells().data();
  const std::uint8_t* viewed = world.viewed().cells().data();
  std::uint32_t* stamp = stamp_.cells().data();
  std::uint8_t* parent = parent_.cells().data();
  const std::uint32_t generation = generation_;

  queue_.clear();
  queue_.push_back(static_cast<std::uint32_t>(stamp_.index(from)));
  stamp[queue_.front()] = generation;
  // The other robots' cells are never entered (CoverageWorld::occupant): stamped as if reached.
  for (const Cell p : partners_) stamp_[p] = generation;
  bool found = false;
  Cell best{};
  std::int64_t best_g = 0;
  std::size_t head = 0;
  // The largest bound among the frontier cells of the level about to be expanded (candidates
  // are frontier cells at depth >= 1; the robot's own cell is none).
  std::uint32_t level_bound = 0;
  for (std::int32_t depth = 0; head < queue_.size(); ++depth) {
    if (found && can_stop && w1 * max_info - w2 * depth < best_g) break;
    // The cells not yet expanded are this level's, at depth `depth`, and cells not yet reached,
    // at depth >= depth + 1 and at least their Chebyshev distance from the robot (a move changes
    // each coordinate by at most 1). One of them can beat best_g only with
    // w1 * bound - w2 * depth > best_g (so bound >= k): if none can, stop.
    if (found && can_stop && w1 > 0) {
      const std::int64_t k = std::max<std::int64_t>(1, floor_div(best_g + w2 * depth, w1) + 1);
      // A cell that is no threat now is none later in this search (reached cells stay reached,
      // depth and best_g only grow): each list is scanned once per search, from its cursor.
      // A cell whose bound makes it a threat but is not exact is measured (its bound falls to
      // its I without claims) and looked at again.
      bool threat = w1 * static_cast<std::int64_t>(level_bound) - w2 * depth > best_g;
      for (std::int64_t v = max_info; !threat && v >= k; --v) {
        const auto& list = bound_cells_[static_cast<std::size_t>(v)];
        if (scan_search_[static_cast<std::size_t>(v)] != search_) {
          scan_search_[static_cast<std::size_t>(v)] = search_;
          scan_cursor_[static_cast<std::size_t>(v)] = 0;
        }
        std::uint32_t& cursor = scan_cursor_[static_cast<std::size_t>(v)];
        while (cursor < list.size()) {
          const std::uint32_t at = list[cursor];
          // Reached, another robot's cell, or not a frontier cell (the frontier does not change
          // during a search): no candidate.
          const Cell c = stamp_.cell_at(at);
          const std::int64_t cheb = std::max(std::abs(c.x - from.x), std::abs(c.y - from.y));
          if (stamp[at] == generation || !map_.is_frontier_at(at) ||
              w1 * v - w2 * std::max<std::int64_t>(depth + 1, cheb) <= best_g) {
            ++cursor;
            continue;
          }
          if (exact_.cells()[at] != 0) {
            threat = true;
            break;
          }
          std::int32_t unused = 0;
          measure(world, at, c, false, unused); // moves `at`; list[cursor] is another cell now
        }
      }
      if (!threat) break;
    }
    std::uint32_t next_bound = 0;
    const std::size_t level_end = queue_.size();
    for (; head < level_end; ++head) {
      const std::uint32_t at = queue_[head];
      ++expanded_;
      // Only a Free cell has a bound (0 elsewhere), and one with 0 has I = 0.
      const auto bound = static_cast<std::int64_t>(bound_.cells()[at]);
      if (depth >= 1 && bound != 0 && map_.is_frontier_at(at)) {
        const Cell c = stamp_.cell_at(at);
        bool taken = false;
        for (std::size_t j = 0; j < robots_.size(); ++j)
          if (j != i && robots_[j].target == c) taken = true;
        // A cell that cannot beat the best even with I at its bound is not worth evaluating.
        const bool hopeless = found && can_stop && w1 * bound - w2 * depth <= best_g;
        std::int32_t info = 0;
        std::int64_t near = 0;
        if (!taken && !hopeless) {
          near = frontier::FrontierPlanner::nearness(c, partners);
          if (exact_.cells()[at] == 0) {
            measure(world, at, c, claims, info); // I with the claims, and the bound made exact
          } else if (!claims) {
            info = static_cast<std::int32_t>(bound); // exact: I without claims
          } else {
            // The I that would beat the best: g > best_g <=> I > (best_g + w2 D - w3 lambda) /
            // w1. Below it the exact I does not matter, so the count may stop early.
            const std::int64_t need =
                found && w1 > 0 ? floor_div(best_g + w2 * depth - w3 * near, w1) + 1 : 1;
            info = stamped_information(world, c, claims, unseen_.cells()[at], need);
          }
        }
        if (info > 0) {
          const std::int64_t g = w1 * info - w2 * depth + w3 * near;
          if (!found || g > best_g) {
            found = true;
            best = c;
            best_g = g;
          }
        }
      }
      // passable_step's bits in bearing order, as the loop over b = 0..7 took them.
      for (unsigned bits = exits[at]; bits != 0; bits &= bits - 1) {
        const auto b = static_cast<std::uint8_t>(std::countr_zero(bits));
        const auto n = static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(at) + step[b]);
        if (stamp[n] == generation || viewed[n] == 0) continue;
        stamp[n] = generation;
        parent[n] = b;
        queue_.push_back(n);
        if (bound_.cells()[n] > next_bound && map_.is_frontier_at(n))
          next_bound = bound_.cells()[n];
      }
    }
    level_bound = next_bound;
  }
  searching_ = false;
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
