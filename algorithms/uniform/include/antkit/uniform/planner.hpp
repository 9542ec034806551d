#pragma once
// The two searches of paper 004's A* algorithm: spiral iteration for the nearest unexplored cell,
// and the modified A-Star that stops as soon as the goal is in sensor view.
//
// Spiral iteration (the paper's Figure 2). The paper iterates "outward through a map from a given
// cell ... in an increasing spiral", and calls the first hit "an approximation of the closest
// unexplored cell". Here the spiral is the sequence of square rings around the centre, ring d
// holding the 8d cells at Chebyshev distance d; the first hit is therefore a nearest cell in
// Chebyshev distance (which, for a robot that moves in eight directions at one cell per tick, is
// the number of ticks on an empty map). Within a ring the order is fixed: start east of the centre
// (x + d, y), go up the east side to the corner (x + d, y - d), then along the top side westward,
// down the west side, along the bottom side eastward, and up the east side to (x + d, y + 1):
// counter-clockwise as drawn, starting east, like the kernel's neighbour order.
//
// A-Star (Hart, Nilsson, Raphael 1968) on the 8-neighbourhood with unit step cost (one tick per
// step, diagonal or not: that is what the paper's movement counts measure). The search stops at
// the first cell taken from the open list that satisfies `reached` (the paper: "until a cell has a
// parent and that cell is close enough to the goal cell that the goal cell would lie in a sensor's
// field of vision"). The caller's heuristic must be consistent for that cell to be a nearest one;
// the A* controller uses max(0, chebyshev(c, goal) - r), which is. Ties in the open list go to the
// smaller f, then the smaller h (deeper first), then the entry pushed first, so the result does not
// depend on the heap's implementation. A cell's neighbours are pushed straight on first (along the
// step that reached it, or the robot's bearing at the start), then turning ever wider, left
// before right: among equally short paths the robot keeps its heading, so that it sweeps rather
// than wanders (our choice; with ties to the smaller cell index the robots drifted north-west).
// Buffers live in the object and are reused: a generation stamp per cell makes clearing them O(1).
#include <algorithm>
#include <antkit/kernel/grid.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace antkit::uniform {

// Calls pred(cell) for every cell of a width x height grid in spiral order around `centre` (which
// may lie off the grid), each ring starting at the cell d steps along `first_bearing`, skipping
// cells off the grid, until pred returns true; returns that cell. Rings below `first_ring` are
// skipped (the caller knows they hold no hit).
template <class Pred>
std::optional<kernel::Cell> spiral_find(kernel::Cell centre, std::uint8_t first_bearing,
                                        std::int32_t width, std::int32_t height, Pred&& pred,
                                        std::int32_t first_ring = 0) {
  using kernel::Cell;
  const auto inside = [&](Cell c) { return c.x >= 0 && c.y >= 0 && c.x < width && c.y < height; };
  if (first_ring <= 0 && inside(centre) && pred(centre)) return centre;
  // The last ring that can still hold a grid cell.
  const std::int64_t far =
      std::max(std::max<std::int64_t>(centre.x, std::int64_t{width} - 1 - centre.x),
               std::max<std::int64_t>(centre.y, std::int64_t{height} - 1 - centre.y));
  // One straight run of `count` cells from `from` by `step`, clipped to the grid.
  std::optional<Cell> hit;
  const auto run = [&](Cell from, Cell step, std::int32_t count) {
    std::int32_t lo = 0, hi = count; // k in [lo, hi)
    const auto clip = [&](std::int32_t pos, std::int32_t dir, std::int32_t limit) {
      if (dir == 0) {
        if (pos < 0 || pos >= limit) hi = lo;
      } else if (dir > 0) {
        lo = std::max(lo, -pos);
        hi = std::min(hi, limit - pos);
      } else {
        lo = std::max(lo, pos - limit + 1);
        hi = std::min(hi, pos + 1);
      }
    };
    clip(from.x, step.x, width);
    clip(from.y, step.y, height);
    for (std::int32_t k = lo; k < hi; ++k) {
      const Cell c{from.x + k * step.x, from.y + k * step.y};
      if (pred(c)) {
        hit = c;
        return true;
      }
    }
    return false;
  };
  for (std::int64_t dd = first_ring > 1 ? first_ring : 1; dd <= far; ++dd) {
    const auto d = static_cast<std::int32_t>(dd);
    // Ring d as eight runs of d cells; run m starts at centre + d * kNeighbours8[m] and walks
    // counter-clockwise (along kNeighbours8[m + 2] from a side's middle, kNeighbours8[m + 3] from
    // a corner).
    for (unsigned s = 0; s < 8; ++s) {
      const unsigned m = (first_bearing + s) & 7u;
      const Cell dir = kernel::kNeighbours8[m];
      const Cell step = kernel::kNeighbours8[(m + ((m & 1u) ? 3u : 2u)) & 7u];
      if (run({centre.x + d * dir.x, centre.y + d * dir.y}, step, d)) return hit;
    }
  }
  return std::nullopt;
}

class PathSearch {
public:
  // A shortest path from `start` on a width x height grid, by steps that step_ok(cell, bearing)
  // allows, to the first cell with reached(cell); heuristic(cell) a consistent lower bound on the
  // steps still needed. On success fills `bearings` with the steps in order and returns true; gives
  // up (returns false) after taking max_expanded cells from the open list.
  template <class StepOk, class Reached, class Heuristic>
  bool find(std::int32_t width, std::int32_t height, kernel::Cell start, std::uint8_t bearing,
            StepOk&& step_ok, Reached&& reached, Heuristic&& heuristic,
            std::vector<std::uint8_t>& bearings, std::uint64_t max_expanded = ~std::uint64_t{0}) {
    prepare(width, height);
    bearings.clear();
    heap_.clear();
    const auto w = static_cast<std::size_t>(width);
    const auto index = [w](kernel::Cell c) {
      return static_cast<std::size_t>(c.y) * w + static_cast<std::size_t>(c.x);
    };
    std::uint32_t sequence = 0;
    std::uint64_t expanded_here = 0;
    const auto push = [&](kernel::Cell c, std::uint32_t g) {
      const auto h = static_cast<std::uint32_t>(heuristic(c));
      heap_.push_back({g + h, h, sequence++, static_cast<std::uint32_t>(index(c))});
      std::push_heap(heap_.begin(), heap_.end(), Later{});
    };
    const std::size_t s = index(start);
    nodes_[s] = {generation_, 0, static_cast<std::uint8_t>(bearing & 7u), false};
    push(start, 0);
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), Later{});
      const Entry e = heap_.back();
      heap_.pop_back();
      const std::uint32_t g = e.f - e.h;
      Node& node = nodes_[e.index];
      if (node.closed || g != node.g) continue; // a stale entry
      node.closed = true;
      ++expanded_;
      if (++expanded_here > max_expanded) return false;
      const kernel::Cell c{static_cast<std::int32_t>(e.index % w),
                           static_cast<std::int32_t>(e.index / w)};
      if (reached(c)) {
        for (kernel::Cell at = c; at != start;) {
          const std::uint8_t b = nodes_[index(at)].parent;
          bearings.push_back(b);
          at = at - kernel::kNeighbours8[b];
        }
        std::reverse(bearings.begin(), bearings.end());
        return true;
      }
      for (const std::uint8_t turn : kStraightFirst) {
        const auto b = static_cast<std::uint8_t>((node.parent + turn) & 7u);
        if (!step_ok(c, b)) continue;
        const kernel::Cell n = c + kernel::kNeighbours8[b];
        Node& next = nodes_[index(n)];
        if (next.stamp == generation_ && (next.closed || next.g <= g + 1)) continue;
        next = {generation_, g + 1, b, false};
        push(n, g + 1);
      }
    }
    return false;
  }

  // Cells taken from the open list over the object's life (for benchmarks and reports).
  [[nodiscard]] std::uint64_t expanded() const noexcept { return expanded_; }

private:
  struct Entry {
    std::uint32_t f, h, sequence, index;
  };
  // Neighbours are tried straight on first, then ever wider turns, left before right.
  static constexpr std::uint8_t kStraightFirst[8] = {0, 1, 7, 2, 6, 3, 5, 4};
  // The heap keeps the "smallest" entry on top; Later{}(a, b) says a comes out after b.
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const noexcept {
      if (a.f != b.f) return a.f > b.f;
      if (a.h != b.h) return a.h > b.h;
      return a.sequence > b.sequence;
    }
  };
  // One record per cell, so that a visit touches one cache line. `stamp` says whether the rest
  // belongs to the current search; closed cells have their g fixed.
  struct Node {
    std::uint32_t stamp = 0;
    std::uint32_t g = 0;
    std::uint8_t parent = 0; // the bearing of the step that reached the cell
    bool closed = false;
  };
  void prepare(std::int32_t width, std::int32_t height) {
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (nodes_.size() != n) {
      nodes_.assign(n, Node{});
      generation_ = 0;
    }
    if (++generation_ == 0) { // wrapped: old stamps could match again
      std::fill(nodes_.begin(), nodes_.end(), Node{});
      generation_ = 1;
    }
  }

  std::vector<Node> nodes_;
  std::vector<Entry> heap_;
  std::uint32_t generation_ = 0;
  std::uint64_t expanded_ = 0;
};

} // namespace antkit::uniform
