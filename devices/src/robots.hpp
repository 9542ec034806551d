#pragma once
// The serial robots' descriptions, one file each (robot_<name>.cpp; internal): describe()
// (robot.cpp) returns them by kind.
#include <antkit/devices/robot.hpp>

namespace antkit::devices::detail {

const RobotDescription& khepera_description() noexcept;        // robot_khepera.cpp
const RobotDescription& hemisson_description() noexcept;       // robot_hemisson.cpp
const RobotDescription& epuck_description() noexcept;          // robot_epuck.cpp
const RobotDescription& khepera_webots_description() noexcept; // robot_khepera_webots.cpp

} // namespace antkit::devices::detail
