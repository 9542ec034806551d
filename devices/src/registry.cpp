// The registry of devices (device.hpp): the robots registered in their own files (registry.hpp),
// in the list the build writes from them (registry_list.cpp).
#include "registry.hpp"

#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/input_error.hpp>
#include <memory>
#include <vector>

namespace antkit::devices {

namespace detail {

std::span<const RobotDescription* const> serial_robots() {
  static const std::vector<const RobotDescription*> kRobots = [] {
    std::vector<const RobotDescription*> out;
    for (const RegistryEntry& e : registry_entries())
      if (e.robot != nullptr) out.push_back(&e.robot());
    return out;
  }();
  return kRobots;
}

} // namespace detail

std::span<const Device* const> all_devices() {
  // The serial robots' devices, made once and kept for the process.
  static const std::vector<std::unique_ptr<const Device>> kSerial = [] {
    std::vector<std::unique_ptr<const Device>> out;
    for (const RobotDescription* robot : detail::serial_robots())
      out.push_back(detail::make_serial_device(*robot));
    return out;
  }();
  static const std::vector<const Device*> kDevices = [] {
    std::vector<const Device*> out;
    std::size_t serial = 0;
    for (const detail::RegistryEntry& e : detail::registry_entries())
      out.push_back(e.robot != nullptr ? kSerial[serial++].get() : &e.device());
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
