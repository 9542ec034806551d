// The robot descriptions (robot.hpp). Sources, as gathered in ../shared/devices/PROTOCOLS.md:
//  Khepera: K-Team, Khepera User Manual ch. 6 and Khepera II User Manual v1.1 section 6.2 (9600
//    8N2, D in pulses per 10 ms = 8 mm/s, H/G counters of 0.08 mm, N: 8 readings 0-1023, six at
//    the front left to right then two at the back; 55 mm body, 53 mm between the wheels).
//  Hemisson: RoadNarrows' Hemisson package (HemiSerial, HemiCmdBase) and the Hemisson User Manual
//    section 3.2.6 (115200 8N1, D in -9..9, N: 8 readings 0-255 in the order front, front-right,
//    front-left, right, left, rear, ground-right, ground-left; 120 mm body, 112 mm wheel base; no
//    wheel encoders).
//  e-puck: the e-puck library's advanced sercom and GCtronic's protocol page (115200 8N1, D in
//    steps/s, +-1000 on the e-puck 1, Q/P step counters, 1000 steps a turn of a 41 mm wheel; IR0..7
//    at -17, -49, -90, -150, +150, +90, +49, +17 degrees; 70 mm body, 53 mm wheel base).
//  Khepera in Webots: the TCP/IP relay controller, cyberbotics/webots
//    projects/robots/k-team/khepera1/controllers/tcpip/tcpip.c, and the Khepera1 PROTO
//    (PROTOCOLS.md, "Khepera in Webots"): D,l,r sets the wheel motors' velocities in rad/s (parsed
//    with %d: whole rad/s) up to the motors' maxVelocity, which the PROTO leaves at Webots' default
//    of 10 rad/s (Webots reference manual, Motor node: "SFFloat maxVelocity 10"); wheel radius 7.5
//    mm, so one speed unit is 7.5 mm/s = 7500 um/s; H is 50 * angle / pi, 100 counts a wheel turn,
//    so a count is 2 pi 7.5 mm / 100 = 471239 nm; G is acknowledged and does nothing (odometry_set
//    = 0); wheels 52 mm apart, body radius 28.5 mm (57 mm across); N: eight distance sensors
//    ds0..ds7 as on the real Khepera, 1023 at contact falling linearly to 0 at 5 cm; B -> "b,0,0".
// Choices where the sources are silent:
//  * Terminator: CR for all four (RoadNarrows' Hemisson driver and asercom drivers send CR; the
//    Khepera firmware ends a command at CR or LF).
//  * Khepera D range +-127 (the counters' speed register is 8-bit signed in the manual's table of
//    limits); the behaviour's unit speed is 10 (80 mm/s), a gentle speed for a 55 mm robot.
//  * Hemisson speed unit: 20 mm/s per step of D (about its top speed at 9); unit speed = 9.
//  * e-puck unit speed = 1000 steps/s (the firmware's limit).
//  * Khepera's rear pair at -165 (6, right) and +165 (7, left) degrees (the Webots Khepera too).
//  * Khepera in Webots: line settings 9600 8N1 are recorded in the log header only -- over TCP they
//    mean nothing (and over a pty to our emulator neither); 9600 as the Khepera it imitates. D's
//    range is +-10 (maxVelocity); unit speed 10 rad/s = 75 mm/s, near the real Khepera's 80 mm/s,
//    with the same resolution (a tenth of the unit speed). Terminator CR: the relay acts on the
//    first letter of what it receives and ignores the rest.
//  * Normalisation scale: the reading's full range (1023, 255), and 4000 for the e-puck's
//    calibrated readings ("0 to about 4000"), whose replies may go to 4095.
//  * The emulators' linear IR model reaches 0 at 40 mm (Khepera, its useful range), 80 mm
//    (Hemisson) and 50 mm (e-puck; the Webots Khepera, its lookup table, though the emulator caps
//    every range at the simulator's 0.75 body diameters: 42.75 mm).
#include <antkit/devices/robot.hpp>

namespace antkit::devices {

namespace {

constexpr RobotDescription kKhepera{
    .kind = RobotKind::Khepera,
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
};

constexpr RobotDescription kHemisson{
    .kind = RobotKind::Hemisson,
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
};

constexpr RobotDescription kEpuck{
    .kind = RobotKind::Epuck,
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
};

constexpr RobotDescription kKheperaWebots{
    .kind = RobotKind::KheperaWebots,
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
};

} // namespace

std::optional<RobotKind> parse_robot(std::string_view name) {
  for (const auto kind :
       {RobotKind::Khepera, RobotKind::KheperaWebots, RobotKind::Hemisson, RobotKind::Epuck})
    if (name == describe(kind).name) return kind;
  return std::nullopt;
}

std::string_view robot_name(RobotKind robot) {
  return describe(robot).name;
}

std::string_view robot_names() {
  return "khepera, khepera-webots, hemisson, epuck";
}

const RobotDescription& describe(RobotKind robot) {
  switch (robot) {
  case RobotKind::Khepera:
    return kKhepera;
  case RobotKind::Hemisson:
    return kHemisson;
  case RobotKind::Epuck:
    return kEpuck;
  case RobotKind::KheperaWebots:
    return kKheperaWebots;
  }
  return kKhepera;
}

} // namespace antkit::devices
