#pragma once
// From a robot's logged wheel odometry to its trail, and paper 000's measurement from two logged
// visits: what section 7 did by hand with pen trails on the floor (Figure 13), as a computation.
//
// Dead reckoning: the logged odometry of each step is the two wheels' cumulative travel in the
// robot's odometry units (RobotDescription::odometry_pulse_nm: Khepera and e-puck encoder pulses;
// for a robot without encoders, the Hemisson, micrometres of commanded travel, see adapter.hpp).
// The heading after a step comes from the totals, not from a sum of increments:
//     theta = theta_0 + ((R - R_0) - (L - L_0)) pulse / wheel_base,
// so it does not drift with the number of steps (only the position integrates), and each step
// moves the centre by the mean wheel travel along the mean of the old and new headings (the chord
// of the arc, as World::move). Units: body diameters (the robot's own scale, as the emulator's
// arena and paper 000's), raw Q15.16 throughout; the start is the origin, heading along +x.
//
// Buffon from two visits (the closed form of estimate.hpp): the exact proper crossings N of the two
// centre-line trails (kernel::count_proper_crossings), and BC, the crossing detector of the
// simulator (detector.hpp) run along visit 2 over visit 1's pheromone band of width w
// (PheromoneRaster), both in the common frame of the two logs (both visits start at the same pose,
// as in paper 000 section 4.1). A_hat = 2 L1 L2 / (pi N); the BC form 2 L1 L2 / (pi BC).
#include <antkit/devices/log.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/segment.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace antkit::devices {

// One simulator step's wheel travel, doubled, in (raw Q15.16 body units) x micrometres, exact: for
// World::move's model at behaviour speeds m_l, m_r (fwd = speed (m_l + m_r) / 2 body units, turn =
// speed (m_r - m_l) radians) on wheels that do not slip, each wheel travels fwd * diameter -/+
// turn * wheel_base / 2; a blocked step (moved == false) turns on the spot. The emulator's
// encoders and the Hemisson's commanded-travel odometry both count this.
struct Travel2 {
  __extension__ __int128 left = 0, right = 0;
};
Travel2 step_travel2(const RobotDescription& robot, kernel::Fx speed, kernel::Fx m_l,
                     kernel::Fx m_r, bool moved);

struct WheelTravel {
  std::int64_t left = 0, right = 0; // cumulative, in the robot's odometry units
};

class DeadReckoning {
public:
  // Throws kernel::InputError("robot", ...) for a robot description without a wheel base.
  DeadReckoning(const RobotDescription& robot, WheelTravel start);
  // The pose after the wheels reached `total` (cumulative).
  void update(WheelTravel total);
  [[nodiscard]] kernel::FxPoint position() const noexcept { return position_; }
  [[nodiscard]] kernel::Angle heading() const noexcept { return heading_; }
  // Trail length so far, raw Q15.16 body units (the sum of the steps' chord lengths).
  [[nodiscard]] std::int64_t length_raw() const noexcept { return length_raw_; }

private:
  [[nodiscard]] kernel::Angle heading_of(WheelTravel total) const;
  std::int64_t unit_nm_;     // one odometry unit, nanometres
  std::int64_t diameter_um_; // the unit of length
  std::int64_t wheel_base_um_;
  WheelTravel start_, last_;
  kernel::FxPoint position_{};
  kernel::Angle heading_{};
  std::int64_t length_raw_ = 0;
};

// The trail of a logged run: the start, then the position after every step record's odometry.
// Throws kernel::InputError(path, line, column, ...) for a log without odometry, or with records
// whose odometry is not two values.
struct LoggedTrail {
  std::string robot;
  std::vector<kernel::FxPoint> points;
  std::int64_t length_raw = 0;
  std::uint64_t steps = 0;
  bool truncated = false;
};
LoggedTrail trail_from_log(const std::string& path);

struct BuffonFromLogs {
  LoggedTrail visit1, visit2;
  std::uint64_t bc = 0;              // the simulator's detector along visit 2 over visit 1's band
  std::uint64_t crossings_exact = 0; // proper crossings of the two centre lines
  std::optional<double> area;        // body diameters squared, from the exact count
  std::optional<double> area_bc;     // from BC
  double diameter_m = 0;             // the unit of length, metres
};
// width: the pheromone band (body diameters; paper 000's default 0.1). Throws kernel::InputError
// when the two logs are of different robots or either has no odometry.
BuffonFromLogs buffon_from_logs(const std::string& visit1, const std::string& visit2,
                                kernel::Fx width);

// The Randomized Search baseline (paper 000 section 8.1) from one logged walk (controller `rs`):
// the area the body covered along the dead-reckoned trail (buffon::rs_footprint: cells of side 0.1
// whose centre came under the body), in body diameters squared.
struct RsFromLog {
  LoggedTrail walk;
  std::uint64_t cells = 0;
  double area = 0;
  double diameter_m = 0;
};
RsFromLog rs_from_log(const std::string& path);

} // namespace antkit::devices
