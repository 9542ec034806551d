#pragma once
// A second reading of a hardware log's record line, by nlohmann-json (the test oracle of
// devices/src/log.cpp's reader; tests/devices/test_log.cpp and fuzz/hardware_log.cpp).
//
// Why the reader keeps its own lexer (issue 45 asked that the log use the JSON library): twice, the
// reader was rebuilt on nlohmann-json's SAX interface (branches devices-house and log-json, not
// merged), and replay of the benchmark's Buffon log (bench/bench_replay.cpp) became 2.3 to 3.8
// times slower (the library's lexer copies each byte into a token buffer, parses integers with
// strtoull, and allocates a parser per line), where issue 46 asks replay to get faster. So the
// reader's lexer stays, and this oracle holds it to the library instead: every line the reader
// accepts as a record must be JSON to nlohmann-json, with the same values. A lexer bug that accepts
// what is not JSON (a leading zero, an exponent read as an integer, a bad escape) or misreads a
// value (an integer's range, an escape's byte) then fails the property test and the fuzz target.
//
// The log's strings are bytes, one per character: the writer escapes bytes 0x80-0xFF as \u0080 to
// \u00ff, which nlohmann-json decodes to UTF-8; the oracle maps each code point back to one byte
// and gives up (nullopt) on a code point above 0xFF.
#include <antkit/devices/log.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace antkit::test {

namespace log_oracle_detail {

inline std::optional<std::int64_t> int64_of(const nlohmann::json& v) {
  if (v.is_number_integer() && !v.is_number_unsigned()) return v.get<std::int64_t>();
  if (v.is_number_unsigned() && v.get<std::uint64_t>() <= std::uint64_t{INT64_MAX})
    return static_cast<std::int64_t>(v.get<std::uint64_t>());
  return std::nullopt;
}

// UTF-8 (as nlohmann-json holds strings) to one byte per code point <= 0xFF.
inline std::optional<std::string> bytes_of(const nlohmann::json& v) {
  if (!v.is_string()) return std::nullopt;
  const auto& s = v.get_ref<const std::string&>();
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if ((c == 0xC2 || c == 0xC3) && i + 1 < s.size()) {
      const auto d = static_cast<unsigned char>(s[++i]);
      out += static_cast<char>(((c & 0x03u) << 6) | (d & 0x3Fu));
    } else {
      return std::nullopt; // a code point above 0xFF
    }
  }
  return out;
}

inline std::optional<std::vector<std::int64_t>> ints_of(const nlohmann::json& v) {
  if (!v.is_array()) return std::nullopt;
  std::vector<std::int64_t> out;
  for (const auto& e : v) {
    const auto i = int64_of(e);
    if (!i) return std::nullopt;
    out.push_back(*i);
  }
  return out;
}

inline std::optional<std::vector<devices::Exchange>> io_of(const nlohmann::json& v) {
  if (!v.is_array()) return std::nullopt;
  std::vector<devices::Exchange> out;
  for (const auto& e : v) {
    if (!e.is_array() || e.size() < 2 || e.size() > 3) return std::nullopt;
    devices::Exchange x;
    const auto sent = bytes_of(e[0]), received = bytes_of(e[1]);
    if (!sent || !received) return std::nullopt;
    x.sent = *sent;
    x.received = *received;
    if (e.size() == 3) {
      const auto t = int64_of(e[2]);
      if (!t) return std::nullopt;
      x.t_ns = *t;
    }
    out.push_back(std::move(x));
  }
  return out;
}

} // namespace log_oracle_detail

// The record nlohmann-json reads from `line`: nullopt when the line is not JSON to the library, or
// not an object holding the record's keys with values of their types.
inline std::optional<devices::LogRecord> record_by_json_library(std::string_view line) {
  namespace d = log_oracle_detail;
  const nlohmann::json j = nlohmann::json::parse(line.begin(), line.end(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::nullopt;
  for (const char* key : {"step", "t_ns", "io", "obs", "cmd", "odo", "state"})
    if (!j.contains(key)) return std::nullopt;
  devices::LogRecord r;
  const auto step = d::int64_of(j["step"]), t = d::int64_of(j["t_ns"]);
  const auto io = d::io_of(j["io"]);
  const auto obs = d::ints_of(j["obs"]), cmd = d::ints_of(j["cmd"]), odo = d::ints_of(j["odo"]);
  const auto state = d::bytes_of(j["state"]);
  if (!step || !t || !io || !obs || !cmd || !odo || !state || state->size() != 16)
    return std::nullopt;
  r.step = *step;
  r.time_ns = *t;
  r.io = *io;
  r.obs = *obs;
  r.cmd = *cmd;
  r.odo = *odo;
  for (const char c : *state) {
    const int v = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (v < 0) return std::nullopt;
    r.state = (r.state << 4) | static_cast<std::uint64_t>(v);
  }
  return r;
}

} // namespace antkit::test
