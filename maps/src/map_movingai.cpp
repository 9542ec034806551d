// MovingAI `.map` files (Sturtevant, "Benchmarks for Grid-Based Pathfinding"): reading and
// writing. The choices where the format is silent are listed in antkit/maps/map_io.hpp.
#include <antkit/maps/detail/text_scan.hpp>
#include <antkit/maps/map_io.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

namespace antkit::maps {

namespace {

using detail::fail;

struct Token {
  std::string_view text;
  std::size_t column = 0; // from 1
};

// The blank-separated words of a header line, with their columns.
std::vector<Token> words(const detail::Line& line) {
  std::vector<Token> out;
  std::size_t i = 0;
  const auto s = line.text;
  while (i < s.size()) {
    while (i < s.size() && detail::is_blank(s[i])) ++i;
    const auto start = i;
    while (i < s.size() && !detail::is_blank(s[i])) ++i;
    if (i > start) out.push_back({s.substr(start, i - start), start + 1});
  }
  return out;
}

std::optional<kernel::Occupancy> movingai_cell(char c) {
  switch (c) {
  case '.':
  case 'G':
  case 'S': // swamp: passable from regular terrain (not a start cell in this format)
    return kernel::Occupancy::Free;
  case '@':
  case 'O':
  case 'T':
  case 'W': // water: not passable from regular terrain, so blocked (map_io.hpp)
    return kernel::Occupancy::Blocked;
  default:
    return std::nullopt;
  }
}

} // namespace

GridMap parse_movingai(std::string_view text, const std::string& name) {
  detail::LineReader lines(text);
  auto header_line = [&](const char* expected) {
    auto line = lines.next();
    if (!line) {
      const auto p = detail::position_of(text, text.size());
      fail(name, p.line, p.column,
           std::string("the file ends inside the header; expected `") + expected + "`");
    }
    return *line;
  };

  const auto type_line = header_line("type octile");
  const auto type = words(type_line);
  if (type.empty() || type[0].text != "type")
    fail(name, type_line.number, type.empty() ? 1 : type[0].column,
         "expected `type octile` as the first line of a MovingAI map");
  if (type.size() != 2 || type[1].text != "octile")
    fail(name, type_line.number, type.size() > 1 ? type[1].column : type_line.text.size() + 1,
         "map type " + (type.size() > 1 ? detail::quoted(type[1].text) : std::string("(none)")) +
             " is not supported; expected `type octile`");

  // height and width, in either order, each once.
  std::optional<std::uint64_t> height;
  std::optional<std::uint64_t> width;
  std::size_t size_line = 0;
  for (int k = 0; k < 2; ++k) {
    const auto line = header_line("height H` and `width W");
    const auto w = words(line);
    const bool is_height = !w.empty() && w[0].text == "height";
    const bool is_width = !w.empty() && w[0].text == "width";
    if (!is_height && !is_width)
      fail(name, line.number, w.empty() ? 1 : w[0].column,
           "expected `height H` or `width W` (lower case) on header line " +
               std::to_string(line.number));
    auto& slot = is_height ? height : width;
    const char* key = is_height ? "height" : "width";
    if (slot) fail(name, line.number, w[0].column, std::string("a second `") + key + "` line");
    if (w.size() != 2)
      fail(name, line.number, w.size() > 2 ? w[2].column : line.text.size() + 1,
           std::string("expected `") + key + "` followed by one whole number");
    // Parse with a cap above kMaxGridSide so that "too large" is told apart from "not a number".
    slot = detail::parse_whole(w[1].text, std::uint64_t{1} << 40);
    if (!slot)
      fail(name, line.number, w[1].column,
           std::string("bad ") + key + " " + detail::quoted(w[1].text) +
               "; expected a whole number");
    size_line = line.number;
  }
  const auto problem = detail::size_problem(*width, *height);
  if (!problem.empty()) fail(name, size_line, 1, problem);

  const auto map_line = header_line("map");
  const auto map_words = words(map_line);
  if (map_words.size() != 1 || map_words[0].text != "map")
    fail(name, map_line.number, 1,
         "expected `map` after the height and width lines, found " + detail::quoted(map_line.text));

  const auto w = static_cast<std::int32_t>(*width);
  const auto h = static_cast<std::int32_t>(*height);
  std::vector<kernel::Occupancy> cells;
  // Reserve no more than the bytes present could fill: the header's size is not trusted.
  cells.reserve(std::min<std::size_t>(static_cast<std::size_t>(*width * *height), text.size()));
  for (std::int32_t row = 0; row < h; ++row) {
    const auto line = lines.next();
    if (!line) {
      const auto p = detail::position_of(text, text.size());
      fail(name, p.line, p.column,
           "the file ends after " + std::to_string(row) + " rows; expected " + std::to_string(h) +
               " (the header's height)");
    }
    if (line->text.size() != static_cast<std::size_t>(w))
      fail(name, line->number, std::min(line->text.size(), static_cast<std::size_t>(w)) + 1,
           "row " + std::to_string(row) + " has " + std::to_string(line->text.size()) +
               " cells; expected " + std::to_string(w) + " (the header's width)");
    for (std::size_t x = 0; x < line->text.size(); ++x) {
      const auto cell = movingai_cell(line->text[x]);
      if (!cell)
        fail(name, line->number, x + 1,
             "unexpected cell " + detail::quoted(line->text.substr(x, 1)) +
                 "; expected one of . G S (free) or @ O T W (blocked)");
      cells.push_back(*cell);
    }
  }
  while (const auto line = lines.next()) {
    if (!line->text.empty())
      fail(name, line->number, 1,
           "unexpected content after the " + std::to_string(h) +
               " rows the header announced; expected the end of the file");
  }

  GridMap map;
  map.cells = kernel::OccupancyGrid(w, h);
  map.cells.cells() = std::move(cells);
  return map;
}

std::string write_movingai(const GridMap& map) {
  const auto& g = map.cells;
  if (g.empty()) throw std::invalid_argument("write_movingai: the map has no cells");
  std::string out = "type octile\nheight " + std::to_string(g.height()) + "\nwidth " +
                    std::to_string(g.width()) + "\nmap\n";
  out.reserve(out.size() + g.size() + static_cast<std::size_t>(g.height()));
  for (std::int32_t y = 0; y < g.height(); ++y) {
    for (std::int32_t x = 0; x < g.width(); ++x)
      // Unknown is written blocked: the format has no unknown (map_io.hpp).
      out += g[{x, y}] == kernel::Occupancy::Free ? '.' : '@';
    out += '\n';
  }
  return out;
}

} // namespace antkit::maps
