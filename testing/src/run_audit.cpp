#include "text_lines.hpp"

#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/testing/run_audit.hpp>
#include <antkit/testing/uniform.hpp>
#include <antkit/uniform/world.hpp>
#include <array>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

namespace antkit::testing {

using kernel::Cell;
using kernel::InputError;
using kernel::Occupancy;
using kernel::OccupancyGrid;
using los::CellState;

namespace {

std::string at(Cell c) {
  return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
}

std::optional<CellState> state_of(char c) {
  for (const CellState s : {CellState::F, CellState::S, CellState::LOS, CellState::S_LOS,
                            CellState::NLOS, CellState::O})
    if (los::code(s) == c) return s;
  return std::nullopt;
}

using detail::blank;

// A whole number in [lo, hi] at l[i...]; advances i. Throws a located error otherwise.
std::int64_t read_number(std::string_view l, std::size_t& i, std::int64_t lo, std::int64_t hi,
                         const std::string& source, std::size_t line, const char* what) {
  while (i < l.size() && blank(l[i])) ++i;
  const std::size_t from = i;
  const detail::Whole number = detail::scan_whole(l, i);
  if (!number.digits) throw InputError(source, line, from + 1, std::string("expected ") + what);
  if (number.overflow)
    throw InputError(source, line, from + 1, std::string(what) + " is out of range");
  const std::int64_t n = number.value;
  if (n < lo || n > hi)
    throw InputError(source, line, from + 1,
                     std::string(what) + " " + std::to_string(n) + " is outside [" +
                         std::to_string(lo) + ", " + std::to_string(hi) + "]");
  while (i < l.size() && blank(l[i])) ++i;
  return n;
}

} // namespace

std::string read_text_file(const std::filesystem::path& path, const char* what,
                           std::size_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path.string(), std::string("cannot open the ") + what + " file for reading");
  std::string text;
  std::array<char, 65536> buf{};
  while (in.read(buf.data(), buf.size()) || in.gcount() > 0) {
    text.append(buf.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes)
      throw InputError(path.string(), std::string(what) + " file larger than " +
                                          std::to_string(max_bytes >> 20) + " MiB");
  }
  if (in.bad()) throw InputError(path.string(), "read error");
  return text;
}

// ---- LOS
// ------------------------------------------------------------------------------------------

LosCellsAudit audit_los_cells(const OccupancyGrid& truth, const kernel::Grid<CellState>& states) {
  LosCellsAudit a;
  for (std::int32_t y = 0; y < states.height(); ++y)
    for (std::int32_t x = 0; x < states.width(); ++x) {
      const Cell c{x, y};
      const CellState s = states[c];
      ++a.by_state[static_cast<std::size_t>(s)];
      const bool free = truth[c] == Occupancy::Free;
      a.free_cells += free;
      if (los::is_known_free(s)) {
        ++a.known_free;
        if (!free) {
          ++a.known_free_not_free;
          if (a.first.empty())
            a.first = "cell " + at(c) + " is marked " + los::code(s) + " but is not free";
        }
      } else if (s == CellState::O && free) {
        ++a.obstacle_but_free;
        if (a.first.empty()) a.first = "cell " + at(c) + " is marked O but is free";
      }
    }
  return a;
}

kernel::Grid<CellState> read_los_cells(std::string_view text, const std::string& source) {
  std::vector<std::string> rows;
  std::vector<std::size_t> lines; // text: the line of each row (0 for JSON)
  std::size_t i = 0;
  while (i < text.size() && (blank(text[i]) || text[i] == '\n' || text[i] == '\r')) ++i;
  if (i == text.size()) throw InputError(source, "empty: no cell states");
  const bool json = text[i] == '{' || text[i] == '[';
  if (json) {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
      const auto [line, column] = kernel::position_of(text, e.byte == 0 ? 0 : e.byte - 1);
      throw InputError(source, line, column, "JSON: " + detail::json_message(e.what()));
    } catch (const nlohmann::json::exception& e) {
      // Not a syntax error: a number out of range ("4E427"), which nlohmann reports without a
      // position (found by fuzz/los_cells).
      throw InputError(source, "JSON: " + detail::json_message(e.what()));
    }
    const nlohmann::json* cells = &j;
    if (j.is_object()) {
      if (!j.contains("cells"))
        throw InputError(source, "no \"cells\": expected an array of rows or an object with "
                                 "\"cells\", as antkit explore prints it");
      cells = &j["cells"];
    }
    if (!cells->is_array()) throw InputError(source, "cells: expected an array of row strings");
    for (std::size_t r = 0; r < cells->size(); ++r) {
      if (!(*cells)[r].is_string())
        throw InputError(source, "cells[" + std::to_string(r) + "]: expected a row string");
      rows.push_back((*cells)[r].get<std::string>());
      lines.push_back(0);
    }
  } else {
    kernel::TextLines text_lines(text);
    while (const auto l = text_lines.next()) {
      if (l->text.find_first_not_of(" \t") == std::string_view::npos) continue;
      rows.emplace_back(l->text);
      lines.push_back(l->number);
    }
  }
  if (rows.empty() || rows.front().empty()) throw InputError(source, "no cell states");
  const std::size_t width = rows.front().size();
  constexpr std::size_t kMaxSide = 1u << 15;
  if (width > kMaxSide || rows.size() > kMaxSide)
    throw InputError(source, "more than 32768 cells across");
  kernel::Grid<CellState> states(static_cast<std::int32_t>(width),
                                 static_cast<std::int32_t>(rows.size()), CellState::F);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    auto where = [&](std::size_t col, const std::string& message) {
      if (lines[r] == 0)
        return InputError(source, "cells[" + std::to_string(r) +
                                      "]: " + (col ? "column " + std::to_string(col) + ": " : "") +
                                      message);
      return InputError(source, lines[r], col ? col : 1, message);
    };
    if (rows[r].size() != width)
      throw where(0, "row " + std::to_string(r) + " has " + std::to_string(rows[r].size()) +
                         " cells, the first row " + std::to_string(width));
    for (std::size_t x = 0; x < width; ++x) {
      const auto s = state_of(rows[r][x]);
      if (!s) {
        const unsigned char ch = static_cast<unsigned char>(rows[r][x]);
        throw where(x + 1, (ch >= 0x20 && ch < 0x7f ? "'" + std::string(1, rows[r][x]) + "'"
                                                    : "byte " + std::to_string(ch)) +
                               " is not a cell state (F S L B N O)");
      }
      states[{static_cast<std::int32_t>(x), static_cast<std::int32_t>(r)}] = *s;
    }
  }
  return states;
}

ExploreCheckReport check_explore_files(const std::string& map_file, const std::string& cells_file) {
  const maps::GridMap map = maps::load_map(map_file);
  return check_explore(
      map.cells,
      read_los_cells(read_text_file(cells_file, "cell states", std::size_t{1} << 30), cells_file),
      cells_file);
}

ExploreCheckReport check_explore(const kernel::OccupancyGrid& map,
                                 const kernel::Grid<los::CellState>& states,
                                 const std::string& cells_source) {
  if (states.width() != map.width() || states.height() != map.height())
    throw InputError(cells_source, "the cell states are " + std::to_string(states.width()) + "x" +
                                       std::to_string(states.height()) + ", the map " +
                                       std::to_string(map.width()) + "x" +
                                       std::to_string(map.height()));
  ExploreCheckReport r;
  r.width = states.width();
  r.height = states.height();
  r.audit = audit_los_cells(map, states);
  return r;
}

// ---- Uniform coverage
// -----------------------------------------------------------------------------

CoverTrace read_cover_trace(std::string_view text, const std::string& source) {
  CoverTrace t;
  constexpr std::int64_t kMaxRobots = 1 << 16;
  constexpr std::int64_t kMaxRows = std::int64_t{1} << 28;
  kernel::TextLines text_lines(text);
  bool header_allowed = true;
  std::int64_t robots = 0, rows_read = 0;
  while (const auto next = text_lines.next()) {
    const std::string_view l = next->text;
    const std::size_t line = next->number;
    std::size_t i = 0;
    while (i < l.size() && blank(l[i])) ++i;
    if (i == l.size()) continue;
    if (l[i] == '#') { // a comment; "# key: value" for the keys below
      auto value_of = [&](std::string_view key) -> std::optional<std::size_t> {
        std::size_t k = i + 1;
        while (k < l.size() && blank(l[k])) ++k;
        if (l.substr(k, key.size()) != key) return std::nullopt;
        k += key.size();
        if (k >= l.size() || l[k] != ':') return std::nullopt;
        return k + 1;
      };
      if (auto k = value_of("sensor")) {
        t.sensor = static_cast<std::int32_t>(
            read_number(l, *k, 0, uniform::kMaxSensorRange, source, line, "the sensor range"));
      } else if (auto v = value_of("claim viewed")) {
        t.claim_viewed = static_cast<std::uint64_t>(
            read_number(l, *v, 0, std::int64_t{1} << 40, source, line, "the viewed cells"));
      } else if (auto w = value_of("claim viewable")) {
        t.claim_viewable = static_cast<std::uint64_t>(
            read_number(l, *w, 0, std::int64_t{1} << 40, source, line, "the viewable cells"));
      } else {
        continue;
      }
      continue;
    }
    if (header_allowed) {
      header_allowed = false;
      if (detail::is_header(l, "tick,robot,x,y,bearing")) continue;
    }
    std::array<std::int64_t, 5> v{};
    static constexpr const char* kWhat[5] = {"a tick", "a robot", "x", "y", "a bearing"};
    static constexpr std::int64_t kHi[5] = {std::numeric_limits<std::int64_t>::max() / 2,
                                            kMaxRobots, std::numeric_limits<std::int32_t>::max(),
                                            std::numeric_limits<std::int32_t>::max(), 7};
    static constexpr std::int64_t kLo[5] = {0, 0, std::numeric_limits<std::int32_t>::min(),
                                            std::numeric_limits<std::int32_t>::min(), 0};
    i = 0;
    for (std::size_t k = 0; k < 5; ++k) {
      v[k] = read_number(l, i, kLo[k], kHi[k], source, line, kWhat[k]);
      if (k < 4) {
        if (i >= l.size() || l[i] != ',')
          throw InputError(source, line, i + 1, "expected ',' (tick,robot,x,y,bearing)");
        ++i;
      }
    }
    if (i != l.size()) throw InputError(source, line, i + 1, "unexpected text after the bearing");
    // Ticks and robots in order; tick 0 sets the number of robots.
    if (rows_read >= kMaxRows) throw InputError(source, line, 1, "more than 2^28 poses");
    if (robots == 0 && v[0] != 0) {
      if (rows_read == 0) throw InputError(source, line, 1, "the trace must begin with tick 0");
      robots = rows_read;
    }
    const std::int64_t want_tick = robots == 0 ? 0 : rows_read / robots;
    const std::int64_t want_robot = robots == 0 ? rows_read : rows_read % robots;
    if (v[0] != want_tick || v[1] != want_robot)
      throw InputError(source, line, 1,
                       "expected tick " + std::to_string(want_tick) + ", robot " +
                           std::to_string(want_robot) +
                           " (ticks count up from 0, each listing its robots in order), not tick " +
                           std::to_string(v[0]) + ", robot " + std::to_string(v[1]));
    if (want_robot == 0) {
      t.cells.emplace_back();
      t.bearings.emplace_back();
    }
    t.cells.back().push_back({static_cast<std::int32_t>(v[2]), static_cast<std::int32_t>(v[3])});
    t.bearings.back().push_back(static_cast<std::uint8_t>(v[4]));
    ++rows_read;
  }
  if (robots == 0) robots = rows_read;
  if (robots > kMaxRobots) throw InputError(source, "more than 65536 robots in tick 0");
  t.robots = static_cast<std::int32_t>(robots);
  if (t.cells.empty()) throw InputError(source, "no poses: expected tick,robot,x,y,bearing lines");
  if (rows_read % robots != 0)
    throw InputError(source, "the last tick lists " + std::to_string(rows_read % robots) + " of " +
                                 std::to_string(robots) + " robots");
  return t;
}

CoverAudit audit_cover_trace(const OccupancyGrid& map, const CoverTrace& trace,
                             std::int32_t sensor) {
  CoverAudit a;
  a.ticks = static_cast<std::int64_t>(trace.cells.size());
  a.robots = trace.robots;
  auto fail = [&](std::int64_t tick, std::int64_t robot, Cell c, const std::string& what) {
    if (a.first.empty()) {
      a.first = "tick " + std::to_string(tick) + ", robot " + std::to_string(robot) + " at " +
                at(c) + ": " + what;
      a.first_tick = tick;
    }
  };
  auto free = [&](Cell c) { return map.in_bounds(c) && map[c] == Occupancy::Free; };
  kernel::Grid<std::uint8_t> stood(map.width(), map.height(), 0);
  kernel::Grid<std::uint32_t> occupied(map.width(), map.height(), 0);
  for (std::size_t t = 0; t < trace.cells.size(); ++t) {
    const auto tick = static_cast<std::uint32_t>(t + 1); // stamps for `occupied`
    for (std::size_t r = 0; r < trace.cells[t].size(); ++r) {
      const Cell c = trace.cells[t][r];
      const std::uint8_t b = trace.bearings[t][r];
      const auto ti = static_cast<std::int64_t>(t), ri = static_cast<std::int64_t>(r);
      bool legal = free(c);
      if (!legal) fail(ti, ri, c, "not on a free cell of the map");
      if (t > 0) {
        const Cell p = trace.cells[t - 1][r];
        const std::uint8_t pb = trace.bearings[t - 1][r];
        if (p == c) {
          const int turn = (b - pb + 8) % 8;
          if (turn != 0) ++a.turns;
          if (turn != 0 && turn != 1 && turn != 7) {
            ++a.bad_turns;
            fail(ti, ri, c,
                 "the bearing turned from " + std::to_string(pb) + " to " + std::to_string(b) +
                     ", more than one eighth");
          }
        } else {
          ++a.moves;
          int dir = -1;
          for (int d = 0; d < 8; ++d)
            if (std::int64_t{p.x} + kernel::kNeighbours8[static_cast<std::size_t>(d)].x == c.x &&
                std::int64_t{p.y} + kernel::kNeighbours8[static_cast<std::size_t>(d)].y == c.y)
              dir = d;
          if (dir < 0) {
            legal = false;
            fail(ti, ri, c, "moved from " + at(p) + ", not one of its eight neighbours");
          } else if (dir % 2 == 1 && (!free({c.x, p.y}) || !free({p.x, c.y}))) {
            legal = false;
            fail(ti, ri, c, "moved diagonally from " + at(p) + " across a corner");
          } else if (b != dir) {
            ++a.bad_turns;
            fail(ti, ri, c,
                 "moved along bearing " + std::to_string(dir) + " but faces " + std::to_string(b));
          }
          if (!legal) ++a.illegal_moves;
        }
      }
      if (map.in_bounds(c)) {
        if (occupied[c] == tick) {
          ++a.collisions;
          fail(ti, ri, c, "another robot stands on this cell");
        }
        occupied[c] = tick;
        if (free(c)) stood[c] = 1;
      }
    }
  }
  // Viewable: the free cells of the 4-connected components the robots start in.
  kernel::Grid<std::uint8_t> viewable(map.width(), map.height(), 0);
  std::vector<Cell> queue;
  for (const Cell s : trace.cells.front())
    if (free(s) && !viewable[s]) {
      viewable[s] = 1;
      queue.push_back(s);
    }
  for (std::size_t i = 0; i < queue.size(); ++i)
    for (const Cell d : {Cell{1, 0}, Cell{0, 1}, Cell{-1, 0}, Cell{0, -1}}) {
      const Cell n = queue[i] + d;
      if (free(n) && !viewable[n]) {
        viewable[n] = 1;
        queue.push_back(n);
      }
    }
  a.viewable = queue.size();
  // Viewed: brute force from every cell a robot stood on.
  kernel::Grid<std::uint8_t> viewed(map.width(), map.height(), 0);
  for (std::int32_t y = 0; y < map.height(); ++y)
    for (std::int32_t x = 0; x < map.width(); ++x) {
      if (!stood[{x, y}]) continue;
      const auto view = brute_force_view(map, {x, y}, sensor);
      for (std::size_t i = 0; i < view.size(); ++i)
        if (view.cells()[i]) viewed.cells()[i] = 1;
    }
  for (std::size_t i = 0; i < viewed.size(); ++i)
    if (viewed.cells()[i] && viewable.cells()[i]) ++a.viewed;
  if (trace.claim_viewed && *trace.claim_viewed != a.viewed) {
    a.claims_match = false;
    if (a.first.empty())
      a.first = "the run claims " + std::to_string(*trace.claim_viewed) +
                " viewed free cells; its poses view " + std::to_string(a.viewed);
  }
  if (trace.claim_viewable && *trace.claim_viewable != a.viewable) {
    a.claims_match = false;
    if (a.first.empty())
      a.first = "the run claims " + std::to_string(*trace.claim_viewable) +
                " viewable free cells; the map has " + std::to_string(a.viewable);
  }
  return a;
}

CoverCheckReport check_cover_files(const std::string& map_file, const std::string& trace_file,
                                   std::optional<std::int64_t> sensor) {
  check_sensor_range(sensor);
  const maps::GridMap map = maps::load_map(map_file);
  return check_cover(
      map.cells,
      read_cover_trace(read_text_file(trace_file, "trace", std::size_t{1} << 30), trace_file),
      sensor, trace_file);
}

void check_sensor_range(std::optional<std::int64_t> sensor) {
  if (sensor && (*sensor < 0 || *sensor > uniform::kMaxSensorRange))
    throw InputError("sensor distance", "expected a sensor distance in [0, " +
                                            std::to_string(uniform::kMaxSensorRange) +
                                            "] cells, not " + std::to_string(*sensor));
}

CoverCheckReport check_cover(const kernel::OccupancyGrid& map, const CoverTrace& trace,
                             std::optional<std::int64_t> sensor, const std::string& trace_source) {
  check_sensor_range(sensor);
  CoverCheckReport r;
  if (sensor) {
    r.sensor = static_cast<std::int32_t>(*sensor);
    r.sensor_from = "--sensor";
  } else if (trace.sensor) {
    r.sensor = *trace.sensor;
    r.sensor_from = "trace";
  } else {
    throw InputError(trace_source, "no \"# sensor: R\" line: give the sensor range with --sensor");
  }
  r.claim_viewed = trace.claim_viewed;
  r.claim_viewable = trace.claim_viewable;
  r.audit = audit_cover_trace(map, trace, r.sensor);
  return r;
}

} // namespace antkit::testing
