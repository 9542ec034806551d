#pragma once
// What every firmware emulator's Device::serve() does around its emulator (device_serial.cpp,
// device_epuck2.cpp; internal): the options they declare alike, take the seed and the faults, open
// the TCP listener when --listen asks for one, serve until SIGINT / SIGTERM, and report what was
// served.
#include <antkit/devices/device.hpp>
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/serial.hpp>
#include <functional>
#include <optional>
#include <string>

namespace antkit::devices::detail {

// The options of the robots of an arena (the serial robots, the epuck2) that they declare alike
// (Device::options()): record's arena and period, emulate's arena and listen address.
// `period_default` says what the robot does without --period.
inline constexpr DeclaredOption kRecordArena{
    .name = "arena",
    .word = "arena spec",
    .use = OptionUse::Record,
    .type = OptionType::Text,
    .label = "SPEC",
    .what = "the arena it runs in (an emulator's spec), written into the log's header for "
            "buffon-from-logs"};
constexpr DeclaredOption record_period(std::string_view period_default) {
  return {.name = "period",
          .word = "control period",
          .use = OptionUse::Record,
          .type = OptionType::Integer,
          .min = 0,
          .max = 60000,
          .default_note = period_default,
          .label = "MS",
          .what = "the shortest time between two sensor reads, in milliseconds (0: as fast as "
                  "the link allows)"};
}
inline constexpr DeclaredOption kEmulateArena{
    .name = "arena",
    .word = "arena spec",
    .use = OptionUse::Emulate,
    .type = OptionType::Text,
    .fallback = "standard",
    .label = "SPEC|F.wkt",
    .what = "the arena the body is simulated in: a named spec or a WKT file, in body diameters"};
// Both emulators pace alike: the command latency, then the answer's bytes at the robot's baud rate.
inline constexpr DeclaredOption kEmulatePace{
    .name = "pace",
    .word = "pacing",
    .use = OptionUse::Emulate,
    .type = OptionType::Switch,
    .what = "pace the emulator's answers: the command latency, then the bytes at the robot's "
            "baud rate"};
inline constexpr DeclaredOption kEmulateListen{
    .name = "listen",
    .word = "listen address",
    .use = OptionUse::Emulate,
    .type = OptionType::Text,
    .label = "HOST:PORT",
    .what = "serve over TCP on HOST:PORT instead of a pty (PORT 0: any free port; one client "
            "at a time); prints tcp:HOST:PORT first"};
// The seed, the parsed --fault specs (parse_faults' InputError on a bad one) and --pace.
EmulatorOptions emulator_options(const EmulateOptions& o);
// The listener --listen asks for, bound now (its InputError before any emulator is made).
std::optional<TcpListener> listen_for(const EmulateOptions& o);

// Serves `emulator` on the listener, or on a new pty when there is none; `ready` hears the port
// once clients may connect. `body` is the emulated body whose trail and pose the report gives.
template <class Emulator>
EmulateReport serve_emulator(Emulator& emulator, std::optional<TcpListener>& listener,
                             const std::function<void(const std::string&)>& ready,
                             const FirmwareEmulator& body) {
  EmulateReport r;
  if (listener) {
    r.listen = listener->port_spec();
    ready(r.listen);
    emulator.serve(*listener);
  } else {
    Pty pty = Pty::open();
    ready(pty.slave_path());
    emulator.serve(pty);
  }
  r.sessions = emulator.sessions();
  r.commands = emulator.commands();
  r.faults = emulator.faults();
  r.periods = body.trail().size() - 1;
  r.position = {static_cast<double>(body.pose().position.x.raw()) / 65536.0,
                static_cast<double>(body.pose().position.y.raw()) / 65536.0};
  return r;
}

} // namespace antkit::devices::detail
