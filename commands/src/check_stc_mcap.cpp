// A checked tour as MCAP for Foxglove (check_stc_mcap.hpp).
#include "foxglove_json.hpp"

#include <antkit/commands/check_stc_mcap.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/io/mcap.hpp>
#include <antkit/kernel/input_error.hpp>
#include <sstream>

namespace antkit::commands {

using foxglove::grid_json, foxglove::log_json, foxglove::pose_json, foxglove::stamp_of;

CheckedStcMcap check_stc_mcap(const testing::StcCheckRequest& request,
                              const std::filesystem::path& out) {
  maps::GridMap map = maps::load_map(request.map_file);
  const testing::TourFile tour = testing::read_tour_file(request.tour_file, request.order);
  if (static_cast<std::int64_t>(tour.path.size()) > kStcMcapMaxSubcells)
    throw kernel::InputError("--mcap", "a tour of at most " + std::to_string(kStcMcapMaxSubcells) +
                                           " positions (" + request.tour_file + " has " +
                                           std::to_string(tour.path.size()) +
                                           "): a message per position");
  CheckedStcMcap result{testing::check_stc(map, tour, request), {}};
  const testing::StcCheckReport& r = result.report;
  if (request.cells) {
    // The sub-cells the check used: 2 x 2 per cell, each half the cell's side.
    kernel::OccupancyGrid sub(r.width, r.height, kernel::Occupancy::Blocked);
    for (std::int32_t y = 0; y < sub.height(); ++y)
      for (std::int32_t x = 0; x < sub.width(); ++x) sub[{x, y}] = map.cells[{x / 2, y / 2}];
    map.cells = std::move(sub);
    map.resolution /= 2;
  }
  const auto t_of = [](std::size_t k) { return static_cast<std::uint64_t>(k) * kStcStepNs; };
  const std::size_t n = tour.path.size();
  std::vector<foxglove::Point> at;
  at.reserve(n);
  for (const auto& c : tour.path) at.push_back(foxglove::cell_centre(map, c));
  const std::vector<double> yaw = foxglove::headings(at);

  foxglove::JsonMcap mcap(
      {"foxglove.Grid", "foxglove.PoseInFrame", "foxglove.PosesInFrame", "foxglove.Log"});
  const std::uint16_t map_ch = mcap.channel("foxglove.Grid", "/map");
  const std::uint16_t pose_ch = mcap.channel("foxglove.PoseInFrame", "/pose");
  const std::uint16_t trail_ch = mcap.channel("foxglove.PosesInFrame", "/trail");
  const std::uint16_t log_ch = mcap.channel("foxglove.Log", "/log");
  const auto put = [&](std::uint16_t ch, std::size_t seq, std::uint64_t t,
                       const nlohmann::json& j) { mcap.put(ch, seq, t, j); };
  put(map_ch, 0, 0, grid_json(map, 0, "occupied", [&](std::int32_t x, std::int32_t y) {
        return map.cells[{x, y}] == kernel::Occupancy::Free ? 0 : 100;
      }));
  put(log_ch, 0, 0,
      log_json(0, 2,
               "check stc " + request.tour_file + " on " + request.map_file + ": " +
                   std::to_string(n) + " positions from (" + std::to_string(r.start.x) + ", " +
                   std::to_string(r.start.y) + ") (" + r.start_from + "), rule " +
                   std::string(testing::tour_rule_name(r.audit.rule)) + ", one every " +
                   std::to_string(kStcStepNs / 1000000) + " ms"));
  const testing::StcAudit& a = r.audit;
  // The broken rule's position; a rule about the whole tour (step -1) goes at the last one.
  const std::size_t last = n == 0 ? 0 : n - 1;
  const std::size_t verdict_at =
      a.ok() || a.first.step < 0 ? last : std::min(static_cast<std::size_t>(a.first.step), last);
  const auto verdict = [&] {
    const std::uint64_t t = t_of(verdict_at);
    put(log_ch, verdict_at, t,
        a.ok()
            ? log_json(t, 2,
                       "check stc: every rule kept; covered " + std::to_string(a.covered) + " of " +
                           std::to_string(a.reachable) + ", repeats " + std::to_string(a.repeats))
            : log_json(t, 4, "check stc: " + a.first.describe()));
  };
  if (n == 0) verdict();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint64_t t = t_of(k);
    put(pose_ch, k, t,
        {{"timestamp", stamp_of(t)},
         {"frame_id", "map"},
         {"pose", pose_json(at[k].x, at[k].y, yaw[k])}});
    if (foxglove::trail_due(k, n))
      put(trail_ch, k, t,
          {{"timestamp", stamp_of(t)},
           {"frame_id", "map"},
           {"poses", foxglove::trail_poses(
                         k, [&](std::size_t j) { return pose_json(at[j].x, at[j].y, yaw[j]); })}});
    if (k == verdict_at) verdict(); // in time order, after the position's pose
  }
  result.written = mcap.write(out);
  return result;
}

} // namespace antkit::commands
