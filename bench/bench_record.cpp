// The record loop's cost per step against the firmware emulator over a real pseudo-terminal
// (issue 26): BM_RecordOverPty runs record() (sensor read, controller, wheel command, counters,
// the log record written and flushed) for a Buffon visit; BM_PtyExchanges sends the same three
// commands a step sends (N, D, H) over the same kind of link without the loop. The ratio of the two
// per-step times is the loop's overhead (the log, the controller, the drains and classification);
// compare them in one run, as ratios.
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/epuck2.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <atomic>
#include <benchmark/benchmark.h>
#include <chrono>
#include <filesystem>
#include <memory>
#include <thread>
#include <unistd.h>

namespace {

namespace devices = antkit::devices;

// An emulator serving a pty from a thread.
template <class Emulator>
class OnPty {
public:
  template <class... Args>
  explicit OnPty(Args&&... args) : pty_(devices::Pty::open()), emu_(std::forward<Args>(args)...) {
    thread_ = std::thread([this] { emu_.serve(pty_, &stop_, false); });
  }
  ~OnPty() {
    stop_ = true;
    thread_.join();
  }
  [[nodiscard]] const std::string& port() const { return pty_.slave_path(); }

private:
  devices::Pty pty_;
  Emulator emu_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// The Khepera's, in the standard arena.
class EmulatorOnPty : public OnPty<devices::FirmwareEmulator> {
public:
  EmulatorOnPty()
      : OnPty(devices::RobotKind::Khepera,
              antkit::geometry::build_arena_spec("circle:d=100").arena.walls_fx()) {}
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

// The e-puck over a pty, ASCII (`--device epuck`: N, D and Q, three round trips a step) against
// binary (`--device epuck2`: one sequence [-'D' l r][-'N'][-'Q'][0], one round trip), a Buffon
// visit each (issue 43). Arguments: binary (0/1), paced (0/1: each emulator answers after its
// command latency and its reply's time at 115 200 baud 8N1, EmulatorOptions::pace). Counters:
// wire_bytes_per_step (sent and received, from the log, start and stop exchanges left out),
// wire_bound_steps_per_s (115 200 / 10 bits a byte / those bytes: no loop beats it on the real
// line), and of_wire_bound (the steps/s measured over that bound: how near the loop gets when
// paced; the unpaced runs show the loop's own cost). items = recorded steps.
void BM_RecordEpuck(benchmark::State& state) {
  const bool binary = state.range(0) != 0;
  devices::EmulatorOptions eo;
  eo.pace = state.range(1) != 0;
  const auto walls = antkit::geometry::build_arena_spec("circle:d=100").arena.walls_fx();
  std::unique_ptr<OnPty<devices::FirmwareEmulator>> ascii;
  std::unique_ptr<OnPty<devices::epuck2::Emulator>> sequences;
  if (binary)
    sequences = std::make_unique<OnPty<devices::epuck2::Emulator>>(walls, eo);
  else
    ascii =
        std::make_unique<OnPty<devices::FirmwareEmulator>>(devices::RobotKind::Epuck, walls, eo);
  const auto log = (std::filesystem::temp_directory_path() /
                    ("antkit-bench-epuck-" + std::to_string(::getpid()) + ".jsonl"))
                       .string();
  devices::RecordOptions o;
  o.device = binary ? "epuck2" : "epuck";
  o.port = binary ? sequences->port() : ascii->port();
  o.controller = devices::make_spec("buffon", 1, {{"visit", 1}}, "bench");
  o.steps = state.range(1) != 0 ? 200 : 2000;
  o.out = log;
  o.force = true;
  std::int64_t steps = 0;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    const auto s = devices::record(o);
    if (!s.succeeded()) state.SkipWithError(s.stop.c_str());
    steps += s.steps;
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  // The bytes on the wire per control step, from the last run's log.
  std::int64_t bytes = 0, logged = 0;
  devices::LogReader reader(log);
  for (devices::LogRecord r; reader.next(r); ++logged)
    if (r.step > 0) // step 0 also carries the start's exchanges
      for (const auto& x : r.io)
        bytes += static_cast<std::int64_t>(x.sent.size() + x.received.size());
  std::filesystem::remove(log);
  if (logged < 2) return;
  const double per_step = static_cast<double>(bytes) / static_cast<double>(logged - 1);
  const double bound = devices::epuck2::kBaud / 10.0 / per_step;
  state.counters["wire_bytes_per_step"] = per_step;
  state.counters["wire_bound_steps_per_s"] = bound;
  state.counters["of_wire_bound"] = static_cast<double>(steps) / elapsed.count() / bound;
  state.SetItemsProcessed(steps);
}
BENCHMARK(BM_RecordEpuck)
    ->ArgNames({"binary", "paced"})
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

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
