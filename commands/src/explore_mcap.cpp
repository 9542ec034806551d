// A two-robot LOS exploration as MCAP for Foxglove (explore_mcap.hpp).
#include "foxglove_json.hpp"

#include <antkit/commands/explore_mcap.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/io/mcap.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <sstream>

namespace antkit::commands {

using foxglove::grid_json, foxglove::log_json, foxglove::pose_json, foxglove::stamp_of;

los::ExploreResult explore_mcap(const kernel::OccupancyGrid& truth,
                                const std::array<kernel::Cell, 2>& start,
                                const los::ExploreOptions& options, const std::string& what,
                                const std::filesystem::path& out, McapWritten* written) {
  // Each tick's observation: both robots' cells and the line of sight. Kept up to the size limit
  // (a run past it is refused below, so the trace stops growing there).
  const auto max_ticks = static_cast<std::size_t>(kStcMcapMaxSubcells / 2);
  std::array<std::vector<foxglove::Point>, 2> at;
  std::vector<std::uint8_t> sight;
  std::size_t ticks = 0;
  const double h = truth.height();
  const los::ExploreResult r =
      los::explore(truth, start[0], start[1], options,
                   [&](const los::TwoRobotWorld&, const los::ExplorationMap&,
                       const los::TeamObservation& obs, const los::TeamCommand&) {
                     if (++ticks > max_ticks) return;
                     for (std::size_t i = 0; i < 2; ++i) {
                       const kernel::Cell c = obs.robots[i].position;
                       at[i].push_back({c.x + 0.5, h - 1 - c.y + 0.5});
                     }
                     sight.push_back(obs.line_of_sight ? 1 : 0);
                   });
  if (ticks > max_ticks)
    throw kernel::InputError("--mcap", "at most " + std::to_string(max_ticks) +
                                           " ticks of two robots (a message each), not " +
                                           std::to_string(ticks));
  if (ticks == 0) throw std::logic_error("explore_mcap: the run observed nothing");

  maps::GridMap map;
  map.cells = truth;
  const auto t_of = [](std::size_t k) { return static_cast<std::uint64_t>(k) * kExploreTickNs; };
  const std::array<std::vector<double>, 2> yaw{foxglove::headings(at[0]),
                                               foxglove::headings(at[1])};
  foxglove::JsonMcap mcap(
      {"foxglove.Grid", "foxglove.PoseInFrame", "foxglove.PosesInFrame", "foxglove.Log"});
  const std::uint16_t map_ch = mcap.channel("foxglove.Grid", "/map");
  const std::uint16_t explored_ch = mcap.channel("foxglove.Grid", "/explored");
  const std::uint16_t log_ch = mcap.channel("foxglove.Log", "/log");
  std::array<std::uint16_t, 2> pose_ch{}, trail_ch{};
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string robot = i == 0 ? "/robotA" : "/robotB";
    pose_ch[i] = mcap.channel("foxglove.PoseInFrame", robot + "/pose");
    trail_ch[i] = mcap.channel("foxglove.PosesInFrame", robot + "/trail");
  }
  const auto put = [&](std::uint16_t ch, std::size_t seq, std::uint64_t t,
                       const nlohmann::json& j) { mcap.put(ch, seq, t, j); };
  put(map_ch, 0, 0, grid_json(map, 0, "occupied", [&](std::int32_t x, std::int32_t y) {
        return truth[{x, y}] == kernel::Occupancy::Free ? 0 : 100;
      }));
  put(log_ch, 0, 0,
      log_json(0, 2,
               what + ": A from (" + std::to_string(start[0].x) + ", " +
                   std::to_string(start[0].y) + "), B from (" + std::to_string(start[1].x) + ", " +
                   std::to_string(start[1].y) + "), one tick every " +
                   std::to_string(kExploreTickNs / 1000000) + " ms"));
  for (std::size_t k = 0; k < ticks; ++k) {
    const std::uint64_t t = t_of(k);
    for (std::size_t i = 0; i < 2; ++i) {
      put(pose_ch[i], k, t,
          {{"timestamp", stamp_of(t)},
           {"frame_id", "map"},
           {"pose", pose_json(at[i][k].x, at[i][k].y, yaw[i][k])}});
      if (!foxglove::trail_due(k, ticks)) continue;
      put(trail_ch[i], k, t,
          {{"timestamp", stamp_of(t)},
           {"frame_id", "map"},
           {"poses", foxglove::trail_poses(k, [&](std::size_t j) {
              return pose_json(at[i][j].x, at[i][j].y, yaw[i][j]);
            })}});
    }
    if (k > 0 && sight[k] != sight[k - 1])
      put(log_ch, k, t,
          log_json(t, 2,
                   "tick " + std::to_string(k) + ": line of sight " +
                       (sight[k] != 0 ? "regained" : "lost")));
  }
  const std::size_t last = ticks - 1;
  const std::uint64_t end = t_of(last);
  put(explored_ch, last, end, grid_json(map, end, "state", [&](std::int32_t x, std::int32_t y) {
        return static_cast<std::uint8_t>(r.cells[{x, y}]);
      }));
  std::string result = "explored " + std::to_string(r.explored) + " cells (" +
                       std::to_string(r.unobservable) + " unobservable) in " +
                       std::to_string(r.steps) + " steps, eme " + std::to_string(r.eme) +
                       ", moves A " + std::to_string(r.moves[0]) + " B " +
                       std::to_string(r.moves[1]) + ", hash " + kernel::hash_hex(r.hash);
  if (options.algorithm == los::Algorithm::FastWallFollow)
    result += "; sight losses " + std::to_string(r.sight_losses) + ", causes found " +
              std::to_string(r.causes_found) + ", meetings " + std::to_string(r.meetings);
  put(log_ch, last, end,
      log_json(end, r.completed ? 2 : 4,
               r.completed ? result
                           : "the exploration did not finish within its tick budget: " + result));
  const McapWritten counts = mcap.write(out);
  if (written != nullptr) *written = counts;
  return r;
}

} // namespace antkit::commands
