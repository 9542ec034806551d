#pragma once
// How a serial line is set up: baud rate and framing (data bits, parity, stop bits). Shared by the
// serial link (serial.hpp), the robot descriptions (robot.hpp) and the log header (log.hpp).
#include <cstdint>
#include <string>

namespace antkit::devices {

enum class Parity : std::uint8_t { None, Even, Odd };

struct LineSettings {
  std::uint32_t baud = 9600;
  std::uint8_t data_bits = 8; // 5..8
  std::uint8_t stop_bits = 1; // 1 or 2
  Parity parity = Parity::None;

  // The usual short form: data bits, parity letter, stop bits ("8N1", "8N2", "7E1").
  [[nodiscard]] std::string framing() const {
    const char p = parity == Parity::None ? 'N' : parity == Parity::Even ? 'E' : 'O';
    return std::string{static_cast<char>('0' + data_bits), p, static_cast<char>('0' + stop_bits)};
  }
  friend bool operator==(const LineSettings&, const LineSettings&) = default;
};

} // namespace antkit::devices
