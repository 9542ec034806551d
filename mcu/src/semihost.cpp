#include "semihost.hpp"

namespace antkit::mcu {

std::size_t length(const char* s) noexcept {
  std::size_t n = 0;
  while (s[n] != 0) ++n;
  return n;
}

namespace {
std::int32_t open(const char* path, std::uint32_t mode) noexcept {
  const std::uint32_t args[3] = {reinterpret_cast<std::uint32_t>(path), mode,
                                 static_cast<std::uint32_t>(length(path))};
  return semihost(Sys::Open, args);
}
} // namespace

std::int32_t open_read(const char* path) noexcept {
  return open(path, 1); // "rb"
}

std::int32_t open_stdout() noexcept {
  return open(":tt", 4); // "w"
}

void close(std::int32_t handle) noexcept {
  const std::uint32_t args[1] = {static_cast<std::uint32_t>(handle)};
  semihost(Sys::Close, args);
}

std::size_t read(std::int32_t handle, void* buffer, std::size_t n) noexcept {
  const std::uint32_t args[3] = {static_cast<std::uint32_t>(handle),
                                 reinterpret_cast<std::uint32_t>(buffer),
                                 static_cast<std::uint32_t>(n)};
  const std::int32_t left = semihost(Sys::Read, args); // the bytes NOT read
  return left < 0 || static_cast<std::size_t>(left) > n ? 0 : n - static_cast<std::size_t>(left);
}

void write(std::int32_t handle, const char* data, std::size_t n) noexcept {
  const std::uint32_t args[3] = {static_cast<std::uint32_t>(handle),
                                 reinterpret_cast<std::uint32_t>(data),
                                 static_cast<std::uint32_t>(n)};
  semihost(Sys::Write, args);
}

std::int32_t file_length(std::int32_t handle) noexcept {
  const std::uint32_t args[1] = {static_cast<std::uint32_t>(handle)};
  return semihost(Sys::Flen, args);
}

bool command_line(char* buffer, std::size_t size) noexcept {
  std::uint32_t args[2] = {reinterpret_cast<std::uint32_t>(buffer),
                           static_cast<std::uint32_t>(size)};
  return semihost(Sys::GetCmdline, args) == 0;
}

void exit(std::uint32_t status) noexcept {
  const std::uint32_t args[2] = {0x20026, status}; // ADP_Stopped_ApplicationExit, exit code
  for (;;) semihost(Sys::ExitExtended, args);
}

} // namespace antkit::mcu
