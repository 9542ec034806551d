#pragma once
// What every firmware emulator's Device::serve() does around its emulator (device_serial.cpp,
// device_epuck2.cpp; internal): take the seed and the faults, open the TCP listener when --listen
// asks for one, serve until SIGINT / SIGTERM, and report what was served.
#include <antkit/devices/device.hpp>
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/serial.hpp>
#include <functional>
#include <optional>
#include <string>

namespace antkit::devices::detail {

// What the robots of an arena (the serial robots, the epuck2) declare of their shared options
// (Device::options()).
inline constexpr std::string_view kArenaWhat =
    "the arena it runs in, a named spec (emulate: or FILE.wkt); record writes it into the log's "
    "header for buffon-from-logs";
inline constexpr std::string_view kPeriodWhat =
    "the shortest time between two sensor reads, in milliseconds (the Hemisson's default: the "
    "motion model's period)";
inline constexpr std::string_view kListenWhat =
    "serve the emulator over TCP on HOST:PORT instead of a pty";
// The seed and the parsed --fault specs (parse_faults' InputError on a bad one).
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
