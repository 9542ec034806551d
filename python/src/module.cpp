// antkit's Python package, the compiled half (`antkit._antkit`): the library's typed calls on numpy
// arrays and plain Python types. The pure-Python half (antkit/__init__.py) wraps the results in
// objects; its docstrings and antkit/__init__.pyi document the API.
//
// Results are the JSON the command prints (commands/), converted to dicts, so that a field means
// the same in Python as in `antkit ... --format json`. Bad input raises antkit.InputError (a
// ValueError) carrying the library's located message ("FILE:LINE:COL: ...", "start: ..."), with
// the command line's option words (--start, --sensor, --arena, ...) spoken as the Python arguments
// that carry them (python_words below). The functions here take arguments that antkit/__init__.py
// has already checked for type (their names begin with '_'), so that pybind11 never answers a
// caller with its own TypeError; what only C++ can check (sizes, ranges, shapes) is checked here.
// Every call that runs a tour, a check or a replay releases the GIL while it runs.
#include <algorithm>
#include <antkit/commands/bags.hpp>
#include <antkit/commands/json.hpp>
#include <antkit/commands/options.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/io/bag.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/segment.hpp>
#include <antkit/los/cell_state.hpp>
#include <antkit/maps/detail/text_scan.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/run_audit.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <optional>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace py = pybind11;
using antkit::kernel::Cell;
using antkit::kernel::InputError;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;

namespace {

// A map and the name it was read from (the reports' "map"; empty for one made from an array).
struct PyMap {
  antkit::maps::GridMap map;
  std::string source;
};

// Text for Python: bytes that are not UTF-8 (a message may quote a cut-off token of a file, a
// bag may name a topic in any bytes) replaced by U+FFFD rather than raising UnicodeDecodeError.
py::str text(const std::string& s) {
  PyObject* o = PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "replace");
  if (!o) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(o);
}

py::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
  case nlohmann::json::value_t::null:
    return py::none();
  case nlohmann::json::value_t::boolean:
    return py::bool_(j.get<bool>());
  case nlohmann::json::value_t::number_integer:
    return py::int_(j.get<std::int64_t>());
  case nlohmann::json::value_t::number_unsigned:
    return py::int_(j.get<std::uint64_t>());
  case nlohmann::json::value_t::number_float:
    return py::float_(j.get<double>());
  case nlohmann::json::value_t::string:
    return text(j.get_ref<const std::string&>());
  case nlohmann::json::value_t::array: {
    py::list out;
    for (const auto& item : j) out.append(to_python(item));
    return out;
  }
  case nlohmann::json::value_t::object: {
    py::dict out;
    for (const auto& [key, value] : j.items()) out[text(key)] = to_python(value);
    return out;
  }
  default:
    throw std::logic_error("a JSON value the package cannot convert");
  }
}

py::tuple cell_tuple(Cell c) {
  return py::make_tuple(c.x, c.y);
}

std::int32_t checked_i32(std::int64_t v, const char* where) {
  if (v < INT32_MIN || v > INT32_MAX)
    throw InputError(where, std::to_string(v) + " is outside [-2^31, 2^31)");
  return static_cast<std::int32_t>(v);
}

std::optional<Cell> optional_cell(const std::optional<std::pair<std::int64_t, std::int64_t>>& p,
                                  const char* where) {
  if (!p) return std::nullopt;
  return Cell{checked_i32(p->first, where), checked_i32(p->second, where)};
}

// At most as many positions or points as a tour file may hold (testing's reader).
constexpr py::ssize_t kMaxRows = py::ssize_t{1} << 28;

// An array's rows [0, n) as C-contiguous T, kChunk rows at a time: a view of any layout (strided,
// reversed, broadcast) is never copied whole, so what it costs is what the result holds.
template <class T, class F>
void for_chunks(const py::array& a, const std::string& what, F&& f) {
  constexpr py::ssize_t kChunk = py::ssize_t{1} << 16;
  const py::ssize_t n = a.shape(0);
  for (py::ssize_t i0 = 0; i0 < n; i0 += kChunk) {
    const py::ssize_t i1 = std::min(n, i0 + kChunk);
    const py::object part = a.attr("__getitem__")(py::slice(i0, i1, 1));
    const auto v = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(part);
    if (!v) throw InputError(what, "cannot read the array's values as numbers");
    f(i0, v);
  }
}

// An (n, 2) integer array as cells, pairs in x, y order (or row, col with `row_col`).
std::vector<Cell> cells_from_array(const py::array& a, const char* what, bool row_col) {
  if (a.ndim() != 2 || a.shape(1) != 2)
    throw InputError(what, "expected an (n, 2) array of integer pairs, not shape " +
                               std::string(py::str(a.attr("shape"))));
  const auto kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw InputError(what, "expected integer pairs (dtype int or uint), not dtype " +
                               std::string(py::str(a.dtype())));
  if (a.shape(0) > kMaxRows)
    throw InputError(what, std::to_string(a.shape(0)) + " positions, more than 2^28");
  std::vector<Cell> out;
  out.reserve(static_cast<std::size_t>(a.shape(0)));
  for_chunks<std::int64_t>(a, what, [&](py::ssize_t i0, const py::array_t<std::int64_t>& v) {
    const auto r = v.unchecked<2>();
    for (py::ssize_t i = 0; i < r.shape(0); ++i) {
      const std::int64_t x = r(i, 0), y = r(i, 1);
      if (x < INT32_MIN || x > INT32_MAX || y < INT32_MIN || y > INT32_MAX) {
        const std::string where = std::string(what) + "[" + std::to_string(i0 + i) + "]";
        throw InputError(where, "(" + std::to_string(x) + ", " + std::to_string(y) +
                                    ") is outside [-2^31, 2^31)");
      }
      Cell c{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
      if (row_col) std::swap(c.x, c.y);
      out.push_back(c);
    }
  });
  return out;
}

py::array_t<std::int32_t> path_array(const std::vector<Cell>& path) {
  py::array_t<std::int32_t> out({static_cast<py::ssize_t>(path.size()), py::ssize_t{2}});
  auto w = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < path.size(); ++i) {
    w(static_cast<py::ssize_t>(i), 0) = path[i].x;
    w(static_cast<py::ssize_t>(i), 1) = path[i].y;
  }
  return out;
}

// ---- maps --------------------------------------------------------------------------------------

PyMap read_map(const std::string& path) {
  py::gil_scoped_release release;
  return {antkit::maps::load_map(path), path};
}

PyMap map_from_array(const py::array& a,
                     const std::optional<std::pair<std::int64_t, std::int64_t>>& start) {
  if (a.dtype().kind() != 'b')
    throw InputError("a", "expected a 2-D bool array (True = free), not dtype " +
                              std::string(py::str(a.dtype())) +
                              "; from an occupancy grid with 0 = free, pass grid == 0");
  if (a.ndim() != 2)
    throw InputError("a",
                     "expected a 2-D array (rows = y), not " + std::to_string(a.ndim()) + "-D");
  // The caps of map files (maps/map_io.hpp): each side and the total, checked before anything is
  // copied or allocated (a broadcast view of a few bytes may claim 2^40 cells).
  const auto problem = antkit::maps::detail::size_problem(static_cast<std::uint64_t>(a.shape(1)),
                                                          static_cast<std::uint64_t>(a.shape(0)));
  if (!problem.empty()) throw InputError("a", problem);
  const auto v = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!v) throw InputError("a", "cannot read the array as bool");
  const auto r = v.unchecked<2>();
  PyMap m;
  m.map.cells = OccupancyGrid(static_cast<std::int32_t>(r.shape(1)),
                              static_cast<std::int32_t>(r.shape(0)), Occupancy::Blocked);
  for (py::ssize_t y = 0; y < r.shape(0); ++y)
    for (py::ssize_t x = 0; x < r.shape(1); ++x)
      if (r(y, x))
        m.map.cells[{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)}] = Occupancy::Free;
  m.map.start = optional_cell(start, "start");
  if (m.map.start &&
      (!m.map.cells.in_bounds(*m.map.start) || m.map.cells[*m.map.start] != Occupancy::Free))
    throw InputError("start", "(" + std::to_string(m.map.start->x) + ", " +
                                  std::to_string(m.map.start->y) + ") is not a free cell of the " +
                                  std::to_string(r.shape(1)) + "x" + std::to_string(r.shape(0)) +
                                  " map");
  return m;
}

py::array_t<bool> map_to_array(const PyMap& m) {
  const auto& g = m.map.cells;
  py::array_t<bool> out(
      {static_cast<py::ssize_t>(g.height()), static_cast<py::ssize_t>(g.width())});
  auto w = out.mutable_unchecked<2>();
  for (std::int32_t y = 0; y < g.height(); ++y)
    for (std::int32_t x = 0; x < g.width(); ++x) w(y, x) = g[{x, y}] == Occupancy::Free;
  return out;
}

void write_map(const PyMap& m, const std::string& path) {
  py::gil_scoped_release release;
  antkit::maps::save_map(path, m.map);
}

// ---- STC ---------------------------------------------------------------------------------------

py::tuple run_stc(const PyMap& m, const std::string& variant_name,
                  const std::optional<std::pair<std::int64_t, std::int64_t>>& start_xy,
                  const std::optional<std::string>& noise, std::uint64_t seed) {
  const auto variant = antkit::commands::stc_variant(variant_name, "variant");
  antkit::stc::RunOptions run;
  std::optional<antkit::commands::StcNoiseFields> noise_fields;
  if (noise) {
    run.noise = antkit::commands::stc_noise(variant, *noise, seed, "noise");
    noise_fields = antkit::commands::StcNoiseFields{run.noise.ppm, seed};
  }
  const auto name = m.source.empty() ? std::string("map") : m.source;
  nlohmann::json j;
  antkit::stc::RunResult r;
  {
    py::gil_scoped_release release;
    const Cell start =
        antkit::commands::choose_stc_start(m.map, variant, optional_cell(start_xy, "start"), name);
    try {
      r = antkit::stc::run_stc(m.map.cells, start, variant, run);
    } catch (const InputError& e) { // name the argument or the map the start came from
      throw InputError(start_xy ? "start" : name, e.message());
    }
    j = antkit::commands::stc_json(r, m.map.cells.width(), m.map.cells.height(), start,
                                   noise_fields);
    j["closed"] = r.closed;
    j["positions"] = r.positions;
  }
  return py::make_tuple(to_python(j), path_array(r.path));
}

std::string tour_hash(const py::array& path, std::int64_t width, std::int64_t height) {
  const auto cells = cells_from_array(path, "path", false);
  if (width < 1 || width > antkit::kernel::kMaxGridSide)
    throw InputError("width", "expected a map width in [1, " +
                                  std::to_string(antkit::kernel::kMaxGridSide) +
                                  "] sub-cells, not " + std::to_string(width));
  if (height < 1 || height > antkit::kernel::kMaxGridSide)
    throw InputError("height", "expected a map height in [1, " +
                                   std::to_string(antkit::kernel::kMaxGridSide) +
                                   "] sub-cells, not " + std::to_string(height));
  const auto w = static_cast<std::int32_t>(width), h = static_cast<std::int32_t>(height);
  // A tour is what antkit stc's hash is over: positions on the map, each a 4-neighbour of the one
  // before (the hash of anything else would match no run).
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell c = cells[i];
    const std::string where = "path[" + std::to_string(i) + "]";
    if (c.x < 0 || c.x >= w || c.y < 0 || c.y >= h)
      throw InputError(where, "(" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                                  ") is off the " + std::to_string(w) + "x" + std::to_string(h) +
                                  " map");
    if (i > 0) {
      const Cell p = cells[i - 1];
      if (std::abs(static_cast<std::int64_t>(c.x) - p.x) +
              std::abs(static_cast<std::int64_t>(c.y) - p.y) !=
          1)
        throw InputError(where, "(" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                                    ") is not a 4-neighbour of (" + std::to_string(p.x) + ", " +
                                    std::to_string(p.y) +
                                    "): a tour moves one sub-cell east, north, west or south");
    }
  }
  py::gil_scoped_release release;
  return antkit::kernel::hash_hex(antkit::stc::tour_hash(w, h, cells));
}

// ---- the oracles -------------------------------------------------------------------------------

antkit::testing::TourOrder parse_order(const std::string& order) {
  if (order == "xy") return antkit::testing::TourOrder::XY;
  if (order == "rc") return antkit::testing::TourOrder::RowCol;
  throw InputError("order", "'" + order + "': expected xy (column, row) or rc (row, col)");
}

py::object check_stc(const PyMap& m, const py::object& path,
                     const std::optional<std::pair<std::int64_t, std::int64_t>>& start,
                     bool coverage, const std::string& order, bool cells) {
  antkit::testing::StcCheckRequest request;
  request.order = parse_order(order);
  request.map_file = m.source.empty() ? "map" : m.source;
  request.start = optional_cell(start, "start");
  request.rule =
      coverage ? antkit::testing::TourRule::Coverage : antkit::testing::TourRule::ExactlyOnce;
  request.cells = cells;
  antkit::testing::TourFile tour;
  const bool is_file = py::isinstance<py::str>(path) || py::hasattr(path, "__fspath__");
  if (is_file) {
    request.tour_file = py::str(py::module_::import("os").attr("fspath")(path));
    py::gil_scoped_release release;
    tour = antkit::testing::read_tour_file(request.tour_file, request.order);
  } else {
    request.tour_file = "path";
    const py::array a = py::array::ensure(path);
    if (!a) throw InputError("path", "expected an (n, 2) array, a list of pairs or a tour file");
    if (a.ndim() == 1 && a.shape(0) == 0) {
      // an empty list: no positions
    } else {
      tour.path = cells_from_array(a, "path", request.order == antkit::testing::TourOrder::RowCol);
    }
    tour.order = request.order;
  }
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const auto report = antkit::testing::check_stc(m.map, tour, request);
    j = antkit::commands::check_stc_json(report, m.source);
  }
  return to_python(j);
}

py::object check_explore_text(const PyMap& m, const std::string& text, const std::string& source) {
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const auto states = antkit::testing::read_los_cells(text, source);
    j = antkit::commands::check_explore_json(
        antkit::testing::check_explore(m.map.cells, states, source), m.source);
  }
  return to_python(j);
}

// Cell states given as row strings (str each, checked by __init__.py), located as cells[ROW] and
// the column, not as lines of a text the caller never wrote.
py::object check_explore_rows(const PyMap& m, const std::vector<std::string>& rows) {
  using antkit::los::CellState;
  constexpr std::size_t kMaxSide = 1u << 15; // read_los_cells' cap
  if (rows.empty() || rows.front().empty())
    throw InputError("cells", "no cell states: expected rows of letters F S L B N O");
  if (rows.size() > kMaxSide || rows.front().size() > kMaxSide)
    throw InputError("cells", "more than 32768 cells across");
  const std::size_t width = rows.front().size();
  antkit::kernel::Grid<CellState> states(static_cast<std::int32_t>(width),
                                         static_cast<std::int32_t>(rows.size()), CellState::F);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::string where = "cells[" + std::to_string(r) + "]";
    if (rows[r].size() != width)
      throw InputError(where, "has " + std::to_string(rows[r].size()) +
                                  " cells (bytes), cells[0] " + std::to_string(width));
    for (std::size_t x = 0; x < width; ++x) {
      std::optional<CellState> state;
      for (std::uint8_t k = 0; k <= static_cast<std::uint8_t>(CellState::O); ++k)
        if (antkit::los::code(static_cast<CellState>(k)) == rows[r][x])
          state = static_cast<CellState>(k);
      if (!state) {
        const auto ch = static_cast<unsigned char>(rows[r][x]);
        throw InputError(where,
                         "column " + std::to_string(x) + ": " +
                             (ch >= 0x20 && ch < 0x7f ? "'" + std::string(1, rows[r][x]) + "'"
                                                      : "byte " + std::to_string(ch)) +
                             " is not a cell state (F S L B N O)");
      }
      states[{static_cast<std::int32_t>(x), static_cast<std::int32_t>(r)}] = *state;
    }
  }
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = antkit::commands::check_explore_json(
        antkit::testing::check_explore(m.map.cells, states, "cells"), m.source);
  }
  return to_python(j);
}

// The sensor range as the argument `sensor` (the library names it "sensor distance").
void check_sensor(std::optional<std::int64_t> sensor) {
  try {
    antkit::testing::check_sensor_range(sensor);
  } catch (const InputError& e) {
    throw InputError("sensor", e.message());
  }
}

py::object check_cover_text(const PyMap& m, const std::string& text, const std::string& source,
                            std::optional<std::int64_t> sensor) {
  check_sensor(sensor);
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const auto trace = antkit::testing::read_cover_trace(text, source);
    j = antkit::commands::check_cover_json(
        antkit::testing::check_cover(m.map.cells, trace, sensor, source), m.source);
  }
  return to_python(j);
}

// A trace given as an integer array (ticks, robots, 3) of (x, y, bearing): the library's
// CoverTrace built directly, each value located as trace[tick, robot].
py::object check_cover_array(const PyMap& m, const py::array& a,
                             std::optional<std::int64_t> sensor) {
  if (!sensor)
    throw InputError("sensor", "required with a trace array (a trace file may say it on a "
                               "\"# sensor: R\" line)");
  check_sensor(sensor);
  if (a.ndim() != 3 || a.shape(2) != 3)
    throw InputError("trace", "expected an integer array of shape (ticks, robots, 3), not shape " +
                                  std::string(py::str(a.attr("shape"))));
  const auto kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw InputError("trace", "expected integers (dtype int or uint), not dtype " +
                                  std::string(py::str(a.dtype())));
  constexpr py::ssize_t kMaxRobots = 1 << 16, kMaxPoses = py::ssize_t{1} << 28; // the reader's
  if (a.shape(0) < 1 || a.shape(1) < 1)
    throw InputError("trace", "no poses: expected at least one tick of at least one robot");
  if (a.shape(1) > kMaxRobots) throw InputError("trace", "more than 65536 robots");
  if (a.shape(0) > kMaxPoses / a.shape(1)) throw InputError("trace", "more than 2^28 poses");
  // One tick at a time (a broadcast view is not copied whole).
  antkit::testing::CoverTrace trace;
  trace.robots = static_cast<std::int32_t>(a.shape(1));
  trace.cells.resize(static_cast<std::size_t>(a.shape(0)));
  trace.bearings.resize(static_cast<std::size_t>(a.shape(0)));
  for (py::ssize_t t = 0; t < a.shape(0); ++t) {
    const py::object tick = a.attr("__getitem__")(t);
    const auto v =
        py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(tick);
    if (!v) throw InputError("trace", "cannot read the array as 64-bit integers");
    const auto r = v.unchecked<2>();
    for (py::ssize_t k = 0; k < r.shape(0); ++k) {
      const std::int64_t x = r(k, 0), y = r(k, 1), b = r(k, 2);
      const auto where = [&] {
        return "trace[" + std::to_string(t) + ", " + std::to_string(k) + "]";
      };
      if (x < INT32_MIN || x > INT32_MAX || y < INT32_MIN || y > INT32_MAX)
        throw InputError(where(), "(" + std::to_string(x) + ", " + std::to_string(y) +
                                      ") is outside [-2^31, 2^31)");
      if (b < 0 || b > 7)
        throw InputError(where(), "bearing " + std::to_string(b) +
                                      " is outside [0, 7] (0 east, counter-clockwise in eighths)");
      trace.cells[static_cast<std::size_t>(t)].push_back(
          {static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)});
      trace.bearings[static_cast<std::size_t>(t)].push_back(static_cast<std::uint8_t>(b));
    }
  }
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = antkit::commands::check_cover_json(
        antkit::testing::check_cover(m.map.cells, trace, sensor, "trace"), m.source);
  }
  return to_python(j);
}

// ---- Buffon and hardware logs ------------------------------------------------------------------

py::object buffon_from_logs(const std::string& visit1, const std::string& visit2, double width,
                            const std::optional<std::string>& arena) {
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = antkit::commands::buffon_from_logs_json(
        antkit::commands::buffon_from_logs(visit1, visit2, width, arena.value_or(""), "width"),
        width);
  }
  return to_python(j);
}

py::dict estimate_dict(const antkit::devices::BuffonEstimate& e) {
  const auto opt = [](const std::optional<double>& v) -> py::object {
    return v ? py::object(py::float_(*v)) : py::object(py::none());
  };
  py::dict d;
  d["area_raw"] = opt(e.area_raw);
  d["area_raw_ci"] = py::make_tuple(opt(e.raw_ci.lower), opt(e.raw_ci.upper));
  d["erosion_factor"] = e.erosion_factor;
  d["area_corrected"] = opt(e.area_corrected);
  d["area_corrected_ci"] = py::make_tuple(opt(e.corrected_ci.lower), opt(e.corrected_ci.upper));
  return d;
}

py::dict buffon_estimate(double length1, double length2, std::uint64_t crossings,
                         std::uint64_t wall_encounters) {
  if (!(length1 >= 0 && length2 >= 0 && length1 < 1e9 && length2 < 1e9))
    throw InputError("length", "trail lengths are in [0, 1e9) body diameters");
  antkit::devices::BuffonCounts counts;
  counts.length1_raw = static_cast<std::int64_t>(length1 * 65536.0 + 0.5);
  counts.length2_raw = static_cast<std::int64_t>(length2 * 65536.0 + 0.5);
  counts.crossings = crossings;
  counts.wall_encounters = wall_encounters;
  return estimate_dict(antkit::devices::estimate_area(counts));
}

py::dict buffon_from_trails(const py::array& trail1, const py::array& trail2,
                            std::uint64_t wall_encounters) {
  const auto points = [](const py::array& a, const char* what) {
    if (a.ndim() != 2 || a.shape(1) != 2)
      throw InputError(what, "expected an (n, 2) array of points, not shape " +
                                 std::string(py::str(a.attr("shape"))));
    const auto kind = a.dtype().kind();
    if (kind != 'i' && kind != 'u' && kind != 'f')
      throw InputError(what, "expected real coordinates (dtype int, uint or float), not dtype " +
                                 std::string(py::str(a.dtype())));
    if (a.shape(0) > kMaxRows)
      throw InputError(what, std::to_string(a.shape(0)) + " points, more than 2^28");
    std::vector<antkit::kernel::FxPoint> out;
    out.reserve(static_cast<std::size_t>(a.shape(0)));
    for_chunks<double>(a, what, [&](py::ssize_t i0, const py::array_t<double>& v) {
      const auto r = v.unchecked<2>();
      for (py::ssize_t i = 0; i < r.shape(0); ++i) {
        const std::string where = std::string(what) + "[" + std::to_string(i0 + i) + "]";
        out.push_back({antkit::geometry::fixed_from_double<antkit::kernel::Fx>(r(i, 0), where),
                       antkit::geometry::fixed_from_double<antkit::kernel::Fx>(r(i, 1), where)});
      }
    });
    return out;
  };
  const auto p1 = points(trail1, "trail1");
  const auto p2 = points(trail2, "trail2");
  py::gil_scoped_release release;
  const auto length_raw = [](const std::vector<antkit::kernel::FxPoint>& p) {
    double sum = 0;
    for (std::size_t i = 1; i < p.size(); ++i)
      sum += std::hypot(static_cast<double>(p[i].x.raw() - p[i - 1].x.raw()),
                        static_cast<double>(p[i].y.raw() - p[i - 1].y.raw()));
    return static_cast<std::int64_t>(std::llround(sum));
  };
  antkit::devices::BuffonCounts counts;
  counts.length1_raw = length_raw(p1);
  counts.length2_raw = length_raw(p2);
  counts.crossings = antkit::kernel::count_proper_crossings(p1, p2);
  counts.wall_encounters = wall_encounters;
  const auto e = antkit::devices::estimate_area(counts);
  py::gil_scoped_acquire acquire;
  py::dict d = estimate_dict(e);
  d["length1"] = static_cast<double>(counts.length1_raw) / 65536.0;
  d["length2"] = static_cast<double>(counts.length2_raw) / 65536.0;
  d["crossings"] = counts.crossings;
  d["wall_encounters"] = wall_encounters;
  return d;
}

py::object replay(const std::string& path, std::optional<std::int64_t> until) {
  if (until && *until < 0) throw InputError("until", "expected a step number >= 0");
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = antkit::commands::replay_json(antkit::devices::replay(path, until));
  }
  return to_python(j);
}

py::dict exchange_dict(const antkit::devices::Exchange& e) {
  py::dict d;
  d["sent"] = py::bytes(e.sent);
  d["received"] = py::bytes(e.received);
  return d;
}

py::list exchanges(const std::vector<antkit::devices::Exchange>& io) {
  py::list out;
  for (const auto& e : io) out.append(exchange_dict(e));
  return out;
}

py::dict read_log(const std::string& path) {
  std::optional<antkit::devices::LogReader> reader;
  std::vector<antkit::devices::LogRecord> records;
  {
    py::gil_scoped_release release;
    reader.emplace(path);
    antkit::devices::LogRecord r;
    while (reader->next(r)) records.push_back(r);
  }
  const auto& h = reader->header();
  py::dict header;
  header["schema"] = h.schema;
  header["antkit_version"] = text(h.antkit_version);
  header["robot"] = text(h.robot);
  header["port"] = text(h.port);
  header["baud"] = h.baud;
  header["framing"] = text(h.framing);
  header["controller"] = text(h.controller);
  py::dict params;
  for (const auto& [k, v] : h.params) params[text(k)] = v;
  header["params"] = params;
  header["seed"] = h.seed;
  header["arena"] = h.arena.empty() ? py::object(py::none()) : py::object(text(h.arena));
  py::list recs;
  for (const auto& r : records) {
    py::dict d;
    d["step"] = r.step;
    d["t_ns"] = r.time_ns;
    d["io"] = exchanges(r.io);
    d["obs"] = r.obs;
    d["cmd"] = r.cmd;
    d["odo"] = r.odo;
    d["state"] = antkit::kernel::hash_hex(r.state);
    recs.append(d);
  }
  py::dict out;
  out["header"] = header;
  out["records"] = recs;
  out["truncated"] = reader->truncated();
  if (const auto& s = reader->stop()) {
    py::dict stop;
    stop["step"] = s->step;
    stop["reason"] = text(s->reason);
    stop["io"] = exchanges(s->io);
    out["stop"] = stop;
  } else {
    out["stop"] = py::none();
  }
  return out;
}

// ---- ROS 2 bags ---------------------------------------------------------------------------------

py::object bag_info(const std::string& path) {
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = antkit::commands::bag_info_json(antkit::io::bag::bag_info(path));
  }
  return to_python(j);
}

// A pose topic: its names and counts, and the poses as numpy columns.
py::dict read_bag_poses(const std::string& path, const std::string& topic,
                        const std::string& stamp_name, const std::string& child_frame) {
  const auto stamp = antkit::commands::bag_stamp(stamp_name, "stamp");
  antkit::io::bag::PoseTrack track;
  {
    py::gil_scoped_release release;
    track = antkit::io::bag::read_poses(path, topic, stamp, child_frame);
  }
  const auto n = static_cast<py::ssize_t>(track.poses.size());
  py::array_t<double> xyyaw({n, py::ssize_t{3}});
  py::array_t<std::int64_t> t_ns(n);
  py::array_t<std::uint64_t> bag_ns(n);
  py::array_t<std::int64_t> header_ns(n);
  auto p = xyyaw.mutable_unchecked<2>();
  auto t = t_ns.mutable_unchecked<1>();
  auto b = bag_ns.mutable_unchecked<1>();
  auto h = header_ns.mutable_unchecked<1>();
  bool has_header = true;
  for (py::ssize_t i = 0; i < n; ++i) {
    const auto& pose = track.poses[static_cast<std::size_t>(i)];
    p(i, 0) = pose.x, p(i, 1) = pose.y, p(i, 2) = pose.yaw;
    t(i) = pose.t_ns;
    b(i) = pose.bag_ns;
    h(i) = pose.header_ns.value_or(0);
    has_header = has_header && pose.header_ns.has_value();
  }
  py::dict d;
  d["bag"] = text(track.path);
  d["topic"] = text(track.topic);
  d["type"] = text(track.type);
  d["stamp"] = stamp == antkit::io::bag::Stamp::bag ? "bag" : "header";
  d["child_frame"] = track.type == "tf2_msgs/msg/TFMessage" ? py::object(text(track.child_frame))
                                                            : py::object(py::none());
  d["messages"] = track.messages;
  d["poses"] = xyyaw;
  d["t_ns"] = t_ns;
  d["bag_ns"] = bag_ns;
  d["header_ns"] = has_header ? py::object(header_ns) : py::object(py::none());
  return d;
}

py::object buffon_from_bags(const std::string& bag1, const std::string& bag2,
                            const std::string& topic, double width, const std::string& stamp_name,
                            const std::string& child_frame,
                            const std::optional<std::string>& arena) {
  const auto stamp = antkit::commands::bag_stamp(stamp_name, "stamp");
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = antkit::commands::buffon_from_bags_json(
        antkit::commands::buffon_from_bags(bag1, bag2, topic, width, stamp, child_frame,
                                           arena.value_or(""), "width"),
        width);
  }
  return to_python(j);
}

py::object check_stc_bag(const PyMap& m, const std::string& bag, const std::string& topic,
                         const std::string& stamp_name, const std::string& child_frame,
                         const std::optional<std::pair<std::int64_t, std::int64_t>>& start,
                         bool coverage) {
  const auto stamp = antkit::commands::bag_stamp(stamp_name, "stamp");
  antkit::testing::StcCheckRequest request;
  request.map_file = m.source.empty() ? "map" : m.source;
  request.tour_file = bag;
  request.start = optional_cell(start, "start");
  request.rule =
      coverage ? antkit::testing::TourRule::Coverage : antkit::testing::TourRule::ExactlyOnce;
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const auto c = antkit::commands::check_stc_bag(m.map, request.map_file, bag, topic, stamp,
                                                   child_frame, request);
    j = antkit::commands::check_stc_bag_json(c, m.source);
  }
  return to_python(j);
}

py::object check_cover_bag(const PyMap& m, const std::string& bag,
                           const std::vector<std::string>& topics, std::int64_t sensor,
                           const std::string& stamp_name, const std::string& child_frame) {
  const auto stamp = antkit::commands::bag_stamp(stamp_name, "stamp");
  const std::string name = m.source.empty() ? "map" : m.source;
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const auto c =
        antkit::commands::check_cover_bag(m.map, name, bag, topics, stamp, child_frame, sensor);
    j = antkit::commands::check_cover_bag_json(c, m.source);
  }
  return to_python(j);
}

// ---- errors ------------------------------------------------------------------------------------

// The library names some parameters by the command line's options (testing's "--start",
// "--sensor", devices' and commands' "--arena"): in Python they are arguments. `where` is "--X" or
// "--X:..." (a position in a spec); in a message the option is followed by its value.
struct OptionWord {
  std::string_view option, argument;
};
constexpr std::array<OptionWord, 8> kOptionWords{{{"--start", "start"},
                                                  {"--sensor", "sensor"},
                                                  {"--arena", "arena"},
                                                  {"--width", "width"},
                                                  {"--stamp", "stamp"},
                                                  {"--topic", "topic"},
                                                  {"--order", "order"},
                                                  {"--child-frame", "child_frame"}}};

std::string python_where(const std::string& where) {
  for (const auto& w : kOptionWords)
    if (where.starts_with(w.option) &&
        (where.size() == w.option.size() || where[w.option.size()] == ':'))
      return std::string(w.argument) + where.substr(w.option.size());
  return where;
}

std::string python_message(std::string message) {
  for (const auto& w : kOptionWords) {
    std::size_t at = 0;
    while ((at = message.find(w.option, at)) != std::string::npos) {
      const std::size_t end = at + w.option.size();
      const bool word_start = at == 0 || message[at - 1] == ' ' || message[at - 1] == '(';
      const bool word_end =
          end == message.size() || !(std::isalnum(static_cast<unsigned char>(message[end])) ||
                                     message[end] == '-' || message[end] == '_');
      if (word_start && word_end) {
        const std::string arg = std::string(w.argument) + "=";
        message.replace(at, w.option.size(), arg);
        at += arg.size();
      } else {
        at = end;
      }
    }
  }
  return message;
}

} // namespace

PYBIND11_MODULE(_antkit, m) {
  m.doc() = "antkit's compiled core; import antkit, not this module";
  m.attr("__version__") = ANTKIT_VERSION;
  // antkit.InputError: a ValueError whose str() is the library's located message, with the place
  // (`where`: a file, FILE:LINE:COL, or the argument) and the reason (`message`) apart.
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.attr("__doc__") =
      "Bad input: a malformed file (map, tour, trace, log, bag), an argument of the wrong type, "
      "an out-of-range value. A ValueError; str() is the located message, 'WHERE: MESSAGE', "
      "WHERE being a file (FILE:LINE:COL, FILE: byte N, ...) or the argument (start, "
      "path[3], trace[0, 1], ...).\n\n"
      "Attributes:\n"
      "    where: the place (a file and position, or the argument's name); '' when none\n"
      "    message: what is wrong and what was expected";
  input_error.attr("where") = "";
  input_error.attr("message") = "";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      const std::string where = python_where(e.where());
      const std::string message = python_message(e.message());
      py::object instance =
          py::handle(input_error.ptr())(text(where.empty() ? message : where + ": " + message));
      instance.attr("where") = text(where);
      instance.attr("message") = text(message);
      PyErr_SetObject(input_error.ptr(), instance.ptr());
    }
  });

  py::class_<PyMap>(m, "Map",
                    "A grid map: x the column, y the row counted down from the first row "
                    "(one cell = one robot-sized STC sub-cell). Made by antkit.read_map or "
                    "Map.from_array")
      .def_property_readonly(
          "width", [](const PyMap& p) { return p.map.cells.width(); },
          "The number of columns (cells along x)")
      .def_property_readonly(
          "height", [](const PyMap& p) { return p.map.cells.height(); },
          "The number of rows (cells along y, counted down from the first row)")
      .def_property_readonly(
          "start",
          [](const PyMap& p) -> py::object {
            return p.map.start ? py::object(cell_tuple(*p.map.start)) : py::object(py::none());
          },
          "The map's own start cell (x, y): an ASCII map's 'S' or Map.from_array's start; None "
          "when it has none")
      .def_property_readonly(
          "source", [](const PyMap& p) { return p.source; },
          "The file the map was read from, as given; '' for a map made from an array")
      .def_property_readonly(
          "resolution", [](const PyMap& p) { return p.map.resolution; },
          "Metres per cell: a ROS map's resolution; 1.0 for MovingAI, ASCII and array maps")
      .def_property_readonly(
          "origin",
          [](const PyMap& p) {
            return py::make_tuple(p.map.origin_x, p.map.origin_y, p.map.origin_yaw);
          },
          "A ROS map's origin (x, y, yaw): metres and radians of its lower-left pixel; "
          "(0.0, 0.0, 0.0) for the other formats and array maps")
      .def_static("_from_array", &map_from_array, py::arg("a"), py::arg("start"))
      .def("to_array", &map_to_array, "The map as a 2-D bool array, True = free, a[y, x]")
      .def("_write", &write_map, py::arg("path"))
      .def("__eq__",
           [](const PyMap& a, const py::object& other) -> py::object {
             if (!py::isinstance<PyMap>(other))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             const auto& b = other.cast<const PyMap&>();
             return py::bool_(a.map.cells == b.map.cells && a.map.start == b.map.start);
           })
      .def("__repr__", [](const PyMap& p) {
        return "<antkit.Map " + std::to_string(p.map.cells.width()) + "x" +
               std::to_string(p.map.cells.height()) +
               (p.source.empty() ? std::string() : " from " + p.source) + ">";
      });

  m.def("_read_map", &read_map, py::arg("path"));
  m.def("_stc", &run_stc, py::arg("map"), py::arg("variant"), py::arg("start"), py::arg("noise"),
        py::arg("seed"));
  m.def("_tour_hash", &tour_hash, py::arg("path"), py::arg("width"), py::arg("height"));
  m.def("_check_stc", &check_stc, py::arg("map"), py::arg("path"), py::arg("start"),
        py::arg("coverage"), py::arg("order"), py::arg("cells"));
  m.def("_check_explore_text", &check_explore_text);
  m.def("_check_explore_rows", &check_explore_rows);
  m.def("_check_cover_text", &check_cover_text);
  m.def("_check_cover_array", &check_cover_array);
  m.def("_buffon_from_logs", &buffon_from_logs);
  m.def("_buffon_estimate", &buffon_estimate);
  m.def("_buffon_from_trails", &buffon_from_trails);
  m.def("_replay", &replay);
  m.def("_read_log", &read_log);
  m.def("_bag_info", &bag_info);
  m.def("_read_bag_poses", &read_bag_poses);
  m.def("_buffon_from_bags", &buffon_from_bags);
  m.def("_check_stc_bag", &check_stc_bag);
  m.def("_check_cover_bag", &check_cover_bag);
}
