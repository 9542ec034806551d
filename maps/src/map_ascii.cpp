// ASCII maps: `.` free, `#` blocked, `S` the start (free), `?` unknown. Reading and writing; the
// choices are listed in antkit/maps/map_io.hpp.
#include <antkit/maps/detail/text_scan.hpp>
#include <antkit/maps/map_io.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

namespace antkit::maps {

GridMap parse_ascii(std::string_view text, const std::string& name) {
  using detail::fail;
  GridMap map;
  std::vector<kernel::Occupancy> cells;
  std::size_t width = 0;
  std::int32_t y = 0;
  std::optional<detail::Position> start_at;
  std::optional<detail::Line> first_blank;
  // One pass, row by row, so that nothing is allocated beyond the cells actually present.
  detail::LineReader lines(text);
  while (const auto line = lines.next()) {
    if (line->text.empty()) {
      // Blank lines after the last row are tolerated (an editor's extra newline).
      if (!first_blank) first_blank = line;
      continue;
    }
    if (first_blank)
      fail(name, first_blank->number, 1,
           "a blank line inside the map; expected every row to have " +
               (width ? std::to_string(width) : std::string("the same number of")) + " cells");
    if (y == 0) width = line->text.size();
    const auto problem = detail::size_problem(width, static_cast<std::uint64_t>(y) + 1);
    if (!problem.empty()) fail(name, line->number, 1, problem);
    if (line->text.size() != width)
      fail(name, line->number, std::min(line->text.size(), width) + 1,
           "row " + std::to_string(y) + " has " + std::to_string(line->text.size()) +
               " cells; expected " + std::to_string(width) + " (the length of the first row)");
    for (std::size_t x = 0; x < width; ++x) {
      switch (line->text[x]) {
      case '.':
        cells.push_back(kernel::Occupancy::Free);
        break;
      case '#':
        cells.push_back(kernel::Occupancy::Blocked);
        break;
      case '?':
        cells.push_back(kernel::Occupancy::Unknown);
        break;
      case 'S':
        if (start_at)
          fail(name, line->number, x + 1,
               "a second start cell S (the first is at " + std::to_string(start_at->line) + ":" +
                   std::to_string(start_at->column) + "); expected at most one");
        start_at = detail::Position{line->number, x + 1};
        map.start = kernel::Cell{static_cast<std::int32_t>(x), y};
        cells.push_back(kernel::Occupancy::Free);
        break;
      default:
        fail(name, line->number, x + 1,
             "unexpected cell " + detail::quoted(line->text.substr(x, 1)) +
                 "; expected one of . (free) # (blocked) S (start) ? (unknown)");
      }
    }
    ++y;
  }
  if (y == 0)
    fail(name, 1, 1,
         "the map is empty; expected rows of . (free) # (blocked) S (start) ? (unknown)");
  map.cells = kernel::OccupancyGrid(static_cast<std::int32_t>(width), y);
  map.cells.cells() = std::move(cells);
  return map;
}

std::string write_ascii(const GridMap& map) {
  const auto& g = map.cells;
  if (g.empty()) throw std::invalid_argument("write_ascii: the map has no cells");
  if (map.start && g.get_or(*map.start, kernel::Occupancy::Blocked) != kernel::Occupancy::Free)
    throw std::invalid_argument("write_ascii: the start cell is not a free cell of the map");
  std::string out;
  out.reserve(g.size() + static_cast<std::size_t>(g.height()));
  for (std::int32_t y = 0; y < g.height(); ++y) {
    for (std::int32_t x = 0; x < g.width(); ++x) {
      const kernel::Cell c{x, y};
      if (map.start && *map.start == c) {
        out += 'S';
        continue;
      }
      switch (g[c]) {
      case kernel::Occupancy::Free:
        out += '.';
        break;
      case kernel::Occupancy::Blocked:
        out += '#';
        break;
      case kernel::Occupancy::Unknown:
        out += '?';
        break;
      }
    }
    out += '\n';
  }
  return out;
}

} // namespace antkit::maps
