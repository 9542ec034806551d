// Fuzz target: a hardware log to MCAP (devices/mcap_export.hpp) on arbitrary bytes, as `antkit
// export mcap` and `replay --mcap` do. Only kernel::InputError may escape (a malformed log); every
// log that exports gives a file the test's MCAP reader (tests/support/mcap_reader.hpp: every
// record, index and CRC checked) reads whole, with one /antkit/step message per record. A log that
// replays is also exported side by side with its replay. The bytes are the same on one thread and
// on three.
#include <antkit/devices/log.hpp>
#include <antkit/devices/mcap_export.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>
#include <mcap_reader.hpp>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antkit::devices;
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::size_t records = 0;
  try {
    LogReader count("fuzz.jsonl", text);
    for (LogRecord r; count.next(r);) ++records;
  } catch (const antkit::kernel::InputError&) {
    return 0;
  }
  try {
    LogReader reader("fuzz.jsonl", text);
    McapOptions one;
    one.threads = 1;
    const auto bytes = mcap_of_log(reader, "fuzz.jsonl", one);
    const auto f = antkit::test::mcap::read(bytes);
    std::size_t steps = 0;
    for (const auto& m : f.messages) steps += f.channels.at(m.channel_id).topic == "/antkit/step";
    if (steps != records) __builtin_trap();
    // On three threads, the same bytes.
    LogReader threaded("fuzz.jsonl", text);
    McapOptions three;
    three.threads = 3;
    if (mcap_of_log(threaded, "fuzz.jsonl", three) != bytes) __builtin_trap();
  } catch (const antkit::kernel::InputError&) {
  } catch (const std::runtime_error&) {
    __builtin_trap(); // the reader refused what the writer wrote
  }
  try {
    LogReader replayed("fuzz.jsonl", text);
    const auto r = replay(replayed, "fuzz.jsonl");
    LogReader again("fuzz.jsonl", text);
    McapOptions one;
    one.threads = 1;
    (void)antkit::test::mcap::read(mcap_of_log(again, "fuzz.jsonl", one, &r));
  } catch (const antkit::kernel::InputError&) {
  } catch (const std::runtime_error&) {
    __builtin_trap();
  }
  return 0;
}
