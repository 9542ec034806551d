#include <algorithm>
#include <antkit/testing/stc.hpp>
#include <array>
#include <sstream>

namespace antkit::testing {

using kernel::Cell;
using kernel::Occupancy;
using kernel::OccupancyGrid;

namespace {

StcCheck fail(std::string rule, std::int64_t step, Cell at, std::string detail) {
  return {false, std::move(rule), step, at, std::move(detail)};
}

std::string text(Cell c) {
  return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
}

bool adjacent(Cell a, Cell b) { // in 64 bits: a tour read from a file may hold any coordinates
  const std::int64_t dx = std::int64_t{a.x} - b.x, dy = std::int64_t{a.y} - b.y;
  return (dx == 0 && (dy == 1 || dy == -1)) || (dy == 0 && (dx == 1 || dx == -1));
}

// Inside the cell area: odd remainders belong to no cell.
bool in_cell_area(const OccupancyGrid& map, Cell s) {
  return s.x >= 0 && s.y >= 0 && s.x < (map.width() / 2) * 2 && s.y < (map.height() / 2) * 2;
}

bool whole_cell_free(const OccupancyGrid& map, Cell cell) {
  if (cell.x < 0 || cell.y < 0 || cell.x >= map.width() / 2 || cell.y >= map.height() / 2)
    return false;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx)
      if (map[{2 * cell.x + dx, 2 * cell.y + dy}] != Occupancy::Free) return false;
  return true;
}

constexpr std::array<Cell, 4> kSteps{{{1, 0}, {0, -1}, {-1, 0}, {0, 1}}};

} // namespace

std::string StcCheck::describe() const {
  if (ok) return "ok";
  std::ostringstream s;
  s << "invariant " << rule;
  if (step >= 0) s << " broken at step " << step;
  s << ", sub-cell " << text(subcell) << ": " << detail;
  return s.str();
}

std::ostream& operator<<(std::ostream& out, const StcCheck& check) {
  return out << check.describe();
}

std::int64_t StcTourChecker::reachable_cells(const OccupancyGrid& map, Cell start) {
  const std::int32_t cw = map.width() / 2, ch = map.height() / 2;
  mark_.assign(static_cast<std::size_t>(cw) * static_cast<std::size_t>(ch), 0);
  queue_.clear();
  const Cell root{start.x >> 1, start.y >> 1};
  if (!in_cell_area(map, start) || !whole_cell_free(map, root)) return 0;
  auto at = [&](Cell c) -> std::uint8_t& {
    return mark_[static_cast<std::size_t>(c.y) * static_cast<std::size_t>(cw) +
                 static_cast<std::size_t>(c.x)];
  };
  at(root) = 1;
  queue_.push_back(root);
  for (std::size_t i = 0; i < queue_.size(); ++i)
    for (Cell d : kSteps) {
      const Cell n = queue_[i] + d;
      if (whole_cell_free(map, n) && at(n) == 0) {
        at(n) = 1;
        queue_.push_back(n);
      }
    }
  return static_cast<std::int64_t>(queue_.size());
}

std::int64_t StcTourChecker::reachable_subcells(const OccupancyGrid& map, Cell start,
                                                bool whole_cells, std::vector<std::uint8_t>& mask) {
  if (whole_cells) {
    const std::int64_t cells = reachable_cells(map, start); // queue_: the cells
    mask.assign(map.size(), 0);
    for (const Cell c : queue_)
      for (int q = 0; q < 4; ++q) mask[map.index({2 * c.x + (q & 1), 2 * c.y + (q >> 1)})] = 1;
    return 4 * cells;
  }
  mask.assign(map.size(), 0);
  queue_.clear();
  if (in_cell_area(map, start) && map[start] == Occupancy::Free) {
    mask[map.index(start)] = 1;
    queue_.push_back(start);
  }
  for (std::size_t i = 0; i < queue_.size(); ++i)
    for (Cell d : kSteps) {
      const Cell n = queue_[i] + d;
      if (in_cell_area(map, n) && map[n] == Occupancy::Free && mask[map.index(n)] == 0) {
        mask[map.index(n)] = 1;
        queue_.push_back(n);
      }
    }
  return static_cast<std::int64_t>(queue_.size());
}

StcCheck StcTourChecker::check_exact(const OccupancyGrid& map, Cell start,
                                     std::span<const Cell> path) {
  const std::int64_t cells = reachable_cells(map, start); // fills mark_: 1 = reachable cell
  if (path.empty()) return fail("3 return", -1, start, "the path is empty");
  if (path.front() != start)
    return fail("3 return", 0, path.front(), "the tour does not begin at the start " + text(start));
  const std::int32_t cw = map.width() / 2;
  seen_.assign(map.size(), 0);
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Cell s = path[i];
    const auto step = static_cast<std::int64_t>(i);
    if (i > 0 && !adjacent(path[i - 1], s))
      return fail("2 moves", step, s,
                  "not 4-adjacent to the previous position " + text(path[i - 1]));
    if (!in_cell_area(map, s) || map[s] != Occupancy::Free)
      return fail("2 moves", step, s, "not a free sub-cell inside the cell area");
    const Cell cell{s.x >> 1, s.y >> 1};
    if (!whole_cell_free(map, cell))
      return fail("2 moves", step, s, "its cell " + text(cell) + " is not free");
    if (mark_[static_cast<std::size_t>(cell.y) * static_cast<std::size_t>(cw) +
              static_cast<std::size_t>(cell.x)] == 0)
      return fail("1 coverage", step, s,
                  "its cell " + text(cell) + " is not 4-connected to the start cell");
    std::uint8_t& seen = seen_[map.index(s)];
    if (seen != 0) return fail("1 coverage", step, s, "entered a second time");
    seen = 1;
  }
  if (static_cast<std::int64_t>(path.size()) != 4 * cells)
    return fail("4 length", -1, path.back(),
                "the tour has " + std::to_string(path.size()) + " positions, 4 x " +
                    std::to_string(cells) + " reachable free cells = " + std::to_string(4 * cells));
  // Every sub-cell of every reachable cell once: distinct and the count matches, so none is
  // missing; name one anyway if the count check above were ever weakened.
  for (const Cell c : queue_)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const Cell s{2 * c.x + dx, 2 * c.y + dy};
        if (seen_[map.index(s)] == 0) return fail("1 coverage", -1, s, "never entered");
      }
  if (path.size() > 1 && !adjacent(path.back(), start))
    return fail("3 return", static_cast<std::int64_t>(path.size() - 1), path.back(),
                "the last sub-cell is not 4-adjacent to the start " + text(start));
  return {};
}

StcCheck StcTourChecker::check_full(const OccupancyGrid& map, Cell start,
                                    std::span<const Cell> path, std::int64_t reported_repeats) {
  if (path.empty()) return fail("3 return", -1, start, "the path is empty");
  if (path.front() != start)
    return fail("3 return", 0, path.front(), "the tour does not begin at the start " + text(start));
  (void)reachable_subcells(map, start, false, mark_); // queue_: the reachable free sub-cells
  seen_.assign(map.size(), 0);
  std::int64_t distinct = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Cell s = path[i];
    const auto step = static_cast<std::int64_t>(i);
    if (i > 0 && !adjacent(path[i - 1], s))
      return fail("2 moves", step, s,
                  "not 4-adjacent to the previous position " + text(path[i - 1]));
    if (!in_cell_area(map, s) || map[s] != Occupancy::Free)
      return fail("2 moves", step, s, "not a free sub-cell inside the cell area");
    if (seen_[map.index(s)] == 0) {
      seen_[map.index(s)] = 1;
      ++distinct;
    }
  }
  for (const Cell s : queue_)
    if (seen_[map.index(s)] == 0) return fail("1 coverage", -1, s, "reachable but never entered");
  const std::int64_t repeats = static_cast<std::int64_t>(path.size()) - distinct;
  if (repeats != reported_repeats)
    return fail("4 length", -1, path.back(),
                "the run reported " + std::to_string(reported_repeats) + " repeats, the path has " +
                    std::to_string(repeats));
  if (path.back() != start && !adjacent(path.back(), start))
    return fail("3 return", static_cast<std::int64_t>(path.size() - 1), path.back(),
                "the last sub-cell is neither the start " + text(start) + " nor 4-adjacent to it");
  return {};
}

StcCheck check_same_tour(std::span<const Cell> expected, std::span<const Cell> actual,
                         const std::string& what) {
  const std::size_t n = std::min(expected.size(), actual.size());
  for (std::size_t i = 0; i < n; ++i)
    if (expected[i] != actual[i])
      return fail("5 same tour", static_cast<std::int64_t>(i), actual[i],
                  what + " is at " + text(actual[i]) + " where the reference is at " +
                      text(expected[i]));
  if (expected.size() != actual.size())
    return fail("5 same tour", static_cast<std::int64_t>(n), n < actual.size() ? actual[n] : Cell{},
                what + " has " + std::to_string(actual.size()) + " positions, the reference " +
                    std::to_string(expected.size()));
  return {};
}

} // namespace antkit::testing
