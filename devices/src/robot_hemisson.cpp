// The Hemisson (K-Team / RoadNarrows): its description (robot.hpp). Sources, as gathered in
// ../shared/devices/PROTOCOLS.md:
//  Hemisson: RoadNarrows' Hemisson package (HemiSerial, HemiCmdBase) and the Hemisson User Manual
//    section 3.2.6 (115200 8N1, D in -9..9, N: 8 readings 0-255 in the order front, front-right,
//    front-left, right, left, rear, ground-right, ground-left; 120 mm body, 112 mm wheel base; no
//    wheel encoders).
// The choices made where the sources are silent are listed in robot.cpp.
#include "registry.hpp"

namespace antkit::devices::detail {

namespace {

// Identification (record's, at connect): PROTOCOLS.md, "Hemisson": `B` answers the HemiOS version
// (RoadNarrows' HemiCmdBase reads it as text, e.g. "HemiOS_v1.50"). The choice: the text starts
// with "HemiOS", whatever the version after it (versions differ in detail, PROTOCOLS.md); a
// Khepera's or the Webots relay's B answers numbers.
constexpr bool hemios_version(std::string_view text) noexcept {
  return text.starts_with("HemiOS");
}

constexpr RobotDescription kHemisson{
    .name = "hemisson",
    .line = {115200, 8, 1, Parity::None},
    .terminator = "\r",
    .speed_min = -9,
    .speed_max = 9,
    .speed_full = 9,
    .speed_unit_um_s = 20000,
    .proximity_count = 8,
    .proximity_min = 0,
    .proximity_max = 255,
    .proximity_scale = 255,
    .sensor_range_um = 80000,
    .proximity_angle_deg = {0, -45, 45, -90, 90, 180, 0, 0},
    .ground = {false, false, false, false, false, false, true, true},
    .front_six = {4, 2, 0, 0, 1, 3},
    .diameter_um = 120000,
    .wheel_base_um = 112000,
    .has_odometry = false,
    .odometry_read = 0,
    .odometry_set = 0,
    .odometry_pulse_nm = 0,
    .version_letter = 'B',
    .version_reply = "b,HemiOS_v1.50 antkit emulator\r\n",
    .identifies = hemios_version,
    .identity = "b,HemiOS... (HemiOS's version text)",
    .safe_stop = {"D,0,0"}, // HemiOS's LED commands differ between versions: none sent
    .reading_digits = 3,    // HemiOS pads sensor readings to three digits (protocol.hpp)
    .unknown_reply = "z,Protocol error\r\n",
};

} // namespace

ANTKIT_SERIAL_ROBOT(30, hemisson_description) {
  return kHemisson;
}

} // namespace antkit::devices::detail
