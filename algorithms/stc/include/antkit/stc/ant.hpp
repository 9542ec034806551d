#pragma once
// Ant-like STC (paper 002): no map memory. The marks the robot leaves on the floor are its only
// memory; the controller's own state is the quadrant it stands in (two bits, kept up to date as it
// moves) and whether it has stopped, so its size is asserted at compile time below.
//
// The paper's loop, with x the current cell and S the start cell:
//   1. w = Parent(x): scanning the sub-cells of x counter-clockwise, the transition from an
//      unmarked to a marked sub-cell; the two sub-cells around it share an exterior edge, and that
//      edge is the one between x and its parent.
//   2. y = Neighbor(w, x): the first new neighbour of x counter-clockwise from w, a neighbour being
//      new when none of its sub-cells is marked.
//   3. y exists: walk around x to the sub-cell that borders y, marking the sub-cells of x as they
//   are
//      covered, and cross into y. Otherwise: walk to the sub-cell that borders w and return to w.
// Each step() performs one sub-cell move of that walk, re-deriving w and y from what it sees, so
// nothing but the quadrant survives between steps.
//
// Choices where the paper is silent (documented here, used by both marker models):
//   * The sub-cell the robot stands on counts as covered (it is marked when the robot leaves it,
//     "marking the sub-cells of x being covered"). So the covered sub-cells of x always form one
//     counter-clockwise run that ends at the robot, and Parent(x) is read by walking back from the
//     robot to the first uncovered sub-cell s: the parent edge is the exterior edge shared by s and
//     s + 1, i.e. direction s. With consistent marks this is the paper's transition (there is only
//     one); with misread marks it picks the run the robot itself is in, the reading most likely to
//     be right.
//   * When all four sub-cells are covered the robot stands on the last one of the run, whose
//     exterior edge in its own direction q is the parent edge: w = q.
//   * The start cell has no parent. Its scan starts at the start sub-cell's quadrant q0 (as if its
//     parent lay in direction q0 - 1), and includes w itself last, so that all four neighbours of
//     S are candidates. A non-root cell's w is marked, so including it changes nothing there.
//   * The loop ends ("while S has unmarked sub-cells") when the robot would return to w but the
//     sub-cell it would enter is marked or not free: for every cell but S, the parent's entry
//     sub-cell is still unmarked (the robot left the parent from the sub-cell before it), so this
//     happens exactly when the tour is about to re-enter the start sub-cell. O(1) memory cannot
//     hold the start's coordinates, and does not need to.
#include <antkit/stc/subcell.hpp>
#include <array>
#include <cstdint>
#include <type_traits>

namespace antkit::stc {

// What the ant senses with sub-cell marks: its cell and the four neighbour cells (the paper's five
// cells in the camera's view). Bit q of a mask: sub-cell q of that cell is marked; a neighbour
// outside the map reads 0 and is not free.
struct MarkObservation {
  std::uint8_t free_neighbours = 0;
  std::uint8_t here = 0;
  std::array<std::uint8_t, 4> neighbour{};
};

// The decision of the ant-like STC from the covered sub-cells of the five cells (bit q of each
// mask: sub-cell q covered, not counting the robot's own sub-cell). Updates q and done.
// Defined here (inline) so that the world's step loop can inline it: one call per move.
inline Command ant_decide(int& q, bool& done, std::uint8_t free_neighbours, std::uint8_t here,
                          const std::array<std::uint8_t, 4>& neighbour) noexcept {
  if (done) return {};
  const int cur = q;
  const unsigned covered = here | (1u << cur);
  // 1. w = Parent(x): walk back from the robot to the first uncovered sub-cell s; the parent edge
  //    is the exterior edge shared by s and s + 1, direction s. All covered: w = q.
  int w = cur;
  for (int k = 1; k <= 3; ++k) {
    const int s = dir_add(cur, -k);
    if (((covered >> s) & 1u) == 0) {
      w = s;
      break;
    }
  }
  // 2. y = Neighbor(w, x): the first new neighbour counter-clockwise after w (w itself last).
  int target = w;
  bool child = false;
  for (int k = 1; k <= 4; ++k) {
    const int d = dir_add(w, k);
    if (((free_neighbours >> d) & 1) != 0 && neighbour[static_cast<std::size_t>(d)] == 0) {
      target = d;
      child = true;
      break;
    }
  }
  // 3./4. Walk around x to the sub-cell that borders the target (marking as we go), then cross.
  if (target != cur) {
    q = dir_add(cur, 1);
    return {move_towards(q), true};
  }
  const int entry = dir_add(cur, 3); // the sub-cell of the neighbour the crossing arrives in
  if (!child) {
    const bool open = ((free_neighbours >> cur) & 1) != 0 &&
                      ((neighbour[static_cast<std::size_t>(cur)] >> entry) & 1) == 0;
    if (!open) { // no parent to return to: the tour is closed
      done = true;
      return {};
    }
  }
  q = entry;
  return {move_towards(cur), true};
}

class AntStc {
public:
  using Observation = MarkObservation;
  using Command = stc::Command;

  explicit AntStc(int start_quadrant) noexcept
      : q_(static_cast<std::uint8_t>(start_quadrant & 3)) {}

  Command step(const Observation& seen) noexcept {
    int q = q_;
    bool done = done_;
    const Command c = ant_decide(q, done, seen.free_neighbours, seen.here, seen.neighbour);
    q_ = static_cast<std::uint8_t>(q);
    done_ = done;
    return c;
  }

private:
  std::uint8_t q_;
  bool done_ = false;
};

// ---- ant-edge: the paper's real robot marks one edge of a sub-cell
// ---------------------------------
//
// The robot's UV LEDs are at its back and are lit only when it drives forward out of a sub-cell, so
// leaving sub-cell s in direction d lights the edge of s in direction d + 2 (behind it), and every
// sub-cell left has exactly one lit edge. An edge is shared by two sub-cells, so a lit edge alone
// does not say whose it is.
//
// Edge masks (12 bits per cell), for the cell's sub-cell e (quadrant numbering, mod 4):
//   bit e      the cross box of e: the interior edge between e and e - 1. Lit when the robot
//              leaves e across the cell's side e (to a child or to the parent): the edge behind it
//              is e's edge in direction e + 2, which is interior.
//   bit 4 + e  the turn box of e: e's exterior edge in direction e - 1. Lit when the robot walks on
//              around the cell, e -> e + 1 (a move in direction e + 1, so the edge behind it is in
//              direction e - 1).
//   bit 8 + e  e's exterior edge in direction e: it is the turn box of the neighbour's sub-cell
//              across it, so this cell's own passes never light it.
// In an STC tour a sub-cell is left only in those two ways, so the edge rule is
//     sub-cell e has been covered  <=>  its cross box or its turn box is lit,
// and no edge lit by a neighbour can be mistaken for one of this cell's boxes.
//
// Seen from the sub-cell 0 the robot is entering (the paper's numbering: 1, 2, 3 counter-clockwise
// after it), the turn box of 3 can never be lit (3 -> 0 would have covered 0), so the rule needs
// the paper's five boxes: box 1 = turn(1), box 2 = turn(2), box 3 = cross(2), box 4 = cross(3), box
// 5 = cross(1), and reads "1 iff box 1 or 5; 2 iff box 2 or 3; 3 iff box 4", the paper's rule. (The
// paper lists the path 1 -> 2 -> 3 -> out as lighting boxes 1, 3, 4; under this motion model it
// lights 1, 2, 4 — box 3 would mean the robot left the cell from 2. The rule is the same.)
// tests/stc checks the rule exhaustively over every way an STC tour can pass through a cell, with
// every combination of the neighbours' edges.
inline constexpr std::uint16_t kCrossBoxes = 0x00F;
inline constexpr std::uint16_t kTurnBoxes = 0x0F0;
inline constexpr std::uint16_t kNeighbourEdges = 0xF00;

// The sub-cells of a cell the edge rule says were covered (bit e).
[[nodiscard]] constexpr std::uint8_t covered_from_edges(std::uint16_t edges) noexcept {
  return static_cast<std::uint8_t>((edges | (edges >> 4)) & 0x0F);
}

// The paper's five boxes, relative to the entry sub-cell `entry`: bit k - 1 is box k.
[[nodiscard]] constexpr std::uint8_t paper_boxes(std::uint16_t edges, int entry) noexcept {
  auto cross = [&](int r) { return (edges >> dir_add(entry, r)) & 1; };
  auto turn = [&](int r) { return (edges >> (4 + dir_add(entry, r))) & 1; };
  return static_cast<std::uint8_t>(turn(1) | (turn(2) << 1) | (cross(2) << 2) | (cross(3) << 3) |
                                   (cross(1) << 4));
}

// The paper's rule over its five boxes: bit r of the result is relative sub-cell r (1, 2, 3).
[[nodiscard]] constexpr std::uint8_t paper_rule(std::uint8_t boxes) noexcept {
  const bool b1 = boxes & 1, b2 = boxes & 2, b3 = boxes & 4, b4 = boxes & 8, b5 = boxes & 16;
  return static_cast<std::uint8_t>(((b1 || b5) ? 2 : 0) | ((b2 || b3) ? 4 : 0) | (b4 ? 8 : 0));
}

struct EdgeObservation {
  std::uint8_t free_neighbours = 0;
  std::uint16_t here = 0;
  std::array<std::uint16_t, 4> neighbour{};
  friend constexpr bool operator==(const EdgeObservation&, const EdgeObservation&) = default;
};

class AntEdgeStc {
public:
  using Observation = EdgeObservation;
  using Command = stc::Command;

  explicit AntEdgeStc(int start_quadrant) noexcept
      : q_(static_cast<std::uint8_t>(start_quadrant & 3)) {}

  Command step(const Observation& seen) noexcept {
    int q = q_;
    bool done = done_;
    const std::array<std::uint8_t, 4> nb{
        covered_from_edges(seen.neighbour[0]), covered_from_edges(seen.neighbour[1]),
        covered_from_edges(seen.neighbour[2]), covered_from_edges(seen.neighbour[3])};
    const Command c = ant_decide(q, done, seen.free_neighbours, covered_from_edges(seen.here), nb);
    q_ = static_cast<std::uint8_t>(q);
    done_ = done;
    return c;
  }

private:
  std::uint8_t q_;
  bool done_ = false;
};

// O(1) state, asserted: two bytes, no pointers, nothing that could grow with the map.
static_assert(sizeof(AntStc) <= 2 && std::is_trivially_copyable_v<AntStc>);
static_assert(sizeof(AntEdgeStc) <= 2 && std::is_trivially_copyable_v<AntEdgeStc>);

} // namespace antkit::stc
