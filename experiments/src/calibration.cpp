// Section 8.1's power-law fit (calibration.hpp), with Eigen.
#include <Eigen/Dense>
#include <antkit/experiments/calibration.hpp>
#include <cmath>
#include <vector>

namespace antkit::experiments {

PowerFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<Eigen::Index>(x.size());
  auto cost_of = [&](double a, double b, double c) {
    double s = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double r =
          (a + b * std::pow(x[static_cast<std::size_t>(i)], c) - y[static_cast<std::size_t>(i)]) /
          y[static_cast<std::size_t>(i)];
      s += r * r;
    }
    return s;
  };
  PowerFit best;
  best.cost = INFINITY;
  for (double c = -3; c <= -0.2 + 1e-9; c += 0.05) {
    Eigen::MatrixXd A(n, 2);
    Eigen::VectorXd rhs(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double yi = y[static_cast<std::size_t>(i)];
      A(i, 0) = 1 / yi;
      A(i, 1) = std::pow(x[static_cast<std::size_t>(i)], c) / yi;
      rhs(i) = 1;
    }
    const Eigen::Vector2d ab = A.colPivHouseholderQr().solve(rhs);
    const double cost = cost_of(ab(0), ab(1), c);
    if (cost < best.cost) best = PowerFit{ab(0), ab(1), c, cost};
  }
  double lambda = 1e-3;
  for (int it = 0; it < 200; ++it) {
    Eigen::MatrixXd J(n, 3);
    Eigen::VectorXd r(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double xi = x[static_cast<std::size_t>(i)], yi = y[static_cast<std::size_t>(i)];
      const double p = std::pow(xi, best.c);
      r(i) = (best.a + best.b * p - yi) / yi;
      J(i, 0) = 1 / yi;
      J(i, 1) = p / yi;
      J(i, 2) = best.b * p * std::log(xi) / yi;
    }
    const Eigen::Matrix3d JtJ = J.transpose() * J;
    const Eigen::Vector3d g = J.transpose() * r;
    Eigen::Matrix3d M = JtJ;
    for (int k = 0; k < 3; ++k) M(k, k) += lambda * (JtJ(k, k) > 0 ? JtJ(k, k) : 1.0);
    const Eigen::Vector3d step = M.ldlt().solve(-g);
    const PowerFit trial{best.a + step(0), best.b + step(1), best.c + step(2), 0};
    const double cost = cost_of(trial.a, trial.b, trial.c);
    if (std::isfinite(cost) && cost < best.cost) {
      const bool converged = best.cost - cost < 1e-15 * (1 + best.cost);
      best = PowerFit{trial.a, trial.b, trial.c, cost};
      lambda /= 3;
      if (converged) break;
    } else {
      lambda *= 4;
      if (lambda > 1e12) break;
    }
  }
  return best;
}

} // namespace antkit::experiments
