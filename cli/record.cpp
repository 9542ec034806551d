// `antkit record`: runs a controller on a robot (or an emulator) and writes its log (issue 13).
//   antkit record --device khepera|khepera-webots|hemisson|epuck --port PATH|tcp:HOST:PORT
//                 --controller buffon|rs|wander
//                 [--seed S] [--trial T] [--visit V] [--param KEY=VALUE ...] [--steps N]
//                 [--baud B] [--framing 8N1|8N2|...] [--timeout MS] [--tries N] [--period MS]
//                 [--arena SPEC] --out LOG [--force] [--format table|json]
//   antkit record --device stc-floor --port PATH --controller ant|ant-edge [--map F] [--start X,Y]
//                 [--heading D] [--calibration F.json] [--turn-ms T] [--led-ms L] [--steps N]
//                 [--baud B] [--framing F] [--timeout MS] [--tries N] --out LOG [--force]
//                 [--format]
//   (paper 002's marker-floor robot, devices/stc_floor/record.hpp: the pilot drives the ant-like
//   controller through the camera pipeline until the tour closes or N steps ran; its summary has
//   the keys of `antkit stc`: path in map sub-cells from the start, reachable_subcells and hash
//   when --map is given (the hash then equals antkit stc's for the same tour), covered, repeats,
//   returned_to_start; and run_hash, which antkit replay prints for the log.)
// Exit status: 0 only when the run did what it set out to do and the robot is known to be stopped:
// every requested step ran (or SIGINT / SIGTERM stopped it between steps), the safe stop was
// acknowledged and, where the robot can say, its wheels read back at zero; for stc-floor, the tour
// passed the oracle of `antkit check stc` (every reachable sub-cell entered exactly once, back next
// to the start) when --map is given, else it closed with no repeat. 1 when the run fell short
// (the link failed, the tour broke a rule; the summary says which) or the robot may still be
// moving ("robot_stopped": false). 2 for bad options, a port that cannot be opened or is held by
// another process ("port busy"), or an --out that exists without --force (no log is written).
#include "commands.hpp"
#include "output.hpp"
#include "stc_violation.hpp"

#include <antkit/algorithms/options.hpp>
#include <antkit/devices/adapter.hpp>
#include <antkit/devices/stc_floor/record.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace {

namespace devices = antkit::devices;
using antkit::cli::Format;
using antkit::kernel::InputError;

struct RecordCommand {
  std::string device, port, controller, out, baud, framing, arena;
  bool force = false;
  std::uint64_t seed = 1;
  std::int64_t trial = -1, visit = -1;
  std::vector<std::string> params;
  std::int64_t steps = 1000, timeout_ms = 250, tries = 12, period_ms = -1;
  Format format = Format::Table;
  // stc-floor
  std::string map, start, calibration;
  std::int32_t heading = 1, turn_ms = 1500, led_ms = 2000;
  CLI::Option* steps_opt = nullptr;
};

// The line and the link from --baud, --framing, --timeout and --tries, over `line`'s defaults.
void line_and_link(const RecordCommand& c, devices::LineSettings& line,
                   devices::LinkOptions& link) {
  if (!c.baud.empty()) line.baud = devices::parse_baud(c.baud, "--baud");
  if (!c.framing.empty()) line = devices::parse_framing(c.framing, line.baud, "--framing");
  if (c.timeout_ms < 1 || c.timeout_ms > 60000)
    throw InputError("--timeout", "expected milliseconds in [1, 60000]");
  if (c.tries < 1 || c.tries > 100) throw InputError("--tries", "expected 1 to 100 sends");
  link.timeout = std::chrono::milliseconds(c.timeout_ms);
  link.tries = static_cast<std::uint32_t>(c.tries);
}

// How a recording ended and what its link went through, as both robots' summaries say it.
void put_link(nlohmann::json& j, const std::string& stop, bool robot_stopped,
              const std::string& safe_stop, const devices::LinkStats& link) {
  j["stopped"] = stop;
  j["robot_stopped"] = robot_stopped;
  j["safe_stop"] = safe_stop.empty() ? "acknowledged" : safe_stop;
  j["exchanges"] = link.exchanges;
  j["retries"] = link.retries;
  j["faults"] = {{"timeouts", link.timeouts},
                 {"bad_replies", link.bad_replies},
                 {"overflows", link.overflows},
                 {"stale", link.stale}};
}

void run_stc_floor(const RecordCommand& c) {
  namespace sf = devices::stc_floor;
  namespace stc = antkit::stc;
  sf::RecordOptions o;
  o.port = c.port;
  const auto variant = stc::parse_variant(c.controller);
  if (!variant || (*variant != stc::Variant::Ant && *variant != stc::Variant::AntEdge))
    throw InputError("--controller",
                     "the stc-floor robot runs ant or ant-edge, not '" + c.controller + "'");
  o.pilot.controller = *variant;
  if (!c.arena.empty()) throw InputError("--arena", "is for khepera, hemisson and epuck");
  std::optional<antkit::maps::GridMap> map;
  if (!c.map.empty()) map = antkit::maps::load_map(c.map);
  if (map) {
    o.pilot.start = antkit::cli::choose_stc_start(*map, *variant, c.start, c.map);
  } else if (!c.start.empty()) {
    o.pilot.start = antkit::algorithms::parse_cell("--start", c.start);
  } else {
    throw InputError("--start", "without --map the robot's start sub-cell must be given (X,Y)");
  }
  if (c.heading < 0 || c.heading > 3)
    throw InputError("--heading", "expected 0 (E), 1 (N), 2 (W) or 3 (S)");
  o.pilot.heading = c.heading;
  if (c.turn_ms < 1 || c.turn_ms > sf::kMaxTurnMs)
    throw InputError("--turn-ms", "expected 1 to 60000 ms");
  if (c.led_ms < 0 || c.led_ms > sf::kMaxLedMs) throw InputError("--led-ms", "expected 0 to 60000");
  o.pilot.quarter_turn_ms = c.turn_ms;
  o.pilot.led_ms = c.led_ms;
  if (c.steps < 1 || c.steps > 1000000000) throw InputError("--steps", "expected 1 to 10^9");
  o.pilot.max_steps = c.steps_opt->count() > 0 ? c.steps : 1000000;
  if (!c.calibration.empty()) o.calibration = devices::stc_floor::read_calibration(c.calibration);
  line_and_link(c, o.line, o.link);
  o.out = c.out;
  o.force = c.force;
  const bool live = ::isatty(STDERR_FILENO) == 1;
  const auto s = sf::record(o, [live](std::int64_t step) {
    if (live && step % 50 == 0) std::cerr << "\rrecord: step " << step << std::flush;
  });
  if (live) std::cerr << '\n';
  nlohmann::json j;
  j["robot"] = "stc-floor";
  j["controller"] = c.controller;
  j["log"] = c.out;
  j["steps"] = s.steps;
  j["start"] = {o.pilot.start.x, o.pilot.start.y};
  nlohmann::json path = nlohmann::json::array();
  for (const auto& p : s.path) path.push_back({p.x, p.y});
  j["path"] = std::move(path);
  if (map) j["reachable_subcells"] = stc::reachable_subcells(map->cells, o.pilot.start, *variant);
  j["covered"] = s.covered;
  j["repeats"] = s.repeats;
  const auto last = s.path.back(), first = s.path.front();
  j["returned_to_start"] = s.closed && std::abs(last.x - first.x) + std::abs(last.y - first.y) <= 1;
  j["hash"] = map ? nlohmann::json(antkit::kernel::hash_hex(
                        stc::tour_hash(map->cells.width(), map->cells.height(), s.path)))
                  : nlohmann::json(nullptr);
  j["run_hash"] = antkit::kernel::hash_hex(s.hash);
  j["turn_ms"] = s.turn_ms;
  // A run is what it says: the believed tour held against the map by `antkit check stc`'s oracle
  // (without a map: closed, next to the start, no sub-cell entered twice).
  std::string broken;
  if (map) {
    const auto a = antkit::testing::audit_stc_tour(map->cells, o.pilot.start, s.path,
                                                   antkit::testing::TourRule::ExactlyOnce);
    j["tour_ok"] = a.ok();
    j["first_violation"] = antkit::cli::first_violation_json(a);
    if (!a.ok()) broken = a.first.describe();
  } else {
    const bool ok = j["returned_to_start"].get<bool>() && s.repeats == 0;
    j["tour_ok"] = ok;
    j["first_violation"] = nullptr;
    if (!ok)
      broken = !j["returned_to_start"].get<bool>()
                   ? "the tour did not close next to the start"
                   : std::to_string(s.repeats) + " sub-cells entered more than once";
  }
  // The marker-floor robot moves in discrete F and R commands, each run to its end by the robot:
  // between commands it stands still, so its safe stop (LEDs off) does not decide robot_stopped.
  put_link(j, s.stop, true, s.safe_stop, s.link);
  antkit::cli::emit(j, c.format, std::cout);
  if (s.kind == devices::StopKind::Interrupted) return;
  if (s.kind != devices::StopKind::Done)
    throw antkit::cli::CheckFailed("the run stopped before the tour closed: " + s.stop);
  if (!broken.empty()) throw antkit::cli::CheckFailed("the tour is not a coverage tour: " + broken);
}

void run(const RecordCommand& c) {
  if (c.device == "stc-floor") return run_stc_floor(c);
  if (!c.map.empty() || !c.start.empty() || !c.calibration.empty())
    throw InputError("--device", "--map, --start and --calibration are for --device stc-floor");
  const auto robot = devices::parse_robot(c.device);
  if (!robot)
    throw InputError("--device", "unknown robot '" + c.device + "': expected " +
                                     std::string(devices::robot_names()) + " or stc-floor");
  devices::Params given;
  if (c.trial >= 0) given.emplace_back("trial", c.trial);
  if (c.visit >= 0) given.emplace_back("visit", c.visit);
  for (const auto& p : c.params) {
    const auto eq = p.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--param", "'" + p + "': expected KEY=VALUE, e.g. visit=2");
    given.emplace_back(p.substr(0, eq), antkit::algorithms::parse_integer(
                                            "--param", p.substr(eq + 1), "a whole number"));
  }
  devices::RecordOptions o;
  o.robot = *robot;
  o.port = c.port;
  o.line = devices::describe(*robot).line;
  line_and_link(c, o.line, o.link);
  o.controller = devices::make_spec(c.controller, c.seed, given, "--controller");
  o.steps = c.steps;
  o.out = c.out;
  o.force = c.force;
  o.arena = c.arena;
  if (c.period_ms < -1 || c.period_ms > 60000)
    throw InputError("--period", "expected milliseconds in [0, 60000]");
  if (c.period_ms >= 0) o.period = std::chrono::milliseconds(c.period_ms);

  const bool live = ::isatty(STDERR_FILENO) == 1;
  const auto summary = devices::record(o, [live](std::int64_t step, std::int64_t steps) {
    if (live && (step % 50 == 0 || step == steps))
      std::cerr << "\rrecord: step " << step << " / " << steps << std::flush;
  });
  if (live) std::cerr << '\n';
  nlohmann::json j;
  j["robot"] = c.device;
  j["controller"] = c.controller;
  j["log"] = c.out;
  j["steps"] = summary.steps;
  j["completed"] = summary.completed;
  put_link(j, summary.stop, summary.safe_stop.stopped, summary.safe_stop.failure, summary.link);
  j["hash"] = antkit::kernel::hash_hex(summary.hash);
  antkit::cli::emit(j, c.format, std::cout);
  if (!summary.safe_stop.stopped)
    throw antkit::cli::CheckFailed("the robot may still be moving: " + summary.safe_stop.failure);
  if (!summary.succeeded())
    throw antkit::cli::CheckFailed("the run stopped early: " + summary.stop);
}

void register_record(CLI::App& app) {
  auto c = std::make_shared<RecordCommand>();
  auto* sub = app.add_subcommand(
      "record", "Run a controller on a robot or an emulator over a serial port and log every step "
                "(JSON Lines) for replay");
  sub->add_option("--device", c->device,
                  "khepera, khepera-webots (Webots' TCP/IP relay), hemisson, epuck or stc-floor")
      ->required();
  sub->add_option("--port", c->port,
                  "The serial device or pty (e.g. /dev/ttyUSB0), or tcp:HOST:PORT (Webots' relay "
                  "listens on 10020; antkit emulate --listen)")
      ->required();
  sub->add_option("--controller", c->controller, "buffon, rs or wander; stc-floor: ant or ant-edge")
      ->required();
  sub->add_option("--map", c->map,
                  "stc-floor: the map, for the start, reachable_subcells and the tour hash");
  sub->add_option("--start", c->start, "stc-floor: the start sub-cell X,Y (default as antkit stc)");
  sub->add_option("--heading", c->heading, "stc-floor: heading at the start, 0 E 1 N 2 W 3 S");
  sub->add_option("--calibration", c->calibration,
                  "stc-floor: the camera's calibration file (antkit stc-floor-calibrate)");
  sub->add_option("--turn-ms", c->turn_ms, "stc-floor: the first time T of a quarter turn");
  sub->add_option("--led-ms", c->led_ms, "stc-floor: LED time before each forward move");
  sub->add_option("--seed", c->seed, "Seed of the controller's keyed streams (default 1)");
  sub->add_option("--trial", c->trial, "The controller's trial number (default 0)");
  sub->add_option("--visit", c->visit, "buffon: visit 1 (lay the trail) or 2 (count crossings)");
  sub->add_option("--param", c->params, "Another controller parameter, KEY=VALUE");
  c->steps_opt = sub->add_option(
      "--steps", c->steps, "Control steps to run (default 1000; stc-floor: until the tour closes)");
  sub->add_option("--baud", c->baud, "Baud rate (default the robot's)");
  sub->add_option("--framing", c->framing, "Framing such as 8N1 or 8N2 (default the robot's)");
  sub->add_option("--timeout", c->timeout_ms, "Reply timeout in milliseconds (default 250)");
  sub->add_option("--tries", c->tries,
                  "Sends of a command before giving up (default 12, see devices/link.hpp)");
  sub->add_option("--period", c->period_ms,
                  "Shortest time between sensor reads in milliseconds (default: 0, as fast as the "
                  "link, for robots with wheel counters; the motion model's period, 112 ms, for "
                  "the Hemisson, whose odometry counts periods)");
  sub->add_option("--out", c->out, "The log to write (JSON Lines); an existing file is refused")
      ->required();
  sub->add_flag("--force", c->force, "Replace --out if it exists");
  sub->add_option("--arena", c->arena,
                  "The arena the robot runs in (an emulator's spec), written into the log's header "
                  "for buffon-from-logs");
  antkit::cli::add_format_option(*sub, c->format);
  sub->callback([c] { run(*c); });
}

const antkit::cli::Registration reg{"record", &register_record};

} // namespace
