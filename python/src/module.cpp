// antkit's Python package, the compiled half (`antkit._antkit`): the library's typed calls on numpy
// arrays and plain Python types. The pure-Python half (antkit/__init__.py) wraps the results in
// objects; its docstrings and antkit/__init__.pyi document the API.
//
// Results are the JSON the command prints (commands/), converted to dicts, so that a field means
// the same in Python as in `antkit ... --format json`. Bad input raises antkit.InputError (a
// ValueError) carrying the command's located message ("FILE:LINE:COL: ...", "--start: ..."). Every
// call that runs a tour, a check or a replay releases the GIL while it runs.
#include <antkit/commands/json.hpp>
#include <antkit/commands/options.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/segment.hpp>
#include <antkit/los/cell_state.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/run_audit.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <cmath>
#include <cstdint>
#include <optional>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <string>
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
    return py::str(j.get_ref<const std::string&>());
  case nlohmann::json::value_t::array: {
    py::list out;
    for (const auto& item : j) out.append(to_python(item));
    return out;
  }
  case nlohmann::json::value_t::object: {
    py::dict out;
    for (const auto& [key, value] : j.items()) out[py::str(key)] = to_python(value);
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

// An (n, 2) integer array as cells, pairs in x, y order (or row, col with `row_col`).
std::vector<Cell> cells_from_array(const py::array& a, const char* what, bool row_col) {
  if (a.ndim() != 2 || a.shape(1) != 2)
    throw InputError(what, "expected an (n, 2) array of integer pairs, not shape " +
                               std::string(py::str(a.attr("shape"))));
  const auto kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw InputError(what, "expected integer pairs (dtype int or uint), not dtype " +
                               std::string(py::str(a.dtype())));
  const auto v = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!v) throw InputError(what, "cannot read the array as 64-bit integers");
  const auto r = v.unchecked<2>();
  std::vector<Cell> out;
  out.reserve(static_cast<std::size_t>(r.shape(0)));
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    const std::int64_t x = r(i, 0), y = r(i, 1);
    if (x < INT32_MIN || x > INT32_MAX || y < INT32_MIN || y > INT32_MAX) {
      const std::string where = std::string(what) + "[" + std::to_string(i) + "]";
      throw InputError(where, "(" + std::to_string(x) + ", " + std::to_string(y) +
                                  ") is outside [-2^31, 2^31)");
    }
    Cell c{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
    if (row_col) std::swap(c.x, c.y);
    out.push_back(c);
  }
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
    throw py::type_error("Map.from_array: expected a 2-D bool array (True = free), not dtype " +
                         std::string(py::str(a.dtype())) +
                         "; from an occupancy grid with 0 = free, pass grid == 0");
  if (a.ndim() != 2)
    throw py::type_error("Map.from_array: expected a 2-D array (rows = y), not " +
                         std::to_string(a.ndim()) + "-D");
  if (a.shape(0) < 1 || a.shape(1) < 1 || a.shape(0) > (1 << 30) || a.shape(1) > (1 << 30))
    throw InputError("array", "a map is 1 to 2^30 cells wide and high, not " +
                                  std::to_string(a.shape(1)) + "x" + std::to_string(a.shape(0)));
  const auto v = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(a);
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
  const auto w = checked_i32(width, "width");
  const auto h = checked_i32(height, "height");
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
    if (!a) throw py::type_error("check_stc: path is an (n, 2) array, a list of pairs or a file");
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

py::object check_cover_text(const PyMap& m, const std::string& text, const std::string& source,
                            std::optional<std::int64_t> sensor) {
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    antkit::testing::check_sensor_range(sensor);
    const auto trace = antkit::testing::read_cover_trace(text, source);
    j = antkit::commands::check_cover_json(
        antkit::testing::check_cover(m.map.cells, trace, sensor, source), m.source);
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
    const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!v) throw InputError(what, "cannot read the array as numbers");
    const auto r = v.unchecked<2>();
    std::vector<antkit::kernel::FxPoint> out;
    out.reserve(static_cast<std::size_t>(r.shape(0)));
    for (py::ssize_t i = 0; i < r.shape(0); ++i) {
      const std::string where = std::string(what) + "[" + std::to_string(i) + "]";
      out.push_back({antkit::geometry::fixed_from_double<antkit::kernel::Fx>(r(i, 0), where),
                     antkit::geometry::fixed_from_double<antkit::kernel::Fx>(r(i, 1), where)});
    }
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
  header["antkit_version"] = h.antkit_version;
  header["robot"] = h.robot;
  header["port"] = h.port;
  header["baud"] = h.baud;
  header["framing"] = h.framing;
  header["controller"] = h.controller;
  py::dict params;
  for (const auto& [k, v] : h.params) params[py::str(k)] = v;
  header["params"] = params;
  header["seed"] = h.seed;
  header["arena"] = h.arena.empty() ? py::object(py::none()) : py::object(py::str(h.arena));
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
    stop["reason"] = s->reason;
    stop["io"] = exchanges(s->io);
    out["stop"] = stop;
  } else {
    out["stop"] = py::none();
  }
  return out;
}

} // namespace

PYBIND11_MODULE(_antkit, m) {
  m.doc() = "antkit's compiled core; import antkit, not this module";
  m.attr("__version__") = ANTKIT_VERSION;
  // antkit.InputError: a ValueError whose str() is the command line's located message, with the
  // place (`where`: a file, FILE:LINE:COL, or the argument) and the reason (`message`) apart.
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object instance = py::handle(input_error.ptr())(e.what());
      instance.attr("where") = e.where();
      instance.attr("message") = e.message();
      PyErr_SetObject(input_error.ptr(), instance.ptr());
    }
  });

  py::class_<PyMap>(m, "Map",
                    "A grid map: x the column, y the row counted down from the first row "
                    "(one cell = one robot-sized STC sub-cell)")
      .def_property_readonly("width", [](const PyMap& p) { return p.map.cells.width(); })
      .def_property_readonly("height", [](const PyMap& p) { return p.map.cells.height(); })
      .def_property_readonly("start",
                             [](const PyMap& p) -> py::object {
                               return p.map.start ? py::object(cell_tuple(*p.map.start))
                                                  : py::object(py::none());
                             })
      .def_property_readonly("source", [](const PyMap& p) { return p.source; })
      .def_property_readonly("resolution", [](const PyMap& p) { return p.map.resolution; })
      .def_static("from_array", &map_from_array, py::arg("a"), py::kw_only(),
                  py::arg("start") = py::none(),
                  "A map from a 2-D bool array, True = free, a[y, x] (row = y); start: an "
                  "optional free (x, y), as an ASCII map's 'S'")
      .def("to_array", &map_to_array, "The map as a 2-D bool array, True = free, a[y, x]")
      .def("write", &write_map, py::arg("path"),
           "Writes the map: MovingAI (.map) or ASCII (.txt, .ascii; the start as 'S'), by the "
           "name's extension (ROS maps are read-only); written whole or not at all")
      .def("__eq__", [](const PyMap& a, const PyMap& b) {
        return a.map.cells == b.map.cells && a.map.start == b.map.start;
      });

  m.def("read_map", &read_map, py::arg("path"),
        "Reads a map: MovingAI (.map), ROS (.yaml and its image) or ASCII (.txt, .ascii; 'S' the "
        "start), by the name's extension; InputError at FILE:LINE:COL when malformed");
  m.def("_stc", &run_stc, py::arg("map"), py::arg("variant"), py::arg("start"), py::arg("noise"),
        py::arg("seed"));
  m.def("tour_hash", &tour_hash, py::arg("path"), py::arg("width"), py::arg("height"),
        "The trace hash of a tour given as its (x, y) positions, the start first, on a map of "
        "width x height sub-cells: antkit stc's \"hash\" for the same tour");
  m.def("_check_stc", &check_stc, py::arg("map"), py::arg("path"), py::arg("start"),
        py::arg("coverage"), py::arg("order"), py::arg("cells"));
  m.def("_check_explore_text", &check_explore_text);
  m.def("_check_cover_text", &check_cover_text);
  m.def("_buffon_from_logs", &buffon_from_logs);
  m.def("_buffon_estimate", &buffon_estimate);
  m.def("_buffon_from_trails", &buffon_from_trails);
  m.def("_replay", &replay);
  m.def("_read_log", &read_log);
}
