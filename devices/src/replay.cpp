// Replay of a hardware log through its controller (replay.hpp).
#include "body.hpp"
#include "logged_link.hpp"

#include <antkit/devices/controllers.hpp>
#include <antkit/devices/device.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>

namespace antkit::devices {

namespace {

using detail::Diverged;
using detail::LoggedLink;

// The stop record against the run: its reason in the words stop_reason() writes, and its safe
// stop re-run on its exchanges. The exchanges of an unfinished step come first; the safe stop is
// the shortest tail, starting with the safe stop's first command, on which safe_stop() replays to
// the verdict the reason states. Returns the difference, if any.
std::optional<Divergence> check_stop(const LogStop& stop, const LineFraming& framing) {
  const Codec& codec = framing.codec();
  const std::string& reason = stop.reason;
  const auto field = [&](std::string what) { return "stop." + std::move(what); };
  // The kind and its words.
  static constexpr std::string_view kinds[] = {"done", "interrupted by SIG", "link: ", "error: "};
  bool known = false;
  for (const auto k : kinds) known = known || reason.rfind(k, 0) == 0;
  if (!known)
    return Divergence{stop.step, field("reason"), "'" + reason + "'",
                      "a reason that starts done, interrupted by SIG..., link: or error:"};
  const std::string may_move = "; " + std::string(kRobotMayBeMoving) + ": ";
  const bool claims_moving = reason.find(may_move) != std::string::npos;
  const bool claims_partial = reason.find("; safe stop: ") != std::string::npos;
  if (reason.rfind("link: disconnected", 0) == 0 && stop.io.empty() && stop.step == 0)
    return std::nullopt; // never connected: nothing was sent
  // Every byte sent in the stop record is a command of this robot, as its codec encodes it.
  for (std::size_t i = 0; i < stop.io.size(); ++i) {
    const auto& sent = stop.io[i].sent;
    if (sent.empty()) continue;
    const auto term = codec.robot().terminator;
    const bool ends = sent.size() > term.size() && sent.substr(sent.size() - term.size()) == term;
    if (!ends || !codec.parse_command(std::string_view(sent).substr(0, sent.size() - term.size())))
      return Divergence{stop.step, field("io[" + std::to_string(i) + "].sent"),
                        "'" + printable(sent) + "'", "a command of this robot"};
  }
  const std::string first = codec.safe_stop().front();
  std::optional<Divergence> last;
  // The live link logs every command it tries, even on a line already gone (link.cpp), so the
  // safe stop always starts with its first command.
  for (std::size_t from = 0; from < stop.io.size(); ++from) {
    if (stop.io[from].sent != first) continue;
    const std::vector<Exchange> tail(stop.io.begin() + static_cast<std::ptrdiff_t>(from),
                                     stop.io.end());
    LoggedLink link(framing, {});
    link.load(tail, stop.step, "stop.io");
    link.set_end_is_failure(true);
    std::vector<Exchange> seen;
    SafeStopResult r;
    try {
      r = detail::safe_stop_steps(link, seen);
    } catch (const Diverged& d) {
      last = d.d;
      continue;
    }
    if (!link.at_end()) { // more after the safe stop: a later start may be the real one
      const std::size_t at = from + link.position();
      last = Divergence{stop.step, field("io[" + std::to_string(at) + "]"),
                        "'" + printable(stop.io[at].sent) + "'",
                        "no further exchange: the safe stop ended before it"};
      continue;
    }
    // The bytes decide the claim where they can: a safe stop acknowledged and read back at zero
    // in the log was one live (the live link reads the same bytes the same way), and one with no
    // acknowledgement of the wheels' command at all left the robot possibly moving. In between
    // (acknowledged, not confirmed) a lost link may explain either words.
    const bool lie = (r.stopped && r.complete && (claims_moving || claims_partial)) ||
                     (!r.acknowledged && !claims_moving);
    if (lie) {
      last = Divergence{stop.step, field("reason"), "'" + reason + "'",
                        r.stopped && r.complete ? "the safe stop acknowledged and read back at 0, 0"
                                                : "no acknowledgement of '" + printable(first) +
                                                      "': " + std::string(kRobotMayBeMoving)};
      continue;
    }
    return std::nullopt;
  }
  if (last) return last;
  return Divergence{stop.step, field("io"), "no safe stop",
                    "the safe stop's '" + printable(first) + "' and its exchanges"};
}

} // namespace

bool compare_fields(std::span<const std::int64_t> expected, std::span<const std::int64_t> actual,
                    std::int64_t step, const char* field, std::optional<Divergence>& out) {
  const std::size_t n = std::max(expected.size(), actual.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (i < expected.size() && i < actual.size() && expected[i] == actual[i]) continue;
    if (!out)
      out = Divergence{step, std::string(field) + "[" + std::to_string(i) + "]",
                       i < expected.size() ? std::to_string(expected[i]) : "(none)",
                       i < actual.size() ? std::to_string(actual[i]) : "(none)"};
    return false;
  }
  return true;
}

ReplayResult replay_records(
    LogReader& reader, std::optional<std::int64_t> until,
    const std::function<std::optional<Divergence>(const LogRecord& r,
                                                  std::vector<std::int64_t>& cmd)>& check,
    const std::function<std::optional<Divergence>(const LogStop& stop)>& check_stop) {
  ReplayResult out;
  out.header = reader.header();
  RunHash run;
  LogRecord r;
  std::vector<std::int64_t> cmd;
  std::int64_t last_t = 0;
  while ((!until || out.steps < *until) && reader.next(r)) {
    // Every device's times never decrease (the recording's steady clock): the records' and the
    // exchanges' (those that have one), each exchange no later than its step's end.
    auto d = r.time_ns < last_t ? std::optional<Divergence>(Divergence{
                                      r.step, "t_ns", std::to_string(r.time_ns),
                                      "a time >= the previous step's " + std::to_string(last_t)})
                                : std::nullopt;
    for (std::size_t k = 0; !d && k < r.io.size(); ++k) {
      const std::int64_t t = r.io[k].t_ns;
      if (t < 0) continue;
      if (t < last_t || t > r.time_ns)
        d = Divergence{r.step, "io[" + std::to_string(k) + "].t", std::to_string(t),
                       "a time in [" + std::to_string(last_t) + ", " + std::to_string(r.time_ns) +
                           "]: after the exchange before it, before the step's end"};
      else if (t > detail::kMaxRunNs)
        d = Divergence{r.step, "io[" + std::to_string(k) + "].t", std::to_string(t),
                       "a time below 2^55 ns (about a year: the longest run reckoned)"};
      last_t = std::max(last_t, t);
    }
    if (!d) d = check(r, cmd);
    last_t = r.time_ns;
    if (d) {
      out.identical = false;
      out.first_divergence = std::move(d);
      break;
    }
    run.add(r.step, r.obs, cmd, r.state);
    ++out.steps;
  }
  // After a divergence the rest is read unchecked, so that the result still says whether the log
  // is whole (its stop record, a cut last line): the divergence stays the finding, and a line the
  // reader refuses after it ends the reading there.
  if (!out.identical && !until) {
    try {
      while (reader.next(r)) {
      }
    } catch (const kernel::InputError&) {
    }
  }
  out.truncated = reader.truncated();
  out.stop = reader.stop();
  out.complete = out.stop.has_value() && !out.truncated;
  out.hash = run.value();
  // The stop record's exchanges come after the last step: their times are no earlier than its end
  // and never decrease (so the last step's t_ns is held from both sides).
  if (out.identical && !until && out.stop) {
    std::int64_t t = last_t;
    for (std::size_t k = 0; k < out.stop->io.size() && out.identical; ++k) {
      const std::int64_t tk = out.stop->io[k].t_ns;
      if (tk < 0) continue;
      if (tk < t || tk > detail::kMaxRunNs) {
        out.identical = false;
        out.first_divergence =
            Divergence{out.stop->step, "stop.io[" + std::to_string(k) + "].t", std::to_string(tk),
                       "a time in [" + std::to_string(t) +
                           ", 2^55]: after the last step's end and the exchange before it"};
      }
      t = std::max(t, tk);
    }
  }
  if (check_stop && out.identical && !until && out.stop)
    if (auto d = check_stop(*out.stop)) {
      out.identical = false;
      out.first_divergence = std::move(d);
    }
  return out;
}

ReplayResult replay(const std::string& path, std::optional<std::int64_t> until) {
  LogReader reader(path);
  return replay(reader, path, until);
}

ReplayResult replay(LogReader& reader, const std::string& path, std::optional<std::int64_t> until) {
  const Device* dev = find_device(reader.header().robot);
  if (dev == nullptr)
    throw kernel::InputError(
        path, 1, 1, "unknown robot '" + reader.header().robot + "': expected " + device_names());
  return dev->replay(reader, path, until);
}

namespace detail {

ReplayResult replay_serial(LogReader& reader, const std::string& path,
                           std::optional<std::int64_t> until, RobotKind kind) {
  const LogHeader& header = reader.header();
  std::unique_ptr<LoggedController> controller;
  try {
    controller = make_controller({header.controller, header.params, header.seed});
  } catch (const kernel::InputError& e) {
    throw kernel::InputError(path, 1, 1, e.message());
  }
  const LineFraming framing(kind);
  const RobotDescription& robot = framing.codec().robot();
  const bool wander = header.controller == "wander";
  // Schema 2 logs begin with the identification at connect (record_loop.hpp); schema 1 logs were
  // written before it and begin with the start's exchanges (log_schema.hpp).
  const bool identified = header.schema >= 2;
  // The same body as record() (body.hpp), over the log's exchanges.
  LoggedLink link(framing, {});
  detail::Body body(link, framing.codec());
  std::vector<std::int64_t> obs;
  std::vector<Exchange> seen;
  return replay_records(
      reader, until,
      [&](const LogRecord& r, std::vector<std::int64_t>& cmd) {
        std::optional<Divergence> d;
        if (!robot.has_odometry)
          for (const Exchange& e : r.io)
            if (!e.sent.empty() && e.t_ns < 0)
              throw kernel::InputError(
                  path, reader.line(), 1,
                  "an exchange without its time: the " + std::string(robot.name) +
                      " has no wheel encoders and its odometry is reckoned from the times its "
                      "commands were sent (a log written before they were logged: re-record "
                      "the run)");
        link.load(r.io, r.step, "io");
        seen.clear();
        try {
          if (r.step == 0) {
            if (identified) body.identify(seen);
            body.start(seen);
          }
          const Proximity readings = body.read_sensors(seen);
          controller->observe(robot, readings, obs);
          if (!compare_fields(r.obs, obs, r.step, "obs", d)) return d;
          try {
            controller->step(robot, r.obs, cmd);
          } catch (const kernel::InputError& e) {
            throw kernel::InputError(path, reader.line(), 1, e.what());
          }
          if (!compare_fields(r.cmd, cmd, r.step, "cmd", d)) return d;
          if (controller->state_hash() != r.state)
            return std::optional<Divergence>(
                Divergence{r.step, "state", kernel::hash_hex(r.state),
                           kernel::hash_hex(controller->state_hash())});
          detail::act(body, wander, cmd, seen);
          const WheelTravel odo = body.odometry(seen);
          const std::int64_t derived[] = {odo.left, odo.right};
          if (!compare_fields(r.odo, derived, r.step, "odo", d)) return d;
        } catch (const Diverged& x) {
          return std::optional<Divergence>(x.d);
        } catch (const WrongRobot& e) {
          return std::optional<Divergence>(
              Divergence{r.step, "io[0].received", std::string(e.what()),
                         "a reply identifying a " + std::string(robot.name) + ": " +
                             std::string(robot.identity)});
        } catch (const LinkError& e) {
          return std::optional<Divergence>(
              Divergence{r.step, "io", "the step's exchanges", std::string(e.what())});
        }
        if (!link.at_end())
          return std::optional<Divergence>(
              Divergence{r.step, "io[" + std::to_string(link.position()) + "]",
                         "'" + printable(r.io[link.position()].sent) + "'",
                         "no further exchange in this step"});
        return d;
      },
      [&](const LogStop& stop) { return check_stop(stop, framing); });
}

} // namespace detail

} // namespace antkit::devices
