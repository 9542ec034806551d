#pragma once
// Paper 004's per-robot world rules, written once (issue 27): the movement rule, the turn, the
// sensor's view from one cell and the state a tick hashes. CoverageWorld (world.hpp: any number
// of robots, cells in kernel::Grid bytes) and StepTurnWorld (step_turn_world.hpp: one robot on
// the Cortex-M image, cells as bits in caller storage) both call these; neither restates them.
//
// Freestanding: templates over the caller's cell storage, no allocation, no exception, no I/O.
// A storage (`Cells`) answers, for cells on the map:
//   bool in_bounds(Cell)        whether the cell lies on the map
//   bool free_at(Cell)          whether the cell is Free (precondition: in_bounds)
//   bool viewed(Cell)           whether the cell has been viewed (precondition: in_bounds)
//   void mark_viewed(Cell)      marks it viewed (precondition: in_bounds)
//   bool counts_free(Cell)      whether a newly viewed cell counts as a viewed free cell
//   bool sees_through() const   true when the sensor needs no line of sight (SensorModel::Disk)
// and a footprint is a range of rays (offset_of(ray), ray.first, ray.count) over a list of cells
// between (offset_of(cell)), as SensorFootprint lays them out (world.hpp).
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/hash.hpp>
#include <cstdint>

namespace antkit::uniform {

// A cell between as an offset (SensorFootprint's list); other layouts overload offset_of beside
// their type (step_turn_world.hpp).
[[nodiscard]] constexpr kernel::Cell offset_of(kernel::Cell c) noexcept {
  return c;
}

// The running counts a view updates and a tick hashes: every cell viewed, and the viewed free
// cells that count for coverage.
struct ViewCounts {
  std::uint64_t cells = 0;
  std::uint64_t free = 0;
};

// Movement (world.hpp): the neighbour at `bearing` must be on the map and Free; a diagonal move
// also needs both side cells Free (no corner cutting). Robots are not considered here.
template <class IsFree>
[[nodiscard]] constexpr bool passable_step_rule(kernel::Cell from, std::uint8_t bearing,
                                                const IsFree& is_free) noexcept {
  const kernel::Cell d = kernel::kNeighbours8[bearing & 7u];
  if (!is_free(from + d)) return false;
  return d.x == 0 || d.y == 0 ||
         (is_free({from.x + d.x, from.y}) && is_free({from.x, from.y + d.y}));
}

// The bearing after turning by `eighths` of a full turn (positive: counter-clockwise).
[[nodiscard]] constexpr std::uint8_t turned_bearing(std::uint8_t bearing, int eighths) noexcept {
  return static_cast<std::uint8_t>((bearing + static_cast<unsigned>(eighths % 8 + 8)) & 7u);
}

// Line of sight along a ray: every cell between is Free. Every cell between lies in the box of
// `from` and the ray's target, so both on the map keep every read on it.
template <class Cells, class Ray, class Offset>
[[nodiscard]] bool ray_clear(const Cells& cells, kernel::Cell from, const Ray& ray,
                             const Offset* between) noexcept {
  if (cells.sees_through()) return true;
  for (std::uint32_t k = 0; k < ray.count; ++k)
    if (!cells.free_at(from + offset_of(between[ray.first + k]))) return false;
  return true;
}

// Marks what a robot on `from` views, ray by ray in the footprint's order; returns how many cells
// were newly viewed and adds them to `counts`.
template <class Cells, class Rays, class Offset>
std::uint32_t view_from(Cells& cells, kernel::Cell from, const Rays& rays, const Offset* between,
                        ViewCounts& counts) noexcept {
  std::uint32_t fresh = 0;
  for (const auto& ray : rays) {
    const kernel::Cell c = from + offset_of(ray);
    if (!cells.in_bounds(c) || cells.viewed(c) || !ray_clear(cells, from, ray, between)) continue;
    cells.mark_viewed(c);
    ++fresh;
    if (cells.counts_free(c)) ++counts.free;
  }
  counts.cells += fresh;
  return fresh;
}

// Whether a robot on `from` would view at least one cell not yet viewed.
template <class Cells, class Rays, class Offset>
[[nodiscard]] bool would_view_new_from(const Cells& cells, kernel::Cell from, const Rays& rays,
                                       const Offset* between) noexcept {
  for (const auto& ray : rays) {
    const kernel::Cell c = from + offset_of(ray);
    if (cells.in_bounds(c) && !cells.viewed(c) && ray_clear(cells, from, ray, between)) return true;
  }
  return false;
}

// The state a tick hashes: every robot's pose in index order (hash_pose), then the counts.
inline void hash_pose(kernel::TraceHash& hash, kernel::Cell cell, std::uint8_t bearing) noexcept {
  hash.add_i32(cell.x).add_i32(cell.y).add_u8(bearing);
}
inline void hash_counts(kernel::TraceHash& hash, const ViewCounts& counts) noexcept {
  hash.add_u64(counts.cells).add_u64(counts.free);
}

} // namespace antkit::uniform
