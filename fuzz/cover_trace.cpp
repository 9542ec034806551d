// Fuzz target: the coverage-trace reader of `antkit check cover` (testing/src/run_audit.cpp) and
// the audit it feeds. Bad input must be an InputError; an accepted trace has its robots in every
// tick, and its audit on a small map with walls adds up (viewed <= viewable <= free cells, every
// counted violation reported as the first one).
#include "fuzz_bytes.hpp"

#include <antkit/kernel/input_error.hpp>
#include <antkit/testing/run_audit.hpp>
#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antkit;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  testing::CoverTrace t;
  try {
    t = testing::read_cover_trace(text, "fuzz");
  } catch (const kernel::InputError&) {
    return 0;
  }
  ANTKIT_FUZZ_REQUIRE(t.robots >= 1 && !t.cells.empty());
  ANTKIT_FUZZ_REQUIRE(t.cells.size() == t.bearings.size());
  for (std::size_t k = 0; k < t.cells.size(); ++k) {
    ANTKIT_FUZZ_REQUIRE(t.cells[k].size() == static_cast<std::size_t>(t.robots));
    ANTKIT_FUZZ_REQUIRE(t.bearings[k].size() == static_cast<std::size_t>(t.robots));
  }
  if (t.cells.size() * static_cast<std::size_t>(t.robots) > 4096) return 0; // keep runs quick
  kernel::OccupancyGrid map(8, 6, kernel::Occupancy::Free);
  for (std::int32_t y = 0; y < 4; ++y) map[{4, y}] = kernel::Occupancy::Blocked;
  map[{1, 1}] = kernel::Occupancy::Unknown;
  const auto a = testing::audit_cover_trace(map, t, t.sensor.value_or(2) % 4);
  ANTKIT_FUZZ_REQUIRE(a.viewed <= a.viewable && a.viewable <= 43); // 48 cells, 4 blocked, 1 unknown
  ANTKIT_FUZZ_REQUIRE(a.moves + a.turns <= (a.ticks - 1) * a.robots);
  ANTKIT_FUZZ_REQUIRE(a.ok() == (a.illegal_moves == 0 && a.bad_turns == 0 && a.collisions == 0 &&
                                 a.claims_match && a.first.empty()));
  return 0;
}
