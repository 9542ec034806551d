#pragma once
// A firmware emulator serving a real pseudo-terminal from a thread of the test, and a temporary
// directory for logs: the end-to-end tests run the real adapter code against it over the tty.
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/serial.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <atomic>
#include <filesystem>
#include <string>
#include <thread>
#include <unistd.h>

namespace antkit::test {

class EmulatedRobot {
public:
  EmulatedRobot(devices::RobotKind robot, const std::string& arena,
                devices::EmulatorOptions options = {})
      : pty_(devices::Pty::open()),
        emulator_(robot, geometry::build_arena_spec(arena).arena.walls_fx(), options) {
    thread_ = std::thread([this] { emulator_.serve(pty_, &stop_, false); });
  }
  EmulatedRobot(const EmulatedRobot&) = delete;
  EmulatedRobot& operator=(const EmulatedRobot&) = delete;
  ~EmulatedRobot() { stop(); }
  // Stops serving (the emulator's state stays readable).
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  [[nodiscard]] const std::string& port() const noexcept { return pty_.slave_path(); }
  [[nodiscard]] const devices::FirmwareEmulator& emulator() const noexcept { return emulator_; }

private:
  devices::Pty pty_;
  devices::FirmwareEmulator emulator_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// A fresh directory under the system's temporary directory, removed with everything in it.
class TempDir {
public:
  TempDir() {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("antkit-devices-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  [[nodiscard]] std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
  std::filesystem::path path_;
};

} // namespace antkit::test
