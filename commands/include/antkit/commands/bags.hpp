#pragma once
// ROS 2 bags in the commands (issue 42, In): `antkit bag info` and `antkit buffon-from-logs
// --topic` over two bags. The readers are io's (antkit/io/bag.hpp); here are the choices the
// commands make from their options and the JSON of their results.
#include <antkit/devices/odometry.hpp>
#include <antkit/io/bag.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

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

} // namespace antkit::commands
