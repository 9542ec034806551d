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
// Memory: one byte per cell (a quarter of a byte per sub-cell) holds everything: the free flag, the
// tree membership, the direction of the parent and the child directions. The depth-first search
// keeps no stack: it backtracks through the parent directions it stored, and on coming back from a
// child in direction e it resumes its scan at e + 1. Nothing recurses, so no map can overflow the
// call stack.
#include <antkit/stc/subcell.hpp>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace antkit::stc {

class SpanningTree {
public:
  // Byte layout of a cell's state. Not in the tree: 0 (blocked, or the one-cell border that spares
  // every bounds check) or kFreeCell. In the tree: kInTree, the direction of the parent in the low
  // two bits (the root: q0 - 1, its virtual parent), kRoot, and one bit per child direction, so
  // that the tour reads one byte per cell it walks through.
  static constexpr std::uint8_t kFreeCell = 0x01;
  static constexpr std::uint8_t kParentMask = 0x03;
  static constexpr std::uint8_t kInTree = 0x04;
  static constexpr std::uint8_t kRoot = 0x08;
  static constexpr int kChildShift = 4;

  // The tree of `map` from `start` (a sub-cell). Throws kernel::InputError when the start
  // sub-cell is outside the cell area or its cell is not free.
  SpanningTree(const kernel::OccupancyGrid& map, SubCell start);

  [[nodiscard]] CellGridShape shape() const noexcept { return shape_; }
  [[nodiscard]] Cell root() const noexcept { return root_; }
  [[nodiscard]] SubCell start() const noexcept { return subcell_of(root_, q0_); }
  [[nodiscard]] std::int64_t cells() const noexcept { return tree_cells_; }
  // Bytes this tree holds: a quarter byte per sub-cell, plus the border and the tiles' rounding.
  [[nodiscard]] std::size_t bytes() const noexcept { return state_.size(); }
  [[nodiscard]] bool in_tree(Cell c) const noexcept {
    return shape_.in_bounds(c) && (state_[index(c)] & kInTree) != 0;
  }
  // The direction from c to its parent; for the root, q0 - 1 (its virtual parent).
  [[nodiscard]] int parent_direction(Cell c) const noexcept {
    return state_[index(c)] & kParentMask;
  }
  // Bit d: the neighbour in direction d is a child of c.
  [[nodiscard]] unsigned children(Cell c) const noexcept {
    return static_cast<unsigned>(state_[index(c)]) >> kChildShift;
  }
  [[nodiscard]] bool is_root(Cell c) const noexcept { return c == root_; }

  // A place on the tour: cell, its index in the state array, and the quadrant.
  struct Cursor {
    Cell cell;
    std::size_t index;
    int q;
  };
  [[nodiscard]] Cursor begin() const noexcept { return {root_, index(root_), q0_}; }

  // One move of the circumnavigation: updates the cursor and returns the direction moved, or -1
  // when the next move would enter the start sub-cell again (the tour is closed).
  int advance(Cursor& at) const noexcept {
    const std::uint8_t here = state_[at.index];
    const int d = at.q;
    if ((here >> (kChildShift + d)) & 1) return cross(at, d);
    if ((here & kRoot) == 0 && (here & kParentMask) == d) {
      // Back to the parent; the only crossing that can lead into the start sub-cell.
      if (dir_add(d, 3) == q0_ && step(at.cell, d) == root_) return -1;
      return cross(at, d);
    }
    at.q = dir_add(d, 1);
    if (at.q == q0_ && at.cell == root_) return -1;
    return at.q; // moving to quadrant q + 1 is a move in direction q + 1
  }

  // Calls visit(SubCell) for every position of the tour, the start first; 4 * cells() calls.
  template <class Visit>
  void tour(Visit&& visit) const {
    Cursor at = begin();
    visit(subcell_of(at.cell, at.q));
    while (advance(at) >= 0) visit(subcell_of(at.cell, at.q));
  }
  [[nodiscard]] std::vector<SubCell> tour() const;

private:
  // The state is stored in 64 x 64-cell tiles of 4 KiB, row-major inside a tile and tiles
  // row-major: the depth-first search and the tour move up and down as often as sideways, and in a
  // plain row-major array of a large map every vertical move would touch another page. Cell
  // (x, y) is stored at (x + 1, y + 1): a border of blocked cells spares every bounds check.
  static constexpr int kTileBits = 6;
  [[nodiscard]] std::size_t index(Cell c) const noexcept {
    const auto x = static_cast<std::size_t>(c.x + 1), y = static_cast<std::size_t>(c.y + 1);
    constexpr std::size_t mask = (std::size_t{1} << kTileBits) - 1;
    return ((((y >> kTileBits) * tiles_x_ + (x >> kTileBits)) << (2 * kTileBits)) |
            ((y & mask) << kTileBits) | (x & mask));
  }
  int cross(Cursor& at, int d) const noexcept {
    at.cell = step(at.cell, d);
    at.index = index(at.cell);
    at.q = dir_add(d, 3);
    return d;
  }
  void build();

  CellGridShape shape_;
  std::size_t tiles_x_;
  std::vector<std::uint8_t> state_;
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
      : tree_(map, start), at_(tree_.begin()) {}

  Command step(const Observation&) {
    if (done_) return {};
    const int d = tree_.advance(at_);
    if (d < 0) {
      done_ = true;
      return {};
    }
    return {move_towards(d), false};
  }
  [[nodiscard]] const SpanningTree& tree() const noexcept { return tree_; }

private:
  SpanningTree tree_;
  SpanningTree::Cursor at_;
  bool done_ = false;
};

} // namespace antkit::stc
