// Replay of a hardware log through its controller (replay.hpp).
#include <antkit/devices/controllers.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/devices/stc_floor/record.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>

namespace antkit::devices {

namespace {

// The first (or last) exchange in io that sent `letter` and got a reply the codec accepts, decoded
// by `decode`: a step's observation is its first valid proximity reply (the wanderer's moves read
// the sensors again, once per control period), its odometry the last valid counter reply.
template <class T, class It, class Decode>
std::optional<T> valid_reply(It first, It last, char letter, Decode&& decode) {
  for (; first != last; ++first) {
    if (first->sent.empty() || first->sent[0] != letter) continue;
    auto d = decode(first->received);
    if (d) return *d.value;
  }
  return std::nullopt;
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

ReplayResult replay_records(LogReader& reader, std::optional<std::int64_t> until,
                            const std::function<std::optional<Divergence>(
                                const LogRecord& r, std::vector<std::int64_t>& cmd)>& check) {
  ReplayResult out;
  out.header = reader.header();
  RunHash run;
  LogRecord r;
  std::vector<std::int64_t> cmd;
  while ((!until || out.steps < *until) && reader.next(r)) {
    if (auto d = check(r, cmd)) {
      out.identical = false;
      out.first_divergence = std::move(d);
      break;
    }
    run.add(r.step, r.obs, cmd, r.state);
    ++out.steps;
  }
  out.truncated = reader.truncated();
  out.stop = reader.stop();
  out.hash = run.value();
  return out;
}

ReplayResult replay(const std::string& path, std::optional<std::int64_t> until) {
  LogReader reader(path);
  if (reader.header().robot == "stc-floor") return stc_floor::replay_log(reader, path, until);
  const LogHeader& header = reader.header();
  const auto kind = parse_robot(header.robot);
  if (!kind)
    throw kernel::InputError(path, 1, 1,
                             "unknown robot '" + header.robot +
                                 "': expected khepera, hemisson, epuck or stc-floor");
  std::unique_ptr<LoggedController> controller;
  try {
    controller = make_controller({header.controller, header.params, header.seed});
  } catch (const kernel::InputError& e) {
    throw kernel::InputError(path, 1, 1, e.message());
  }
  const Codec codec(*kind);
  const RobotDescription& robot = codec.robot();
  const char proximity = codec.read_proximity()[0];
  const char counters = robot.has_odometry ? codec.read_odometry()[0] : 0;
  std::vector<std::int64_t> obs, odo;
  return replay_records(reader, until, [&](const LogRecord& r, std::vector<std::int64_t>& cmd) {
    std::optional<Divergence> d;
    const auto readings =
        valid_reply<Proximity>(r.io.begin(), r.io.end(), proximity,
                               [&](std::string_view line) { return codec.decode_proximity(line); });
    if (!readings) {
      d = Divergence{r.step, "io", "a valid proximity reply", "none in the step's exchanges"};
    } else {
      controller->observe(robot, *readings, obs);
      if (compare_fields(r.obs, obs, r.step, "obs", d) && counters != 0) {
        const auto w = valid_reply<WheelPair>(
            r.io.rbegin(), r.io.rend(), counters,
            [&](std::string_view line) { return codec.decode_odometry(line); });
        odo.clear();
        if (w) odo.assign({w->left, w->right});
        compare_fields(r.odo, odo, r.step, "odo", d);
      }
    }
    if (!d) {
      try {
        controller->step(robot, r.obs, cmd);
      } catch (const kernel::InputError& e) {
        throw kernel::InputError(path, reader.line(), 1, e.what());
      }
      if (compare_fields(r.cmd, cmd, r.step, "cmd", d) && controller->state_hash() != r.state)
        d = Divergence{r.step, "state", kernel::hash_hex(r.state),
                       kernel::hash_hex(controller->state_hash())};
    }
    return d;
  });
}

} // namespace antkit::devices
