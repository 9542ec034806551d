// Replay speed: steps per second of `antkit replay` on a Buffon log (issue 13's target: >= 1 M
// steps/s, so that a day of robot logs replays in seconds; issue 46's: 2 M). The log is made in
// process, without a tty (devices::emulated_log: the Khepera emulator's firmware answers each
// command directly, the Buffon controller decides, and the records are what record() would write:
// every exchange, the observation, the command, the odometry and the state hash, the
// identification's, the start's and the safe stop's exchanges).
#include <antkit/devices/controllers.hpp>
#include <antkit/devices/emulated_log.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/mcap_export.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <benchmark/benchmark.h>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace {

namespace devices = antkit::devices;

// A Buffon visit of `steps` steps on an emulated Khepera, logged to `path` (emulated_log.hpp).
void make_log(const std::string& path, std::int64_t steps) {
  const auto spec = devices::make_spec("buffon", 1, {{"visit", 1}}, "bench");
  std::ofstream(path, std::ios::binary) << devices::emulated_log(
      devices::RobotKind::Khepera,
      antkit::geometry::build_arena_spec("circle:d=100").arena.walls_fx(), spec, steps);
}

// The log, made once per process on first use and removed when the process ends (44 MB: every
// run of the benchmark used to leave one behind in the temporary directory).
class BenchLog {
public:
  BenchLog()
      : path_((std::filesystem::temp_directory_path() /
               ("antkit-bench-replay-" + std::to_string(::getpid()) + ".jsonl"))
                  .string()) {
    make_log(path_, 200000);
  }
  ~BenchLog() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  BenchLog(const BenchLog&) = delete;
  BenchLog& operator=(const BenchLog&) = delete;
  [[nodiscard]] const std::string& path() const noexcept { return path_; }

private:
  std::string path_;
};

const std::string& buffon_log() {
  static const BenchLog log;
  return log.path();
}

// items = replayed steps (read, re-decoded, stepped and checked). Argument: whether the log is
// read ahead on a second thread (replay.hpp, detail::ReadAhead; by default it is on a machine of
// two hardware threads); wall time.
void BM_ReplayBuffonLog(benchmark::State& state) {
  const auto& path = buffon_log();
  devices::detail::set_read_ahead(state.range(0) != 0 ? devices::detail::ReadAhead::Always
                                                      : devices::detail::ReadAhead::Never);
  std::int64_t steps = 0;
  for (auto _ : state) {
    const auto r = devices::replay(path);
    if (!r.identical) state.SkipWithError("the benchmark's own log does not replay");
    steps += r.steps;
  }
  devices::detail::set_read_ahead(devices::detail::ReadAhead::Auto);
  state.SetItemsProcessed(steps);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(std::filesystem::file_size(path)));
}
BENCHMARK(BM_ReplayBuffonLog)
    ->ArgName("ahead")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The floor under both: the log read and parsed, nothing else. items = records read.
void BM_ReadBuffonLog(benchmark::State& state) {
  const auto& path = buffon_log();
  std::int64_t records = 0;
  for (auto _ : state) {
    devices::LogReader reader(path);
    devices::LogRecord r;
    while (reader.next(r)) ++records;
    benchmark::DoNotOptimize(r.state);
  }
  state.SetItemsProcessed(records);
}
BENCHMARK(BM_ReadBuffonLog)->Unit(benchmark::kMillisecond);

// The same log to an MCAP file (`antkit export mcap`); issue 42 asks that it be no slower than
// replaying it. Argument: the threads that format (McapOptions::threads); wall time, since the
// work is spread. The file is removed between iterations, untimed: writing over an existing file
// adds the kernel's freeing of the old one's pages (about 150 MB here) to the export's time.
// items = exported steps.
void BM_ExportMcapBuffonLog(benchmark::State& state) {
  const auto& path = buffon_log();
  const auto out = path + ".mcap";
  devices::McapOptions options;
  options.threads = static_cast<unsigned>(state.range(0));
  std::int64_t steps = 0;
  std::uint64_t bytes = 0;
  for (auto _ : state) {
    const auto s = devices::export_mcap(path, out, options);
    bytes = s.bytes;
    steps += 200000;
    state.PauseTiming();
    std::filesystem::remove(out);
    state.ResumeTiming();
  }
  state.SetItemsProcessed(steps);
  state.counters["mcap_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_ExportMcapBuffonLog)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace
