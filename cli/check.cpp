// `antkit check`: an oracle for any planner's output (issue 18). The checks are antkit::testing's
// (testing/include/antkit/testing/); this file parses options, calls one function and prints.
//
//   antkit check stc --map F --path P [--start X,Y] [--coverage] [--format table|json]
//
// Exit status: 0 the output keeps every rule, 1 a rule is broken (the report is printed, then the
// first broken rule on stderr), 2 bad input (a malformed map or tour file, a start off the map).
#include "commands.hpp"
#include "output.hpp"

#include <antkit/algorithms/options.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <iostream>
#include <memory>
#include <string>

namespace {

using antkit::cli::Format;
namespace testing = antkit::testing;

nlohmann::json cell_json(antkit::kernel::Cell c) {
  return nlohmann::json::array({c.x, c.y});
}

struct StcCheckCommand {
  std::string map, path, start;
  bool coverage = false;
  Format format = Format::Table;
};

void run_stc(const StcCheckCommand& c) {
  testing::StcCheckRequest request;
  request.map_file = c.map;
  request.tour_file = c.path;
  if (!c.start.empty()) request.start = antkit::algorithms::parse_cell("--start", c.start);
  request.rule = c.coverage ? testing::TourRule::Coverage : testing::TourRule::ExactlyOnce;
  const testing::StcCheckReport r = testing::check_stc_files(request);
  const testing::StcAudit& a = r.audit;
  nlohmann::json j;
  j["check"] = "stc";
  j["rule"] = std::string(testing::tour_rule_name(a.rule));
  j["ok"] = a.ok();
  j["map"] = c.map;
  j["width"] = r.width;
  j["height"] = r.height;
  j["start"] = cell_json(r.start);
  j["start_from"] = r.start_from;
  j["positions"] = a.positions;
  j["closed_form"] = a.closed_form;
  j["reachable_subcells"] = a.reachable;
  j["covered"] = a.covered;
  j["missed"] = a.missed;
  j["repeats"] = a.repeats;
  j["illegal_moves"] = a.illegal_moves;
  j["off_limits"] = a.off_limits;
  j["end_distance"] = a.end_distance;
  nlohmann::json missed = nlohmann::json::array();
  for (const auto s : a.missed_sample) missed.push_back(cell_json(s));
  j["missed_sample"] = std::move(missed);
  if (a.ok()) {
    j["first_violation"] = nullptr;
  } else {
    j["first_violation"] = {
        {"rule", a.first.rule},
        {"step", a.first.step < 0 ? nlohmann::json(nullptr) : nlohmann::json(a.first.step)},
        {"subcell", cell_json(a.first.subcell)},
        {"detail", a.first.detail}};
  }
  antkit::cli::emit(j, c.format, std::cout);
  if (!a.ok()) throw antkit::cli::CheckFailed(c.path + ": " + a.first.describe());
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
                  "(sub-cells: one map cell each, y down from the first row)")
      ->required();
  stc->add_option("--start", s->start,
                  "The start sub-cell X,Y (default: the tour file's start, else the map's, else "
                  "the tour's first position)");
  stc->add_flag("--coverage", s->coverage,
                "Every reachable free sub-cell at least once, repeats counted (Full-STC, "
                "boustrophedon), instead of exactly once");
  antkit::cli::add_format_option(*stc, s->format);
  stc->callback([s] { run_stc(*s); });
}

const antkit::cli::Registration reg{"check", &register_check};

} // namespace
