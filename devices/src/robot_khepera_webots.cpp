// The Khepera in Webots behind its TCP/IP relay controller: its description (robot.hpp). Sources,
// as gathered in ../shared/devices/PROTOCOLS.md:
//  Khepera in Webots: the TCP/IP relay controller, cyberbotics/webots
//    projects/robots/k-team/khepera1/controllers/tcpip/tcpip.c, and the Khepera1 PROTO
//    (PROTOCOLS.md, "Khepera in Webots"): D,l,r sets the wheel motors' velocities in rad/s (parsed
//    with %d: whole rad/s) up to the motors' maxVelocity, which the PROTO leaves at Webots' default
//    of 10 rad/s (Webots reference manual, Motor node: "SFFloat maxVelocity 10"); wheel radius 7.5
//    mm, so one speed unit is 7.5 mm/s = 7500 um/s; H is 50 * angle / pi, 100 counts a wheel turn,
//    so a count is 2 pi 7.5 mm / 100 = 471239 nm; G is acknowledged and does nothing (odometry_set
//    = 0); wheels 52 mm apart, body radius 28.5 mm (57 mm across); N: eight distance sensors
//    ds0..ds7 as on the real Khepera, 1023 at contact falling linearly to 0 at 5 cm; B -> "b,0,0".
// The choices made where the sources are silent are listed in robot.cpp.
#include "registry.hpp"

namespace antkit::devices::detail {

namespace {

// Identification (record's, at connect): PROTOCOLS.md, "Khepera in Webots": `B` -> `b,0,0`
// exactly, the relay's "pretend version string" (tcpip.c); a real Khepera answers its BIOS and
// protocol versions (b,5.02,5.01), so the two are told apart although they share the protocol.
constexpr bool relay_version(std::string_view text) noexcept {
  return text == "0,0";
}

constexpr RobotDescription kKheperaWebots{
    .name = "khepera-webots",
    .line = {9600, 8, 1, Parity::None}, // irrelevant over TCP (see above)
    .terminator = "\r",
    .speed_min = -10, // rad/s, the motors' default maxVelocity
    .speed_max = 10,
    .speed_full = 10,
    .speed_unit_um_s = 7500, // 1 rad/s x 7.5 mm
    .proximity_count = 8,
    .proximity_min = 0,
    .proximity_max = 1023,
    .proximity_scale = 1023,
    .sensor_range_um = 50000, // lookup table 0 1023 0; 0.05 0 0.01
    .proximity_angle_deg = {90, 45, 10, -10, -45, -90, -165, 165},
    .ground = {false, false, false, false, false, false, false, false},
    .front_six = {0, 1, 2, 3, 4, 5},
    .diameter_um = 57000,
    .wheel_base_um = 52000,
    .has_odometry = true,
    .odometry_read = 'H',
    .odometry_set = 0,           // G is acknowledged and ignored: the counters cannot be reset
    .odometry_pulse_nm = 471239, // 2 pi x 7.5 mm / 100
    .reads_speed = false,        // the relay answers no E
    .version_letter = 'B',
    .version_reply = "b,0,0\r\n", // "a pretend version string" (tcpip.c)
    .identifies = relay_version,
    .identity = "b,0,0 (the relay's pretend version)",
    .safe_stop = {"D,0,0", "L,0,0", "L,1,0"}, // the relay has L for LEDs 0 and 1 (tcpip.c)
    // The relay answers what it does not know with a bare LF (tcpip.c: send(fd, "\n", 1)).
    .unknown_reply = "\n",
    .webots_relay = true,
    .reply_timeout = std::chrono::milliseconds(1000), // a control step can pass before the reply
};

} // namespace

ANTKIT_SERIAL_ROBOT(20, khepera_webots_description) {
  return kKheperaWebots;
}

} // namespace antkit::devices::detail
