#pragma once
// The registry's parts (registry.cpp; internal).
#include "robots.hpp"

#include <antkit/devices/device.hpp>
#include <span>

namespace antkit::devices::detail {

// The serial robots' descriptions, in the registry's order (one line each in registry.cpp):
// describe() finds a robot's among them.
std::span<const RobotDescription* const> serial_robots();
// The device of a serial robot (device_serial.cpp); only the registry's list calls it.
const Device& serial_device(const RobotDescription& robot);
const Device& stc_floor_device() noexcept; // device_stc_floor.cpp
const Device& epuck2_device() noexcept;    // device_epuck2.cpp (binary mode)

} // namespace antkit::devices::detail
