#include <algorithm>
#include <antkit/experiments/verdict.hpp>
#include <antkit/kernel/random.hpp>
#include <cmath>
#include <stdexcept>

namespace antkit::experiments {

namespace {

// P(X <= k) for X ~ Binomial(n, p), summed in log space.
double binomial_cdf(std::uint64_t k, std::uint64_t n, double p) {
  if (p <= 0) return 1;
  if (p >= 1) return k >= n ? 1 : 0;
  const double nn = static_cast<double>(n);
  double sum = 0;
  for (std::uint64_t i = 0; i <= k; ++i) {
    const double ii = static_cast<double>(i);
    const double log_pmf = std::lgamma(nn + 1) - std::lgamma(ii + 1) - std::lgamma(nn - ii + 1) +
                           ii * std::log(p) + (nn - ii) * std::log1p(-p);
    sum += std::exp(log_pmf);
  }
  return std::min(sum, 1.0);
}

// The p in [0, 1] where f (monotone decreasing in p) crosses `target`.
template <class F>
double solve_decreasing(F f, double target) {
  double lo = 0, hi = 1;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (f(mid) > target)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

// The two order statistics it needs, i and i + 1, by a selection (linear time) instead of a sort:
// the same values, so the same figures bit for bit. Reorders v.
double type7(std::vector<double>& v, double q) {
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(pos));
  const auto at = v.begin() + static_cast<std::ptrdiff_t>(i);
  std::nth_element(v.begin(), at, v.end());
  const double vi = *at;
  const double vj = i + 1 < v.size() ? *std::min_element(at + 1, v.end()) : vi;
  return vi + (pos - static_cast<double>(i)) * (vj - vi);
}

} // namespace

const char* verdict_text(Verdict v) {
  switch (v) {
  case Verdict::Holds:
    return "holds";
  case Verdict::Partly:
    return "partly";
  case Verdict::DoesNotHold:
    return "does not hold";
  case Verdict::Inconclusive:
    return "inconclusive at this trial count";
  }
  return "?";
}

Interval clopper_pearson(std::uint64_t k, std::uint64_t n, double level) {
  if (n == 0 || k > n) throw std::invalid_argument("clopper_pearson: need 0 <= k <= n, n >= 1");
  const double alpha = 1 - level;
  Interval out{0, 1};
  // Lower: the p with P(X >= k) = alpha / 2, i.e. P(X <= k - 1) = 1 - alpha / 2.
  if (k > 0)
    out.lo = solve_decreasing([&](double p) { return binomial_cdf(k - 1, n, p); }, 1 - alpha / 2);
  // Upper: the p with P(X <= k) = alpha / 2.
  if (k < n) out.hi = solve_decreasing([&](double p) { return binomial_cdf(k, n, p); }, alpha / 2);
  return out;
}

std::uint64_t claim_key(const std::string& id) {
  std::uint64_t h = 1469598103934665603ull;
  for (const char c : id) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

Interval bootstrap(const Samples& samples, std::size_t block, const Statistic& statistic,
                   double level, BootstrapKey key, int resamples) {
  if (samples.empty() || resamples < 2)
    throw std::invalid_argument("bootstrap: no samples or fewer than 2 resamples");
  if (block == 0) block = samples.size();
  for (std::size_t s = 0; s < samples.size(); ++s)
    if (samples[s].empty() || samples[s].size() >= (std::size_t{1} << 32) ||
        samples[s].size() != samples[s - s % block].size())
      throw std::invalid_argument("bootstrap: an empty sample, or a block of unequal sizes");
  Samples drawn = samples;
  std::vector<double> replicates;
  replicates.reserve(static_cast<std::size_t>(resamples));
  std::vector<std::uint32_t> index;
  for (int r = 0; r < resamples; ++r) {
    kernel::Stream stream(key.seed, kBootstrapExperiment, key.claim, key.part,
                          static_cast<std::uint64_t>(r));
    for (std::size_t first = 0; first < samples.size(); first += block) {
      const auto n = static_cast<std::uint32_t>(samples[first].size());
      index.resize(n);
      for (auto& i : index) i = stream.below(n);
      for (std::size_t s = first; s < std::min(first + block, samples.size()); ++s)
        for (std::size_t i = 0; i < n; ++i) drawn[s][i] = samples[s][index[i]];
    }
    replicates.push_back(statistic(drawn));
  }
  const double alpha = 1 - level;
  std::vector<double> copy = replicates;
  return {type7(copy, alpha / 2), type7(replicates, 1 - alpha / 2)};
}

Verdict decide(const Interval& ci, const Rule& rule) {
  const double t = rule.threshold;
  switch (rule.side) {
  // The rules are strict (below t: figure < t), so a figure on the threshold is on the side where
  // the rule does not hold: an interval that reaches the threshold only from that side decides.
  // For a figure that varies continuously this changes nothing (an end exactly on t has
  // probability 0); for a discrete one (a blending size in steps of 10, an exact count) it is
  // what lets an interval [t, t] decide at all.
  case Side::Below:
    return ci.hi < t ? Verdict::Holds : ci.lo >= t ? Verdict::DoesNotHold : Verdict::Inconclusive;
  case Side::Above:
    return ci.lo > t ? Verdict::Holds : ci.hi <= t ? Verdict::DoesNotHold : Verdict::Inconclusive;
  case Side::Within:
    if (ci.lo > -t && ci.hi < t) return Verdict::Holds;
    if (ci.lo >= t || ci.hi <= -t) return Verdict::DoesNotHold;
    return Verdict::Inconclusive;
  }
  return Verdict::Inconclusive;
}

Verdict combine(const std::vector<Verdict>& parts) {
  std::size_t holds = 0, not_held = 0;
  for (const auto v : parts) {
    holds += v == Verdict::Holds;
    not_held += v == Verdict::DoesNotHold;
  }
  if (parts.empty()) return Verdict::Inconclusive;
  if (holds == parts.size()) return Verdict::Holds;
  if (not_held == parts.size()) return Verdict::DoesNotHold;
  if (holds > 0 && not_held > 0) return Verdict::Partly;
  return Verdict::Inconclusive;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  return type7(v, 0.5);
}

double mean(const std::vector<double>& v) {
  if (v.empty()) return 0;
  double s = 0;
  for (const double x : v) s += x;
  return s / static_cast<double>(v.size());
}

} // namespace antkit::experiments
