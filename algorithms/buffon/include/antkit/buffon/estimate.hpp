#pragma once
// Reporting-side statistics of the Buffon measurement (after the deterministic run, so floating
// point is allowed here: DESIGN.md, rule 1).
//
// Closed-form estimate (Buffon-Crofton): two independent isotropic curves of lengths L1, L2 in a
// region of area A cross on average E[N] = 2 L1 L2 / (pi A) times, so A_hat = 2 L1 L2 / (pi N).
// Confidence interval: N is treated as Poisson (many nearly independent chances to cross); its
// 95 % interval comes from the variance-stabilising square root, sqrt(N) +/- 1.96 / 2, i.e.
// N in [(sqrt(N) - 0.98)^2, (sqrt(N) + 0.98)^2], and A's interval is the image of that. When
// N = 0 there is no estimate (the area is unbounded above given the data): estimate and upper
// bound are absent, and the lower bound is 2 L1 L2 / (pi 0.98^2) from N's upper bound 0.98^2.
// The curves are the robot's centre lines, which never come within 0.5 of a wall, so A_hat
// estimates the area the centre can reach (the arena eroded by the body radius and somewhat more,
// since the behaviour keeps a sensing distance from walls), not the arena's area.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace antkit::buffon {

struct ClosedForm {
  std::optional<double> area;  // absent when N = 0
  double lower = 0;            // 95 % interval
  std::optional<double> upper; // absent when N's lower bound is 0
};

inline ClosedForm closed_form_area(double length1, double length2, std::uint64_t crossings) {
  constexpr double pi = 3.14159265358979323846;
  const double n = static_cast<double>(crossings);
  const double k = 2.0 * length1 * length2 / pi;
  const double root = std::sqrt(n);
  const double n_hi = (root + 0.98) * (root + 0.98);
  const double n_lo = root > 0.98 ? (root - 0.98) * (root - 0.98) : 0.0;
  ClosedForm out;
  if (crossings > 0) out.area = k / n;
  out.lower = k / n_hi;
  if (n_lo > 0) out.upper = k / n_lo;
  return out;
}

// Erosion correction (issue 17). The closed form estimates the area the robot's centre explores,
// the arena eroded by an effective distance delta (the body radius and the margin the wall
// avoidance keeps): A' = A - perimeter delta + O(delta^2) (tests/convergence/test_robot.cpp fits
// delta = 0.7 on a circle and a square). The robot does not know the perimeter, but it meets the
// walls at a rate proportional to it: by Crofton, a walk spread evenly over A' crosses a curve of
// length P' on average 2 L P' / (pi A') times, so the wall encounters E (WallEncounters,
// measurement.hpp) over the trail length L give P / A' = E / (c L) for a constant c of the
// behaviour and the encounter threshold. Then A = A' (1 + (delta / c) E / L) to first order, and
// one constant kappa = delta / c carries the correction:
//     A_corrected = A_hat (1 + kappa E / L).
// kappa = 3.6 is the least-squares fit through the origin of A / A_hat - 1 against E / L on three
// calibration arenas (circle:d=36, square:area=1000, circle:d=80; 8 trials each at P = 0.03 with
// --rule online, medians: 3.84, 3.42, 3.30 each alone; pooled 3.58), and it predicts the held-out
// arenas' bias to within 0.6 % of the area: a 6368-unit^2 trapezoid with two pillars 4.15 %
// predicted against 4.03 % measured, ellipse:area=5000,e=0.968 4.95 % against 5.49 %, obstacles
// 4.40 % against 4.51 % (`antkit buffon --arena A --trials 8 --precision 0.03 --rule online
// --max-steps 60000000`, this 2-core machine). With c = E L^-1 A' / P = 0.2 on the circle, delta =
// kappa c = 0.72: the same delta as the convergence fit, from a different measurement. The
// interval is scaled by the same factor: the correction's own error (E is a count of hundreds to
// thousands, so a few per cent of a few per cent) is small against P.
inline constexpr double kErosionKappa = 3.6;
inline double erosion_factor(std::uint64_t wall_encounters, double length_total) {
  return length_total > 0
             ? 1.0 + kErosionKappa * static_cast<double>(wall_encounters) / length_total
             : 1.0;
}

// The precision rule's interval and the erosion correction of one measurement, from its counts:
// what `antkit buffon --precision` reports per trial ("precision_ci", "area_corrected",
// "area_corrected_ci", "precision_reached"). The interval is stopping.hpp's: A_hat N / (N +/- z
// sqrt V), V = max(V1 + V2, N) the two-way batch-means variance floored at N, z^2 =
// PrecisionMonitor::kZSquaredMilli / 1000; here in double, for reporting (the rule's decision is
// the exact integer test in stopping.cpp). Without an estimate (N = 0) every field but the
// erosion factor is absent; the upper side (and the precision reached) also when N <= z sqrt V.
struct PrecisionCounts {
  std::optional<double> area;                      // A_hat (closed_form_area); absent when N = 0
  std::uint64_t crossings = 0;                     // N, the exact crossings A_hat came from
  double variance_visit1 = 0, variance_visit2 = 0; // PrecisionMonitor::spread() (0: no check)
  std::uint64_t wall_encounters = 0;               // WallEncounters over both trails
  double length_total = 0;                         // L1 + L2, the erosion factor's trail length
};
struct PrecisionInterval {
  std::optional<double> lower, upper;
};
struct PrecisionEstimate {
  PrecisionInterval ci;                    // the rule's 95 % interval of A_hat
  double erosion_factor = 1;               // erosion_factor(wall_encounters, length_total)
  std::optional<double> area_corrected;    // A_hat * erosion_factor: the arena's area
  PrecisionInterval corrected_ci;          // ci * erosion_factor
  std::optional<double> precision_reached; // ci.upper / A_hat - 1: the relative precision reached
};
[[nodiscard]] PrecisionEstimate precision_estimate(const PrecisionCounts& counts);

// Quantile q of `v` by linear interpolation between order statistics (type 7, the default of R
// and numpy); `v` need not be sorted. Empty input gives 0.
inline double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(pos));
  const std::size_t j = std::min(i + 1, v.size() - 1);
  return v[i] + (pos - static_cast<double>(i)) * (v[j] - v[i]);
}

} // namespace antkit::buffon
