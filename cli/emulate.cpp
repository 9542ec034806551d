// `antkit emulate`: a robot's firmware on a pseudo-terminal or over TCP (issues 13, 14 and 26).
//   antkit emulate khepera|khepera-webots|hemisson|epuck [--arena SPEC|F.wkt] [--seed S]
//                  [--fault F ...] [--pace] [--listen HOST:PORT] [--format table|json]
//   antkit emulate stc-floor --map F [--start X,Y] [--heading D] [--seed S] [--noise A]
//                  [--dark-offset A] [--fade S] [--rotation-error PPM] [--drift PPM]
//                  [--format table|json]
// stc-floor: the marker-floor robot of paper 002 (devices/stc_floor/floor.hpp, link.hpp), placed
// at the start sub-cell (default as `antkit stc`), rendering its camera frames; its summary's
// "floor" block (written by the device, devices/stc_floor/report.hpp) is the truth of the last
// session: map, start, frames, positions, the sub-cells the body entered (covered), repeats,
// reachable_subcells, the largest distance from a sub-cell's centre (max_offset_subcells) and
// heading error (max_heading_error_degrees), the floor's clock (clock_s).
// --listen HOST:PORT serves the firmware over TCP instead of a pty (PORT 0: any free port), one
// client at a time (a second is refused while one is connected), each connection a session; the
// first line is then `tcp:HOST:PORT` with the real port, what `antkit record --port` takes.
// Prints the pty's path on the first line of stdout (flushed), then answers the robot's protocol
// from the simulated body (devices/emulator.hpp), one client session after another (each starts the
// robot at the arena's start pose), until SIGINT / SIGTERM or a disconnect fault, and prints a
// summary: sessions, commands served, faults injected, the last session's control periods and end
// position.
#include "buffon_options.hpp"
#include "commands.hpp"
#include "device_flags.hpp"
#include "output.hpp"

#include <antkit/commands/options.hpp>
#include <antkit/devices/device.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <iostream>
#include <memory>
#include <optional>

namespace {

namespace devices = antkit::devices;
using antkit::cli::Format;
using antkit::kernel::InputError;

struct EmulateCommand {
  std::string robot;
  std::uint64_t seed = 1;
  Format format = Format::Table;
  antkit::cli::DeviceFlags device_flags; // the chosen device's own options (its declarations)
};

void run(const EmulateCommand& c) {
  devices::EmulateOptions o;
  o.seed = c.seed;
  // The device's own options, read and checked against its declarations (device_options.hpp).
  o.device_options =
      devices::parse_device_options(devices::device(c.robot, "robot"), devices::OptionUse::Emulate,
                                    antkit::cli::given_device_options(c.device_flags));
  // The robots of an arena: its walls (the devices do not read arena specs or WKT files).
  const auto arena_text = o.device_options.text("arena");
  if (arena_text) {
    const auto arena = antkit::commands::is_wkt_path(*arena_text)
                           ? antkit::geometry::read_wkt_file(*arena_text)
                           : antkit::geometry::build_arena_spec(*arena_text, "--arena").arena;
    o.walls = arena.walls_fx();
  }
  const auto r = devices::emulate(c.robot, o, [](const std::string& port) {
    std::cout << port << std::endl; // the first line, flushed: clients wait for it
  });
  nlohmann::json j;
  j["robot"] = c.robot;
  j["seed"] = c.seed;
  j["sessions"] = r.sessions;
  j["commands"] = r.commands;
  if (!r.listen.empty()) j["listen"] = r.listen;
  if (r.position) { // a body in an arena
    j["arena"] = arena_text.value_or("");
    j["faults"] = r.faults;
    j["periods"] = *r.periods;
    j["position"] = {r.position->first, r.position->second};
  }
  // The device's own results, one block under its key (devices/device_report.hpp: the
  // marker-floor robot's "floor").
  if (r.device_report)
    j[std::string(r.device_report->key())] =
        nlohmann::json::parse(devices::report_json(r.device_report->fields()));
  antkit::cli::emit(j, c.format, std::cout);
}

void register_emulate(CLI::App& app) {
  auto o = std::make_shared<EmulateCommand>();
  auto* sub = app.add_subcommand(
      "emulate", "A robot's firmware on a pseudo-terminal (or over TCP with --listen): khepera, "
                 "khepera-webots (the Khepera in Webots behind its TCP/IP relay), hemisson or "
                 "epuck (its body simulated in a Buffon arena) or stc-floor (paper 002's "
                 "marker-floor robot, its camera frames rendered); prints the pty path (or "
                 "tcp:HOST:PORT) on the first line");
  sub->add_option("robot", o->robot, "The robot: " + antkit::devices::device_names())->required();
  sub->add_option("--seed", o->seed,
                  "Seed of the emulator's keyed streams (start, faults; stc-floor: noise)");
  antkit::cli::add_format_option(*sub, o->format);
  // The device's own options: flags from every device's declarations, --help from the chosen
  // device's (`antkit emulate epuck2 --help`).
  antkit::cli::add_device_flags(*sub, o->device_flags, devices::OptionUse::Emulate,
                                antkit::cli::registry().at("emulate").flags);
  sub->footer([o] {
    return antkit::cli::device_options_footer(o->robot, devices::OptionUse::Emulate, "emulate");
  });
  sub->callback([o] { run(*o); });
}

// devices::emulate()'s words for its inputs (device.hpp, emulator.hpp), as this command's options.
// devices::emulate()'s words for its inputs are each device option's (add_device_flags).
const antkit::cli::Registration emulate_registration{"emulate", &register_emulate};

} // namespace
