// `antkit buffon-from-logs` as the real executable (issue 26): visits recorded by `antkit record`
// against `antkit emulate` over a pty; each refusal exits 2 with the file and the reason, and a
// measurement exits 0 with the erosion-corrected area and its interval beside the raw one.
#include "antkit_child.hpp"
#include "run_antkit.hpp"

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using antkit::test::Emulator;
using antkit::test::run_antkit;

namespace {

antkit::test::ScratchDir scratch_dir(const std::string& name) {
  return antkit::test::scratch_dir("bfl-cli", name);
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

void write_lines(const std::string& path, const std::vector<std::string>& lines) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  for (const auto& l : lines) out << l << '\n';
}

// `antkit record` of one run on `emu` into `out`.
void record(const Emulator& emu, const std::string& device, const std::string& controller_args,
            int steps, const std::string& out) {
  const auto r =
      run_antkit("record --device " + device + " --port " + emu.port() + " " + controller_args +
                 " --steps " + std::to_string(steps) + " --out " + out + " --format json");
  INFO(r.err);
  REQUIRE(r.status == 0);
}

// The header as `antkit record --arena SPEC` writes it (LogHeader::arena, the last key).
void name_arena(const std::string& path, const std::string& spec) {
  auto lines = lines_of(path);
  REQUIRE(!lines.empty());
  lines[0].pop_back();
  lines[0] += ",\"arena\":\"" + spec + "\"}";
  write_lines(path, lines);
}

void check_refused(const std::string& args, const std::string& where, const std::string& why) {
  const auto r = run_antkit("buffon-from-logs " + args + " --format json");
  INFO(args);
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find("antkit: error: " + where) != std::string::npos);
  CHECK(r.err.find(why) != std::string::npos);
}

} // namespace

TEST_CASE("antkit buffon-from-logs: refusals exit 2 with the file and why, a measurement exits 0 "
          "with the corrected area and its interval",
          "[cli][devices][buffon-from-logs]") {
  const auto dir = scratch_dir("main");
  const auto path = [&dir](const std::string& name) { return (dir / name).string(); };
  const auto v1 = path("v1.jsonl"), v2 = path("v2.jsonl"), rs = path("rs.jsonl");
  const auto other1 = path("other-v1.jsonl"), puck2 = path("epuck-v2.jsonl");
  // An emulator per run, all with one seed: each run starts at the arena's start pose (one emulator
  // for runs in turn may serve a run that opens before it saw the last one close as the same
  // session, starting it where the last one ended).
  const auto run = [](const std::string& device, const std::string& controller_args, int steps,
                      const std::string& out) {
    Emulator emu({device, "--arena", "circle:d=8", "--seed", "5"});
    record(emu, device, controller_args, steps, out);
  };
  run("khepera", "--controller buffon --visit 1", 1500, v1);
  run("khepera", "--controller buffon --visit 2", 1500, v2);
  run("khepera", "--controller rs", 100, rs);
  run("khepera", "--controller buffon --visit 1 --seed 9", 100, other1);
  run("epuck", "--controller buffon --visit 2", 100, puck2);

  SECTION("refusals") {
    check_refused(v1 + " " + v1, v1 + ":1:1:", "the same file as VISIT1");
    const auto copy = path("copy.jsonl");
    std::filesystem::copy_file(v1, copy, std::filesystem::copy_options::overwrite_existing);
    check_refused(v1 + " " + copy, copy + ":1:1:", "two copies of one run");
    check_refused(v1 + " " + rs, rs + ":1:", "controller 'rs' is not a Buffon visit");
    check_refused(rs + " " + v2, rs + ":1:", "controller 'rs' is not a Buffon visit");
    check_refused(v2 + " " + v1, v2 + ":1:",
                  "a visit-2 log (its header says \"visit\":2) given as "
                  "VISIT1");
    check_refused(v1 + " " + other1, other1 + ":1:",
                  "a visit-1 log (its header says \"visit\":1) "
                  "given as VISIT2");
    check_refused(v1 + " " + puck2, puck2 + ":1:",
                  "robot 'epuck' but visit 1 was recorded on "
                  "'khepera'");
    const auto a1 = path("a1.jsonl"), a2 = path("a2.jsonl");
    std::filesystem::copy_file(v1, a1, std::filesystem::copy_options::overwrite_existing);
    std::filesystem::copy_file(v2, a2, std::filesystem::copy_options::overwrite_existing);
    name_arena(a1, "circle:d=8");
    name_arena(a2, "square:area=50");
    check_refused(a1 + " " + a2, a2 + ":1:",
                  "arena 'square:area=50' but visit 1 was recorded in "
                  "'circle:d=8'");
    std::filesystem::copy_file(v2, a2, std::filesystem::copy_options::overwrite_existing);
    name_arena(a2, "circle:d=8");
    check_refused(a1 + " " + a2 + " --arena circle:d=20",
                  "--arena:", "'circle:d=20' but the logs' headers name arena 'circle:d=8'");
    check_refused(v1 + " " + v2 + " --arena circle:d=0", "--arena:", "");
    // One arena written two ways is one arena (compared as arenas, not as text).
    const auto same =
        run_antkit("buffon-from-logs " + a1 + " " + a2 + " --arena circle:d=8.0 --format json");
    INFO(same.err);
    CHECK(same.status == 0);

    // A visit is measured only as recorded: a log that does not replay, and one cut short.
    auto lines = lines_of(v2);
    REQUIRE(lines.size() > 102);
    const auto state = lines[101].find("\"state\":\"");
    REQUIRE(state != std::string::npos);
    char& digit = lines[101][state + 9];
    digit = digit == '0' ? '1' : '0'; // step 100's controller state hash, edited
    const auto edited = path("edited.jsonl");
    write_lines(edited, lines);
    check_refused(v1 + " " + edited, edited + ":102:1:", "does not replay at step 100, state");
    lines = lines_of(v2);
    lines.pop_back(); // its stop record
    const auto cut = path("cut.jsonl");
    write_lines(cut, lines);
    check_refused(v1 + " " + cut, cut + ":1502:1:", "no stop record after 1500 steps");
  }

  SECTION("the measurement: corrected area and interval, the raw one beside it") {
    const auto r = run_antkit("buffon-from-logs " + v1 + " " + v2 + " --format json");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    // The keys of issue 13 stay (test_devices_cli.cpp reads them).
    for (const char* key : {"robot", "diameter_m", "visit1", "visit2", "width", "bc",
                            "crossings_exact", "area", "area_m2", "area_bc", "area_bc_m2"})
      CHECK(j.contains(key));
    CHECK(j["visit1"]["steps"] == 1500);
    CHECK(j["visit1"]["hash"].get<std::string>().size() == 16);
    REQUIRE(j["area_corrected"].is_number());
    REQUIRE(j["area_raw"].is_number());
    CHECK(j["area_raw"] == j["area"]);
    CHECK(j["area_corrected"].get<double>() ==
          j["area_raw"].get<double>() * j["erosion_factor"].get<double>());
    CHECK(j["erosion_factor"].get<double>() > 1);
    CHECK(j["wall_encounters"].get<int>() > 0);
    REQUIRE(j["area_corrected_ci"].size() == 2);
    CHECK(j["area_corrected_ci"][0].get<double>() < j["area_corrected"].get<double>());
    CHECK(j["area_corrected_ci"][1].get<double>() > j["area_corrected"].get<double>());
    CHECK(j["area_raw_ci"][0].get<double>() < j["area_raw"].get<double>());
    CHECK(j["area_corrected_m2"].is_number());
    CHECK(j["arena"].is_null());
    CHECK(j["arena_source"].is_null());
    CHECK(j["area_true"].is_null());
    CHECK(j["relative_error"].is_null());

    // --arena supplies the true area when the headers do not name it.
    const auto k = nlohmann::json::parse(
        run_antkit("buffon-from-logs " + v1 + " " + v2 + " --arena circle:d=8 --format json").out);
    CHECK(k["arena"] == "circle:d=8");
    CHECK(k["arena_source"] == "--arena");
    REQUIRE(k["area_true"].is_number());
    CHECK(k["area_true"].get<double>() == Approx(3.14159265 * 16).epsilon(0.01));
    CHECK(k["relative_error"].get<double>() ==
          (k["area_corrected"].get<double>() - k["area_true"].get<double>()) /
              k["area_true"].get<double>());
    CHECK(k["area_corrected"] == j["area_corrected"]);

    // Headers that name the arena: the same, from the logs.
    const auto a1 = path("n1.jsonl"), a2 = path("n2.jsonl");
    std::filesystem::copy_file(v1, a1, std::filesystem::copy_options::overwrite_existing);
    std::filesystem::copy_file(v2, a2, std::filesystem::copy_options::overwrite_existing);
    name_arena(a1, "circle:d=8");
    name_arena(a2, "circle:d=8");
    const auto h = run_antkit("buffon-from-logs " + a1 + " " + a2 + " --format json");
    REQUIRE(h.status == 0);
    const auto n = nlohmann::json::parse(h.out);
    CHECK(n["arena_source"] == "logs");
    CHECK(n["area_true"] == k["area_true"]);
    CHECK(n["relative_error"] == k["relative_error"]);

    // The table, for people: the corrected area, its interval, and the raw one, each named.
    const auto t = run_antkit("buffon-from-logs " + a1 + " " + a2);
    REQUIRE(t.status == 0);
    for (const char* word : {"area_corrected", "area_corrected_ci", "area_raw", "area_true",
                             "relative_error", "circle:d=8"})
      CHECK(t.out.find(word) != std::string::npos);
  }
}
