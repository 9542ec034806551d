#pragma once
// The record loop: the bodies (adapters) that carry a controller's commands out on a real robot
// (or an emulator) over a serial link, and record(), which runs one and writes its log (DESIGN.md:
// a log recorded on a robot replays through the same controller and must reproduce every command
// it recorded).
//
// First, at connect, the robot is identified where its protocol allows (Session::identify): the
// text robots are asked for their version (B; the e-puck: V; the e-puck2 in binary mode its ASCII
// V, device_epuck2.cpp) and the reply must be this robot's (RobotDescription::identifies, each
// robot's rule and its source beside its description; epuck2::identifies): the
// Webots relay's `b,0,0` is not a Khepera's `b,5.02,5.01`, so `--device khepera` against the relay
// is refused instead of running in the wrong units. The exchange is step 0's first (its log is
// schema 2, log_schema.hpp) and replay checks it. A robot that answers, but not as this one -- an
// identity that is another's, or to the version request only lines of another shape (its error
// reply, the relay's bare LF) until the tries are spent -- is a wrong --device: record() throws
// kernel::InputError("device", ...) (exit 2) before any log is written, and nothing but the
// identification was sent (the version request; the e-puck2's resynchronisation zeros before it):
// the robot was never set moving, and no command in a protocol it may not speak is sent to it. A
// robot that does not answer at all is a link failure as any other.
//
// One control step, for every robot:
//   1. read the proximity sensors (`N`) and decode them; the controller's observation comes from
//      that reply (LoggedController::observe);
//   2. step the controller;
//   3. carry the command out:
//        buffon / rs: set the wheel speeds (`D,l,r`) to the command's wheel values;
//        wander:      a 45-degree turn or a step of one cell (half a body diameter, a choice):
//                     the wheels at half speed (turning: opposite), then one sensor read per
//                     control period until the wheel travel reaches the target (robots with
//                     encoders: closed loop on the counters; the Hemisson: on the travel it
//                     reckons from the times, step 4), then the wheels to zero; Wait does nothing;
//   4. read the odometry: the wheel counters (Khepera `H`, e-puck `Q`; reset to 0 with `G`/`P`
//      before the first step); the Hemisson has no encoders, so its odometry is reckoned: the
//      wheel travel the motion model gives the speeds in force (odometry.hpp, step_travel2, per
//      model period), times the time they were in force, from each command's send to the next
//      (the times the log holds for every exchange, so a replay reckons it again from them and
//      an edited time shows in "odo"), in micrometres.
// Then the step's record (every exchange of the step, the observation, the command, the odometry
// and the controller's state hash) is written and flushed before the next step starts.
//
// Every way out stops the robot safely (safe_stop() in link.hpp: wheels to zero until acknowledged
// and read back as zero, LEDs off; when that cannot be confirmed the stop record and the summary
// say the robot may still be moving, and the run is not a success) and ends
// the log with its stop record, which also holds the exchanges of an unfinished step: the run's
// steps, a stop signal (SIGINT, SIGTERM, SIGHUP, SIGQUIT), a link failure (resends exhausted, the
// watchdog, a disconnect), or any other error. No record is lost.
#include <antkit/devices/controllers.hpp>
#include <antkit/devices/device_options.hpp>
#include <antkit/devices/device_report.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/kernel/grid.hpp>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace antkit::devices {

// The robot at the port is not the device asked for (see "First, at connect" above): what it
// answered, and to what.
class WrongRobot : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The identification every device shares (Session::identify): `request` (a version request) sent
// through `link` until its reply; WrongRobot when the reply does not satisfy `identifies`, or when
// every try of the request got only whole lines that are not its reply (a robot of another
// protocol); LinkError as transact() otherwise. The message names the reply, the device (`name`,
// whose rule `identity` says in words) and the serial robots that answer so (identified_as()).
void identify_by_version(CommandLink& link, const std::string& request,
                         const std::function<bool(std::string_view reply)>& identifies,
                         std::string_view name, std::string_view identity,
                         std::vector<Exchange>& io);

// What a run is asked to do, for every device (device.hpp). The options of one device or another
// are in device_options, refused unless the device declared them (Device::options()); the device
// refuses values it cannot take (kernel::InputError naming the option in its declared word, or in
// these: "controller", "controller parameter", "steps", "device").
struct RecordOptions {
  std::string device = "khepera";   // a registry name (device.hpp)
  std::string port;                 // a tty or pty path, or tcp:HOST:PORT (serial.hpp)
  std::optional<LineSettings> line; // unset: the device's
  // The controller: its name, parameters (any order; the device makes them canonical) and seed.
  // The serial robots: controllers.hpp. The marker-floor robot: ant or ant-edge, params heading
  // (0 E, 1 N, 2 W, 3 S; default 1), quarter_turn_ms (the first T, default 1500), led_ms (2000).
  ControllerSpec controller;
  std::optional<std::int64_t> steps; // unset: 1000; the marker-floor robot: until its tour closes
  std::string out;                   // the log
  bool force = false; // replace `out` if it exists (otherwise an existing log is bad input)
  LinkOptions link;
  // The device's own options (device_options.hpp), by the names it declared (Device::options()):
  // the serial robots' and the epuck2's arena and period, the marker-floor robot's map, start,
  // calibration, heading, turn-ms and led-ms. prepare() refuses a name the device did not declare
  // and checks the others' ranges.
  DeviceValues device_options;
  std::uint32_t sync_every = 0; // fdatasync the log every N records (0: only at the end)
};

// The control period the simulator's motion model assumes for `robot` (a step of kDefaultSpeed body
// diameters at the wheels' unit speed), to the nanosecond: 11031 / 65536 x 120 mm at 9 x 20 mm/s =
// 112.214 ms for the Hemisson. A robot without encoders reads its sensors once per such period
// by default (the emulator, lock-stepped, moves one model step per read, so the travel reckoned
// from the times is the emulated one to within the pacing's jitter); robots with encoders read
// their counters and default to 0 (as fast as the link allows).
std::chrono::nanoseconds model_period(const RobotDescription& robot);
std::chrono::nanoseconds default_period(const RobotDescription& robot);

// How a run ended, typed (the log's stop record says it in words: stop_reason()).
enum class StopKind : std::uint8_t {
  Done,        // every requested step ran
  Interrupted, // a stop signal between steps (SIGINT, SIGTERM, SIGHUP, SIGQUIT: stop_signals.hpp)
  Link,        // resends exhausted, the watchdog, a disconnect, a refused connection
  Error        // anything else
};
std::string_view stop_kind_name(StopKind kind) noexcept;

// The words of a stop record: "done", "interrupted by SIGINT", "link: timeout: ...", "error: ...",
// then "; robot may be moving: WHY" when the safe stop could not confirm the wheels at zero, or
// "; safe stop: WHY" when only a later safe-stop command (LEDs off) failed.
inline constexpr std::string_view kRobotMayBeMoving = "robot may be moving";
std::string stop_reason(StopKind kind, const std::string& detail, const SafeStopResult& safe);

struct RecordSummary {
  std::int64_t steps = 0; // completed steps (records written)
  LinkStats link;
  StopKind kind = StopKind::Error;
  int signal = 0;         // the stop signal, when kind is Interrupted
  bool connected = true;  // the link opened (false: nothing was sent, no safe stop was needed)
  std::string log_error;  // "" when the log is whole; else why it is not (a full disk...)
  std::string stop;       // the stop record's reason
  bool completed = false; // all the requested steps ran
  SafeStopResult safe_stop;
  std::uint64_t hash = 0; // RunHash of the run (replay() recomputes it)
  // The device's own results of the run (Session::report, device_report.hpp), or null: the
  // marker-floor robot's tour (stc_floor/report.hpp). Null when the port never opened.
  std::shared_ptr<const DeviceReport> device_report;
  // The run did what it set out to do (every step) and the robot is known to be stopped. A run
  // stopped by a signal did not: `antkit record` exits 128 + the signal's number then (a script's
  // `record ... && record ...` must not drive the second visit after the user stopped the first).
  [[nodiscard]] bool succeeded() const noexcept {
    return kind == StopKind::Done && safe_stop.stopped && log_error.empty();
  }
};

using RecordProgress = std::function<void(std::int64_t step, std::int64_t steps)>;

// One record loop for every device (device.hpp): validates the options with the device (bad input
// is kernel::InputError, before anything is opened), refuses an existing `out` unless `force`,
// opens the port (a bad --port is bad input and leaves no log; a refused TCP connection leaves a
// log with only its stop record, kind Link), identifies the robot (a wrong one is bad input and
// leaves no log, above), then writes the log as it runs. Installs the SIGINT /
// SIGTERM handlers for its duration (StopSignals::Scope). Every failure of the run itself ends in
// the summary.
RecordSummary record(const RecordOptions& options, const RecordProgress& progress = {});

} // namespace antkit::devices
