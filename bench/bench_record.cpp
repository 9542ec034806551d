// The record loop's cost per step against the firmware emulator over a real pseudo-terminal
// (issue 26): BM_RecordOverPty runs record() (sensor read, controller, wheel command, counters,
// the log record written and flushed) for a Buffon visit; BM_PtyExchanges sends the same three
// commands a step sends (N, D, H) over the same kind of link without the loop. The ratio of the two
// per-step times is the loop's overhead (the log, the controller, the drains and classification);
// compare them in one run, as ratios.
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <atomic>
#include <benchmark/benchmark.h>
#include <filesystem>
#include <thread>
#include <unistd.h>

namespace {

namespace devices = antkit::devices;

// A Khepera emulator serving a pty from a thread.
class EmulatorOnPty {
public:
  EmulatorOnPty()
      : pty_(devices::Pty::open()),
        emu_(devices::RobotKind::Khepera,
             antkit::geometry::build_arena_spec("circle:d=100").arena.walls_fx()) {
    thread_ = std::thread([this] { emu_.serve(pty_, &stop_, false); });
  }
  ~EmulatorOnPty() {
    stop_ = true;
    thread_.join();
  }
  [[nodiscard]] const std::string& port() const { return pty_.slave_path(); }

private:
  devices::Pty pty_;
  devices::FirmwareEmulator emu_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// items = recorded steps.
void BM_RecordOverPty(benchmark::State& state) {
  EmulatorOnPty emu;
  const auto log = (std::filesystem::temp_directory_path() /
                    ("antkit-bench-record-" + std::to_string(::getpid()) + ".jsonl"))
                       .string();
  devices::RecordOptions o;
  o.device = std::string(devices::robot_name(devices::RobotKind::Khepera));
  o.port = emu.port();
  o.line = devices::describe(devices::RobotKind::Khepera).line;
  o.controller = devices::make_spec("buffon", 1, {{"visit", 1}}, "bench");
  o.steps = state.range(0);
  o.out = log;
  o.force = true;
  std::int64_t steps = 0;
  for (auto _ : state) {
    const auto s = devices::record(o);
    if (!s.succeeded()) state.SkipWithError(s.stop.c_str());
    steps += s.steps;
  }
  state.SetItemsProcessed(steps);
  std::filesystem::remove(log);
}
BENCHMARK(BM_RecordOverPty)->Arg(2000)->Unit(benchmark::kMillisecond)->UseRealTime();

// items = steps' worth of exchanges (N, D, H).
void BM_PtyExchanges(benchmark::State& state) {
  EmulatorOnPty emu;
  devices::RobotLink link(
      devices::SerialPort::open(emu.port(), devices::describe(devices::RobotKind::Khepera).line),
      devices::RobotKind::Khepera);
  const devices::Codec codec(devices::RobotKind::Khepera);
  std::vector<devices::Exchange> io;
  std::int64_t steps = 0;
  for (auto _ : state) {
    for (std::int64_t k = 0; k < state.range(0); ++k) {
      io.clear();
      link.transact(codec.read_proximity(), io);
      link.transact(codec.set_speed(3, 4), io);
      link.transact(codec.read_odometry(), io);
    }
    steps += state.range(0);
  }
  state.SetItemsProcessed(steps);
}
BENCHMARK(BM_PtyExchanges)->Arg(2000)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace
