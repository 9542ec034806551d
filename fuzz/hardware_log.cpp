// Fuzz target: the hardware log reader (devices/log.hpp) on arbitrary bytes, read to the end. Only
// kernel::InputError may escape; every record it accepts re-formats (format_record) and re-reads
// to the same record, and the header likewise.
#include <antkit/devices/log.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antkit::devices;
  std::string text(reinterpret_cast<const char*>(data), size);
  try {
    LogReader reader("fuzz.jsonl", text);
    const std::string header = format_header(reader.header());
    LogRecord r;
    std::size_t n = 0;
    while (reader.next(r) && n++ < 100000) {
      LogReader again("again.jsonl", header + "\n" + format_record(r) + "\n");
      LogRecord s;
      // The re-read log starts at step 0: compare all but the step number.
      if (r.step == 0) {
        if (!again.next(s) || !(s == r)) __builtin_trap();
      }
    }
    if (!(LogReader("h.jsonl", header + "\n").header() == reader.header())) __builtin_trap();
  } catch (const antkit::kernel::InputError&) {
  }
  return 0;
}
