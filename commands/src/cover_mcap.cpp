// A coverage run's trace as MCAP for Foxglove (cover_mcap.hpp).
#include "foxglove_json.hpp"

#include <algorithm>
#include <antkit/commands/cover_mcap.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/io/mcap.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <sstream>

namespace antkit::commands {

using foxglove::grid_json, foxglove::log_json, foxglove::pose_json, foxglove::stamp_of;

McapWritten write_cover_mcap(const kernel::OccupancyGrid& cells, const testing::CoverTrace& trace,
                             const testing::CoverCheckReport* check, const std::string& what,
                             const std::filesystem::path& out) {
  const std::size_t ticks = trace.cells.size();
  const auto robots = static_cast<std::size_t>(std::max(trace.robots, 0));
  if (ticks == 0 || robots == 0) throw kernel::InputError("--mcap", "the run has no ticks");
  if (static_cast<double>(ticks) * static_cast<double>(robots) >
      static_cast<double>(kStcMcapMaxSubcells))
    throw kernel::InputError("--mcap", "at most " + std::to_string(kStcMcapMaxSubcells) +
                                           " robot-ticks (a message each), not " +
                                           std::to_string(ticks) + " ticks of " +
                                           std::to_string(robots) + " robots");
  maps::GridMap map;
  map.cells = cells;
  const auto t_of = [](std::size_t k) { return static_cast<std::uint64_t>(k) * kCoverTickNs; };
  const double h = cells.height();
  const auto pose_of = [&](std::size_t k, std::size_t r) {
    const auto& c = trace.cells[k][r];
    const double yaw = trace.bearings[k][r] * (M_PI / 4); // bearing 2 is up (y down in cells)
    return pose_json(c.x + 0.5, h - 1 - c.y + 0.5, yaw);
  };
  foxglove::JsonMcap mcap(
      {"foxglove.Grid", "foxglove.PoseInFrame", "foxglove.PosesInFrame", "foxglove.Log"});
  const std::uint16_t map_ch = mcap.channel("foxglove.Grid", "/map");
  const std::uint16_t log_ch = mcap.channel("foxglove.Log", "/log");
  std::vector<std::uint16_t> pose_ch, trail_ch;
  for (std::size_t r = 0; r < robots; ++r) {
    const std::string robot = "/robot" + std::to_string(r);
    pose_ch.push_back(mcap.channel("foxglove.PoseInFrame", robot + "/pose"));
    trail_ch.push_back(mcap.channel("foxglove.PosesInFrame", robot + "/trail"));
  }
  const auto put = [&](std::uint16_t ch, std::size_t seq, std::uint64_t t,
                       const nlohmann::json& j) { mcap.put(ch, seq, t, j); };
  put(map_ch, 0, 0, grid_json(map, 0, "occupied", [&](std::int32_t x, std::int32_t y) {
        return cells[{x, y}] == kernel::Occupancy::Free ? 0 : 100;
      }));
  put(log_ch, 0, 0, log_json(0, 2, what));
  const std::int64_t first_tick = check && !check->audit.ok() ? check->audit.first_tick : -1;
  for (std::size_t k = 0; k < ticks; ++k) {
    const std::uint64_t t = t_of(k);
    for (std::size_t r = 0; r < robots; ++r) {
      put(pose_ch[r], k, t,
          {{"timestamp", stamp_of(t)}, {"frame_id", "map"}, {"pose", pose_of(k, r)}});
      if (!foxglove::trail_due(k, ticks)) continue;
      const auto trail = foxglove::trail_poses(k, [&](std::size_t j) { return pose_of(j, r); });
      put(trail_ch[r], k, t, {{"timestamp", stamp_of(t)}, {"frame_id", "map"}, {"poses", trail}});
    }
    if (first_tick >= 0 && static_cast<std::size_t>(first_tick) == k)
      put(log_ch, k, t, log_json(t, 4, "check cover: " + check->audit.first));
  }
  const std::uint64_t end = t_of(ticks - 1);
  if (check && (check->audit.ok() || first_tick < 0))
    put(log_ch, ticks - 1, end,
        log_json(end, check->audit.ok() ? 2 : 4,
                 check->audit.ok()
                     ? "check cover: every rule kept; " + std::to_string(check->audit.viewed) +
                           " of " + std::to_string(check->audit.viewable) + " cells viewed"
                     : "check cover: " + check->audit.first));
  return mcap.write(out);
}

McapWritten cover_trace_mcap(const kernel::OccupancyGrid& map, const std::string& trace_file,
                             std::optional<std::int64_t> sensor,
                             const testing::CoverCheckReport* check, const std::string& what,
                             const std::filesystem::path& out) {
  const auto trace = testing::read_cover_trace(
      testing::read_text_file(trace_file, "trace", std::size_t{1} << 30), trace_file);
  if (check != nullptr) return write_cover_mcap(map, trace, check, what, out);
  const auto report = testing::check_cover(map, trace, sensor, trace_file);
  return write_cover_mcap(map, trace, &report, what, out);
}

} // namespace antkit::commands
