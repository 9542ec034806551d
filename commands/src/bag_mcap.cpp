// A bag's poses back out to MCAP, with the map and a check's result (bags.hpp, export_bag_mcap).
#include "foxglove_json.hpp"

#include <algorithm>
#include <antkit/commands/bags.hpp>
#include <antkit/devices/mcap_export.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/io/mcap.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <cmath>
#include <map>
#include <sstream>

namespace antkit::commands {

namespace {

using kernel::InputError;
namespace mcap = io::mcap;
using foxglove::at_or_zero, foxglove::grid_json, foxglove::log_json, foxglove::pose_json,
    foxglove::stamp_of;

} // namespace

BagMcapSummary export_bag_mcap(const BagMcapRequest& r) {
  if (r.topics.empty()) throw InputError("--topic", "name at least one pose topic");
  if (r.check != "" && r.check != "stc" && r.check != "cover")
    throw InputError("--check", "expected stc or cover, not " + r.check);
  if (r.check == "stc" && r.topics.size() != 1)
    throw InputError("--check", "check stc takes one robot: one --topic");
  BagMcapSummary out;
  // The check first: its refusals (a pose off the map, a bad sensor range) come before any file.
  const maps::GridMap map = maps::load_map(r.map_file);
  std::vector<io::bag::PoseTrack> tracks;
  std::optional<std::int64_t> violation_ns;
  if (r.check == "stc") {
    testing::StcCheckRequest request;
    request.map_file = r.map_file;
    const auto c =
        check_stc_bag(map, r.map_file, r.bag, r.topics[0], r.stamp, r.child_frame, request);
    tracks.push_back(c.track);
    out.check_ok = c.report.audit.ok();
    out.check_text = out.check_ok ? "check stc: every reachable cell entered exactly once"
                                  : "check stc: " + c.report.audit.first.describe();
    violation_ns = c.violation_ns();
  } else if (r.check == "cover") {
    const auto c =
        check_cover_bag(map, r.map_file, r.bag, r.topics, r.stamp, r.child_frame, r.sensor);
    tracks = c.tracks;
    out.check_ok = c.report.audit.ok();
    out.check_text = out.check_ok ? "check cover: " + std::to_string(c.report.audit.viewed) +
                                        " of " + std::to_string(c.report.audit.viewable) +
                                        " cells viewed, every rule kept"
                                  : "check cover: " + c.report.audit.first;
    violation_ns = c.violation_ns();
  } else {
    for (const auto& topic : r.topics)
      tracks.push_back(io::bag::read_poses(r.bag, topic, r.stamp, r.child_frame));
  }
  // Each robot's cells (the same reading as the checks'), counted per cell for /visits.
  std::vector<std::vector<BagCell>> cells;
  std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t> visits;
  std::uint64_t first = UINT64_MAX, last = 0;
  for (const auto& t : tracks) {
    if (t.poses.empty())
      throw InputError(r.bag, "topic " + t.topic + ": no poses, so nothing to export");
    cells.push_back(bag_cells(map, t, r.map_file));
    for (const auto& c : cells.back()) ++visits[{c.x, c.y}];
    first = std::min(first, at_or_zero(t.poses.front().t_ns));
    last = std::max(last, at_or_zero(t.poses.back().t_ns));
  }

  std::ostringstream bytes;
  mcap::Writer w(bytes);
  std::map<std::string, std::uint16_t> schemas;
  const auto channel = [&](const std::string& schema, const std::string& topic) {
    if (!schemas.count(schema))
      schemas[schema] = w.add_schema(schema, "jsonschema", devices::mcap_schema(schema));
    return w.add_channel(schemas[schema], topic, "json");
  };
  const std::uint16_t map_channel = channel("foxglove.Grid", "/map");
  const std::uint16_t visits_channel = channel("foxglove.Grid", "/visits");
  const std::uint16_t log_channel = channel("foxglove.Log", "/log");
  std::vector<std::uint16_t> pose_channels, trail_channels;
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const std::string robot = "/robot" + std::to_string(i);
    pose_channels.push_back(channel("foxglove.PoseInFrame", robot + "/pose"));
    trail_channels.push_back(channel("foxglove.PosesInFrame", robot + "/trail"));
  }
  // Messages in time order (MCAP readers sort within chunks; a file in order scrubs best).
  struct Pending {
    std::uint64_t t;
    std::uint16_t channel;
    std::uint32_t sequence;
    std::string data;
  };
  std::vector<Pending> pending;
  const auto add = [&](std::uint64_t t, std::uint16_t ch, std::uint32_t seq,
                       const nlohmann::json& j) {
    pending.push_back({t, ch, seq, j.dump()});
  };
  add(first, map_channel, 0, grid_json(map, first, "occupied", [&](std::int32_t x, std::int32_t y) {
        return map.cells[{x, y}] == kernel::Occupancy::Free ? 0 : 100;
      }));
  add(first, log_channel, 0,
      log_json(
          first, 2,
          "bag " + r.bag + ", map " + r.map_file + ", " + std::to_string(tracks.size()) +
              " robot(s): " + [&] {
                std::string s;
                for (std::size_t i = 0; i < tracks.size(); ++i)
                  s += (i ? ", " : "") + std::string("/robot") + std::to_string(i) + " = " +
                       tracks[i].topic;
                return s;
              }()));
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const auto& poses = tracks[i].poses;
    for (std::size_t k = 0; k < poses.size(); ++k) {
      const auto& p = poses[k];
      const std::uint64_t t = at_or_zero(p.t_ns);
      add(t, pose_channels[i], static_cast<std::uint32_t>(k),
          {{"timestamp", stamp_of(t)}, {"frame_id", "map"}, {"pose", pose_json(p.x, p.y, p.yaw)}});
      if (!foxglove::trail_due(k, poses.size())) continue;
      const auto trail = foxglove::trail_poses(
          k, [&](std::size_t j) { return pose_json(poses[j].x, poses[j].y, poses[j].yaw); });
      add(t, trail_channels[i], static_cast<std::uint32_t>(k),
          {{"timestamp", stamp_of(t)}, {"frame_id", "map"}, {"poses", trail}});
    }
  }
  add(last, visits_channel, 0, grid_json(map, last, "entries", [&](std::int32_t x, std::int32_t y) {
        const auto v = visits.find({x, y});
        return v == visits.end() ? 0U : std::min<std::uint32_t>(v->second, 255);
      }));
  if (!r.check.empty()) {
    const std::uint64_t t = violation_ns ? at_or_zero(*violation_ns) : last;
    add(t, log_channel, 1, log_json(t, out.check_ok ? 2 : 4, out.check_text));
  }
  std::stable_sort(pending.begin(), pending.end(),
                   [](const Pending& a, const Pending& b) { return a.t < b.t; });
  for (auto& m : pending) w.write({m.channel, m.sequence, m.t, m.t, std::move(m.data)});
  w.finish();
  out.bytes = w.bytes();
  out.messages = w.messages();
  out.channels = w.channel_counts();
  io::write_file_atomic(r.out, bytes.str());
  return out;
}

nlohmann::json bag_mcap_json(const BagMcapRequest& r, const BagMcapSummary& s) {
  nlohmann::json channels = nlohmann::json::object();
  for (const auto& [topic, n] : s.channels) channels[topic] = n;
  nlohmann::json j{{"bag", r.bag},      {"map", r.map_file},      {"out", r.out},
                   {"bytes", s.bytes},  {"messages", s.messages}, {"channels", channels},
                   {"topics", r.topics}};
  j["check"] = r.check.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.check);
  j["check_ok"] = r.check.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.check_ok);
  j["check_result"] = r.check.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.check_text);
  return j;
}

} // namespace antkit::commands
