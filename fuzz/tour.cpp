// Fuzz target: the tour reader of `antkit check stc` (testing/src/stc_audit.cpp) and the audit it
// feeds. Bad input must be an InputError; an accepted tour must read back the same from its CSV
// and JSON forms, in x,y and as row,col pairs (by header and by --order), and its audit on a small
// map (with blocked sub-cells, a partly blocked cell and an odd column) must add up: every position
// is a first entry, a repeat or off limits, and the covered and missed sub-cells make the reachable
// ones.
#include "fuzz_bytes.hpp"

#include <antkit/kernel/input_error.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antkit;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  testing::TourFile tour;
  try {
    tour = testing::read_tour(text, "fuzz");
  } catch (const kernel::InputError&) {
    return 0;
  }
  // The tour's pairs as CSV lines and a JSON array, x,y or (rc) row,col.
  const auto written = [&](bool rc) {
    std::string csv, json = "[";
    for (std::size_t i = 0; i < tour.path.size(); ++i) {
      const auto c = tour.path[i];
      const auto a = std::to_string(rc ? c.y : c.x), b = std::to_string(rc ? c.x : c.y);
      csv += a + "," + b + "\n";
      json += (i ? ",[" : "[") + a + "," + b + "]";
    }
    return std::pair{csv, json + "]"};
  };
  const auto [csv, json] = written(false);
  if (!tour.path.empty())
    ANTKIT_FUZZ_REQUIRE(testing::read_tour("x,y\n" + csv, "csv").path == tour.path);
  ANTKIT_FUZZ_REQUIRE(testing::read_tour("{\"path\": " + json + "}", "json").path == tour.path);
  // The same positions as row,col pairs: by header, and by order (CSV and JSON).
  const auto [rc, rc_json] = written(true);
  if (!tour.path.empty()) {
    ANTKIT_FUZZ_REQUIRE(testing::read_tour("row,col\n" + rc, "rc").path == tour.path);
    ANTKIT_FUZZ_REQUIRE(testing::read_tour(rc, "rc", testing::TourOrder::RowCol).path == tour.path);
  }
  ANTKIT_FUZZ_REQUIRE(testing::read_tour(rc_json, "rc", testing::TourOrder::RowCol).path ==
                      tour.path);

  kernel::OccupancyGrid map(7, 4, kernel::Occupancy::Free);
  map[{2, 0}] = kernel::Occupancy::Blocked; // cell (1, 0) partly blocked
  for (std::int32_t y = 2; y < 4; ++y) map[{4, y}] = map[{5, y}] = kernel::Occupancy::Blocked;
  const kernel::Cell start = tour.start.value_or(kernel::Cell{0, 0});
  for (const auto rule : {testing::TourRule::ExactlyOnce, testing::TourRule::Coverage}) {
    const auto a = testing::audit_stc_tour(map, start, tour.path, rule);
    ANTKIT_FUZZ_REQUIRE(a.covered + a.repeats + a.off_limits == a.positions);
    ANTKIT_FUZZ_REQUIRE(a.covered + a.missed == a.reachable);
    ANTKIT_FUZZ_REQUIRE(a.missed >= 0 && a.illegal_moves < a.positions + (a.positions == 0));
    ANTKIT_FUZZ_REQUIRE(!a.ok() || (a.missed == 0 && a.off_limits == 0 && a.illegal_moves == 0));
    ANTKIT_FUZZ_REQUIRE(rule != testing::TourRule::ExactlyOnce || !a.ok() || a.repeats == 0);
  }
  return 0;
}
