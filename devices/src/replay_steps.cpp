// The replay of a run of the serial robots' controllers (replay_steps.hpp).
#include "replay_steps.hpp"

#include <antkit/devices/controllers.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>

namespace antkit::devices::detail {

ReplayResult replay_controller_run(
    LogReader& reader, const std::string& path, std::optional<std::int64_t> until,
    const ReplayedRobot& robot,
    const std::function<std::optional<Divergence>(const LogStop& stop)>& check_stop) {
  const LogHeader& header = reader.header();
  std::unique_ptr<LoggedController> controller;
  try {
    controller = make_controller({header.controller, header.params, header.seed});
  } catch (const kernel::InputError& e) {
    throw kernel::InputError(path, 1, 1, e.message());
  }
  const bool wander = header.controller == "wander";
  // Schema 2 logs begin with the identification at connect (record_loop.hpp); schema 1 logs were
  // written before it and begin with the start's exchanges (log_schema.hpp).
  const bool identified = header.schema >= 2;
  const RobotDescription& description = robot.robot;
  LoggedLink& link = robot.link;
  ReplayedBody& body = robot.body;
  std::vector<std::int64_t> obs;
  std::vector<Exchange> seen;
  return replay_records_with_attempts(
      reader, until, &link,
      [&](const LogRecord& r, std::size_t line, std::span<const Attempt> attempts,
          std::vector<std::int64_t>& cmd) -> std::optional<Divergence> {
        std::optional<Divergence> d;
        body.check_record(r, path, line);
        link.load(r.io, r.step, "io", attempts);
        seen.clear();
        try {
          if (r.step == 0) {
            if (identified) body.identify(seen);
            body.start(seen);
          }
          const Proximity readings = body.read_sensors(seen);
          controller->observe(description, readings, obs);
          if (!compare_fields(r.obs, obs, r.step, "obs", d)) return d;
          try {
            controller->step(description, r.obs, cmd);
          } catch (const kernel::InputError& e) {
            throw kernel::InputError(path, line, 1, e.what());
          }
          if (!compare_fields(r.cmd, cmd, r.step, "cmd", d)) return d;
          if (controller->state_hash() != r.state)
            return Divergence{r.step, "state", kernel::hash_hex(r.state),
                              kernel::hash_hex(controller->state_hash())};
          body.act(wander, cmd, seen);
          const auto odo = body.odometry(seen);
          if (!compare_fields(r.odo, odo, r.step, "odo", d)) return d;
        } catch (const Diverged& x) {
          return x.d;
        } catch (const WrongRobot& e) {
          return Divergence{r.step, robot.wrong_robot_field, std::string(e.what()),
                            robot.wrong_robot_expected};
        } catch (const LinkError& e) {
          return Divergence{r.step, "io", "the step's exchanges", std::string(e.what())};
        }
        if (!link.at_end())
          return Divergence{r.step, "io[" + std::to_string(link.position()) + "]",
                            "'" + printable(r.io[link.position()].sent) + "'",
                            "no further exchange in this step"};
        return d;
      },
      check_stop);
}

std::optional<Divergence> check_stop_kind(const LogStop& stop) {
  const std::string& reason = stop.reason;
  static constexpr std::string_view kinds[] = {"done", "interrupted by SIG", "link: ", "error: "};
  bool known = false;
  for (const auto k : kinds) known = known || reason.rfind(k, 0) == 0;
  if (!known)
    return Divergence{stop.step, "stop.reason", "'" + reason + "'",
                      "a reason that starts done, interrupted by SIG..., link: or error:"};
  return std::nullopt;
}

std::optional<Divergence> check_safe_stop_tails(
    const LogStop& stop, const Framing& framing, const std::string& first,
    const std::function<std::optional<Divergence>(const SafeStopResult&)>& verdict,
    const std::string& none_expected) {
  std::optional<Divergence> last;
  // The live link logs every command it tries, even on a line already gone (link.cpp), so the
  // safe stop always starts with its first exchange.
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
      r = safe_stop_steps(link, seen);
    } catch (const Diverged& d) {
      last = d.d;
      continue;
    }
    if (!link.at_end()) { // more after the safe stop: a later start may be the real one
      const std::size_t at = from + link.position();
      last = Divergence{stop.step, "stop.io[" + std::to_string(at) + "]",
                        "'" + printable(stop.io[at].sent) + "'",
                        "no further exchange: the safe stop ended before it"};
      continue;
    }
    if (auto lie = verdict(r)) {
      last = std::move(lie);
      continue;
    }
    return std::nullopt;
  }
  if (last) return last;
  return Divergence{stop.step, "stop.io", "no safe stop", none_expected};
}

} // namespace antkit::devices::detail
