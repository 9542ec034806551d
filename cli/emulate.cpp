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

#include <antkit/devices/emulator.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/devices/serial.hpp>
#include <antkit/devices/stc_floor/link.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <iostream>
#include <memory>
#include <optional>

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
  std::string listen;
  Format format = Format::Table;
  // stc-floor
  std::string map, start;
  std::int32_t heading = 1, noise = 0, dark_offset = 12, rotation_error = 0, drift = 0;
  std::int64_t fade_s = 0;
  CLI::Option *arena_opt = nullptr, *fault_opt = nullptr, *pace_opt = nullptr,
              *listen_opt = nullptr, *floor_opts[8]{};
};

void run_stc_floor(const EmulateOptions& o) {
  if (o.arena_opt->count() + o.fault_opt->count() + o.pace_opt->count() + o.listen_opt->count() > 0)
    throw InputError("stc-floor", "--arena, --fault, --pace and --listen are for " +
                                      std::string(devices::robot_names()) +
                                      "; the marker-floor robot takes --map and serves a pty");
  if (o.map.empty()) throw InputError("--map", "stc-floor needs a map (--map FILE)");
  const auto map = antkit::maps::load_map(o.map);
  const auto start =
      antkit::cli::choose_stc_start(map, antkit::stc::Variant::AntEdge, o.start, o.map);
  namespace sf = devices::stc_floor;
  sf::FloorOptions f;
  f.seed = o.seed;
  f.noise = o.noise;
  f.dark_offset = o.dark_offset;
  if (o.fade_s < 0 || o.fade_s > 86400) throw InputError("--fade", "expected 0 to 86400 seconds");
  f.fade_half_life_ms = o.fade_s * 1000;
  f.rotation_error_ppm = o.rotation_error;
  f.drift_ppm_per_minute = o.drift;
  sf::FloorEmulator emulator(map.cells, start, o.heading, f);
  devices::StopSignals::Scope signals;
  devices::Pty pty = devices::Pty::open();
  std::cout << pty.slave_path() << std::endl; // the first line, flushed: clients wait for it
  emulator.serve(pty);
  const auto& w = emulator.world();
  nlohmann::json j;
  j["robot"] = "stc-floor";
  j["map"] = o.map;
  j["start"] = {start.x, start.y};
  j["seed"] = o.seed;
  j["sessions"] = emulator.sessions();
  j["commands"] = emulator.commands();
  j["frames"] = w.frames();
  j["positions"] = w.path().size();
  j["covered"] = w.covered();
  j["repeats"] = w.repeats();
  j["reachable_subcells"] =
      antkit::stc::reachable_subcells(map.cells, start, antkit::stc::Variant::AntEdge);
  j["max_offset_subcells"] = static_cast<double>(w.max_offset()) / 65536.0;
  j["max_heading_error_degrees"] =
      static_cast<double>(w.max_heading_error()) * 360.0 / 4294967296.0;
  j["clock_s"] = static_cast<double>(w.clock_ms()) / 1000.0;
  antkit::cli::emit(j, o.format, std::cout);
}

void run(const EmulateOptions& o) {
  if (o.robot == "stc-floor") return run_stc_floor(o);
  for (const auto* opt : o.floor_opts)
    if (opt != nullptr && opt->count() > 0)
      throw InputError(opt->get_name(), "is an option of the stc-floor robot");
  const auto robot = devices::parse_robot(o.robot);
  if (!robot)
    throw InputError("robot", "unknown robot '" + o.robot + "': expected " +
                                  std::string(devices::robot_names()) + " or stc-floor");
  devices::EmulatorOptions options;
  options.seed = o.seed;
  options.faults = devices::parse_faults(o.faults);
  options.pace = o.pace;
  const auto arena = antkit::cli::is_wkt_path(o.arena)
                         ? antkit::geometry::read_wkt_file(o.arena)
                         : antkit::geometry::build_arena_spec(o.arena, "--arena").arena;
  std::optional<devices::TcpListener> listener;
  if (!o.listen.empty())
    listener.emplace(devices::TcpListener::listen(
        devices::parse_tcp_endpoint(o.listen, "--listen", true), "--listen"));
  devices::FirmwareEmulator emulator(*robot, arena.walls_fx(), options);
  devices::StopSignals::Scope signals;
  if (listener) {
    std::cout << listener->port_spec() << std::endl; // the first line, flushed: clients wait for it
    emulator.serve(*listener);
  } else {
    devices::Pty pty = devices::Pty::open();
    std::cout << pty.slave_path() << std::endl; // the first line, flushed: clients wait for it
    emulator.serve(pty);
  }
  nlohmann::json j;
  j["robot"] = std::string(devices::robot_name(*robot));
  j["arena"] = o.arena;
  j["seed"] = o.seed;
  if (listener) j["listen"] = listener->port_spec();
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
      "emulate", "A robot's firmware on a pseudo-terminal (or over TCP with --listen): khepera, "
                 "khepera-webots (the Khepera in Webots behind its TCP/IP relay), hemisson or "
                 "epuck (its body simulated in a Buffon arena) or stc-floor (paper 002's "
                 "marker-floor robot, its camera frames rendered); prints the pty path (or "
                 "tcp:HOST:PORT) on the first line");
  sub->add_option("robot", o->robot, "khepera, khepera-webots, hemisson, epuck or stc-floor")
      ->required();
  o->arena_opt = sub->add_option(
      "--arena", o->arena, "A named arena spec or FILE.wkt, in body diameters (default standard)");
  sub->add_option("--seed", o->seed,
                  "Seed of the emulator's keyed streams (start, faults; stc-floor: noise)");
  o->fault_opt = sub->add_option("--fault", o->faults,
                                 "A fault: delay=P:MS, garbage=P, drop=P, cut=P (P per command) or "
                                 "disconnect=N (after N commands); may be repeated");
  o->pace_opt =
      sub->add_flag("--pace", o->pace, "Pace replies at the robot's baud rate and command latency");
  o->listen_opt = sub->add_option("--listen", o->listen,
                                  "Serve over TCP on HOST:PORT instead of a pty (PORT 0: any free "
                                  "port; one client at a time); prints tcp:HOST:PORT first");
  o->floor_opts[0] = sub->add_option("--map", o->map, "stc-floor: the map (MovingAI, ROS, ASCII)");
  o->floor_opts[1] = sub->add_option("--start", o->start,
                                     "stc-floor: the start sub-cell X,Y (default as antkit stc)");
  o->floor_opts[2] =
      sub->add_option("--heading", o->heading, "stc-floor: heading at the start, 0 E 1 N 2 W 3 S");
  o->floor_opts[3] = sub->add_option("--noise", o->noise,
                                     "stc-floor: camera noise, uniform +-A per channel (0-255)");
  o->floor_opts[4] =
      sub->add_option("--dark-offset", o->dark_offset,
                      "stc-floor: dark-current pattern, 0..A per pixel (default 12)");
  o->floor_opts[5] = sub->add_option(
      "--fade", o->fade_s, "stc-floor: half-life of the marks' glow in seconds (0: no fading)");
  o->floor_opts[6] = sub->add_option("--rotation-error", o->rotation_error,
                                     "stc-floor: turn rate against nominal, ppm");
  o->floor_opts[7] = sub->add_option(
      "--drift", o->drift, "stc-floor: the turn rate falls by this many ppm a minute (battery)");
  antkit::cli::add_format_option(*sub, o->format);
  sub->callback([o] { run(*o); });
}

const antkit::cli::Registration reg{"emulate", &register_emulate};

} // namespace
