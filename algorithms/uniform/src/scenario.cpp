#include <algorithm>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/uniform/scenario.hpp>
#include <string>
#include <utility>

namespace antkit::uniform {

using kernel::Cell;
using kernel::Occupancy;
using kernel::OccupancyGrid;

std::uint64_t obstacle_count(std::int32_t width, std::int32_t height,
                             std::uint32_t density_ppm) noexcept {
  const std::uint64_t cells = static_cast<std::uint64_t>(width < 0 ? 0 : width) *
                              static_cast<std::uint64_t>(height < 0 ? 0 : height);
  // cells < 2^40 and density_ppm <= 10^6 < 2^20: the product fits in 64 bits.
  return (cells * density_ppm + kPpm / 2) / kPpm;
}

OccupancyGrid random_obstacles(std::int32_t width, std::int32_t height, std::uint32_t density_ppm,
                               std::uint64_t seed, std::uint64_t trial) {
  if (density_ppm > kPpm)
    throw kernel::InputError("obstacle density", "the obstacle density must lie in [0, 1]");
  OccupancyGrid grid(width, height, Occupancy::Free);
  const std::size_t n = grid.size();
  const auto blocked = static_cast<std::size_t>(obstacle_count(width, height, density_ppm));
  kernel::Stream stream(seed, kStreamExperiment, trial, 0,
                        static_cast<std::uint64_t>(StreamPurpose::Obstacles));
  // Partial Fisher-Yates over the cell indices: the first `blocked` entries become a uniform
  // sample without replacement. Indices fit 32 bits because the grid side is below 2^20... and the
  // product below 2^32 is checked here, since below() takes a 32-bit bound.
  if (n > 0xFFFFFFFFu)
    throw kernel::InputError("map size", "the grid must have fewer than 2^32 cells");
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
  for (std::size_t i = 0; i < blocked; ++i) {
    const std::size_t j = i + stream.below(static_cast<std::uint32_t>(n - i));
    std::swap(order[i], order[j]);
    grid.cells()[order[i]] = Occupancy::Blocked;
  }
  return grid;
}

FreeComponents free_components(const OccupancyGrid& map) {
  FreeComponents out{kernel::Grid<std::uint32_t>(map.width(), map.height(), 0), {0}};
  std::vector<std::uint32_t> stack;
  for (std::size_t start = 0; start < map.size(); ++start) {
    if (map.cells()[start] != Occupancy::Free || out.label.cells()[start] != 0) continue;
    const auto label = static_cast<std::uint32_t>(out.size.size());
    std::uint64_t size = 0;
    out.label.cells()[start] = label;
    stack.assign(1, static_cast<std::uint32_t>(start));
    while (!stack.empty()) {
      const Cell c = map.cell_at(stack.back());
      stack.pop_back();
      ++size;
      for (const Cell d : kernel::kNeighbours4) {
        const Cell n = c + d;
        if (!map.in_bounds(n) || map[n] != Occupancy::Free || out.label[n] != 0) continue;
        out.label[n] = label;
        stack.push_back(static_cast<std::uint32_t>(map.index(n)));
      }
    }
    out.size.push_back(size);
  }
  return out;
}

std::vector<Pose> place_robots(const OccupancyGrid& map, std::size_t robots,
                               std::optional<Cell> start, std::uint64_t seed, std::uint64_t trial) {
  const FreeComponents comps = free_components(map);
  std::uint32_t label = 0;
  if (start) {
    if (!map.in_bounds(*start) || map[*start] != Occupancy::Free)
      throw kernel::InputError("start", "the start cell (" + std::to_string(start->x) + ", " +
                                            std::to_string(start->y) +
                                            ") is not a free cell of the map");
    label = comps.label[*start];
  } else {
    for (std::uint32_t l = 1; l < comps.size.size(); ++l)
      if (label == 0 || comps.size[l] > comps.size[label]) label = l;
    if (label == 0) throw kernel::InputError("start", "the map has no free cell to start on");
  }
  if (robots > comps.size[label])
    throw kernel::InputError("robots", "asked for " + std::to_string(robots) +
                                           " robots but their free region has only " +
                                           std::to_string(comps.size[label]) + " cells");
  std::vector<std::uint32_t> cells;
  cells.reserve(comps.size[label]);
  for (std::size_t i = 0; i < map.size(); ++i)
    if (comps.label.cells()[i] == label) cells.push_back(static_cast<std::uint32_t>(i));
  kernel::Stream stream(seed, kStreamExperiment, trial, 0,
                        static_cast<std::uint64_t>(StreamPurpose::Starts));
  std::vector<Pose> poses;
  poses.reserve(robots);
  std::size_t taken = 0;
  if (start && robots > 0) {
    // The map's start cell is robot 0's; it leaves the pool so that no other robot draws it.
    const auto it =
        std::find(cells.begin(), cells.end(), static_cast<std::uint32_t>(map.index(*start)));
    std::swap(*it, cells[0]);
    poses.push_back({*start, static_cast<std::uint8_t>(stream.below(8))});
    taken = 1;
  }
  for (std::size_t i = taken; i < robots; ++i) {
    const std::size_t j = i + stream.below(static_cast<std::uint32_t>(cells.size() - i));
    std::swap(cells[i], cells[j]);
    poses.push_back({map.cell_at(cells[i]), static_cast<std::uint8_t>(stream.below(8))});
  }
  return poses;
}

std::uint32_t parse_density_ppm(std::string_view text) {
  const auto bad = [&]() -> kernel::InputError {
    return kernel::InputError("obstacle density",
                              "expected a fraction in [0, 1] such as 0.2 (at most six "
                              "decimals) or a percentage such as 20%, not '" +
                                  std::string(text) + "'");
  };
  const bool percent = !text.empty() && text.back() == '%';
  if (percent) text.remove_suffix(1);
  const int max_decimals = percent ? 4 : 6;
  std::uint64_t whole = 0, frac = 0;
  int decimals = 0, digits = 0;
  bool point = false;
  for (const char ch : text) {
    if (ch == '.' && !point) {
      point = true;
    } else if (ch >= '0' && ch <= '9') {
      ++digits;
      if (point) {
        if (++decimals > max_decimals) throw bad();
        frac = frac * 10 + static_cast<std::uint64_t>(ch - '0');
      } else {
        whole = whole * 10 + static_cast<std::uint64_t>(ch - '0');
        if (whole > 1000) throw bad();
      }
    } else {
      throw bad();
    }
  }
  if (digits == 0) throw bad();
  for (; decimals < max_decimals; ++decimals) frac *= 10;
  // A fraction has 10^6 ppm per unit; a percentage 10^4 ppm per percent.
  const std::uint64_t ppm = percent ? whole * 10'000 + frac : whole * 1'000'000 + frac;
  if (ppm > kPpm) throw bad();
  return static_cast<std::uint32_t>(ppm);
}

std::pair<std::int32_t, std::int32_t> parse_size(std::string_view text, std::int32_t max_side) {
  const auto bad = [&]() -> kernel::InputError {
    return kernel::InputError(
        "map size", "expected WxH with W and H integers in [1, " + std::to_string(max_side) +
                        "], such as 100x100, not '" + std::string(text) + "'");
  };
  const auto x = text.find_first_of("xX");
  if (x == std::string_view::npos) throw bad();
  const auto number = [&](std::string_view part) {
    if (part.empty() || part.size() > 9) throw bad();
    std::int64_t v = 0;
    for (const char ch : part) {
      if (ch < '0' || ch > '9') throw bad();
      v = v * 10 + (ch - '0');
    }
    if (v < 1 || v > max_side) throw bad();
    return static_cast<std::int32_t>(v);
  };
  return {number(text.substr(0, x)), number(text.substr(x + 1))};
}

} // namespace antkit::uniform
