// The Coq model of the line-of-sight cell states (proofs/coq/LosStates.v) and the shipped
// antkit::los::ExplorationMap, held to each other: proof.coq.LosStates requires coqc's `Compute`
// output to equal proofs/golden/LosStates.out, and this test requires the shipped code to produce
// the same transition table and order. Tested correspondence, not a proof about the C++ code.
#include "coq_golden.hpp"
#include "test_paths.hpp"

#include <antkit/los/cell_state.hpp>
#include <antkit/los/exploration_map.hpp>
#include <array>
#include <catch2/catch.hpp>
#include <cctype>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using antkit::kernel::Cell;
using antkit::los::CellState;
using antkit::los::ExplorationMap;
using antkit::los::Sensed;

// The model's events, in the golden table's column order.
enum class Event { ScanFree, ScanObstacle, Seen, NotSeen };

// On a 3x3 map, the target cell T = (1, 0) is the north neighbour of a robot at (1, 1) and the
// only interior cell of the line from (0, 0) to (2, 0).
constexpr Cell kTarget{1, 0};

void apply(ExplorationMap& map, Event e) {
  std::array<Sensed, 8> sensed;
  sensed.fill(Sensed::Outside);
  switch (e) {
  case Event::ScanFree:
  case Event::ScanObstacle:
    sensed[2] = e == Event::ScanFree ? Sensed::Free : Sensed::Obstacle; // index 2 is N
    map.scan({1, 1}, sensed);
    break;
  case Event::Seen:
  case Event::NotSeen:
    map.sweep_line({0, 0}, {2, 0}, e == Event::Seen);
    break;
  }
}

// Events that bring T from F to each state (by the paper's rules), in CellState order.
const std::array<std::vector<Event>, 6> kReach{{
    {},                             // F
    {Event::ScanFree},              // S
    {Event::Seen},                  // LOS
    {Event::ScanFree, Event::Seen}, // S_LOS
    {Event::NotSeen},               // NLOS
    {Event::ScanObstacle},          // O
}};

} // namespace

TEST_CASE("the shipped LOS cell-state transitions equal the Coq model's golden table",
          "[proofs][los]") {
  const auto vectors =
      antkit::test::coq_golden_vectors(antkit::test::source_path("proofs/golden/LosStates.out"));
  REQUIRE(vectors.size() >= 2);
  const std::vector<int>& table = vectors[0]; // 6 states x 4 events
  REQUIRE(table.size() == 24);
  for (int s = 0; s < 6; ++s) {
    for (int e = 0; e < 4; ++e) {
      ExplorationMap map(3, 3);
      for (Event r : kReach[static_cast<std::size_t>(s)]) apply(map, r);
      REQUIRE(static_cast<int>(map.at(kTarget)) == s);
      apply(map, static_cast<Event>(e));
      INFO("state " << s << ", event " << e);
      CHECK(static_cast<int>(map.at(kTarget)) == table[static_cast<std::size_t>(s * 4 + e)]);
    }
  }
}

TEST_CASE("the shipped cell-state order equals the Coq model's golden order", "[proofs][los]") {
  const auto vectors =
      antkit::test::coq_golden_vectors(antkit::test::source_path("proofs/golden/LosStates.out"));
  REQUIRE(vectors.size() >= 2);
  const std::vector<int>& order = vectors[1]; // 6 x 6
  REQUIRE(order.size() == 36);
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) {
      INFO(a << " at or below " << b);
      CHECK(antkit::los::at_or_below(static_cast<CellState>(a), static_cast<CellState>(b)) ==
            (order[static_cast<std::size_t>(a * 6 + b)] == 1));
    }
}
