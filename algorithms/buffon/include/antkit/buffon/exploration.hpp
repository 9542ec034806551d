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
#include <antkit/kernel/fixed_random.hpp>
#include <antkit/kernel/random.hpp>
#include <array>
#include <cstddef>
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

namespace detail {

constexpr Fx ratio(std::int32_t num, std::int32_t den) {
  return Fx::from_ratio(num, den);
}

// The printed constants, rounded to the nearest 2^-16.
inline constexpr Fx kOne = Fx::one();
inline constexpr Fx kQuarter = ratio(1, 4);
inline constexpr Fx kNLimit = ratio(2, 5);       // n in [-0.4, 0.4]
inline constexpr Fx kNBarLow = ratio(3, 10);     // n_bar in [0.3, 1.0]
inline constexpr Fx kFrontSum = ratio(27, 10);   // sum of I_1..I_4 above 2.7
inline constexpr Fx kSideClose = ratio(95, 100); // I_0 or I_5 above 0.95
inline constexpr Fx kRDecay = ratio(9, 10);
inline constexpr Fx kRGain = ratio(3, 10);
inline constexpr Fx kOuter = ratio(3, 2); // 1.5 for I_1, I_4
inline constexpr Fx kInner = ratio(6, 5); // 1.2 for I_2, I_3
inline constexpr Fx kWDecay = ratio(1, 10);
inline constexpr Fx kWFront = ratio(7, 10);
inline constexpr Fx kWallGain = Fx::from_raw(32768); // 0.5, the lost dw term (see above)

} // namespace detail

// The behaviour's state and outputs after one step, over the number type of a policy.
template <class Num>
struct ExplorationStep {
  Num r, w_l, w_r; // the new state
  Num r_bar;       // the turn chosen from the old state
  Num m_l, m_r;    // the wheel commands
};

// The machine policy: Q15.16 numbers (kernel::Fx) and bool.
struct FxPolicy {
  using num = Fx;
  static constexpr Fx select(bool c, Fx a, Fx b) noexcept { return c ? a : b; }
  static constexpr Fx abs(Fx x) noexcept { return kernel::abs(x); }
  static constexpr Fx lift(Fx x) noexcept { return x; }
};

// One step of the behaviour given the draws n and n_bar, written once over a number policy P
// (DESIGN.md rule 6): P::num has + - * and comparisons, P::select(c, a, b) chooses, P::abs is |x|
// and P::lift turns a constant Fx into a P::num. ExplorationBehaviour::step runs it with FxPolicy;
// proofs/z3/buffon_behaviour.cpp runs it with Z3 integers inside the same Fixed kernels
// (fx_mul_raw ...). Branch-free: every case is evaluated and chosen by select, so one symbolic run
// covers all of them.
template <class P>
ExplorationStep<typename P::num>
exploration_step(const typename P::num& r, const typename P::num& w_l, const typename P::num& w_r,
                 const std::array<typename P::num, 6>& I, const typename P::num& n,
                 const typename P::num& n_bar) {
  using Num = typename P::num;
  const Num zero = P::lift(Fx{}), one = P::lift(detail::kOne);
  const auto clamp_unit = [&](const Num& v) {
    return P::select(v < -one, -one, P::select(v > one, one, v));
  };
  const auto clamp01 = [&](const Num& v) {
    return P::select(v < zero, zero, P::select(v > one, one, v));
  };
  const auto very_close = (I[1] + I[2] + I[3] + I[4]) > P::lift(detail::kFrontSum) ||
                          I[0] > P::lift(detail::kSideClose) || I[5] > P::lift(detail::kSideClose);
  // The current turning direction (see above for why not the printed sign): the sign of r; if r is
  // 0, sign(w_l - w_r); if that is 0 too, away from the stronger front side (a tie turns left).
  const auto r_positive = r > zero;
  const auto r_negative = r < zero;
  const auto left_front = (I[0] + I[1] + I[2]) > (I[3] + I[4] + I[5]);
  const auto turn_positive =
      r_positive || (!r_negative && (w_l > w_r || (!(w_l < w_r) && !left_front)));
  const Num r_bar =
      P::select(very_close, P::select(turn_positive, n_bar, -n_bar), clamp_unit(r + n));

  const Num gain = P::lift(detail::kRGain), outer = P::lift(detail::kOuter),
            inner = P::lift(detail::kInner);
  const Num dr = -(P::lift(detail::kRDecay) * r) +
                 gain * (one - r) * (w_l + outer * I[4] + inner * I[3]) -
                 gain * (one + r) * (w_r + outer * I[1] + inner * I[2]);
  const Num front = I[2] + I[3];
  const Num wdecay = P::lift(detail::kWDecay), wfront = P::lift(detail::kWFront),
            wall = P::lift(detail::kWallGain);
  const Num dwl = -(wdecay * w_l) - wfront * w_l * front + wall * (one - w_l) * I[5];
  const Num dwr = -(wdecay * w_r) - wfront * w_r * front + wall * (one - w_r) * I[0];
  // A choice: r is kept in [-1, 1] and w in [0, 1]. The printed update can overshoot (at r = -1
  // with strong right-side readings, 0.1 r + 0.6 * 3.7 > 1); the paper clamps r + n, so r itself
  // is read as an activation in the same range.
  const Num forward = (one - P::abs(r_bar)) * P::lift(detail::kQuarter);
  return {clamp_unit(r + dr), clamp01(w_l + dwl), clamp01(w_r + dwr), r_bar,
          forward - r_bar,    forward + r_bar};
}

// The behaviour's stream read through a buffer filled by the batched draw (Stream::next_u32s):
// the words come out in the stream's order, so every draw is the one kernel::uniform would make
// from the stream itself, but the Philox blocks are computed 4 at a time (8 steps' worth), off the
// step's critical path. The stream is only read through the buffer.
class BufferedStream {
public:
  explicit BufferedStream(kernel::Stream stream) : stream_(stream) {}
  std::uint32_t next_u32() noexcept {
    if (next_ == kWords) refill();
    return words_[next_++];
  }
  // kernel::uniform(stream, a, b) for a <= b: Lemire's map with rejection of the next words, as
  // uniform_offset_u32 does it (the same words accepted or rejected, the same offset).
  Fx uniform(Fx a, Fx b) noexcept {
    const auto span = static_cast<std::uint32_t>(static_cast<std::uint32_t>(b.raw()) -
                                                 static_cast<std::uint32_t>(a.raw()));
    std::uint32_t offset = 0;
    if (span == 0xFFFFFFFFu) {
      offset = next_u32();
    } else {
      while (!kernel::lemire_bounded<std::uint32_t, std::uint64_t>(next_u32(), span + 1u, offset)) {
      }
    }
    return Fx::from_raw(static_cast<std::int32_t>(static_cast<std::uint32_t>(a.raw()) + offset));
  }

private:
  // Out of line: it runs once every eight steps, and inlined twice (one per draw) it made the
  // behaviour's step several times larger.
  [[gnu::noinline]] void refill() noexcept {
    stream_.next_u32s(words_);
    next_ = 0;
  }
  static constexpr std::size_t kWords = 16;
  kernel::Stream stream_;
  std::array<std::uint32_t, kWords> words_{};
  std::size_t next_ = kWords;
};

class ExplorationBehaviour {
public:
  static constexpr Fx kWallGain = detail::kWallGain;

  explicit ExplorationBehaviour(kernel::Stream stream) : stream_(stream) {}

  Command step(const Observation& obs);

  [[nodiscard]] Fx r() const noexcept { return r_; }
  [[nodiscard]] Fx w_left() const noexcept { return w_l_; }
  [[nodiscard]] Fx w_right() const noexcept { return w_r_; }
  [[nodiscard]] Fx r_bar() const noexcept { return r_bar_; }

private:
  BufferedStream stream_;
  Fx r_{};
  Fx w_l_{};
  Fx w_r_{};
  Fx r_bar_{};
};

} // namespace antkit::buffon
