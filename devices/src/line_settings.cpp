// The line settings: the supported baud rates and their termios codes, and the baud and framing
// parsers (line_settings.hpp, serial.hpp).
#include "serial_internal.hpp"

#include <antkit/devices/serial.hpp>
#include <antkit/kernel/input_error.hpp>
#include <termios.h>

namespace antkit::devices {

using kernel::InputError;

namespace {

struct Rate {
  std::uint32_t baud;
  speed_t code;
};
constexpr Rate kRates[] = {{1200, B1200},     {2400, B2400},     {4800, B4800},
                           {9600, B9600},     {19200, B19200},   {38400, B38400},
                           {57600, B57600},   {115200, B115200}, {230400, B230400},
                           {460800, B460800}, {921600, B921600}};

} // namespace

speed_t serial_detail::speed_code(std::uint32_t baud) {
  for (const auto& r : kRates)
    if (r.baud == baud) return r.code;
  throw InputError("baud rate", "unsupported baud rate " + std::to_string(baud));
}

std::uint32_t parse_baud(std::string_view text, const std::string& where) {
  std::uint64_t v = 0;
  if (text.empty() || text.size() > 7)
    v = 0;
  else
    for (const char c : text) {
      if (c < '0' || c > '9') {
        v = 0;
        break;
      }
      v = v * 10 + static_cast<std::uint64_t>(c - '0');
    }
  for (const auto& r : kRates)
    if (r.baud == v) return r.baud;
  throw InputError(where, "'" + std::string(text) +
                              "' is not a supported baud rate: expected one of 1200, 2400, 4800, "
                              "9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600");
}

LineSettings parse_framing(std::string_view text, std::uint32_t baud, const std::string& where) {
  LineSettings s;
  s.baud = baud;
  const bool ok = text.size() == 3 && text[0] >= '5' && text[0] <= '8' &&
                  (text[1] == 'N' || text[1] == 'E' || text[1] == 'O') &&
                  (text[2] == '1' || text[2] == '2');
  if (!ok)
    throw InputError(where, "'" + std::string(text) +
                                "' is not a framing: expected data bits 5-8, parity N, E or O, "
                                "stop bits 1 or 2, e.g. 8N1 or 8N2");
  s.data_bits = static_cast<std::uint8_t>(text[0] - '0');
  s.parity = text[1] == 'N' ? Parity::None : text[1] == 'E' ? Parity::Even : Parity::Odd;
  s.stop_bits = static_cast<std::uint8_t>(text[2] - '0');
  return s;
}

} // namespace antkit::devices
