#pragma once
// The simulated world of paper 004: the true map, the robots' poses, and the one communal map of
// viewed cells that all robots share.
//
// The sensor. A robot views every cell within Euclidean distance r (an integer number of cells,
// the paper's "sensor distance ... in relation to the robot's size" with a robot one cell wide) of
// its own cell's centre, dx^2 + dy^2 <= r^2, to which it has line of sight by the kernel's rule
// (kernel::line_of_sight: every supercover cell strictly between the two centres is on the grid
// and Free; Blocked and Unknown cells block). The sensor sees all round: the bearing does not
// narrow it (the paper's figures colour a disc of sensor cells around each robot). Robots do not
// block one another's view (the paper's sensors read the map, not each other).
//
// Viewing marks every cell in view, free or not: an obstacle that has been seen is explored.
// Coverage counts only free cells: viewed free cells over viewable free cells, where the viewable
// free cells are the 4-connected free components that hold a robot. That is exact, not an
// estimate: every supercover cell strictly between two cells is Free when there is line of sight,
// and consecutive supercover cells share an edge (the corner rule adds both side cells), so a
// free cell in view of a robot lies in the robot's 4-connected component; and a robot stands on,
// and so views, every cell of its component it can reach (see can_step), which is all of it.
//
// The movement, view and hash rules for one robot are coverage_rules.hpp's, which the Cortex-M
// image's one-robot world (step_turn_world.hpp) shares.
//
// Movement. A robot moves one cell along its bearing. The target must be on the map, Free, and
// not occupied by another robot; a diagonal move also needs both side cells Free (no corner
// cutting: the same rule by which a diagonal gap between two obstacles blocks line of sight, so a
// robot only ever moves to a cell it can see). Two robots never occupy one cell.
//
// Precomputation. The supercover of the segment between two cell centres depends only on their
// offset, so the cells between the centre and each footprint offset are computed once per range
// (SensorFootprint) with kernel::supercover; a line-of-sight test is then a scan of a short
// precomputed list. The tests hold this against kernel::line_of_sight cell by cell.
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/uniform/coverage_rules.hpp>
#include <antkit/uniform/scenario.hpp>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace antkit::uniform {

// The largest sensor range accepted: a footprint of about pi * 255^2 offsets.
inline constexpr std::int32_t kMaxSensorRange = 255;

class SensorFootprint {
public:
  // One offset in range and the cells strictly between the centre and it: between[first, first +
  // count) of between().
  struct Ray {
    kernel::Cell offset;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    friend constexpr kernel::Cell offset_of(const Ray& ray) noexcept { return ray.offset; }
  };

  // Throws kernel::InputError (where "sensor distance") unless 0 <= range <= kMaxSensorRange.
  explicit SensorFootprint(std::int32_t range);

  [[nodiscard]] std::int32_t range() const noexcept { return range_; }
  // Rays in a fixed order: by dx^2 + dy^2, then by row-major offset (y, then x). The first ray is
  // the robot's own cell.
  [[nodiscard]] const std::vector<Ray>& rays() const noexcept { return rays_; }
  [[nodiscard]] const std::vector<kernel::Cell>& between() const noexcept { return between_; }
  // Whether offset d is within range: dx^2 + dy^2 <= r^2.
  [[nodiscard]] bool in_range(kernel::Cell d) const noexcept {
    const std::int64_t dx = d.x, dy = d.y;
    return dx * dx + dy * dy <= std::int64_t{range_} * range_;
  }
  // The ray of an offset in range; precondition in_range(d).
  [[nodiscard]] const Ray& ray(kernel::Cell d) const noexcept {
    return rays_[lookup_[static_cast<std::size_t>((d.y + range_) * (2 * range_ + 1) +
                                                  (d.x + range_))]];
  }

private:
  std::int32_t range_;
  std::vector<Ray> rays_;
  std::vector<kernel::Cell> between_;
  std::vector<std::uint32_t> lookup_; // (2r+1)^2 offsets -> index into rays_
};

// What the sensor needs to view a cell in range: line of sight (the model above, the default), or
// nothing (Disk: every cell within the range is viewed, through walls). Disk exists to test paper
// 004's numbers against a sensor that sees through obstacles (issue 15); nothing else uses it.
enum class SensorModel : std::uint8_t { LineOfSight, Disk };

class CoverageWorld {
public:
  // `robots` must stand on distinct Free cells of `map` (a grid of at most 2^32 - 1 cells); throws
  // kernel::InputError otherwise.
  // Every robot views its surroundings once, in index order, before the first tick.
  CoverageWorld(kernel::OccupancyGrid map, std::vector<Pose> robots, std::int32_t sensor_range,
                SensorModel model = SensorModel::LineOfSight);

  [[nodiscard]] const kernel::OccupancyGrid& map() const noexcept { return map_; }
  [[nodiscard]] const SensorFootprint& footprint() const noexcept { return footprint_; }
  [[nodiscard]] SensorModel sensor_model() const noexcept { return model_; }
  [[nodiscard]] std::size_t robot_count() const noexcept { return robots_.size(); }
  [[nodiscard]] const std::vector<Pose>& robots() const noexcept { return robots_; }
  [[nodiscard]] const Pose& robot(std::size_t i) const noexcept { return robots_[i]; }
  [[nodiscard]] std::uint8_t bearing(std::size_t i) const noexcept { return robots_[i].bearing; }

  // The communal map: 1 where a cell has been viewed.
  [[nodiscard]] const kernel::Grid<std::uint8_t>& viewed() const noexcept { return viewed_; }
  [[nodiscard]] bool is_viewed(kernel::Cell c) const noexcept { return viewed_[c] != 0; }
  // The 4-connected free component of each cell (0: not free), as free_components().
  [[nodiscard]] const kernel::Grid<std::uint32_t>& component() const noexcept {
    return components_.label;
  }
  // Whether a cell is a free cell that counts for coverage (its component holds a robot).
  [[nodiscard]] bool is_viewable(kernel::Cell c) const noexcept {
    const std::uint32_t l = components_.label[c];
    return l != 0 && viewable_label_[l] != 0;
  }
  [[nodiscard]] std::uint64_t viewable() const noexcept { return viewable_; }
  [[nodiscard]] std::uint64_t viewed_free() const noexcept { return counts_.free; }
  [[nodiscard]] bool complete() const noexcept { return counts_.free == viewable_; }

  [[nodiscard]] bool is_free(kernel::Cell c) const noexcept {
    return map_.in_bounds(c) && map_[c] == kernel::Occupancy::Free;
  }
  // Index of the robot on c plus one, or 0.
  [[nodiscard]] std::uint16_t occupant(kernel::Cell c) const noexcept {
    return map_.in_bounds(c) ? occupant_[c] : 0;
  }
  // Whether a robot on `from` may move to its neighbour at bearing b on the map alone (robots
  // ignored): see Movement above.
  // Precondition: `from` is on the map.
  [[nodiscard]] bool passable_step(kernel::Cell from, std::uint8_t bearing) const noexcept {
    return ((static_cast<unsigned>(exits_[from]) >> (bearing & 7u)) & 1u) != 0;
  }
  // The grids behind occupant() and passable_step(), for searches that walk cell indices.
  [[nodiscard]] const kernel::Grid<std::uint16_t>& occupants() const noexcept { return occupant_; }
  [[nodiscard]] const kernel::Grid<std::uint8_t>& exits() const noexcept { return exits_; }
  // passable_step and the target holds no robot.
  [[nodiscard]] bool can_step(kernel::Cell from, std::uint8_t bearing) const noexcept {
    return passable_step(from, bearing) && occupant(from + kernel::kNeighbours8[bearing & 7u]) == 0;
  }
  // Whether `target` is in view from `from` (in range and line of sight).
  [[nodiscard]] bool in_view(kernel::Cell from, kernel::Cell target) const noexcept;
  // Whether a robot standing on `from` would view at least one cell not yet viewed.
  [[nodiscard]] bool would_view_new(kernel::Cell from) const noexcept;

  // Changes of the world. Each returns whether it happened; a move that the rules forbid does
  // nothing (the body, not the controller, is the authority on what is possible).
  bool turn(std::size_t robot, int eighths) noexcept;
  bool move(std::size_t robot, std::uint8_t bearing) noexcept; // faces `bearing`, then steps
  // Marks what robot i views from where it stands; returns how many cells were newly viewed.
  std::uint32_t view(std::size_t robot) noexcept;

  // Appends the canonical state (every pose, the count of viewed cells and of viewed free cells)
  // to a trace hash.
  void hash_state(kernel::TraceHash& hash) const noexcept;

private:
  struct Cells; // coverage_rules.hpp's storage over the grids below
  [[nodiscard]] bool clear_ray(kernel::Cell from, const SensorFootprint::Ray& ray) const noexcept;

  kernel::OccupancyGrid map_;
  SensorFootprint footprint_;
  SensorModel model_ = SensorModel::LineOfSight;
  std::vector<Pose> robots_;
  kernel::Grid<std::uint8_t> viewed_;
  kernel::Grid<std::uint16_t> occupant_;
  kernel::Grid<std::uint8_t> exits_; // bit b: passable_step(c, b), computed once
  FreeComponents components_;
  std::vector<std::uint8_t> viewable_label_;
  std::uint64_t viewable_ = 0;
  ViewCounts counts_; // every viewed cell, and the viewed free cells that count
};

} // namespace antkit::uniform
