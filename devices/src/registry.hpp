#pragma once
// The devices' definitions, for the registry (registry.cpp; internal).
#include <antkit/devices/device.hpp>

namespace antkit::devices::detail {

const Device& khepera_device() noexcept;        // device_serial.cpp
const Device& khepera_webots_device() noexcept; // device_serial.cpp
const Device& hemisson_device() noexcept;       // device_serial.cpp
const Device& epuck_device() noexcept;          // device_serial.cpp
const Device& stc_floor_device() noexcept;      // device_stc_floor.cpp

} // namespace antkit::devices::detail
