// An STC tour as MCAP for Foxglove (stc_mcap.hpp's declaration is in json.hpp's neighbour,
// commands/stc_mcap.hpp).
#include "foxglove_json.hpp"

#include <algorithm>
#include <antkit/commands/stc_mcap.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/io/mcap.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <set>
#include <sstream>

namespace antkit::commands {

namespace {

using foxglove::grid_json, foxglove::log_json, foxglove::pose_json, foxglove::stamp_of;

using Point = foxglove::Point;
Point centre(const maps::GridMap& map, stc::SubCell c) {
  return foxglove::cell_centre(map, {c.x, c.y});
}

} // namespace

void check_stc_mcap_size(const kernel::OccupancyGrid& map) {
  if (static_cast<std::int64_t>(map.width()) * map.height() > kStcMcapMaxSubcells)
    throw kernel::InputError(
        "--mcap", "a tour over at most " + std::to_string(kStcMcapMaxSubcells) +
                      " sub-cells (the map has " +
                      std::to_string(static_cast<std::int64_t>(map.width()) * map.height()) +
                      "): a message per step");
}

McapWritten write_stc_mcap(const maps::GridMap& map, const stc::RunResult& r,
                           const std::string& map_name, const std::filesystem::path& out) {
  check_stc_mcap_size(map.cells);
  if (r.path.empty()) throw std::logic_error("write_stc_mcap: the run kept no path");
  const auto t_of = [](std::size_t step) { return static_cast<std::uint64_t>(step) * kStcStepNs; };
  foxglove::JsonMcap mcap({"foxglove.Grid", "foxglove.SceneUpdate", "foxglove.PoseInFrame",
                           "foxglove.PosesInFrame", "foxglove.Log"});
  const std::uint16_t map_ch = mcap.channel("foxglove.Grid", "/map");
  const std::uint16_t tree_ch = mcap.channel("foxglove.SceneUpdate", "/tree");
  const std::uint16_t pose_ch = mcap.channel("foxglove.PoseInFrame", "/pose");
  const std::uint16_t trail_ch = mcap.channel("foxglove.PosesInFrame", "/trail");
  const std::uint16_t log_ch = mcap.channel("foxglove.Log", "/log");
  const auto put = [&](std::uint16_t ch, std::size_t seq, std::uint64_t t,
                       const nlohmann::json& j) { mcap.put(ch, seq, t, j); };

  // Time 0: the map, the tree (cell centre to cell centre wherever the tour changes cell: the
  // spanning tree the tour circumnavigates, as the pictures draw it) and what ran.
  put(map_ch, 0, 0, grid_json(map, 0, "occupied", [&](std::int32_t x, std::int32_t y) {
        return map.cells[{x, y}] == kernel::Occupancy::Free ? 0 : 100;
      }));
  std::set<std::pair<kernel::Cell, kernel::Cell>> edges;
  nlohmann::json points = nlohmann::json::array();
  for (std::size_t i = 1; i < r.path.size(); ++i) {
    const kernel::Cell a{r.path[i - 1].x / 2, r.path[i - 1].y / 2};
    const kernel::Cell b{r.path[i].x / 2, r.path[i].y / 2};
    if (a == b || !edges.insert({std::min(a, b), std::max(a, b)}).second) continue;
    for (const auto& c : {a, b}) {
      // The cell's centre is the shared corner of its four sub-cells: between (2x, 2y) and
      // (2x + 1, 2y + 1).
      const Point p0 = centre(map, {2 * c.x, 2 * c.y}),
                  p1 = centre(map, {2 * c.x + 1, 2 * c.y + 1});
      points.push_back({{"x", (p0.x + p1.x) / 2}, {"y", (p0.y + p1.y) / 2}, {"z", 0.0}});
    }
  }
  put(tree_ch, 0, 0,
      foxglove::line_list_scene(0, "map", "spanning-tree", std::move(points),
                                {{"r", 0.6}, {"g", 0.6}, {"b", 0.6}, {"a", 1}}));
  put(log_ch, 0, 0,
      log_json(0, 2,
               "stc " + std::string(stc::variant_name(r.variant)) + " on " + map_name + " from (" +
                   std::to_string(r.path[0].x) + ", " + std::to_string(r.path[0].y) + "), " +
                   std::to_string(r.path.size()) + " positions, one every " +
                   std::to_string(kStcStepNs / 1000000) + " ms"));

  // Each step: the pose (facing the way it last moved), the trail (every ceil(n / 100)-th step and
  // the last, each at most 1000 poses), and for the exact variants the first repeat as an ERROR at
  // its step.
  std::vector<Point> at;
  at.reserve(r.path.size());
  for (const auto& c : r.path) at.push_back(centre(map, c));
  const auto yaw_at = [&](std::size_t k) {
    if (k == 0) return 0.0;
    return std::atan2(at[k].y - at[k - 1].y, at[k].x - at[k - 1].x);
  };
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(map.cells.width()) *
                                     static_cast<std::size_t>(map.cells.height()),
                                 0);
  bool repeat_logged = false;
  for (std::size_t k = 0; k < at.size(); ++k) {
    const std::uint64_t t = t_of(k);
    const auto seq = static_cast<std::uint32_t>(k);
    put(pose_ch, seq, t,
        {{"timestamp", stamp_of(t)},
         {"frame_id", "map"},
         {"pose", pose_json(at[k].x, at[k].y, yaw_at(k))}});
    if (foxglove::trail_due(k, at.size()))
      put(trail_ch, seq, t,
          {{"timestamp", stamp_of(t)},
           {"frame_id", "map"},
           {"poses", foxglove::trail_poses(k, [&](std::size_t j) {
              return pose_json(at[j].x, at[j].y, yaw_at(j));
            })}});
    auto& s =
        seen[static_cast<std::size_t>(r.path[k].y) * static_cast<std::size_t>(map.cells.width()) +
             static_cast<std::size_t>(r.path[k].x)];
    if (s != 0 && !repeat_logged && r.variant != stc::Variant::Full && k + 1 != at.size()) {
      repeat_logged = true;
      put(log_ch, seq, t,
          log_json(t, 4,
                   "step " + std::to_string(k) + ": sub-cell (" + std::to_string(r.path[k].x) +
                       ", " + std::to_string(r.path[k].y) + ") entered a second time"));
    }
    s = 1;
  }
  const bool ok = stc::keeps_invariants(r);
  const std::uint64_t end = t_of(at.size() - 1);
  put(log_ch, static_cast<std::uint32_t>(at.size() - 1), end,
      log_json(end, ok ? 2 : 4,
               std::string(ok ? "the tour keeps its invariants" : "the tour breaks an invariant") +
                   ": covered " + std::to_string(r.covered) + " of " +
                   std::to_string(r.reachable_subcells) + ", repeats " + std::to_string(r.repeats) +
                   (r.returned_to_start ? ", back at the start" : "")));
  return mcap.write(out);
}

} // namespace antkit::commands
