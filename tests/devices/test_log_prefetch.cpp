// LogPrefetch (log_prefetch.hpp): the records LogReader::next gives, in order, batch by batch
// with the last batch marked, the prepared text of each, a reader's error after the records
// before it, and LogReader::records_ahead equal to the records read, for every batch size from 1.
#include <antkit/devices/log.hpp>
#include <antkit/devices/log_prefetch.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <string>
#include <vector>

namespace devices = antkit::devices;

namespace {

std::string log_text(int records, bool stop) {
  devices::LogHeader h;
  h.antkit_version = "0.1.0";
  h.robot = "khepera";
  h.port = "/dev/pts/3";
  h.baud = 9600;
  h.framing = "8N2";
  h.controller = "buffon";
  h.seed = 1;
  std::string text = devices::format_header(h) + "\n";
  for (int s = 0; s < records; ++s) {
    devices::LogRecord r;
    r.step = s;
    r.time_ns = 1000 * s;
    r.io = {{"N\r", "n," + std::to_string(s) + "\r\n"}};
    r.obs = {s, -s};
    r.cmd = {1, 2};
    r.odo = {s * 3, s * 5};
    r.state = std::uint64_t{0x9E3779B97F4A7C15U} * static_cast<std::uint32_t>(s);
    text += devices::format_record(r) + "\n";
  }
  if (stop) text += R"({"stop":"done","step":)" + std::to_string(records) + R"(,"io":[]})" + "\n";
  return text;
}

std::vector<devices::LogRecord> read_all(const std::string& text) {
  devices::LogReader reader("t.jsonl", text);
  std::vector<devices::LogRecord> out;
  for (devices::LogRecord r; reader.next(r); r = {}) out.push_back(r);
  return out;
}

} // namespace

TEST_CASE("LogPrefetch gives LogReader's records, batch by batch, the last marked", "[devices]") {
  for (const int records : {0, 1, 2, 7, 8, 9, 64}) {
    for (const bool stop : {true, false}) {
      const std::string text = log_text(records, stop);
      const auto expected = read_all(text);
      REQUIRE(expected.size() == static_cast<std::size_t>(records));
      for (const std::size_t batch : {1U, 2U, 3U, 8U, 4096U})
        for (const auto threads :
             {devices::LogPrefetch::Threads::Auto, devices::LogPrefetch::Threads::Inline}) {
          CAPTURE(records, stop, batch, threads == devices::LogPrefetch::Threads::Inline);
          devices::LogReader reader("t.jsonl", text);
          CHECK(reader.records_ahead() == expected.size());
          std::vector<devices::LogRecord> got;
          std::vector<std::string> texts;
          int lasts = 0;
          {
            devices::LogPrefetch prefetch(
                reader,
                [](const devices::LogRecord& r, devices::LogPrefetch::Prepared& p) {
                  p.text = "step " + std::to_string(r.step);
                  p.cuts[0] = p.text.size();
                },
                batch, threads);
            for (auto b = prefetch.next(); !b.records.empty(); b = prefetch.next()) {
              REQUIRE(b.prepared.size() == b.records.size());
              CHECK(b.records.size() <= batch);
              CHECK(lasts == 0); // nothing after the last batch
              lasts += b.last ? 1 : 0;
              for (std::size_t i = 0; i < b.records.size(); ++i) {
                got.push_back(b.records[i]);
                texts.push_back(b.prepared[i].text);
              }
            }
            CHECK(prefetch.next().records.empty()); // and again
          }
          CHECK(got == expected);
          CHECK(lasts == (records > 0 ? 1 : 0));
          for (std::size_t i = 0; i < texts.size(); ++i)
            CHECK(texts[i] == "step " + std::to_string(i));
          // The reader's end is seen after the last batch: its stop record.
          CHECK(reader.stop().has_value() == stop);
        }
    }
  }
}

TEST_CASE("LogPrefetch throws a reader's error after the records before it", "[devices]") {
  // Record 5 has the wrong step number: records 0 to 4 come first, then LogReader's error.
  std::string text = log_text(9, true);
  const auto at = text.find(R"({"step":5,)");
  REQUIRE(at != std::string::npos);
  text.replace(at, 10, R"({"step":6,)");
  for (const std::size_t batch : {1U, 2U, 4U, 5U, 6U, 4096U})
    for (const auto threads :
         {devices::LogPrefetch::Threads::Auto, devices::LogPrefetch::Threads::Inline}) {
      CAPTURE(batch, threads == devices::LogPrefetch::Threads::Inline);
      devices::LogReader reader("t.jsonl", text);
      devices::LogPrefetch prefetch(reader, {}, batch, threads);
      std::int64_t seen = 0;
      bool last_seen = false;
      std::string error;
      try {
        for (auto b = prefetch.next(); !b.records.empty(); b = prefetch.next()) {
          CHECK(b.prepared.empty());
          last_seen = last_seen || b.last;
          for (const auto& r : b.records) CHECK(r.step == seen++);
        }
      } catch (const antkit::kernel::InputError& e) {
        error = e.what();
      }
      CHECK(seen == 5);
      CHECK_FALSE(last_seen); // a batch cut by an error is not "the last"
      CHECK(error.find("t.jsonl:7:") == 0);
      CHECK(error.find("step 6 where step 5 was expected") != std::string::npos);
    }
}

TEST_CASE("LogPrefetch stopped early joins its thread", "[devices]") {
  const std::string text = log_text(100, true);
  for (const std::size_t batch : {1U, 7U}) {
    devices::LogReader reader("t.jsonl", text);
    devices::LogPrefetch prefetch(reader, {}, batch);
    CHECK(prefetch.next().records.size() == batch);
  } // the destructor stops the reading thread part way
}

TEST_CASE("records_ahead counts a cut last line and a missing stop", "[devices]") {
  const std::string whole = log_text(4, false);
  devices::LogReader a("a.jsonl", whole);
  CHECK(a.records_ahead() == 4);
  // The last record cut short: three records are read (and the log is truncated).
  const std::string cut = whole.substr(0, whole.size() - 10);
  devices::LogReader b("b.jsonl", cut);
  CHECK(b.records_ahead() == 3);
  CHECK(read_all(cut).size() == 3);
  // No newline after a whole last record: it is read, and counted.
  const std::string unterminated = whole.substr(0, whole.size() - 1);
  devices::LogReader c("c.jsonl", unterminated);
  CHECK(c.records_ahead() == 4);
  CHECK(read_all(unterminated).size() == 4);
}
