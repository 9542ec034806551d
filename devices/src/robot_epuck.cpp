// The e-puck (GCtronic / EPFL): its description (robot.hpp). Sources, as gathered in
// ../shared/devices/PROTOCOLS.md:
//  e-puck: the e-puck library's advanced sercom and GCtronic's protocol page (115200 8N1, D in
//    steps/s, +-1000 on the e-puck 1, Q/P step counters, 1000 steps a turn of a 41 mm wheel; IR0..7
//    at -17, -49, -90, -150, +150, +90, +49, +17 degrees; 70 mm body, 53 mm wheel base).
// The choices made where the sources are silent are listed in robot.cpp.
#include "registry.hpp"

namespace antkit::devices::detail {

namespace {

// Identification (record's, at connect): PROTOCOLS.md, "e-puck (advanced sercom, ASCII mode)" and
// the binary-mode section's ASCII differences: `V` -> `v,Version 1.2.2 August 2008 GCtronic` on
// the e-puck1, `v,Version 2.0 January 2018 GCtronic` on the e-puck2 (asercom), then a second line
// "HW version: ..." (our emulator sends only the first): the link drains it as a late line before
// the next command, or, when it comes after that command was sent, takes it for a bad reply and
// resends the command (the start's P,0,0: idempotent). The choice: the
// text starts with "Version " (both firmwares speak this ASCII protocol); the Khepera, the Hemisson
// and the Webots relay do not know V (an error line, or the relay's bare LF).
constexpr bool asercom_version(std::string_view text) noexcept {
  return text.starts_with("Version ");
}

constexpr RobotDescription kEpuck{
    .name = "epuck",
    .line = {115200, 8, 1, Parity::None},
    .terminator = "\r",
    .speed_min = -1000,
    .speed_max = 1000,
    .speed_full = 1000,
    .speed_unit_um_s = 129,
    .proximity_count = 8,
    .proximity_min = -4095,
    .proximity_max = 4095,
    .proximity_scale = 4000,
    .sensor_range_um = 50000,
    .proximity_angle_deg = {-17, -49, -90, -150, 150, 90, 49, 17},
    .ground = {false, false, false, false, false, false, false, false},
    .front_six = {5, 6, 7, 0, 1, 2},
    .diameter_um = 70000,
    .wheel_base_um = 53000,
    .has_odometry = true,
    .odometry_read = 'Q',
    .odometry_set = 'P',
    .odometry_pulse_nm = 128805,
    .version_letter = 'V',
    .version_reply = "v,Version 1.2.2 antkit emulator\r\n",
    .identifies = asercom_version,
    .identity = "v,Version ... (advanced sercom's version text)",
    .safe_stop = {"D,0,0", "S"}, // S: "stop and LEDs off" in one command (asercom)
    .stop_letter = 'S',
    .proximity_extra = 2,
    .lower_case_commands = true,
    .unknown_reply = "z,Command not found\r\n",
};

} // namespace

ANTKIT_SERIAL_ROBOT(40, epuck_description) {
  return kEpuck;
}

} // namespace antkit::devices::detail
