// The ant-edge marker: the rule that infers a cell's covered sub-cells from its lit edges (paper
// 002's five boxes), checked over every way an STC tour can pass through a cell.
#include <antkit/stc/ant.hpp>
#include <antkit/stc/world.hpp>
#include <catch2/catch.hpp>

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using namespace antkit::stc;

namespace {

// The moves of one pass history through the centre cell (1, 1) of a 3 x 3-cell world, in the
// motion model of the tour: the robot enters at sub-cell `entry` and leaves each of `left`
// sub-cells in turn, either walking on around the cell (e -> e + 1) or across the cell's side e
// (to a neighbour and, unless it is the last, back into e + 1).
struct Pass {
  int entry;
  int left;         // how many sub-cells have been left (0..4)
  unsigned crossed; // bit i: the i-th sub-cell left was left across the side
};

// Drives the world through the pass with real moves, marking as the controllers do (every move
// marks). An excursion across a side that is not the last one is a childless child: the robot goes
// around the neighbour cell and comes back into e + 1, lighting the neighbour's boxes (one of them
// on the side it shares with the centre). Returns the set of sub-cells of the centre left (bit q).
unsigned drive(StcWorld& world, const Pass& p) {
  unsigned left = 0;
  int q = p.entry;
  for (int i = 0; i < p.left; ++i) {
    const bool cross = ((p.crossed >> i) & 1u) != 0;
    const bool last = i + 1 == p.left;
    if (cross) {
      REQUIRE(world.apply({move_towards(q), true}));
      if (!last) {
        for (int k = 0; k < 3; ++k) REQUIRE(world.apply({move_towards(dir_add(q, k)), true}));
        REQUIRE(world.apply({move_towards(dir_add(q, 2)), true}));
      }
    } else {
      REQUIRE(world.apply({move_towards(dir_add(q, 1)), true}));
    }
    left |= 1u << q;
    q = dir_add(q, 1);
  }
  return left;
}

} // namespace

TEST_CASE("edge rule: over every pass through a cell and every state of the neighbours' edges - "
          "the lit boxes say exactly which sub-cells were left",
          "[stc][proof]") {
  const OccupancyGrid map(6, 6, Occupancy::Free);
  StcWorld world;
  int cases = 0;
  for (int entry = 0; entry < 4; ++entry)
    for (int left = 0; left <= 4; ++left)
      for (unsigned crossed = 0; crossed < (1u << left); ++crossed)
        for (unsigned outside = 0; outside < 16; ++outside) {
          // A fourth sub-cell is never left by walking on: that would re-enter the first one.
          if (left == 4 && ((crossed >> 3) & 1u) == 0) continue;
          world.reset(map, subcell_of({1, 1}, entry), {}, Marker::Edge);
          // The neighbours' own passes may have lit the centre's bits 8..11 (their turn boxes).
          for (int e = 0; e < 4; ++e)
            if ((outside >> e) & 1u) world.light_edge(subcell_of({1, 1}, e), e);
          const unsigned truth = drive(world, {entry, left, crossed});
          const std::uint16_t edges = world.cell_edges({1, 1});
          INFO("entry " << entry << ", left " << left << ", crossed " << crossed << ", outside "
                        << outside << ", edges " << edges);
          REQUIRE(covered_from_edges(edges) == truth);
          // Seen from the uncovered sub-cell the robot enters next from outside the cell (its first
          // entry, or its return from the excursion it is on), the paper's five boxes and rule
          // give the same answer.
          const int next = dir_add(entry, left);
          const bool from_outside = left == 0 || ((crossed >> (left - 1)) & 1u) != 0;
          if (left < 4 && from_outside) {
            const std::uint8_t relative = paper_rule(paper_boxes(edges, next));
            unsigned absolute = 0;
            for (int r = 1; r <= 3; ++r)
              if ((relative >> r) & 1u) absolute |= 1u << dir_add(next, r);
            REQUIRE(absolute == truth);
          }
          ++cases;
        }
  CHECK(cases == 4 * (1 + 2 + 4 + 8 + 8) * 16);
}

TEST_CASE("edge marker: leaving a sub-cell lights exactly the edge behind the robot", "[stc]") {
  const OccupancyGrid map(4, 4, Occupancy::Free);
  StcWorld world(map, {1, 1}, {}, Marker::Edge);
  REQUIRE(world.apply({Move::East, true})); // from (1,1) to (2,1): lights (1,1)'s west edge
  // (1,1) is SE of cell (0,0): its west edge is interior, the cross box of SE (bit 0).
  CHECK(world.cell_edges({0, 0}) == 0x001);
  CHECK(world.cell_edges({1, 0}) == 0);
  REQUIRE(world.apply({Move::North, true})); // from (2,1) to (2,0): lights (2,1)'s south edge
  // (2,1) is SW (3) of cell (1,0): its south edge is exterior in SW's own direction (S = 3), bit
  // 8 + 3 of cell (1,0). The same edge is the north edge of (2,2), the NW (2) sub-cell of cell
  // (1,1), for which it is the turn box (exterior, direction 2 - 1 = N): bit 4 + 2.
  CHECK(world.cell_edges({1, 0}) == (1u << 11));
  CHECK(world.cell_edges({1, 1}) == (1u << 6));
}
