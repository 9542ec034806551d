// Fuzz target: replay (devices/replay.hpp) of arbitrary bytes as a hardware log: the header's
// robot and controller, every record's exchanges run through the shared body and link
// classification (body.hpp, link.hpp), the stop record's safe stop re-run. Only kernel::InputError
// may escape (a malformed log); a replay is deterministic (a second replay of the same bytes gives
// the same verdict, steps and hash).
#include <antkit/devices/log.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antkit::devices;
  if (size > (1u << 16)) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    LogReader a("fuzz.jsonl", text);
    const ReplayResult first = replay(a, "fuzz.jsonl");
    LogReader b("fuzz.jsonl", text);
    const ReplayResult second = replay(b, "fuzz.jsonl");
    if (first.identical != second.identical || first.steps != second.steps ||
        first.hash != second.hash || first.complete != second.complete)
      __builtin_trap();
    if (first.complete && first.truncated) __builtin_trap();
  } catch (const antkit::kernel::InputError&) {
  }
  return 0;
}
