#include <algorithm>
#include <antkit/testing/los.hpp>
#include <cstdlib>
#include <string>

namespace antkit::testing {

using kernel::Cell;
using los::CellState;

namespace {
std::string at(Cell c) {
  return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
}
} // namespace

std::string check_sound(const kernel::OccupancyGrid& truth, const kernel::Grid<CellState>& states) {
  if (truth.width() != states.width() || truth.height() != states.height())
    return "the map and the states differ in size";
  for (std::size_t i = 0; i < states.size(); ++i) {
    const Cell c = states.cell_at(i);
    const CellState s = states.cells()[i];
    const bool free = truth.cells()[i] == kernel::Occupancy::Free;
    if (los::is_known_free(s) && !free)
      return std::string("cell ") + at(c) + " is marked " + los::code(s) + " but is not free";
    if (s == CellState::O && free) return "cell " + at(c) + " is marked O but is free";
  }
  return {};
}

std::string check_monotone(const kernel::Grid<CellState>& before,
                           const kernel::Grid<CellState>& after) {
  for (std::size_t i = 0; i < before.size(); ++i) {
    const CellState from = before.cells()[i], to = after.cells()[i];
    if (!los::at_or_below(from, to))
      return "cell " + at(before.cell_at(i)) + " moved down or sideways: " + los::code(from) +
             " -> " + los::code(to);
    if (to == CellState::NLOS && from != CellState::NLOS && from != CellState::F)
      return "cell " + at(before.cell_at(i)) + " was given NLOS from " + los::code(from);
  }
  return {};
}

std::string check_frontier_set(const frontier::FrontierMap& map) {
  std::size_t count = 0;
  for (std::int32_t y = 0; y < map.height(); ++y)
    for (std::int32_t x = 0; x < map.width(); ++x) {
      const Cell c{x, y};
      if (map.is_frontier(c) != map.frontier_by_definition(c))
        return "cell " + at(c) +
               (map.is_frontier(c) ? " is in the frontier set but is not one"
                                   : " is a frontier but not in the set");
      count += map.is_frontier(c) ? 1u : 0u;
    }
  if (count != map.frontier_count()) return "the frontier count does not match the cells";
  auto list = map.frontiers();
  std::sort(list.begin(), list.end());
  if (std::adjacent_find(list.begin(), list.end()) != list.end())
    return "a cell is listed twice in the frontier list";
  for (const Cell c : list)
    if (!map.is_frontier(c)) return "listed cell " + at(c) + " is not a frontier";
  return {};
}

std::string check_complete(const kernel::OccupancyGrid& truth, const los::ExploreResult& r) {
  if (!r.completed) return "the run did not finish";
  const Cell a = r.trajectories[0].front(), b = r.trajectories[1].front();
  const auto observable = los::observable_cells(truth, a, b);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const bool explored = los::is_explored(r.cells.cells()[i]);
    if (observable.cells()[i] && !explored)
      return "observable cell " + at(truth.cell_at(i)) + " was left unexplored";
    if (!observable.cells()[i] && explored)
      return "unobservable cell " + at(truth.cell_at(i)) + " is marked explored";
  }
  if (r.explored != r.observable) return "explored count differs from the observable count";
  if (r.eme != r.moves[0] + r.moves[1]) return "eme is not the sum of the moves";
  if (r.trajectories[0].size() != r.moves[0] + 1 || r.trajectories[1].size() != r.moves[1] + 1)
    return "a trajectory does not match the moves counted";
  return {};
}

std::string check_run(const kernel::OccupancyGrid& truth, Cell a, Cell b,
                      const los::ExploreOptions& options, los::ExploreResult* out) {
  std::string error;
  kernel::Grid<CellState> before(truth.width(), truth.height(), CellState::F);
  std::array<Cell, 2> last{a, b};
  auto hook = [&](const los::TwoRobotWorld& world, const los::ExplorationMap& map,
                  const los::TeamObservation& obs, const los::TeamCommand&) {
    if (!error.empty()) return;
    for (int r = 0; r < 2; ++r) {
      const Cell p = obs.robots[static_cast<std::size_t>(r)].position;
      if (!world.free(p)) error = "robot on a cell that is not free: " + at(p);
      const Cell d = p - last[static_cast<std::size_t>(r)];
      if (std::abs(d.x) > 1 || std::abs(d.y) > 1) error = "robot jumped to " + at(p);
      last[static_cast<std::size_t>(r)] = p;
    }
    if (obs.robots[0].position == obs.robots[1].position) error = "the robots share a cell";
    if (error.empty()) error = check_sound(truth, map.states());
    if (error.empty()) error = check_monotone(before, map.states());
    if (error.empty()) error = check_frontier_set(map.frontiers());
    before = map.states();
  };
  los::ExploreResult r = los::explore(truth, a, b, options, hook);
  if (error.empty()) error = check_complete(truth, r);
  if (out) *out = std::move(r);
  return error;
}

} // namespace antkit::testing
