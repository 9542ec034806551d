#pragma once
// The papers' claims as data (issue 29). Each paper's claims are one table in its own file,
// experiments/src/claims_000.cpp, claims_001.cpp, claims_002.cpp and claims_004.cpp: one ClaimSpec
// per claim, with its id, where the paper says it, the claim in a sentence, the paper's own words,
// the rule in words, the experiment it reads, and a function from the experiments' results to the
// claim's parts. reproduce.cpp evaluates every spec of the papers it ran (evaluate() below) and
// writes the report; adding a claim touches its paper's file only.
//
// A part is one test of a claim (one arena, row, environment, pair...): a figure, its interval,
// and a rule (verdict.hpp: below, above or within a threshold). Its interval is one of
//   Bootstrap       the figure is `statistic(samples)`, the interval its percentile bootstrap
//                   (resamples below, keyed by the run's seed, the claim's id and the part's
//                   index);
//   ClopperPearson  the figure is a proportion k / n of runs, the interval exact (binomial);
//   Exact           the figure has no sampling noise (an invariant checked on every run, a count
//                   over a fixed set of maps); the interval is the figure itself.
// Levels: a claim's verdict is at 95 %, family-wise: a claim of m parts with intervals gives each
// part the level 1 - 0.05 / m (Bonferroni), so that all its intervals hold together with
// probability at least 95 %. The claim's verdict combines its parts' (verdict.hpp's partly
// convention).
#include <antkit/experiments/buffon_figures.hpp>
#include <antkit/experiments/explore_tables.hpp>
#include <antkit/experiments/reproduce.hpp>
#include <antkit/experiments/stc_floor.hpp>
#include <antkit/experiments/stc_tours.hpp>
#include <antkit/experiments/uniform_tables.hpp>
#include <antkit/experiments/verdict.hpp>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <typeindex>
#include <typeinfo>
#include <vector>

namespace antkit::experiments {

struct BuffonResults {
  std::map<int, BuffonFigure> figures; // 5..9
  Figure14 fig14;
};

// Paper 004's results: its tables with the line-of-sight sensor and with the disk sensor, and the
// runs per row.
struct UniformResults {
  std::vector<uniform_tables::TablesRow> rows, disk;
  std::uint32_t runs = 0;
};

// What the experiments of one run gave, by type (each paper puts its own results: papers.hpp);
// get<T>() is null where no paper put a T. Paper 000 puts BuffonResults, 001 ExploreTables, 002
// StcTours and FloorCurves (its robot on its floor), 004 UniformResults.
class ClaimInputs {
public:
  template <class T>
  void put(const T& results) {
    results_[std::type_index(typeid(T))] = &results;
  }
  template <class T>
  [[nodiscard]] const T* get() const {
    const auto it = results_.find(std::type_index(typeid(T)));
    return it == results_.end() ? nullptr : static_cast<const T*>(it->second);
  }

private:
  std::map<std::type_index, const void*> results_;
};

enum class IntervalMethod { Exact, Bootstrap, ClopperPearson };
[[nodiscard]] const char* interval_method_text(IntervalMethod m);

// How a part's figure is printed: a fraction as a percentage (0.123 -> "12.3 %"), or a number
// with `decimals` decimals.
enum class Unit { Percent, Number };

struct Part {
  std::string label; // "d = 30", "10 % / 2 robots"
  Rule rule;
  IntervalMethod method = IntervalMethod::Exact;
  Unit unit = Unit::Number;
  int decimals = 2;
  // Bootstrap: the figure is statistic(samples).
  Samples samples;
  std::size_t block = 1; // samples sharing resampling indices (verdict.hpp; 0: all)
  Statistic statistic;
  // ClopperPearson: `successes` of `trials`; the figure is their ratio.
  std::uint64_t successes = 0, trials = 0;
  // Exact: the figure.
  double exact = 0;

  // Set by evaluate().
  double value = 0;
  Interval ci;
  double level = 1; // the interval's level
  Verdict verdict = Verdict::Inconclusive;

  [[nodiscard]] std::string format(double v) const;
  [[nodiscard]] std::string figure() const; // "12.3 % [10.1 %, 14.0 %]"
};

// Builders of the usual parts.
[[nodiscard]] Part exact_part(std::string label, double value, Rule rule, Unit unit = Unit::Number,
                              int decimals = 2);
[[nodiscard]] Part count_part(std::string label, std::uint64_t successes, std::uint64_t trials,
                              Rule rule);
[[nodiscard]] Part bootstrap_part(std::string label, Samples samples, std::size_t block,
                                  Statistic statistic, Rule rule, Unit unit = Unit::Percent,
                                  int decimals = 1);

struct ClaimSpec {
  const char* id;         // "000-1"
  const char* family;     // the --only name that runs its experiment: buffon, los, stc, uniform
  const char* source;     // where the paper says it: "Figure 5, section 6.1"
  const char* text;       // the claim, in a sentence
  const char* quote;      // the paper's own words ("" for a claim of ours beside the paper)
  const char* rule;       // how we decide it, in words
  const char* experiment; // the report's file it reads, e.g. "buffon/figure5.csv"
  std::function<std::vector<Part>(const ClaimInputs&)> parts;
  // Optional: what the report says besides the parts' figures (e.g. the paper's numbers), and why
  // where the claim does not hold (default: the parts that do not hold, and those undecided).
  std::function<std::string(const ClaimInputs&, const std::vector<Part>&)> note = {};
  std::function<std::string(const ClaimInputs&, const std::vector<Part>&)> why = {};
};

// Each paper's table, in id order.
[[nodiscard]] const std::vector<ClaimSpec>& claims_000();
[[nodiscard]] const std::vector<ClaimSpec>& claims_001();
[[nodiscard]] const std::vector<ClaimSpec>& claims_002();
[[nodiscard]] const std::vector<ClaimSpec>& claims_004();

// Bootstrap resamples per interval.
inline constexpr int kBootstrapResamples = 2000;

// The claim a spec gives on these results: its parts evaluated (intervals at 1 - alpha / m for m
// parts with intervals, bootstrap streams keyed by `seed`), their verdicts combined, the measured
// text (note, then each part's figure) and why. `antkit reproduce` uses alpha = 0.05; --decide
// spends it over its planned looks (reproduce.hpp).
[[nodiscard]] Claim evaluate(const ClaimSpec& spec, const ClaimInputs& inputs, std::uint64_t seed,
                             double alpha = 0.05);
// The two halves of evaluate(): the parts, each with its figure, interval and verdict; and the
// claim those parts give (--decide keeps each part as it was at the look that decided it).
[[nodiscard]] std::vector<Part> evaluate_parts(const ClaimSpec& spec, const ClaimInputs& inputs,
                                               std::uint64_t seed, double alpha = 0.05);
[[nodiscard]] Claim claim_of(const ClaimSpec& spec, const ClaimInputs& inputs,
                             const std::vector<Part>& parts);
// How far a part's figure is past its threshold on the side where it does not hold (its miss;
// negative when it is on the holding side): figure - t below t, t - figure above t, |figure| - t
// within +-t.
[[nodiscard]] double miss_of(const Part& part);

// The rule's threshold in words ("below 5 %", "within +-15 %").
[[nodiscard]] std::string rule_text(const Rule& rule, Unit unit, int decimals);

// Relative difference a / b - 1 (0 when b = 0).
[[nodiscard]] double relative(double a, double b);

} // namespace antkit::experiments
