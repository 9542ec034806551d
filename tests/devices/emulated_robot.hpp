#pragma once
// A firmware emulator serving a real pseudo-terminal from a thread of the test, and a temporary
// directory for logs: the end-to-end tests run the real record loop against it over the tty.
#include "scratch_dir.hpp"

#include <antkit/devices/emulator.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/serial.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <utility>
#include <vector>

namespace antkit::test {

// An emulator (FirmwareEmulator, stc_floor::FloorEmulator) serving a real pty from a thread.
template <class Emulator>
class OnPty {
public:
  template <class... Args>
  explicit OnPty(Args&&... args)
      : pty_(devices::Pty::open()), emulator_(std::forward<Args>(args)...) {
    thread_ = std::thread([this] { emulator_.serve(pty_, &stop_, false); });
  }
  OnPty(const OnPty&) = delete;
  OnPty& operator=(const OnPty&) = delete;
  ~OnPty() { stop(); }
  // Stops serving (the emulator's state stays readable).
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  [[nodiscard]] const std::string& port() const noexcept { return pty_.slave_path(); }
  [[nodiscard]] const Emulator& emulator() const noexcept { return emulator_; }

private:
  devices::Pty pty_;
  Emulator emulator_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

class EmulatedRobot : public OnPty<devices::FirmwareEmulator> {
public:
  EmulatedRobot(devices::RobotKind robot, const std::string& arena,
                devices::EmulatorOptions options = {})
      : OnPty(robot, geometry::build_arena_spec(arena).arena.walls_fx(), options) {}
};

// A recording's options for the tests: the robot's own line, a short timeout and back-off (a pty
// answers within a millisecond), the library's number of tries, and no control period (the
// emulator is lock-stepped: a period is a sensor read, however fast it comes).
inline devices::RecordOptions record_options(devices::RobotKind robot, const std::string& port,
                                             const std::string& controller,
                                             const devices::Params& params, std::int64_t steps,
                                             const std::string& out) {
  devices::RecordOptions o;
  o.device = std::string(devices::robot_name(robot));
  o.port = port;
  o.line = devices::describe(robot).line;
  o.controller = devices::make_spec(controller, 7, params, "test");
  o.steps = steps;
  o.out = out;
  o.link.timeout = std::chrono::milliseconds(60);
  o.link.backoff = std::chrono::milliseconds(1);
  o.link.backoff_max = std::chrono::milliseconds(4);
  o.device_options.set("period", std::int64_t{0});
  return o;
}

// A file's lines (without their newlines), and lines written back each with its newline.
inline std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}
inline void write_lines(const std::string& path, const std::vector<std::string>& lines) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  for (const auto& l : lines) out << l << '\n';
}

// A fresh directory under the system's temporary directory, removed with everything in it
// (scratch_dir.hpp).
class TempDir {
public:
  [[nodiscard]] std::string file(const std::string& name) const { return (dir_ / name).string(); }

private:
  ScratchDir dir_{"devices"};
};

} // namespace antkit::test
