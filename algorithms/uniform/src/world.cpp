#include <algorithm>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/raster.hpp>
#include <antkit/uniform/coverage_rules.hpp>
#include <antkit/uniform/world.hpp>
#include <string>
#include <utility>

namespace antkit::uniform {

using kernel::Cell;
using kernel::kNeighbours8;
using kernel::Occupancy;

// coverage_rules.hpp's cell storage over CoverageWorld's grids.
struct CoverageWorld::Cells {
  const CoverageWorld& world;
  kernel::Grid<std::uint8_t>* marks = nullptr; // the viewed cells, for a view
  [[nodiscard]] bool in_bounds(Cell c) const noexcept { return world.map_.in_bounds(c); }
  [[nodiscard]] bool free_at(Cell c) const noexcept { return world.map_[c] == Occupancy::Free; }
  [[nodiscard]] bool viewed(Cell c) const noexcept { return world.viewed_[c] != 0; }
  void mark_viewed(Cell c) const noexcept { (*marks)[c] = 1; }
  // A disk views through walls, also free cells of components no robot is in: those do not
  // count for coverage. (Line of sight never reaches another component.)
  [[nodiscard]] bool counts_free(Cell c) const noexcept {
    return free_at(c) && (world.model_ == SensorModel::LineOfSight || world.is_viewable(c));
  }
  [[nodiscard]] bool sees_through() const noexcept { return world.model_ == SensorModel::Disk; }
};

SensorFootprint::SensorFootprint(std::int32_t range) : range_(range) {
  if (range < 0 || range > kMaxSensorRange)
    throw kernel::InputError("sensor distance", "the sensor distance must be an integer in [0, " +
                                                    std::to_string(kMaxSensorRange) +
                                                    "] cells, not " + std::to_string(range));
  std::vector<Cell> offsets;
  for (std::int32_t dy = -range; dy <= range; ++dy)
    for (std::int32_t dx = -range; dx <= range; ++dx)
      if (in_range({dx, dy})) offsets.push_back({dx, dy});
  // Nearest first, so that a scan for "anything new" stops early; row-major among equals.
  std::stable_sort(offsets.begin(), offsets.end(),
                   [](Cell a, Cell b) { return a.x * a.x + a.y * a.y < b.x * b.x + b.y * b.y; });
  const auto side = static_cast<std::size_t>(2 * range + 1);
  lookup_.assign(side * side, 0);
  for (const Cell d : offsets) {
    Ray ray{d, static_cast<std::uint32_t>(between_.size()), 0};
    const Cell origin{0, 0};
    kernel::for_each_supercover_cell(origin, d, [&](Cell c) {
      if (c != origin && c != d) between_.push_back(c);
    });
    ray.count = static_cast<std::uint32_t>(between_.size()) - ray.first;
    lookup_[static_cast<std::size_t>(d.y + range) * side + static_cast<std::size_t>(d.x + range)] =
        static_cast<std::uint32_t>(rays_.size());
    rays_.push_back(ray);
  }
}

CoverageWorld::CoverageWorld(kernel::OccupancyGrid map, std::vector<Pose> robots,
                             std::int32_t sensor_range, SensorModel model)
    : map_(std::move(map)), footprint_(sensor_range), model_(model), robots_(std::move(robots)),
      viewed_(map_.width(), map_.height(), 0), occupant_(map_.width(), map_.height(), 0),
      exits_(map_.width(), map_.height(), 0), components_(free_components(map_)) {
  if (map_.size() > 0xFFFFFFFFu)
    throw kernel::InputError("map size", "the map must have fewer than 2^32 cells");
  for (std::size_t k = 0; k < map_.size(); ++k) {
    const Cell c = map_.cell_at(k);
    std::uint8_t bits = 0;
    for (std::uint8_t b = 0; b < 8; ++b)
      if (passable_step_rule(c, b, [this](Cell n) { return is_free(n); }))
        bits = static_cast<std::uint8_t>(bits | (1u << b));
    exits_.cells()[k] = bits;
  }
  if (robots_.size() >= 0xFFFFu)
    throw kernel::InputError("robots", "at most 65534 robots are supported");
  viewable_label_.assign(components_.size.size(), 0);
  for (std::size_t i = 0; i < robots_.size(); ++i) {
    const Cell c = robots_[i].cell;
    if (!is_free(c))
      throw kernel::InputError("start", "robot " + std::to_string(i) + " at (" +
                                            std::to_string(c.x) + ", " + std::to_string(c.y) +
                                            ") does not stand on a free cell");
    if (occupant_[c] != 0)
      throw kernel::InputError("start", "robots " + std::to_string(occupant_[c] - 1) + " and " +
                                            std::to_string(i) + " share the cell (" +
                                            std::to_string(c.x) + ", " + std::to_string(c.y) + ")");
    robots_[i].bearing &= 7u;
    occupant_[c] = static_cast<std::uint16_t>(i + 1);
    const std::uint32_t l = components_.label[c];
    if (viewable_label_[l] == 0) {
      viewable_label_[l] = 1;
      viewable_ += components_.size[l];
    }
  }
  for (std::size_t i = 0; i < robots_.size(); ++i) view(i);
}

bool CoverageWorld::clear_ray(Cell from, const SensorFootprint::Ray& ray) const noexcept {
  return ray_clear(Cells{*this}, from, ray, footprint_.between().data());
}

bool CoverageWorld::in_view(Cell from, Cell target) const noexcept {
  // Bounds first: only then is the difference of the two cells free of overflow.
  if (!map_.in_bounds(from) || !map_.in_bounds(target)) return false;
  const Cell d = target - from;
  return footprint_.in_range(d) && clear_ray(from, footprint_.ray(d));
}

bool CoverageWorld::would_view_new(Cell from) const noexcept {
  if (!map_.in_bounds(from)) return false;
  return would_view_new_from(Cells{*this}, from, footprint_.rays(), footprint_.between().data());
}

bool CoverageWorld::turn(std::size_t robot, int eighths) noexcept {
  auto& b = robots_[robot].bearing;
  b = turned_bearing(b, eighths);
  return true;
}

bool CoverageWorld::move(std::size_t robot, std::uint8_t bearing) noexcept {
  Pose& p = robots_[robot];
  bearing &= 7u;
  if (!can_step(p.cell, bearing)) return false;
  p.bearing = bearing;
  occupant_[p.cell] = 0;
  p.cell = p.cell + kNeighbours8[bearing];
  occupant_[p.cell] = static_cast<std::uint16_t>(robot + 1);
  return true;
}

std::uint32_t CoverageWorld::view(std::size_t robot) noexcept {
  Cells cells{*this, &viewed_};
  return view_from(cells, robots_[robot].cell, footprint_.rays(), footprint_.between().data(),
                   counts_);
}

void CoverageWorld::hash_state(kernel::TraceHash& hash) const noexcept {
  for (const Pose& p : robots_) hash_pose(hash, p.cell, p.bearing);
  hash_counts(hash, counts_);
}

} // namespace antkit::uniform
