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
// Two ways to get the tour: SpanningTree(map, start) then tour() (the two phases apart), or
// SpanningTree(map, start, visit), where the search emits the tour as it builds the tree. The
// second is the fast one (about 1.5 times the speed of the first on the benchmark maps): the
// depth-first search visits the cells in the very order of the circumnavigation, so walking the
// finished tree again repeats its loop. Both give the same positions and leave the same tree.
//
// Memory: the tree is one byte per cell (a quarter of a byte per sub-cell): the tree membership,
// the direction of the parent and the child directions. While it is built, the depth-first search
// keeps one more byte per cell (the mask of its new neighbours, its parent and the root flag) and
// releases it after: at most half a byte per sub-cell beyond the map. The search keeps no stack:
// it backtracks through the parent directions it stored. Nothing recurses, so no map can overflow
// the call stack. Both bytes are stored in 64 x 64-cell tiles (see index()).
#include <antkit/stc/subcell.hpp>
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace antkit::stc {

namespace detail {
// The in-tile index steps of SpanningTree's 64 x 64 tiles, E N W S.
inline constexpr std::array<int, 4> kTileStep{1, -64, -1, 64};
// A direction and its in-tile step in one table entry: 4 * step + d (d = entry & 3, step =
// entry >> 2, an arithmetic shift in C++20).
constexpr std::int16_t with_step(int d) noexcept {
  return static_cast<std::int16_t>(4 * kTileStep[static_cast<std::size_t>(d)] + d);
}
// A position packed in one word for the walk's buffer: x in the low 32 bits, y in the high 32.
// Coordinates are never negative, so adding packed offsets adds the coordinates apart (an offset
// with a negative part wraps around 2^64 and lands on the right word, as the sum is in range).
constexpr std::uint64_t pack(std::int64_t x, std::int64_t y) noexcept {
  return static_cast<std::uint64_t>(x) + (static_cast<std::uint64_t>(y) << 32);
}
} // namespace detail

class SpanningTree {
public:
  // Byte layout of a cell's state. Not in the tree: 0 (blocked, not reachable from the start, or
  // the one-cell border that spares every bounds check). In the tree: kInTree, the direction of the
  // parent in the low two bits (the root: q0 - 1, its virtual parent), kRoot, and one bit per child
  // direction, so that the tour reads one byte per cell it walks through.
  static constexpr std::uint8_t kParentMask = 0x03;
  static constexpr std::uint8_t kInTree = 0x04;
  static constexpr std::uint8_t kRoot = 0x08;
  static constexpr int kChildShift = 4;

  // The tree of `map` from `start` (a sub-cell). Throws kernel::InputError when the start
  // sub-cell is outside the cell area or its cell is not free.
  SpanningTree(const kernel::OccupancyGrid& map, SubCell start);

  // The same tree, and its tour while it is built: visit(SubCell) is called for every position of
  // the tour, the start first, in the order tour() gives (4 * cells() calls). The depth-first
  // search that builds the tree moves exactly as the robot circumnavigates it: each event of the
  // search (a descent to a new child in direction d, or the return to the parent in direction d)
  // is the run of sub-cells from the quadrant q the robot is in up to quadrant d, then the move
  // across side d (see tour()); the search and the walk of the tree are one loop. The tree is
  // complete when the constructor returns, and tour() walks it again if asked.
  template <class Visit>
  SpanningTree(const kernel::OccupancyGrid& map, SubCell start, Visit&& visit)
      : SpanningTree(map, start, Prepare{}) {
    search(visit);
  }

  [[nodiscard]] CellGridShape shape() const noexcept { return shape_; }
  [[nodiscard]] Cell root() const noexcept { return root_; }
  [[nodiscard]] SubCell start() const noexcept { return subcell_of(root_, q0_); }
  [[nodiscard]] std::int64_t cells() const noexcept { return tree_cells_; }
  // Bytes this tree holds: a quarter byte per sub-cell, plus the border and the tiles' rounding.
  // Building it took twice as much for a while (peak_bytes()).
  [[nodiscard]] std::size_t bytes() const noexcept { return state_.size(); }
  [[nodiscard]] std::size_t peak_bytes() const noexcept { return 2 * state_.size(); }
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

  // Calls visit(SubCell) for every position of the tour, the start first; 4 * cells() calls,
  // the same positions in the same order as repeated advance() from begin().
  //
  // Why it is not a loop over advance(): that decides cross-or-turn once per sub-cell, a branch
  // the processor cannot predict on a cluttered map. Here the walk goes one run at a time: from
  // the quadrant q it enters a cell in, the robot turns counter-clockwise through q, q + 1, ...
  // until the first side d (in that order) with a tree edge (a child, or the parent), then
  // crosses it. kRunEnd[state][q] gives d (and the step to the next cell's index); the run's up to
  // four sub-cells are written to a small buffer without a branch (all four are written, the write
  // position advances by the run's length), and the buffer is handed to `visit` in a plain loop.
  // The tour is closed after exactly 4 * cells() positions (issue 3, invariant 4), so the walk
  // counts positions instead of testing for the start sub-cell; the root needs no special case: its
  // virtual parent side is not an edge, and the count ends the walk before the run that would
  // re-enter the start.
  template <class Visit>
  void tour(Visit&& visit) const {
    const std::int64_t total = 4 * tree_cells_;
    std::int64_t emitted = 0;
    PositionBuffer<Visit> out(visit);
    const TileSteps steps = steps_;
    std::size_t at = index(root_);
    std::uint64_t corner = detail::pack(2 * root_.x, 2 * root_.y); // the cell's NW sub-cell
    int q = q0_;
    for (;;) {
      const int run =
          kRunEnd[static_cast<std::size_t>(state_[at]) * 4 + static_cast<std::size_t>(q)];
      const int d = run & 3;
      const int length = dir_add(d, -q) + 1;
      emitted += length;
      if (emitted >= total) {
        out.run(corner, q, length - static_cast<int>(emitted - total));
        out.flush();
        return;
      }
      out.run(corner, q, length);
      at = steps.next(at, d, run >> 2);
      corner += kCellMove[static_cast<std::size_t>(d)];
      q = dir_add(d, 3);
    }
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
  // Moving between cells by index, without the cell's coordinates: inside a tile a step is +-1
  // (E/W) or -+64 (N/S); from a tile's edge it lands in the next tile, at the opposite edge (the
  // `leave` steps).
  static constexpr std::array<int, 4> kStep = detail::kTileStep;
  static constexpr std::array<std::size_t, 4> kField{63, 63 << 6, 63, 63 << 6};
  static constexpr std::array<std::size_t, 4> kEdge{63, 0, 0, 63 << 6};
  // The four neighbours at once (the search updates them all when a cell joins the tree); the
  // tests against the tile's edges compile to conditional moves.
  struct Around {
    std::size_t e, n, w, s;
  };
  struct TileSteps {
    std::array<std::size_t, 4> leave; // E N W S
    [[nodiscard]] Around around(std::size_t i) const noexcept {
      constexpr std::size_t row = 63 << 6;
      const std::size_t x = i & 63, y = i & row;
      return {i + (x == 63 ? leave[0] : 1), i + (y == 0 ? leave[1] : 0 - std::size_t{64}),
              i + (x == 0 ? leave[2] : 0 - std::size_t{1}), i + (y == row ? leave[3] : 64)};
    }
    // The neighbour of i in direction d, given the in-tile step (kStep[d], which the callers read
    // from the same table entry as d, so that the chain of loads the search and the walk wait for
    // is one load, one table lookup and one add per cell). Leaving the tile is the rare case (one
    // move in 64 at most), a branch the processor predicts.
    [[nodiscard]] std::size_t next(std::size_t i, int d, int in_tile) const noexcept {
      const auto k = static_cast<std::size_t>(d);
      if ((i & kField[k]) == kEdge[k]) [[unlikely]]
        return i + leave[k];
      return i + static_cast<std::size_t>(static_cast<std::ptrdiff_t>(in_tile));
    }
  };
  // kRunOffsets[q][i]: sub-cell q + i of a cell, relative to the cell's NW sub-cell.
  static constexpr std::array<std::array<std::uint64_t, 4>, 4> kRunOffsets = [] {
    std::array<std::array<std::uint64_t, 4>, 4> t{};
    for (int q = 0; q < 4; ++q)
      for (int i = 0; i < 4; ++i) {
        const Cell o = kQuadrantOffset[static_cast<std::size_t>(dir_add(q, i))];
        t[static_cast<std::size_t>(q)][static_cast<std::size_t>(i)] = detail::pack(o.x, o.y);
      }
    return t;
  }();
  // The move of a cell's NW sub-cell to the neighbour cell in direction d, packed.
  static constexpr std::array<std::uint64_t, 4> kCellMove = [] {
    std::array<std::uint64_t, 4> t{};
    for (std::size_t d = 0; d < 4; ++d)
      t[d] = detail::pack(2 * kernel::kNeighbours4[d].x, 2 * kernel::kNeighbours4[d].y);
    return t;
  }();
  // kRunEnd[state * 4 + q]: the first side d = q, q + 1, q + 2, q + 3 of a cell with that state
  // byte that has a tree edge (a child, or the parent unless the cell is the root); q + 3 when
  // there is none (the root of a one-cell tree, whose four sub-cells are the whole tour). Stored
  // with_step(d).
  static constexpr std::array<std::int16_t, 1024> kRunEnd = [] {
    std::array<std::int16_t, 1024> t{};
    for (unsigned s = 0; s < 256; ++s)
      for (int q = 0; q < 4; ++q) {
        unsigned edges = s >> kChildShift;
        if ((s & kRoot) == 0) edges |= 1u << (s & kParentMask);
        int d = dir_add(q, 3);
        for (int i = 3; i >= 0; --i)
          if ((edges >> dir_add(q, i)) & 1u) d = dir_add(q, i);
        t[s * 4 + static_cast<unsigned>(q)] = detail::with_step(d);
      }
    return t;
  }();
  // kFirstFrom[mask * 4 + q]: the first direction q, q + 1, q + 2, q + 3 whose bit is set in the
  // 4-bit mask (mask != 0), stored detail::with_step(d).
  static constexpr std::array<std::int16_t, 64> kFirstFrom = [] {
    std::array<std::int16_t, 64> t{};
    for (unsigned m = 1; m < 16; ++m)
      for (int q = 0; q < 4; ++q) {
        int d = 0;
        for (int i = 3; i >= 0; --i)
          if ((m >> dir_add(q, i)) & 1u) d = dir_add(q, i);
        t[m * 4 + static_cast<unsigned>(q)] = detail::with_step(d);
      }
    return t;
  }();
  int cross(Cursor& at, int d) const noexcept {
    at.cell = step(at.cell, d);
    at.index = index(at.cell);
    at.q = dir_add(d, 3);
    return d;
  }
  // The runs of the tour on their way to the visitor: each run's up to four sub-cells are written
  // without a branch (all four are written, the write position advances by the run's length),
  // and a full buffer is handed to the visitor in a plain loop.
  template <class Visit>
  class PositionBuffer {
  public:
    explicit PositionBuffer(Visit& visit) noexcept : visit_(visit) {}
    // Sub-cells q, q + 1, ... of the cell whose NW sub-cell is `corner`, `length` (0 to 4) of them.
    void run(std::uint64_t corner, int q, int length) {
      const std::array<std::uint64_t, 4>& offsets = kRunOffsets[static_cast<std::size_t>(q)];
      std::uint64_t* out = buffer_.data() + filled_;
      for (std::size_t i = 0; i < 4; ++i) out[i] = corner + offsets[i];
      filled_ += length;
      if (filled_ >= kBuffer) flush();
    }
    void flush() {
      for (int i = 0; i < filled_; ++i) {
        const std::uint64_t v = buffer_[static_cast<std::size_t>(i)];
        visit_(SubCell{static_cast<std::int32_t>(static_cast<std::uint32_t>(v)),
                       static_cast<std::int32_t>(static_cast<std::uint32_t>(v >> 32))});
      }
      filled_ = 0;
    }

  private:
    static constexpr int kBuffer = 512;
    Visit& visit_;
    int filled_ = 0;
    std::array<std::uint64_t, kBuffer + 4> buffer_; // packed positions, see detail::pack()
  };

  // The visitor of the plain constructor: the search then builds the tree and writes no tour.
  struct NoVisit {
    void operator()(SubCell) const noexcept {}
  };
  struct Prepare {};
  // Checks the start, allocates the tree and computes the search's new-neighbour masks.
  SpanningTree(const kernel::OccupancyGrid& map, SubCell start, Prepare);

  // The byte the search keeps per cell (in the tree's tiled layout), apart from the tree itself:
  // bits 0-3, bit d set while the neighbour in direction d is a new cell (free, not yet in the
  // tree; Gabriely & Rimon's "new" cells); once the cell is in the tree, bits 4-5 hold the
  // direction of its parent and bit 6 says it is the root.
  static constexpr unsigned kNewMask = 0x0F;
  static constexpr int kOpenParentShift = 4;
  static constexpr unsigned kOpenRoot = 0x40;

  // The depth-first search, one event per loop. A cell scans its neighbours counter-clockwise from
  // after its parent; every direction it has scanned is no longer new (it was blocked or in the
  // tree then and stays so, or it was descended into), so the next direction of the scan is simply
  // the first new neighbour at or after the scan position `q`: one byte read (the cell's
  // new-neighbour mask) and one table lookup (kFirstFrom). The masks are kept up to date by the
  // cell that joins the tree: it clears its own bit in its four neighbours' masks, stores that are
  // off the chain of loads the search waits for. No new neighbour: back to the parent, whose scan
  // resumes after the direction that led here. After a descent in direction d the child's scan
  // starts at d + 3 (after its parent, in direction d + 2); after coming back from a child whose
  // parent lies in direction p, the parent's scan resumes at p + 3 (after p + 2): both are d + 3
  // for the direction d just moved in. The root's scan starts at q0 and covers all four directions;
  // it ends the search when it has no new neighbour. No stack, no recursion.
  template <class Visit>
  void search(Visit& visit) {
    constexpr bool kTour = !std::is_same_v<std::remove_cvref_t<Visit>, NoVisit>;
    std::uint8_t* open = open_.data();
    std::uint8_t* s = state_.data();
    const TileSteps steps = steps_;
    // A cell joins the tree: its bit leaves the masks of its four neighbours (border cells
    // included; their masks are never read).
    const auto join = [open](const Around& n) {
      open[n.e] = static_cast<std::uint8_t>(open[n.e] & ~(1u << 2));
      open[n.n] = static_cast<std::uint8_t>(open[n.n] & ~(1u << 3));
      open[n.w] = static_cast<std::uint8_t>(open[n.w] & ~(1u << 0));
      open[n.s] = static_cast<std::uint8_t>(open[n.s] & ~(1u << 1));
    };
    std::size_t at = index(root_);
    const int p0 = dir_add(q0_, 3);
    s[at] = static_cast<std::uint8_t>(kInTree | kRoot | p0);
    join(steps.around(at));
    unsigned here =
        (open[at] & kNewMask) | kOpenRoot | static_cast<unsigned>(p0) << kOpenParentShift;
    open[at] = static_cast<std::uint8_t>(here);
    std::int64_t cells = 1;
    int q = q0_;
    PositionBuffer<Visit> out(visit);
    std::uint64_t corner = detail::pack(2 * root_.x, 2 * root_.y);
    std::int64_t emitted = 0;
    for (;;) {
      const unsigned fresh = here & kNewMask;
      int d = 0;
      if (fresh != 0) {
        const int first = kFirstFrom[fresh * 4 + static_cast<unsigned>(q)];
        d = first & 3;
        const std::size_t child = steps.next(at, d, first >> 2);
        s[at] = static_cast<std::uint8_t>(s[at] | (1u << (kChildShift + d)));
        s[child] = static_cast<std::uint8_t>(kInTree | opposite(d));
        // The child's mask as it is now (its bit for `at` already clear), plus its parent.
        here = open[child] | static_cast<unsigned>(opposite(d)) << kOpenParentShift;
        open[child] = static_cast<std::uint8_t>(here);
        join(steps.around(child)); // clears bit d of open[at] among others
        at = child;
        ++cells;
      } else {
        if (here & kOpenRoot) break;
        d = static_cast<int>(here >> kOpenParentShift) & 3;
        at = steps.next(at, d, kStep[static_cast<std::size_t>(d)]);
        here = open[at];
      }
      if constexpr (kTour) {
        const int length = dir_add(d, -q) + 1;
        out.run(corner, q, length);
        emitted += length;
        corner += kCellMove[static_cast<std::size_t>(d)];
      }
      q = dir_add(d, 3);
    }
    tree_cells_ = cells;
    if constexpr (kTour) {
      // The root's last run, up to its virtual parent's side q0 - 1: what is left of the 4 * cells
      // positions (0 when the last child lay in direction q0 - 1; 4 for a one-cell tree).
      out.run(corner, q, static_cast<int>(4 * cells - emitted));
      out.flush();
    }
    std::vector<std::uint8_t>().swap(open_); // the search's memory is released
  }

  void mark_free_cells(const kernel::OccupancyGrid& map, std::vector<std::uint8_t>& open);

  CellGridShape shape_;
  std::size_t tiles_x_;
  TileSteps steps_{};
  std::vector<std::uint8_t> state_;
  std::vector<std::uint8_t> open_; // the search's new-neighbour masks, released after it
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
