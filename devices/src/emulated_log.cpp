// A hardware log made against the firmware emulator in process (emulated_log.hpp).
#include <antkit/devices/emulated_log.hpp>
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/protocol.hpp>

namespace antkit::devices {

std::string emulated_log(RobotKind robot, std::vector<kernel::FxSegment> walls,
                         const ControllerSpec& spec, std::int64_t steps, const std::string& arena) {
  FirmwareEmulator emu(robot, std::move(walls));
  const Codec codec(robot);
  auto controller = make_controller(spec);
  LogHeader header;
  header.antkit_version = "emulated";
  header.robot = std::string(robot.name());
  header.port = "(in process)";
  header.baud = codec.robot().line.baud;
  header.framing = codec.robot().line.framing();
  header.controller = spec.name;
  header.params = spec.params;
  header.seed = spec.seed;
  header.arena = arena;
  std::string text = format_header(header) + "\n";
  const auto exchange = [&](const std::string& command, std::vector<Exchange>& io) {
    std::string line = command;
    while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.pop_back();
    io.push_back({command, emu.handle(line).bytes});
    return io.back().received;
  };
  LogRecord rec;
  for (std::int64_t s = 0; s < steps; ++s) {
    rec.io.clear();
    if (s == 0) {
      exchange(codec.version(), rec.io);          // record()'s identification at connect
      exchange(codec.set_odometry(0, 0), rec.io); // its start: the counters to zero
    }
    const auto readings = *codec.decode_proximity(exchange(codec.read_proximity(), rec.io)).value;
    controller->observe(codec.robot(), readings, rec.obs);
    controller->step(codec.robot(), rec.obs, rec.cmd);
    exchange(codec.set_speed(static_cast<std::int32_t>(rec.cmd[2]),
                             static_cast<std::int32_t>(rec.cmd[3])),
             rec.io);
    const auto odo = *codec.decode_odometry(exchange(codec.read_odometry(), rec.io)).value;
    rec.step = s;
    rec.time_ns = s * 100000;
    rec.odo.assign({odo.left, odo.right});
    rec.state = controller->state_hash();
    text += format_record(rec) + "\n";
  }
  // record()'s safe stop: wheels to zero, LEDs off, the speeds read back.
  LogStop stop{steps, "done", {}};
  for (const auto& command : codec.safe_stop()) exchange(command, stop.io);
  exchange(codec.read_speed(), stop.io);
  return text + format_stop(stop) + "\n";
}

} // namespace antkit::devices
