#pragma once
// `full`: STC that keeps partially blocked cells (after Gabriely & Rimon's Full-STC, 2003). The
// issue asks that every free sub-cell reachable from the start be covered, with the repeats
// counted.
//
// Model (our construction; the 2003 paper's own handling of partially occupied cells is not in
// paper 002, so the choices are written down here):
//   * A cell's free sub-cells split into parts: sub-cells q and q + 1 of a cell are joined when
//   both
//     are free (they are 4-adjacent), so a part is the whole 4-cycle, a run of 1 to 3 sub-cells, or
//     one of two diagonal singles. Parts joined by a free 4-adjacent pair of sub-cells across a
//     side are neighbours; this graph is connected exactly where the free sub-cells are, so a tree
//     of it reaches every reachable free sub-cell.
//   * The tree is depth-first, with the exact variants' scan order (the root from the start
//     quadrant's side, every other part counter-clockwise after the side it was entered from). On a
//     map with no partial cells the tree is the exact variants' tree.
//   * Across a side d the robot prefers the exact variants' crossing (out from sub-cell d, back
//   into
//     sub-cell d + 1); where one of those sub-cells is blocked it uses the other free pair on that
//     side, for both ways if need be.
//   * Inside a part the robot walks counter-clockwise around a whole 4-cycle (keeping the tree on
//   its
//     left, as in the exact tour) and along the run otherwise. Before leaving a part for the last
//     time it covers whatever sub-cells of the part it has not yet entered, by the shortest walk
//     (tried over every order of the at most three of them). Those walks are where repeats come
//     from: a sub-cell entered again is a repeat.
//   * The tour ends in the start part, at the start sub-cell or a sub-cell 4-adjacent to it, once
//     everything is covered.
// The plan is computed from the known map (like `offline`) and replayed by a controller. Its
// memory is linear in the map (a byte per sub-cell and a stack of parts), which is fine for the
// map sizes it is meant for; the exact variants are the ones built for huge maps.
#include <antkit/stc/subcell.hpp>
#include <cstdint>
#include <vector>

namespace antkit::stc {

// The whole tour, the start first. Throws kernel::InputError when the start sub-cell is outside
// the cell area or blocked.
std::vector<SubCell> full_stc_tour(const kernel::OccupancyGrid& map, SubCell start);

class FullStc {
public:
  struct Observation {};
  using Command = stc::Command;

  FullStc(const kernel::OccupancyGrid& map, SubCell start);

  Command step(const Observation&);

private:
  std::vector<std::uint8_t> moves_; // directions
  std::size_t next_ = 0;
};

} // namespace antkit::stc
