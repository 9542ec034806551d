// `antkit emulate`: a robot's firmware on a pseudo-terminal (issue 13).
//   antkit emulate khepera|hemisson|epuck [--arena SPEC|F.wkt] [--seed S] [--fault F ...] [--pace]
//                  [--format table|json]
// Prints the pty's path on the first line of stdout (flushed), then answers the robot's protocol
// from the simulated body (devices/emulator.hpp), one client session after another (each starts the
// robot at the arena's start pose), until SIGINT / SIGTERM or a disconnect fault, and prints a
// summary: sessions, commands served, faults injected, the last session's control periods and end
// position.
#include "buffon_options.hpp"
#include "commands.hpp"
#include "output.hpp"

#include <antkit/devices/emulator.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/devices/serial.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <iostream>
#include <memory>

namespace {

namespace devices = antkit::devices;
using antkit::cli::Format;
using antkit::kernel::InputError;

struct EmulateOptions {
  std::string robot;
  std::string arena = "standard";
  std::uint64_t seed = 1;
  std::vector<std::string> faults;
  bool pace = false;
  Format format = Format::Table;
};

void run(const EmulateOptions& o) {
  const auto robot = devices::parse_robot(o.robot);
  if (!robot)
    throw InputError("robot",
                     "unknown robot '" + o.robot + "': expected khepera, hemisson or epuck");
  devices::EmulatorOptions options;
  options.seed = o.seed;
  options.faults = devices::parse_faults(o.faults);
  options.pace = o.pace;
  const auto arena = antkit::cli::is_wkt_path(o.arena)
                         ? antkit::geometry::read_wkt_file(o.arena)
                         : antkit::geometry::build_arena_spec(o.arena, "--arena").arena;
  devices::FirmwareEmulator emulator(*robot, arena.walls_fx(), options);
  devices::StopSignals::Scope signals;
  devices::Pty pty = devices::Pty::open();
  std::cout << pty.slave_path() << std::endl; // the first line, flushed: clients wait for it
  emulator.serve(pty);
  nlohmann::json j;
  j["robot"] = std::string(devices::robot_name(*robot));
  j["arena"] = o.arena;
  j["seed"] = o.seed;
  j["sessions"] = emulator.sessions();
  j["commands"] = emulator.commands();
  j["faults"] = emulator.faults();
  j["periods"] = emulator.trail().size() - 1;
  j["position"] = {static_cast<double>(emulator.pose().position.x.raw()) / 65536.0,
                   static_cast<double>(emulator.pose().position.y.raw()) / 65536.0};
  antkit::cli::emit(j, o.format, std::cout);
}

void register_emulate(CLI::App& app) {
  auto o = std::make_shared<EmulateOptions>();
  auto* sub = app.add_subcommand(
      "emulate", "A robot's firmware (khepera, hemisson, epuck) on a pseudo-terminal, its body "
                 "simulated in a Buffon arena; prints the pty path on the first line");
  sub->add_option("robot", o->robot, "khepera, hemisson or epuck")->required();
  sub->add_option("--arena", o->arena,
                  "A named arena spec or FILE.wkt, in body diameters (default standard)");
  sub->add_option("--seed", o->seed, "Seed of the emulator's keyed streams (start, faults)");
  sub->add_option("--fault", o->faults,
                  "A fault: delay=P:MS, garbage=P, drop=P, cut=P (P per command) or "
                  "disconnect=N (after N commands); may be repeated");
  sub->add_flag("--pace", o->pace, "Pace replies at the robot's baud rate and command latency");
  antkit::cli::add_format_option(*sub, o->format);
  sub->callback([o] { run(*o); });
}

const antkit::cli::Registration reg{"emulate", &register_emulate};

} // namespace
