#pragma once
// Section 8.1's calibration of paper 000: area = a + b * nBC^c, fitted by Levenberg-Marquardt
// (Eigen) to the (median nBC, area) pairs of the calibration arenas (circles of diameter 30, 50,
// 70, 90), then used to turn any nBC into an area. Reporting side (after the deterministic runs),
// so it is floating point.
//
// Choices where the paper is silent: residuals are relative, (model - area) / area, so that the
// small arenas weigh as much as the large ones (the areas span a factor of 9); the start is the
// best of a grid of exponents c in [-3, -0.2] (step 0.05) with a and b solved by linear least
// squares for each, which keeps LM away from the flat region c ~ 0; LM stops after 200 iterations
// or when a step changes the cost by less than 1e-15 relative.
#include <antkit/buffon/checkpoints.hpp>
#include <antkit/buffon/estimate.hpp>
#include <cmath>
#include <cstddef>
#include <vector>

namespace antkit::experiments {

struct PowerFit {
  double a = 0, b = 0, c = -1;
  double cost = 0; // sum of squared relative residuals
  [[nodiscard]] double operator()(double x) const { return a + b * std::pow(x, c); }
};

// The fit (experiments/src/calibration.cpp: Eigen stays out of this header, which the command's
// Buffon files include).
PowerFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y);

// Figure 14 (Section 8.1): circles of diameter 30, 40, ..., 100; those of 30, 50, 70, 90 calibrate
// and 40, 60, 80, 100 are held out. At every checkpoint k the calibration circles' median nBC at k
// is fitted to their areas and each held-out trial's nBC at k becomes one estimate. One definition
// for the experiment driver (cli/buffon_experiment.cpp) and the test that asserts the figure's
// claim (tests/buffon_fig14).
struct Figure14Arena {
  double diameter = 0, area = 0;
  std::vector<std::vector<double>> nbc, rs; // [checkpoint][trial]: nBC and the RS estimate
};

inline bool is_calibration_diameter(double d) {
  return static_cast<int>(d) % 20 == 10;
}

// Appends one trial's checkpoints (checkpoints.hpp) to the arena's columns.
inline void add_checkpoints(Figure14Arena& a, const buffon::CheckpointResult& r) {
  const std::size_t k_count = r.bc.size();
  a.nbc.resize(k_count);
  a.rs.resize(k_count);
  const double cell = static_cast<double>(r.rs_cell_raw) / 65536.0;
  for (std::size_t k = 0; k < k_count; ++k) {
    const double l2 = static_cast<double>(r.length2_raw[k]) / 65536.0;
    a.nbc[k].push_back(l2 > 0 ? static_cast<double>(r.bc[k]) / l2 : 0.0);
    a.rs[k].push_back(static_cast<double>(r.rs_cells[k]) * cell * cell);
  }
}

// The median of a sample (type 7 quantile, as estimate.hpp's quantile).
inline double median_of(std::vector<double> v) {
  return buffon::quantile(std::move(v), 0.5);
}

// The fit at checkpoint k: area = a + b nBC^c through the calibration circles' median nBC.
inline PowerFit calibrate_at(const std::vector<Figure14Arena>& arenas, std::size_t k) {
  std::vector<double> xs, ys;
  for (const auto& a : arenas)
    if (is_calibration_diameter(a.diameter)) {
      xs.push_back(median_of(a.nbc[k]));
      ys.push_back(a.area);
    }
  return fit_power_law(xs, ys);
}

// A held-out arena's estimates at checkpoint k, one per trial (0 where the trial saw no crossing).
inline std::vector<double> estimates_at(const Figure14Arena& a, std::size_t k,
                                        const PowerFit& fit) {
  std::vector<double> est;
  for (double x : a.nbc[k]) est.push_back(x > 0 ? fit(x) : 0.0);
  return est;
}

} // namespace antkit::experiments
