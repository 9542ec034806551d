#pragma once
// The environment of paper 004 (Tyler & Hettiarachchi, "A comparative analysis of three algorithms
// for uniform coverage"): a W x H grid with a given obstacle density, robots that stand on distinct
// free cells and hold one of the eight bearings.
//
// Choices the paper leaves open, made here:
//   * Obstacle density is given in parts per million (an exact integer, so that a decision never
//     depends on rounding a binary fraction): exactly round(ppm * W * H / 10^6) cells are blocked,
//     halves rounded up, chosen uniformly without replacement (a partial Fisher-Yates shuffle of
//     the cell indices) from the keyed stream (seed, kStreamExperiment, trial, 0, Obstacles).
//   * The free space is NOT forced to be connected. Robots start in one 4-connected free component
//     (the one holding the map's start cell if it has one, otherwise the largest, ties to the one
//     whose first cell comes first in row-major order), on distinct cells drawn uniformly without
//     replacement from that component in row-major order, each with a bearing drawn uniformly from
//     0..7, all from the keyed stream (seed, kStreamExperiment, trial, 0, Starts). Free cells that
//     no robot can reach are not "viewable" and do not count against coverage.
//   * Bearing b faces kernel::kNeighbours8[b]: 0 is east (+x) and each step turns 45 degrees
//     counter-clockwise as drawn, which is the paper's Figure 1 with the grid's rows drawn
//     downward.
#include <antkit/kernel/grid.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace antkit::uniform {

// The experiment word of every keyed stream this family draws from (issue 6).
inline constexpr std::uint64_t kStreamExperiment = 6;

// The purpose word of the keyed streams (kernel::Stream's fifth key).
enum class StreamPurpose : std::uint64_t {
  Obstacles = 1,      // obstacle placement (robot word 0)
  Starts = 2,         // start cells and bearings (robot word 0)
  RandomWanderer = 3, // the random wanderer's 0/1/2 draws (robot word = robot index)
  Unstick = 4,        // A*'s and frontier's way out of a standoff (robot word = robot index)
};

inline constexpr std::uint32_t kPpm = 1'000'000; // density 1.0 in parts per million

struct Pose {
  kernel::Cell cell;
  std::uint8_t bearing = 0; // 0..7, see above
  friend constexpr bool operator==(Pose, Pose) = default;
};

// round(density_ppm * width * height / 10^6), halves up. density_ppm <= kPpm.
[[nodiscard]] std::uint64_t obstacle_count(std::int32_t width, std::int32_t height,
                                           std::uint32_t density_ppm) noexcept;

// A width x height grid with exactly obstacle_count(...) Blocked cells, the rest Free.
// Throws kernel::InputError (where "obstacle density") if density_ppm > kPpm.
[[nodiscard]] kernel::OccupancyGrid random_obstacles(std::int32_t width, std::int32_t height,
                                                     std::uint32_t density_ppm, std::uint64_t seed,
                                                     std::uint64_t trial);

// The 4-connected components of the Free cells. label[c] is 0 for a cell that is not Free and
// 1, 2, ... otherwise, numbered in the row-major order of each component's first cell;
// size[l] is the number of cells labelled l (size[0] is 0).
struct FreeComponents {
  kernel::Grid<std::uint32_t> label;
  std::vector<std::uint64_t> size;
};
[[nodiscard]] FreeComponents free_components(const kernel::OccupancyGrid& map);

// `robots` start poses as described above. Throws kernel::InputError (where "robots") when the
// component holds fewer free cells than robots, and (where "start") when `start` is off the map or
// not Free, or when the map has no free cell.
[[nodiscard]] std::vector<Pose> place_robots(const kernel::OccupancyGrid& map, std::size_t robots,
                                             std::optional<kernel::Cell> start, std::uint64_t seed,
                                             std::uint64_t trial);

// Parses an obstacle density, exactly: a decimal fraction in [0, 1] with at most six decimals
// ("0.2", "0", "1", ".25") or a percentage in [0, 100] with at most four decimals ("20%",
// "12.5%"); returns parts per million. Throws kernel::InputError (where "obstacle density")
// otherwise.
[[nodiscard]] std::uint32_t parse_density_ppm(std::string_view text);

// Parses "WxH" (or "WXH"): two decimal integers in [1, max_side]; throws kernel::InputError
// (where "map size") otherwise.
[[nodiscard]] std::pair<std::int32_t, std::int32_t> parse_size(std::string_view text,
                                                               std::int32_t max_side);

} // namespace antkit::uniform
