// `antkit record`: runs a controller on a robot (or an emulator) and writes its log (issue 13).
//   antkit record --device khepera|hemisson|epuck --port PATH --controller buffon|rs|wander
//                 [--seed S] [--trial T] [--visit V] [--param KEY=VALUE ...] [--steps N]
//                 [--baud B] [--framing 8N1|8N2|...] [--timeout MS] [--tries N] [--period MS]
//                 --out LOG [--format table|json]
// Exit status: 0 when the run completed or was stopped by SIGINT / SIGTERM (the robot stopped
// safely, the log complete), 1 when the link failed (resends exhausted, watchdog, disconnect: the
// robot was stopped as far as the link allowed, the log holds every step and ends with the
// reason), 2 for bad options or a port that cannot be opened (no log is written).
#include "commands.hpp"
#include "output.hpp"

#include <antkit/algorithms/options.hpp>
#include <antkit/devices/adapter.hpp>
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
  std::string device, port, controller, out, baud, framing;
  std::uint64_t seed = 1;
  std::int64_t trial = -1, visit = -1;
  std::vector<std::string> params;
  std::int64_t steps = 1000, timeout_ms = 250, tries = 3, period_ms = 0;
  Format format = Format::Table;
};

void run(const RecordCommand& c) {
  const auto robot = devices::parse_robot(c.device);
  if (!robot)
    throw InputError("--device",
                     "unknown robot '" + c.device + "': expected khepera, hemisson or epuck");
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
  if (!c.baud.empty()) o.line.baud = devices::parse_baud(c.baud, "--baud");
  if (!c.framing.empty()) o.line = devices::parse_framing(c.framing, o.line.baud, "--framing");
  o.controller = devices::make_spec(c.controller, c.seed, given, "--controller");
  o.steps = c.steps;
  o.out = c.out;
  if (c.timeout_ms < 1 || c.timeout_ms > 60000)
    throw InputError("--timeout", "expected milliseconds in [1, 60000]");
  if (c.tries < 1 || c.tries > 100) throw InputError("--tries", "expected 1 to 100 sends");
  if (c.period_ms < 0 || c.period_ms > 60000)
    throw InputError("--period", "expected milliseconds in [0, 60000]");
  o.link.timeout = std::chrono::milliseconds(c.timeout_ms);
  o.link.tries = static_cast<std::uint32_t>(c.tries);
  o.link.watchdog =
      std::max(o.link.watchdog, std::chrono::milliseconds(4 * c.timeout_ms * c.tries));
  o.period = std::chrono::milliseconds(c.period_ms);

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
  j["stopped"] = summary.stop;
  j["safe_stop"] = summary.safe_stop.empty() ? "acknowledged" : summary.safe_stop;
  j["exchanges"] = summary.link.exchanges;
  j["retries"] = summary.link.retries;
  j["faults"] = {{"timeouts", summary.link.timeouts},
                 {"bad_replies", summary.link.bad_replies},
                 {"overflows", summary.link.overflows}};
  j["hash"] = antkit::kernel::hash_hex(summary.hash);
  antkit::cli::emit(j, c.format, std::cout);
  if (!summary.completed && summary.stop.rfind("interrupted", 0) != 0)
    throw antkit::cli::CheckFailed("the run stopped early: " + summary.stop);
}

void register_record(CLI::App& app) {
  auto c = std::make_shared<RecordCommand>();
  auto* sub = app.add_subcommand(
      "record", "Run a controller on a robot or an emulator over a serial port and log every step "
                "(JSON Lines) for replay");
  sub->add_option("--device", c->device, "khepera, hemisson or epuck")->required();
  sub->add_option("--port", c->port, "The serial device or pty, e.g. /dev/ttyUSB0")->required();
  sub->add_option("--controller", c->controller, "buffon, rs or wander")->required();
  sub->add_option("--seed", c->seed, "Seed of the controller's keyed streams (default 1)");
  sub->add_option("--trial", c->trial, "The controller's trial number (default 0)");
  sub->add_option("--visit", c->visit, "buffon: visit 1 (lay the trail) or 2 (count crossings)");
  sub->add_option("--param", c->params, "Another controller parameter, KEY=VALUE");
  sub->add_option("--steps", c->steps, "Control steps to run (default 1000)");
  sub->add_option("--baud", c->baud, "Baud rate (default the robot's)");
  sub->add_option("--framing", c->framing, "Framing such as 8N1 or 8N2 (default the robot's)");
  sub->add_option("--timeout", c->timeout_ms, "Reply timeout in milliseconds (default 250)");
  sub->add_option("--tries", c->tries, "Sends of a command before giving up (default 3)");
  sub->add_option("--period", c->period_ms,
                  "Shortest control period in milliseconds (default 0: as fast as the link)");
  sub->add_option("--out", c->out, "The log to write (JSON Lines)")->required();
  antkit::cli::add_format_option(*sub, c->format);
  sub->callback([c] { run(*c); });
}

const antkit::cli::Registration reg{"record", &register_record};

} // namespace
