// `antkit check stc --mcap`, `explore --mcap` and `buffon --mcap` (issue 42: --mcap where a run has
// a timeline), read back with the tests' own MCAP reader (every CRC, index and offset checked):
// a message a step at k * 100 ms, the counts the run's own output gives, the events on /log at
// their steps, and bad input refused with exit 2 and no file.
#include "mcap_reader.hpp"
#include "run_antkit.hpp"
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
using Catch::Matchers::Contains;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

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

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() /
             ("antkit-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
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
