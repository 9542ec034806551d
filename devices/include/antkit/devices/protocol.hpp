#pragma once
// The robots' ASCII serial protocols (PROTOCOLS.md, "Common to all three"): a command is an
// upper-case letter and comma-separated decimal integers, ended by the robot's terminator; the
// reply is the letter in lower case, its values after commas, and CR LF. The codec encodes
// commands, validates replies completely (the echoed letter, CR LF and nothing after it, arity,
// ranges, decimal syntax), and on the firmware side parses commands and encodes replies for the
// emulators. Decoders never throw and do not allocate on success.
//
// Per-robot choices and their sources (see also robot.cpp):
//  * Replies: values are plain decimals with an optional '-'; leading zeros are accepted because
//    HemiOS pads (RoadNarrows' HemiSerial expects an N reply of at least 33 characters: eight
//    3-digit fields), and our Hemisson emulator pads the same way. '+', spaces and empty fields
//    are refused.
//  * e-puck N and O replies carry 8 values, or 10 on lab firmwares that append two (GCtronic's
//    advanced sercom page): both are accepted, the first eight used. Calibrated e-puck proximity
//    can dip below 0 by a little: values down to -proximity_max are accepted; normalisation
//    clamps them to 0.
//  * B (Khepera, Hemisson) and V (e-puck) reply with free text after the letter's comma.
//  * Unknown commands: the Khepera and Hemisson firmwares answer "z,Protocol error" and asercom
//    "z,Command not found" (a choice following the shape of the sources' error replies; no driver
//    relies on the text); the Webots relay a bare "\n" (its tcpip.c).
//  * The Webots Khepera: the Khepera's codec (B, D, G, H, L, N, O) with its own ranges (robot.cpp);
//    set_odometry is refused (a logic_error), as G does nothing on the relay.
//  * Firmware leniency: asercom accepts lower-case command letters (PROTOCOLS.md); the Khepera
//    and Hemisson emulators accept only upper case, as their manuals print them.
#include <antkit/devices/robot.hpp>
#include <antkit/kernel/fixed.hpp>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::devices {

struct Fields {
  char letter = 0;
  std::array<std::int32_t, 12> values{};
  std::uint8_t count = 0;
};

struct DecodeError {
  std::size_t column = 0;
  std::string message;
};
template <class T>
struct Decoded {
  std::optional<T> value;
  DecodeError error;
  explicit operator bool() const noexcept { return value.has_value(); }
};

// The common line grammar (PROTOCOLS.md, "Common to all three"), for every robot's codec:
// a reply line is `letter`, then `min_n` to `max_n` decimal values in [lo, hi] after commas, then
// CR LF and nothing else; a command line (terminator stripped) is an upper-case letter (lower case
// too when lower_ok) and up to 12 decimal 32-bit values after commas. Columns count from 1.
Decoded<Fields> scan_reply(std::string_view line, char letter, std::size_t min_n, std::size_t max_n,
                           std::int64_t lo, std::int64_t hi);
Decoded<Fields> scan_command(std::string_view line, bool lower_ok);

struct Proximity {
  std::array<std::int32_t, 8> raw{};
};
struct WheelPair {
  std::int32_t left = 0, right = 0;
};

class Codec {
public:
  explicit Codec(RobotKind robot);
  [[nodiscard]] const RobotDescription& robot() const noexcept { return *robot_; }

  std::string set_speed(std::int32_t left, std::int32_t right) const;
  std::string read_speed() const;
  std::string read_proximity() const;
  std::string read_odometry() const;
  std::string set_odometry(std::int32_t left, std::int32_t right) const;
  std::string set_led(std::int32_t led, std::int32_t action) const;
  std::string version() const;
  // Whether a reply to version() (a whole line, CR LF included) identifies this robot by its rule
  // (RobotDescription::identifies); false for a robot without one.
  bool identifies(std::string_view version_reply) const;
  std::vector<std::string> safe_stop() const;

  Decoded<bool> decode_ack(std::string_view line, char command_letter) const;
  Decoded<Proximity> decode_proximity(std::string_view line) const;
  Decoded<WheelPair> decode_odometry(std::string_view line) const;
  Decoded<WheelPair> decode_speed(std::string_view line) const;
  Decoded<Fields> decode_reply(std::string_view sent_command, std::string_view line) const;

  Decoded<Fields> parse_command(std::string_view line) const;
  std::string reply(char command_letter, std::span<const std::int32_t> values = {}) const;
  std::string unknown_command_reply(std::string_view line) const;

private:
  const RobotDescription* robot_;
  // The requests without values, encoded once (a replay asks for two of them every step).
  std::string read_proximity_, read_odometry_;
};

// The letter of a reply to a command of letter `c`: c in lower case (ASCII only: what std::tolower
// does in the C locale, the only one antkit runs in; it never calls setlocale).
constexpr char reply_letter(char c) noexcept {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

// The serial robots whose identification rule a reply line to `version_command` ("B\r", "V\r")
// satisfies, by name ("khepera-webots"; "" when none): for the message refusing another robot.
std::string identified_as(std::string_view version_command, std::string_view reply);

kernel::Fx normalise_reading(const RobotDescription& robot, std::int32_t raw);

// normalise_reading() for one robot, by a table of every reading on its scale: the same value for
// every raw reading (test_protocol checks each), with no division per reading (a controller
// normalises six readings a step: 3 % of a replay's checking thread's samples, by perf).
class ReadingNormaliser {
public:
  explicit ReadingNormaliser(const RobotDescription& robot);
  [[nodiscard]] const RobotDescription& robot() const noexcept { return *robot_; }
  [[nodiscard]] kernel::Fx operator()(std::int32_t raw) const noexcept {
    const auto top = static_cast<std::int32_t>(raw_.size()) - 1;
    return kernel::Fx::from_raw(raw_[static_cast<std::size_t>(raw < 0     ? 0
                                                              : raw > top ? top
                                                                          : raw)]);
  }

private:
  const RobotDescription* robot_;
  std::vector<std::int32_t> raw_; // raw_[v]: normalise_reading(robot, v).raw(), v in [0, scale]
};
std::int32_t reading_to_raw(const RobotDescription& robot, kernel::Fx reading);
std::int32_t to_wheel_command(const RobotDescription& robot, kernel::Fx m);
kernel::Fx from_wheel_command(const RobotDescription& robot, std::int32_t v);

} // namespace antkit::devices
