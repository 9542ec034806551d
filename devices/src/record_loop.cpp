// The robot bodies under the controller contract, and record() (record_loop.hpp).
#include "body.hpp"

#include <algorithm>
#include <antkit/buffon/world.hpp>
#include <antkit/devices/device.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/controllers.hpp>
#include <csignal>
#include <optional>
#include <sys/stat.h>
#include <thread>

namespace antkit::devices {

namespace {

using Clock = std::chrono::steady_clock;
using kernel::Fx;
__extension__ using i128 = __int128;

// pi / 4 as Q15.16, for the wanderer's 45-degree turn.
constexpr Fx kQuarterPi = Fx::from_raw(51472);

// The wanderer's moves by the plan (body.hpp), one sensor read per control period.
void wander_move(detail::Body& body, uniform::Action action, std::vector<Exchange>& io) {
  const detail::WanderMove move = detail::wander_move_plan(body.robot(), action);
  const WheelTravel start = body.odometry(io);
  body.set_wheels(move.left, move.right, io);
  for (std::int64_t k = 0; k < 2 * move.periods; ++k) {
    body.read_sensors(io);
    const WheelTravel now = body.odometry(io);
    if (move.done(std::abs(now.right - start.right))) break;
  }
  body.set_wheels(0, 0, io);
}

std::string signal_name(int sig) {
  switch (sig) {
  case SIGINT:
    return "SIGINT";
  case SIGTERM:
    return "SIGTERM";
  case SIGHUP:
    return "SIGHUP";
  case SIGQUIT:
    return "SIGQUIT";
  default:
    return "signal " + std::to_string(sig);
  }
}

} // namespace

namespace detail {

Body::Body(CommandLink& link, const Codec& codec, std::chrono::nanoseconds period)
    : link_(link), codec_(codec), robot_(codec.robot()), period_(period) {}

void Body::identify(std::vector<Exchange>& io) {
  if (robot_.identifies == nullptr) return;
  identify_by_version(
      link_, codec_.version(), [&](std::string_view reply) { return codec_.identifies(reply); },
      robot_.name, robot_.identity, io);
}

void Body::start(std::vector<Exchange>& io) {
  if (!robot_.has_odometry) return;
  if (robot_.odometry_set != 0) {
    link_.transact(codec_.set_odometry(0, 0), io);
    return;
  }
  std::string bytes;
  const WheelPair w = odometry_of(link_.transact_view(codec_.read_odometry(), io, bytes));
  baseline_ = {w.left, w.right};
}

// The link returns only a reply its framing validated: the text robots' by decode_reply() of the
// request, whose values for the proximity and odometry requests are decode_proximity()'s and
// decode_odometry()'s (held equal by test_protocol's property, for every serial robot). A replay's
// link keeps the values of the replies it judged itself (reply_fields()): those are used, not
// decoded again.
Proximity Body::proximity_of(std::string_view reply) const {
  if (const Fields* f = link_.reply_fields();
      f != nullptr && f->letter == reply_letter('N') && f->count >= 8) {
    Proximity p;
    std::copy_n(f->values.begin(), 8, p.raw.begin());
    return p;
  }
  return *codec_.decode_proximity(reply).value;
}

WheelPair Body::odometry_of(std::string_view reply) const {
  if (const Fields* f = link_.reply_fields();
      f != nullptr && f->letter == reply_letter(robot_.odometry_read) && f->count == 2)
    return {f->values[0], f->values[1]};
  return *codec_.decode_odometry(reply).value;
}

Proximity Body::read_sensors(std::vector<Exchange>& io) {
  // One sensor read per control period at most.
  if (period_.count() > 0) {
    std::this_thread::sleep_until(next_read_);
    next_read_ = Clock::now() + period_;
  }
  std::string bytes; // a replay's link reads the reply in place (transact_view)
  const std::string_view reply = link_.transact_view(codec_.read_proximity(), io, bytes);
  // The robot senses where the wheels took it by the time the read was sent.
  if (!robot_.has_odometry) reckon_until(link_.last_send_ns());
  return proximity_of(reply);
}

void Body::set_wheels(std::int32_t left, std::int32_t right, std::vector<Exchange>& io) {
  link_.transact(codec_.set_speed(left, right), io);
  // The old speeds were in force until the acknowledged command was sent (a choice: an earlier
  // attempt whose reply was lost may have reached the robot sooner; the difference is one timeout
  // at most, and only on a faulty line).
  if (!robot_.has_odometry) reckon_until(link_.last_send_ns());
  left_ = left;
  right_ = right;
}

WheelTravel Body::odometry(std::vector<Exchange>& io) {
  if (!robot_.has_odometry) {
    // travel2 over one model step, times ns in force, over the model step's ns: the step is
    // kDefaultSpeed x diameter micrometres at speed_full x speed_unit micrometres per second
    // (model_period), so ns per step = um_per_step x 1e9 / um_per_s, both x 2^16.
    const i128 um_per_step = i128{buffon::kDefaultSpeed.raw()} * robot_.diameter_um;
    const i128 um_per_s = i128{robot_.speed_full} * robot_.speed_unit_um_s * 65536;
    const i128 den = um_per_step * 1000000000 * 2 * 65536;
    return {static_cast<std::int64_t>(weighted_.left * um_per_s / den),
            static_cast<std::int64_t>(weighted_.right * um_per_s / den)};
  }
  std::string bytes;
  const WheelPair w = odometry_of(link_.transact_view(codec_.read_odometry(), io, bytes));
  return {w.left - baseline_.left, w.right - baseline_.right};
}

void Body::reckon_until(std::int64_t t_ns) {
  if (t_ns < 0) throw std::logic_error("a send without its time");
  if (t_ns > kMaxRunNs)
    throw std::runtime_error("the run is longer than 2^55 ns (about 13 months), the longest "
                             "whose travel a robot without encoders reckons");
  if (reckoned_ns_ >= 0 && t_ns > reckoned_ns_) {
    const Travel2 one =
        step_travel2(robot_, buffon::kDefaultSpeed, from_wheel_command(robot_, left_),
                     from_wheel_command(robot_, right_), true);
    weighted_.left += one.left * (t_ns - reckoned_ns_);
    weighted_.right += one.right * (t_ns - reckoned_ns_);
  }
  reckoned_ns_ = std::max(reckoned_ns_, t_ns);
}

WanderMove wander_move_plan(const RobotDescription& robot, uniform::Action action) {
  WanderMove m;
  const std::int32_t s = std::max<std::int32_t>(1, robot.speed_full / 2);
  m.left = m.right = s;
  // Targets: one cell = half a body diameter; 45 degrees = pi/4 * wheel_base / 2 per wheel.
  m.target_um = robot.diameter_um / 2;
  if (action == uniform::Action::TurnLeft || action == uniform::Action::TurnRight) {
    m.target_um =
        (Fx::from_raw(static_cast<std::int32_t>(robot.wheel_base_um / 2)) * kQuarterPi).raw();
    m.left = action == uniform::Action::TurnLeft ? -s : s;
    m.right = -m.left;
  }
  // Nominal periods (for a robot without encoders, and a bound for those with them): the travel
  // of one period at speed s by the motion model.
  const Travel2 one = step_travel2(robot, buffon::kDefaultSpeed, from_wheel_command(robot, m.left),
                                   from_wheel_command(robot, m.right), true);
  const i128 per_period = (one.right < 0 ? -one.right : one.right) / (2 * 65536);
  m.periods =
      per_period > 0 ? static_cast<std::int64_t>((m.target_um + per_period - 1) / per_period) : 1;
  // The odometry in nanometres per unit: encoder pulses, or the Hemisson's reckoned micrometres.
  m.unit_nm = robot.has_odometry ? robot.odometry_pulse_nm : 1000;
  return m;
}

bool WanderMove::done(std::int64_t travelled_units) const noexcept {
  return i128{travelled_units} * unit_nm >= i128{target_um} * 1000;
}

void act(Body& body, bool wander, std::span<const std::int64_t> cmd, std::vector<Exchange>& io) {
  if (wander) {
    const auto action = static_cast<uniform::Action>(cmd[0]);
    if (action != uniform::Action::Wait && action != uniform::Action::Stop)
      wander_move(body, action, io);
    return;
  }
  body.set_wheels(static_cast<std::int32_t>(cmd[2]), static_cast<std::int32_t>(cmd[3]), io);
}

} // namespace detail

void identify_by_version(CommandLink& link, const std::string& request,
                         const std::function<bool(std::string_view reply)>& identifies,
                         std::string_view name, std::string_view identity,
                         std::vector<Exchange>& io) {
  const std::size_t first = io.size();
  const auto refuse = [&](const std::string& reply) {
    const std::string as = identified_as(request, reply);
    throw WrongRobot("the robot answers '" + printable(reply) + "' to '" + printable(request) +
                     "', not as --device " + std::string(name) + " does (" + std::string(identity) +
                     ")" +
                     (as.empty() ? std::string() : "; it answers as --device " + as + " does"));
  };
  std::string reply;
  try {
    reply = link.transact(request, io);
  } catch (const LinkError& e) {
    if (e.kind() != LinkError::Kind::Timeout) throw;
    // Every try answered, with whole lines that are not a reply to the version request: a robot of
    // another protocol (an error line; the Webots relay's bare LF). The last such line is named.
    std::string last;
    bool every = true, any = false;
    for (std::size_t k = first; k < io.size(); ++k) {
      const Exchange& x = io[k];
      if (x.sent != request) continue; // drained bytes, a resynchronisation
      any = true;
      const std::string_view r = x.received;
      if (r.empty() || r.back() != '\n') {
        every = false; // silence or a partial line: a link fault, not an answer
        break;
      }
      const auto from = r.size() >= 2 ? r.rfind('\n', r.size() - 2) : std::string_view::npos;
      last = std::string(r.substr(from == std::string_view::npos ? 0 : from + 1));
    }
    if (!any || !every) throw;
    refuse(last);
  }
  if (!identifies(reply)) refuse(reply);
}

std::chrono::nanoseconds model_period(const RobotDescription& robot) {
  // A simulator step moves kDefaultSpeed body diameters at unit speed; the robot covers that at
  // speed_full x speed_unit_um_s micrometres per second.
  const i128 um_per_step = i128{buffon::kDefaultSpeed.raw()} * robot.diameter_um; // x 2^16
  const i128 um_per_s = i128{robot.speed_full} * robot.speed_unit_um_s * 65536;   // x 2^16
  if (um_per_s <= 0) return std::chrono::nanoseconds(0);
  return std::chrono::nanoseconds(
      static_cast<std::int64_t>((um_per_step * 1000000000 + um_per_s / 2) / um_per_s));
}

std::chrono::nanoseconds default_period(const RobotDescription& robot) {
  return robot.has_odometry ? std::chrono::nanoseconds(0) : model_period(robot);
}

std::string_view stop_kind_name(StopKind kind) noexcept {
  switch (kind) {
  case StopKind::Done:
    return "done";
  case StopKind::Interrupted:
    return "interrupted";
  case StopKind::Link:
    return "link";
  case StopKind::Error:
    return "error";
  }
  return "?";
}

std::string stop_reason(StopKind kind, const std::string& detail, const SafeStopResult& safe) {
  std::string out(stop_kind_name(kind));
  if (!detail.empty()) out += (kind == StopKind::Interrupted ? " by " : ": ") + detail;
  if (!safe.stopped)
    out += std::string("; ") + std::string(kRobotMayBeMoving) + ": " + safe.failure;
  else if (!safe.complete)
    out += "; safe stop: " + safe.failure;
  return out;
}

RecordSummary record(const RecordOptions& options, const RecordProgress& progress) {
  if (options.steps && (*options.steps < 0 || *options.steps > 1000000000))
    throw kernel::InputError("steps", "expected a whole number in [0, 1000000000]");
  const Device& dev = device(options.device, "device");
  PreparedRun run = dev.prepare(options);
  // A log is never replaced by accident: a mistyped name must not lose a recorded visit.
  check_new_log(options.out, options.force);
  // The log is not the robot's own line (--force would otherwise write the log into the port).
  // stat(), not std::filesystem::equivalent(), which refuses to compare two character devices.
  struct stat out_st {
  }, port_st{};
  if (!is_tcp_port(options.port) && ::stat(options.out.c_str(), &out_st) == 0 &&
      ::stat(options.port.c_str(), &port_st) == 0 && out_st.st_dev == port_st.st_dev &&
      out_st.st_ino == port_st.st_ino)
    throw kernel::InputError(options.out, "is the robot's port (--port " + options.port +
                                              "): the log must be another file");

  LogHeader header = std::move(run.header);
  header.antkit_version = ANTKIT_DEVICES_VERSION;
  header.port = options.port;
  header.baud = run.line.baud;
  header.framing = run.line.framing();

  RecordSummary summary;
  // The port first: a bad --port is bad input and must leave no log behind. A link that cannot be
  // reached (a TCP relay that refuses) is a link failure: its log says so, and the run exits 1.
  std::optional<SerialPort> port;
  try {
    port.emplace(run.max_line > 0 ? SerialPort::open(options.port, run.line, run.max_line)
                                  : SerialPort::open(options.port, run.line));
  } catch (const LinkError& e) {
    LogWriter log(options.out, header, 0, options.force);
    summary.kind = StopKind::Link;
    summary.connected = false;
    summary.safe_stop = {.stopped = true, .complete = true, .failure = {}}; // never driven by us
    summary.stop =
        stop_reason(StopKind::Link, std::string(link_error_name(e.kind())) + ": " + e.what(),
                    summary.safe_stop);
    try {
      log.finish({0, summary.stop, {}});
    } catch (const LogWriteError& w) {
      summary.log_error = w.what();
    }
    return summary;
  }
  StopSignals::Scope signals;
  // One clock for the run: the records' t_ns and every exchange's time count from t0.
  const auto t0 = Clock::now();
  LinkOptions link_options = options.link;
  link_options.origin = t0;
  const std::unique_ptr<Session> session = run.connect(std::move(*port), link_options);
  std::vector<Exchange> pending; // exchanges of the step under way
  // The robot identified before the log is opened (record_loop.hpp, "First, at connect"): another
  // robot is a wrong --device, bad input with no log; only the version request was sent to it.
  std::optional<LinkError> unidentified;
  try {
    session->identify(pending);
  } catch (const WrongRobot& e) {
    throw kernel::InputError("device",
                             options.device + " at " + options.port + ": " + e.what() +
                                 " (only the identification was sent: the robot was not driven)");
  } catch (const LinkError& e) {
    unidentified = e; // the link failed: a run that stopped at once, with its log
  }
  LogWriter log(options.out, header, options.sync_every, options.force);

  RunHash hash;
  LogRecord rec;
  std::string detail;
  try {
    if (unidentified) throw *unidentified;
    session->start(pending);
    bool more = true;
    for (std::int64_t step = 0; more && step < run.steps; ++step) {
      if (StopSignals::requested()) throw LinkError(LinkError::Kind::Interrupted, "stop signal");
      more = session->step(rec, pending);
      rec.step = step;
      rec.time_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count();
      rec.io.swap(pending);
      pending.clear();
      log.write(rec);
      hash.add(rec.step, rec.obs, rec.cmd, rec.state);
      summary.steps = step + 1;
      if (progress) progress(summary.steps, run.steps);
    }
    detail = session->failure();
    summary.completed = detail.empty();
    summary.kind = detail.empty() ? StopKind::Done : StopKind::Error;
  } catch (const LinkError& e) {
    if (e.kind() == LinkError::Kind::Interrupted) {
      summary.kind = StopKind::Interrupted;
      summary.signal = StopSignals::signal();
      detail = signal_name(summary.signal);
    } else {
      summary.kind = StopKind::Link;
      detail = std::string(link_error_name(e.kind())) + ": " + e.what();
    }
  } catch (const std::exception& e) {
    summary.kind = StopKind::Error;
    detail = e.what();
  }
  // The safe stop: the signal that ended the run is taken first (the stop reason already says it
  // came), so that only a second one cuts the stop short (link.hpp).
  StopSignals::reset();
  if (summary.kind == StopKind::Interrupted && link_options.on_stop_notice)
    link_options.on_stop_notice("interrupted by " + detail +
                                ": stopping the robot (Ctrl-C again to give up)");
  summary.safe_stop = session->safe_stop(pending);
  StopSignals::reset();
  summary.stop = stop_reason(summary.kind, detail, summary.safe_stop);
  // A log that cannot take its stop record (the disk filled during the run) keeps what it has: the
  // summary says so, and the run is not a success.
  try {
    log.finish({summary.steps, summary.stop, std::move(pending)});
  } catch (const LogWriteError& e) {
    summary.log_error = e.what();
  }
  summary.link = session->stats();
  summary.hash = hash.value();
  summary.device_report = session->report();
  return summary;
}

} // namespace antkit::devices
