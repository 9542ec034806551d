// write_stc_tour (experiments/stc_tour.hpp), the tour `antkit stc` streams: the JSON document's
// path and counts are run_stc's (and its tour keeps its invariants, stc::keeps_invariants), the
// path files (CSV and binary) hold the same positions, and a start run_stc refuses is named as the
// caller asks, with no byte of JSON and no path file.
#include "scratch_dir.hpp"

#include <antkit/experiments/stc_tour.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/path_format.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
namespace stc = antkit::stc;

namespace {

OccupancyGrid room() {
  OccupancyGrid map(12, 10, Occupancy::Free);
  for (std::int32_t y = 2; y < 6; ++y) map.at({6, y}) = Occupancy::Blocked;
  map.at({7, 3}) = Occupancy::Blocked;
  return map;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

TEST_CASE("write_stc_tour: the streamed JSON and path files are run_stc's tour", "[stc]") {
  const auto map = room();
  const antkit::test::ScratchDir scratch("stc-tour");
  const fs::path& dir = scratch.path();
  for (const auto variant : {stc::Variant::Offline, stc::Variant::Ant, stc::Variant::Full}) {
    const Cell start{0, 0};
    const auto expected = stc::run_stc(map, start, variant);
    for (const bool binary : {false, true}) {
      std::ostringstream json;
      antkit::experiments::StcTourOutput out;
      out.json = &json;
      out.path_file = dir / (binary ? "p.bin" : "p.csv");
      out.binary_path = binary;
      const auto r = antkit::experiments::write_stc_tour(map, start, variant, {}, out);
      CHECK(r.hash == expected.hash);
      CHECK(stc::keeps_invariants(r));
      CHECK(r.path.empty()); // not kept unless asked for
      const auto j = nlohmann::json::parse(json.str());
      CHECK(j["variant"] == std::string(stc::variant_name(variant)));
      CHECK(j["width"] == 12);
      CHECK(j["height"] == 10);
      CHECK(j["covered"] == expected.covered);
      CHECK(j["repeats"] == expected.repeats);
      CHECK(j["hash"] == antkit::kernel::hash_hex(expected.hash));
      CHECK_FALSE(j.contains("noise_ppm"));
      REQUIRE(j["path"].size() == expected.path.size());
      for (std::size_t i = 0; i < expected.path.size(); ++i) {
        CHECK(j["path"][i][0] == expected.path[i].x);
        CHECK(j["path"][i][1] == expected.path[i].y);
      }
      const std::string file = slurp(out.path_file);
      if (binary) {
        CHECK(file == stc::path_format::encode(12, 10, expected.path));
      } else {
        std::string csv = "x,y\n";
        for (const auto& s : expected.path)
          csv += std::to_string(s.x) + "," + std::to_string(s.y) + "\n";
        CHECK(file == csv);
      }
    }
  }
  SECTION("marker noise adds its level and seed; the path is kept for a picture") {
    std::ostringstream json;
    antkit::experiments::StcTourOutput out;
    out.json = &json;
    out.keep_path = true;
    out.seed = 5;
    const stc::NoiseModel noise{10000, 5, 0};
    const auto r = antkit::experiments::write_stc_tour(map, {0, 0}, stc::Variant::Ant, noise, out);
    CHECK(static_cast<std::int64_t>(r.path.size()) == r.positions);
    antkit::experiments::save_stc_tour_figure(map, r, "room", dir / "tour.svg", "");
    CHECK(fs::exists(dir / "tour.svg"));
    const auto j = nlohmann::json::parse(json.str());
    CHECK(j["noise_ppm"] == 10000);
    CHECK(j["seed"] == 5);
  }
  SECTION("keeps_invariants: a repeat breaks an exact tour, not a full one") {
    auto r = stc::run_stc(map, {0, 0}, stc::Variant::Ant);
    REQUIRE(stc::keeps_invariants(r));
    r.repeats = 1;
    CHECK_FALSE(stc::keeps_invariants(r));
    r.variant = stc::Variant::Full;
    CHECK(stc::keeps_invariants(r));
    r.covered -= 1;
    CHECK_FALSE(stc::keeps_invariants(r));
  }
  SECTION("a refused start: named as asked, no JSON, no path file") {
    std::ostringstream json;
    antkit::experiments::StcTourOutput out;
    out.json = &json;
    out.path_file = dir / "refused.bin";
    out.binary_path = true;
    out.start_where = "--start";
    try {
      (void)antkit::experiments::write_stc_tour(map, {6, 2}, stc::Variant::Ant, {}, out);
      FAIL("the start in an obstacle was accepted");
    } catch (const antkit::kernel::InputError& e) {
      CHECK(e.where() == "--start");
    }
    CHECK(json.str().empty());
    CHECK_FALSE(fs::exists(out.path_file));
    for (const auto& entry : fs::directory_iterator(dir))
      CHECK(entry.path().filename().string().find("refused") == std::string::npos);
  }
}
