#include <algorithm>
#include <antkit/algorithms/units.hpp>
#include <antkit/experiments/sequential.hpp>
#include <antkit/kernel/random.hpp>
#include <cmath>

namespace antkit::experiments {

double look_alpha(double alpha, int look) {
  return alpha / (static_cast<double>(look + 1) * static_cast<double>(look + 2));
}

SequentialSimulation simulate_sequential(SequentialSimulation s, unsigned threads) {
  const double truth = std::log(2.0);
  const Rule rule{Side::Below, truth * (1 + s.margin)};
  const Statistic median_of = [](const Samples& x) { return median(x[0]); };
  struct Outcome {
    Verdict verdict = Verdict::Inconclusive;
    std::size_t trials = 0;
  };
  std::vector<Outcome> outcomes(static_cast<std::size_t>(std::max(s.replications, 0)));
  algorithms::for_each_unit(outcomes.size(), threads, [&](std::uint64_t unit, unsigned) {
    const auto r = static_cast<int>(unit);
    kernel::Stream stream(s.seed, kSequentialExperiment, static_cast<std::uint64_t>(r));
    Samples x(1);
    Verdict verdict = Verdict::Inconclusive;
    for (int look = 0; look < s.looks && verdict == Verdict::Inconclusive; ++look) {
      const auto n = static_cast<std::size_t>(s.first_trials) << look;
      while (x[0].size() < n) {
        // An exponential draw from 53 random bits in (0, 1].
        const double u = (static_cast<double>(stream.next_u64() >> 11) + 1) * 0x1.0p-53;
        x[0].push_back(-std::log(u));
      }
      const double level = 1 - (s.spend ? look_alpha(s.alpha, look) : s.alpha);
      const Interval ci =
          bootstrap(x, 1, median_of, level,
                    {s.seed, kSequentialExperiment, static_cast<std::uint64_t>(r)}, s.resamples);
      verdict = decide(ci, rule);
    }
    outcomes[unit] = {verdict, x[0].size()};
  });
  std::uint64_t trials_used = 0;
  s.decided = s.false_verdicts = 0;
  for (const auto& [verdict, trials] : outcomes) {
    trials_used += trials;
    if (verdict == Verdict::Inconclusive) continue;
    ++s.decided;
    const bool right = (s.margin > 0 && verdict == Verdict::Holds) ||
                       (s.margin < 0 && verdict == Verdict::DoesNotHold);
    s.false_verdicts += !right;
  }
  s.mean_trials = s.replications > 0 ? static_cast<double>(trials_used) / s.replications : 0.0;
  s.false_rate_ci =
      s.replications > 0
          ? clopper_pearson(s.false_verdicts, static_cast<std::uint64_t>(s.replications), 0.95)
          : Interval{0, 1};
  return s;
}

std::vector<std::string> fit_next_look(std::vector<UnitForecast> open, double left) {
  std::sort(open.begin(), open.end(),
            [](const UnitForecast& a, const UnitForecast& b) { return a.unit < b.unit; });
  std::erase_if(open, [left](const UnitForecast& u) {
    return u.next_seconds * std::max(0.0, u.need - 1) > left;
  });
  double total = 0;
  for (const auto& u : open) total += u.next_seconds;
  while (total > left && !open.empty()) {
    const auto costliest =
        std::max_element(open.begin(), open.end(), [](const auto& a, const auto& b) {
          return a.next_seconds < b.next_seconds;
        });
    total -= costliest->next_seconds;
    open.erase(costliest);
  }
  std::vector<std::string> kept;
  for (const auto& u : open) kept.push_back(u.unit);
  return kept;
}

} // namespace antkit::experiments
