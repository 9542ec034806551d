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
// Choices where the sources are silent:
//  * Terminator: CR for all three (RoadNarrows' Hemisson driver and asercom drivers send CR; the
//    Khepera firmware ends a command at CR or LF).
//  * Khepera D range +-127 (the counters' speed register is 8-bit signed in the manual's table of
//    limits); the behaviour's unit speed is 10 (80 mm/s), a gentle speed for a 55 mm robot.
//  * Hemisson speed unit: 20 mm/s per step of D (about its top speed at 9); unit speed = 9.
//  * e-puck unit speed = 1000 steps/s (the firmware's limit).
//  * Khepera's rear pair at -165 (6, right) and +165 (7, left) degrees.
//  * Normalisation scale: the reading's full range (1023, 255), and 4000 for the e-puck's
//    calibrated readings ("0 to about 4000"), whose replies may go to 4095.
//  * The emulators' linear IR model reaches 0 at 40 mm (Khepera, its useful range), 80 mm
//    (Hemisson) and 50 mm (e-puck).
#include <antkit/devices/robot.hpp>

namespace antkit::devices {

namespace {

constexpr RobotDescription kKhepera{RobotKind::Khepera,
                                    "khepera",
                                    {9600, 8, 2, Parity::None},
                                    "\r",
                                    -127,
                                    127,
                                    10,
                                    8000,
                                    8,
                                    0,
                                    1023,
                                    1023,
                                    40000,
                                    {90, 45, 10, -10, -45, -90, -165, 165},
                                    {false, false, false, false, false, false, false, false},
                                    {0, 1, 2, 3, 4, 5},
                                    55000,
                                    53000,
                                    true,
                                    'H',
                                    'G',
                                    80000};

constexpr RobotDescription kHemisson{RobotKind::Hemisson,
                                     "hemisson",
                                     {115200, 8, 1, Parity::None},
                                     "\r",
                                     -9,
                                     9,
                                     9,
                                     20000,
                                     8,
                                     0,
                                     255,
                                     255,
                                     80000,
                                     {0, -45, 45, -90, 90, 180, 0, 0},
                                     {false, false, false, false, false, false, true, true},
                                     {4, 2, 0, 0, 1, 3},
                                     120000,
                                     112000,
                                     false,
                                     0,
                                     0,
                                     0};

constexpr RobotDescription kEpuck{RobotKind::Epuck,
                                  "epuck",
                                  {115200, 8, 1, Parity::None},
                                  "\r",
                                  -1000,
                                  1000,
                                  1000,
                                  129,
                                  8,
                                  -4095,
                                  4095,
                                  4000,
                                  50000,
                                  {-17, -49, -90, -150, 150, 90, 49, 17},
                                  {false, false, false, false, false, false, false, false},
                                  {5, 6, 7, 0, 1, 2},
                                  70000,
                                  53000,
                                  true,
                                  'Q',
                                  'P',
                                  128805};

} // namespace

std::optional<RobotKind> parse_robot(std::string_view name) {
  if (name == "khepera") return RobotKind::Khepera;
  if (name == "hemisson") return RobotKind::Hemisson;
  if (name == "epuck") return RobotKind::Epuck;
  return std::nullopt;
}

std::string_view robot_name(RobotKind robot) {
  return describe(robot).name;
}

const RobotDescription& describe(RobotKind robot) {
  switch (robot) {
  case RobotKind::Khepera:
    return kKhepera;
  case RobotKind::Hemisson:
    return kHemisson;
  case RobotKind::Epuck:
    return kEpuck;
  }
  return kKhepera;
}

} // namespace antkit::devices
