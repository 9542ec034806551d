// Dead reckoning from logged odometry, and Buffon's measurement from two logged visits
// (odometry.hpp).
#include <algorithm>
#include <antkit/buffon/checkpoints.hpp>
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/buffon/detector.hpp>
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/run_hash.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/segment.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

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

namespace {

// The records of an open log: the trail, the run hash and, with `walls`, the wall encounters of
// its observations (a buffon log's six front readings, the ones the behaviour acted on at each
// step: what the simulator's WallEncounters observes, measurement.hpp).
LoggedTrail read_trail(LogReader& reader, const std::string& path, buffon::WallEncounters* walls) {
  const auto kind = body_of(reader.header().robot);
  if (!kind) throw InputError(path, 1, 1, "unknown robot '" + reader.header().robot + "'");
  LoggedTrail out;
  out.robot = reader.header().robot;
  std::optional<DeadReckoning> dr;
  RunHash run;
  kernel::TraceHash head;
  LogRecord r;
  while (reader.next(r)) {
    if (r.odo.size() != 2)
      throw InputError(path, reader.line(), 1,
                       "a step record without odometry: a trail needs \"odo\" with the two wheels' "
                       "travel");
    if (walls) {
      if (r.obs.size() != 6)
        throw InputError(path, reader.line(), 1,
                         "a buffon step record needs \"obs\" with the six front readings");
      buffon::Observation o;
      for (std::size_t i = 0; i < 6; ++i) {
        if (r.obs[i] < 0 || r.obs[i] > Fx::one_raw)
          throw InputError(path, reader.line(), 1,
                           "a reading must be in [0, 65536] (raw Q15.16 of [0, 1])");
        o.ir[i] = Fx::from_raw(static_cast<std::int32_t>(r.obs[i]));
      }
      walls->observe(o);
    }
    run.add(r.step, r.obs, r.cmd, r.state);
    if (out.head_steps < LoggedTrail::kHead) {
      head.add_i64(r.step).add_i64(r.time_ns).add_u64(r.state);
      for (const auto& x : r.io)
        head.add_u32(static_cast<std::uint32_t>(x.sent.size()))
            .add_bytes(
                std::span(reinterpret_cast<const std::uint8_t*>(x.sent.data()), x.sent.size()))
            .add_u32(static_cast<std::uint32_t>(x.received.size()))
            .add_bytes(std::span(reinterpret_cast<const std::uint8_t*>(x.received.data()),
                                 x.received.size()));
      for (const auto v : r.odo) head.add_i64(v);
      out.head[out.head_steps++] = head.finish();
    }
    const WheelTravel w{r.odo[0], r.odo[1]};
    if (!dr) {
      dr.emplace(describe(*kind), w);
    } else {
      dr->update(w);
    }
    out.points.push_back(dr->position());
    ++out.steps;
  }
  if (out.points.empty())
    throw InputError(path, reader.line() + 1, 1, "the log has no step records");
  out.length_raw = dr->length_raw();
  out.truncated = reader.truncated();
  out.run_hash = run.value();
  return out;
}

// The column (from 1) of "key" in a log's header line, so that a refusal points at the field it
// is about; 1 when it is not there.
std::size_t header_column(const std::string& path, const std::string& key) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::getline(in, line);
  const auto at = line.find('"' + key + '"');
  return at == std::string::npos ? 1 : at + 1;
}

// A Buffon visit's log: controller buffon, and the visit its header says (`expected`).
void check_visit_header(const std::string& path, const LogHeader& h, std::int64_t expected) {
  if (h.controller != "buffon") {
    std::string msg = "controller '" + h.controller +
                      "' is not a Buffon visit: buffon-from-logs measures from the logs of visits "
                      "1 and 2 of controller buffon (antkit record --controller buffon --visit 1, "
                      "then --visit 2)";
    if (h.controller == "rs") msg += "; an rs walk is measured by antkit rs-from-log";
    throw InputError(path, 1, header_column(path, "controller"), msg);
  }
  const auto it = std::find_if(h.params.begin(), h.params.end(),
                               [](const auto& p) { return p.first == "visit"; });
  if (it == h.params.end())
    throw InputError(path, 1, header_column(path, "params"),
                     "the buffon controller's params have no \"visit\": which visit this log "
                     "recorded is unknown");
  if (it->second != expected) {
    const std::string is = std::to_string(it->second), want = std::to_string(expected);
    throw InputError(path, 1, header_column(path, "visit"),
                     "a visit-" + is + " log (its header says \"visit\":" + is +
                         ") given as VISIT" + want + ": the " +
                         (expected == 1 ? "first" : "second") + " argument is the log of visit " +
                         want + " (antkit record ... --visit " + want + ")");
  }
}

} // namespace

LoggedTrail trail_from_log(const std::string& path) {
  LogReader reader(path);
  return read_trail(reader, path, nullptr);
}

RelativeErrors relative_errors(const BuffonEstimate& estimate, double truth) {
  const auto error = [truth](const std::optional<double>& a) {
    return a && truth > 0 ? std::optional<double>((*a - truth) / truth) : std::nullopt;
  };
  return {error(estimate.area_corrected), error(estimate.area_raw)};
}

BuffonEstimate estimate_area(const BuffonCounts& c) {
  // The per-trial report of `antkit buffon --precision` (buffon::precision_estimate), from the
  // logs' counts (two visits: pair_share 1).
  const double l1 = static_cast<double>(c.length1_raw) / 65536.0;
  const double l2 = static_cast<double>(c.length2_raw) / 65536.0;
  const auto cf = buffon::closed_form_area(l1, l2, c.crossings);
  const auto e = buffon::precision_estimate(
      {cf.area, c.crossings, c.variance_visit1, c.variance_visit2, c.wall_encounters, l1 + l2});
  BuffonEstimate out;
  out.area_raw = cf.area;
  out.raw_ci = {e.ci.lower, e.ci.upper};
  out.erosion_factor = e.erosion_factor;
  out.area_corrected = e.area_corrected;
  out.corrected_ci = {e.corrected_ci.lower, e.corrected_ci.upper};
  return out;
}

std::string_view arena_source_name(ArenaSource source) noexcept {
  switch (source) {
  case ArenaSource::logs:
    return "logs";
  case ArenaSource::visit1:
    return "visit1";
  case ArenaSource::visit2:
    return "visit2";
  case ArenaSource::option:
    return "--arena";
  case ArenaSource::none:
    break;
  }
  return "";
}

BuffonFromLogs buffon_from_logs(const std::string& visit1, const std::string& visit2, Fx width,
                                const TrueArena& arena) {
  // One file named twice (also through a link or another path to it).
  std::error_code ec;
  if (std::filesystem::equivalent(visit1, visit2, ec) && !ec)
    throw InputError(visit2, 1, 1,
                     "the same file as VISIT1 (" + visit1 +
                         "): a Buffon measurement needs the logs of two visits");
  LogReader reader1(visit1), reader2(visit2);
  const LogHeader h1 = reader1.header(), h2 = reader2.header();
  // Another controller's walk is not a Buffon visit (rs walks the visit-3 stream for as long as
  // both visits together; wander is another behaviour): refused by its header, before its records
  // are read, so that the message says what the log is rather than what its records lack.
  if (h1.controller != "buffon") check_visit_header(visit1, h1, 1);
  if (h2.controller != "buffon") check_visit_header(visit2, h2, 2);

  BuffonFromLogs out;
  // One counter over both visits in order, as run_trial observes them (its hysteresis carries
  // from the end of visit 1 into visit 2).
  buffon::WallEncounters walls;
  out.visit1 = read_trail(reader1, visit1, &walls);
  out.visit2 = read_trail(reader2, visit2, &walls);
  out.wall_encounters = walls.count();
  // Two logs of one run: the run hash folds every record's step, observation, command and
  // controller state, so equal hashes over equal step counts are the same walk (a copy, perhaps
  // with an edited header). Checked before the visits so that a copy is called what it is.
  if (out.visit1.steps == out.visit2.steps && out.visit1.run_hash == out.visit2.run_hash)
    throw InputError(visit2, 1, 1,
                     "the same run as VISIT1 (" + visit1 + "): both logs have run hash " +
                         kernel::hash_hex(out.visit1.run_hash) + " over " +
                         std::to_string(out.visit1.steps) +
                         " steps; two copies of one run are not two visits");
  // ... or a cut copy: the same first records, times to the nanosecond included.
  if (const std::size_t n = std::min(out.visit1.head_steps, out.visit2.head_steps);
      n > 0 && out.visit1.head[n - 1] == out.visit2.head[n - 1])
    throw InputError(visit2, 1, 1,
                     "the same run as VISIT1 (" + visit1 + "): its first " + std::to_string(n) +
                         " records are visit 1's, times to the nanosecond included (a copy, cut "
                         "short); two copies of one run are not two visits");
  check_visit_header(visit1, h1, 1);
  check_visit_header(visit2, h2, 2);
  // A visit is measured only as it was recorded: its log must replay (every byte, replay.hpp) and
  // end with its stop record (a log cut short is not the visit the robot walked).
  for (const auto* path : {&visit1, &visit2}) {
    const ReplayResult r = replay(*path);
    if (!r.identical && r.first_divergence) {
      const auto& d = *r.first_divergence;
      throw InputError(*path, static_cast<std::size_t>(d.step + 2), 1,
                       "does not replay at step " + std::to_string(d.step) + ", " + d.field +
                           ": the log holds " + d.expected + ", this build derives " + d.actual +
                           " (a visit is measured only as recorded; antkit replay says more)");
    }
    if (!r.complete)
      throw InputError(*path, static_cast<std::size_t>(r.steps + 2), 1,
                       std::string(r.truncated ? "its last line is cut" : "no stop record") +
                           " after " + std::to_string(r.steps) +
                           " steps: the visit's log is not whole (a visit is measured only as "
                           "recorded)");
  }
  if (out.visit1.robot != out.visit2.robot)
    throw InputError(visit2, 1, header_column(visit2, "robot"),
                     "robot '" + out.visit2.robot + "' but visit 1 was recorded on '" +
                         out.visit1.robot + "'");

  // The arena: the headers', which must agree with each other and with arena.spec.
  const auto same_arena = [&](const std::string& a, const std::string& b) {
    return arena.same ? arena.same(a, b) : a == b;
  };
  if (!h1.arena.empty() && !h2.arena.empty() && !same_arena(h1.arena, h2.arena))
    throw InputError(visit2, 1, header_column(visit2, "arena"),
                     "arena '" + h2.arena + "' but visit 1 was recorded in '" + h1.arena +
                         "': both visits of one measurement walk the same arena");
  if (!h1.arena.empty()) {
    out.arena = h1.arena;
    out.arena_source = h2.arena.empty() ? ArenaSource::visit1 : ArenaSource::logs;
  } else if (!h2.arena.empty()) {
    out.arena = h2.arena;
    out.arena_source = ArenaSource::visit2;
  }
  if (!arena.spec.empty()) {
    if (!out.arena.empty() && !same_arena(arena.spec, out.arena))
      throw InputError("arena spec",
                       "'" + arena.spec + "' but the logs' headers name arena '" + out.arena + "'");
    if (out.arena.empty()) out.arena = arena.spec, out.arena_source = ArenaSource::option;
  }

  const auto& robot = describe(*body_of(out.visit1.robot));
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
  // Visit 2's exact crossings step by step into the precision rule's monitor, as run_trial feeds
  // it, for the variance shares at its last check. Its precision only decides when it would have
  // stopped, which a logged visit did not: any valid value gives the same shares.
  const auto& p1 = out.visit1.points;
  buffon::PrecisionMonitor monitor(buffon::kPrecisionDenominator / 10, p1.size() - 1);
  buffon::CrossingCounter counter(p1);
  std::vector<std::uint32_t> crossed;
  const auto& p2 = out.visit2.points;
  for (std::size_t i = 1; i < p2.size(); ++i) {
    crossed.clear();
    if (p1.size() >= 2) counter.add(p2[i - 1], p2[i], &crossed);
    for (const std::uint32_t segment : crossed) monitor.crossing(segment);
    monitor.end_step();
  }
  out.crossings_exact = monitor.count(); // = count_proper_crossings (tests/convergence)
  out.variance_visit1 = monitor.spread().visit1;
  out.variance_visit2 = monitor.spread().visit2;
  const double l1 = static_cast<double>(out.visit1.length_raw) / 65536.0;
  const double l2 = static_cast<double>(out.visit2.length_raw) / 65536.0;
  out.area = buffon::closed_form_area(l1, l2, out.crossings_exact).area;
  out.area_bc = buffon::closed_form_area(l1, l2, out.bc).area;
  out.estimate = estimate_area({out.visit1.length_raw, out.visit2.length_raw, out.crossings_exact,
                                out.variance_visit1, out.variance_visit2, out.wall_encounters});

  if (!out.arena.empty() && arena.area_of) {
    const std::string where =
        out.arena_source == ArenaSource::option
            ? std::string("--arena")
            : (out.arena_source == ArenaSource::visit2 ? visit2 : visit1) + " (header \"arena\")";
    const double truth = arena.area_of(out.arena, where);
    out.area_true = truth;
    const RelativeErrors e = relative_errors(out.estimate, truth);
    out.relative_error = e.corrected;
    out.relative_error_raw = e.raw;
  }
  return out;
}

RsFromLog rs_from_log(const std::string& path) {
  RsFromLog out;
  out.walk = trail_from_log(path);
  const auto f = buffon::rs_footprint(out.walk.points);
  out.cells = f.cells;
  const double cell = static_cast<double>(f.cell_raw) / 65536.0;
  out.area = static_cast<double>(f.cells) * cell * cell;
  out.diameter_m = static_cast<double>(describe(*body_of(out.walk.robot)).diameter_um) / 1e6;
  return out;
}

} // namespace antkit::devices
