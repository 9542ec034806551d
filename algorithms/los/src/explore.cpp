#include <algorithm>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/los/explore.hpp>
#include <antkit/los/fast_wall_follow.hpp>
#include <antkit/los/frontier_team.hpp>
#include <cstdlib>
#include <stdexcept>
#include <variant>

namespace antkit::los {

using kernel::Cell;
using kernel::Occupancy;
using kernel::OccupancyGrid;

namespace {

std::int32_t chebyshev(Cell a, Cell b) {
  return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y));
}

bool is_free(const OccupancyGrid& g, Cell c) {
  return g.get_or(c, Occupancy::Blocked) == Occupancy::Free;
}

template <class Controller>
ExploreResult run(Controller& ctrl, const OccupancyGrid& truth, Cell a, Cell b,
                  const ExploreOptions& options, const TickHook& hook) {
  TwoRobotWorld world(truth, a, b);
  kernel::TraceHash hash;
  const std::uint64_t max_ticks = options.max_ticks != 0
                                      ? options.max_ticks
                                      : 8 * static_cast<std::uint64_t>(truth.size()) + 1024;
  ExploreResult r;
  for (std::uint64_t tick = 0;; ++tick) {
    const TeamObservation obs = world.observe();
    ctrl.clear_changes();
    const TeamCommand cmd = ctrl.step(obs);
    hash.add_u32(static_cast<std::uint32_t>(tick));
    for (const auto& robot : obs.robots) hash.add_i32(robot.position.x).add_i32(robot.position.y);
    hash.add_bool(obs.line_of_sight);
    const auto& changes = ctrl.map().changes();
    hash.add_u32(static_cast<std::uint32_t>(changes.size()));
    for (const Change& c : changes)
      hash.add_u32(c.index).add_u8(static_cast<std::uint8_t>(c.state));
    hash.add_i8(cmd.move[0]).add_i8(cmd.move[1]).add_bool(cmd.finished);
    if (hook) hook(world, ctrl.map(), obs, cmd);
    if (cmd.finished) {
      r.completed = true;
      break;
    }
    if (tick >= max_ticks) break;
    world.apply(cmd);
    ++r.steps;
  }
  r.moves = {world.moves(0), world.moves(1)};
  r.eme = r.moves[0] + r.moves[1];
  r.explored = ctrl.map().explored();
  const auto observable = observable_cells(truth, a, b);
  r.observable = static_cast<std::size_t>(
      std::count(observable.cells().begin(), observable.cells().end(), std::uint8_t{1}));
  r.unobservable = truth.size() - r.observable;
  r.cells = ctrl.map().states();
  r.hash = hash.finish();
  r.trajectories = {world.trajectory(0), world.trajectory(1)};
  return r;
}

} // namespace

ExploreResult explore(const OccupancyGrid& truth, Cell a, Cell b, const ExploreOptions& options,
                      const TickHook& hook) {
  if (options.algorithm == Algorithm::Frontier) {
    FrontierTeam ctrl(truth.width(), truth.height(), {options.weights, options.line_of_sight});
    return run(ctrl, truth, a, b, options, hook);
  }
  FastWallFollow ctrl(truth.width(), truth.height(), {options.weights});
  ExploreResult r = run(ctrl, truth, a, b, options, hook);
  r.sight_losses = ctrl.sight_losses();
  r.causes_found = ctrl.causes_found();
  r.meetings = ctrl.meetings();
  r.wall_stage_ticks = ctrl.wall_stage_ticks();
  return r;
}

Cell default_start(const OccupancyGrid& truth) {
  const Cell corner{0, truth.height() - 1};
  bool found = false;
  Cell best{};
  std::int64_t best_d = 0;
  for (std::int32_t y = truth.height() - 1; y >= 0; --y)
    for (std::int32_t x = 0; x < truth.width(); ++x) {
      const Cell c{x, y};
      if (!is_free(truth, c)) continue;
      const std::int64_t dx = c.x - corner.x, dy = c.y - corner.y;
      const std::int64_t d = dx * dx + dy * dy;
      if (found && d >= best_d) continue; // rows from the bottom, x ascending: ties keep the first
      bool has_neighbour = false;
      for (const Cell n : kernel::kNeighbours8)
        has_neighbour = has_neighbour || is_free(truth, c + n);
      if (!has_neighbour) continue;
      found = true;
      best = c;
      best_d = d;
    }
  if (!found) throw std::invalid_argument("the map has no two neighbouring free cells to start on");
  return best;
}

std::array<Cell, 2> start_pair(const OccupancyGrid& truth, Cell start) {
  if (!truth.in_bounds(start)) throw std::invalid_argument("the start cell is outside the map");
  if (!is_free(truth, start)) throw std::invalid_argument("the start cell is not free");
  for (const Cell d : kernel::kNeighbours4)
    if (is_free(truth, start + d)) return {start, start + d};
  for (const std::size_t k : {1u, 3u, 5u, 7u})
    if (is_free(truth, start + kernel::kNeighbours8[k]))
      return {start, start + kernel::kNeighbours8[k]};
  throw std::invalid_argument("the start cell has no free neighbour for the second robot");
}

kernel::Grid<std::uint8_t> observable_cells(const OccupancyGrid& truth, Cell a, Cell b) {
  kernel::Grid<std::uint8_t> reach(truth.width(), truth.height(), 0);
  kernel::Grid<std::uint8_t> seen(truth.width(), truth.height(), 0);
  std::vector<Cell> queue;
  for (const Cell s : {a, b})
    if (is_free(truth, s) && !reach[s]) {
      reach[s] = 1;
      queue.push_back(s);
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const Cell c = queue[head];
    seen[c] = 1;
    for (const Cell d : kernel::kNeighbours8) {
      const Cell n = c + d;
      if (!truth.in_bounds(n)) continue;
      seen[n] = 1;
      if (truth[n] == Occupancy::Free && !reach[n]) {
        reach[n] = 1;
        queue.push_back(n);
      }
    }
  }
  return seen;
}

OccupancyGrid scattered_obstacles(std::int32_t width, std::int32_t height, std::int32_t k,
                                  std::uint64_t seed, std::uint64_t trial, Cell keep_free) {
  OccupancyGrid g(width, height, Occupancy::Free);
  std::int64_t room = 0;
  for (std::int32_t y = 0; y < height; ++y)
    for (std::int32_t x = 0; x < width; ++x) room += chebyshev({x, y}, keep_free) > 1 ? 1 : 0;
  if (k < 0 || k > room)
    throw std::invalid_argument("cannot place " + std::to_string(k) + " obstacles in a " +
                                std::to_string(width) + "x" + std::to_string(height) + " grid");
  kernel::Stream stream(seed, kExperiment, trial, 0, 1);
  for (std::int32_t placed = 0; placed < k;) {
    const Cell c{static_cast<std::int32_t>(stream.below(static_cast<std::uint32_t>(width))),
                 static_cast<std::int32_t>(stream.below(static_cast<std::uint32_t>(height)))};
    if (g[c] == Occupancy::Blocked || chebyshev(c, keep_free) <= 1) continue;
    g[c] = Occupancy::Blocked;
    ++placed;
  }
  return g;
}

OccupancyGrid obstacle_blocks(std::int32_t width, std::int32_t height, std::int32_t k,
                              std::uint64_t seed, std::uint64_t trial, Cell keep_free) {
  if (k < 0) throw std::invalid_argument("the number of blocks must not be negative");
  OccupancyGrid g(width, height, Occupancy::Free);
  kernel::Stream stream(seed, kExperiment, trial, 0, 2);
  constexpr int kAttempts = 100000;
  int attempts = 0;
  for (std::int32_t placed = 0; placed < k;) {
    if (++attempts > kAttempts)
      throw std::invalid_argument("cannot place " + std::to_string(k) + " blocks of six in a " +
                                  std::to_string(width) + "x" + std::to_string(height) + " grid");
    const bool wide = stream.chance(1, 2);
    const std::int32_t bw = wide ? 3 : 2, bh = wide ? 2 : 3;
    // An island: one free cell at least between the block and the edge.
    if (width < bw + 2 || height < bh + 2) continue;
    const std::int32_t x0 =
        1 + static_cast<std::int32_t>(stream.below(static_cast<std::uint32_t>(width - bw - 1)));
    const std::int32_t y0 =
        1 + static_cast<std::int32_t>(stream.below(static_cast<std::uint32_t>(height - bh - 1)));
    bool fits = true;
    for (std::int32_t y = y0 - 1; y <= y0 + bh && fits; ++y)
      for (std::int32_t x = x0 - 1; x <= x0 + bw && fits; ++x) {
        const Cell c{x, y};
        const bool inside = x >= x0 && x < x0 + bw && y >= y0 && y < y0 + bh;
        if (g.in_bounds(c) && g[c] == Occupancy::Blocked) fits = false; // touches another block
        if (inside && chebyshev(c, keep_free) <= 1) fits = false;
      }
    if (!fits) continue;
    for (std::int32_t y = y0; y < y0 + bh; ++y)
      for (std::int32_t x = x0; x < x0 + bw; ++x) g[{x, y}] = Occupancy::Blocked;
    ++placed;
  }
  return g;
}

} // namespace antkit::los
