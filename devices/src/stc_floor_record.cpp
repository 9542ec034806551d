// Recording and replaying the marker-floor robot (stc_floor/record.hpp).
#include <algorithm>
#include <antkit/devices/run_hash.hpp>
#include <antkit/devices/stc_floor/record.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <chrono>
#include <csignal>

namespace antkit::devices::stc_floor {

namespace {

using Clock = std::chrono::steady_clock;

std::string controller_name(stc::Variant v) {
  return std::string(stc::variant_name(v));
}

// Every exchange of a floor step as the link makes them (link.hpp): a command of the robot's set,
// encoded as this build encodes it; its reply valid, or else resent at once (V, L and C only: F
// and R are never resent, a resent move would move twice); a frame's valid header may be resent
// too (its bytes, not logged, failed their CRC); the step's last exchange answered.
std::optional<Divergence> check_floor_io(const LogRecord& r) {
  const auto at = [&](std::size_t i, const char* what) {
    return "io[" + std::to_string(i) + "]." + what;
  };
  for (std::size_t i = 0; i < r.io.size(); ++i) {
    const auto& x = r.io[i];
    const auto f = x.sent.empty() || x.sent.back() != '\r'
                       ? Decoded<Fields>{}
                       : scan_command(std::string_view(x.sent).substr(0, x.sent.size() - 1), false);
    std::string again;
    bool valid = false, resendable = true;
    if (f && f.value->count == 0 && f.value->letter == 'V') {
      again = version_command();
      valid = x.received.size() >= 3 && x.received[0] == 'v' &&
              x.received.substr(x.received.size() - 2) == "\r\n";
    } else if (f && f.value->count == 1) {
      const std::int32_t v = f.value->values[0];
      try {
        switch (f.value->letter) {
        case 'F':
          again = forward_command(v);
          valid = bool(decode_forward(x.received));
          resendable = false;
          break;
        case 'R':
          again = rotate_command(v);
          valid = bool(decode_ack(x.received, 'r'));
          resendable = false;
          break;
        case 'L':
          if (v == 0 || v == 1) again = leds_command(v == 1);
          valid = bool(decode_ack(x.received, 'l'));
          break;
        case 'C':
          if (v == 0 || v == 1) again = capture_command(v == 1);
          valid = bool(decode_frame_header(x.received));
          break;
        default:
          break;
        }
      } catch (const kernel::InputError&) { // a value out of the command's range
        again.clear();
      }
    }
    if (again.empty() || again != x.sent)
      return Divergence{r.step, at(i, "sent"), "'" + printable(x.sent) + "'",
                        again.empty() ? "a command of the floor robot's set"
                                      : "'" + printable(again) + "'"};
    const bool resent = i + 1 < r.io.size() && r.io[i + 1].sent == x.sent;
    const bool frame = f.value->letter == 'C';
    if (resent && !resendable)
      return Divergence{r.step, at(i + 1, "sent"), "'" + printable(x.sent) + "' again",
                        "no resend of a move"};
    if (!valid && !resent)
      return Divergence{r.step, at(i, "received"), "'" + printable(x.received) + "'",
                        i + 1 < r.io.size() ? "a valid reply, or a resend of the command next"
                                            : "a valid reply ending the step"};
    if (valid && resent && !frame)
      return Divergence{r.step, at(i + 1, "sent"), "'" + printable(x.sent) + "' again",
                        "no resend after a valid reply"};
  }
  return std::nullopt;
}

// The pilot lights the LEDs for the header's led_ms before a move exactly when the step marks
// (cmd[1]): every F of the step says so.
std::optional<Divergence> check_marking(const LogRecord& r, std::optional<std::int64_t> led_ms,
                                        std::span<const std::int64_t> cmd) {
  if (!led_ms || cmd.size() < 2) return std::nullopt;
  const std::string want = forward_command(static_cast<std::int32_t>(cmd[1] != 0 ? *led_ms : 0));
  for (std::size_t i = 0; i < r.io.size(); ++i)
    if (r.io[i].sent.rfind("F,", 0) == 0 && r.io[i].sent != want)
      return Divergence{r.step, "io[" + std::to_string(i) + "].sent",
                        "'" + printable(r.io[i].sent) + "'", "'" + printable(want) + "'"};
  return std::nullopt;
}

} // namespace

RecordSummary record(const RecordOptions& o, const RecordProgress& progress) {
  check_controller(o.pilot.controller, "--controller");
  const View view(o.calibration, o.view ? *o.view : default_view(o.calibration));
  check_new_log(o.out, o.force);
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
  std::optional<std::int64_t> led_ms;
  int seen = 0;
  for (const auto& [k, v] : header.params) {
    if (k == "start_x")
      sx = v, seen |= 1;
    else if (k == "start_y")
      sy = v, seen |= 2;
    else if (k == "heading")
      heading = v, seen |= 4;
    else if (k == "led_ms")
      led_ms = v;
  }
  if (seen != 7 || sx < 0 || sy < 0 || sx > INT32_MAX || sy > INT32_MAX || heading < 0 ||
      heading > 3)
    throw kernel::InputError(path, 1, 1,
                             "the header needs params start_x, start_y (>= 0) and heading (0..3)");
  stc::SubCell pos{static_cast<std::int32_t>(sx), static_cast<std::int32_t>(sy)};
  FloorController controller(*variant, stc::quadrant_of(pos));
  auto h = static_cast<int>(heading);
  std::int64_t last_t = 0;
  return replay_records(reader, until, [&](const LogRecord& r, std::vector<std::int64_t>& cmd) {
    std::optional<Divergence> d;
    if (r.time_ns < last_t)
      return std::optional<Divergence>(
          Divergence{r.step, "t_ns", std::to_string(r.time_ns),
                     "a time >= the previous step's " + std::to_string(last_t)});
    last_t = r.time_ns;
    if (auto bad = check_floor_io(r)) return bad;
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
    if (!d) d = check_marking(r, led_ms, cmd);
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
