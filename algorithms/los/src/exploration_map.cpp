#include <antkit/kernel/raster.hpp>
#include <antkit/los/exploration_map.hpp>

namespace antkit::los {

using kernel::Cell;

ExplorationMap::ExplorationMap(std::int32_t width, std::int32_t height)
    : states_(width, height, CellState::F), frontiers_(width, height) {
  changes_.reserve(64);
}

void ExplorationMap::raise(Cell c, CellState to) {
  CellState& s = states_[c];
  if (s == to || !at_or_below(s, to)) return; // never down, never sideways
  if (!is_explored(s) && is_explored(to)) ++explored_;
  s = to;
  frontiers_.set(c, knowledge(to));
  changes_.push_back({static_cast<std::uint32_t>(states_.index(c)), to});
}

void ExplorationMap::scanned_free(Cell c) {
  switch (states_[c]) {
  case CellState::F:
  case CellState::NLOS:
    raise(c, CellState::S);
    break; // rule 1
  case CellState::LOS:
    raise(c, CellState::S_LOS);
    break; // rule 2
  default:
    break;
  }
}

void ExplorationMap::scan(Cell robot, const std::array<Sensed, 8>& sensed) {
  if (!states_.in_bounds(robot)) return;
  scanned_free(robot);
  for (std::size_t k = 0; k < kernel::kNeighbours8.size(); ++k) {
    const Cell c = robot + kernel::kNeighbours8[k];
    if (!states_.in_bounds(c)) continue;
    switch (sensed[k]) {
    case Sensed::Free:
    case Sensed::Robot:
      scanned_free(c);
      break;
    case Sensed::Obstacle:
      raise(c, CellState::O);
      break; // rule 5
    case Sensed::Outside:
      break;
    }
  }
}

void ExplorationMap::sweep_line(Cell a, Cell b, bool seen) {
  if (a == b) return;
  // The interior of the supercover: every cell but a and b (they lie between a and b, so in the
  // grid whenever a and b are).
  Cell prev_end = b;
  kernel::for_each_supercover_cell(a, b, [&](Cell c) {
    if (c == a || c == prev_end || !states_.in_bounds(c)) return;
    const CellState s = states_[c];
    if (seen) {
      if (s == CellState::F || s == CellState::NLOS)
        raise(c, CellState::LOS); // rule 3.1
      else if (s == CellState::S)
        raise(c, CellState::S_LOS); // rule 3.2
    } else if (s == CellState::F) {
      raise(c, CellState::NLOS); // rule 4
    }
  });
}

} // namespace antkit::los
