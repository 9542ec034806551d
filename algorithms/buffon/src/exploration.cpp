// The exploration behaviour of Section 4.2 (see exploration.hpp for the equations and choices).
#include <antkit/buffon/exploration.hpp>
#include <antkit/kernel/fixed_random.hpp>

namespace antkit::buffon {

namespace {

constexpr Fx ratio(std::int32_t num, std::int32_t den) {
  return Fx::from_ratio(num, den);
}

// The printed constants, rounded to the nearest 2^-16.
constexpr Fx kOne = Fx::one();
constexpr Fx kQuarter = ratio(1, 4);
constexpr Fx kNLimit = ratio(2, 5);       // n in [-0.4, 0.4]
constexpr Fx kNBarLow = ratio(3, 10);     // n_bar in [0.3, 1.0]
constexpr Fx kFrontSum = ratio(27, 10);   // sum of I_1..I_4 above 2.7
constexpr Fx kSideClose = ratio(95, 100); // I_0 or I_5 above 0.95
constexpr Fx kRDecay = ratio(9, 10);
constexpr Fx kRGain = ratio(3, 10);
constexpr Fx kOuter = ratio(3, 2); // 1.5 for I_1, I_4
constexpr Fx kInner = ratio(6, 5); // 1.2 for I_2, I_3
constexpr Fx kWDecay = ratio(1, 10);
constexpr Fx kWFront = ratio(7, 10);

constexpr Fx clamp_unit(Fx v) {
  return v < -kOne ? -kOne : (v > kOne ? kOne : v);
}
constexpr Fx clamp01(Fx v) {
  return v < Fx{} ? Fx{} : (v > kOne ? kOne : v);
}

} // namespace

Command ExplorationBehaviour::step(const Observation& obs) {
  const auto& I = obs.ir;
  // Both random numbers are drawn every step, in this order, so that the stream's position does
  // not depend on which case applies (a replay that diverges in one case stays aligned).
  const Fx n = kernel::uniform(stream_, -kNLimit, kNLimit);
  const Fx n_bar = kernel::uniform(stream_, kNBarLow, kOne);

  const bool very_close =
      (I[1] + I[2] + I[3] + I[4]) > kFrontSum || I[0] > kSideClose || I[5] > kSideClose;
  Fx r_bar;
  if (very_close) {
    // The current turning direction (see exploration.hpp for why not the printed sign).
    int sign = (r_ > Fx{}) - (r_ < Fx{});
    if (sign == 0) sign = (w_l_ > w_r_) - (w_l_ < w_r_);
    if (sign == 0) sign = (I[0] + I[1] + I[2]) > (I[3] + I[4] + I[5]) ? -1 : 1;
    r_bar = sign > 0 ? n_bar : -n_bar;
  } else {
    r_bar = clamp_unit(r_ + n);
  }
  r_bar_ = r_bar;

  const Fx dr = -(kRDecay * r_) + kRGain * (kOne - r_) * (w_l_ + kOuter * I[4] + kInner * I[3]) -
                kRGain * (kOne + r_) * (w_r_ + kOuter * I[1] + kInner * I[2]);
  const Fx front = I[2] + I[3];
  const Fx dwl = -(kWDecay * w_l_) - kWFront * w_l_ * front + kWallGain * (kOne - w_l_) * I[5];
  const Fx dwr = -(kWDecay * w_r_) - kWFront * w_r_ * front + kWallGain * (kOne - w_r_) * I[0];
  // A choice: r is kept in [-1, 1] and w in [0, 1]. The printed update can overshoot (at r = -1
  // with strong right-side readings, 0.1 r + 0.6 * 3.7 > 1); the paper clamps r + n, so r itself
  // is read as an activation in the same range.
  r_ = clamp_unit(r_ + dr);
  w_l_ = clamp01(w_l_ + dwl);
  w_r_ = clamp01(w_r_ + dwr);

  const Fx forward = (kOne - kernel::abs(r_bar)) * kQuarter;
  return Command{forward - r_bar, forward + r_bar};
}

} // namespace antkit::buffon
