#pragma once
// The pheromone detector of visit 2 (measurement.hpp): a leaky integrator y <- (y + b) / 2 of the
// raster bit b under the robot's centre, thresholded with hysteresis: the output goes high when
// y >= 1/2 and low again when y < 1/4. A low-to-high transition is one Buffon count.
#include <antkit/kernel/fixed.hpp>

namespace antkit::buffon {

class CrossingDetector {
public:
  // Feeds one raster bit; true on a low-to-high transition of the thresholded value.
  bool update(bool bit) noexcept {
    // y <- (y + b) / 2, exactly: y stays a dyadic fraction in [0, 1].
    y_ = kernel::Fx::from_raw((y_.raw() + (bit ? kernel::Fx::one_raw : 0)) / 2);
    const bool was = high_;
    if (!high_ && y_.raw() >= kernel::Fx::one_raw / 2)
      high_ = true;
    else if (high_ && y_.raw() < kernel::Fx::one_raw / 4)
      high_ = false;
    return high_ && !was;
  }
  [[nodiscard]] bool high() const noexcept { return high_; }
  [[nodiscard]] kernel::Fx level() const noexcept { return y_; }

private:
  kernel::Fx y_{};
  bool high_ = false;
};

} // namespace antkit::buffon
