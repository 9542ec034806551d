// The registry of devices (device.hpp): a robot is one line here.
#include "registry.hpp"

#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/input_error.hpp>
#include <array>
#include <vector>

namespace antkit::devices {

namespace detail {

std::span<const RobotDescription* const> serial_robots() {
  // A serial robot is its description (robot_<name>.cpp) and one line here.
  static const std::array<const RobotDescription*, 4> kRobots{
      &khepera_description(),
      &khepera_webots_description(),
      &hemisson_description(),
      &epuck_description(),
  };
  return kRobots;
}

} // namespace detail

std::span<const Device* const> all_devices() {
  static const std::vector<const Device*> kDevices = [] {
    std::vector<const Device*> out;
    for (const RobotDescription* robot : detail::serial_robots())
      out.push_back(&detail::serial_device(*robot));
    out.push_back(&detail::epuck2_device());    // the e-puck2 in binary mode (epuck2.hpp)
    out.push_back(&detail::stc_floor_device()); // paper 002's marker-floor robot
    return out;
  }();
  return kDevices;
}

const Device* find_device(std::string_view name) noexcept {
  for (const Device* d : all_devices())
    if (d->name() == name) return d;
  return nullptr;
}

std::string device_names() {
  std::string out;
  for (const Device* d : all_devices()) {
    if (!out.empty()) out += ", ";
    out += d->name();
  }
  return out;
}

const Device& device(std::string_view name, const std::string& where) {
  if (const Device* d = find_device(name)) return *d;
  throw kernel::InputError(where, "unknown device '" + std::string(name) + "': expected " +
                                      device_names());
}

EmulateReport emulate(const std::string& name, const EmulateOptions& options,
                      const std::function<void(const std::string& port)>& ready) {
  const Device& d = device(name, "robot");
  StopSignals::Scope signals;
  return d.emulate(options, ready);
}

} // namespace antkit::devices
