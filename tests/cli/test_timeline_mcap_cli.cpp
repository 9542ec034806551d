// `antkit check stc --mcap`, `explore --mcap` and `buffon --mcap` (issue 42: --mcap where a run has
// a timeline), read back with the tests' own MCAP reader (every CRC, index and offset checked):
// a message a step at k * 100 ms, the counts the run's own output gives, the events on /log at
// their steps, and bad input refused with exit 2 and no file.
#include "antkit_child.hpp"
#include "mcap_reader.hpp"
#include "run_antkit.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>
#include <vector>

using antkit::test::run_antkit;
using antkit::test::slurp;
using Catch::Matchers::Contains;

namespace {

struct Read {
  std::map<std::string, std::size_t> counts;                              // topic -> messages
  std::map<std::string, std::vector<antkit::io::mcap::Message>> by_topic; // in file order
};
Read read_mcap(const std::string& path) {
  const auto file = antkit::test::mcap::read(slurp(path));
  Read r;
  for (const auto& m : file.messages) {
    const std::string topic = file.channels.at(m.channel_id).topic;
    ++r.counts[topic];
    r.by_topic[topic].push_back(m);
  }
  return r;
}

// A fresh scratch directory, removed when the test case ends (scratch_dir.hpp).
struct TempDir {
  antkit::test::ScratchDir scratch;
  std::filesystem::path path = scratch.path();
  explicit TempDir(const std::string& name) : scratch(name) {}
  [[nodiscard]] std::string operator/(const std::string& name) const {
    return (path / name).string();
  }
};

} // namespace

TEST_CASE("antkit check stc --mcap: a pose a position, the first broken rule at its position",
          "[cli][mcap]") {
  const TempDir dir("check-stc-mcap");
  // A 4 x 2 free map: two cells of 2 x 2 sub-cells, the exactly-once tour round them from (0, 0).
  std::ofstream(dir / "free.txt") << "....\n....\n";
  std::ofstream(dir / "good.json") << "[[0,0],[1,0],[2,0],[3,0],[3,1],[2,1],[1,1],[0,1]]";
  // The same tour with position 3 back on (1, 0): a repeat at step 3.
  std::ofstream(dir / "bad.json") << "[[0,0],[1,0],[2,0],[1,0],[2,0],[3,0],[3,1],[2,1],[1,1],"
                                     "[0,1]]";
  const auto good = run_antkit("check stc --map " + (dir / "free.txt") + " --path " +
                               (dir / "good.json") + " --mcap " + (dir / "good.mcap"));
  REQUIRE(good.status == 0);
  const Read ok = read_mcap(dir / "good.mcap");
  CHECK(ok.counts.at("/map") == 1);
  CHECK(ok.counts.at("/pose") == 8);
  CHECK(ok.counts.at("/trail") == 8); // n <= 100: every position
  REQUIRE(ok.counts.at("/log") == 2);
  const auto verdict = nlohmann::json::parse(ok.by_topic.at("/log")[1].data);
  CHECK(verdict["level"] == 2);
  CHECK(ok.by_topic.at("/log")[1].sequence == 7);
  CHECK_THAT(verdict["message"].get<std::string>(), Contains("every rule kept"));
  for (const auto& m : ok.by_topic.at("/pose")) {
    CHECK(m.log_time == m.sequence * 100000000ULL);
    const auto body = nlohmann::json::parse(m.data);
    // 1 m a sub-cell, y up from the bottom row: (3, 1) is at (3.5, 0.5), (0, 0) at (0.5, 1.5).
    if (m.sequence == 4) {
      CHECK(body["pose"]["position"]["x"] == 3.5);
      CHECK(body["pose"]["position"]["y"] == 0.5);
    }
    if (m.sequence == 0) CHECK(body["pose"]["position"]["y"] == 1.5);
  }

  const auto bad = run_antkit("check stc --map " + (dir / "free.txt") + " --path " +
                              (dir / "bad.json") + " --format json --mcap " + (dir / "bad.mcap"));
  CHECK(bad.status == 1); // as check stc without --mcap: the rule is broken, the file whole
  const auto j = nlohmann::json::parse(bad.out);
  REQUIRE(j["first_violation"]["step"] == 3);
  const Read broken = read_mcap(dir / "bad.mcap");
  CHECK(broken.counts.at("/pose") == 10);
  std::size_t errors = 0;
  for (const auto& m : broken.by_topic.at("/log")) {
    const auto body = nlohmann::json::parse(m.data);
    if (body["level"] != 4) continue;
    ++errors;
    CHECK(m.sequence == 3);
    CHECK(m.log_time == 300000000ULL);
    CHECK_THAT(body["message"].get<std::string>(), Contains("step 3"));
  }
  CHECK(errors == 1);

  // --cells: the map's two cells are 2 x 2 sub-cells each, half a cell's side (1 m) apiece.
  std::ofstream(dir / "cells.txt") << "..\n";
  const auto cells = run_antkit("check stc --cells --map " + (dir / "cells.txt") + " --path " +
                                (dir / "good.json") + " --mcap " + (dir / "cells.mcap"));
  REQUIRE(cells.status == 0);
  const Read in_cells = read_mcap(dir / "cells.mcap");
  const auto grid = nlohmann::json::parse(in_cells.by_topic.at("/map")[0].data);
  CHECK(grid["column_count"] == 4);
  CHECK(grid["cell_size"]["x"] == 0.5);
  const auto p4 = nlohmann::json::parse(in_cells.by_topic.at("/pose")[4].data);
  CHECK(p4["pose"]["position"]["x"] == 1.75);
  CHECK(p4["pose"]["position"]["y"] == 0.25);

  // Bad input: exit 2, a located error, nothing written.
  std::ofstream(dir / "malformed.csv") << "0,0\n1,x\n";
  const auto malformed = run_antkit("check stc --map " + (dir / "free.txt") + " --path " +
                                    (dir / "malformed.csv") + " --mcap " + (dir / "no1.mcap"));
  CHECK(malformed.status == 2);
  CHECK_THAT(malformed.err, Contains("malformed.csv:2:"));
  CHECK_FALSE(std::filesystem::exists(dir / "no1.mcap"));
  const auto off = run_antkit("check stc --map " + (dir / "free.txt") + " --path " +
                              (dir / "good.json") + " --start 9,9 --mcap " + (dir / "no2.mcap"));
  CHECK(off.status == 2);
  CHECK_FALSE(std::filesystem::exists(dir / "no2.mcap"));
  // --mcap with --bag is refused (bag export writes a bag's tour).
  const auto with_bag = run_antkit("check stc --map " + (dir / "free.txt") +
                                   " --bag x.mcap --topic /p --mcap " + (dir / "no3.mcap"));
  CHECK(with_bag.status == 2);
  CHECK_THAT(with_bag.err, Contains("bag export"));
  CHECK_FALSE(std::filesystem::exists(dir / "no3.mcap"));
  // A tour of more than 2^22 positions is refused before anything is written.
  {
    std::ofstream big(dir / "big.csv");
    std::string chunk;
    for (int i = 0; i < 4096; ++i) chunk += "0,0\n";
    for (int i = 0; i <= 1024; ++i) big << chunk;
  }
  const auto too_long = run_antkit("check stc --map " + (dir / "free.txt") + " --path " +
                                   (dir / "big.csv") + " --mcap " + (dir / "no4.mcap"));
  CHECK(too_long.status == 2);
  CHECK_THAT(too_long.err, Contains("--mcap"));
  CHECK_FALSE(std::filesystem::exists(dir / "no4.mcap"));
}

namespace {

std::string unbase64(const std::string& s) {
  static const std::string alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::uint32_t bits = 0;
  int n = 0;
  for (const char ch : s) {
    if (ch == '=') break;
    bits = (bits << 6) | static_cast<std::uint32_t>(alphabet.find(ch));
    n += 6;
    if (n >= 8) {
      n -= 8;
      out.push_back(static_cast<char>((bits >> n) & 0xff));
    }
  }
  return out;
}

} // namespace

TEST_CASE("antkit explore --mcap: both robots each tick, the line of sight's events at their "
          "ticks, the explored map at the end",
          "[cli][mcap]") {
  const TempDir dir("explore-mcap");
  const std::string map = antkit::test::source_path("data/maps/movingai/room-32-32-4.map");
  const auto r = run_antkit("explore --map " + map +
                            " --algo fast-wall-follow --format json --mcap " + (dir / "run.mcap"));
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto ticks = j["steps"].get<std::size_t>() + 1; // the last tick's observation completes it
  const Read run = read_mcap(dir / "run.mcap");
  CHECK(run.counts.at("/map") == 1);
  CHECK(run.counts.at("/robotA/pose") == ticks);
  CHECK(run.counts.at("/robotB/pose") == ticks);
  CHECK(run.counts.at("/robotA/trail") == run.counts.at("/robotB/trail"));
  CHECK(run.counts.at("/robotA/trail") <= 101);
  REQUIRE(run.counts.at("/explored") == 1);
  for (const auto& topic : {"/robotA/pose", "/robotB/pose"})
    for (const auto& m : run.by_topic.at(topic)) CHECK(m.log_time == m.sequence * 100000000ULL);
  // Robot A's moves: the ticks where its cell changed.
  std::size_t moves = 0;
  const auto& poses = run.by_topic.at("/robotA/pose");
  for (std::size_t k = 1; k < poses.size(); ++k)
    if (nlohmann::json::parse(poses[k].data)["pose"]["position"] !=
        nlohmann::json::parse(poses[k - 1].data)["pose"]["position"])
      ++moves;
  CHECK(moves == j["moves"][0].get<std::size_t>());
  // /log: what ran at 0, the line of sight's changes at their ticks, the result at the last tick.
  const auto& logs = run.by_topic.at("/log");
  REQUIRE(logs.size() >= 2);
  CHECK(logs.front().log_time == 0);
  CHECK(logs.back().sequence == ticks - 1);
  const auto result = nlohmann::json::parse(logs.back().data);
  CHECK(result["level"] == 2);
  CHECK_THAT(result["message"].get<std::string>(),
             Contains("explored " + std::to_string(j["explored"].get<int>()) + " cells"));
  CHECK_THAT(result["message"].get<std::string>(), Contains(j["hash"].get<std::string>()));
  std::size_t events = 0;
  for (std::size_t i = 1; i + 1 < logs.size(); ++i) {
    const std::string text = nlohmann::json::parse(logs[i].data)["message"];
    CHECK(text.rfind("tick " + std::to_string(logs[i].sequence) + ": line of sight", 0) == 0);
    CHECK(logs[i].log_time == logs[i].sequence * 100000000ULL);
    ++events;
  }
  CHECK(events > 0); // the room's walls break the pair's line of sight
  // /explored: the JSON's cells (F S L B N O as 0..5), row 0 the map's bottom row.
  const auto grid = nlohmann::json::parse(run.by_topic.at("/explored")[0].data);
  const std::string data = unbase64(grid["data"].get<std::string>());
  const auto& rows = j["cells"];
  const std::size_t h = rows.size(), w = rows[0].get<std::string>().size();
  REQUIRE(data.size() == w * h);
  const std::string codes = "FSLBNO";
  std::size_t mismatches = 0;
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x)
      if (codes[static_cast<std::size_t>(data[(h - 1 - y) * w + x])] !=
          rows[y].get<std::string>()[x])
        ++mismatches;
  CHECK(mismatches == 0);
  // Bad input: exit 2, nothing written.
  const auto off = run_antkit("explore --map " + map + " --algo frontier --start 99,99 --mcap " +
                              (dir / "no.mcap"));
  CHECK(off.status == 2);
  CHECK_FALSE(std::filesystem::exists(dir / "no.mcap"));
  const auto los_off = run_antkit("explore --size 10x10 --algo fast-wall-follow --los off --mcap " +
                                  (dir / "no2.mcap"));
  CHECK(los_off.status == 2);
  CHECK_FALSE(std::filesystem::exists(dir / "no2.mcap"));
}

TEST_CASE("antkit buffon --mcap: trial 0's two visits one after the other, visit 2's crossings at "
          "their steps",
          "[cli][mcap]") {
  const TempDir dir("buffon-mcap");
  const auto r = run_antkit("buffon --arena circle:d=20 --steps 2000 --trials 2 --format json "
                            "--mcap " +
                            (dir / "run.mcap"));
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto& trial = j["trials"][0];
  const std::size_t n = 2001; // the start and 2000 steps, each visit
  const Read run = read_mcap(dir / "run.mcap");
  CHECK(run.counts.at("/arena") == 1);
  CHECK(run.counts.at("/visit1/pose") == n);
  CHECK(run.counts.at("/visit2/pose") == n);
  CHECK(run.counts.at("/visit1/trail") == 97); // positions 0, 21, ..., 1995 and the last
  CHECK(run.counts.at("/visit2/trail") == 97);
  // Visit 1 from time 0, visit 2 from position n, 100 ms a position.
  const auto& v1 = run.by_topic.at("/visit1/pose");
  const auto& v2 = run.by_topic.at("/visit2/pose");
  CHECK(v1.front().log_time == 0);
  CHECK(v2.front().sequence == n);
  for (const auto* visit : {&v1, &v2})
    for (const auto& m : *visit) CHECK(m.log_time == m.sequence * 100000000ULL);
  // /log: what ran, one line per step of visit 2 that crosses visit 1's trail (at that step), the
  // result; the crossings' running count ends at the trial's exact count.
  const auto& logs = run.by_topic.at("/log");
  REQUIRE(logs.size() >= 2);
  CHECK_THAT(nlohmann::json::parse(logs.front().data)["message"].get<std::string>(),
             Contains("trial 0 of 2"));
  const auto crossings = trial["crossings_exact"].get<std::uint64_t>();
  REQUIRE(crossings > 0);
  CHECK(logs.size() >= 2 + 1);
  CHECK(logs.size() <= 2 + crossings);
  for (std::size_t i = 1; i + 1 < logs.size(); ++i) {
    CHECK(logs[i].sequence >= n);
    CHECK(logs[i].log_time == logs[i].sequence * 100000000ULL);
    const std::string text = nlohmann::json::parse(logs[i].data)["message"];
    CHECK(text.rfind("visit 2 step " + std::to_string(logs[i].sequence - n) + " crosses", 0) == 0);
  }
  CHECK_THAT(nlohmann::json::parse(logs[logs.size() - 2].data)["message"].get<std::string>(),
             Contains("(" + std::to_string(crossings) + " so far)"));
  const auto result = nlohmann::json::parse(logs.back().data)["message"].get<std::string>();
  CHECK(logs.back().sequence == 2 * n - 1);
  CHECK_THAT(result, Contains("crossings " + std::to_string(crossings) + " (exact), BC " +
                              std::to_string(trial["bc"].get<int>())));
  // The bytes do not depend on --threads (trial 0 is the same trial).
  const auto threads = run_antkit("buffon --arena circle:d=20 --steps 2000 --trials 2 --threads 2 "
                                  "--mcap " +
                                  (dir / "threads.mcap"));
  REQUIRE(threads.status == 0);
  CHECK(slurp(dir / "threads.mcap") == slurp(dir / "run.mcap"));
  // Refused before the run, nothing written: the markers rule (one walk, no two visits), visits of
  // more than 2^22 positions together, a bad arena.
  const auto markers =
      run_antkit("buffon --arena circle:d=20 --precision 0.1 --mcap " + (dir / "no1.mcap"));
  CHECK(markers.status == 2);
  CHECK_THAT(markers.err, Contains("--mcap") && Contains("markers"));
  CHECK_FALSE(std::filesystem::exists(dir / "no1.mcap"));
  const auto big =
      run_antkit("buffon --arena circle:d=20 --steps 2100000 --mcap " + (dir / "no2.mcap"));
  CHECK(big.status == 2);
  CHECK_THAT(big.err, Contains("--mcap"));
  CHECK_FALSE(std::filesystem::exists(dir / "no2.mcap"));
  const auto arena = run_antkit("buffon --arena circle:d=-1 --mcap " + (dir / "no3.mcap"));
  CHECK(arena.status == 2);
  CHECK_FALSE(std::filesystem::exists(dir / "no3.mcap"));
}
