#pragma once
// From a robot's logged wheel odometry to its trail, and paper 000's measurement from two logged
// visits: what section 7 did by hand with pen trails on the floor (Figure 13), as a computation.
//
// Dead reckoning: the logged odometry of each step is the two wheels' cumulative travel in the
// robot's odometry units (RobotDescription::odometry_pulse_nm: Khepera and e-puck encoder pulses;
// for a robot without encoders, the Hemisson, micrometres of travel reckoned from the logged
// times, see record_loop.hpp).
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
// as in paper 000 section 4.1). A_hat = 2 L1 L2 / (pi N); the BC form 2 L1 L2 / (pi BC). A_hat
// estimates the area the robot's centre explores, smaller than the arena (estimate.hpp; issue 26
// measured it 14 % low on a circle of diameter 20); the estimate to report is the erosion-corrected
// one, from the wall encounters in the logged front readings, with the precision rule's interval,
// exactly as `antkit buffon --precision` reports a simulated trial (estimate_area below).
#include <antkit/devices/log.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/segment.hpp>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::devices {

// One simulator step's wheel travel, doubled, in (raw Q15.16 body units) x micrometres, exact: for
// World::move's model at behaviour speeds m_l, m_r (fwd = speed (m_l + m_r) / 2 body units, turn =
// speed (m_r - m_l) radians) on wheels that do not slip, each wheel travels fwd * diameter -/+
// turn * wheel_base / 2; a blocked step (moved == false) turns on the spot. The emulator's
// encoders and the Hemisson's reckoned odometry (per model period) both count this.
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
// whose odometry is not two values. run_hash is the RunHash of the records (run_hash.hpp): the hash
// `antkit record` and `replay` print for the run.
struct LoggedTrail {
  std::string robot;
  std::vector<kernel::FxPoint> points;
  std::int64_t length_raw = 0;
  std::uint64_t steps = 0;
  bool truncated = false;
  std::uint64_t run_hash = 0;
  // The log's first records as they were written (times and bytes included): head[k] is a hash
  // of records 0..k, for k < head_steps = min(steps, kHead). Two recordings never share their
  // times to the nanosecond; a copy of one run, cut or not, shares its head.
  static constexpr std::size_t kHead = 16;
  std::array<std::uint64_t, kHead> head{};
  std::size_t head_steps = 0;
};
LoggedTrail trail_from_log(const std::string& path);

// The closed form with the precision rule's interval and the erosion correction, from a Buffon
// measurement's counts: what `antkit buffon --precision` reports per trial ("area_closed_form",
// "precision_ci", "area_corrected", "area_corrected_ci"), as a typed function so that the logged
// measurement reports the same numbers by the same arithmetic (estimate.hpp: closed_form_area,
// erosion_factor; stopping.hpp: the interval A_hat N / (N +/- z sqrt V), V = max(V1 + V2, N),
// z^2 = PrecisionMonitor::kZSquaredMilli / 1000). Reporting side: double (DESIGN.md, rule 1).
struct BuffonCounts {
  std::int64_t length1_raw = 0, length2_raw = 0;   // the two trails, raw Q15.16 body diameters
  std::uint64_t crossings = 0;                     // N: exact proper crossings of the trails
  double variance_visit1 = 0, variance_visit2 = 0; // PrecisionMonitor::spread() (0: no check)
  std::uint64_t wall_encounters = 0;               // buffon::WallEncounters over both visits
};
struct AreaInterval {
  std::optional<double> lower, upper; // absent where N cannot bound it (N = 0; N <= z sqrt V)
};
struct BuffonEstimate {
  std::optional<double> area_raw;       // 2 L1 L2 / (pi N): the area the centre explores (eroded)
  AreaInterval raw_ci;                  // the precision rule's 95 % interval of area_raw
  double erosion_factor = 1;            // 1 + kappa E / (L1 + L2)
  std::optional<double> area_corrected; // area_raw * erosion_factor: the arena's area
  AreaInterval corrected_ci;            // raw_ci * erosion_factor
};
BuffonEstimate estimate_area(const BuffonCounts& counts);

// An estimate against the arena's true area: (area - truth) / truth of its corrected and raw areas;
// none for an area the estimate lacks or a truth that is not positive.
struct RelativeErrors {
  std::optional<double> corrected, raw;
};
[[nodiscard]] RelativeErrors relative_errors(const BuffonEstimate& estimate, double truth);

// The arena a measurement took place in, for its true area. The logs' headers may name it
// (LogHeader::arena, written by `record --arena`); `spec` supplies it when they do not (`--arena`),
// and must agree with them when they do. area_of gives a spec's exact area in body diameters
// squared (a named spec or a WKT file; the caller's geometry: this library does not link the CGAL
// arenas, so the CLI passes geometry's builder); `where` names the spec's origin for its error
// messages. Without area_of the spec is still checked and reported, and the true area is absent.
// `same` says whether two specs name one arena (`circle:d=20` and `circle:d=20.0`: geometry's
// parser, which the caller has); without it specs are compared as text.
struct TrueArena {
  std::string spec; // "" unless given
  std::function<double(const std::string& spec, const std::string& where)> area_of;
  std::function<bool(const std::string& a, const std::string& b)> same = {};
};
enum class ArenaSource { none, logs, visit1, visit2, option };
std::string_view arena_source_name(ArenaSource source) noexcept; // "", "logs", "visit1", ...

struct BuffonFromLogs {
  LoggedTrail visit1, visit2;
  std::uint64_t bc = 0;              // the simulator's detector along visit 2 over visit 1's band
  std::uint64_t crossings_exact = 0; // proper crossings of the two centre lines
  std::optional<double> area;        // body diameters squared, from the exact count: RAW (eroded)
  std::optional<double> area_bc;     // from BC, raw
  double diameter_m = 0;             // the unit of length, metres
  // The precision rule's variance shares (visit 2 fed to a PrecisionMonitor step by step, as the
  // simulator does; both 0 when visit 2 is shorter than one check, 10 000 steps: the interval is
  // then the Poisson floor V = N) and the wall encounters of both visits' logged readings.
  double variance_visit1 = 0, variance_visit2 = 0;
  std::uint64_t wall_encounters = 0;
  BuffonEstimate estimate; // area_raw == area; area_corrected is the one to report
  std::string arena;       // the arena's spec ("" when unknown)
  ArenaSource arena_source = ArenaSource::none;
  std::optional<double> area_true;          // with an arena and area_of
  std::optional<double> relative_error;     // (area_corrected - area_true) / area_true
  std::optional<double> relative_error_raw; // (area_raw - area_true) / area_true
};
// width: the pheromone band (body diameters; paper 000's default 0.1). Refuses, with
// kernel::InputError at the offending file's header (FILE:1:COL, the column of the key):
//  * the same file given twice (same inode), and two logs of one run: equal run hashes over equal
//    step counts (the records' steps, observations, commands and controller states are the same,
//    so the two trails are one walk and their crossings are not Buffon's; a copy with an edited
//    header is caught too);
//  * a log whose controller is not `buffon` (rs and wander walks are not Buffon visits);
//  * a visit-1 log given as visit 2 or a visit-2 log as visit 1 (the header's params "visit");
//  * logs of different robots, or headers naming different arenas (or an arena other than
//    arena.spec, which is then refused as "arena spec");
//  * a log without odometry, or with a buffon observation that is not six readings in [0, 1];
//  * a log that does not replay (replay.hpp: at the first divergence's line) or is not whole (no
//    stop record, a cut last line): a visit is measured only as it was recorded.
BuffonFromLogs buffon_from_logs(const std::string& visit1, const std::string& visit2,
                                kernel::Fx width, const TrueArena& arena = {});

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
