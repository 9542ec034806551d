// `antkit buffon-from-logs`: paper 000's measurement from two recorded visits (issue 13): what
// section 7 counted by hand on the floor, from the robots' odometry (devices/odometry.hpp).
//   antkit buffon-from-logs VISIT1 VISIT2 [--width W] [--arena SPEC|FILE.wkt] [--format table|json]
//
// Refused with exit 2 and the offending file's FILE:1:COL (issue 26; devices/odometry.hpp): the
// same file twice, two logs of one run (equal run hashes over equal step counts), a log whose
// controller is not buffon, a visit-1 log as VISIT2 or a visit-2 log as VISIT1, logs of two robots,
// headers naming two arenas, and an --arena other than the one the headers name.
//
// JSON (lengths in body diameters, areas in body diameters squared; *_m2 in square metres; an area
// or interval end is null when the counts cannot give it):
//   "robot", "diameter_m"      the robot and its body diameter, the unit of length
//   "visit1", "visit2"         {"steps", "length", "truncated", "hash"}: records, trail length, a
//                              log cut mid-line, the run hash (as record and replay print it)
//   "width"                    the pheromone band of BC, body diameters
//   "bc"                       the simulator's crossing detector along visit 2 over visit 1's band
//   "crossings_exact"          N, the proper crossings of the two dead-reckoned centre lines
//   "area", "area_m2"          the RAW closed form 2 L1 L2 / (pi N): the area the robot's centre
//                              explores, below the arena's (kept under this name; = "area_raw")
//   "area_bc", "area_bc_m2"    the same from BC, raw
//   "area_raw", "area_raw_ci"  the raw closed form again, named as such, and the precision rule's
//                              95 % interval of it ([lower, upper]), as `antkit buffon --precision`
//                              reports "precision_ci"
//   "area_corrected", "area_corrected_m2", "area_corrected_ci", "area_corrected_ci_m2"
//                              THE ESTIMATE: the erosion-corrected area and interval, as `antkit
//                              buffon --precision` reports them ("area_corrected", "_ci")
//   "erosion_factor"           1 + kappa E / (L1 + L2), area_corrected / area_raw
//   "wall_encounters"          E, from both visits' logged front readings
//   "variance_visit1", "variance_visit2"  the interval's variance shares (0 when visit 2 is under
//                              10 000 steps, the rule's first check: the interval is then Poisson)
//   "arena"                    the arena's spec; null when neither the headers nor --arena name it
//   "arena_source"             "logs" (both headers), "visit1" or "visit2" (one header), "--arena"
//                              or null
//   "area_true", "area_true_m2"  the arena's exact area (null without an arena); a relative WKT
//                              path in a header is read from the current directory
//   "relative_error"           (area_corrected - area_true) / area_true (null without an arena)
//   "relative_error_raw"       (area_raw - area_true) / area_true, for comparison
//
// From two ROS 2 bags (issue 42): `--topic T` reads VISIT1 and VISIT2 as bags (.mcap, .db3 or bag
// folders), the topic's poses (nav_msgs/msg/Odometry, geometry_msgs/msg/PoseStamped,
// PoseWithCovarianceStamped, a Twist integrated over bag time, or a tf2_msgs/msg/TFMessage's
// --child-frame, default base_link) as two random walks in the bags' metres; --width is then in
// metres, and --arena's lengths too. `--stamp bag|header` picks the poses' time (bag by default).
// The same keys, with: "robot", "diameter_m", "wall_encounters" null (a bag has no robot
// description and no front readings; the erosion factor is 1, so area_corrected = area_raw);
// "unit": "m" and every *_m2 equal to its unitless twin; "visit1"/"visit2" {"bag", "topic", "type",
// "poses", "steps" (poses - 1), "length" (m), "start_ns", "end_ns" (the chosen stamp), "truncated"
// and "hash" null}; "stamp"; "arena_source" "--arena" or null.
#include "commands.hpp"
#include "output.hpp"

#include <antkit/commands/bags.hpp>
#include <antkit/commands/json.hpp>
#include <antkit/commands/options.hpp>
#include <antkit/devices/odometry.hpp>
#include <iostream>
#include <memory>

namespace {

using antkit::cli::Format;

struct FromLogsCommand {
  std::string visit1, visit2;
  double width = 0.1;
  std::string arena;
  std::string topic, stamp = "bag", child_frame = "base_link";
  Format format = Format::Table;
};

void run(const FromLogsCommand& c) {
  if (!c.topic.empty()) {
    const auto r = antkit::commands::buffon_from_bags(
        c.visit1, c.visit2, c.topic, c.width, antkit::commands::bag_stamp(c.stamp, "--stamp"),
        c.child_frame, c.arena, "--width");
    antkit::cli::emit(antkit::commands::buffon_from_bags_json(r, c.width), c.format, std::cout);
    return;
  }
  const auto r =
      antkit::commands::buffon_from_logs(c.visit1, c.visit2, c.width, c.arena, "--width");
  antkit::cli::emit(antkit::commands::buffon_from_logs_json(r, c.width), c.format, std::cout);
}

void register_from_logs(CLI::App& app) {
  auto c = std::make_shared<FromLogsCommand>();
  auto* sub = app.add_subcommand(
      "buffon-from-logs",
      "Buffon's measurement (paper 000) from two recorded visits' odometry: the erosion-corrected "
      "area with its 95 % interval (as antkit buffon --precision), the raw closed form, BC and the "
      "exact crossing count");
  sub->add_option("visit1", c->visit1,
                  "The log of visit 1 (antkit record --controller buffon "
                  "--visit 1)")
      ->required();
  sub->add_option("visit2", c->visit2, "The log of visit 2 (--visit 2)")->required();
  sub->add_option("--width", c->width, "Pheromone band width in body diameters (default 0.1)");
  sub->add_option("--arena", c->arena,
                  "The arena (named spec or FILE.wkt) when the logs' headers do not name it: its "
                  "true area and the estimate's relative error are reported");
  sub->add_option("--topic", c->topic,
                  "Read VISIT1 and VISIT2 as ROS 2 bags (.mcap, .db3, bag folders): this pose "
                  "topic's walks, lengths and --width in metres");
  sub->add_option("--stamp", c->stamp,
                  "With --topic: the poses' time, bag or header (default bag)");
  sub->add_option("--child-frame", c->child_frame,
                  "With --topic on a tf2_msgs/msg/TFMessage: the child frame (default base_link)");
  antkit::cli::add_format_option(*sub, c->format);
  sub->callback([c] { run(*c); });
}

const antkit::cli::Registration buffon_from_logs_registration{
    "buffon-from-logs",
    &register_from_logs,
    {{"arena spec", "--arena"}, {"stamp", "--stamp"}, {"trail width", "--width"}}};

} // namespace
