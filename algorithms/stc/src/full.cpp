#include <algorithm>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/full.hpp>
#include <array>
#include <string>

namespace antkit::stc {

namespace {

struct Frame {
  Cell cell;
  std::uint8_t mask; // the part: bit q = quadrant q belongs to it
  int base;          // side the part was entered across (root: q0 - 1)
  int k;             // next scan position: side base + 1 + k
  bool root;
};

class Planner {
public:
  Planner(const kernel::OccupancyGrid& map, SubCell start)
      : map_(map), shape_(cell_shape(map)),
        seen_(static_cast<std::size_t>(map.width()) * static_cast<std::size_t>(map.height()), 0),
        entered_(seen_.size(), 0), cur_(start) {}

  std::vector<SubCell> run(SubCell start) {
    const Cell root = cell_of(start);
    const int q0 = quadrant_of(start);
    std::vector<Frame> stack;
    const std::uint8_t root_mask = part_mask(root, q0);
    mark_part(root, root_mask);
    stack.push_back({root, root_mask, dir_add(q0, 3), 0, true});
    emit(start);
    while (!stack.empty()) {
      Frame& f = stack.back();
      const int limit = f.root ? 4 : 3;
      bool descended = false;
      while (!descended && f.k < limit) {
        const int d = dir_add(f.base, 1 + f.k);
        ++f.k;
        const Cell y = step(f.cell, d);
        // The exact variants' crossing first (out of d into y's d + 3), then the other pair.
        for (const auto& [s, t] :
             {std::pair{d, dir_add(d, 3)}, std::pair{dir_add(d, 1), dir_add(d, 2)}}) {
          if (((f.mask >> s) & 1) == 0 || !free_sub(y, t) || seen_[index(subcell_of(y, t))])
            continue;
          walk_along(f.cell, f.mask, s);
          emit(subcell_of(y, t));
          const std::uint8_t m = part_mask(y, t);
          mark_part(y, m);
          const Frame child{y, m, opposite(d), 0, false};
          stack.push_back(child); // invalidates f: the loop condition tests `descended` first
          descended = true;
          break;
        }
      }
      if (descended) continue;
      const Frame done = stack.back();
      stack.pop_back();
      if (done.root) {
        // End at the start sub-cell or one 4-adjacent to it, inside the start part.
        const std::uint8_t ends =
            done.mask &
            static_cast<std::uint8_t>((1 << q0) | (1 << dir_add(q0, 1)) | (1 << dir_add(q0, 3)));
        cover_and_end(done.cell, done.mask, ends);
        break;
      }
      const Frame& parent = stack.back();
      const int p = done.base;
      int s = p, t = dir_add(p, 3);
      if (((done.mask >> s) & 1) == 0 || ((parent.mask >> t) & 1) == 0) {
        s = dir_add(p, 1);
        t = dir_add(p, 2);
      }
      cover_and_end(done.cell, done.mask, static_cast<std::uint8_t>(1 << s));
      emit(subcell_of(parent.cell, t));
    }
    return std::move(path_);
  }

private:
  [[nodiscard]] std::size_t index(SubCell s) const noexcept { return map_.index(s); }
  [[nodiscard]] bool free_sub(Cell cell, int q) const noexcept {
    return shape_.in_bounds(cell) && map_[subcell_of(cell, q)] == kernel::Occupancy::Free;
  }
  [[nodiscard]] std::uint8_t part_mask(Cell cell, int q) const noexcept {
    unsigned m = 1u << q;
    for (int k = 1; k < 4 && free_sub(cell, dir_add(q, k)); ++k) m |= 1u << dir_add(q, k);
    for (int k = 1; k < 4 && free_sub(cell, dir_add(q, -k)); ++k) m |= 1u << dir_add(q, -k);
    return static_cast<std::uint8_t>(m);
  }
  void mark_part(Cell cell, std::uint8_t mask) {
    for (int q = 0; q < 4; ++q)
      if ((mask >> q) & 1) seen_[index(subcell_of(cell, q))] = 1;
  }
  void emit(SubCell s) {
    path_.push_back(s);
    entered_[index(s)] = 1;
    cur_ = s;
  }
  // The step (+1 or -1) that leads from a to b inside the part, and how many moves it takes.
  // A whole 4-cycle: `prefer_ccw` walks counter-clockwise, otherwise the shorter way (ties CCW).
  static std::pair<int, int> route(std::uint8_t mask, int a, int b, bool prefer_ccw) noexcept {
    if (a == b) return {1, 0};
    const int ccw = dir_add(b, -a), cw = dir_add(a, -b);
    if (mask == 0x0F) return (prefer_ccw || ccw <= cw) ? std::pair{1, ccw} : std::pair{-1, cw};
    for (int r = a, n = 1; n < 4; ++n) { // a run: +1 reaches b before leaving it, or -1 does
      r = dir_add(r, 1);
      if (((mask >> r) & 1) == 0) break;
      if (r == b) return {1, n};
    }
    return {-1, cw};
  }
  void walk(Cell cell, std::uint8_t mask, int to, bool prefer_ccw) {
    int r = quadrant_of(cur_);
    const auto [dir, n] = route(mask, r, to, prefer_ccw);
    for (int i = 0; i < n; ++i) {
      r = dir_add(r, dir);
      emit(subcell_of(cell, r));
    }
  }
  void walk_along(Cell cell, std::uint8_t mask, int to) { walk(cell, mask, to, true); }

  // Enters every sub-cell of the part not yet entered, then ends on one of `ends`, by the shortest
  // walk over every order of the missing sub-cells (at most three, so at most six orders).
  void cover_and_end(Cell cell, std::uint8_t mask, std::uint8_t ends) {
    std::array<int, 4> missing{};
    int n = 0;
    for (int q = 0; q < 4; ++q)
      if (((mask >> q) & 1) && !entered_[index(subcell_of(cell, q))])
        missing[static_cast<std::size_t>(n++)] = q;
    const int start = quadrant_of(cur_);
    int best = 1 << 30;
    std::array<int, 4> best_order{};
    int best_end = -1;
    std::array<int, 4> order = missing;
    const auto first = order.begin(), last = order.begin() + n;
    do {
      int cost = 0, at = start;
      for (int i = 0; i < n; ++i) {
        cost += route(mask, at, order[static_cast<std::size_t>(i)], false).second;
        at = order[static_cast<std::size_t>(i)];
      }
      for (int e = 0; e < 4; ++e) {
        if (((ends >> e) & 1) == 0) continue;
        const int total = cost + route(mask, at, e, false).second;
        if (total < best) {
          best = total;
          best_order = order;
          best_end = e;
        }
      }
    } while (std::next_permutation(first, last));
    for (int i = 0; i < n; ++i) walk(cell, mask, best_order[static_cast<std::size_t>(i)], false);
    if (best_end >= 0) walk(cell, mask, best_end, false);
  }

  const kernel::OccupancyGrid& map_;
  CellGridShape shape_;
  std::vector<std::uint8_t> seen_;    // per sub-cell: its part is in the tree
  std::vector<std::uint8_t> entered_; // per sub-cell: the tour has entered it
  std::vector<SubCell> path_;
  SubCell cur_;
};

} // namespace

std::vector<SubCell> full_stc_tour(const kernel::OccupancyGrid& map, SubCell start) {
  const CellGridShape shape = cell_shape(map);
  const std::string at =
      "sub-cell (" + std::to_string(start.x) + ", " + std::to_string(start.y) + ")";
  if (start.x < 0 || start.y < 0 || !shape.in_bounds(cell_of(start)))
    throw kernel::InputError("start", at + " is outside the map's cells");
  if (map[start] != kernel::Occupancy::Free) throw kernel::InputError("start", at + " is not free");
  return Planner(map, start).run(start);
}

FullStc::FullStc(const kernel::OccupancyGrid& map, SubCell start) {
  const std::vector<SubCell> path = full_stc_tour(map, start);
  moves_.reserve(path.size());
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Cell delta = path[i] - path[i - 1];
    for (int d = 0; d < 4; ++d)
      if (kernel::kNeighbours4[static_cast<std::size_t>(d)] == delta)
        moves_.push_back(static_cast<std::uint8_t>(d));
  }
}

Command FullStc::step(const Observation&) {
  if (next_ >= moves_.size()) return {};
  return {move_towards(moves_[next_++]), false};
}

} // namespace antkit::stc
