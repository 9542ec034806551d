// Fuzz target: the firmware side of every robot's protocol (Codec::parse_command, what the
// emulators read) on arbitrary bytes, and the emulator answering it. Parsing must never crash or
// throw; an accepted command re-encoded from its fields parses back to the same fields; the
// emulator's answer to any line is a complete reply (ends in CR LF) or nothing.
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/kernel/segment.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace antkit::devices;

std::vector<antkit::kernel::FxSegment> square_walls() {
  using antkit::kernel::Fx;
  const Fx lo = Fx::from_int(-4), hi = Fx::from_int(4);
  return {{{lo, lo}, {hi, lo}}, {{hi, lo}, {hi, hi}}, {{hi, hi}, {lo, hi}}, {{lo, hi}, {lo, lo}}};
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const auto robot : antkit::devices::serial_robots()) {
    const Codec codec(robot);
    const auto f = codec.parse_command(text);
    if (f) {
      std::string again(1, f.value->letter);
      for (std::size_t i = 0; i < f.value->count; ++i)
        again += "," + std::to_string(f.value->values[i]);
      const auto g = codec.parse_command(again);
      if (!g || g.value->letter != f.value->letter || g.value->count != f.value->count)
        __builtin_trap();
    }
    // The emulator answers each line of the input in turn (at most 64 lines).
    static const auto walls = square_walls();
    FirmwareEmulator emu(robot, walls);
    std::size_t start = 0, lines = 0;
    while (start < text.size() && lines++ < 64) {
      auto end = text.find_first_of("\r\n", start);
      if (end == std::string_view::npos) end = text.size();
      const auto r = emu.handle(text.substr(start, end - start));
      // Replies end CR LF; the Webots relay answers what it does not know with a bare LF.
      const bool bare_lf = robot == antkit::devices::RobotKind::KheperaWebots && r.bytes == "\n";
      if (!r.bytes.empty() && !bare_lf &&
          (r.bytes.size() < 3 || r.bytes.substr(r.bytes.size() - 2) != "\r\n"))
        __builtin_trap();
      start = end + 1;
    }
  }
  return 0;
}
