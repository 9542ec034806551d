// `antkit record`: runs a controller on a robot (or an emulator) and writes its log (issue 13).
//   antkit record --device khepera|khepera-webots|hemisson|epuck --port PATH|tcp:HOST:PORT
//                 --controller buffon|rs|wander
//                 [--seed S] [--trial T] [--visit V] [--param KEY=VALUE ...] [--steps N]
//                 [--baud B] [--framing 8N1|8N2|...] [--timeout MS] [--tries N] [--period MS]
//                 [--stop-within MS] [--arena SPEC] --out LOG [--force] [--mcap FILE.mcap]
//                 [--format table|json]
//   antkit record --device stc-floor --port PATH --controller ant|ant-edge [--map F] [--start X,Y]
//                 [--heading D] [--calibration F.json] [--turn-ms T] [--led-ms L] [--steps N]
//                 [--baud B] [--framing F] [--timeout MS] [--tries N] --out LOG [--force]
//                 [--format]
//   (paper 002's marker-floor robot, devices/stc_floor/record.hpp: the pilot drives the ant-like
//   controller through the camera pipeline until the tour closes or N steps ran.)
// JSON: robot, controller, log, steps, completed, hash (the run's RunHash, which antkit replay
// prints for the log; null when the port never opened) and run_hash (the same), stopped,
// robot_stopped, safe_stop, log_error (when the log is not whole), exchanges, retries, faults; the
// device's own results as one block under its key (devices/device_report.hpp), written by the
// device: stc-floor's "tour" has the keys of `antkit stc` (start, path in map sub-cells from the
// start, reachable_subcells and hash when --map is given, the hash then equal to antkit stc's for
// the same tour, covered, repeats, returned_to_start), turn_ms, and its verdict's tour_ok and
// first_violation (experiments/recorded_run.hpp).
// Exit status: 0 only when the run did what it set out to do and the robot is known to be stopped:
// every requested step ran (or SIGINT / SIGTERM stopped it between steps), the safe stop was
// acknowledged and, where the robot can say, its wheels read back at zero; for stc-floor, the tour
// passed the oracle of `antkit check stc` (every reachable sub-cell entered exactly once, back next
// to the start) when --map is given (without it, never: nothing says how much floor there was). 1
// when the run fell short (the link failed, the tour broke a rule; the summary says which) or the
// robot may still be moving ("robot_stopped": false). 2 for bad options, a port that cannot be
// opened or is held
// ("port busy"), an --out that exists without --force, or a robot that is not --device's (no log
// written).
// --mcap: the log, once written, also as MCAP (antkit export mcap; devices/mcap_export.hpp).
#include "commands.hpp"
#include "device_flags.hpp"
#include "output.hpp"

#include <antkit/algorithms/options.hpp>
#include <antkit/commands/options.hpp>
#include <antkit/devices/device.hpp>
#include <antkit/devices/mcap_export.hpp>
#include <antkit/experiments/recorded_run.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace {

namespace devices = antkit::devices;
using antkit::cli::Format;
using antkit::kernel::InputError;

struct RecordCommand {
  std::string device, port, controller, out, baud, framing, mcap;
  bool force = false;
  std::uint64_t seed = 1;
  std::int64_t trial = -1, visit = -1;
  std::vector<std::string> params;
  std::int64_t steps = 1000, timeout_ms = -1, tries = 12, stop_within_ms = 10000;
  Format format = Format::Table;
  CLI::Option* steps_opt = nullptr;
  antkit::cli::DeviceFlags device_flags; // the chosen device's own options (its declarations)
};

// The line (the device's, with --baud and --framing over it) and the link from --timeout and
// --tries.
void line_and_link(const RecordCommand& c, devices::RecordOptions& o) {
  if (!c.baud.empty() || !c.framing.empty()) {
    devices::LineSettings line = devices::device(c.device, "--device").line();
    if (!c.baud.empty()) line.baud = devices::parse_baud(c.baud, "--baud");
    if (!c.framing.empty()) line = devices::parse_framing(c.framing, line.baud, "--framing");
    o.line = line;
  }
  if (c.timeout_ms != -1 && (c.timeout_ms < 1 || c.timeout_ms > 60000))
    throw InputError("--timeout", "expected milliseconds in [1, 60000]");
  if (c.tries < 1 || c.tries > 100) throw InputError("--tries", "expected 1 to 100 sends");
  o.link.timeout = c.timeout_ms == -1 ? devices::device(c.device, "--device").reply_timeout()
                                      : std::chrono::milliseconds(c.timeout_ms);
  o.link.tries = static_cast<std::uint32_t>(c.tries);
  if (c.stop_within_ms < 1 || c.stop_within_ms > 600000)
    throw InputError("--stop-within", "expected milliseconds in [1, 600000]");
  o.link.stop_within = std::chrono::milliseconds(c.stop_within_ms);
  // A safe stop that takes long says what it is doing (on every stderr: the user may be waiting).
  o.link.on_stop_notice = [](const std::string& what) { std::cerr << "antkit: " << what << '\n'; };
}

void run(const RecordCommand& c) {
  devices::RecordOptions o;
  o.device = c.device;
  o.port = c.port;
  // The device's own options, read and checked against its declarations (device_options.hpp).
  o.device_options =
      devices::parse_device_options(devices::device(c.device, "device"), devices::OptionUse::Record,
                                    antkit::cli::given_device_options(c.device_flags));
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
  o.controller = {c.controller, given, c.seed};
  if (c.steps_opt->count() > 0) o.steps = c.steps;
  o.out = c.out;
  o.force = c.force;
  line_and_link(c, o);
  // The arena goes into the log's header for buffon-from-logs: a spec that names no arena would
  // make both visits unusable later, so it is refused now (as emulate refuses it).
  if (const auto arena = o.device_options.text("arena"))
    (void)antkit::commands::arena_spec_area(*arena, "--arena");

  const bool live = ::isatty(STDERR_FILENO) == 1;
  const auto r = antkit::experiments::record_run(o, [live](std::int64_t step, std::int64_t steps) {
    if (live && (step % 50 == 0 || step == steps))
      std::cerr << "\rrecord: step " << step << " / " << steps << std::flush;
  });
  if (live) std::cerr << '\n';
  if (!c.mcap.empty()) devices::export_mcap(c.out, c.mcap, antkit::commands::mcap_options());
  const auto& s = r.summary;
  nlohmann::json j;
  j["robot"] = c.device;
  j["controller"] = c.controller;
  j["log"] = c.out;
  j["steps"] = s.steps;
  j["completed"] = s.completed;
  j["hash"] = antkit::kernel::hash_hex(s.hash);
  j["run_hash"] = j["hash"];
  // The device's own results, one block under its key (devices/device_report.hpp: the marker-floor
  // robot's "tour"), with what its verdict adds (experiments/recorded_run.hpp).
  if (const auto& report = s.device_report) {
    auto fields = report->fields();
    fields.insert(fields.end(), r.verdict.fields.begin(), r.verdict.fields.end());
    j[std::string(report->key())] = nlohmann::json::parse(devices::report_json(fields));
  }
  j["stopped"] = s.stop;
  j["robot_stopped"] = s.safe_stop.stopped;
  j["safe_stop"] = !s.connected                  ? "not needed: never connected"
                   : s.safe_stop.failure.empty() ? "acknowledged"
                                                 : s.safe_stop.failure;
  if (!s.connected) j["hash"] = j["run_hash"] = nullptr; // no run to hash
  if (!s.log_error.empty()) j["log_error"] = s.log_error;
  j["exchanges"] = s.link.exchanges;
  j["retries"] = s.link.retries;
  j["faults"] = {{"timeouts", s.link.timeouts},
                 {"bad_replies", s.link.bad_replies},
                 {"overflows", s.link.overflows},
                 {"stale", s.link.stale}};
  antkit::cli::emit(j, c.format, std::cout);
  if (r.succeeded()) return;
  if (!s.safe_stop.stopped)
    throw antkit::cli::CheckFailed("the robot may still be moving: " + s.safe_stop.failure);
  if (!s.log_error.empty())
    throw antkit::cli::CheckFailed("the log is not whole (the robot is stopped): " + s.log_error);
  if (s.kind == devices::StopKind::Interrupted)
    throw antkit::cli::Interrupted(s.signal, s.stop + " (the robot is stopped)");
  if (s.kind != devices::StopKind::Done)
    throw antkit::cli::CheckFailed("the run stopped early: " + s.stop);
  throw antkit::cli::CheckFailed(r.verdict.failure);
}

void register_record(CLI::App& app) {
  auto c = std::make_shared<RecordCommand>();
  auto* sub = app.add_subcommand(
      "record", "Run a controller on a robot or an emulator over a serial port and log every step "
                "(JSON Lines) for replay");
  sub->add_option("--device", c->device, "The robot: " + devices::device_names())->required();
  sub->add_option("--port", c->port,
                  "The serial device or pty (e.g. /dev/ttyUSB0), or tcp:HOST:PORT (Webots' relay "
                  "listens on 10020; antkit emulate --listen)")
      ->required();
  sub->add_option("--controller", c->controller, "buffon, rs or wander; stc-floor: ant or ant-edge")
      ->required();
  sub->add_option("--seed", c->seed, "Seed of the controller's keyed streams (default 1)");
  sub->add_option("--trial", c->trial, "The controller's trial number (default 0)");
  sub->add_option("--visit", c->visit, "buffon: visit 1 (lay the trail) or 2 (count crossings)");
  sub->add_option("--param", c->params, "Another controller parameter, KEY=VALUE");
  c->steps_opt = sub->add_option(
      "--steps", c->steps, "Control steps to run (default 1000; stc-floor: until the tour closes)");
  sub->add_option("--baud", c->baud, "Baud rate (default the robot's)");
  sub->add_option("--framing", c->framing, "Framing such as 8N1 or 8N2 (default the robot's)");
  sub->add_option("--timeout", c->timeout_ms,
                  "Reply timeout in milliseconds (default the robot's: 250; khepera-webots 1000)");
  sub->add_option("--stop-within", c->stop_within_ms,
                  "The safe stop gives up after this many milliseconds (default 10000; Ctrl-C "
                  "again gives up at once)");
  sub->add_option("--tries", c->tries,
                  "Sends of a command before giving up (default 12, see devices/link.hpp)");
  sub->add_option("--out", c->out, "The log to write (JSON Lines); an existing file is refused")
      ->required();
  sub->add_flag("--force", c->force, "Replace --out if it exists");
  sub->add_option("--mcap", c->mcap, "Also write the log as MCAP (for Foxglove) when the run ends");
  antkit::cli::add_format_option(*sub, c->format);
  // The device's own options: flags from every device's declarations, --help from the chosen
  // device's (`antkit record --device epuck2 --help`).
  antkit::cli::add_device_flags(*sub, c->device_flags, devices::OptionUse::Record,
                                antkit::cli::registry().at("record").flags);
  sub->footer([c] {
    return antkit::cli::device_options_footer(c->device, devices::OptionUse::Record, "record");
  });
  sub->callback([c] { run(*c); });
}

// devices::record()'s words for its inputs (record_loop.hpp, serial.hpp) as this command's options.
const antkit::cli::Registration record_registration{
    "record",
    &register_record,
    {{"device", "--device"},
     {"port", "--port"},
     {"baud rate", "--baud"},
     {"controller", "--controller"},
     {"controller parameter", "--param"},
     {"controller parameter heading", "--param heading"},
     {"controller parameter quarter_turn_ms", "--param quarter_turn_ms"},
     {"controller parameter led_ms", "--param led_ms"},
     {"steps", "--steps"}}}; // and each device option's word (add_device_flags)

} // namespace
