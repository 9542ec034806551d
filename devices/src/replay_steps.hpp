#pragma once
// The replay of a run of the serial robots' controllers (controllers.hpp: buffon, rs, wander),
// written once for every device that records them (internal): the text robots (replay.cpp,
// replay_serial) and the e-puck2 in binary mode (device_epuck2.cpp). A device gives only what
// differs: its body over the log's exchanges (ReplayedBody: its codec, its framing, its
// decoding), where a refused identification diverges, and its stop record's safe stop
// (check_safe_stop_tails, from where its safe stop starts). The checks and their words are here.
#include "logged_link.hpp"

#include <antkit/devices/log.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/robot.hpp>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace antkit::devices::detail {

// A robot's half of a step, as its recording ran it, over a LoggedLink: each call reads the
// exchanges it needs from the link the device built it on (a divergence is thrown as Diverged, a
// wrong identity as WrongRobot, a link failure as LinkError).
class ReplayedBody {
public:
  virtual ~ReplayedBody() = default;
  // Before the record's exchanges are read: kernel::InputError(path, line, ...) for a record this
  // robot's replay cannot check (the Hemisson's exchanges without their times).
  virtual void check_record(const LogRecord& r, const std::string& path, std::size_t line) const {
    (void)r, (void)path, (void)line;
  }
  virtual void identify(std::vector<Exchange>& io) = 0;
  virtual void start(std::vector<Exchange>& io) = 0;
  virtual Proximity read_sensors(std::vector<Exchange>& io) = 0;
  virtual void act(bool wander, std::span<const std::int64_t> cmd, std::vector<Exchange>& io) = 0;
  // The odometry after the step, as its record's odo holds it.
  virtual std::array<std::int64_t, 2> odometry(std::vector<Exchange>& io) = 0;
};

struct ReplayedRobot {
  const RobotDescription& robot; // the controllers' robot (its scales and sensors)
  LoggedLink& link;              // the link `body` reads from
  ReplayedBody& body;
  // Where a refused identification diverges, and what was expected there.
  std::string wrong_robot_field;
  std::string wrong_robot_expected;
};

// A record's check (replay_records(), replay.hpp), with the record's attempts (LoggedLink::
// read_attempt of each exchange) when they were read ahead, else empty.
using CheckRecord = std::function<std::optional<Divergence>(const LogRecord& r, std::size_t line,
                                                            std::span<const Attempt> attempts,
                                                            std::vector<std::int64_t>& cmd)>;

// replay_records() (replay.hpp), whose reading thread, when it reads ahead, also reads each
// record's exchanges as `link` would (its read_attempt: a pure function of an exchange and the
// framing) for check() to load them with: the same replay, its reply-side reading moved off the
// checking thread. `link` null: none read ahead.
ReplayResult replay_records_with_attempts(
    LogReader& reader, std::optional<std::int64_t> until, const LoggedLink* link,
    const CheckRecord& check,
    const std::function<std::optional<Divergence>(const LogStop& stop)>& check_stop);

// The log's controller rebuilt from its header (kernel::InputError(path, 1, 1, ...) when it cannot
// be), then every record through replay_records(): at step 0 the identification (schema 2 and
// later, log_schema.hpp) and the start; then the sensor read, the observation, the command, the
// state hash, the command carried out, the odometry, and no exchange left over; the stop record
// through `check_stop`.
ReplayResult replay_controller_run(
    LogReader& reader, const std::string& path, std::optional<std::int64_t> until,
    const ReplayedRobot& robot,
    const std::function<std::optional<Divergence>(const LogStop& stop)>& check_stop);

// The stop record's reason, as stop_reason() words it: a divergence unless it starts with a kind.
std::optional<Divergence> check_stop_kind(const LogStop& stop);

// The stop record's safe stop re-run on its exchanges: the exchanges of an unfinished step come
// first, so each tail that starts with an exchange that sent `first` is replayed through
// safe_stop_steps() over `framing`, until one replays to its end and `verdict` (the device's:
// whether the reason's words match what the bytes say of the stop) finds nothing. Else the last
// tail's divergence, or, when no tail starts, "no safe stop" expecting `none_expected`.
std::optional<Divergence> check_safe_stop_tails(
    const LogStop& stop, const Framing& framing, const std::string& first,
    const std::function<std::optional<Divergence>(const SafeStopResult&)>& verdict,
    const std::string& none_expected);

} // namespace antkit::devices::detail
