// `antkit emulate`: a robot's firmware on a pseudo-terminal or over TCP (issues 13, 14 and 26).
//   antkit emulate khepera|khepera-webots|hemisson|epuck [--arena SPEC|F.wkt] [--seed S]
//                  [--fault F ...] [--pace] [--listen HOST:PORT] [--format table|json]
//   antkit emulate stc-floor --map F [--start X,Y] [--heading D] [--seed S] [--noise A]
//                  [--dark-offset A] [--fade S] [--rotation-error PPM] [--drift PPM]
//                  [--format table|json]
// stc-floor: the marker-floor robot of paper 002 (devices/stc_floor/floor.hpp, link.hpp), placed
// at the start sub-cell (default as `antkit stc`), rendering its camera frames; its summary is the
// truth of the last session: the sub-cells the body entered, repeats, the largest distance from a
// sub-cell's centre and heading error, the floor's clock.
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
#include "output.hpp"

#include <antkit/algorithms/options.hpp>
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
  std::string arena = "standard";
  std::uint64_t seed = 1;
  std::vector<std::string> faults;
  bool pace = false;
  std::string listen;
  Format format = Format::Table;
  std::string map, start;
  std::int64_t heading = 1, noise = 0, dark_offset = 12, rotation_error = 0, drift = 0, fade_s = 0;
  CLI::Option *arena_opt = nullptr, *listen_opt = nullptr, *heading_opt = nullptr,
              *noise_opt = nullptr, *dark_opt = nullptr, *fade_opt = nullptr,
              *rotation_opt = nullptr, *drift_opt = nullptr;
};

template <class T>
std::optional<T> given(const CLI::Option* opt, const T& value) {
  return opt->count() > 0 ? std::optional<T>(value) : std::nullopt;
}

void run(const EmulateCommand& c) {
  devices::EmulateOptions o;
  o.seed = c.seed;
  o.arena = given(c.arena_opt, c.arena);
  const auto arena = antkit::commands::is_wkt_path(c.arena)
                         ? antkit::geometry::read_wkt_file(c.arena)
                         : antkit::geometry::build_arena_spec(c.arena, "--arena").arena;
  o.walls = arena.walls_fx();
  o.faults = c.faults;
  o.pace = c.pace;
  o.listen = given(c.listen_opt, c.listen);
  if (!c.map.empty()) o.map = c.map;
  if (!c.start.empty()) o.start = antkit::algorithms::parse_cell("--start", c.start);
  o.heading = given(c.heading_opt, c.heading);
  o.noise = given(c.noise_opt, c.noise);
  o.dark_offset = given(c.dark_opt, c.dark_offset);
  o.fade_s = given(c.fade_opt, c.fade_s);
  o.rotation_error = given(c.rotation_opt, c.rotation_error);
  o.drift = given(c.drift_opt, c.drift);
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
    j["arena"] = c.arena;
    j["faults"] = r.faults;
    j["periods"] = *r.periods;
    j["position"] = {r.position->first, r.position->second};
  }
  if (r.start) { // a robot on a floor map
    j["map"] = c.map;
    j["start"] = {r.start->x, r.start->y};
    j["frames"] = r.frames;
    j["positions"] = r.positions;
    j["covered"] = r.covered;
    j["repeats"] = r.repeats;
    j["reachable_subcells"] = r.reachable_subcells;
    j["max_offset_subcells"] = r.max_offset_subcells;
    j["max_heading_error_degrees"] = r.max_heading_error_degrees;
    j["clock_s"] = r.clock_s;
  }
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
  o->arena_opt = sub->add_option(
      "--arena", o->arena, "A named arena spec or FILE.wkt, in body diameters (default standard)");
  sub->add_option("--seed", o->seed,
                  "Seed of the emulator's keyed streams (start, faults; stc-floor: noise)");
  sub->add_option("--fault", o->faults,
                  "A fault: delay=P:MS, garbage=P, drop=P, cut=P (P per command) or "
                  "disconnect=N (after N commands) or silent=N (no answer after N commands); may "
                  "be repeated");
  sub->add_flag("--pace", o->pace, "Pace replies at the robot's baud rate and command latency");
  o->listen_opt = sub->add_option("--listen", o->listen,
                                  "Serve over TCP on HOST:PORT instead of a pty (PORT 0: any free "
                                  "port; one client at a time); prints tcp:HOST:PORT first");
  sub->add_option("--map", o->map, "stc-floor: the map (MovingAI, ROS, ASCII)");
  sub->add_option("--start", o->start, "stc-floor: the start sub-cell X,Y (default as antkit stc)");
  o->heading_opt =
      sub->add_option("--heading", o->heading, "stc-floor: heading at the start, 0 E 1 N 2 W 3 S");
  o->noise_opt = sub->add_option("--noise", o->noise,
                                 "stc-floor: camera noise, uniform +-A per channel (0-255)");
  o->dark_opt = sub->add_option("--dark-offset", o->dark_offset,
                                "stc-floor: dark-current pattern, 0..A per pixel (default 12)");
  o->fade_opt = sub->add_option(
      "--fade", o->fade_s, "stc-floor: half-life of the marks' glow in seconds (0: no fading)");
  o->rotation_opt = sub->add_option("--rotation-error", o->rotation_error,
                                    "stc-floor: turn rate against nominal, ppm");
  o->drift_opt = sub->add_option(
      "--drift", o->drift, "stc-floor: the turn rate falls by this many ppm a minute (battery)");
  antkit::cli::add_format_option(*sub, o->format);
  sub->footer(devices::options_by_device(devices::OptionUse::Emulate,
                                         antkit::cli::registry().at("emulate").flags));
  sub->callback([o] { run(*o); });
}

// devices::emulate()'s words for its inputs (device.hpp, emulator.hpp), as this command's options.
const antkit::cli::Registration emulate_registration{"emulate",
                                                     &register_emulate,
                                                     {{"arena spec", "--arena"},
                                                      {"fault", "--fault"},
                                                      {"pacing", "--pace"},
                                                      {"listen address", "--listen"},
                                                      {"floor map", "--map"},
                                                      {"start sub-cell", "--start"},
                                                      {"start heading", "--heading"},
                                                      {"camera noise", "--noise"},
                                                      {"dark offset", "--dark-offset"},
                                                      {"fade half-life", "--fade"},
                                                      {"rotation error", "--rotation-error"},
                                                      {"drift", "--drift"}}};

} // namespace
