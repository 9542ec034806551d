// Fuzz target: every reply decoder of every robot (devices/protocol.hpp) on arbitrary bytes. The
// first byte picks the command the reply answers; the rest is the received line. Decoders must
// never crash or throw; a line a decoder accepts must be canonical enough to re-encode: the
// values it returns, encoded by the firmware side (Codec::reply), decode again to the same values.
// The identification rules (Codec::identifies, record's check at connect) take any line: one they
// accept is a valid reply to the version request, and no line identifies two robots that share a
// version request (the Khepera and the Webots relay both answer B).
#include <antkit/devices/protocol.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

using namespace antkit::devices;

void check(const Codec& codec, std::string_view sent, std::string_view line) {
  const auto f = codec.decode_reply(sent, line);
  if (f) {
    if (f.value->count > f.value->values.size()) __builtin_trap();
    const char letter = f.value->letter;
    if (letter != 'b' && letter != 'v') {
      const std::string again = codec.reply(
          letter, std::span<const std::int32_t>(f.value->values.data(), f.value->count));
      const auto g = codec.decode_reply(sent, again);
      if (!g || g.value->count != f.value->count) __builtin_trap();
      for (std::size_t i = 0; i < f.value->count; ++i)
        if (g.value->values[i] != f.value->values[i]) __builtin_trap();
    }
  } else if (f.error.column == 0 || f.error.column > line.size() + 1) {
    __builtin_trap(); // an error must point into the line (or just past it)
  }
  const auto p = codec.decode_proximity(line);
  if (p) {
    for (const auto v : p.value->raw) {
      if (v < codec.robot().proximity_min || v > codec.robot().proximity_max) __builtin_trap();
      const auto n = normalise_reading(codec.robot(), v);
      if (n < antkit::kernel::Fx{} || n > antkit::kernel::Fx::one()) __builtin_trap();
    }
  }
  if (codec.identifies(line)) {
    if (!codec.decode_reply(codec.version(), line)) __builtin_trap();
    if (identified_as(codec.version(), line) != codec.robot().name) __builtin_trap();
  }
  (void)codec.decode_ack(line, sent.empty() ? 'D' : sent[0]);
  (void)codec.decode_speed(line);
  if (codec.robot().has_odometry) (void)codec.decode_odometry(line);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static constexpr const char* kSent[] = {"N\r", "D,1,2\r", "H\r",     "Q\r",     "E\r",
                                          "B\r", "V\r",     "G,0,0\r", "L,0,1\r", "O\r"};
  const char* sent = kSent[data[0] % 10];
  const std::string_view line(reinterpret_cast<const char*>(data + 1), size - 1);
  for (const auto robot : antkit::devices::serial_robots()) check(Codec(robot), sent, line);
  return 0;
}
