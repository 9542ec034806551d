#pragma once
// The uncertainty behind every verdict of `antkit reproduce` (issue 29): intervals for a measured
// figure, the rule that compares an interval with a threshold, and the one "partly" convention.
// Reporting side (after the deterministic runs), so floating point is allowed here (DESIGN.md,
// rule 1); the bootstrap's resampling draws come from the kernel's keyed streams, so an interval
// depends only on the data and its key, never on threads, ranks or what ran before.
//
// Intervals:
//   - clopper_pearson: the exact (conservative) binomial interval for k successes of n, by
//     bisection on the binomial tail sums; [0, 1 - (alpha/2)^(1/n)] for k = 0 and its mirror for
//     k = n.
//   - bootstrap: the percentile bootstrap of a statistic of one or more samples; each sample is
//     resampled with replacement, `resamples` times; the samples come in blocks of `block`
//     consecutive samples measured on the same trials (e.g. an arena's nBC and trail length, or
//     three algorithms on the same maps), which share their indices (block 1: every sample
//     independent; 0: all samples one block), and the interval is the (alpha/2, 1 - alpha/2)
//     quantiles (type 7) of the replicates. Replicate r of part `part` of the claim keyed `claim`
//     draws from kernel::Stream(seed, kBootstrapExperiment, claim, part, r).
//
// Deciding: a rule is "below t", "above t" or "within +-t", each strict (t itself is where it
// does not hold). decide() says holds when the whole interval is on the rule's side, does not hold
// when the whole interval is on the other side or on the threshold, and inconclusive when it has
// figures on both sides. An exact figure (no sampling noise) has the interval [v, v]; a figure on
// the threshold decides only for a discrete figure, whose interval can be [t, t] (a blending size
// equal at two widths: not larger).
//
// The partly convention (combine): a claim of several parts (one per arena, row, environment...)
// holds when every part holds, does not hold when every part does not hold, is partly when at
// least one part holds and at least one does not, and is inconclusive otherwise (some part
// undecided and the decided parts all on one side). So a claim decided at a small trial count
// cannot be decided the other way at a larger one unless an interval missed its true value.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace antkit::experiments {

enum class Verdict { Holds, Partly, DoesNotHold, Inconclusive };
[[nodiscard]] const char* verdict_text(Verdict v);

struct Interval {
  double lo = 0, hi = 0;
};

// The exact binomial interval at `level` (e.g. 0.95) for k of n (n >= 1, k <= n).
[[nodiscard]] Interval clopper_pearson(std::uint64_t k, std::uint64_t n, double level);

using Samples = std::vector<std::vector<double>>;
using Statistic = std::function<double(const Samples&)>;

// The streams' experiment number of the bootstrap (no experiment uses it).
inline constexpr std::uint64_t kBootstrapExperiment = 29000;

struct BootstrapKey {
  std::uint64_t seed = 1;  // the run's seed
  std::uint64_t claim = 0; // claim_key(id)
  std::uint64_t part = 0;  // the part's index in its claim
};
// A claim id's stream key: FNV-1a of its text.
[[nodiscard]] std::uint64_t claim_key(const std::string& id);

// The percentile bootstrap interval at `level` of `statistic` over `samples` (none empty; the
// samples of a block of one length).
[[nodiscard]] Interval bootstrap(const Samples& samples, std::size_t block,
                                 const Statistic& statistic, double level, BootstrapKey key,
                                 int resamples);

enum class Side {
  Below, // holds when the figure is below the threshold
  Above, // holds when the figure is above the threshold
  Within // holds when -threshold < figure < threshold (a magnitude against the paper's number)
};
struct Rule {
  Side side = Side::Below;
  double threshold = 0;
};
[[nodiscard]] Verdict decide(const Interval& ci, const Rule& rule);
[[nodiscard]] Verdict combine(const std::vector<Verdict>& parts);

// The sample median (type 7) and mean; 0 for an empty sample.
[[nodiscard]] double median(std::vector<double> v);
[[nodiscard]] double mean(const std::vector<double>& v);

} // namespace antkit::experiments
