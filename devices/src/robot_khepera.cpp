// The Khepera (K-Team): its description (robot.hpp). Sources, as gathered in
// ../shared/devices/PROTOCOLS.md:
//  Khepera: K-Team, Khepera User Manual ch. 6 and Khepera II User Manual v1.1 section 6.2 (9600
//    8N2, D in pulses per 10 ms = 8 mm/s, H/G counters of 0.08 mm, N: 8 readings 0-1023, six at
//    the front left to right then two at the back; 55 mm body, 53 mm between the wheels).
// The choices made where the sources are silent are listed in robot.cpp.
#include "registry.hpp"

namespace antkit::devices::detail {

namespace {

// A dotted version number: digits, '.', digits.
constexpr bool dotted(std::string_view v) noexcept {
  const auto dot = v.find('.');
  if (dot == 0 || dot == std::string_view::npos || dot + 1 == v.size()) return false;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (i != dot && (v[i] < '0' || v[i] > '9')) return false;
  return true;
}

// Identification (record's, at connect): PROTOCOLS.md, "Khepera": `B` -> `b,5.02,5.01`, the BIOS
// and protocol versions (Khepera II User Manual v1.1, 6.2). The choice: any two dotted version
// numbers, since other BIOS releases print other numbers; this is what tells the robot from the
// Webots relay, which imitates its protocol but answers `b,0,0` ("Khepera in Webots", tcpip.c),
// and from a Hemisson, whose B answers HemiOS's version text.
constexpr bool khepera_version(std::string_view text) noexcept {
  const auto comma = text.find(',');
  return comma != std::string_view::npos && dotted(text.substr(0, comma)) &&
         dotted(text.substr(comma + 1));
}

constexpr RobotDescription kKhepera{
    .name = "khepera",
    .line = {9600, 8, 2, Parity::None},
    .terminator = "\r",
    .speed_min = -127,
    .speed_max = 127,
    .speed_full = 10,
    .speed_unit_um_s = 8000,
    .proximity_count = 8,
    .proximity_min = 0,
    .proximity_max = 1023,
    .proximity_scale = 1023,
    .sensor_range_um = 40000,
    .proximity_angle_deg = {90, 45, 10, -10, -45, -90, -165, 165},
    .ground = {false, false, false, false, false, false, false, false},
    .front_six = {0, 1, 2, 3, 4, 5},
    .diameter_um = 55000,
    .wheel_base_um = 53000,
    .has_odometry = true,
    .odometry_read = 'H',
    .odometry_set = 'G',
    .odometry_pulse_nm = 80000,
    .version_letter = 'B',
    .version_reply = "b,5.02,5.01\r\n",
    .identifies = khepera_version,
    .identity = "b,BIOS,PROTOCOL with dotted version numbers (b,5.02,5.01 on a Khepera II)",
    .safe_stop = {"D,0,0", "L,0,0", "L,1,0"}, // wheels, then both LEDs off (L,n,0)
    .unknown_reply = "z,Protocol error\r\n",
};

} // namespace

ANTKIT_SERIAL_ROBOT(10, khepera_description) {
  return kKhepera;
}

} // namespace antkit::devices::detail
