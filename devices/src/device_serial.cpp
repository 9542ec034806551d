// The serial robots of paper 000's family as devices (device.hpp): khepera, khepera-webots,
// hemisson and epuck, each a RobotDescription (robot.hpp) driven by the body (body.hpp) over a
// RobotLink (link.hpp) under a controller of controllers.hpp.
//
// A session's step (record_loop.hpp, "One control step"): the proximity read, the controller, the
// command carried out, the odometry. Its record: obs and cmd as controllers.hpp writes them, odo
// the wheel travel [left, right] (counters less the start's baseline; the Hemisson's commanded
// travel in micrometres), state the controller's state hash.
#include "body.hpp"
#include "emulate_serve.hpp"
#include "registry.hpp"

#include <antkit/devices/device.hpp>
#include <antkit/devices/emulator.hpp>
#include <antkit/kernel/input_error.hpp>
#include <array>
#include <optional>

namespace antkit::devices {

namespace {

class SerialSession final : public Session {
public:
  SerialSession(SerialPort port, RobotKind robot, const LinkOptions& link,
                std::unique_ptr<LoggedController> controller, bool wander,
                std::chrono::nanoseconds period)
      : framing_(std::make_shared<const LineFraming>(robot)),
        link_(std::move(port), framing_, link), body_(link_, framing_->codec(), period),
        controller_(std::move(controller)), wander_(wander) {}

  void identify(std::vector<Exchange>& io) override { body_.identify(io); }
  void start(std::vector<Exchange>& io) override { body_.start(io); }

  bool step(LogRecord& rec, std::vector<Exchange>& io) override {
    const Proximity readings = body_.read_sensors(io);
    controller_->observe(body_.robot(), readings, rec.obs);
    controller_->step(body_.robot(), rec.obs, rec.cmd);
    detail::act(body_, wander_, rec.cmd, io);
    const WheelTravel odo = body_.odometry(io);
    rec.odo.assign({odo.left, odo.right});
    rec.state = controller_->state_hash();
    return true;
  }

  SafeStopResult safe_stop(std::vector<Exchange>& io) noexcept override {
    return devices::safe_stop(link_, io);
  }
  [[nodiscard]] LinkStats stats() const override { return link_.stats(); }

private:
  std::shared_ptr<const LineFraming> framing_;
  RobotLink link_;
  detail::Body body_;
  std::unique_ptr<LoggedController> controller_;
  bool wander_;
};

} // namespace

class SerialDevice final : public Device {
public:
  explicit SerialDevice(const RobotDescription& robot)
      : description_(robot), robot_(RobotKind::of(robot)) {}
  [[nodiscard]] std::string_view name() const noexcept override { return description_.name; }
  [[nodiscard]] LineSettings line() const noexcept override { return description_.line; }
  [[nodiscard]] const RobotDescription* body() const noexcept override { return &description_; }
  [[nodiscard]] std::chrono::milliseconds reply_timeout() const noexcept override {
    return description_.reply_timeout;
  }

  [[nodiscard]] std::span<const DeclaredOption> options() const noexcept override {
    // One list for the robots that read their wheel counters, one for those that do not (their
    // period's default is the motion model's).
    static constexpr DeclaredOption kFault{
        .name = "fault",
        .word = "fault",
        .use = OptionUse::Emulate,
        .type = OptionType::Texts,
        .label = "F",
        .what = "a fault the emulator injects: delay=P:MS, garbage=P, drop=P, cut=P (P per "
                "command), disconnect=N (after N commands) or silent=N (no answer after N "
                "commands)"};
    static constexpr DeclaredOption kCounted[] = {
        detail::kRecordArena,  detail::record_period("0, as fast as the link allows"),
        detail::kEmulateArena, kFault,
        detail::kEmulatePace,  detail::kEmulateListen,
    };
    static constexpr DeclaredOption kModelled[] = {
        detail::kRecordArena,  detail::record_period("the motion model's period, 112 ms"),
        detail::kEmulateArena, kFault,
        detail::kEmulatePace,  detail::kEmulateListen,
    };
    if (description_.has_odometry) return kCounted;
    return kModelled;
  }

  [[nodiscard]] PreparedRun prepare_run(const RecordOptions& o) const override {
    ControllerSpec spec =
        make_spec(o.controller.name, o.controller.seed, o.controller.params, "controller");
    (void)make_controller(spec); // refuses a spec it cannot build, before anything is opened
    const RobotDescription& robot = description_;
    PreparedRun run;
    run.header.robot = std::string(robot.name);
    run.header.controller = spec.name;
    run.header.params = spec.params;
    run.header.seed = spec.seed;
    run.header.arena = o.device_options.text("arena").value_or("");
    run.line = o.line ? *o.line : line();
    run.steps = o.steps ? *o.steps : 1000;
    const auto period_ms = o.device_options.integer("period");
    const std::chrono::nanoseconds period =
        period_ms ? std::chrono::nanoseconds(std::chrono::milliseconds(*period_ms))
                  : default_period(robot);
    const bool wander = spec.name == "wander";
    const RobotKind kind = robot_;
    run.connect = [kind, period, wander, spec](SerialPort port, const LinkOptions& link) {
      return std::make_unique<SerialSession>(std::move(port), kind, link, make_controller(spec),
                                             wander, period);
    };
    return run;
  }

  [[nodiscard]] ReplayResult replay(LogReader& reader, const std::string& path,
                                    std::optional<std::int64_t> until) const override {
    return detail::replay_serial(reader, path, until, robot_);
  }

  [[nodiscard]] EmulateReport
  serve(const EmulateOptions& o,
        const std::function<void(const std::string&)>& ready) const override {
    EmulatorOptions options = detail::emulator_options(o);
    if (options.faults.unterminated_ppm > 0)
      throw kernel::InputError("fault", "unterminated=P is a fault of the epuck2's binary "
                                        "sequences (the text robots' lines have no 0 to lose)");
    std::optional<TcpListener> listener = detail::listen_for(o);
    FirmwareEmulator emulator(robot_, o.walls, options);
    return detail::serve_emulator(emulator, listener, ready, emulator);
  }

private:
  const RobotDescription& description_; // registered: it lives as long as the process
  RobotKind robot_;                     // its kind, for the session, replay and emulator
};

namespace detail {

std::unique_ptr<const Device> make_serial_device(const RobotDescription& robot) {
  return std::make_unique<const SerialDevice>(robot);
}

} // namespace detail

} // namespace antkit::devices
