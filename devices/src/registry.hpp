#pragma once
// The registry's parts (registry.cpp; internal).
//
// A robot registers itself in its own file: the head of the function that gives its description
// or its device is written with one of the two macros below, at the start of a line, at namespace
// scope in antkit::devices::detail:
//
//   ANTKIT_SERIAL_ROBOT(10, khepera_description) { return kKhepera; }   // robot_khepera.cpp
//   ANTKIT_DEVICE(50, epuck2_device) { static const Epuck2Device d; return d; }
//
// The build reads these lines from devices/src/*.cpp (devices/registry_list.cmake) and writes the
// registry's list from them (registry_list.cpp in the build tree), so adding a robot edits no
// shared file. The number is the robot's place in the registry: the order of device_names(), of
// `--device`'s help and of the messages that list the robots (unique; the build refuses two robots
// at one place). A serial robot (a RobotDescription read by the shared codec, emulator and
// device) gets its Device from device_serial.cpp; a robot of another kind is its own Device.
#include <antkit/devices/device.hpp>
#include <antkit/devices/robot.hpp>
#include <memory>
#include <span>

#define ANTKIT_SERIAL_ROBOT(place, function) const RobotDescription& function() noexcept
#define ANTKIT_DEVICE(place, function) const Device& function() noexcept

namespace antkit::devices::detail {

// One line of the registry's list: a serial robot's description or a device of its own.
struct RegistryEntry {
  const RobotDescription& (*robot)() noexcept; // a serial robot
  const Device& (*device)() noexcept;          // a robot of another kind
};
// The list the build writes (registry_list.cpp), in the order of the places (which it keeps only
// as that order).
std::span<const RegistryEntry> registry_entries();

// The serial robots' descriptions, in the registry's order: describe() finds a robot's among them.
std::span<const RobotDescription* const> serial_robots();
// The device of a serial robot (device_serial.cpp); only the registry calls it, once per robot.
std::unique_ptr<const Device> make_serial_device(const RobotDescription& robot);

} // namespace antkit::devices::detail
