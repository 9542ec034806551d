#pragma once
// Exact rasterization of segments between cell centres, and line of sight on a grid.
//
// Geometry. Cell (x, y) is the closed unit square [x - 1/2, x + 1/2] x [y - 1/2, y + 1/2]; its
// centre has integer coordinates (x, y). A segment joins the centres of two cells a and b.
//
// Supercover. The supercover of a segment is the set of cells whose closed square the closed
// segment touches. Because the segment's ends are integer points, it can never run along a cell
// edge (edges lie on half-integer lines, and a horizontal or vertical segment between centres lies
// on an integer line), so the only way to touch a square without entering it is to pass exactly
// through one of its corners.
//
// Corner rule: when the segment passes exactly through a cell corner, the supercover holds both
// side cells (the two cells that meet the segment only at that corner), not just the cells before
// and after. This is the exact "closed segment touches closed square" set, so it needs no
// tie-break: it is the same set from a to b as from b to a, and line of sight is symmetric without
// any further rule. For line of sight it means that a diagonal gap between two blocked cells that
// touch at a corner does not let sight (or a robot of nonzero width) through.
//
// Order. Cells are visited from a to b, each once. At a corner the two side cells come first, the
// x-side one (the cell reached by stepping along x) before the y-side one, then the diagonal cell.
// So every cell is 4-adjacent to the one before it, except the y-side cell of a corner, which is
// 4-adjacent to the cell two before it (the cell the corner leaves). The set is 4-connected; the
// sequence cannot be a 4-path, since no 4-path through a 2x2 block starts and ends at opposite
// cells while visiting all four.
//
// Decision variable and its range. Reflect the segment so that it runs from (0, 0) to (dx, dy) with
// dx, dy >= 0, and let (i, j) be the current cell in those local coordinates. The segment leaves
// the square of (i, j) through its right edge, its top edge or its corner according to the sign of
//     e = dy * (2i + 1) - dx * (2j + 1)
// (twice the signed vertical distance, times dx, between the corner (i + 1/2, j + 1/2) and the line
// at x = i + 1/2): e < 0 steps x, e > 0 steps y, e == 0 is the corner. It starts at dy - dx and
// changes by +2dy on an x step, -2dx on a y step and 2dy - 2dx at a corner. While the walk is on
// the supercover, e lies in [-2dx, 2dy] (the line is at or below the top edge at x = i - 1/2 and
// at or above the bottom edge at x = i + 1/2), and every value it takes, including the increments
// 2dx and 2dy, stays inside that interval. For cells in [0, kMaxGridSide) (grid.hpp),
// dx, dy < 2^20, so |e| < 2^21: the walk is free of overflow even in a 32-bit integer. The public
// functions take any Cell, whose differences need 33 bits, so they instantiate the walk with
// std::int64_t (|e| < 2^34); the templates over the integer type are what the proofs check.
//
// Bresenham. The classic 8-connected line: one cell per step along the major axis (the axis with
// the larger extent; x when the extents are equal), and on each step the minor coordinate nearest
// to the line. Tie rule (the line passes exactly halfway between two cells of a column): take the
// one farther from a. So bresenham(b, a) is the reverse of bresenham(a, b) only when no tie
// occurs; use the supercover where direction must not matter. Its decision variable
//     D = 2 dy (k + 1) - dx (2j + 1)       (major step k, minor j, dx >= dy after the swap)
// lies in [-2dx, 2dy) and moves by +2dy and -2dx, with the same bounds as e.
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace antkit::kernel {

// What the supercover walk does next from the current cell.
enum class SupercoverStep : std::uint8_t { X, Y, Corner };

// One state of the supercover walk in local coordinates (the segment runs from (0, 0) to
// (dx, dy), dx, dy >= 0). Written over the integer type so that the same source is run with
// machine integers and interpreted by the proofs (DESIGN.md rule 6).
template <class Int>
struct SupercoverWalk {
  Int dx;
  Int dy;
  Int i{0};
  Int j{0};
  Int e; // dy * (2i + 1) - dx * (2j + 1), in [-2dx, 2dy]

  constexpr SupercoverWalk(Int dx_, Int dy_) noexcept : dx(dx_), dy(dy_), e(dy_ - dx_) {}

  [[nodiscard]] constexpr bool done() const noexcept { return i == dx && j == dy; }
  [[nodiscard]] constexpr SupercoverStep next() const noexcept {
    if (e < 0) return SupercoverStep::X;
    if (e > 0) return SupercoverStep::Y;
    return SupercoverStep::Corner;
  }
  // Moves to the next cell along the segment (the diagonal one at a corner). Precondition:
  // !done().
  constexpr SupercoverStep advance() noexcept {
    const SupercoverStep s = next();
    switch (s) {
    case SupercoverStep::X:
      i = i + 1;
      e = e + dy + dy;
      break;
    case SupercoverStep::Y:
      j = j + 1;
      e = e - dx - dx;
      break;
    case SupercoverStep::Corner:
      i = i + 1;
      j = j + 1;
      e = e + (dy - dx) + (dy - dx);
      break;
    }
    return s;
  }
};

// One state of Bresenham's walk along the major axis, in local coordinates where the segment runs
// from (0, 0) to (dmajor, dminor) with dmajor >= dminor >= 0.
template <class Int>
struct BresenhamWalk {
  Int dmajor;
  Int dminor;
  Int k{0};
  Int j{0};
  Int d; // 2 dminor (k + 1) - dmajor (2j + 1), in [-2 dmajor, 2 dminor)

  constexpr BresenhamWalk(Int dmajor_, Int dminor_) noexcept
      : dmajor(dmajor_), dminor(dminor_), d(dminor_ + dminor_ - dmajor_) {}

  [[nodiscard]] constexpr bool done() const noexcept { return k == dmajor; }
  // Moves one step along the major axis; returns whether the minor coordinate moved too.
  // Precondition: !done(). The explicit bool conversion is the one branch: on machine integers a
  // plain comparison, on the proofs' Z3 integers a fork of the run (proofs/z3/bresenham_walk.cpp).
  constexpr bool advance() noexcept {
    k = k + 1;
    const bool minor = static_cast<bool>(d >= Int{0}); // ties (d == 0) move away from a
    if (minor) {
      j = j + 1;
      d = d - dmajor - dmajor;
    }
    d = d + dminor + dminor;
    return minor;
  }
};

namespace detail {

// The offsets of b from a, their signs and magnitudes, in 64 bits: differences of any two int32
// coordinates fit.
struct RasterFrame {
  std::int64_t ax, ay;
  std::int64_t sx, sy; // +1 or -1
  std::int64_t dx, dy; // >= 0

  RasterFrame(Cell a, Cell b) noexcept : ax(a.x), ay(a.y) {
    const std::int64_t ddx = std::int64_t{b.x} - a.x;
    const std::int64_t ddy = std::int64_t{b.y} - a.y;
    sx = ddx < 0 ? -1 : 1;
    sy = ddy < 0 ? -1 : 1;
    dx = ddx < 0 ? -ddx : ddx;
    dy = ddy < 0 ? -ddy : ddy;
  }
  // Local (i, j) back to a cell; it lies between a and b, so it fits in int32.
  [[nodiscard]] Cell cell(std::int64_t i, std::int64_t j) const noexcept {
    return {static_cast<std::int32_t>(ax + sx * i), static_cast<std::int32_t>(ay + sy * j)};
  }
};

// Calls f and says whether to go on: a void f always goes on, a bool f goes on while it returns
// true.
template <class F>
constexpr bool visit(F& f, Cell c) {
  if constexpr (std::is_void_v<std::invoke_result_t<F&, Cell>>) {
    f(c);
    return true;
  } else {
    return static_cast<bool>(f(c));
  }
}

// Calls f for every supercover cell strictly between a and b (neither a nor b), in order; stops
// and returns false as soon as f returns false.
template <class F>
bool for_each_supercover_interior(Cell a, Cell b, F& f) {
  const RasterFrame fr(a, b);
  SupercoverWalk<std::int64_t> w(fr.dx, fr.dy);
  if (w.done()) return true;
  for (;;) {
    if (w.next() == SupercoverStep::Corner) {
      if (!visit(f, fr.cell(w.i + 1, w.j))) return false;
      if (!visit(f, fr.cell(w.i, w.j + 1))) return false;
    }
    w.advance();
    if (w.done()) return true;
    if (!visit(f, fr.cell(w.i, w.j))) return false;
  }
}

template <class F>
bool for_each_supercover_cell_until(Cell a, Cell b, F& f) {
  if (!visit(f, a)) return false;
  if (a == b) return true;
  if (!for_each_supercover_interior(a, b, f)) return false;
  return visit(f, b);
}

template <class F>
bool for_each_bresenham_cell_until(Cell a, Cell b, F& f) {
  const RasterFrame fr(a, b);
  if (!visit(f, a)) return false;
  const bool x_major = fr.dx >= fr.dy;
  BresenhamWalk<std::int64_t> w(x_major ? fr.dx : fr.dy, x_major ? fr.dy : fr.dx);
  while (!w.done()) {
    w.advance();
    if (!visit(f, x_major ? fr.cell(w.k, w.j) : fr.cell(w.j, w.k))) return false;
  }
  return true;
}

} // namespace detail

// Calls f(Cell) for every cell of the supercover from a to b, in order from a to b, each cell once
// (a once when a == b). If f returns bool, returning false stops the walk.
template <class F>
void for_each_supercover_cell(Cell a, Cell b, F&& f) {
  detail::for_each_supercover_cell_until(a, b, f);
}

// The number of supercover cells: |dx| + |dy| + 1, plus one per corner the segment passes
// through (it crosses gcd(|dx|, |dy|) corners when |dx| and |dy| are both odd after dividing by
// their gcd, and none otherwise).
[[nodiscard]] inline std::vector<Cell> supercover(Cell a, Cell b) {
  std::vector<Cell> out;
  for_each_supercover_cell(a, b, [&out](Cell c) { out.push_back(c); });
  return out;
}

// Calls f(Cell) for every cell of Bresenham's line from a to b, in order; max(|dx|, |dy|) + 1
// cells, 8-connected. If f returns bool, returning false stops the walk.
template <class F>
void for_each_bresenham_cell(Cell a, Cell b, F&& f) {
  detail::for_each_bresenham_cell_until(a, b, f);
}

[[nodiscard]] inline std::vector<Cell> bresenham(Cell a, Cell b) {
  std::vector<Cell> out;
  for_each_bresenham_cell(a, b, [&out](Cell c) { out.push_back(c); });
  return out;
}

// Line of sight between the centres of a and b: true when every cell of the supercover other than
// a and b themselves is inside the grid and not blocked. `blocked(Cell)` decides (cells off any
// grid included: it is the caller's predicate). Symmetric in a and b; no allocation.
template <class Blocked>
[[nodiscard]] bool line_of_sight(Cell a, Cell b, Blocked&& blocked) {
  auto clear = [&blocked](Cell c) { return !static_cast<bool>(blocked(c)); };
  return detail::for_each_supercover_interior(a, b, clear);
}

// On an occupancy grid: Blocked and Unknown cells block, and so do cells off the grid; a and b
// themselves never do (they may even lie off the grid).
[[nodiscard]] inline bool line_of_sight(const OccupancyGrid& grid, Cell a, Cell b) {
  // Every supercover cell lies in the bounding box of a and b, so when both are on the grid no
  // cell needs a bounds check.
  if (grid.in_bounds(a) && grid.in_bounds(b)) {
    const Occupancy* cells = grid.cells().data();
    const auto width = static_cast<std::size_t>(grid.width());
    return line_of_sight(a, b, [cells, width](Cell c) {
      return cells[static_cast<std::size_t>(c.y) * width + static_cast<std::size_t>(c.x)] !=
             Occupancy::Free;
    });
  }
  return line_of_sight(
      a, b, [&grid](Cell c) { return grid.get_or(c, Occupancy::Blocked) != Occupancy::Free; });
}

} // namespace antkit::kernel
