#pragma once
// The cell states of paper 001, Table 1, and the order in which a cell may move between them.
//
//   F      "Fresh": no idea yet                               (gray)
//   S      free by scanning                                   (brown)
//   LOS    free by line of sight only                         (red)
//   S_LOS  free by scanning and line of sight ("S+LOS")       (yellow)
//   NLOS   potentially occupied, by no line of sight          (blue)
//   O      occupied, by scanning                              (orange)
//
// States only move up. The issue lists the chains F -> NLOS -> LOS -> S+LOS, F -> S -> S+LOS and
// F -> O. Rule 1 ("all free neighbours are assigned S") and rule 5 ("an obstacle ... is assigned
// O") also apply to a scanned NLOS cell, which the chains do not mention; we therefore read "up" as
// the partial order
//     F < NLOS < {S, LOS, O},   S < S+LOS,   LOS < S+LOS
// in which NLOS is still unexplored (it is only "potentially" occupied) and a scan settles it. All
// the chains are chains of this order.
#include <antkit/frontier/frontier_map.hpp>
#include <cstdint>

namespace antkit::los {

enum class CellState : std::uint8_t { F = 0, S = 1, LOS = 2, S_LOS = 3, NLOS = 4, O = 5 };

// The one-letter code of the command's JSON: F S L B N O (B for S+LOS).
constexpr char code(CellState s) noexcept {
  switch (s) {
  case CellState::F:
    return 'F';
  case CellState::S:
    return 'S';
  case CellState::LOS:
    return 'L';
  case CellState::S_LOS:
    return 'B';
  case CellState::NLOS:
    return 'N';
  case CellState::O:
    return 'O';
  }
  return '?';
}

// Rule 6: a cell is explored once it is known free or occupied.
constexpr bool is_explored(CellState s) noexcept {
  return s == CellState::S || s == CellState::LOS || s == CellState::S_LOS || s == CellState::O;
}
constexpr bool is_known_free(CellState s) noexcept {
  return s == CellState::S || s == CellState::LOS || s == CellState::S_LOS;
}

// a <= b in the partial order above (reflexive).
constexpr bool at_or_below(CellState a, CellState b) noexcept {
  if (a == b || a == CellState::F) return true;
  switch (a) {
  case CellState::NLOS:
    return b == CellState::S || b == CellState::LOS || b == CellState::O || b == CellState::S_LOS;
  case CellState::S:
  case CellState::LOS:
    return b == CellState::S_LOS;
  default:
    return false;
  }
}

// What the frontier component needs to know of a state.
constexpr frontier::Knowledge knowledge(CellState s) noexcept {
  if (is_known_free(s)) return frontier::Knowledge::Free;
  if (s == CellState::O) return frontier::Knowledge::Occupied;
  return frontier::Knowledge::Unexplored;
}

} // namespace antkit::los
