#pragma once
// The exact oracle the rasterization and line-of-sight tests hold the kernel against.
#include <algorithm>
#include <antkit/kernel/grid.hpp>
#include <cstdint>

namespace antkit::test {

// Does the closed segment between the centres of a and b touch the closed square of cell c?
// Doubled coordinates make everything integral: the segment runs from 2a to 2b and the square is
// [2c - 1, 2c + 1] in each axis. Two convex sets are disjoint iff some axis separates them; for a
// segment and an axis-aligned square the candidate axes are x, y and the segment's normal. The
// normal separates iff all four corners lie strictly on one side of the segment's line.
inline bool oracle_touches(kernel::Cell a, kernel::Cell b, kernel::Cell c) {
  const std::int64_t px = 2 * std::int64_t{a.x}, py = 2 * std::int64_t{a.y};
  const std::int64_t qx = 2 * std::int64_t{b.x}, qy = 2 * std::int64_t{b.y};
  const std::int64_t x0 = 2 * std::int64_t{c.x} - 1, x1 = x0 + 2;
  const std::int64_t y0 = 2 * std::int64_t{c.y} - 1, y1 = y0 + 2;
  if (std::max(px, qx) < x0 || std::min(px, qx) > x1) return false;
  if (std::max(py, qy) < y0 || std::min(py, qy) > y1) return false;
  int pos = 0, neg = 0;
  for (std::int64_t x : {x0, x1})
    for (std::int64_t y : {y0, y1}) {
      const std::int64_t cross = (qx - px) * (y - py) - (qy - py) * (x - px);
      pos += cross > 0 ? 1 : 0;
      neg += cross < 0 ? 1 : 0;
    }
  return !(pos == 4 || neg == 4);
}

} // namespace antkit::test
