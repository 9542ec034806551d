#pragma once
// The robots of paper 000's family as antkit drives them -- the Khepera, the Hemisson, the e-puck,
// and the Khepera in Webots behind its TCP/IP relay controller (its units differ from the real
// Khepera's: a device of its own) -- line settings, command ranges, sensor layout and scales, body.
// Facts from ../shared/devices/PROTOCOLS.md and its sources (cited per robot in robot.cpp); where a
// source is silent, the choice is named there.
#include <antkit/devices/line_settings.hpp>
#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace antkit::devices {

struct RobotDescription;

// A robot of the serial protocols: a handle on its description in the registry (one file per
// robot, devices/src/robot_<name>.cpp, registered from that file: nothing shared names it), held
// by the robot's name and compared by it. Obtained from the registry (serial_robots(),
// parse_robot(), body_of(), of()); the four robots antkit was built with are also named here, for
// the tests, examples and benchmarks that pick one (a robot added later needs no name here: it is
// parse_robot("its-name")).
class RobotKind {
public:
  static const RobotKind Khepera, Hemisson, Epuck, KheperaWebots;
  // The kind of a registered description (describe(of(d)) is d).
  static RobotKind of(const RobotDescription& robot) noexcept;
  [[nodiscard]] constexpr std::string_view name() const noexcept { return name_; }
  friend constexpr bool operator==(RobotKind a, RobotKind b) noexcept { return a.name_ == b.name_; }

private:
  constexpr explicit RobotKind(std::string_view name) noexcept : name_(name) {}
  friend std::span<const RobotKind> serial_robots();
  friend std::optional<RobotKind> parse_robot(std::string_view name);
  std::string_view name_;
};
inline constexpr RobotKind RobotKind::Khepera{"khepera"};
inline constexpr RobotKind RobotKind::Hemisson{"hemisson"};
inline constexpr RobotKind RobotKind::Epuck{"epuck"};
inline constexpr RobotKind RobotKind::KheperaWebots{"khepera-webots"};

// Every robot of the serial protocols, in the registry's order, for loops over them (tests, fuzz
// targets, benchmarks).
std::span<const RobotKind> serial_robots();
// The serial robot of that name ("khepera", "khepera-webots", "hemisson", "epuck", ...), nullopt
// for a name no serial robot has.
std::optional<RobotKind> parse_robot(std::string_view name);
std::string_view robot_name(RobotKind robot);
// The names parse_robot accepts, for messages, in the registry's order: "khepera,
// khepera-webots, hemisson, epuck".
std::string_view robot_names();
// The description whose body and scales a log's robot runs with (dead reckoning, the MCAP
// export, buffon-from-logs): the one the device of that name says it runs with (Device::body(),
// device.hpp: a serial robot's own, the e-puck2's the e-puck's). nullopt for a name no device has,
// or a device without a body (stc-floor).
std::optional<RobotKind> body_of(std::string_view log_robot);

struct RobotDescription {
  std::string_view name; // the robot's name, its device's (--device) and its kind's
  LineSettings line;
  std::string_view terminator;       // sent after each command
  std::int32_t speed_min, speed_max; // D's accepted range
  std::int32_t speed_full;           // the wheel command for the behaviour's unit speed 1.0
  std::int32_t speed_unit_um_s;      // micrometres per second per speed unit
  std::size_t proximity_count;       // readings in an N reply used by controllers
  std::int32_t proximity_min;        // smallest reading a reply may carry
  std::int32_t proximity_max;        // largest
  std::int32_t proximity_scale;      // the reading normalised to 1.0
  std::int32_t sensor_range_um;      // the emulator's linear model reaches 0 here
  std::array<std::int16_t, 8> proximity_angle_deg; // per reading, CCW from the heading
  std::array<bool, 8> ground;                      // downward-looking sensors
  std::array<std::uint8_t, 6>
      front_six; // readings for the Buffon behaviour's I_0 (+90) .. I_5 (-90)
  std::int32_t diameter_um, wheel_base_um;
  bool has_odometry;
  char odometry_read; // the command reading the wheel counters
  // The command setting them; 0 when the robot has none that works (the Webots relay acknowledges
  // G and ignores it): the record loop then reads a baseline instead of resetting them.
  char odometry_set;
  std::int64_t odometry_pulse_nm;
  // `E` reads the wheel speeds back (all but the Webots relay, which answers only B, D, G, H, L, N
  // and O): the safe stop confirms the wheels at zero with it (link.hpp).
  bool reads_speed = true;
  // What else the protocol does its own way (the codec, protocol.cpp, and the emulator read these):
  char version_letter = 'B'; // the command asking for the firmware's version (B; the e-puck: V)
  // The emulator's answer to it, in the shape the manual prints (Khepera "b,5.02,5.01", HemiOS
  // "b,<version>", e-puck "v,<version text>"), its text naming the emulator so that nobody takes
  // it for a robot.
  std::string_view version_reply;
  // What identifies the robot in its reply to version_letter (record() asks for it at connect and
  // refuses a robot it does not identify, record_loop.hpp): the reply's text after its letter and
  // comma, CR LF stripped, e.g. "5.02,5.01" for the Khepera's "b,5.02,5.01\r\n". Each robot's
  // rule, with its PROTOCOLS.md source, is beside its description (robot_<name>.cpp); `identity`
  // says it in words for the refusal's message. A robot without a rule is not identified.
  bool (*identifies)(std::string_view version_text) = nullptr;
  std::string_view identity;
  std::array<std::string_view, 3> safe_stop{}; // the safe stop's commands (no terminator), the
                                               // wheels' stop first; empty entries are unused
  char stop_letter = 0; // a command that stops the wheels (and more) in one (the e-puck's S)
  std::size_t proximity_extra = 0;  // readings an N reply may carry beyond proximity_count
  bool lower_case_commands = false; // the firmware also takes commands in lower case
  std::uint8_t reading_digits = 0;  // readings padded with zeros to this many digits (HemiOS: 3)
  std::string_view unknown_reply;   // the answer to a command the firmware does not know
  // The Webots relay controller (tcpip.c): the emulator answers only its commands, closes on
  // "exit", ignores G, and truncates its counters toward zero.
  bool webots_relay = false;
  // How long a command waits for its reply by default (record's --timeout). 250 ms for the robots,
  // which answer within milliseconds; the Webots relay acts on one command per 250 ms control step
  // of simulated time (PROTOCOLS.md), so a reply takes up to a step, longer when the simulation
  // runs slower than real time, and a resend after a 250 ms timeout would reach the relay as a
  // second command and be executed twice: 1000 ms (four steps) there.
  std::chrono::milliseconds reply_timeout{250};
};
// The robot's registered description; std::logic_error for a kind no registered robot has (a kind
// comes from the registry, so only a robot named here and removed from it).
const RobotDescription& describe(RobotKind robot);

} // namespace antkit::devices
