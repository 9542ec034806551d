// Recording and replaying the marker-floor robot (stc_floor/record.hpp).
#include <algorithm>
#include <antkit/devices/run_hash.hpp>
#include <antkit/devices/stc_floor/record.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <chrono>
#include <csignal>
#include <sys/stat.h>

namespace antkit::devices::stc_floor {

namespace {

using Clock = std::chrono::steady_clock;

std::string controller_name(stc::Variant v) {
  return std::string(stc::variant_name(v));
}

} // namespace

RecordSummary record(const RecordOptions& o, const RecordProgress& progress) {
  check_controller(o.pilot.controller, "--controller");
  const View view(o.calibration, o.view ? *o.view : default_view(o.calibration));
  struct stat st {};
  if (!o.force && ::stat(o.out.c_str(), &st) == 0)
    throw kernel::InputError(o.out, "the log exists: give another --out, or --force to replace it");
  SerialPort port = SerialPort::open(o.port, o.line, 512);
  StopSignals::Scope signals;
  LinkedRobot robot(std::move(port), o.link);

  LogHeader header;
  header.antkit_version = ANTKIT_DEVICES_VERSION;
  header.robot = "stc-floor";
  header.port = o.port;
  header.baud = o.line.baud;
  header.framing = o.line.framing();
  header.controller = controller_name(o.pilot.controller);
  header.params = {{"start_x", o.pilot.start.x},
                   {"start_y", o.pilot.start.y},
                   {"heading", o.pilot.heading & 3},
                   {"quarter_turn_ms", o.pilot.quarter_turn_ms},
                   {"led_ms", o.pilot.led_ms}};
  header.seed = 0;
  LogWriter log(o.out, header, 0, o.force);

  RecordSummary s;
  s.path.push_back(o.pilot.start);
  RunHash run;
  const auto t0 = Clock::now();
  try {
    const PilotResult r = run_pilot(robot, view, o.pilot, [&](const PilotStep& step) {
      LogRecord rec;
      rec.step = step.step;
      rec.time_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count();
      rec.io = robot.take_io();
      rec.obs = step.obs;
      rec.cmd = step.cmd;
      rec.odo = {step.position.x, step.position.y, step.heading, step.turn_ms};
      rec.state = step.state;
      log.write(rec);
      run.add(rec.step, rec.obs, rec.cmd, rec.state);
      s.steps = step.step + 1;
      if (step.moved) s.path.push_back(step.position);
      if (progress) progress(s.steps);
      if (StopSignals::requested()) throw LinkError(LinkError::Kind::Interrupted, "stop signal");
    });
    s.closed = r.closed;
    s.refused = r.refused;
    s.turn_ms = r.turn_ms;
    s.kind = StopKind::Done;
    s.stop = r.closed ? "done" : r.refused ? "refused: the robot bumped" : "steps";
  } catch (const LinkError& e) {
    s.kind = e.kind() == LinkError::Kind::Interrupted ? StopKind::Interrupted : StopKind::Link;
    s.stop = e.kind() == LinkError::Kind::Interrupted
                 ? std::string("interrupted by ") +
                       (StopSignals::signal() == SIGTERM ? "SIGTERM" : "SIGINT")
                 : "link: " + std::string(link_error_name(e.kind())) + ": " + e.what();
  } catch (const std::exception& e) {
    s.stop = std::string("error: ") + e.what();
  }
  StopSignals::reset();
  auto pending = robot.take_io();
  s.safe_stop = robot.safe_stop();
  auto tail = robot.take_io();
  pending.insert(pending.end(), tail.begin(), tail.end());
  LogStop stop{s.steps, s.stop, std::move(pending)};
  if (!s.safe_stop.empty()) stop.reason += "; safe stop: " + s.safe_stop;
  log.finish(stop);
  const PathCounts counts = path_counts(s.path); // also when the run ended early
  s.covered = counts.covered;
  s.repeats = counts.repeats;
  s.link = robot.stats();
  s.hash = run.value();
  return s;
}

ReplayResult replay_log(LogReader& reader, const std::string& path,
                        std::optional<std::int64_t> until) {
  const LogHeader& header = reader.header();
  const auto variant = stc::parse_variant(header.controller);
  if (!variant || (*variant != stc::Variant::Ant && *variant != stc::Variant::AntEdge))
    throw kernel::InputError(path, 1, 1,
                             "the stc-floor robot runs controller ant or ant-edge, not '" +
                                 header.controller + "'");
  std::int64_t sx = 0, sy = 0, heading = 1;
  int seen = 0;
  for (const auto& [k, v] : header.params) {
    if (k == "start_x")
      sx = v, seen |= 1;
    else if (k == "start_y")
      sy = v, seen |= 2;
    else if (k == "heading")
      heading = v, seen |= 4;
  }
  if (seen != 7 || sx < 0 || sy < 0 || sx > INT32_MAX || sy > INT32_MAX || heading < 0 ||
      heading > 3)
    throw kernel::InputError(path, 1, 1,
                             "the header needs params start_x, start_y (>= 0) and heading (0..3)");
  stc::SubCell pos{static_cast<std::int32_t>(sx), static_cast<std::int32_t>(sy)};
  FloorController controller(*variant, stc::quadrant_of(pos));
  auto h = static_cast<int>(heading);
  return replay_records(reader, until, [&](const LogRecord& r, std::vector<std::int64_t>& cmd) {
    std::optional<Divergence> d;
    std::optional<bool> moved;
    for (std::size_t i = 0; i < r.io.size(); ++i) {
      const auto& x = r.io[i];
      if (!d && x.sent.rfind("C,", 0) == 0 && !x.received.empty() && x.received[0] == 'c' &&
          !decode_frame_header(x.received))
        d = Divergence{r.step, "io[" + std::to_string(i) + "]", "a frame header",
                       "one this build refuses"};
      if (x.sent.rfind("F,", 0) == 0)
        if (const auto f = decode_forward(x.received)) moved = *f.value;
    }
    try {
      controller.step(r.obs, cmd);
    } catch (const kernel::InputError& e) {
      throw kernel::InputError(path, reader.line(), 1, e.what());
    }
    if (compare_fields(r.cmd, cmd, r.step, "cmd", d) && controller.state_hash() != r.state && !d)
      d = Divergence{r.step, "state", kernel::hash_hex(r.state),
                     kernel::hash_hex(controller.state_hash())};
    if (!d && cmd[0] != static_cast<std::int64_t>(stc::Move::Stop)) {
      h = static_cast<int>(cmd[0]);
      if (moved.value_or(false)) pos = stc::step(pos, h);
    }
    const std::vector<std::int64_t> odo{pos.x, pos.y, h};
    compare_fields(std::span(r.odo).first(std::min<std::size_t>(r.odo.size(), 3)), odo, r.step,
                   "odo", d);
    return d;
  });
}

} // namespace antkit::devices::stc_floor
