#pragma once
// One robot model for every robot antkit drives (DESIGN.md, devices/): a Device is a robot as the
// command line names it (`--device khepera`), with what record(), replay() and emulate() need of
// it; a registry lists them. The loops are written once, for every device:
//   record()   (record_loop.hpp) opens the port, asks the device for a Session, and runs
//              start, then step after step (each step's record written and flushed before the
//              next), then the safe stop and the stop record, on every way out;
//   replay()   (replay.hpp) reads the log's header, finds its device by the header's robot and
//              checks every record through the device's checker inside the shared record loop
//              (replay_records);
//   emulate()  serves the device's firmware emulator on a pty or over TCP until SIGINT / SIGTERM.
// A log has one schema for every device (log.hpp): a header, step records (io, obs, cmd, odo,
// state) and a stop record; what a device puts in obs, cmd and odo is written beside its session.
//
// The devices (registry.cpp; each registers itself in its own file, devices/src/registry.hpp):
//   khepera, khepera-webots, hemisson, epuck   the serial robots of paper 000's family
//                                              (robot.hpp), running the controllers of
//                                              controllers.hpp (buffon, rs, wander)
//   epuck2                                     the e-puck2 in binary mode (epuck2.hpp,
//                                              device_epuck2.cpp): its binary codec and framing
//                                              (Framing, framing.hpp) over the shared link, and
//                                              its emulator; the e-puck's body and controllers
//   stc-floor                                  paper 002's marker-floor robot (stc_floor/), running
//                                              ant or ant-edge through the camera pipeline
// Adding a robot is one set of files (its description or codec, its Session, its Device), none
// shared: CONTRIBUTING.md walks through it.
#include <antkit/devices/device_options.hpp>
#include <antkit/devices/device_report.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/serial.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/segment.hpp>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::devices {

// One robot under one controller for one run, connected: the robot's half of record()'s loop.
// Every exchange goes into the `io` given (the step's record, or the stop record's).
class Session {
public:
  virtual ~Session() = default;
  // At connect, before the log is opened: asks the robot who it is where its protocol allows and
  // throws WrongRobot when it is another (record_loop.hpp); LinkError when the link fails. The
  // exchanges go into `io` (step 0's record). Nothing for a robot that cannot be identified.
  virtual void identify(std::vector<Exchange>& io) { (void)io; }
  // Before the first step (the wheel counters' reset, the marker-floor robot's dark frame).
  virtual void start(std::vector<Exchange>& io) = 0;
  // One control step: fills rec.obs, rec.cmd, rec.odo and rec.state (record() sets step, t_ns
  // and io). Returns false when the controller ended the run with this step (a closed tour);
  // throws LinkError when the link fails, another exception for anything else.
  virtual bool step(LogRecord& rec, std::vector<Exchange>& io) = 0;
  // Never throws: the robot stopped, confirmed where the robot can say (link.hpp).
  virtual SafeStopResult safe_stop(std::vector<Exchange>& io) noexcept = 0;
  [[nodiscard]] virtual LinkStats stats() const = 0;
  // Why the run, ended by a step that returned false, fell short of what it set out to do ("":
  // it did not; the marker-floor robot: it bumped and did not move). The run's stop is then an
  // error with these words.
  [[nodiscard]] virtual std::string failure() const { return {}; }
  // The device's own results of the run, beyond what every run has (RecordSummary::device_report:
  // the marker-floor robot's tour); null when it has none. Not called when the port never opened.
  [[nodiscard]] virtual std::shared_ptr<const DeviceReport> report() const { return nullptr; }
};

// A run prepared from the options, before anything is opened: its log header and how to connect.
struct PreparedRun {
  LogHeader header; // the device's fields: robot, controller, params, seed, arena
  LineSettings line;
  std::size_t max_line = 0; // the longest reply line the link accepts (0: SerialPort's default)
  std::int64_t steps = 0;
  std::function<std::unique_ptr<Session>(SerialPort port, const LinkOptions& link)> connect;
};

// The emulator's options: what every emulator takes, and the device's own options by the names
// it declared (Device::options()): the serial robots' arena, faults, pacing and listen address,
// the marker-floor robot's map, start, heading and camera.
struct EmulateOptions {
  std::uint64_t seed = 1;
  // The robots of an arena: its walls, from the `arena` option by the caller (the devices do not
  // link the geometry layer that reads arena specs and WKT files; antkit emulate builds them).
  std::vector<kernel::FxSegment> walls;
  DeviceValues device_options;
};

// What an emulator served (emulate()'s summary).
struct EmulateReport {
  std::string listen; // tcp:HOST:PORT when served over TCP
  std::uint64_t sessions = 0, commands = 0, faults = 0;
  // The serial robots: the last session's control periods and end position (body diameters).
  std::optional<std::uint64_t> periods;
  std::optional<std::pair<double, double>> position;
  // The device's own results, beyond these (device_report.hpp), or null: the marker-floor robot's
  // truth of its last session (stc_floor/report.hpp, its "floor" block).
  std::shared_ptr<const DeviceReport> device_report;
};

class Device {
public:
  virtual ~Device() = default;
  [[nodiscard]] virtual std::string_view name() const noexcept = 0;
  // The line the robot talks on (record's --baud and --framing go over it).
  [[nodiscard]] virtual LineSettings line() const noexcept = 0;
  // The body a log of this device runs with (dead reckoning, the MCAP export, buffon-from-logs:
  // body_of() in robot.hpp asks the device its log names): a serial robot's own description; a
  // robot may borrow another's (the e-puck2 the e-puck's); null when it has none (stc-floor).
  [[nodiscard]] virtual const RobotDescription* body() const noexcept { return nullptr; }
  // How long a command waits for its reply unless record's --timeout says (RobotDescription).
  [[nodiscard]] virtual std::chrono::milliseconds reply_timeout() const noexcept {
    return std::chrono::milliseconds(250);
  }
  // The device's own options, record's and emulate's (device_options.hpp), and those it refuses
  // with a reason of its own; any other one given is refused for it, in one place
  // (resolve_options()).
  [[nodiscard]] virtual std::span<const DeclaredOption> options() const noexcept = 0;
  // Checks the device's options against its declarations (resolve_options(): refuses an undeclared
  // one, a number out of range; applies the defaults), then validates the run for this device
  // (prepare_run()); kernel::InputError naming the option otherwise, in its declared word.
  [[nodiscard]] PreparedRun prepare(const RecordOptions& options) const;
  // The replay of a log whose header names this device (replay.hpp).
  [[nodiscard]] virtual ReplayResult replay(LogReader& reader, const std::string& path,
                                            std::optional<std::int64_t> until) const = 0;
  // Checks the device's options (resolve_options(), as prepare()), then serves the firmware
  // emulator (serve()): `ready` gets the pty's path (or tcp:HOST:PORT) once clients may connect;
  // returns after SIGINT / SIGTERM (or a disconnect fault).
  [[nodiscard]] EmulateReport
  emulate(const EmulateOptions& options,
          const std::function<void(const std::string& port)>& ready) const;

protected:
  // The device's own part of prepare() and emulate(), given only options it declared, in range,
  // with their defaults applied.
  [[nodiscard]] virtual PreparedRun prepare_run(const RecordOptions& options) const = 0;
  [[nodiscard]] virtual EmulateReport
  serve(const EmulateOptions& options,
        const std::function<void(const std::string& port)>& ready) const = 0;
};

// The declaration of option `name` of `use` by `device`, or null (a refused one included).
[[nodiscard]] const DeclaredOption* declared(const Device& device, OptionUse use,
                                             std::string_view name) noexcept;
// The values of `device`'s options of `use` as it reads them: kernel::InputError(word, ...) for the
// first name `given` holds that the device did not declare (" is an option of the stc-floor robot",
// of "the serial robots (khepera, ...)" when several take it, or the device's reason), a value of
// another type, or a number outside its range (naming the range); then each declared default not
// given is applied.
[[nodiscard]] DeviceValues resolve_options(const Device& device, OptionUse use,
                                           const DeviceValues& given);
// The same from the command line's words: each option given by name with the texts it was given
// (one for most, none for a Switch, one per time given for Texts), parsed by its declaration.
using GivenTexts = std::vector<std::pair<std::string, std::vector<std::string>>>;
[[nodiscard]] DeviceValues parse_device_options(const Device& device, OptionUse use,
                                                const GivenTexts& given);
// Every option of `use` that some device declares, once by name (the first declaration, in
// registry order): the flags a command registers. Two devices declaring one name declare it with
// one type (a test checks).
[[nodiscard]] std::vector<DeclaredOption> declared_options(OptionUse use);
// The devices that take option `name` of `use`, for messages and --help: "stc-floor",
// "khepera, khepera-webots, hemisson, epuck, epuck2".
[[nodiscard]] std::string option_takers(OptionUse use, std::string_view name);
// --help of a command for one device: its options of `use`, one paragraph each (flag, value,
// range, default, then what it is), and those it refuses with the reason.
[[nodiscard]] std::string device_options_help(const Device& device, OptionUse use);
// --help of a command without a device: the devices, each with the flags of its own options.
[[nodiscard]] std::string devices_options_help(OptionUse use, std::string_view command);

// Every device, in the order of device_names().
[[nodiscard]] std::span<const Device* const> all_devices();
// The device named `name`, or nullptr.
[[nodiscard]] const Device* find_device(std::string_view name) noexcept;
// The device named `name`; throws kernel::InputError(where, "unknown device ...: expected ...").
[[nodiscard]] const Device& device(std::string_view name, const std::string& where);
// "khepera, khepera-webots, hemisson, epuck, stc-floor", for messages and --help.
[[nodiscard]] std::string device_names();

// Serves `device`'s emulator (the library call behind `antkit emulate`); installs the SIGINT /
// SIGTERM handlers for its duration.
EmulateReport emulate(const std::string& device, const EmulateOptions& options,
                      const std::function<void(const std::string& port)>& ready);

} // namespace antkit::devices
