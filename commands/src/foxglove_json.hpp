#pragma once
// Foxglove messages as JSON for the commands' MCAP writers (bag_mcap.cpp, stc_mcap.cpp, ...): the
// fields devices::mcap_schema's texts name, built with nlohmann (keys sorted, numbers round-trip:
// the bytes depend on the values alone).
#include <algorithm>
#include <antkit/commands/stc_mcap.hpp>
#include <antkit/devices/mcap_export.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/io/mcap.hpp>
#include <antkit/maps/map_io.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace antkit::commands::foxglove {

// An MCAP file of JSON messages for Foxglove, built in memory and written whole: the schemas named
// (devices::mcap_schema's texts) added first, in that order, then channels on them by schema name.
class JsonMcap {
public:
  explicit JsonMcap(std::initializer_list<std::string_view> schemas) : w_(bytes_) {
    for (const auto name : schemas)
      ids_.emplace_back(std::string(name),
                        w_.add_schema(name, "jsonschema", devices::mcap_schema(name)));
  }
  std::uint16_t channel(std::string_view schema, const std::string& topic) {
    for (const auto& [name, id] : ids_)
      if (name == schema) return w_.add_channel(id, topic, "json");
    throw std::logic_error("JsonMcap: a channel of a schema not named up front");
  }
  void put(std::uint16_t channel, std::size_t seq, std::uint64_t t, const nlohmann::json& j) {
    w_.write({channel, static_cast<std::uint32_t>(seq), t, t, j.dump()});
  }
  // Closes the file and writes it to `out` whole (io::write_file_atomic); what it holds.
  McapWritten write(const std::filesystem::path& out) {
    w_.finish();
    McapWritten written{w_.bytes(), w_.messages(), w_.channel_counts()};
    io::write_file_atomic(out, bytes_.str());
    return written;
  }

private:
  std::ostringstream bytes_;
  io::mcap::Writer w_;
  std::vector<std::pair<std::string, std::uint16_t>> ids_;
};

inline nlohmann::json stamp_of(std::uint64_t t) {
  return {{"sec", t / 1000000000U}, {"nsec", t % 1000000000U}};
}
inline std::uint64_t at_or_zero(std::int64_t t) {
  return t < 0 ? 0 : static_cast<std::uint64_t>(t);
}

inline nlohmann::json pose_json(double x, double y, double yaw) {
  return {{"position", {{"x", x}, {"y", y}, {"z", 0.0}}},
          {"orientation",
           {{"x", 0.0}, {"y", 0.0}, {"z", std::sin(yaw / 2)}, {"w", std::cos(yaw / 2)}}}};
}

// A sub-cell's (a map cell's) centre in the map's frame (metres: the map's resolution and origin;
// x right, y up).
struct Point {
  double x, y;
};
inline Point cell_centre(const maps::GridMap& map, kernel::Cell c) {
  const double h = map.cells.height();
  const double lx = (c.x + 0.5) * map.resolution, ly = (h - 1 - c.y + 0.5) * map.resolution;
  const double co = std::cos(map.origin_yaw), si = std::sin(map.origin_yaw);
  return {map.origin_x + lx * co - ly * si, map.origin_y + lx * si + ly * co};
}

// The headings of a path of points ({x, y}): the way it last moved at each point (0 until it
// first moves; a point where it did not move keeps the heading before it).
template <class Points>
std::vector<double> headings(const Points& at) {
  std::vector<double> yaw(at.size(), 0.0);
  for (std::size_t k = 1; k < at.size(); ++k)
    yaw[k] = at[k].x == at[k - 1].x && at[k].y == at[k - 1].y
                 ? yaw[k - 1]
                 : std::atan2(at[k].y - at[k - 1].y, at[k].x - at[k - 1].x);
  return yaw;
}

// A foxglove.SceneUpdate of one entity `id` in `frame` at time t: a line list (pairs of points,
// each {x, y, z}) drawn `thickness` pixels wide in `color` ({r, g, b, a}).
inline nlohmann::json line_list_scene(std::uint64_t t, const std::string& frame,
                                      const std::string& id, nlohmann::json points,
                                      nlohmann::json color) {
  const nlohmann::json line{{"type", 2},
                            {"pose", pose_json(0, 0, 0)},
                            {"thickness", 2},
                            {"scale_invariant", true},
                            {"points", std::move(points)},
                            {"color", std::move(color)},
                            {"colors", nlohmann::json::array()},
                            {"indices", nlohmann::json::array()}};
  nlohmann::json entity{{"timestamp", stamp_of(t)},
                        {"frame_id", frame},
                        {"id", id},
                        {"lifetime", stamp_of(0)},
                        {"frame_locked", true},
                        {"metadata", nlohmann::json::array()},
                        {"lines", nlohmann::json::array({line})}};
  for (const char* empty :
       {"arrows", "cubes", "spheres", "cylinders", "triangles", "texts", "models"})
    entity[empty] = nlohmann::json::array();
  return {{"deletions", nlohmann::json::array()}, {"entities", nlohmann::json::array({entity})}};
}

// A foxglove.Grid of one UINT8 field over the map, its row 0 the map's bottom row (Grid rows
// count up along y from the pose, antkit's rows down from the first): `value(x, y)` with y down.
template <class Value>
inline nlohmann::json grid_json(const maps::GridMap& map, std::uint64_t t, const std::string& field,
                                Value value) {
  const std::int32_t w = map.cells.width(), h = map.cells.height();
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (std::int32_t r = 0; r < h; ++r)
    for (std::int32_t x = 0; x < w; ++x) bytes.push_back(static_cast<char>(value(x, h - 1 - r)));
  return {{"timestamp", stamp_of(t)},
          {"frame_id", "map"},
          {"pose", pose_json(map.origin_x, map.origin_y, map.origin_yaw)},
          {"column_count", w},
          {"cell_size", {{"x", map.resolution}, {"y", map.resolution}}},
          {"row_stride", w},
          {"cell_stride", 1},
          {"fields", nlohmann::json::array({{{"name", field}, {"offset", 0}, {"type", 1}}})},
          {"data", devices::base64(bytes)}};
}

inline nlohmann::json log_json(std::uint64_t t, int level, const std::string& message) {
  return {{"timestamp", stamp_of(t)}, {"level", level}, {"message", message},
          {"name", "antkit"},         {"file", ""},     {"line", 0}};
}

// The trail of a run of n poses: a PosesInFrame message at every ceil(n / 100)-th pose and the
// last (trail_due), each holding at most 1000 of the poses so far, its last the message's own
// (trail_poses; pose_at(j) gives pose j's JSON), as antkit's own logs' /trail.
inline bool trail_due(std::size_t k, std::size_t n) {
  const std::size_t every = std::max<std::size_t>(1, (n + 99) / 100);
  return k % every == 0 || k + 1 == n;
}
template <class PoseAt>
nlohmann::json trail_poses(std::size_t k, PoseAt pose_at) {
  const std::size_t stride = std::max<std::size_t>(1, (k + 1 + 999) / 1000);
  nlohmann::json trail = nlohmann::json::array();
  for (std::size_t j = k % stride; j <= k; j += stride) trail.push_back(pose_at(j));
  return trail;
}

} // namespace antkit::commands::foxglove
