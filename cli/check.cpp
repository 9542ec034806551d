// `antkit check`: an oracle for any planner's output (issue 18). The checks are antkit::testing's
// (testing/include/antkit/testing/), their JSON commands/; this file parses options, calls one
// function and prints.
//
//   antkit check stc --map F --path P [--start X,Y] [--coverage] [--order xy|rc] [--cells]
//                    [--mcap F.mcap] [--format table|json]
//                    (--mcap: the tour and the verdict for Foxglove, commands/check_stc_mcap.hpp)
//   antkit check stc --map F --bag BAG --topic T [--stamp bag|header] [--child-frame F]
//                    [--start X,Y] [--coverage]: a ROS 2 bag's poses as the tour
//                    (commands/bags.hpp, check_stc_bag: cells through the map's resolution and
//                    origin, the cells between two poses filled in); the JSON adds "bag", "topic",
//                    "type", "stamp", "poses" and "first_violation_time_ns"
//   antkit check explore --map F --cells C [--format table|json]
//   antkit check cover --map F --log L [--sensor R] [--mcap F.mcap] [--format table|json]
//   antkit check cover --map F --bag BAG --topic T [--topic T2 ...] --sensor R [--stamp ...]
//                      [--child-frame F]: each topic's poses one robot (check_cover_bag); the
//                      JSON adds "bag", "stamp", "topics" and "first_violation_time_ns"
//
// Exit status: 0 the output keeps every rule, 1 a rule is broken (the report is printed, then the
// first broken rule on stderr), 2 bad input (a malformed map or tour file, a start off the map).
#include "commands.hpp"
#include "output.hpp"

#include <antkit/algorithms/options.hpp>
#include <antkit/commands/bags.hpp>
#include <antkit/commands/check_stc_mcap.hpp>
#include <antkit/commands/cover_mcap.hpp>
#include <antkit/commands/json.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/testing/run_audit.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace {

using antkit::cli::Format;
namespace testing = antkit::testing;

struct StcCheckCommand {
  std::string map, path, start, order = "xy";
  std::string bag, topic, stamp = "bag", child_frame = "base_link", mcap;
  bool coverage = false, cells = false;
  Format format = Format::Table;
};

void run_stc(const StcCheckCommand& c) {
  testing::StcCheckRequest request;
  request.map_file = c.map;
  request.tour_file = c.path;
  if (!c.start.empty()) request.start = antkit::algorithms::parse_cell("--start", c.start);
  request.rule = c.coverage ? testing::TourRule::Coverage : testing::TourRule::ExactlyOnce;
  request.order = c.order == "rc" ? testing::TourOrder::RowCol : testing::TourOrder::XY;
  request.cells = c.cells;
  if (c.path.empty() && c.bag.empty())
    throw antkit::kernel::InputError("", "--path is required (or --bag BAG --topic T)");
  if (!c.path.empty() && !c.bag.empty())
    throw antkit::kernel::InputError("--bag", "one tour: --path FILE or --bag BAG, not both");
  if (!c.bag.empty()) {
    if (c.topic.empty()) throw antkit::kernel::InputError("--topic", "--bag needs --topic");
    if (!c.mcap.empty())
      throw antkit::kernel::InputError("--mcap", "with --path; a bag's tour goes out with antkit "
                                                 "bag export --check stc");
    const auto b = antkit::commands::check_stc_bag(c.map, c.bag, c.topic,
                                                   antkit::commands::bag_stamp(c.stamp, "--stamp"),
                                                   c.child_frame, request);
    antkit::cli::emit(antkit::commands::check_stc_bag_json(b, c.map), c.format, std::cout);
    if (!b.report.audit.ok())
      throw antkit::cli::CheckFailed(
          c.bag + ": " + b.report.audit.first.describe() +
          (b.violation_ns() ? " at bag time " + std::to_string(*b.violation_ns()) + " ns" : ""));
    return;
  }
  const testing::StcCheckReport r = c.mcap.empty()
                                        ? testing::check_stc_files(request)
                                        : antkit::commands::check_stc_mcap(request, c.mcap).report;
  const testing::StcAudit& a = r.audit;
  const nlohmann::json j = antkit::commands::check_stc_json(r, c.map);
  antkit::cli::emit(j, c.format, std::cout);
  if (!a.ok()) throw antkit::cli::CheckFailed(c.path + ": " + a.first.describe());
}

struct ExploreCheckCommand {
  std::string map, cells;
  Format format = Format::Table;
};

void run_explore(const ExploreCheckCommand& c) {
  const auto r = testing::check_explore_files(c.map, c.cells);
  const auto& a = r.audit;
  const nlohmann::json j = antkit::commands::check_explore_json(r, c.map);
  antkit::cli::emit(j, c.format, std::cout);
  if (!a.ok()) throw antkit::cli::CheckFailed(c.cells + ": " + a.first);
}

struct CoverCheckCommand {
  std::string map, log, bag, stamp = "bag", child_frame = "base_link", mcap;
  std::vector<std::string> topics;
  std::int64_t sensor = -1;
  Format format = Format::Table;
};

void run_cover(const CoverCheckCommand& c) {
  if (c.log.empty() == c.bag.empty())
    throw antkit::kernel::InputError("--log", "one run: --log TRACE or --bag BAG --topic T");
  if (!c.bag.empty()) {
    if (c.sensor == -1) throw antkit::kernel::InputError("--sensor", "--bag needs --sensor");
    if (!c.mcap.empty())
      throw antkit::kernel::InputError("--mcap", "with --log; a bag's run goes out with antkit "
                                                 "bag export --check cover");
    const auto b = antkit::commands::check_cover_bag(
        c.map, c.bag, c.topics, antkit::commands::bag_stamp(c.stamp, "--stamp"), c.child_frame,
        c.sensor);
    antkit::cli::emit(antkit::commands::check_cover_bag_json(b, c.map), c.format, std::cout);
    if (!b.report.audit.ok())
      throw antkit::cli::CheckFailed(
          c.bag + ": " + b.report.audit.first +
          (b.violation_ns() ? " at bag time " + std::to_string(*b.violation_ns()) + " ns" : ""));
    return;
  }
  std::optional<std::int64_t> sensor; // checked by check_cover_files
  if (c.sensor != -1) sensor = c.sensor;
  const auto r = testing::check_cover_files(c.map, c.log, sensor);
  if (!c.mcap.empty())
    (void)antkit::commands::cover_trace_mcap(antkit::maps::load_map(c.map).cells, c.log, sensor, &r,
                                             "check cover " + c.log + " on " + c.map, c.mcap);
  const auto& a = r.audit;
  const nlohmann::json j = antkit::commands::check_cover_json(r, c.map);
  antkit::cli::emit(j, c.format, std::cout);
  if (!a.ok()) throw antkit::cli::CheckFailed(c.log + ": " + a.first);
}

// --stamp and --child-frame, as check stc and check cover take them with --bag.
void add_bag_time_options(CLI::App& sub, std::string& stamp, std::string& child_frame) {
  sub.add_option("--stamp", stamp, "With --bag: the poses' time, bag or header");
  sub.add_option("--child-frame", child_frame,
                 "With --bag on a TFMessage topic: the child frame (default base_link)");
}

void register_check(CLI::App& app) {
  auto* check = app.add_subcommand(
      "check", "Check a planner's output against the map: the invariants of antkit's own tests, "
               "for anyone's planner");
  check->require_subcommand(1);

  auto s = std::make_shared<StcCheckCommand>();
  auto* stc = check->add_subcommand(
      "stc", "Check a coverage tour: every reachable sub-cell exactly once (or, with --coverage, "
             "at least once), 4-adjacent free moves, ending next to the start");
  stc->add_option("--map", s->map, "The map (MovingAI .map, ROS .yaml, ASCII .txt)")->required();
  stc->add_option("--path", s->path,
                  "The tour: JSON [[x, y], ...] or antkit stc's JSON output, or CSV x,y per line "
                  "(sub-cells: one map cell each, y down from the first row); or --bag");
  stc->add_option("--bag", s->bag,
                  "A ROS 2 bag (.mcap, .db3, folder) whose --topic poses are the tour, through "
                  "the map's resolution and origin");
  stc->add_option("--topic", s->topic, "With --bag: the pose topic");
  add_bag_time_options(*stc, s->stamp, s->child_frame);
  stc->add_option("--start", s->start,
                  "The start sub-cell X,Y (default: the tour file's start, else the map's, else "
                  "the tour's first position)");
  stc->add_option("--order", s->order,
                  "The order of the tour's pairs when the file does not say: xy (column, row; the "
                  "default) or rc (row, col: numpy's). A CSV header x,y, row,col or y,x decides "
                  "for its file; --start is always X,Y; the report's cells are x,y")
      ->check(CLI::IsMember({"xy", "rc"}));
  stc->add_flag("--cells", s->cells,
                "The map, --start and the tour file's start are in robot-sized cells (2 x 2 "
                "sub-cells each); the tour in sub-cells, starting in any sub-cell of the start "
                "cell. Reachable: every sub-cell of the free cells 4-connected to the start cell");
  stc->add_flag("--coverage", s->coverage,
                "Every reachable free sub-cell at least once, repeats counted (Full-STC, "
                "boustrophedon), instead of exactly once");
  stc->add_option("--mcap", s->mcap,
                  "With --path: also write the tour and the verdict as MCAP for Foxglove (the "
                  "first broken rule an ERROR at its position)");
  antkit::cli::add_format_option(*stc, s->format);
  stc->callback([s] { run_stc(*s); });

  auto e = std::make_shared<ExploreCheckCommand>();
  auto* explore = check->add_subcommand(
      "explore", "Check LOS exploration cell states against the true map: S, LOS and S+LOS "
                 "cells free, O cells not free");
  explore->add_option("--map", e->map, "The true map (MovingAI .map, ROS .yaml, ASCII .txt)")
      ->required();
  explore
      ->add_option("--cells", e->cells,
                   "The cell states: antkit explore's JSON output, a JSON array of rows, or "
                   "text rows of F S L B N O")
      ->required();
  antkit::cli::add_format_option(*explore, e->format);
  explore->callback([e] { run_explore(*e); });

  auto v = std::make_shared<CoverCheckCommand>();
  auto* cover = check->add_subcommand(
      "cover", "Check a coverage run's trace: legal moves and turns, no two robots on one cell, "
               "and the coverage it claims recomputed from its poses");
  cover->add_option("--map", v->map, "The map (MovingAI .map, ROS .yaml, ASCII .txt)")->required();
  cover->add_option("--log", v->log,
                    "The trace: tick,robot,x,y,bearing per line (antkit cover --trace); or --bag");
  cover->add_option("--bag", v->bag,
                    "A ROS 2 bag (.mcap, .db3, folder): each --topic's poses are one robot, "
                    "through the map's resolution and origin (commands/bags.hpp)");
  cover->add_option("--topic", v->topics, "With --bag: a robot's pose topic (repeat for more)");
  add_bag_time_options(*cover, v->stamp, v->child_frame);
  cover->add_option("--mcap", v->mcap,
                    "With --log: also write the run and the verdict as MCAP for Foxglove (the "
                    "first broken rule an ERROR at its tick)");
  cover->add_option("--sensor", v->sensor,
                    "Sensor distance in cells (default: the trace's '# sensor:' line; required "
                    "with --bag)");
  antkit::cli::add_format_option(*cover, v->format);
  cover->callback([v] { run_cover(*v); });
}

const antkit::cli::Registration check_registration{
    "check", &register_check, {{"stamp", "--stamp"}}};

} // namespace
