// The robot descriptions (robot.hpp): each robot's is in its own file, robot_<name>.cpp, with its
// sources (as gathered in ../shared/devices/PROTOCOLS.md), registered from there (registry.hpp);
// this file looks them up by kind, which is the robot's name.
// Choices where the sources are silent:
//  * Terminator: CR for all four (RoadNarrows' Hemisson driver and asercom drivers send CR; the
//    Khepera firmware ends a command at CR or LF).
//  * Khepera D range +-127 (the counters' speed register is 8-bit signed in the manual's table of
//    limits); the behaviour's unit speed is 10 (80 mm/s), a gentle speed for a 55 mm robot.
//  * Hemisson speed unit: 20 mm/s per step of D (about its top speed at 9); unit speed = 9.
//  * e-puck unit speed = 1000 steps/s (the firmware's limit).
//  * Khepera's rear pair at -165 (6, right) and +165 (7, left) degrees (the Webots Khepera too).
//  * Khepera in Webots: line settings 9600 8N1 are recorded in the log header only -- over TCP they
//    mean nothing (and over a pty to our emulator neither); 9600 as the Khepera it imitates. D's
//    range is +-10 (maxVelocity); unit speed 10 rad/s = 75 mm/s, near the real Khepera's 80 mm/s,
//    with the same resolution (a tenth of the unit speed). Terminator CR: the relay acts on the
//    first letter of what it receives and ignores the rest.
//  * Normalisation scale: the reading's full range (1023, 255), and 4000 for the e-puck's
//    calibrated readings ("0 to about 4000"), whose replies may go to 4095.
//  * The emulators' linear IR model reaches 0 at 40 mm (Khepera, its useful range), 80 mm
//    (Hemisson) and 50 mm (e-puck; the Webots Khepera, its lookup table, though the emulator caps
//    every range at the simulator's 0.75 body diameters: 42.75 mm).
#include "registry.hpp"

#include <antkit/devices/device.hpp>
#include <antkit/devices/robot.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace antkit::devices {

RobotKind RobotKind::of(const RobotDescription& robot) noexcept {
  return RobotKind(robot.name);
}

std::span<const RobotKind> serial_robots() {
  static const std::vector<RobotKind> kinds = [] {
    std::vector<RobotKind> out;
    for (const RobotDescription* d : detail::serial_robots()) out.push_back(RobotKind(d->name));
    return out;
  }();
  return kinds;
}

std::optional<RobotKind> parse_robot(std::string_view name) {
  for (const auto kind : serial_robots())
    if (name == kind.name()) return kind;
  return std::nullopt;
}

std::optional<RobotKind> body_of(std::string_view log_robot) {
  if (const Device* d = find_device(log_robot))
    if (const RobotDescription* body = d->body()) return RobotKind::of(*body);
  return std::nullopt;
}

std::string_view robot_name(RobotKind robot) {
  return describe(robot).name;
}

std::string_view robot_names() {
  static const std::string names = [] {
    std::string out;
    for (const auto kind : serial_robots())
      out += (out.empty() ? "" : ", ") + std::string(kind.name());
    return out;
  }();
  return names;
}

const RobotDescription& describe(RobotKind robot) {
  for (const RobotDescription* d : detail::serial_robots())
    if (d->name == robot.name()) return *d;
  throw std::logic_error("robot '" + std::string(robot.name()) + "' is not registered");
}

} // namespace antkit::devices
