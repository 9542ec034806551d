// Table 1's states and the order they move in (cell_state.hpp), checked over all 36 pairs.
#include <antkit/los/cell_state.hpp>
#include <array>
#include <catch2/catch.hpp>

using antkit::los::at_or_below;
using antkit::los::CellState;

namespace {
constexpr std::array<CellState, 6> kAll{CellState::F,     CellState::S,    CellState::LOS,
                                        CellState::S_LOS, CellState::NLOS, CellState::O};
}

TEST_CASE("the state order is a partial order with F at the bottom", "[proof]") {
  for (const CellState a : kAll) {
    CHECK(at_or_below(a, a));
    CHECK(at_or_below(CellState::F, a));
    for (const CellState b : kAll) {
      if (a != b && at_or_below(a, b)) CHECK_FALSE(at_or_below(b, a)); // antisymmetric
      for (const CellState c : kAll)
        if (at_or_below(a, b) && at_or_below(b, c)) CHECK(at_or_below(a, c)); // transitive
    }
  }
}

TEST_CASE("the issue's chains are chains of the order and explored states stay explored",
          "[proof]") {
  CHECK(at_or_below(CellState::F, CellState::NLOS));
  CHECK(at_or_below(CellState::NLOS, CellState::LOS));
  CHECK(at_or_below(CellState::LOS, CellState::S_LOS));
  CHECK(at_or_below(CellState::S, CellState::S_LOS));
  CHECK(at_or_below(CellState::F, CellState::O));
  for (const CellState a : kAll)
    for (const CellState b : kAll)
      if (at_or_below(a, b) && antkit::los::is_explored(a)) {
        CHECK(antkit::los::is_explored(b));
        // free stays free, occupied stays occupied
        CHECK(antkit::los::is_known_free(a) == antkit::los::is_known_free(b));
      }
  // Nothing but F moves to NLOS.
  for (const CellState a : kAll)
    if (a != CellState::F && a != CellState::NLOS) CHECK_FALSE(at_or_below(a, CellState::NLOS));
}

TEST_CASE("codes are the command's letters", "[los]") {
  std::string letters;
  for (const CellState s : kAll) letters += antkit::los::code(s);
  CHECK(letters == "FSLBNO");
}
