// Reading a ROS 2 bag (issue 42's target: >= 1 M odometry messages/s from an uncompressed MCAP
// file on this machine). The bag is made in process with antkit's MCAP writer: 1 M
// nav_msgs/msg/Odometry messages on /odom (little-endian XCDR1, 724 bytes each: a header with frame
// "odom", child frame "base_link", the pose, both covariances and the twist), about 0.75 GB, in
// 4 MiB chunks, every CRC written. Measured: read_poses (the reader, every CRC checked, the CDR
// decoded into the pose list) and the MCAP reader alone, with and without the CRC checks.
#include <antkit/io/bag.hpp>
#include <antkit/io/mcap.hpp>
#include <antkit/io/mcap_reader.hpp>
#include <benchmark/benchmark.h>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace {

constexpr std::int64_t kMessages = 1000000;

void put(std::string& s, const void* p, std::size_t n) {
  s.append(static_cast<const char*>(p), n);
}
void pad(std::string& s, std::size_t align) {
  while ((s.size() - 4) % align != 0) s += '\0';
}

std::string odometry(std::int64_t i) {
  std::string s("\x00\x01\x00\x00", 4);
  const std::int32_t sec = static_cast<std::int32_t>(1700000000 + i / 10);
  const std::uint32_t nsec = static_cast<std::uint32_t>((i % 10) * 100000000);
  put(s, &sec, 4);
  put(s, &nsec, 4);
  const std::uint32_t odom = 5, base = 10;
  put(s, &odom, 4);
  put(s, "odom", 5);
  pad(s, 4);
  put(s, &base, 4);
  put(s, "base_link", 10);
  pad(s, 8);
  const double t = static_cast<double>(i) * 1e-3;
  const double pose[7] = {std::cos(t) * t, std::sin(t) * t, 0, 0, 0,
                          std::sin(t / 2), std::cos(t / 2)};
  put(s, pose, sizeof pose);
  const double zeros[36 + 6 + 36] = {};
  put(s, zeros, sizeof zeros);
  return s;
}

const std::string& bag_path() {
  static const std::string path = [] {
    const auto p = std::filesystem::temp_directory_path() /
                   ("antkit_bench_odometry_" + std::to_string(::getpid()) + ".mcap");
    std::ofstream out(p, std::ios::binary);
    antkit::io::mcap::Writer w(out, {"ros2", "antkit", 4U << 20});
    const auto s = w.add_schema("nav_msgs/msg/Odometry", "ros2msg", "");
    const auto c = w.add_channel(s, "/odom", "cdr");
    for (std::int64_t i = 0; i < kMessages; ++i) {
      const auto t = static_cast<std::uint64_t>(1700000000000000000LL + i * 100000000LL);
      w.write({c, static_cast<std::uint32_t>(i), t, t, odometry(i)});
    }
    w.finish();
    return p.string();
  }();
  static const struct Cleanup {
    ~Cleanup() { std::filesystem::remove(path); }
  } cleanup;
  return path;
}

void BM_BagReadPoses(benchmark::State& state) {
  const std::string& path = bag_path();
  for (auto _ : state) {
    const auto track = antkit::io::bag::read_poses(path, "/odom", antkit::io::bag::Stamp::bag);
    benchmark::DoNotOptimize(track.poses.data());
    if (track.poses.size() != kMessages) state.SkipWithError("wrong pose count");
  }
  state.SetItemsProcessed(state.iterations() * kMessages);
}
BENCHMARK(BM_BagReadPoses)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_McapReaderNext(benchmark::State& state) {
  const std::string& path = bag_path();
  for (auto _ : state) {
    antkit::io::mcap::Reader reader(path, {state.range(0) != 0});
    antkit::io::mcap::MessageView m;
    std::int64_t n = 0;
    while (reader.next(m)) ++n;
    benchmark::DoNotOptimize(n);
  }
  state.SetItemsProcessed(state.iterations() * kMessages);
}
BENCHMARK(BM_McapReaderNext)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace

namespace {

// CRC-32 over 1 MiB: the folded CRC (PCLMULQDQ, where the CPU has it) and the tables alone
// (io/crc32.hpp). Every MCAP record the writer and the bag reader touch goes through it.
void BM_Crc32(benchmark::State& state) {
  std::string bytes(1U << 20, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = static_cast<char>(i * 2654435761U >> 24);
  const auto f = state.range(0) != 0 ? &antkit::io::crc32 : &antkit::io::crc32_portable;
  for (auto _ : state) benchmark::DoNotOptimize(f(bytes, 0));
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes.size()));
}
BENCHMARK(BM_Crc32)->ArgName("folded")->Arg(1)->Arg(0);

} // namespace
