// The e-puck2 in binary mode as a device (device.hpp, `--device epuck2`): one binary sequence per
// control step (epuck2.hpp), driven through its binary framing (epuck2::SequenceFraming,
// framing.hpp) by the link, the safe stop, the record loop, the log and the replay every device
// shares (link.hpp, logged_link.hpp).
//
// What the framing makes of the shared link: a reply is read as exactly the size its sequence
// asks for, and bytes after it are a fault; after a failed attempt the link resynchronises
// (kResyncZeros 0 bytes sent, whatever comes back read until the line stays quiet, logged as its
// own exchange: the firmware, which waits forever for a sequence's 0, is back at the top of its
// loop, and the reply of a sequence that this ended is gone); replies are validated by the codec
// (the proximity readings below 4096, the rest by size).
//
// The safe stop (no acknowledgement exists in binary mode, PROTOCOLS.md): the framing's stop plan,
// a resynchronisation, then [-'D' 0 0][-'E'][0] until the speeds read back 0, 0, in up to
// stop_rounds rounds of tries, bounded by stop_within (no send starts after it); a second stop
// signal cuts it short. The wheels are stopped only when read back at 0, 0: acknowledged, stopped
// and complete are then all true, and otherwise all false.
//
// Its log: the same schema (log.hpp); the bytes as JSON strings, one character per byte (binary
// bytes as \u00XX escapes, log_schema.hpp). obs, cmd and state as the e-puck's (controllers.hpp,
// with the e-puck's description: the e-puck2's body is taken as the e-puck1's); odo the step
// counters' travel since the start, unwrapped from their 16 bits.
// Controllers: buffon, rs and the wanderer (its move: Body::act below).
//
// Identification at connect (record_loop.hpp, "First, at connect"): binary mode has no version
// request (PROTOCOLS.md, binary mode: "the version (V) and reset (R) exist only as ASCII
// commands"), so after a resynchronisation (the firmware at the top of its loop, the banner read
// off) the ASCII `V` goes, ended by a single CR as binary follows, and its reply is read as lines
// (SequenceFraming::reading_for): the `v,` line is the reply, held to epuck2::identifies (major
// version 2 or more: `v,Version 2.0 January 2018 GCtronic`; an e-puck1 answers 1.x), and the
// lines before it (the banner) are read past; its second line (`HW version: ...`) is read by the
// start's resynchronisation. A robot that answers another version, or only lines of another
// shape, is refused as the text robots are (exit 2, no log). Logs of schema 2 hold the exchanges
// in step 0 and replay checks them; schema-1 logs have none.
#include "body.hpp"
#include "emulate_serve.hpp"
#include "logged_link.hpp"
#include "registry.hpp"
#include "replay_steps.hpp"

#include <antkit/devices/controllers.hpp>
#include <antkit/devices/device.hpp>
#include <antkit/devices/epuck2.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <thread>

namespace antkit::devices {

namespace {

using Clock = std::chrono::steady_clock;
using detail::LoggedLink;

// The robot's half of a step, over either link: the same code records and replays.
class Body {
public:
  void identify(CommandLink& link, std::vector<Exchange>& io) {
    link.resync(io); // the firmware's state at connect is unknown; its banner may be waiting
    identify_by_version(link, std::string(epuck2::kVersionRequest), epuck2::identifies, "epuck2",
                        epuck2::kIdentity, io);
  }
  void start(CommandLink& link, std::vector<Exchange>& io) {
    link.resync(io); // the firmware's state at connect is unknown; its banner may be waiting
    const auto reply = link.transact(epuck2::start_sequence(), io);
    const WheelPair w = *epuck2::decode_pair(reply).value;
    total_[0] = base_[0] = w.left;
    total_[1] = base_[1] = w.right;
  }
  // The step's sequence (the last command's speeds, the proximity and the counters).
  Proximity read(CommandLink& link, std::vector<Exchange>& io) {
    return read_at(link, left_, right_, io);
  }
  // The command carried out. buffon and rs: the speeds the next step's sequence sends. The
  // wanderer: its move (body.hpp, WanderMove, as every robot's), one step sequence per control
  // period at the move's speeds (`pace` waits for the period; the counters come back in the same
  // round trip, so the first read is taken as the wheels start), until the right wheel has
  // travelled the move's target or 2 x its nominal periods have passed, then one at 0, 0.
  void act(CommandLink& link, bool wander, std::span<const std::int64_t> cmd,
           std::vector<Exchange>& io, const std::function<void()>& pace) {
    if (!wander) {
      left_ = static_cast<std::int32_t>(cmd[2]);
      right_ = static_cast<std::int32_t>(cmd[3]);
      return;
    }
    const auto action = static_cast<uniform::Action>(cmd[0]);
    if (action == uniform::Action::Wait || action == uniform::Action::Stop) return;
    const detail::WanderMove move = detail::wander_move_plan(describe(RobotKind::Epuck), action);
    const std::int64_t start = total_[1];
    for (std::int64_t k = 0; k < 2 * move.periods; ++k) {
      pace();
      (void)read_at(link, move.left, move.right, io);
      if (move.done(std::abs(total_[1] - start))) break;
    }
    (void)read_at(link, 0, 0, io);
    left_ = right_ = 0;
  }
  [[nodiscard]] std::array<std::int64_t, 2> odometry() const noexcept {
    return {total_[0] - base_[0], total_[1] - base_[1]};
  }

private:
  Proximity read_at(CommandLink& link, std::int32_t left, std::int32_t right,
                    std::vector<Exchange>& io) {
    const auto reply = link.transact(epuck2::step_sequence(left, right), io);
    const epuck2::StepReply r = *epuck2::decode_step(reply).value;
    total_[0] = epuck2::unwrap(total_[0], r.left);
    total_[1] = epuck2::unwrap(total_[1], r.right);
    return r.proximity;
  }
  std::int32_t left_ = 0, right_ = 0;
  std::int64_t total_[2] = {0, 0}, base_[2] = {0, 0};
};

class Epuck2Session final : public Session {
public:
  Epuck2Session(SerialPort port, const LinkOptions& link,
                std::unique_ptr<LoggedController> controller, bool wander,
                std::chrono::nanoseconds period)
      : link_(std::move(port), std::make_shared<const epuck2::SequenceFraming>(), link),
        controller_(std::move(controller)), wander_(wander), period_(period) {}

  void identify(std::vector<Exchange>& io) override { body_.identify(link_, io); }
  void start(std::vector<Exchange>& io) override { body_.start(link_, io); }

  bool step(LogRecord& rec, std::vector<Exchange>& io) override {
    const auto pace = [this] {
      if (period_.count() > 0) {
        std::this_thread::sleep_until(next_);
        next_ = Clock::now() + period_;
      }
    };
    pace();
    const RobotDescription& robot = describe(RobotKind::Epuck);
    const Proximity readings = body_.read(link_, io);
    controller_->observe(robot, readings, rec.obs);
    controller_->step(robot, rec.obs, rec.cmd);
    body_.act(link_, wander_, rec.cmd, io, pace);
    const auto odo = body_.odometry();
    rec.odo.assign(odo.begin(), odo.end());
    rec.state = controller_->state_hash();
    return true;
  }

  SafeStopResult safe_stop(std::vector<Exchange>& io) noexcept override {
    return devices::safe_stop(link_, io);
  }
  [[nodiscard]] LinkStats stats() const override { return link_.stats(); }

private:
  RobotLink link_;
  Body body_;
  std::unique_ptr<LoggedController> controller_;
  bool wander_;
  std::chrono::nanoseconds period_;
  Clock::time_point next_{};
};

// The stop record against the run (as replay.cpp's check_stop for the text robots,
// replay_steps.hpp): its reason's kind, and its safe stop re-run on its exchanges from a
// resynchronisation on; a stop read back at 0, 0 in the bytes may not claim the robot may be
// moving, and one never read back must.
std::optional<Divergence> check_stop(const LogStop& stop) {
  const std::string& reason = stop.reason;
  if (auto d = detail::check_stop_kind(stop)) return d;
  const bool claims_moving =
      reason.find("; " + std::string(kRobotMayBeMoving) + ": ") != std::string::npos;
  if (reason.rfind("link: disconnected", 0) == 0 && stop.io.empty() && stop.step == 0)
    return std::nullopt; // never connected: nothing was sent
  const epuck2::SequenceFraming framing;
  return detail::check_safe_stop_tails(
      stop, framing, epuck2::resync_bytes(),
      [&](const SafeStopResult& r) -> std::optional<Divergence> {
        if (r.stopped != claims_moving) return std::nullopt;
        return Divergence{stop.step, "stop.reason", "'" + reason + "'",
                          r.stopped ? "the wheels read back at 0, 0"
                                    : "never read back at 0, 0: " + std::string(kRobotMayBeMoving)};
      },
      "a resynchronisation, then '" + printable(epuck2::stop_sequence()) + "'");
}

// The e-puck2's body (Body above) over the log's exchanges: the same code as its session's.
class ReplayedEpuck2Body final : public detail::ReplayedBody {
public:
  explicit ReplayedEpuck2Body(LoggedLink& link) : link_(link) {}
  void identify(std::vector<Exchange>& io) override { body_.identify(link_, io); }
  void start(std::vector<Exchange>& io) override { body_.start(link_, io); }
  Proximity read_sensors(std::vector<Exchange>& io) override { return body_.read(link_, io); }
  void act(bool wander, std::span<const std::int64_t> cmd, std::vector<Exchange>& io) override {
    body_.act(link_, wander, cmd, io, [] {});
  }
  std::array<std::int64_t, 2> odometry(std::vector<Exchange>& io) override {
    (void)io;
    return body_.odometry();
  }

private:
  LoggedLink& link_;
  Body body_;
};

ReplayResult replay_epuck2(LogReader& reader, const std::string& path,
                           std::optional<std::int64_t> until) {
  const epuck2::SequenceFraming framing;
  LoggedLink link(framing, {});
  ReplayedEpuck2Body body(link);
  return detail::replay_controller_run(
      reader, path, until,
      {describe(RobotKind::Epuck), link, body, "io",
       "a reply identifying an epuck2: " + std::string(epuck2::kIdentity)},
      [&](const LogStop& stop) { return check_stop(stop); });
}

class Epuck2Device final : public Device {
public:
  [[nodiscard]] std::string_view name() const noexcept override { return "epuck2"; }
  // The e-puck's body: its axle and wheel taken as the e-puck1's (PROTOCOLS.md).
  [[nodiscard]] const RobotDescription* body() const noexcept override {
    return &describe(RobotKind::Epuck);
  }
  // PROTOCOLS.md: 115200 8N1 (UART3 to the radio module; over USB the setting does nothing).
  [[nodiscard]] LineSettings line() const noexcept override {
    return {epuck2::kBaud, 8, 1, Parity::None};
  }

  [[nodiscard]] std::span<const DeclaredOption> options() const noexcept override {
    static constexpr DeclaredOption kOptions[] = {
        detail::kRecordArena,
        detail::record_period("0, as fast as the link allows"),
        detail::kEmulateArena,
        {.name = "fault",
         .word = "fault",
         .use = OptionUse::Emulate,
         .type = OptionType::Texts,
         .label = "F",
         .what = "a fault the emulator injects: those of the serial robots (delay=P:MS, "
                 "garbage=P, drop=P, cut=P, disconnect=N, silent=N) and unterminated=P, a "
                 "sequence's lost 0"},
        detail::kEmulatePace,
        detail::kEmulateListen,
    };
    return kOptions;
  }

  [[nodiscard]] PreparedRun prepare_run(const RecordOptions& o) const override {
    ControllerSpec spec =
        make_spec(o.controller.name, o.controller.seed, o.controller.params, "controller");
    (void)make_controller(spec);
    PreparedRun run;
    run.header.robot = "epuck2";
    run.header.controller = spec.name;
    run.header.params = spec.params;
    run.header.seed = spec.seed;
    run.header.arena = o.device_options.text("arena").value_or("");
    run.line = o.line ? *o.line : line();
    run.steps = o.steps ? *o.steps : 1000;
    const std::chrono::nanoseconds period =
        std::chrono::milliseconds(o.device_options.integer("period").value_or(0));
    const bool wander = spec.name == "wander";
    run.connect = [period, spec, wander](SerialPort port, const LinkOptions& link) {
      return std::make_unique<Epuck2Session>(std::move(port), link, make_controller(spec), wander,
                                             period);
    };
    return run;
  }

  [[nodiscard]] ReplayResult replay(LogReader& reader, const std::string& path,
                                    std::optional<std::int64_t> until) const override {
    return replay_epuck2(reader, path, until);
  }

  [[nodiscard]] EmulateReport
  serve(const EmulateOptions& o,
        const std::function<void(const std::string&)>& ready) const override {
    const EmulatorOptions options = detail::emulator_options(o);
    std::optional<TcpListener> listener = detail::listen_for(o);
    epuck2::Emulator emulator(o.walls, options);
    return detail::serve_emulator(emulator, listener, ready, emulator.body());
  }
};

} // namespace

namespace detail {

ANTKIT_DEVICE(50, epuck2_device) {
  static const Epuck2Device device;
  return device;
}

} // namespace detail

} // namespace antkit::devices
