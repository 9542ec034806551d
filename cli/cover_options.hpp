#pragma once
// The map options shared by `antkit cover` and `antkit dev wanderer-mcu-input` (--map, or --size
// and --density; --seed, --trial, --sensor, --limit): one check and one message each, so the
// plumbing refuses what `antkit cover` refuses, the same way (exit 2), and builds the same grid.
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/world.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace antkit::cli {

// Generated maps: a side of at most 8192 cells and at most 2^26 cells in all, like map files
// (antkit/maps/map_io.hpp), so that no option can ask for more memory than a map file could.
inline constexpr std::int32_t kCoverMaxSide = 8192;
inline constexpr std::int64_t kCoverMaxCells = std::int64_t{1} << 26;
inline constexpr std::int64_t kCoverMaxRobots = 1024;

struct CoverMapOptions {
  std::string map, size, density;
  std::uint64_t seed = 1, trial = 0;
  std::int64_t sensor = 5;
  std::int64_t limit = -1; // default: 10 * W * H
};

// Refuses a map given twice or not at all, a density without --size (or --size without one), a
// number of robots, a sensor distance or a time limit out of range.
inline void check_cover_options(const CoverMapOptions& o, std::int64_t robots) {
  using antkit::kernel::InputError;
  if (o.map.empty() == o.size.empty())
    throw InputError("", "give either --map FILE or --size WxH --density P");
  if (!o.map.empty() && !o.density.empty())
    throw InputError("--density", "a map file has its own obstacles; --density goes with --size");
  if (!o.size.empty() && o.density.empty())
    throw InputError("--density", "--size needs an obstacle density, such as --density 0.2");
  if (robots < 1 || robots > kCoverMaxRobots)
    throw InputError("--robots", "expected 1 to " + std::to_string(kCoverMaxRobots) +
                                     " robots, not " + std::to_string(robots));
  if (o.sensor < 0 || o.sensor > uniform::kMaxSensorRange)
    throw InputError("--sensor", "expected a sensor distance in [0, " +
                                     std::to_string(uniform::kMaxSensorRange) + "] cells, not " +
                                     std::to_string(o.sensor));
  if (o.limit < -1) throw InputError("--limit", "expected a number of ticks >= 0");
}

struct CoverGrid {
  kernel::OccupancyGrid cells;
  std::optional<kernel::Cell> start;        // the map file's start, if it names one
  std::optional<std::uint32_t> density_ppm; // a generated grid's obstacle density
};

// The grid: the map file read, or W x H cells with the density's obstacles drawn from the seed's
// and the trial's stream.
inline CoverGrid read_cover_grid(const CoverMapOptions& o) {
  CoverGrid g;
  if (!o.map.empty()) {
    auto loaded = antkit::maps::load_map(o.map);
    g.cells = std::move(loaded.cells);
    g.start = loaded.start;
    return g;
  }
  const auto [w, h] = uniform::parse_size(o.size, kCoverMaxSide);
  if (std::int64_t{w} * h > kCoverMaxCells)
    throw kernel::InputError("--size", "at most " + std::to_string(kCoverMaxCells) +
                                           " cells, not " + std::to_string(std::int64_t{w} * h));
  g.density_ppm = uniform::parse_density_ppm(o.density);
  g.cells = uniform::random_obstacles(w, h, *g.density_ppm, o.seed, o.trial);
  return g;
}

// --limit, or 10 ticks per cell of the grid.
inline std::uint64_t cover_limit(const CoverMapOptions& o, const kernel::OccupancyGrid& grid) {
  const std::int64_t cells = std::int64_t{grid.width()} * grid.height();
  return static_cast<std::uint64_t>(o.limit >= 0 ? o.limit : 10 * cells);
}

} // namespace antkit::cli
