// Hardware logs (devices/log.hpp): the canonical lines, round trips of arbitrary bytes and
// integers, any valid JSON of the shapes accepted, everything else refused at its line and
// column, truncation at any byte of the last line, and the writer's per-record flush.
#include "scratch_dir.hpp"

#include <algorithm>
#include <antkit/devices/log.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <fstream>
#include <log_json_oracle.hpp>
#include <rapidcheck/catch.h>
#include <unistd.h>

namespace devices = antkit::devices;
using antkit::kernel::InputError;

namespace {

devices::LogHeader header() {
  devices::LogHeader h;
  h.antkit_version = "0.1.0";
  h.robot = "khepera";
  h.port = "/dev/pts/3";
  h.baud = 9600;
  h.framing = "8N2";
  h.controller = "buffon";
  h.params = {{"trial", 0}, {"visit", 1}};
  h.seed = 1;
  return h;
}

devices::LogRecord record(std::int64_t step) {
  devices::LogRecord r;
  r.step = step;
  r.time_ns = 1234;
  r.io = {{"N\r", "n,0,0,0,0,0,0,0,0\r\n"}, {"D,3,4\r", "d\r\n"}};
  r.obs = {0, 0};
  r.cmd = {1, -2};
  r.odo = {10, 20};
  r.state = 0x0123456789abcdefULL;
  return r;
}

const std::string kHeader =
    R"({"schema":2,"antkit":"0.1.0","robot":"khepera","port":{"path":"/dev/pts/3","baud":9600,)"
    R"("framing":"8N2"},"controller":{"name":"buffon","params":{"trial":0,"visit":1}},"seed":1})";

// The error a log with `line` as its first record gets: line and column.
std::pair<std::size_t, std::size_t> error_of(const std::string& text) {
  try {
    devices::LogReader r("t.jsonl", text);
    devices::LogRecord rec;
    while (r.next(rec)) {
    }
  } catch (const InputError& e) {
    return {e.line(), e.column()};
  }
  return {0, 0};
}

// One edit of `text` at byte `at` (0 to its size): kind 0 replaces that byte with c, 1 inserts c
// before it, 2 erases it (a replace or an erase at the end changes nothing).
void edit_byte(std::string& text, std::size_t at, char c, int kind) {
  if (kind == 1)
    text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), c);
  else if (at < text.size() && kind == 0)
    text[at] = c;
  else if (at < text.size())
    text.erase(at, 1);
}

} // namespace

TEST_CASE("the writer's lines are the documented canonical form", "[devices]") {
  CHECK(devices::format_header(header()) == kHeader);
  CHECK(devices::format_record(record(0)) ==
        R"({"step":0,"t_ns":1234,"io":[["N\r","n,0,0,0,0,0,0,0,0\r\n"],["D,3,4\r","d\r\n"]],)"
        R"("obs":[0,0],"cmd":[1,-2],"odo":[10,20],"state":"0123456789abcdef"})");
  CHECK(devices::format_stop({1000, "done", {{"D,0,0\r", "d\r\n"}}}) ==
        R"({"stop":"done","step":1000,"io":[["D,0,0\r","d\r\n"]]})");
  devices::LogRecord junk = record(0);
  junk.io = {{std::string("\x00\x7f\xff\"\\\t", 6), ""}};
  CHECK(devices::format_record(junk).find(R"([["\u0000\u007f\u00ff\"\\\t",""]])") !=
        std::string::npos);
}

TEST_CASE("records of arbitrary bytes and integers read back as written", "[devices][property]") {
  rc::prop("format then read is the identity", [] {
    devices::LogRecord r;
    r.step = 0;
    r.time_ns = *rc::gen::arbitrary<std::int64_t>();
    const auto n = *rc::gen::inRange<std::size_t>(0, 4);
    for (std::size_t i = 0; i < n; ++i)
      r.io.push_back({*rc::gen::arbitrary<std::string>(), *rc::gen::arbitrary<std::string>()});
    r.obs = *rc::gen::arbitrary<std::vector<std::int64_t>>();
    r.cmd = *rc::gen::container<std::vector<std::int64_t>>(
        rc::gen::element(INT64_MIN, INT64_MAX, std::int64_t{0}, std::int64_t{-1}));
    r.odo = *rc::gen::arbitrary<std::vector<std::int64_t>>();
    r.state = *rc::gen::arbitrary<std::uint64_t>();
    const devices::LogStop s{1, *rc::gen::arbitrary<std::string>(), r.io};
    devices::LogReader reader("p.jsonl", devices::format_header(header()) + "\n" +
                                             devices::format_record(r) + "\n" +
                                             devices::format_stop(s) + "\n");
    RC_ASSERT(reader.header() == header());
    devices::LogRecord back;
    RC_ASSERT(reader.next(back));
    RC_ASSERT(back == r);
    RC_ASSERT(!reader.next(back));
    RC_ASSERT(reader.stop().has_value());
    RC_ASSERT(*reader.stop() == s);
    RC_ASSERT(!reader.truncated());
  });
}

// The reader's lexer against nlohmann-json (tests/support/log_json_oracle.hpp says why the reader
// keeps its own): a canonical record line with a few bytes replaced, inserted or deleted (drawn
// from what JSON's grammar turns on: digits, signs, exponents, quotes, escapes, brackets, blanks,
// bytes above 0x7F, or a whole escape sequence), and whenever the reader accepts it as a record,
// nlohmann-json must read the same line as JSON, to the same record. Lines the reader refuses need
// no check here (it refuses more than JSON does: its schema); the tests above and below hold the
// refusals.
TEST_CASE("every record line the reader accepts is JSON to nlohmann-json, with the same values",
          "[devices][property]") {
  std::size_t accepted = 0, edited_and_accepted = 0, fast_edited = 0;
  rc::prop("reader accepts => nlohmann-json reads the same record", [&] {
    devices::LogRecord r = record(0);
    r.time_ns = *rc::gen::arbitrary<std::int64_t>();
    r.io = {{*rc::gen::arbitrary<std::string>(), *rc::gen::arbitrary<std::string>()}};
    if (*rc::gen::arbitrary<bool>()) r.io[0].t_ns = *rc::gen::inRange<std::int64_t>(0, INT64_MAX);
    r.obs = *rc::gen::container<std::vector<std::int64_t>>(
        rc::gen::oneOf(rc::gen::arbitrary<std::int64_t>(),
                       rc::gen::element(INT64_MIN, INT64_MAX, std::int64_t{0})));
    r.state = *rc::gen::arbitrary<std::uint64_t>();
    const std::string canonical = devices::format_record(r);
    static const std::string kAlphabet = "0123456789-+.eE\\\"u/bfnrt[]{},: \t\r\x7f\x80\xc3\xff";
    // Fifty edited lines per record: an edit that slips past the lexer is rare among edits.
    for (int variant = 0; variant < 50; ++variant) {
      std::string line = canonical;
      const int edits = *rc::gen::inRange(0, 4);
      for (int k = 0; k < edits; ++k) {
        const auto at = *rc::gen::inRange<std::size_t>(0, line.size() + 1);
        const char c = kAlphabet[*rc::gen::inRange<std::size_t>(0, kAlphabet.size())];
        if (const int kind = *rc::gen::inRange(0, 4); kind < 3)
          edit_byte(line, at, c, kind);
        else // a whole escape (read only inside a string)
          line.insert(at, *rc::gen::element<std::string>("\\\"", "\\\\", "\\/", "\\b", "\\f", "\\n",
                                                         "\\r", "\\t", "\\u0041", "\\u00e9",
                                                         "\\u00FF", "\\u0100"));
      }
      // The fast path (detail::read_canonical_step) accepts a subset of what the reader does, to
      // the same record: whatever it accepts, nlohmann-json reads the same.
      if (devices::LogRecord fast; devices::detail::read_canonical_step(line, fast)) {
        if (line != canonical) ++fast_edited;
        const auto theirs = antkit::test::record_by_json_library(line);
        RC_ASSERT(theirs.has_value());
        RC_ASSERT(*theirs == fast);
      } else {
        // The writer's own lines take the fast path unless an integer has 19 digits.
        const auto short_ints = [](const std::vector<std::int64_t>& v) {
          return std::all_of(v.begin(), v.end(), [](std::int64_t x) {
            return x > -1000000000000000000 && x < 1000000000000000000;
          });
        };
        RC_ASSERT(!(line == canonical && short_ints(r.obs) && short_ints(r.cmd) &&
                    short_ints({r.time_ns, r.io[0].t_ns})));
      }
      devices::LogRecord mine;
      bool read = false;
      try {
        devices::LogReader reader("o.jsonl", kHeader + "\n" + line + "\n");
        read = reader.next(mine);
      } catch (const InputError&) {
        read = false;
      }
      if (!read) continue;
      ++accepted;
      if (line != canonical) ++edited_and_accepted;
      const auto theirs = antkit::test::record_by_json_library(line);
      RC_ASSERT(theirs.has_value());
      RC_ASSERT(*theirs == mine);
    }
  });
  // The property must have compared lines, edited ones among them (not only the canonical form).
  CHECK(accepted > 0);
  CHECK(edited_and_accepted > 0);
  CHECK(fast_edited > 0);
}

// The fast path copies a string's plain bytes as they are (log.cpp, Canonical::string): every
// byte value, raw, at every place of a 24-byte plain run, must be read as nlohmann-json reads the
// line: accepted exactly when JSON takes the byte raw in a string (0x20 to 0x7F but '"' and
// '\\'; the reader refuses bytes above 0x7F, which JSON takes only as UTF-8), to the same record.
// (It held a word-at-a-time scan of the run, tried and not kept, to the same: each of its four
// byte tests removed failed it.)
TEST_CASE("the fast path's strings: every byte at every place of a run, against nlohmann-json",
          "[devices][proof]") {
  devices::LogRecord r = record(0);
  const std::string run = "ABCDEFGHIJKLMNOPQRSTUVWX";
  r.io = {{run, "z\r\n"}};
  const std::string canonical = devices::format_record(r);
  const auto at = canonical.find(run);
  REQUIRE(at != std::string::npos);
  std::size_t accepted = 0, wrong = 0;
  for (std::size_t k = 0; k < run.size(); ++k)
    for (int b = 0; b < 256; ++b) {
      std::string line = canonical;
      line[at + k] = static_cast<char>(b);
      const bool plain = b >= 0x20 && b < 0x80 && b != '"' && b != '\\';
      devices::LogRecord fast;
      const bool read = devices::detail::read_canonical_step(line, fast);
      const auto theirs = antkit::test::record_by_json_library(line);
      bool right = read == plain && theirs.has_value() == plain;
      if (read && right) {
        devices::LogRecord expected = r;
        expected.io[0].sent[k] = static_cast<char>(b);
        right = fast == expected && *theirs == expected;
      }
      if (!right) {
        UNSCOPED_INFO("byte " << b << " at " << k << ": fast " << read << ", json "
                              << theirs.has_value());
        ++wrong;
      }
      accepted += read ? 1 : 0;
    }
  CHECK(wrong == 0);
  CHECK(accepted == run.size() * (0x80 - 0x20 - 2));
}

TEST_CASE("any key order, whitespace and escapes are read", "[devices]") {
  const std::string text =
      kHeader + "\n" +
      R"( { "state" : "0123456789abcdef", "odo":[ 10 , 20 ], "cmd":[1,-2],"obs":[0,0],)"
      R"("io":[["N\u000d","n,0,0,0,0,0,0,0,0\r\n"],["D,3,4\r","d\r\n"]],"t_ns":1234,"step":0})" +
      "\n";
  devices::LogReader reader("w.jsonl", text);
  devices::LogRecord r;
  REQUIRE(reader.next(r));
  CHECK(r == record(0));
}

TEST_CASE("malformed lines are refused with their line and column", "[devices]") {
  const std::string r0 = devices::format_record(record(0));
  const auto with = [&](const std::string& second) { return kHeader + "\n" + second + "\n"; };
  CHECK(
      error_of(
          with(
              R"({"step":0,"t_ns":1.5,"io":[],"obs":[],"cmd":[],"odo":[],"state":"0123456789abcdef"})"))
          .first == 2);
  CHECK(
      error_of(with(
          R"({"step":0,"t_ns":1,"io":[["\u0100",""]],"obs":[],"cmd":[],"odo":[],"state":"0123456789abcdef"})")) ==
      std::pair<std::size_t, std::size_t>{2, 33});
  CHECK(
      error_of(
          with(
              R"({"step":0,"t_ns":1,"io":[],"obs":[],"cmd":[],"odo":[],"state":"0123456789ABCDEF"})"))
          .first == 2);
  CHECK(error_of(with(R"({"step":0,"t_ns":1,"io":[],"obs":[],"cmd":[],"odo":[]})")).first == 2);
  CHECK(
      error_of(
          with(
              R"({"step":0,"step":0,"t_ns":1,"io":[],"obs":[],"cmd":[],"odo":[],"state":"0123456789abcdef"})"))
          .first == 2);
  CHECK(
      error_of(
          with(
              R"({"step":0,"t_ns":1,"io":[],"obs":[],"cmd":[],"odo":[],"state":"0123456789abcdef","x":1})"))
          .first == 2);
  CHECK(
      error_of(
          with(
              R"({"step":0,"t_ns":99999999999999999999,"io":[],"obs":[],"cmd":[],"odo":[],"state":"0123456789abcdef"})"))
          .first == 2);
  CHECK(error_of(with(devices::format_record(record(1)))).first == 2); // steps count from 0
  CHECK(error_of(kHeader + "\n" + r0 + "\n" + devices::format_stop({1, "done", {}}) + "\n" + r0 +
                 "\n")
            .first == 4); // a line after the stop record
  CHECK(error_of(kHeader + "\n" + "{\"step\":0,\n" + r0 + "\n").first == 2);
  CHECK(error_of("").first == 1);
  CHECK(error_of("not json\n").first == 1);
}

TEST_CASE("a log of another schema version is refused", "[devices]") {
  std::string h = kHeader;
  h.replace(h.find("\"schema\":2"), 10, "\"schema\":3");
  try {
    devices::LogReader r("s.jsonl", h + "\n");
    FAIL("schema 3 accepted");
  } catch (const InputError& e) {
    CHECK(e.line() == 1);
    CHECK(std::string(e.what()) ==
          "s.jsonl:1:1: schema version 3; this antkit reads schemas 1 to 2");
  }
  h.replace(h.find("\"schema\":3"), 10, "\"schema\":0");
  CHECK_THROWS_AS(devices::LogReader("s.jsonl", h + "\n"), InputError);
}

TEST_CASE("a log of schema 1 (before the identification at connect) is still read", "[devices]") {
  std::string h = kHeader;
  h.replace(h.find("\"schema\":2"), 10, "\"schema\":1");
  devices::LogReader r("s.jsonl", h + "\n");
  CHECK(r.header().schema == 1);
}

TEST_CASE("a last line cut at any byte is reported and every record before it is read",
          "[devices][property]") {
  const std::string r0 = devices::format_record(record(0));
  const std::string r1 = devices::format_record(record(1));
  for (std::size_t cut = 1; cut < r1.size(); ++cut) {
    devices::LogReader reader("c.jsonl", kHeader + "\n" + r0 + "\n" + r1.substr(0, cut));
    devices::LogRecord r;
    REQUIRE(reader.next(r));
    CHECK(r.step == 0);
    CHECK(!reader.next(r));
    CHECK(reader.truncated());
  }
}

TEST_CASE("the writer flushes each record as it is written", "[devices]") {
  const antkit::test::ScratchDir dir("log-flush");
  const std::string path = (dir / "flush.jsonl").string();
  {
    devices::LogWriter w(path, header());
    for (std::int64_t s = 0; s < 3; ++s) {
      w.write(record(s));
      // Another reader sees every record so far while the writer is still open.
      devices::LogReader r(path);
      devices::LogRecord rec;
      std::int64_t n = 0;
      while (r.next(rec)) ++n;
      CHECK(n == s + 1);
      CHECK(!r.truncated());
      CHECK(!r.stop().has_value());
    }
    w.finish({3, "done", {}});
    CHECK(w.records() == 3);
  }
  devices::LogReader r(path);
  devices::LogRecord rec;
  while (r.next(rec)) {
  }
  REQUIRE(r.stop().has_value());
  CHECK(r.stop()->step == 3);
  CHECK_THROWS_AS(devices::LogWriter("/nonexistent/dir/x.jsonl", header()), InputError);
}

TEST_CASE("records_ahead counts the records next() will read", "[devices]") {
  const std::string r0 = devices::format_record(record(0));
  const std::string r1 = devices::format_record(record(1));
  const std::string stop = R"({"stop":"done","step":2,"io":[]})";
  const auto ahead = [](const std::string& text) {
    devices::LogReader reader("a.jsonl", text);
    const std::size_t counted = reader.records_ahead();
    std::size_t read = 0;
    for (devices::LogRecord r; reader.next(r);) ++read;
    CHECK(read == counted);
    return counted;
  };
  CHECK(ahead(kHeader + "\n") == 0);
  CHECK(ahead(kHeader + "\n" + r0 + "\n" + r1 + "\n") == 2);
  CHECK(ahead(kHeader + "\n" + r0 + "\n" + r1 + "\n" + stop + "\n") == 2);
  CHECK(ahead(kHeader + "\n" + r0 + "\n" + r1 + "\n" + stop + "\n\n") == 2); // blank after stop
  CHECK(ahead(kHeader + "\n" + r0 + "\n" + r1) == 2);   // no newline after a whole last record
  for (std::size_t cut = 1; cut + 1 < r1.size(); ++cut) // the last record cut short
    CHECK(ahead(kHeader + "\n" + r0 + "\n" + r1.substr(0, cut)) == 1);
}

TEST_CASE("the fast reader's state hash: every byte at every digit, against the definition",
          "[devices][log][property]") {
  // A canonical line whose hash digits are each replaced, in turn, by every byte value: accepted
  // exactly when the byte is a lower-case hex digit, then with the hash the 16 digits spell.
  const std::string head =
      R"({"step":0,"t_ns":5,"io":[["N\r","n,1\r\n",3]],"obs":[1],"cmd":[2],"odo":[3,4],"state":")";
  const std::string digits = "0123456789abcdef";
  std::string hash = "f0e1d2c3b4a59687";
  std::size_t accepted = 0;
  for (std::size_t at = 0; at < 16; ++at)
    for (int b = 0; b < 256; ++b) {
      std::string h = hash;
      h[at] = static_cast<char>(b);
      const std::string line = head + h + "\"}";
      devices::LogRecord r;
      const bool ok = devices::detail::read_canonical_step(line, r);
      const bool hex = digits.find(static_cast<char>(b)) != std::string::npos;
      INFO("digit " << at << ", byte " << b);
      REQUIRE(ok == hex);
      if (ok) {
        ++accepted;
        std::uint64_t want = 0;
        for (const char c : h) want = want * 16 + digits.find(c);
        REQUIRE(r.state == want);
      }
    }
  CHECK(accepted == 16 * 16);
  // Random hashes, round trip through the writer's text.
  rc::prop("any hash", [&](std::uint64_t v) {
    devices::LogRecord r;
    RC_ASSERT(devices::detail::read_canonical_step(head + antkit::kernel::hash_hex(v) + "\"}", r));
    RC_ASSERT(r.state == v);
  });
}

// The reader's fast path reads a record from where the last one ended, over the rest of the log,
// and takes the line it read to end at the first newline after it (it accepts none inside a
// record): held here on logs of several lines with bytes replaced, inserted or deleted, newlines
// and carriage returns among them (lines split, joined, cut). Every record the reader hands out
// must be what nlohmann-json reads from the line the reader says it read (reader.line()), and
// those lines must come in order.
TEST_CASE("the reader's records are its lines, whatever bytes the lines hold",
          "[devices][property]") {
  std::size_t records = 0, edited_logs_read = 0;
  rc::prop("each record read is its line's, to nlohmann-json", [&] {
    std::string text = kHeader + "\n";
    for (std::int64_t step = 0; step < 4; ++step) {
      devices::LogRecord r = record(step);
      r.io[0].received = *rc::gen::element<std::string>("n,0,0,0,0,0,0,0,0\r\n", "", "\n", "\r\n");
      text += devices::format_record(r) + "\n";
    }
    static const std::string kAlphabet = "\n\n\n\r 0123456789-\"\\{}[],:";
    const auto edits = *rc::gen::inRange(0, 5);
    for (int k = 0; k < edits; ++k) {
      // Anywhere, or (the edits that tell) at a line's end: just before or after a newline.
      auto at = *rc::gen::inRange<std::size_t>(kHeader.size() + 1, text.size() + 1);
      if (const auto nl = text.find('\n', at); *rc::gen::inRange(0, 4) != 0 && nl != text.npos)
        at = nl + 1 - *rc::gen::inRange<std::size_t>(0, 3);
      const char c = kAlphabet[*rc::gen::inRange<std::size_t>(0, kAlphabet.size())];
      edit_byte(text, at, c, *rc::gen::inRange(0, 3));
    }
    std::vector<std::string> lines = {""}; // lines[1] is the header
    for (std::size_t at = 0; at <= text.size();) {
      const auto nl = std::min(text.find('\n', at), text.size());
      lines.push_back(text.substr(at, nl - at));
      at = nl + 1;
    }
    std::size_t last_line = 1;
    bool any = false;
    try {
      devices::LogReader reader("m.jsonl", text);
      for (devices::LogRecord r; reader.next(r);) {
        RC_ASSERT(reader.line() > last_line);
        last_line = reader.line();
        RC_ASSERT(last_line < lines.size());
        const auto theirs = antkit::test::record_by_json_library(lines[last_line]);
        RC_ASSERT(theirs.has_value());
        RC_ASSERT(*theirs == r);
        ++records;
        any = true;
      }
    } catch (const InputError&) {
    }
    if (any && edits > 0) ++edited_logs_read;
  });
  CHECK(records > 0);
  CHECK(edited_logs_read > 0);
}
