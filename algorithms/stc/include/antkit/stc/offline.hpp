#pragma once
// Offline STC: the map is known. Phase 1 builds a spanning tree of the free cells 4-connected to
// the start cell; phase 2 walks the sub-cells around it (the robot keeps the tree on its left).
//
// The tree is the depth-first tree whose neighbour order is the one online STC uses: the root
// scans its four neighbours counter-clockwise starting at the direction of the start sub-cell's
// quadrant q0 (q0, q0 + 1, q0 + 2, q0 + 3), every other cell scans counter-clockwise starting after
// its parent. So offline, online and the ant-like variants produce the same tour, move for move
// (issue 3, invariant 5). Any spanning tree would give a valid tour; this one is chosen so that
// they agree.
//
// Memory: one byte per cell (a quarter of a byte per sub-cell) holds everything, the free flag, the
// tree membership and the direction of the parent. The depth-first search keeps no stack: it
// backtracks through the parent directions it stored, and on coming back from a child in direction
// e it resumes its scan at e + 1. Nothing recurses, so no map can overflow the call stack.
#include <antkit/stc/subcell.hpp>
#include <cstdint>
#include <vector>

namespace antkit::stc {

class SpanningTree {
public:
  // Byte layout of a cell's state.
  static constexpr std::uint8_t kParentMask = 0x03; // direction to the parent (root: q0 - 1)
  static constexpr std::uint8_t kInTree = 0x04;
  static constexpr std::uint8_t kFree = 0x08;
  static constexpr std::uint8_t kRoot = 0x10;

  // The tree of `map` from `start` (a sub-cell). Throws kernel::InputError when the start
  // sub-cell is outside the cell area or its cell is not free.
  SpanningTree(const kernel::OccupancyGrid& map, SubCell start);

  // The same from a grid of free cells (non-zero = free), one byte per cell; the grid is taken
  // over as the tree's storage, so no memory beyond it is used. For maps too large to hold twice.
  SpanningTree(kernel::Grid<std::uint8_t> free_cells, SubCell start);

  [[nodiscard]] CellGridShape shape() const noexcept { return {state_.width(), state_.height()}; }
  [[nodiscard]] Cell root() const noexcept { return root_; }
  [[nodiscard]] SubCell start() const noexcept { return subcell_of(root_, q0_); }
  [[nodiscard]] std::int64_t cells() const noexcept { return tree_cells_; }
  [[nodiscard]] bool in_tree(Cell c) const noexcept {
    return shape().in_bounds(c) && (state_[c] & kInTree) != 0;
  }
  // The direction from c to its parent; for the root, q0 - 1 (its virtual parent).
  [[nodiscard]] int parent_direction(Cell c) const noexcept { return state_[c] & kParentMask; }
  [[nodiscard]] bool is_root(Cell c) const noexcept { return c == root_; }

  // One move of the circumnavigation from sub-cell q of cell `cur`: updates (cur, q) and returns
  // the direction moved, or -1 when the next move would enter the start sub-cell again (the tour
  // is closed).
  int advance(Cell& cur, int& q) const noexcept {
    const int d = q;
    const Cell nb = step(cur, d);
    if (shape().in_bounds(nb)) {
      const std::uint8_t n = state_[nb];
      // nb is a child of cur when its parent direction points back at cur.
      if ((n & (kInTree | kRoot)) == kInTree && (n & kParentMask) == opposite(d))
        return cross(cur, q, nb, d);
    }
    const std::uint8_t here = state_[cur];
    if ((here & kRoot) == 0 && (here & kParentMask) == d) return cross(cur, q, nb, d);
    q = dir_add(q, 1);
    if (cur == root_ && q == q0_) return -1;
    return q; // moving to quadrant q + 1 is a move in direction q + 1
  }

  // Calls visit(SubCell) for every position of the tour, the start first; 4 * cells() calls.
  template <class Visit>
  void tour(Visit&& visit) const {
    Cell cur = root_;
    int q = q0_;
    visit(subcell_of(cur, q));
    while (advance(cur, q) >= 0) visit(subcell_of(cur, q));
  }
  [[nodiscard]] std::vector<SubCell> tour() const;

private:
  int cross(Cell& cur, int& q, Cell nb, int d) const noexcept {
    const int arrive = dir_add(d, 3);
    if (nb == root_ && arrive == q0_) return -1;
    cur = nb;
    q = arrive;
    return d;
  }
  void build();

  kernel::Grid<std::uint8_t> state_;
  Cell root_{};
  int q0_ = 0;
  std::int64_t tree_cells_ = 0;
};

// Offline STC as a controller (DESIGN.md contract): it knows the map (given at construction), so it
// needs nothing from its observations; each step is the next move around the tree.
class OfflineStc {
public:
  struct Observation {};
  using Command = stc::Command;

  OfflineStc(const kernel::OccupancyGrid& map, SubCell start)
      : tree_(map, start), cur_(tree_.root()), q_(quadrant_of(start)) {}

  Command step(const Observation&) {
    if (done_) return {};
    const int d = tree_.advance(cur_, q_);
    if (d < 0) {
      done_ = true;
      return {};
    }
    return {move_towards(d), false};
  }
  [[nodiscard]] const SpanningTree& tree() const noexcept { return tree_; }

private:
  SpanningTree tree_;
  Cell cur_;
  int q_;
  bool done_ = false;
};

} // namespace antkit::stc
