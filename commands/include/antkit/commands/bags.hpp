#pragma once
// ROS 2 bags in the commands (issue 42, In): `antkit bag info` and `antkit buffon-from-logs
// --topic` over two bags. The readers are io's (antkit/io/bag.hpp); here are the choices the
// commands make from their options and the JSON of their results.
#include <antkit/devices/odometry.hpp>
#include <antkit/io/bag.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/testing/run_audit.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace antkit::commands {

// `--stamp bag|header`, or an InputError(where).
[[nodiscard]] io::bag::Stamp bag_stamp(const std::string& name, const std::string& where);

// `antkit bag info`: {"bag", "storage", "files", "messages", "start_ns", "end_ns", "duration_s",
// "topics": [{"topic", "type", "encoding", "messages", "start_ns", "end_ns"}]} (bag time, ns since
// the epoch; null without messages).
[[nodiscard]] nlohmann::json bag_info_json(const io::bag::BagInfo& info);

// Paper 000's measurement from two bags' pose topics, taken as two random walks (visit 1, visit
// 2) in the bags' metres: the poses quantized to kernel::Fx (Q15.16 metres: |x|, |y| < 32768 m),
// their polylines' exact proper crossings (kernel::count_proper_crossings), BC along walk 2 over
// walk 1's band of `width_m`, and the closed form with the precision rule's interval
// (devices::estimate_area, with no wall encounters: a bag has no front readings, so the erosion
// factor is 1 and area_corrected = area_raw).
struct BuffonFromBags {
  io::bag::PoseTrack walk1, walk2;
  double length1_m = 0, length2_m = 0;
  std::uint64_t bc = 0, crossings_exact = 0;
  double variance_visit1 = 0, variance_visit2 = 0;
  std::optional<double> area_bc;
  devices::BuffonEstimate estimate;
  std::string arena; // the --arena spec, its lengths read as metres ("" without)
  std::optional<double> area_true, relative_error, relative_error_raw;
};
// Refuses (InputError) the same bag twice, a width outside [0.01, 10] m (width_where), a walk of
// fewer than two poses, and a pose outside the Q15.16 range; the bags' own errors are io's.
[[nodiscard]] BuffonFromBags buffon_from_bags(const std::string& bag1, const std::string& bag2,
                                              const std::string& topic, double width_m,
                                              io::bag::Stamp stamp, const std::string& child_frame,
                                              const std::string& arena,
                                              const std::string& width_where);
[[nodiscard]] nlohmann::json buffon_from_bags_json(const BuffonFromBags& r, double width_m);

// `antkit check stc --bag`: a bag's poses as a tour on a grid map. Each pose goes to the map cell
// (one sub-cell, as `check stc` reads a tour) it lies in, through the map's resolution and origin
// (x, y and yaw of the lower-left pixel; y down from the first row, as antkit's cells are); between
// two poses, the cells the straight segment from one to the other passes through, in order (a
// segment through a cell corner steps in x first), each entered at the time interpolated along the
// segment; a pose in the cell of the one before adds nothing. The tour is then checked as any tour
// (testing::check_stc: `request`'s rule and start; the start defaults to the first pose's cell).
// Refuses (InputError at the pose's place in the bag, with its time) a pose off the map.
struct StcBagCheck {
  testing::StcCheckReport report;
  io::bag::PoseTrack track;
  std::vector<std::int64_t> entered_ns; // the time each tour position was entered (the stamp)
  // The first broken rule's time, when it names a position of the tour.
  [[nodiscard]] std::optional<std::int64_t> violation_ns() const;
};
[[nodiscard]] StcBagCheck check_stc_bag(const std::string& map_file, const std::string& bag,
                                        const std::string& topic, io::bag::Stamp stamp,
                                        const std::string& child_frame,
                                        const testing::StcCheckRequest& request);
// The same on a map in memory (the Python package's Map), `map_name` naming it in messages: its
// resolution and origin are the map's own (1 m and 0 for a map made from an array).
[[nodiscard]] StcBagCheck check_stc_bag(maps::GridMap map, const std::string& map_name,
                                        const std::string& bag, const std::string& topic,
                                        io::bag::Stamp stamp, const std::string& child_frame,
                                        const testing::StcCheckRequest& request);
// check_stc_json's keys, and "bag", "topic", "type", "stamp", "poses", "first_violation_time_ns"
// (null when the tour passes or the broken rule is about the whole tour).
[[nodiscard]] nlohmann::json check_stc_bag_json(const StcBagCheck& check, const std::string& map);

// A pose track's cells on a grid map, as check_stc_bag reads them (above): x right, y down from
// the first row, each with the time it was entered. Refuses (InputError at the pose's place in the
// bag, with its time) a pose off the map.
struct BagCell {
  std::int32_t x = 0, y = 0;
  std::int64_t t_ns = 0;
};
[[nodiscard]] std::vector<BagCell>
bag_cells(const maps::GridMap& map, const io::bag::PoseTrack& track, const std::string& map_file);

// `antkit check cover --bag`: the poses of one or more topics of a bag (one robot each) as a
// coverage trace (testing::check_cover, paper 004's movement model and sensor): the cells each
// robot passes through as bag_cells reads them; tick 0 puts every robot on its first cell, facing
// its first pose's yaw to the nearest eighth, and each later tick is one robot entering its next
// cell (in time order, ties in topic order), facing the way it stepped, the others staying. So
// the rules checked are those a recorded run can break: leaving the free cells, two robots on one
// cell, and the coverage recomputed with `sensor` (cells, [0, uniform::kMaxSensorRange]).
struct CoverBagCheck {
  testing::CoverCheckReport report;
  std::vector<io::bag::PoseTrack> tracks;
  std::vector<std::int64_t> tick_ns; // each tick's time (the stamp); tick 0: the earliest start
  [[nodiscard]] std::optional<std::int64_t> violation_ns() const;
};
[[nodiscard]] CoverBagCheck check_cover_bag(const std::string& map_file, const std::string& bag,
                                            const std::vector<std::string>& topics,
                                            io::bag::Stamp stamp, const std::string& child_frame,
                                            std::int64_t sensor);
// The same on a map in memory (the Python package's Map), `map_name` naming it in messages.
[[nodiscard]] CoverBagCheck check_cover_bag(const maps::GridMap& map, const std::string& map_name,
                                            const std::string& bag,
                                            const std::vector<std::string>& topics,
                                            io::bag::Stamp stamp, const std::string& child_frame,
                                            std::int64_t sensor);
// check_cover_json's keys, and "bag", "stamp", "topics" ([{"topic", "type", "poses"}]),
// "first_violation_time_ns" (null when the run passes or the broken rule is about the whole run).
[[nodiscard]] nlohmann::json check_cover_bag_json(const CoverBagCheck& check,
                                                  const std::string& map);

// `antkit bag export`: a bag's pose topics back out to MCAP for Foxglove, with the map and, when
// asked, a check's result (issue 42, "Back out"). Channels (schema encoding jsonschema, message
// encoding json; the schemas are devices::mcap_schema's), every message at its pose's time:
//   /map              foxglove.Grid         the map at the first pose's time: one UINT8 field,
//                                           "occupied" (0 free, 100 otherwise), frame "map", its
//                                           pose the map's origin, cells of its resolution
//   /robotI/pose      foxglove.PoseInFrame  topic I's poses (frame "map": the poses are taken to be
//   /robotI/trail     foxglove.PosesInFrame in the map's frame, as the checks take them); the trail
//                                           every ceil(n / 100)-th pose and the last, each at most
//                                           1000
//   /visits           foxglove.Grid         at the last pose's time: "entries", the times robots
//                                           entered each cell (capped at 255; the checks' cells)
//   /log              foxglove.Log          which topic is which robot (INFO, first time); with a
//                                           check, its result: INFO when it passes (last time), or
//                                           ERROR with the first broken rule at its bag time
// `check` is "" (none), "stc" (one topic; check_stc_bag, exactly once from the first pose's
// cell) or "cover" (check_cover_bag with `sensor`). The file is written whole or not at all, also
// when the check fails (BagMcapSummary::check_ok says so); refusals are the checks' and the
// readers' (InputError), before any file.
struct BagMcapRequest {
  std::string bag, map_file, out;
  std::vector<std::string> topics;
  io::bag::Stamp stamp = io::bag::Stamp::bag;
  std::string child_frame = "base_link";
  std::string check; // "", "stc" or "cover"
  std::int64_t sensor = -1;
};
struct BagMcapSummary {
  std::uint64_t bytes = 0, messages = 0;
  std::vector<std::pair<std::string, std::uint64_t>> channels; // topic, messages
  bool check_ok = true;
  std::string check_text;
};
[[nodiscard]] BagMcapSummary export_bag_mcap(const BagMcapRequest& request);
// {"bag", "map", "out", "bytes", "messages", "channels": {topic: messages}, "topics", "check",
// "check_ok", "check_result"} (the last three null without a check).
[[nodiscard]] nlohmann::json bag_mcap_json(const BagMcapRequest& request,
                                           const BagMcapSummary& summary);

} // namespace antkit::commands
