// Fuzz target: the cell-state reader of `antkit check explore` (testing/src/run_audit.cpp) and the
// soundness audit. Bad input must be an InputError; accepted states are a non-empty rectangle, and
// their audit against a map of the same size counts every cell once.
#include "fuzz_bytes.hpp"

#include <antkit/kernel/input_error.hpp>
#include <antkit/testing/run_audit.hpp>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antkit;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  kernel::Grid<los::CellState> states;
  try {
    states = testing::read_los_cells(text, "fuzz");
  } catch (const kernel::InputError&) {
    return 0;
  }
  ANTKIT_FUZZ_REQUIRE(states.width() >= 1 && states.height() >= 1);
  kernel::OccupancyGrid map(states.width(), states.height(), kernel::Occupancy::Free);
  for (std::size_t i = 0; i < map.size(); i += 3) map.cells()[i] = kernel::Occupancy::Blocked;
  const auto a = testing::audit_los_cells(map, states);
  const auto total = std::accumulate(a.by_state.begin(), a.by_state.end(), std::int64_t{0});
  ANTKIT_FUZZ_REQUIRE(total == static_cast<std::int64_t>(map.size()));
  ANTKIT_FUZZ_REQUIRE(a.ok() == (a.known_free_not_free == 0 && a.obstacle_but_free == 0));
  return 0;
}
