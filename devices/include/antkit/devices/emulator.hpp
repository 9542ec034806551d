#pragma once
// Firmware emulators: a Khepera, a Hemisson, an e-puck or the Khepera in Webots (its TCP/IP relay)
// answering its own protocol on a pseudo-terminal or over TCP, its body simulated in the Buffon
// world (algorithms/buffon/world.hpp), so that the real record loop (link.hpp, record_loop.hpp)
// runs end to end over a real tty.
//
// The body, at the robot's own scale: the arena's unit of length is the robot's diameter (as in
// paper 000, where the Khepera's diameter is the unit and Figure 13 scales the arenas with the
// Hemisson's). Each proximity sensor sits on the body's edge at the robot's own angle
// (RobotDescription::proximity_angle_deg) and reads the Buffon world's linear model along its ray
// (World::ray_reading) over the robot's own range (sensor_range_um / diameter_um body units, at
// most the simulator's 0.75), converted to the robot's raw scale by reading_to_raw. Ground sensors
// read a constant floor (kFloorReading: the emulated floor carries no trail). Wheels: the
// simulator's differential drive (World::move) at m = from_wheel_command(v) for wheel command v.
//
// Time: the emulator is lock-stepped, not clocked. Each proximity read (`N`) is one control period:
// the body first moves one simulation step at the wheel speeds in force, then senses. Every other
// command takes no time (setting speeds, reading counters, LEDs). So a run does not depend on how
// fast the host is, and the record loop -- read sensors, decide, set speeds, read odometry -- is
// the simulator's step. A resent `N` is a second period (on a real robot a resend costs time too).
// A robot without encoders (the Hemisson) reckons its travel from real time (step 4 of
// record_loop.hpp): the emulated body matches it when the reads come once per model period, the
// recording's default for such a robot; read faster, the body moves a period per read while the
// robot reckons less (a choice: lock-step keeps every emulated run independent of the host's
// speed).
//
// Odometry: the wheel counters (Khepera H/G, e-puck Q/P) count what the wheels really turned, in
// the robot's pulses (RobotDescription::odometry_pulse_nm) from the exact running total, so there
// is no drift: for a step that moved by `fwd` and turned by `turn` radians, each wheel travels fwd
// * diameter -/+ turn * wheel_base / 2 (a blocked step turns on the spot: fwd = 0). The wheels do
// not slip. The counters are the dead reckoning's input (odometry.hpp), which recovers the body's
// trail from them.
//
// Sessions: a client's session lasts from its first command until it closes the tty. Each session
// starts afresh -- the body at the arena's start pose (from --seed), wheels stopped, counters at
// zero, the fault stream from its start -- as paper 000 puts the robot back at its start for each
// visit; so `antkit record` run twice against one emulator records two visits from the same pose.
// (The reset happens at the new session's first command, so the last session's state stays
// readable after its client has gone.)
//
// Over TCP (serve_tcp, `antkit emulate ... --listen HOST:PORT`): a session is one connection; one
// client at a time, a second one is refused while the first is connected (TcpListener, serial.hpp);
// the next connection is the next session. A disconnect fault closes the connection and ends the
// serving, as it hangs up a pty. The Webots relay is stricter (below): one client, once.
//
// The Khepera in Webots (RobotKind::KheperaWebots) answers as the relay controller does
// (PROTOCOLS.md, "Khepera in Webots"; Webots' khepera1/controllers/tcpip/tcpip.c): it acts on the
// command's first letter; D sets the speeds in rad/s, clamped to the motors' maxVelocity (+-10, as
// Webots clamps a velocity above it) and is acknowledged whatever follows the letter; G is
// acknowledged and does nothing; H counts 100 a wheel turn (50 * angle / pi, truncated toward zero
// as the relay's cast to int), cumulative; L is acknowledged; B answers "b,0,0"; anything else (E,
// an unknown letter, a malformed line) gets a bare "\n"; `exit` closes the connection. It is as
// strict as the relay (issue 43), so that a client that works against it works against Webots:
//   * one command a read: the relay reads at most 256 bytes a control step and acts on the first
//     letter of what it read, so the emulator reads its input as bytes, at most 256 a read, and
//     acts on the read's first line only: a second command that arrived in the same read is lost,
//     unanswered (a client sends one command and waits for its reply, as the record loop does);
//   * over TCP, one client, once: the relay listens with a backlog of 1 and calls accept() once,
//     when the simulation starts. The emulator accepts its first client and never accepts again:
//     a second client's connect completes in the kernel's backlog (or, the backlog full, is not
//     answered) and nothing it sends is ever read or answered, while the first is connected and
//     after it has gone -- the relay takes no other client until the world is reset, which here is
//     a new `antkit emulate`. (Over a pty, which the relay does not have, clients follow one
//     another as for the other robots.)
// The counters are cumulative within the session.
//
// Faults (FaultSpec), each decided per command from the emulator's keyed streams, so a faulty run
// is itself reproducible: a delay before the reply, garbage bytes before it, the reply dropped, the
// reply cut in half (no terminator), a disconnect (hang-up) after N commands, and silence after N
// commands (a robot whose firmware hangs behind a live USB adapter: commands read, nothing answered
// or done, the line open).
// `pace`: replies are paced at the robot's baud rate (10 or 11 bit times a byte) plus a command
// latency (kCommandLatency), as the real firmware would; by default it answers as fast as the pty
// allows.
#include <antkit/buffon/world.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/devices/serial.hpp>
#include <antkit/kernel/random.hpp>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace antkit::devices {

// The experiment number of the emulators' keyed streams (issue 13).
inline constexpr std::uint64_t kEmulatorExperiment = 13;
inline constexpr std::int32_t kFloorReading = 200; // ground sensors over the bare floor (a choice)
inline constexpr std::chrono::milliseconds kCommandLatency{2};

struct FaultSpec {
  std::uint32_t delay_ppm = 0; // per command, in millionths
  std::chrono::milliseconds delay{0};
  std::uint32_t garbage_ppm = 0;
  std::uint32_t drop_ppm = 0;
  std::uint32_t cut_ppm = 0;
  std::int64_t disconnect_after = -1; // hang up after this many commands (-1: never)
  std::int64_t silent_after = -1; // after this many commands, answer nothing, line open (-1: never)
  std::uint32_t unterminated_ppm = 0; // the e-puck2's binary sequences only: the ending 0 lost
  friend bool operator==(const FaultSpec&, const FaultSpec&) = default;
};

// Parses --fault values: `delay=P:MS`, `garbage=P`, `drop=P`, `cut=P` (P a probability in [0, 1]
// with up to six decimals), `disconnect=N`, `silent=N` (N >= 0 commands), `unterminated=P` (the
// e-puck2's binary emulator only: a sequence's ending 0 lost, epuck2.hpp). Several may be given.
// Throws kernel::InputError("fault", ...).
FaultSpec parse_faults(const std::vector<std::string>& specs);

struct EmulatorOptions {
  std::uint64_t seed = 1;
  FaultSpec faults;
  bool pace = false;
};

// What an emulator's firmware does with one received command line.
struct EmulatorResponse {
  std::string bytes;                  // to write (empty: nothing)
  std::chrono::microseconds delay{0}; // before writing
  bool hang_up = false;               // then hang up the line
  // Then close this client's connection (the Webots relay's `exit`); on a pty, where the far side
  // cannot be closed, nothing.
  bool close_session = false;
};

// The serving loop every emulator shares: reads command lines (ended by CR, LF or CR LF; empty
// lines skipped) from the pty's master, calls new_session() before the first command of each
// client (a client's session lasts until it closes the tty), answers each line with handle(), and
// returns when `stop` is set, on a stop signal (when stop_on_signal), or after a hang-up response.
// `raw`: a byte-stream firmware (the e-puck2's binary mode): handle() gets whatever bytes came, as
// they came, not lines.
// `max_read` (raw only): at most this many bytes a read, handed to handle() whole (the Webots
// relay's 256; 0: every byte there is).
void serve_pty(Pty& pty, const std::function<EmulatorResponse(std::string_view)>& handle,
               const std::function<void()>& new_session, const std::atomic<bool>* stop,
               bool stop_on_signal, bool raw = false, std::size_t max_read = 0);

// The same over TCP: serves one client at a time from `listener` (pausing it while a client is
// connected, so a second client is refused), each connection a session (new_session() before its
// first command), until `stop`, a stop signal (when stop_on_signal) or a hang-up response (which
// closes the connection and returns). `accept_once` (the Webots relay): the first client only; the
// listener stays open and is never accepted from again (see above).
void serve_tcp(TcpListener& listener,
               const std::function<EmulatorResponse(std::string_view)>& handle,
               const std::function<void()>& new_session, const std::atomic<bool>* stop,
               bool stop_on_signal, bool raw = false, std::size_t max_read = 0,
               bool accept_once = false);

// The Webots relay's read: at most this many bytes a control step (tcpip.c, PROTOCOLS.md).
inline constexpr std::size_t kRelayReadBytes = 256;

class FirmwareEmulator {
public:
  // `walls` in body diameters (geometry::arena_walls of an arena spec or WKT). Throws
  // kernel::InputError for an arena the Buffon world refuses or with no clear start.
  FirmwareEmulator(RobotKind robot, std::vector<kernel::FxSegment> walls,
                   EmulatorOptions options = {});

  // What the firmware does with one received command line (terminator stripped); the Webots
  // relay: with what one read returned, of which it takes the first line only (above).
  using Response = EmulatorResponse;
  Response handle(std::string_view line);
  // Starts a new session (see above): what serve() does at a new client's first command.
  void reset();

  // Serves `pty`, session after session, until a stop is requested (`stop` set, or a stop signal:
  // StopSignals) or a disconnect fault hangs up. Returns the number of commands served.
  // With stop_on_signal false the stop signals are left to the rest of the process (an emulator
  // serving from a thread of a program that records through it, as the tests do).
  std::uint64_t serve(Pty& pty, const std::atomic<bool>* stop = nullptr,
                      bool stop_on_signal = true);
  // The same over TCP, one connection a session (serve_tcp).
  std::uint64_t serve(TcpListener& listener, const std::atomic<bool>* stop = nullptr,
                      bool stop_on_signal = true);

  [[nodiscard]] const RobotDescription& robot() const noexcept { return codec_.robot(); }
  [[nodiscard]] const buffon::Pose& pose() const noexcept { return pose_; }
  [[nodiscard]] const buffon::World& world() const noexcept { return world_; }
  // The body's centre at every control period so far (the start first): the truth that dead
  // reckoning from the logged odometry should recover.
  [[nodiscard]] const std::vector<kernel::FxPoint>& trail() const noexcept { return trail_; }
  [[nodiscard]] std::uint64_t commands() const noexcept { return commands_; } // all sessions
  [[nodiscard]] std::uint64_t sessions() const noexcept { return sessions_; } // served
  [[nodiscard]] std::uint64_t faults() const noexcept { return faults_; }
  [[nodiscard]] std::int32_t counter(int wheel) const noexcept;

private:
  std::string answer(const Fields& cmd);
  std::string relay_answer(std::string_view line); // the Webots relay (above)
  void new_session();
  void advance();
  void sense(std::array<std::int32_t, 8>& raw) const;

  Codec codec_;
  buffon::World world_;
  EmulatorOptions options_;
  buffon::Pose start_, pose_;
  kernel::Fx range_;
  std::int32_t speed_left_ = 0, speed_right_ = 0;
  // Twice the wheels' travel in (raw Q15.16 body units) x micrometres, exact.
  __extension__ __int128 travel2_[2] = {0, 0};
  std::int32_t offset_[2] = {0, 0}; // counter = pulses + offset (set by G / P)
  std::vector<kernel::FxPoint> trail_;
  kernel::Stream fault_stream_;
  std::uint64_t commands_ = 0, faults_ = 0, sessions_ = 0;
  std::uint64_t session_commands_ = 0; // for disconnect=N
};

} // namespace antkit::devices
