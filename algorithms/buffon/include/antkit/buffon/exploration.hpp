#pragma once
// The exploration behaviour of Section 4.2 of Sahin, Girgin, Ugur (2006), "Area measurement of
// large closed regions with a mobile robot", as a controller (DESIGN.md, the controller contract):
// six front IR readings in, two wheel speeds out. Everything is Q15.16 fixed point (kernel::Fx);
// the random terms come from the controller's own keyed stream.
//
// The equations, as printed:
//   m_l = (1 - |r_bar|) * 0.25 - r_bar,   m_r = (1 - |r_bar|) * 0.25 + r_bar
//   r_bar = sign(w_r - w_l) * n_bar   if sum_{i=1..4} I_i > 2.7 or I_0 > 0.95 or I_5 > 0.95
//         = clamp(r + n, -1, 1)       otherwise
//   n uniform in [-0.4, 0.4], n_bar uniform in [0.3, 1.0]
//   dr   = -0.9 r + 0.3 (1 - r)(w_l + 1.5 I_4 + 1.2 I_3) - 0.3 (1 + r)(w_r + 1.5 I_1 + 1.2 I_2)
//   dw_l = -0.1 w_l - 0.7 w_l (I_2 + I_3) + [lost term],   dw_r likewise.
//
// Sensor indices are the Khepera's: I_0 left (90 degrees), I_1 45, I_2 10, I_3 -10, I_4 -45,
// I_5 right (-90 degrees). The paper calls w_l the perceived wall "on the right" and w_r "on the
// left" (w_l raises r, i.e. turns the robot left, away from a wall on its right), and we keep its
// names with that meaning.
//
// Choices where the text is silent (documented here, used below):
//  * The lost term of dw. As printed, w_l and w_r only decay from 0 and so are always 0. We add
//    +kWallGain (1 - w_l) I_5 to dw_l and +kWallGain (1 - w_r) I_0 to dw_r with kWallGain = 0.5:
//    the side sensor on the right raises the perceived wall on the right, saturating at 1, so the
//    robot keeps turning away from a side wall for a few steps after the wall leaves its sensors
//    (the decay 0.1 per step gives the memory about ten steps). The side sensors (I_0, I_5) are
//    the ones the other terms do not already use for w, which is what "peripheral wall" suggests.
//  * The direction of the first case of r_bar. The printed sign(w_r - w_l) contradicts the printed
//    dr: dr turns the robot left (r up) for w_l, so w_l is a wall on the right, and then
//    sign(w_r - w_l) would turn it towards the wall it remembers. In simulation that sign
//    (with w's tiny rounding residues deciding it) pinned the robot against walls for half of its
//    steps. We follow the prose instead, "a turn of random size in its current turning
//    direction": the sign of r; if r is 0, sign(w_l - w_r) (away from the remembered wall); if
//    that is 0 too, away from the side with the stronger front readings (I_0 + I_1 + I_2 versus
//    I_3 + I_4 + I_5; a tie turns left).
//  * r is updated every step by dr (r <- r + dr) after r_bar is chosen from the old r.
//  * Q15.16 arithmetic rounds each product to the nearest 2^-16 (ties up), so the behaviour is
//    the printed one to within a few 2^-16 per step.
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/random.hpp>
#include <array>
#include <cstdint>

namespace antkit::buffon {

using kernel::Fx;

// The six front IR readings I_0 .. I_5 in [0, 1].
struct Observation {
  std::array<Fx, 6> ir{};
};

// Wheel speeds m_l, m_r in [-1, 1] (the paper's units; the body scales them to distance).
struct Command {
  Fx left;
  Fx right;
};

class ExplorationBehaviour {
public:
  static constexpr Fx kWallGain = Fx::from_raw(32768); // 0.5, the lost dw term (see above)

  explicit ExplorationBehaviour(kernel::Stream stream) : stream_(stream) {}

  Command step(const Observation& obs);

  [[nodiscard]] Fx r() const noexcept { return r_; }
  [[nodiscard]] Fx w_left() const noexcept { return w_l_; }
  [[nodiscard]] Fx w_right() const noexcept { return w_r_; }
  [[nodiscard]] Fx r_bar() const noexcept { return r_bar_; }

private:
  kernel::Stream stream_;
  Fx r_{};
  Fx w_l_{};
  Fx w_r_{};
  Fx r_bar_{};
};

} // namespace antkit::buffon
