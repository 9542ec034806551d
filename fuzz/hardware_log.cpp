// Fuzz target: the hardware log reader (devices/log.hpp) on arbitrary bytes, read to the end. Only
// kernel::InputError may escape; every record it accepts re-formats (format_record) and re-reads
// to the same record, and the header likewise; and every record line it accepts is JSON to
// nlohmann-json with the same values (tests/support/log_json_oracle.hpp: the reader's own lexer
// held to the library), as is every line its fast path (detail::read_canonical_step) accepts.
#include <antkit/devices/log.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>
#include <log_json_oracle.hpp>
#include <string>
#include <string_view>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antkit::devices;
  std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string_view> lines; // lines[k] is line k + 1, as the reader counts them
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t nl = text.find('\n', at);
    const std::size_t end = nl == std::string::npos ? text.size() : nl;
    lines.emplace_back(text.data() + at, end - at);
    at = end + 1;
  }
  // The reader's fast path for the writer's own form accepts no line nlohmann-json reads
  // differently (or not at all).
  for (const auto line : lines)
    if (LogRecord fast; detail::read_canonical_step(line, fast)) {
      const auto theirs = antkit::test::record_by_json_library(line);
      if (!theirs || !(*theirs == fast)) __builtin_trap();
    }
  try {
    LogReader reader("fuzz.jsonl", text);
    const std::string header = format_header(reader.header());
    LogRecord r;
    std::size_t n = 0;
    while (reader.next(r) && n++ < 100000) {
      const auto theirs = antkit::test::record_by_json_library(lines.at(reader.line() - 1));
      if (!theirs || !(*theirs == r)) __builtin_trap();
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
