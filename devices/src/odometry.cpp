// Dead reckoning from logged odometry, and Buffon's measurement from two logged visits
// (odometry.hpp).
#include <algorithm>
#include <antkit/buffon/checkpoints.hpp>
#include <antkit/buffon/detector.hpp>
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/segment.hpp>

namespace antkit::devices {

namespace {
using kernel::Fx;
using kernel::InputError;
__extension__ using i128 = __int128;

std::int64_t unit_nm_of(const RobotDescription& robot) {
  return robot.has_odometry ? robot.odometry_pulse_nm : 1000; // Hemisson: micrometres
}

// n / d rounded half up (d > 0).
std::int64_t div_round(i128 n, i128 d) {
  i128 q = n / d, r = n % d;
  if (r < 0) --q, r += d;
  if (2 * r >= d) ++q;
  return static_cast<std::int64_t>(q);
}
} // namespace

Travel2 step_travel2(const RobotDescription& robot, Fx speed, Fx m_l, Fx m_r, bool moved) {
  const Fx turn = speed * (m_r - m_l);                           // World::move's turn
  const Fx forward = speed * (m_l + m_r) * Fx::from_ratio(1, 2); // and its forward distance
  const i128 fwd2 = moved ? i128{2} * forward.raw() * robot.diameter_um : 0;
  const i128 spin = i128{turn.raw()} * robot.wheel_base_um;
  return {fwd2 - spin, fwd2 + spin};
}

DeadReckoning::DeadReckoning(const RobotDescription& robot, WheelTravel start)
    : unit_nm_(unit_nm_of(robot)), diameter_um_(robot.diameter_um),
      wheel_base_um_(robot.wheel_base_um), start_(start), last_(start) {
  if (wheel_base_um_ <= 0 || diameter_um_ <= 0)
    throw InputError("robot", "the robot description has no wheel base or diameter");
}

kernel::Angle DeadReckoning::heading_of(WheelTravel total) const {
  const i128 diff = (i128{total.right} - start_.right) - (i128{total.left} - start_.left);
  // radians = diff * unit / wheel_base; as Q15.16, reduced below 2^30 raw (16384 rad) by whole
  // turns of 2 pi (411775 raw, 2 pi to 2^-17: the rest of the error is that rounding per turn).
  i128 raw = diff * unit_nm_ * 65536;
  const i128 den = i128{wheel_base_um_} * 1000;
  std::int64_t rad = div_round(raw, den);
  constexpr std::int64_t kTwoPi = 411775;
  if (rad > (std::int64_t{1} << 30) || rad < -(std::int64_t{1} << 30)) rad %= kTwoPi;
  return kernel::Angle::from_radians(Fx::from_raw(static_cast<std::int32_t>(rad)));
}

void DeadReckoning::update(WheelTravel total) {
  const kernel::Angle next = heading_of(total);
  const i128 moved_nm = ((i128{total.left} - last_.left) + (i128{total.right} - last_.right)) *
                        unit_nm_; // twice the mean travel, nm
  const std::int64_t d_raw = div_round(moved_nm * 65536, i128{2} * diameter_um_ * 1000);
  if (d_raw > INT32_MAX || d_raw < -INT32_MAX)
    throw InputError("odometry", "a step of more than 32767 body diameters");
  const kernel::Angle mid =
      heading_ +
      kernel::Angle::from_raw(static_cast<std::uint32_t>((next - heading_).signed_raw() / 2));
  const Fx d = Fx::from_raw(static_cast<std::int32_t>(d_raw));
  position_ = {position_.x + d * kernel::cos(mid), position_.y + d * kernel::sin(mid)};
  heading_ = next;
  length_raw_ += d_raw < 0 ? -d_raw : d_raw;
  last_ = total;
}

LoggedTrail trail_from_log(const std::string& path) {
  LogReader reader(path);
  const auto kind = parse_robot(reader.header().robot);
  if (!kind) throw InputError(path, 1, 1, "unknown robot '" + reader.header().robot + "'");
  LoggedTrail out;
  out.robot = reader.header().robot;
  std::optional<DeadReckoning> dr;
  LogRecord r;
  while (reader.next(r)) {
    if (r.odo.size() != 2)
      throw InputError(path, reader.line(), 1,
                       "a step record without odometry: a trail needs \"odo\" with the two wheels' "
                       "travel");
    const WheelTravel w{r.odo[0], r.odo[1]};
    if (!dr) {
      dr.emplace(describe(*kind), w);
      out.points.push_back(dr->position());
    } else {
      dr->update(w);
      out.points.push_back(dr->position());
    }
    ++out.steps;
  }
  if (out.points.empty())
    throw InputError(path, reader.line() + 1, 1, "the log has no step records");
  out.length_raw = dr->length_raw();
  out.truncated = reader.truncated();
  return out;
}

BuffonFromLogs buffon_from_logs(const std::string& visit1, const std::string& visit2, Fx width) {
  BuffonFromLogs out;
  out.visit1 = trail_from_log(visit1);
  out.visit2 = trail_from_log(visit2);
  if (out.visit1.robot != out.visit2.robot)
    throw InputError(visit2, 1, 1,
                     "robot '" + out.visit2.robot + "' but visit 1 was recorded on '" +
                         out.visit1.robot + "'");
  const auto& robot = describe(*parse_robot(out.visit1.robot));
  out.diameter_m = static_cast<double>(robot.diameter_um) / 1e6;
  // The band of visit 1 over the bounding box of both trails (and the band's half width).
  std::int32_t x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;
  for (const auto* trail : {&out.visit1.points, &out.visit2.points})
    for (const auto& p : *trail) {
      x0 = std::min(x0, p.x.raw()), y0 = std::min(y0, p.y.raw());
      x1 = std::max(x1, p.x.raw()), y1 = std::max(y1, p.y.raw());
    }
  const std::int32_t margin = width.raw() + 65536;
  const kernel::FxPoint lo{Fx::from_raw(x0 - margin), Fx::from_raw(y0 - margin)};
  const kernel::FxPoint hi{Fx::from_raw(x1 + margin), Fx::from_raw(y1 + margin)};
  buffon::PheromoneRaster raster(lo, hi, width);
  for (const auto& p : out.visit1.points) raster.lay(p);
  buffon::CrossingDetector detector;
  for (const auto& p : out.visit2.points)
    if (detector.update(raster.at(p))) ++out.bc;
  out.crossings_exact = kernel::count_proper_crossings(out.visit1.points, out.visit2.points);
  const double l1 = static_cast<double>(out.visit1.length_raw) / 65536.0;
  const double l2 = static_cast<double>(out.visit2.length_raw) / 65536.0;
  out.area = buffon::closed_form_area(l1, l2, out.crossings_exact).area;
  out.area_bc = buffon::closed_form_area(l1, l2, out.bc).area;
  return out;
}

RsFromLog rs_from_log(const std::string& path) {
  RsFromLog out;
  out.walk = trail_from_log(path);
  const auto f = buffon::rs_footprint(out.walk.points);
  out.cells = f.cells;
  const double cell = static_cast<double>(f.cell_raw) / 65536.0;
  out.area = static_cast<double>(f.cells) * cell * cell;
  out.diameter_m = static_cast<double>(describe(*parse_robot(out.walk.robot)).diameter_um) / 1e6;
  return out;
}

} // namespace antkit::devices
