#pragma once
// The pheromone detector of visit 2 (measurement.hpp): a leaky integrator y <- (y + b) / 2 of the
// raster bit b under the robot's centre, thresholded with hysteresis: the output goes high when
// y >= 1/2 and low again when y < 1/4. A low-to-high transition is one Buffon count.
//
// The step is written once over the integer type I of y's raw Q15.16 value and the truth type B
// (DESIGN.md rule 6): CrossingDetector instantiates it with std::int32_t and bool, and
// proofs/z3/buffon_detector.cpp with Z3 integers, proving that y stays in [0, 1], that a count
// needs y >= 1/2 and comes only from the low state, and that the output falls only below 1/4 (so
// after a count y must fall below 1/4 before the next count).
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/int_ops.hpp>
#include <cstdint>

namespace antkit::buffon {

// One detector state after a step, and whether the step counted a crossing.
template <class I, class B>
struct DetectorStep {
  I y;     // raw Q15.16 level
  B high;  // the thresholded output
  B count; // a low-to-high transition happened in this step
};

// One step of the detector from raw level y (in [0, one]) and output `high`, fed raster bit `bit`.
// Branch-free (select and boolean algebra) so that one symbolic run covers every case.
template <class I, class B>
constexpr DetectorStep<I, B> detector_step(I y, B high, B bit) {
  using kernel::ops::select;
  constexpr std::int32_t one = kernel::Fx::one_raw;
  // y <- (y + b) / 2 on the raw value: the division truncates, which for y + b >= 0 is the floor,
  // so y stays a dyadic fraction in [0, 1].
  const I next = (y + select(bit, I(one), I(0))) / I(2);
  const B rises = !high && next >= I(one / 2);
  const B falls = high && next < I(one / 4);
  return {next, rises || (high && !falls), rises};
}

class CrossingDetector {
public:
  // Feeds one raster bit; true on a low-to-high transition of the thresholded value.
  bool update(bool bit) noexcept {
    const DetectorStep<std::int32_t, bool> s =
        detector_step<std::int32_t, bool>(y_.raw(), high_, bit);
    y_ = kernel::Fx::from_raw(s.y);
    high_ = s.high;
    return s.count;
  }
  [[nodiscard]] bool high() const noexcept { return high_; }
  [[nodiscard]] kernel::Fx level() const noexcept { return y_; }

private:
  kernel::Fx y_{};
  bool high_ = false;
};

} // namespace antkit::buffon
