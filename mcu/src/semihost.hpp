#pragma once
// ARM semihosting (the "Semihosting for AArch32 and AArch64" specification, ARM DUI 0471 and its
// successor on GitHub, ARM-software/abi-aa): the debugger (here QEMU, -semihosting-config
// enable=on,target=native) carries out a call made by `bkpt 0xAB` with the operation in r0 and a
// pointer to its arguments in r1. This is the image's only I/O: its input file, its output, its
// command line and its exit status.
#include <cstddef>
#include <cstdint>

namespace antkit::mcu {

enum class Sys : std::uint32_t {
  Open = 0x01,
  Close = 0x02,
  Write0 = 0x04,
  Write = 0x05,
  Read = 0x06,
  Flen = 0x0C,
  GetCmdline = 0x15,
  ExitExtended = 0x20,
};

inline std::int32_t semihost(Sys op, const void* args) noexcept {
  register std::uint32_t r0 asm("r0") = static_cast<std::uint32_t>(op);
  register const void* r1 asm("r1") = args;
  asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return static_cast<std::int32_t>(r0);
}

std::size_t length(const char* s) noexcept;

// Opens a host file for reading in binary ("rb"); -1 when it cannot.
std::int32_t open_read(const char* path) noexcept;
// The host's standard output (":tt" opened for writing).
std::int32_t open_stdout() noexcept;
void close(std::int32_t handle) noexcept;
// Reads up to n bytes; the number read.
std::size_t read(std::int32_t handle, void* buffer, std::size_t n) noexcept;
void write(std::int32_t handle, const char* data, std::size_t n) noexcept;
std::int32_t file_length(std::int32_t handle) noexcept;
// The command line QEMU was given with -semihosting-config arg=...; false when it does not fit.
bool command_line(char* buffer, std::size_t size) noexcept;
// Ends the emulation with `status` as QEMU's exit status (SYS_EXIT_EXTENDED).
[[noreturn]] void exit(std::uint32_t status) noexcept;

} // namespace antkit::mcu
