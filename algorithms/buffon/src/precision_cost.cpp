// The cost of precision (precision_cost.hpp).
#include <algorithm>
#include <antkit/buffon/checkpoints.hpp>
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/precision_cost.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/buffon/two_markers.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <limits>

namespace antkit::buffon {

std::string_view cost_method_name(CostMethod m) noexcept {
  switch (m) {
  case CostMethod::markers:
    return "markers";
  case CostMethod::online:
    return "online";
  case CostMethod::rs:
    break;
  }
  return "rs";
}

CostFit fit_power_law(std::span<const double> x, std::span<const double> y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (!(x[i] > 0) || !(y[i] > 0)) continue;
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    ++n;
  }
  CostFit f;
  f.points = n;
  const double dn = static_cast<double>(n);
  const double den = dn * sxx - sx * sx;
  if (n < 2 || !(std::abs(den) > 1e-12 * dn * sxx)) return f; // fewer than two distinct x
  f.exponent = (dn * sxy - sx * sy) / den;
  f.coefficient = std::exp((sy - f.exponent * sx) / dn);
  return f;
}

namespace {
// One trial's total trail length, or +infinity when the budget ran out first.
double trial_cost(const CostArena& a, CostMethod method, std::uint32_t p, const CostParams& c,
                  std::uint64_t experiment, std::uint64_t trial) {
  TrialParams params;
  params.seed = c.seed;
  params.experiment = experiment;
  params.precision_millionths = p;
  params.total_steps = c.budget;
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (method == CostMethod::rs) {
    const RsCost r = rs_cost_to_precision(*a.world, params, trial, a.area, p, c.budget);
    return r.reached ? static_cast<double>(r.length_raw) / 65536.0 : inf;
  }
  params.online_first_visit = method == CostMethod::online;
  const TrialResult t = method == CostMethod::markers
                            ? run_two_marker_trial(*a.world, params, trial)
                            : run_trial(*a.world, params, trial);
  return t.reached_precision ? static_cast<double>(t.length1_raw + t.length2_raw) / 65536.0 : inf;
}
} // namespace

CostTable precision_cost(std::span<const CostArena> arenas, const CostParams& c,
                         const algorithms::Runner& runner) {
  if (arenas.empty()) throw kernel::InputError("arenas", "no arena to measure");
  if (c.precisions.empty() || c.methods.empty())
    throw kernel::InputError("precision", "no precision or no method to measure");
  for (const std::uint32_t p : c.precisions)
    if (p < 1 || p >= kPrecisionDenominator)
      throw kernel::InputError("precision", "the relative precision must be in (0, 1)");
  if (c.trials < 1 || c.trials > 100000)
    throw kernel::InputError("trials", "the number of trials must be in [1, 100000]");
  detail::check_total_steps(c.budget);
  // The points, arena-major, then precision, then method; a point's trials are units
  // point * trials + trial.
  struct At {
    std::size_t arena, precision;
    CostMethod method;
  };
  std::vector<At> at;
  for (std::size_t ai = 0; ai < arenas.size(); ++ai) {
    if (arenas[ai].world == nullptr)
      throw kernel::InputError("arenas", arenas[ai].name + " has no world");
    for (std::size_t pi = 0; pi < c.precisions.size(); ++pi)
      for (const CostMethod m : c.methods) at.push_back({ai, pi, m});
  }
  const std::vector<algorithms::Payload> units =
      algorithms::run_units(runner, "trials", at.size() * c.trials, [&](std::uint64_t unit) {
        const At& p = at[static_cast<std::size_t>(unit / c.trials)];
        // Streams: experiment 17000 + 100 arena + 10 precision + method, so that no two points
        // share a draw and a point's trials do not depend on which other points are measured.
        const std::uint64_t experiment =
            17000 + 100 * p.arena + 10 * p.precision + static_cast<std::uint64_t>(p.method);
        algorithms::Payload out;
        out.put_d(trial_cost(arenas[p.arena], p.method, c.precisions[p.precision], c, experiment,
                             unit % c.trials));
        return out;
      });
  CostTable out;
  if (!runner.root()) return out;
  for (std::size_t i = 0; i < at.size(); ++i) {
    const CostArena& a = arenas[at[i].arena];
    std::vector<double> costs(static_cast<std::size_t>(c.trials));
    for (std::uint64_t t = 0; t < c.trials; ++t) {
      algorithms::Payload unit = units[static_cast<std::size_t>(i * c.trials + t)];
      costs[static_cast<std::size_t>(t)] = unit.get_d();
    }
    CostPoint point{a.name, a.family, a.area,  c.precisions[at[i].precision], at[i].method, {}, {},
                    {},     0,        c.trials};
    for (const double v : costs) point.reached += std::isfinite(v) ? 1u : 0u;
    // Unreached trials are +infinity: they sort last and a quantile that lands on one is absent
    // (not reached), never a finite number averaged with infinity.
    auto q = [&costs](double where) -> std::optional<double> {
      std::vector<double> v = costs;
      std::sort(v.begin(), v.end());
      const double pos = where * static_cast<double>(v.size() - 1);
      const auto lo = static_cast<std::size_t>(std::floor(pos));
      const std::size_t hi = std::min(lo + 1, v.size() - 1);
      if (!std::isfinite(v[hi]) && pos > static_cast<double>(lo)) return std::nullopt;
      if (!std::isfinite(v[lo])) return std::nullopt;
      return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
    };
    point.median = q(0.5);
    point.q1 = q(0.25);
    point.q3 = q(0.75);
    out.points.push_back(point);
  }
  for (const std::uint32_t p : c.precisions)
    for (const CostMethod m : c.methods) {
      std::vector<double> x, y;
      for (std::size_t i = 0; i < out.points.size(); ++i) {
        const CostPoint& point = out.points[i];
        const std::size_t arena = i / (c.precisions.size() * c.methods.size());
        if (arenas[arena].in_fit && point.method == m && point.precision_millionths == p &&
            point.median) {
          x.push_back(point.area);
          y.push_back(*point.median);
        }
      }
      CostFit f = fit_power_law(x, y);
      f.method = m;
      f.precision_millionths = p;
      if (f.points >= 2 && f.coefficient > 0) out.fits.push_back(f);
    }
  return out;
}

} // namespace antkit::buffon
