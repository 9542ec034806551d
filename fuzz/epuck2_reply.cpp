// Fuzz target: the e-puck2's binary reply decoders (devices/epuck2.hpp) on arbitrary bytes, and its
// firmware emulator on the same bytes as a byte stream. The first byte picks the decoder; the rest
// is the received reply. Decoders never crash or throw; a reply a decoder accepts is exactly its
// values re-encoded (16-bit little-endian), and a refusal points into the reply or just past it.
// The emulator takes any stream: after it, "\rx\r" and a resync bring the firmware back to the top
// of its loop whatever state the stream left it in, and its reply to a step sequence is 20 bytes
// that the step decoder accepts. The binary framing (SequenceFraming, which the link classifies
// replies by) accepts a reply to a step or a stop sequence exactly when the decoder does, and
// sizes any bytes taken as a sequence without crashing. The identification's rule
// (epuck2::identifies) takes any line, and a line it accepts is one the framing takes as the
// reply to the ASCII version request.
#include <antkit/devices/epuck2.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

using namespace antkit::devices;

std::string le16(std::int32_t v) {
  const auto u = static_cast<std::uint16_t>(v);
  return {static_cast<char>(u & 0xFF), static_cast<char>(u >> 8)};
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view reply(reinterpret_cast<const char*>(data + 1), size - 1);
  if (data[0] % 2 == 0) {
    const auto d = epuck2::decode_step(reply);
    if (d) {
      std::string again;
      for (const auto v : d.value->proximity.raw) {
        if (v < 0 || v >= epuck2::kProximityLimit) __builtin_trap();
        again += le16(v);
      }
      again += le16(d.value->left) + le16(d.value->right);
      if (again != reply) __builtin_trap();
    } else if (d.error.column == 0 || d.error.column > reply.size() + 1) {
      __builtin_trap();
    }
  } else {
    const auto d = epuck2::decode_pair(reply);
    if (d) {
      if (le16(d.value->left) + le16(d.value->right) != reply) __builtin_trap();
    } else if (d.error.column == 0 || d.error.column > reply.size() + 1) {
      __builtin_trap();
    }
  }
  // The framing the link reads by agrees with the decoders.
  const epuck2::SequenceFraming framing;
  const auto accepts = [&](const std::string& request) {
    return framing.classify(request, reply).kind == ReplyKind::Reply;
  };
  if (accepts(epuck2::step_sequence(1, -1)) != bool(epuck2::decode_step(reply))) __builtin_trap();
  if (accepts(epuck2::stop_sequence()) != bool(epuck2::decode_pair(reply))) __builtin_trap();
  (void)framing.reply_size(reply);
  if (epuck2::identifies(reply) &&
      framing.classify(epuck2::kVersionRequest, reply).kind != ReplyKind::Reply)
    __builtin_trap();
  // The firmware on the stream; then back to the top of its loop, and a step.
  static epuck2::Emulator emulator(
      antkit::geometry::build_arena_spec("circle:d=8").arena.walls_fx());
  emulator.reset();
  (void)emulator.feed("");
  const auto junk = emulator.feed(reply);
  if (junk.hang_up) __builtin_trap(); // no faults were asked for
  (void)emulator.feed("\rx\r"); // ends an ASCII line or the CR/LF skipping; skipped in a sequence
  (void)emulator.feed(epuck2::resync_bytes());
  const auto step = emulator.feed(epuck2::step_sequence(100, -100));
  if (step.bytes.size() != epuck2::kStepReplySize || !epuck2::decode_step(step.bytes))
    __builtin_trap();
  return 0;
}
