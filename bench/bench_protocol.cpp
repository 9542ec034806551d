// The robots' protocol codecs: commands encoded and replies validated per second, per robot
// (devices/protocol.hpp). Replay decodes every logged reply again, so decode speed bounds it.
#include <antkit/devices/protocol.hpp>
#include <benchmark/benchmark.h>

namespace {

namespace devices = antkit::devices;

// The robots benchmarked, by the benchmark's argument: the three real robots' codecs.
const devices::RobotKind kRobots[] = {devices::RobotKind::Khepera, devices::RobotKind::Hemisson,
                                      devices::RobotKind::Epuck};

void BM_EncodeSetSpeed(benchmark::State& state) {
  const devices::Codec codec(kRobots[state.range(0)]);
  std::int32_t v = 0;
  for (auto _ : state) {
    auto s = codec.set_speed(v % 9, -(v % 9));
    benchmark::DoNotOptimize(s);
    ++v;
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(std::string(codec.robot().name));
}
BENCHMARK(BM_EncodeSetSpeed)->DenseRange(0, 2);

void BM_DecodeProximity(benchmark::State& state) {
  const devices::Codec codec(kRobots[state.range(0)]);
  const std::array<std::int32_t, 8> raw{0, 12, 250, 5, 0, 0, 200, 200};
  const std::string line = codec.reply('N', raw);
  for (auto _ : state) {
    auto d = codec.decode_proximity(line);
    benchmark::DoNotOptimize(d);
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(std::string(codec.robot().name));
}
BENCHMARK(BM_DecodeProximity)->DenseRange(0, 2);

} // namespace
