#include <antkit/stc/ant.hpp>

namespace antkit::stc {

Command ant_decide(int& q, bool& done, std::uint8_t free_neighbours, std::uint8_t here,
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
    if (((free_neighbours >> d) & 1u) != 0 && neighbour[static_cast<std::size_t>(d)] == 0) {
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
    const bool open = ((free_neighbours >> cur) & 1u) != 0 &&
                      ((neighbour[static_cast<std::size_t>(cur)] >> entry) & 1u) == 0;
    if (!open) { // no parent to return to: the tour is closed
      done = true;
      return {};
    }
  }
  q = entry;
  return {move_towards(cur), true};
}

} // namespace antkit::stc
