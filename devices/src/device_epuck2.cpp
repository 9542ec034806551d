// The e-puck2 in binary mode as a device (device.hpp, `--device epuck2`): one binary sequence per
// control step (epuck2.hpp), the record loop, log and replay every device shares, and its own
// link, since a binary reply has no letter, no line and no terminator to classify by.
//
// The sequence link (SequenceLink), one sequence and its reply of a known size, attempt after
// attempt up to `tries` sends:
//   1. after a failed attempt: the back-off, then a resynchronisation -- kResyncZeros 0 bytes sent,
//      and whatever comes back read until the line stays quiet for `backoff_max` (at least 20 ms,
//      at most one timeout), logged as its own exchange: the firmware, which waits forever for a
//      sequence's 0, is back at the top of its loop, and the reply of a sequence that this ended is
//      gone;
//   2. drain: whatever waits on the line cannot be this send's reply (logged with nothing sent);
//   3. send the sequence and read exactly its reply's size within the timeout, then whatever is
//      already waiting after it. The reply is taken when exactly that many bytes came and nothing
//      after them, and the codec validates them (decode_step, decode_pair). A short reply (a cut,
//      a lost terminator, a silent robot), bytes after it (a banner or ASCII text in front of the
//      reply, a late reply) or a reply that does not validate is a fault: the next attempt.
// The same ambiguity as the text robots' link (link.hpp): a late reply that arrives whole, alone,
// after a resend, is taken as the resend's; every request here reads the robot's state (or sets
// given speeds), so it is harmless.
//
// The safe stop (no acknowledgement exists in binary mode, PROTOCOLS.md): a resynchronisation,
// then [-'D' 0 0][-'E'][0] until the speeds read back 0, 0, in up to stop_rounds rounds of tries,
// bounded by stop_within (no send starts after it); a second stop signal cuts it short. The
// wheels are stopped only when read back at 0, 0: acknowledged, stopped and complete are then all
// true, and otherwise all false.
//
// Its log: the same schema (log.hpp); the bytes as JSON strings, one character per byte (binary
// bytes as \u00XX escapes, log_schema.hpp). obs, cmd and state as the e-puck's (controllers.hpp,
// with the e-puck's description: the e-puck2's body is taken as the e-puck1's); odo the step
// counters' travel since the start, unwrapped from their 16 bits.
// Controllers: buffon and rs. The wanderer (several reads per step) is not supported here yet.
#include "emulate_serve.hpp"
#include "registry.hpp"

#include <antkit/devices/controllers.hpp>
#include <antkit/devices/device.hpp>
#include <antkit/devices/epuck2.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <thread>

namespace antkit::devices {

namespace {

using Clock = std::chrono::steady_clock;
using Check = std::string (*)(std::string_view);
// The quiet that ends a resynchronisation's read, at least (a choice: a robot answers within a few
// milliseconds; a host under load, or an emulator between two polls, a little later).
constexpr std::chrono::milliseconds kSettleMin{20};

std::string check_step(std::string_view b) {
  const auto d = epuck2::decode_step(b);
  return d ? std::string() : "byte " + std::to_string(d.error.column) + ": " + d.error.message;
}
std::string check_pair(std::string_view b) {
  const auto d = epuck2::decode_pair(b);
  return d ? std::string() : "byte " + std::to_string(d.error.column) + ": " + d.error.message;
}

std::chrono::milliseconds backoff_for(const LinkOptions& o, std::uint32_t attempt) noexcept {
  auto d = o.backoff;
  for (std::uint32_t k = 1; k < attempt && d < o.backoff_max; ++k) d *= 2;
  return std::min(d, std::max(o.backoff, o.backoff_max));
}

// A divergence found inside the shared steps (a replay): ends the record's check.
struct Diverged {
  Divergence d;
};

class SequenceLink {
public:
  virtual ~SequenceLink() = default;
  [[nodiscard]] virtual const LinkOptions& options() const noexcept = 0;
  // The reply (exactly n bytes that `check` accepts) to `seq`; LinkError as RobotLink::transact.
  virtual std::string transact(const std::string& seq, std::size_t n, Check check,
                               std::vector<Exchange>& io) = 0;
  // Step 1 above, on its own (the start's and the safe stop's first exchange).
  virtual void resync(std::vector<Exchange>& io) = 0;
  virtual void pause(std::chrono::milliseconds d) = 0;
  virtual void set_deadline(std::optional<Clock::time_point> deadline) noexcept = 0;
};

class LiveLink final : public SequenceLink {
public:
  LiveLink(SerialPort port, LinkOptions options) : port_(std::move(port)), options_(options) {
    if (options_.tries == 0) options_.tries = 1;
  }
  [[nodiscard]] const LinkOptions& options() const noexcept override { return options_; }
  [[nodiscard]] const LinkStats& stats() const noexcept { return stats_; }
  void pause(std::chrono::milliseconds d) override { std::this_thread::sleep_for(d); }
  void set_deadline(std::optional<Clock::time_point> deadline) noexcept override {
    deadline_ = deadline;
  }

  void resync(std::vector<Exchange>& io) override {
    io.push_back({epuck2::resync_bytes(), {}, now_ns()});
    const std::size_t at = io.size() - 1;
    ++stats_.exchanges;
    port_.write_all(io[at].sent, options_.timeout);
    const auto settle = std::min(std::max(options_.backoff_max, kSettleMin), options_.timeout);
    const auto end = Clock::now() + options_.timeout;
    while (Clock::now() < end) {
      std::string b = port_.read_bytes(1, settle);
      if (b.empty()) break;
      io[at].received += b;
      io[at].received += port_.read_bytes(65536, std::chrono::milliseconds(0));
    }
    if (!io[at].received.empty()) ++stats_.stale;
  }

  std::string transact(const std::string& seq, std::size_t n, Check check,
                       std::vector<Exchange>& io) override {
    std::string why;
    for (std::uint32_t attempt = 0; attempt < options_.tries; ++attempt) {
      if (attempt > 0) {
        ++stats_.retries;
        std::this_thread::sleep_for(backoff_for(options_, attempt));
      }
      if (StopSignals::requested())
        throw LinkError(LinkError::Kind::Interrupted,
                        port_.name() + ": interrupted by a stop signal");
      if (deadline_ && Clock::now() >= *deadline_)
        throw LinkError(LinkError::Kind::Timeout,
                        port_.name() + ": the safe stop's time is up" +
                            (why.empty() ? std::string() : " (last: " + why + ")"));
      try {
        if (attempt > 0) resync(io);
        drain(io);
      } catch (const LinkError&) {
        io.push_back({seq, {}, now_ns()}); // every attempt logged, as RobotLink does
        ++stats_.exchanges;
        throw;
      }
      io.push_back({seq, {}, now_ns()});
      const std::size_t at = io.size() - 1;
      ++stats_.exchanges;
      port_.write_all(seq, options_.timeout);
      std::string got = port_.read_bytes(n, options_.timeout);
      io[at].received = got;
      if (got.size() < n) {
        ++stats_.timeouts;
        why = got.empty() ? "no reply within " + std::to_string(options_.timeout.count()) + " ms"
                          : "a short reply of " + std::to_string(got.size()) + " of " +
                                std::to_string(n) + " bytes";
        continue;
      }
      const std::string extra = port_.read_bytes(65536, std::chrono::milliseconds(0));
      io[at].received += extra;
      if (!extra.empty()) {
        ++stats_.bad_replies;
        why = std::to_string(extra.size()) + " bytes after the " + std::to_string(n) +
              "-byte reply '" + printable(io[at].received) + "'";
        continue;
      }
      if (std::string e = check(got); !e.empty()) {
        ++stats_.bad_replies;
        why = "reply '" + printable(got) + "': " + e;
        continue;
      }
      return got;
    }
    throw LinkError(LinkError::Kind::Timeout,
                    port_.name() + ": no valid reply to the sequence '" + printable(seq) +
                        "' after " + std::to_string(options_.tries) + " tries: " + why);
  }

private:
  void drain(std::vector<Exchange>& io) {
    std::string bytes;
    for (std::string b; !(b = port_.read_bytes(65536, std::chrono::milliseconds(0))).empty();)
      bytes += b;
    if (bytes.empty()) return;
    ++stats_.stale;
    io.push_back({{}, std::move(bytes), now_ns()});
  }
  [[nodiscard]] std::int64_t now_ns() const noexcept {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - options_.origin)
        .count();
  }
  SerialPort port_;
  LinkOptions options_;
  LinkStats stats_;
  std::optional<Clock::time_point> deadline_;
};

// A replay's link: the live link's decisions re-run on the logged bytes.
class LoggedLink final : public SequenceLink {
public:
  void load(const std::vector<Exchange>& io, std::int64_t step, std::string field) {
    io_ = &io;
    k_ = 0;
    step_ = step;
    field_ = std::move(field);
  }
  void set_end_is_failure(bool on) noexcept { end_is_failure_ = on; }
  [[nodiscard]] std::size_t position() const noexcept { return k_; }
  [[nodiscard]] bool at_end() const noexcept { return k_ >= io_->size(); }
  [[nodiscard]] const LinkOptions& options() const noexcept override { return options_; }
  void pause(std::chrono::milliseconds) override {}
  void set_deadline(std::optional<Clock::time_point>) noexcept override {}

  void resync(std::vector<Exchange>&) override { (void)expect(epuck2::resync_bytes()); }

  std::string transact(const std::string& seq, std::size_t n, Check check,
                       std::vector<Exchange>&) override {
    for (std::uint32_t attempt = 0;; ++attempt) {
      if (attempt > 0) (void)expect(epuck2::resync_bytes());
      const Exchange& e = expect(seq);
      if (e.received.size() == n && check(e.received).empty()) return e.received;
    }
  }

private:
  const Exchange& expect(const std::string& sent) {
    while (k_ < io_->size() && (*io_)[k_].sent.empty()) ++k_; // drained bytes
    if (k_ >= io_->size()) {
      if (end_is_failure_)
        throw LinkError(LinkError::Kind::Timeout, "the log ends before a valid reply");
      throw Diverged{{step_, field_ + "[" + std::to_string(k_) + "]", "(no exchange)",
                      "a send of '" + printable(sent) + "'"}};
    }
    const Exchange& e = (*io_)[k_];
    if (e.sent != sent) {
      if (end_is_failure_)
        throw LinkError(LinkError::Kind::Timeout, "no valid reply (the log goes on)");
      throw Diverged{{step_, field_ + "[" + std::to_string(k_) + "].sent",
                      "'" + printable(e.sent) + "'", "'" + printable(sent) + "'"}};
    }
    ++k_;
    return e;
  }
  LinkOptions options_;
  const std::vector<Exchange>* io_ = nullptr;
  std::size_t k_ = 0;
  std::int64_t step_ = 0;
  std::string field_;
  bool end_is_failure_ = false;
};

// The robot's half of a step, over either link: the same code records and replays.
class Body {
public:
  void start(SequenceLink& link, std::vector<Exchange>& io) {
    link.resync(io); // the firmware's state at connect is unknown; its banner may be waiting
    const auto reply =
        link.transact(epuck2::start_sequence(), epuck2::kPairReplySize, check_pair, io);
    const WheelPair w = *epuck2::decode_pair(reply).value;
    total_[0] = base_[0] = w.left;
    total_[1] = base_[1] = w.right;
  }
  // The step's sequence (the last command's speeds, the proximity and the counters).
  Proximity read(SequenceLink& link, std::vector<Exchange>& io) {
    const auto reply =
        link.transact(epuck2::step_sequence(left_, right_), epuck2::kStepReplySize, check_step, io);
    const epuck2::StepReply r = *epuck2::decode_step(reply).value;
    total_[0] = epuck2::unwrap(total_[0], r.left);
    total_[1] = epuck2::unwrap(total_[1], r.right);
    return r.proximity;
  }
  void command(std::span<const std::int64_t> cmd) {
    left_ = static_cast<std::int32_t>(cmd[2]);
    right_ = static_cast<std::int32_t>(cmd[3]);
  }
  [[nodiscard]] std::array<std::int64_t, 2> odometry() const noexcept {
    return {total_[0] - base_[0], total_[1] - base_[1]};
  }

private:
  std::int32_t left_ = 0, right_ = 0;
  std::int64_t total_[2] = {0, 0}, base_[2] = {0, 0};
};

SafeStopResult stop_steps(SequenceLink& link, std::vector<Exchange>& io) {
  SafeStopResult out;
  const auto& o = link.options();
  const auto rounds = std::max<std::uint32_t>(1, o.stop_rounds);
  const auto deadline = Clock::now() + o.stop_within;
  link.set_deadline(deadline);
  const auto notice = [&](const std::string& what) {
    if (o.on_stop_notice) o.on_stop_notice(what);
  };
  const auto time_up = [&] { return Clock::now() >= deadline; };
  bool cut = false, gone = false, late = false;
  std::string why = "no reply";
  const auto failed = [&](const LinkError& e) {
    why = e.what();
    if (e.kind() == LinkError::Kind::Interrupted) cut = true;
    if (e.kind() == LinkError::Kind::Disconnected) gone = true;
    if (time_up()) late = true;
  };
  try {
    link.resync(io);
  } catch (const LinkError& e) {
    failed(e);
  }
  for (std::uint32_t round = 0; round < rounds && !cut && !gone && !late; ++round) {
    if (round > 0) {
      if (time_up()) {
        late = true;
        break;
      }
      notice("the wheels not read back at 0, 0 yet (" + why + "); round " +
             std::to_string(round + 1) + " of " + std::to_string(rounds) +
             " (Ctrl-C again to give up)");
      link.pause(o.backoff_max);
    }
    try {
      const auto reply =
          link.transact(epuck2::stop_sequence(), epuck2::kPairReplySize, check_pair, io);
      const WheelPair w = *epuck2::decode_pair(reply).value;
      if (w.left == 0 && w.right == 0) {
        out.stopped = out.acknowledged = out.complete = true;
        break;
      }
      why =
          "the robot reads back speeds " + std::to_string(w.left) + ", " + std::to_string(w.right);
    } catch (const LinkError& e) {
      failed(e);
    }
  }
  link.set_deadline(std::nullopt);
  if (!out.stopped) {
    out.failure = "wheels not read back at 0, 0 (" + why + ")";
    if (cut) out.failure += "; cut short by a stop signal";
    if (late) {
      const std::string gave_up =
          "gave up after " + std::to_string(o.stop_within.count()) + " ms (--stop-within)";
      out.failure += "; " + gave_up;
      notice("the safe stop " + gave_up);
    }
  }
  return out;
}

class Epuck2Session final : public Session {
public:
  Epuck2Session(SerialPort port, const LinkOptions& link,
                std::unique_ptr<LoggedController> controller, std::chrono::nanoseconds period)
      : link_(std::move(port), link), controller_(std::move(controller)), period_(period) {}

  void start(std::vector<Exchange>& io) override { body_.start(link_, io); }

  bool step(LogRecord& rec, std::vector<Exchange>& io) override {
    if (period_.count() > 0) {
      std::this_thread::sleep_until(next_);
      next_ = Clock::now() + period_;
    }
    const RobotDescription& robot = describe(RobotKind::Epuck);
    const Proximity readings = body_.read(link_, io);
    controller_->observe(robot, readings, rec.obs);
    controller_->step(robot, rec.obs, rec.cmd);
    body_.command(rec.cmd);
    const auto odo = body_.odometry();
    rec.odo.assign(odo.begin(), odo.end());
    rec.state = controller_->state_hash();
    return true;
  }

  SafeStopResult safe_stop(std::vector<Exchange>& io) noexcept override {
    try {
      return stop_steps(link_, io);
    } catch (const std::exception& e) {
      SafeStopResult out;
      out.failure = std::string("the safe stop failed: ") + e.what();
      return out;
    }
  }
  [[nodiscard]] LinkStats stats() const override { return link_.stats(); }

private:
  LiveLink link_;
  Body body_;
  std::unique_ptr<LoggedController> controller_;
  std::chrono::nanoseconds period_;
  Clock::time_point next_{};
};

// The stop record against the run (as replay.cpp's check_stop for the text robots): its reason's
// kind, and its safe stop re-run on its exchanges from a resynchronisation on; a stop read back
// at 0, 0 in the bytes may not claim the robot may be moving, and one never read back must.
std::optional<Divergence> check_stop(const LogStop& stop) {
  const std::string& reason = stop.reason;
  const auto field = [&](std::string what) { return "stop." + std::move(what); };
  static constexpr std::string_view kinds[] = {"done", "interrupted by SIG", "link: ", "error: "};
  bool known = false;
  for (const auto k : kinds) known = known || reason.rfind(k, 0) == 0;
  if (!known)
    return Divergence{stop.step, field("reason"), "'" + reason + "'",
                      "a reason that starts done, interrupted by SIG..., link: or error:"};
  const bool claims_moving =
      reason.find("; " + std::string(kRobotMayBeMoving) + ": ") != std::string::npos;
  if (reason.rfind("link: disconnected", 0) == 0 && stop.io.empty() && stop.step == 0)
    return std::nullopt; // never connected: nothing was sent
  std::optional<Divergence> last;
  for (std::size_t from = 0; from < stop.io.size(); ++from) {
    if (stop.io[from].sent != epuck2::resync_bytes()) continue;
    const std::vector<Exchange> tail(stop.io.begin() + static_cast<std::ptrdiff_t>(from),
                                     stop.io.end());
    LoggedLink link;
    link.load(tail, stop.step, "stop.io");
    link.set_end_is_failure(true);
    std::vector<Exchange> seen;
    SafeStopResult r;
    try {
      r = stop_steps(link, seen);
    } catch (const Diverged& d) {
      last = d.d;
      continue;
    }
    if (!link.at_end()) {
      const std::size_t at = from + link.position();
      last = Divergence{stop.step, field("io[" + std::to_string(at) + "]"),
                        "'" + printable(stop.io[at].sent) + "'",
                        "no further exchange: the safe stop ended before it"};
      continue;
    }
    if (r.stopped == claims_moving) {
      last = Divergence{stop.step, field("reason"), "'" + reason + "'",
                        r.stopped ? "the wheels read back at 0, 0"
                                  : "never read back at 0, 0: " + std::string(kRobotMayBeMoving)};
      continue;
    }
    return std::nullopt;
  }
  if (last) return last;
  return Divergence{stop.step, field("io"), "no safe stop",
                    "a resynchronisation, then '" + printable(epuck2::stop_sequence()) + "'"};
}

ReplayResult replay_epuck2(LogReader& reader, const std::string& path,
                           std::optional<std::int64_t> until) {
  const LogHeader& header = reader.header();
  if (header.controller == "wander")
    throw kernel::InputError(path, 1, 1, "the epuck2 does not run the wanderer (yet)");
  std::unique_ptr<LoggedController> controller;
  try {
    controller = make_controller({header.controller, header.params, header.seed});
  } catch (const kernel::InputError& e) {
    throw kernel::InputError(path, 1, 1, e.message());
  }
  const RobotDescription& robot = describe(RobotKind::Epuck);
  LoggedLink link;
  Body body;
  std::vector<std::int64_t> obs;
  std::vector<Exchange> seen;
  return replay_records(
      reader, until,
      [&](const LogRecord& r, std::vector<std::int64_t>& cmd) -> std::optional<Divergence> {
        std::optional<Divergence> d;
        link.load(r.io, r.step, "io");
        try {
          if (r.step == 0) body.start(link, seen);
          const Proximity readings = body.read(link, seen);
          controller->observe(robot, readings, obs);
          if (!compare_fields(r.obs, obs, r.step, "obs", d)) return d;
          try {
            controller->step(robot, r.obs, cmd);
          } catch (const kernel::InputError& e) {
            throw kernel::InputError(path, reader.line(), 1, e.what());
          }
          if (!compare_fields(r.cmd, cmd, r.step, "cmd", d)) return d;
          if (controller->state_hash() != r.state)
            return Divergence{r.step, "state", kernel::hash_hex(r.state),
                              kernel::hash_hex(controller->state_hash())};
          body.command(cmd);
          const auto odo = body.odometry();
          if (!compare_fields(r.odo, odo, r.step, "odo", d)) return d;
        } catch (const Diverged& x) {
          return x.d;
        } catch (const LinkError& e) {
          return Divergence{r.step, "io", "the step's exchanges", std::string(e.what())};
        }
        if (!link.at_end())
          return Divergence{r.step, "io[" + std::to_string(link.position()) + "]",
                            "'" + printable(r.io[link.position()].sent) + "'",
                            "no further exchange in this step"};
        return d;
      },
      [&](const LogStop& stop) { return check_stop(stop); });
}

class Epuck2Device final : public Device {
public:
  [[nodiscard]] std::string_view name() const noexcept override { return "epuck2"; }
  // PROTOCOLS.md: 115200 8N1 (UART3 to the radio module; over USB the setting does nothing).
  [[nodiscard]] LineSettings line() const noexcept override { return {115200, 8, 1, Parity::None}; }

  [[nodiscard]] PreparedRun prepare(const RecordOptions& o) const override {
    const std::string others = " is an option of the stc-floor robot";
    if (!o.map.empty()) throw kernel::InputError("floor map", others);
    if (o.start) throw kernel::InputError("start sub-cell", others);
    if (!o.calibration.empty()) throw kernel::InputError("camera calibration", others);
    ControllerSpec spec =
        make_spec(o.controller.name, o.controller.seed, o.controller.params, "controller");
    if (spec.name == "wander")
      throw kernel::InputError("controller",
                               "the epuck2 runs buffon and rs; the wanderer is not supported yet");
    (void)make_controller(spec);
    PreparedRun run;
    run.header.robot = "epuck2";
    run.header.controller = spec.name;
    run.header.params = spec.params;
    run.header.seed = spec.seed;
    run.header.arena = o.arena;
    run.line = o.line ? *o.line : line();
    run.steps = o.steps ? *o.steps : 1000;
    const std::chrono::nanoseconds period =
        o.period ? std::chrono::nanoseconds(*o.period) : std::chrono::nanoseconds(0);
    run.connect = [period, spec](SerialPort port, const LinkOptions& link) {
      return std::make_unique<Epuck2Session>(std::move(port), link, make_controller(spec), period);
    };
    return run;
  }

  [[nodiscard]] ReplayResult replay(LogReader& reader, const std::string& path,
                                    std::optional<std::int64_t> until) const override {
    return replay_epuck2(reader, path, until);
  }

  [[nodiscard]] EmulateReport
  emulate(const EmulateOptions& o,
          const std::function<void(const std::string&)>& ready) const override {
    detail::refuse_floor_options(o);
    if (o.pace) throw kernel::InputError("pacing", "is not supported by the epuck2 emulator yet");
    const EmulatorOptions options = detail::emulator_options(o);
    std::optional<TcpListener> listener = detail::listen_for(o);
    epuck2::Emulator emulator(o.walls, options);
    return detail::serve_emulator(emulator, listener, ready, emulator.body());
  }
};

} // namespace

namespace detail {

const Device& epuck2_device() noexcept {
  static const Epuck2Device device;
  return device;
}

} // namespace detail

} // namespace antkit::devices
