// Fuzz target: the TCP address parser of `antkit record --port tcp:HOST:PORT` and `antkit emulate
// --listen HOST:PORT` (parse_tcp_endpoint). Each input line is one address, parsed as a client's
// (port 1-65535) and as a listener's (port 0 too). Bad input must be an InputError; an accepted
// address must print (text()) as one that parses back to itself, and a client's never has port 0.
#include <antkit/devices/serial.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>
#include <string>

namespace {

void check(const std::string& line, bool any_port) {
  try {
    const auto at = antkit::devices::parse_tcp_endpoint(line, "--port", any_port);
    if (!any_port && at.port == 0) __builtin_trap();
    if (at.host.empty()) __builtin_trap();
    if (antkit::devices::parse_tcp_endpoint(at.text(), "x", any_port) != at) __builtin_trap();
    (void)antkit::devices::is_tcp_port(line);
  } catch (const antkit::kernel::InputError&) {
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto end = text.find('\n', start);
    const std::string line =
        text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    check(line, false);
    check(line, true);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return 0;
}
