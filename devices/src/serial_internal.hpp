#pragma once
// Helpers shared by the link sources (serial_port.cpp, port_lock.cpp, tcp.cpp, pty.cpp,
// line_settings.cpp): internal to antkit_devices, not installed.
#include <chrono>
#include <cstdint>
#include <string>
#include <sys/stat.h>
#include <termios.h>

namespace antkit::devices::serial_detail {

using Clock = std::chrono::steady_clock;

// serial_port.cpp: waiting on a descriptor.
int remaining_ms(Clock::time_point deadline);
// A LinkError for `err` from `what` on the link `name`: Disconnected for the errors a lost peer
// gives, else System.
[[noreturn]] void fail(const std::string& name, const char* what, int err);
// EINTR: a stop signal ends the wait, any other signal just retries it.
void interrupted(const std::string& name);

// line_settings.cpp: the termios code of a supported baud rate (InputError otherwise).
speed_t speed_code(std::uint32_t baud);

// port_lock.cpp: the port held exclusively (serial.hpp).
long lock_holder(const struct stat& device, int self_fd);
[[noreturn]] void port_busy(const std::string& path, long pid);
void lock_port(int fd, const std::string& path);

} // namespace antkit::devices::serial_detail
