// The precision rule's interval and the erosion correction (estimate.hpp).
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/stopping.hpp>

namespace antkit::buffon {

PrecisionEstimate precision_estimate(const PrecisionCounts& c) {
  PrecisionEstimate out;
  const double n = static_cast<double>(c.crossings);
  const double v = std::max(c.variance_visit1 + c.variance_visit2, n);
  const double z2 = static_cast<double>(PrecisionMonitor::kZSquaredMilli) / 1000.0;
  const double half = std::sqrt(z2 * v);
  if (c.area && n > 0) out.ci.lower = *c.area * n / (n + half);
  if (c.area && n > half) out.ci.upper = *c.area * n / (n - half);
  out.erosion_factor = erosion_factor(c.wall_encounters, c.length_total);
  const auto scale = [f = out.erosion_factor](const std::optional<double>& a) {
    return a ? std::optional<double>(*a * f) : std::nullopt;
  };
  out.area_corrected = scale(c.area);
  out.corrected_ci = {scale(out.ci.lower), scale(out.ci.upper)};
  if (c.area && out.ci.upper) out.precision_reached = *out.ci.upper / *c.area - 1;
  return out;
}

} // namespace antkit::buffon
