// A device's report as its command prints it (device_report.hpp): typed fields to one JSON block,
// and the marker-floor robot's two reports' keys (stc_floor/report.hpp).
#include <antkit/devices/device_report.hpp>
#include <antkit/devices/stc_floor/report.hpp>
#include <catch2/catch.hpp>
#include <string>
#include <vector>

namespace devices = antkit::devices;
using devices::ReportField;
using devices::ReportFields;

namespace {
std::vector<std::string> keys(const ReportFields& fields) {
  std::vector<std::string> out;
  for (const auto& f : fields) out.push_back(f.name);
  return out;
}
} // namespace

TEST_CASE("report_json: every field type, in the fields' order", "[devices]") {
  const ReportFields fields{
      {"none", ReportField::Value()},
      {"yes", true},
      {"count", std::int64_t{-3}},
      {"ratio", 0.5},
      {"text", std::string("a \"b\"")},
      {"cell", antkit::kernel::Cell{2, 7}},
      {"path", std::vector<antkit::kernel::Cell>{{0, 0}, {1, 0}}},
      {"empty", std::vector<antkit::kernel::Cell>{}},
      {"hash", devices::ReportHash{0x00ab}},
      {"inner", ReportFields{{"z", std::int64_t{1}}, {"a", ReportField::Value()}}},
  };
  CHECK(devices::report_json(fields) ==
        R"({"none":null,"yes":true,"count":-3,"ratio":0.5,"text":"a \"b\"","cell":[2,7],)"
        R"("path":[[0,0],[1,0]],"empty":[],"hash":"00000000000000ab","inner":{"z":1,"a":null}})");
  CHECK(devices::report_json({}) == "{}");
}

TEST_CASE("the marker-floor robot's reports: the tour with antkit stc's keys, the floor's truth",
          "[devices]") {
  namespace sf = devices::stc_floor;
  sf::Tour tour;
  tour.start = {0, 1};
  tour.path = {{0, 1}, {1, 1}};
  tour.covered = 2;
  tour.turn_ms = 1500;
  CHECK(tour.key() == "tour");
  CHECK(tour.verdict() == sf::Tour::kVerdict);
  // Without a map: no reachable_subcells, and a null hash.
  CHECK(keys(tour.fields()) == std::vector<std::string>{"start", "path", "covered", "repeats",
                                                        "returned_to_start", "hash", "turn_ms"});
  CHECK(devices::report_json(tour.fields()) ==
        R"({"start":[0,1],"path":[[0,1],[1,1]],"covered":2,"repeats":0,)"
        R"("returned_to_start":false,"hash":null,"turn_ms":1500})");
  tour.reachable_subcells = 4;
  tour.tour_hash = 0x1234;
  CHECK(keys(tour.fields()) == std::vector<std::string>{"start", "path", "reachable_subcells",
                                                        "covered", "repeats", "returned_to_start",
                                                        "hash", "turn_ms"});
  sf::FloorTruth truth;
  CHECK(truth.key() == "floor");
  CHECK(truth.verdict().empty());
  CHECK(keys(truth.fields()) == std::vector<std::string>{"map", "start", "frames", "positions",
                                                         "covered", "repeats", "reachable_subcells",
                                                         "max_offset_subcells",
                                                         "max_heading_error_degrees", "clock_s"});
}
