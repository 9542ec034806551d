#include <algorithm>
#include <antkit/experiments/claims.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/papers.hpp>
#include <antkit/experiments/reproduce.hpp>
#include <antkit/experiments/sequential.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace antkit::experiments {

using kernel::InputError;

namespace {

nlohmann::json parts_json(const std::vector<ClaimPart>& parts) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : parts)
    out.push_back({{"label", p.label},
                   {"value", p.value},
                   {"interval", {p.ci.lo, p.ci.hi}},
                   {"level", p.level},
                   {"method", p.method},
                   {"rule", p.rule},
                   {"verdict", verdict_text(p.verdict)},
                   {"miss", p.miss}});
  return out;
}

// The counts of a look: the scale's, times `factor`.
Trials scaled(const Trials& base, int factor) {
  Trials t = base;
  t.buffon *= factor;
  t.uniform_runs *= factor;
  t.stc_random_maps *= factor;
  t.stc_noise_trials *= factor;
  t.stc_floor_boards *= factor;
  return t;
}

// --decide's looks: look k runs 2^k times the scale's counts. Its alpha is 0.05 / ((k + 1)(k + 2))
// (0.025, 0.0083, 0.0042, ...: the series sums to 0.05 over any number of looks), so no look count
// is planned: a budget only says where the looks stop, and a time budget's report is the report
// of the budget in trials it reached.
double look_alpha(int look) {
  return experiments::look_alpha(0.05, look); // sequential.hpp
}
int look_factor(int look) {
  return 1 << look;
}
inline constexpr int kMaxLooks = 20;

// How many times a look's trials would settle a claim, if every interval's half-width shrinks as
// one over the square root of the trials and each undecided part ends on the side its figure is
// on now: parts decide in the order of their own need ((half-width / distance from the threshold
// it straddles)^2), and the claim's need is the first at which the combined verdict is decided.
// Infinite when a figure sits on its threshold.
double settling_ratio(const std::vector<Part>& parts) {
  std::vector<Verdict> verdicts;
  std::vector<std::pair<double, std::size_t>> open;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Part& p = parts[i];
    verdicts.push_back(p.verdict);
    if (p.verdict != Verdict::Inconclusive) continue;
    const double half = (p.ci.hi - p.ci.lo) / 2;
    double distance = std::fabs(p.value - p.rule.threshold);
    if (p.rule.side == Side::Within)
      distance = std::min(distance, std::fabs(p.value + p.rule.threshold));
    const double ratio = distance <= 1e-12 * std::max(1.0, std::fabs(p.rule.threshold))
                             ? std::numeric_limits<double>::infinity()
                             : (half / distance) * (half / distance);
    open.emplace_back(std::max(1.0, ratio), i);
  }
  std::sort(open.begin(), open.end());
  for (const auto& [ratio, i] : open) {
    const Part& p = parts[i];
    verdicts[i] = decide({p.value, p.value}, p.rule);
    if (verdicts[i] == Verdict::Inconclusive) return std::numeric_limits<double>::infinity();
    if (combine(verdicts) != Verdict::Inconclusive) return ratio;
  }
  return std::numeric_limits<double>::infinity();
}

// --decide's state: every claim's parts as decided so far. A part decided at a look keeps that
// look's figure, interval and verdict; a claim is settled once its combined verdict is decided
// (holds, does not hold or partly: none of them can change as more parts decide) and then keeps
// the claim of that look. Look k evaluates at alpha_k = look_alpha(k) per claim (alpha_k / m per
// part of a claim of m parts): by the union bound every interval of every look of a claim holds
// with probability at least 1 - sum alpha_k >= 95 %.
class Settling {
public:
  // Evaluates the claim at this look unless it is settled; returns whether it still asks for
  // trials (unsettled, with an estimate of the trials that would settle it: ratio()). When it
  // asks, its undecided parts are added to `undecided` (what the next look must extend). A claim
  // without an estimate (a figure on its threshold) stops asking; it is evaluated again only when
  // this look ran everything its undecided parts read (`fresh`: another claim asked for the same
  // rows), so that its parts stay at one look's count; otherwise it keeps the look at which it
  // stopped. Whether a claim's trials are worth their time is the time budget's question
  // (reproduce()), not this one's: an estimate from one look's intervals is rough.
  bool look(const ClaimSpec& spec, const ClaimInputs& inputs, std::uint64_t seed, int look,
            std::vector<Part>& undecided,
            const std::function<bool(const std::vector<Part>&)>& fresh) {
    auto& st = states_[spec.id];
    if (st.settled) return false;
    std::vector<Part> parts = evaluate_parts(spec, inputs, seed, look_alpha(look));
    if (st.parts.size() == parts.size())
      for (std::size_t i = 0; i < parts.size(); ++i)
        if (st.parts[i].verdict != Verdict::Inconclusive) parts[i] = st.parts[i];
    if (st.stopped) {
      std::vector<Part> open;
      for (const auto& p : parts)
        if (p.verdict == Verdict::Inconclusive) open.push_back(p);
      if (!fresh(open)) return false;
    }
    st.parts = parts;
    st.claim = claim_of(spec, inputs, parts);
    st.claim.look = look;
    st.settled = st.claim.verdict != Verdict::Inconclusive;
    if (st.settled) return false;
    const double ratio = settling_ratio(parts);
    st.claim.needed = needed_text(ratio, look);
    st.ratio = ratio;
    st.stopped = !std::isfinite(ratio);
    if (st.stopped) return false;
    for (const auto& p : parts)
      if (p.verdict == Verdict::Inconclusive) undecided.push_back(p);
    return true;
  }
  [[nodiscard]] Claim claim(const std::string& id) const { return states_.at(id).claim; }
  // Its last estimate: how many times its last look's trials would settle it.
  [[nodiscard]] double ratio(const std::string& id) const { return states_.at(id).ratio; }

private:
  static std::string needed_text(double ratio, int look) {
    if (!std::isfinite(ratio))
      return "no estimate: a figure sits on its threshold; it stopped asking for trials";
    if (ratio > 1e6) return "more than a million times these trials";
    char buf[128];
    std::snprintf(buf, sizeof buf,
                  "about %.0f times the first look's trials (%.1f times this look's)",
                  std::ceil(ratio * look_factor(look)), ratio);
    return buf;
  }

  struct State {
    std::vector<Part> parts;
    Claim claim;
    double ratio = 1;
    bool settled = false, stopped = false;
  };
  std::map<std::string, State> states_;
};

// A part's interval as its margin over the threshold, in units of `scale`: > 0 on the side where
// it holds. Within +-t, the margin of a figure v is t - |v|.
Interval margin_of(const ClaimPart& p, double scale) {
  const auto m = [&](double v) {
    switch (p.side) {
    case Side::Below:
      return (p.threshold - v) / scale;
    case Side::Above:
      return (v - p.threshold) / scale;
    case Side::Within:
      return (p.threshold - std::fabs(v)) / scale;
    }
    return 0.0;
  };
  if (p.side == Side::Within) {
    const double far = std::max(std::fabs(p.ci.lo), std::fabs(p.ci.hi));
    const double near =
        p.ci.lo <= 0 && p.ci.hi >= 0 ? 0.0 : std::min(std::fabs(p.ci.lo), std::fabs(p.ci.hi));
    return {m(far), m(near)};
  }
  const double a = m(p.ci.lo), b = m(p.ci.hi);
  return {std::min(a, b), std::max(a, b)};
}

// The report's first figure (issue 44): every claim's parts, each its interval as a margin over
// its threshold in units of the tolerance (the threshold's size; for a threshold of 0, the
// largest interval end among the claim's parts), coloured by the claim's verdict, one column per
// claim; above 0 a part holds, below 0 it does not, across 0 it is undecided. Margins are clipped
// to [-3, 3].
Figure forest_plot(const std::vector<Claim>& claims) {
  Figure fig;
  fig.title = "Every claim's parts against their thresholds";
  fig.y_label = "margin over the threshold, in tolerances";
  fig.x_label = "claim";
  fig.caption =
      "Each bar: one part's interval, as its distance past the threshold on the side where it "
      "holds,\nin units of the threshold (of the claim's largest interval end for a threshold of "
      "0), clipped to [-3, 3].\nAbove 0 the part holds, below 0 it does not, across 0 it is "
      "undecided. Colour: the claim's verdict.";
  const std::pair<Verdict, const char*> colours[] = {{Verdict::Holds, "#1b9e3a"},
                                                     {Verdict::Partly, "#e08a00"},
                                                     {Verdict::DoesNotHold, "#d81e1e"},
                                                     {Verdict::Inconclusive, "#707070"}};
  PlotPanel panel;
  for (const auto& [verdict, colour] : colours) {
    PlotSeries series{verdict_text(verdict), colour, false, true, {}};
    for (std::size_t i = 0; i < claims.size(); ++i) {
      const auto& c = claims[i];
      if (c.verdict != verdict) continue;
      double zero_scale = 1e-12;
      for (const auto& p : c.parts)
        zero_scale = std::max({zero_scale, std::fabs(p.ci.lo), std::fabs(p.ci.hi)});
      const std::size_t n = c.parts.size();
      for (std::size_t j = 0; j < n; ++j) {
        const auto& p = c.parts[j];
        const double scale = p.threshold != 0 ? std::fabs(p.threshold) : zero_scale;
        const Interval m = margin_of(p, scale);
        const auto clip = [](double v) { return std::clamp(v, -3.0, 3.0); };
        const double x =
            static_cast<double>(i) +
            (n > 1 ? 0.6 * (static_cast<double>(j) / static_cast<double>(n - 1) - 0.5) : 0.0);
        series.points.push_back({x, clip((m.lo + m.hi) / 2), clip(m.lo), clip(m.hi)});
      }
    }
    if (!series.points.empty()) panel.series.push_back(std::move(series));
  }
  panel.marks.push_back({0, "threshold", "#404040", true, false});
  fig.panels.push_back(std::move(panel));
  for (const auto& c : claims) fig.x_categories.push_back(c.id);
  return fig;
}

// A simulation row of the report: its figures depend on the margin and the spending alone (the
// model and its seed are fixed), so a process computes each once.
SequentialSimulation simulation(double margin, bool spend, unsigned threads) {
  static std::mutex lock;
  static std::map<std::pair<double, bool>, SequentialSimulation> done;
  const std::lock_guard<std::mutex> hold(lock);
  const auto key = std::make_pair(margin, spend);
  if (const auto it = done.find(key); it != done.end()) return it->second;
  SequentialSimulation sim;
  sim.margin = margin;
  sim.spend = spend;
  return done[key] = simulate_sequential(sim, threads);
}

// The report's account of --decide: the method, the looks, what each settled, what is left, and
// the simulation that shows the error stays at or below its rate.
std::string decide_section(const std::vector<Claim>& claims, int looks, const Trials& base,
                           unsigned threads) {
  std::ostringstream s;
  s << "### How `--decide` decided\n\n"
    << looks << " look(s), each twice the trials of the last: paper 000's trials per arena ";
  for (int k = 0; k < looks; ++k)
    s << (k ? ", " : "") << std::int64_t{base.buffon} * look_factor(k);
  s << ", the other papers' counts by the same factors. A look runs only what a claim still asks "
       "trials for: in a figure of paper 000, the arenas whose trials its undecided parts "
       "resample (their later trials added to the earlier ones, keyed by their index; so a "
       "figure's arenas can end at different counts, its CSV's trials column), or a whole family "
       "of the others (rerun at the new count: seconds). After each look every claim still "
       "asking is evaluated again; a part whose interval decides it keeps that look's figure and "
       "verdict, and a claim is settled once its combined verdict is decided (holds, does not "
       "hold or partly: none can change as more parts decide). A claim with no estimate of the "
       "trials it needs (a figure on its threshold) stops asking for them; it is evaluated "
       "again only at a look that reran everything it reads for another claim. Within a budget "
       "in trials every other claim asks until the budget. Within a time budget a unit (a "
       "figure of paper 000, or another paper) stops when the trials its likeliest claim still "
       "needs (its estimate below) would not fit in the time left, and when the next look does "
       "not fit, its costliest runs stop first; the rerun line above names the units stopped so "
       "(`--unit-budget`). The looks end when nothing asks, or at the budget.\n\n"
    << "The error across the repeated looks: alpha spending over an open-ended series of looks. "
       "Look k (from 0) evaluates at alpha_k = 0.05 / ((k + 1)(k + 2)) per claim (0.025, "
       "0.0083, 0.0042, 0.0025, ...), a part of a claim of m parts at 1 - alpha_k / m; the "
       "alpha_k sum to 0.05 over any number of looks, so by the union bound every interval of "
       "every look of a claim holds with probability at least 95 %, and then no verdict of the "
       "claim is false. We chose it because it needs no planned number of looks (a budget, in "
       "trials or in time, only says where the looks stop, so a time budget's report is the "
       "report of the trial budget it reached) and nothing of the joint law of the looks (the "
       "later looks contain the earlier trials, and the intervals are percentile bootstraps of "
       "medians, not the Gaussian statistics O'Brien-Fleming or Pocock boundaries assume); it "
       "is conservative, and the error is controlled per claim: across the claims it bounds the "
       "expected share of false verdicts at 5 %, not the chance of any.\n\n"
    << "| look | alpha | paper 000 trials per arena | claims settled at this look |\n"
       "|---|---|---|---|\n";
  for (int k = 0; k < looks; ++k) {
    std::string ids;
    for (const auto& c : claims)
      if (c.look == k && c.verdict != Verdict::Inconclusive)
        ids += (ids.empty() ? "" : ", ") + c.id;
    char alpha[32];
    std::snprintf(alpha, sizeof alpha, "%.4g", look_alpha(k));
    s << "| " << k + 1 << " | " << alpha << " | " << std::int64_t{base.buffon} * look_factor(k)
      << " | " << (ids.empty() ? std::string("none") : ids) << " |\n";
  }
  std::string open;
  for (const auto& c : claims)
    if (c.verdict == Verdict::Inconclusive)
      open += "- " + c.id + ": " + c.measured + "; " + c.needed + ".\n";
  s << '\n'
    << (open.empty() ? std::string("Every claim is settled.\n\n")
                     : "Still undecided (the last look's intervals, and the trials that would "
                       "settle the claim if the intervals shrink as one over the square root of "
                       "the trials and each undecided part ends on the side its figure is on "
                       "now):\n\n" +
                           open + "\n");
  s << "#### The error, by simulation\n\n"
    << "Claims whose truth we set: exponential trials, their median against a threshold at the "
       "true median times (1 + margin), decided by the same bootstrap (1000 resamples) at the "
       "same looks (20, 40, 80, 160 trials, each at its alpha_k), 400 claims a row "
       "(experiments/sequential.hpp). At margin 0 the truth sits on the threshold and any "
       "verdict is false: the worst case. The last row looks four times at 95 % without "
       "spending, to show what the spending buys.\n\n"
    << "| truth | margin | spending | verdicts | false | false rate [95 %] | mean trials |\n"
       "|---|---|---|---|---|---|---|\n";
  struct Row {
    double margin;
    bool spend;
  };
  for (const Row r : {Row{0, true}, Row{0.5, true}, Row{-0.5, true}, Row{0, false}}) {
    const SequentialSimulation sim = simulation(r.margin, r.spend, threads);
    char rate[96];
    std::snprintf(rate, sizeof rate, "%.1f %% [%.1f %%, %.1f %%]", 100 * sim.false_rate(),
                  100 * sim.false_rate_ci.lo, 100 * sim.false_rate_ci.hi);
    s << "| "
      << (r.margin > 0   ? "holds"
          : r.margin < 0 ? "does not hold"
                         : "on the threshold")
      << " | " << number(r.margin) << " | " << (r.spend ? "alpha_k" : "none (0.05 a look)") << " | "
      << sim.decided << " | " << sim.false_verdicts << " | " << rate << " | "
      << fixed(sim.mean_trials, 1) << " |\n";
  }
  s << '\n';
  return s.str();
}

// Whether the options run paper `e` (--only, or every paper).
bool runs(const ReproduceOptions& o, const PaperEntry& e) {
  return o.only.empty() || std::find(o.only.begin(), o.only.end(), e.family) != o.only.end();
}

// The --unit-budget flags of the options, in unit order.
std::string unit_budget_flags(const ReproduceOptions& o) {
  std::string s;
  for (const auto& [unit, n] : o.unit_budget)
    s += " --unit-budget " + unit + "=" + std::to_string(n);
  return s;
}
} // namespace

Trials trials_of(Scale scale) {
  if (scale == Scale::Full) return {};
  return {20, 3, 6, 10, 4};
}

void validate(const ReproduceOptions& options) {
  std::string families;
  for (const auto& e : papers()) families += (families.empty() ? "" : ", ") + e.family;
  for (const auto& name : options.only)
    if (std::none_of(papers().begin(), papers().end(),
                     [&](const PaperEntry& e) { return e.family == name; }))
      throw InputError("families", "'" + name + "' is not one of " + families);
  if (!options.decide && (options.budget_trials != 0 || options.budget_seconds != 0))
    throw InputError("--budget", "a budget is for --decide");
  const int base = trials_of(options.scale).buffon;
  if (options.budget_trials != 0 &&
      (options.budget_trials < base || options.budget_trials > 100000))
    throw InputError("--budget", "expected " + std::to_string(base) +
                                     " to 100000 trials per arena (the first look runs " +
                                     std::to_string(base) + "), not " +
                                     std::to_string(options.budget_trials));
  if (options.budget_seconds < 0 || options.budget_seconds > 30 * 86400.0)
    throw InputError("--budget", "expected a duration from 1s to 30 days");
  if (options.budget_trials != 0 && options.budget_seconds != 0)
    throw InputError("--budget", "give a budget in trials or in time, not both");
  if (!options.unit_budget.empty() && !options.decide)
    throw InputError("--unit-budget", "a unit's budget is for --decide");
  std::set<std::string> units; // of the papers that run
  if (!options.unit_budget.empty())
    for (const auto& e : papers())
      if (runs(options, e))
        for (const auto& unit : e.make(options)->units()) units.insert(unit);
  for (const auto& [unit, n] : options.unit_budget) {
    if (units.count(unit) == 0) {
      std::string names;
      for (const auto& u : units) names += (names.empty() ? "" : ", ") + u;
      throw InputError("--unit-budget",
                       "'" + unit + "' is not a unit of the papers run (" + names + ")");
    }
    if (n < base || n > 100000)
      throw InputError("--unit-budget", "expected " + std::to_string(base) +
                                            " to 100000 trials per arena for '" + unit + "', not " +
                                            std::to_string(n));
  }
}

std::string reproduce_command(const ReproduceOptions& o, const std::vector<std::string>& only) {
  std::string s =
      std::string("antkit reproduce ") + (o.scale == Scale::Full ? "--full" : "--quick");
  if (!only.empty()) {
    s += " --only ";
    for (std::size_t i = 0; i < only.size(); ++i) s += (i ? "," : "") + only[i];
  }
  if (o.decide) {
    s += " --decide";
    if (o.budget_trials > 0) s += " --budget " + std::to_string(o.budget_trials);
    s += unit_budget_flags(o);
  }
  s += " --seed " + std::to_string(o.seed);
  if (only.empty() || std::find(only.begin(), only.end(), "stc") != only.end())
    s += " --maps " + (o.maps_dir.empty() ? std::string("''") : o.maps_dir.string());
  return s + " --out DIR";
}

std::string claims_markdown(const std::vector<Claim>& claims) {
  // A '|' inside a cell would end it.
  const auto cell = [](const std::string& text) {
    std::string out;
    for (const char ch : text) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
    return out;
  };
  std::ostringstream s;
  s << "| claim | paper | where | the paper says | verdict | measured | why (where it does not "
       "hold) |\n|---|---|---|---|---|---|---|\n";
  for (const auto& c : claims)
    s << "| " << c.id << " | " << c.paper << " | " << cell(c.source) << " | " << cell(c.text)
      << " | **" << verdict_text(c.verdict) << "** | " << cell(c.measured) << " | " << cell(c.why)
      << " |\n";
  return s.str();
}

ReproduceReport reproduce(const ReproduceOptions& o, const algorithms::Runner& runner) {
  validate(o);
  const auto reproduce_started = std::chrono::steady_clock::now();
  const Trials base = trials_of(o.scale);
  ReportFiles w(o.out);
  ReproduceReport report;
  std::ostringstream md;
  const std::string scale = o.scale == Scale::Full ? "full" : "quick";

  // The papers asked for, in id order, each with its run.
  struct Paper {
    const PaperEntry* entry;
    std::unique_ptr<PaperRun> run;
  };
  std::vector<Paper> ran;
  for (const auto& e : papers())
    if (runs(o, e)) ran.push_back({&e, e.make(o)});

  // The looks (one without --decide): look k runs what still has a claim asking for trials, at
  // 2^k times the scale's counts (paper 000 figure by figure and within a figure only the arenas
  // that undecided parts read, its trials added to the earlier looks'; the others whole).
  std::vector<std::pair<PaperRun*, std::string>> running; // the next look's units
  for (const auto& p : ran)
    for (const auto& unit : p.run->units()) running.emplace_back(p.run.get(), unit);
  std::map<std::string, int> unit_look;    // the last look each unit ran
  std::map<std::string, double> unit_cost; // its time at that look, seconds (time budgets)
  Settling settling;                       // --decide: every claim as decided so far (rank 0)
  const auto inputs_now = [&] {
    ClaimInputs in;
    for (const auto& p : ran) p.run->inputs(in);
    return in;
  };
  std::map<std::string, std::int64_t> caps = o.unit_budget; // grows as a time budget stops units
  int last_look = 0;
  for (int look = 0; look < kMaxLooks; ++look) {
    const int factor = look_factor(look);
    const Trials trials = scaled(base, factor);
    if (o.decide && runner.root()) {
      std::cerr << "reproduce: look " << look + 1 << ", " << factor
                << " times the first look's trials, running:";
      for (const auto& [paper, unit] : running) {
        const std::string kept = paper->narrowed_text(unit);
        std::cerr << ' ' << unit << (kept.empty() ? "" : " (" + kept + ")");
      }
      std::cerr << '\n';
    }
    for (const auto& [paper, unit] : running) {
      const auto started = std::chrono::steady_clock::now();
      paper->run(unit, trials, factor, runner);
      unit_cost[unit] =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      unit_look[unit] = look;
    }
    last_look = look;
    if (!o.decide) break;
    // Decide what this look can (rank 0); the units whose claims still ask for trials run again.
    std::set<std::string> open;
    std::map<std::string, std::vector<Part>> undecided; // per open unit
    std::map<std::string, double> share;                // the next run's share of its last
    std::map<std::string, double> need; // per open unit: its asking claims' least estimate
    if (runner.root()) {
      const ClaimInputs inputs = inputs_now();
      for (const auto& p : ran)
        for (const auto& spec : p.entry->claims()) {
          const std::string unit = p.run->unit_of(spec);
          const auto fresh = [&](const std::vector<Part>& parts) {
            return p.run->fresh(unit, parts);
          };
          if (unit_look[unit] == look &&
              settling.look(spec, inputs, o.seed, look, undecided[unit], fresh)) {
            open.insert(unit);
            const double r = settling.ratio(spec.id);
            need[unit] = need.count(unit) > 0 ? std::min(need[unit], r) : r;
          }
        }
      for (const auto& p : ran)
        for (const auto& unit : p.run->units())
          if (open.count(unit) > 0) share[unit] = p.run->narrow(unit, undecided[unit]);
    }
    // The next look: the open units within the budget. A trial budget (and --unit-budget) bounds
    // every unit's count. A time budget predicts each unit's next run from its last: twice its
    // time (paper 000's added trials are twice the last look's, a family's rerun is at twice the
    // counts) times the share the undecided parts still read (PaperRun::narrow). A unit stops
    // when what its likeliest claim still needs (need(), from its intervals: at least its next
    // run times that estimate less one, the runs doubling) cannot fit in the time left; then the
    // costliest next runs stop until the look fits (fit_next_look, sequential.hpp). A stopped unit
    // keeps its last look's count, recorded in `caps` so that a rerun with the budget in trials
    // gives the same bytes.
    std::set<std::string> go;
    const std::int64_t now_trials = std::int64_t{base.buffon} * look_factor(look);
    const std::int64_t next_trials = std::int64_t{base.buffon} * look_factor(look + 1);
    if (runner.root() && look + 1 < kMaxLooks && next_trials <= 100000) {
      const std::int64_t budget = o.budget_trials > 0 ? o.budget_trials : 8 * base.buffon;
      const bool within_trials = o.budget_seconds > 0 || next_trials <= budget;
      for (const auto& unit : open) {
        const auto cap = caps.find(unit);
        if (within_trials && (cap == caps.end() || next_trials <= cap->second)) go.insert(unit);
      }
      if (o.budget_seconds > 0) {
        const double left =
            o.budget_seconds -
            std::chrono::duration<double>(std::chrono::steady_clock::now() - reproduce_started)
                .count();
        std::vector<UnitForecast> forecasts;
        for (const auto& unit : go)
          forecasts.push_back({unit, unit_cost[unit] * 2 * share[unit], need[unit]});
        const auto kept = fit_next_look(std::move(forecasts), left);
        for (const auto& unit : go)
          if (std::find(kept.begin(), kept.end(), unit) == kept.end()) caps[unit] = now_trials;
        go = std::set<std::string>(kept.begin(), kept.end());
      }
    }
    std::vector<std::pair<PaperRun*, std::string>> next;
    for (const auto& r : running)
      if (runner.any(runner.root() && go.count(r.second) > 0)) next.push_back(r);
    running = std::move(next);
    if (running.empty()) break;
  }
  if (!runner.root()) return report;

  // The options that reproduce this report: under --decide, the budget in trials the looks used
  // and the units stopped before it.
  ReproduceOptions ro = o;
  if (o.decide) {
    ro.budget_trials = std::int64_t{base.buffon} * look_factor(last_look);
    ro.budget_seconds = 0;
    ro.unit_budget.clear();
    for (const auto& [unit, n] : caps)
      if (n < ro.budget_trials) ro.unit_budget[unit] = n;
    report.unit_budget = ro.unit_budget;
    report.rerun = "--budget " + std::to_string(ro.budget_trials) + unit_budget_flags(ro);
  }

  // Each paper's files and report section (rank 0).
  std::ostringstream body;
  for (const auto& p : ran) p.run->write(w, ro, body, report.experiments);

  // Every claim of the papers that ran, in the papers' order: as the looks left it under
  // --decide, on the one run's results otherwise.
  const ClaimInputs inputs = inputs_now();
  for (const auto& p : ran)
    for (const auto& spec : p.entry->claims()) {
      if (!o.decide) {
        report.claims.push_back(evaluate(spec, inputs, o.seed));
        continue;
      }
      Claim c = settling.claim(spec.id);
      c.trials = p.run->trials_text(scaled(base, look_factor(c.look)), look_factor(c.look));
      const auto cap = ro.unit_budget.find(p.run->unit_of(spec));
      if (c.verdict == Verdict::Inconclusive && cap != ro.unit_budget.end())
        c.needed += "; the budget stopped " + cap->first + " at the look of " +
                    std::to_string(cap->second) + " trials per arena";
      report.claims.push_back(std::move(c));
    }

  report.looks = last_look + 1;
  report.budget_trials = std::int64_t{base.buffon} * look_factor(last_look);
  if (!report.claims.empty()) w.figure("claims_forest", forest_plot(report.claims));

  // The report.
  std::size_t holds = 0, partly = 0, not_held = 0, open = 0;
  for (const auto& c : report.claims)
    (c.verdict == Verdict::Holds         ? holds
     : c.verdict == Verdict::Partly      ? partly
     : c.verdict == Verdict::DoesNotHold ? not_held
                                         : open)++;
  md << "# The papers, reproduced by antkit\n\n"
     << "`" << reproduce_command(ro, o.only) << "` (" << scale << " scale";
  if (o.scale == Scale::Quick || o.decide) {
    md << ": ";
    for (std::size_t i = 0; i < ran.size(); ++i) md << (i ? "; " : "") << ran[i].run->counts_text();
    md << (o.decide ? "" : ". `--full` runs the papers' counts");
  } else {
    md << ": the papers' trial counts";
  }
  md << "). Every number below depends only on these options, not on the threads or the MPI "
        "ranks: the trials are the kernel's, bit-exact on every compiler and CPU that "
        "scripts/determinism.sh checks; the reductions (medians, means, Figure 14's fit) are "
        "floating point on the machine that writes the report.\n\n"
     << "## Claims\n\n"
     << report.claims.size() << " claims: " << holds << " hold, " << partly << " partly, "
     << not_held << " do not hold, " << open << " inconclusive at this trial count.\n\n"
     << report_image("claims_forest", "every claim's parts against their thresholds")
     << (o.decide ? decide_section(report.claims, last_look + 1, base, runner.threads)
                  : std::string())
     << "How to read a verdict. Each claim is one or more parts (an arena, a row, an "
        "environment...); each part is a figure with an interval and a rule that compares it with "
        "a threshold. The intervals are percentile bootstraps over the trials ("
     << kBootstrapResamples
     << " resamples, drawn from the kernel's keyed streams by seed, claim and part, so the "
        "report stays byte-identical), Clopper-Pearson intervals for a proportion of runs, or "
        "none for an exact figure (an invariant checked on every run). A claim's intervals hold "
        "together at 95 %: with m parts, each is at 1 - 0.05 / m (Bonferroni"
     << (o.decide ? "; under --decide 1 - alpha_k / m at look k, above" : "")
     << "). A part holds when "
        "its interval is on the rule's side of the threshold, does not hold when it is on the "
        "other side or on the threshold itself (the rules are strict: a blending size equal at "
        "two widths is not larger), and is undecided when the interval has figures on both "
        "sides. A claim holds "
        "when every part holds, does not hold when no part holds and every part is decided, is "
        "*partly* when at least one part holds and at least one does not (the one convention "
        "for every claim), and is *inconclusive at this trial count* otherwise: more trials "
        "would decide it"
     << (o.scale == Scale::Quick ? " (`--full` runs the papers' counts)" : "")
     << ". The measured column gives each part's figure [its interval] for claims of up to "
        "four parts, a count for longer ones; every part is listed under \"Claims in detail\" "
        "below.\n\n"
     << claims_markdown(report.claims) << "\nRules, and the papers' own words:\n\n";
  for (const auto& c : report.claims)
    md << "- " << c.id << ": " << c.rule << "."
       << (c.quote.empty() ? std::string(" (A claim of ours beside the paper.)")
                           : " The paper: \"" + c.quote + "\"")
       << " Reads " << c.experiment << ".\n";
  md << "\n## Claims in detail\n\n"
     << "Each part: its figure, the interval (method, level) and the rule.\n\n";
  for (const auto& c : report.claims) {
    md << "### " << c.id << ": " << verdict_text(c.verdict) << "\n\n"
       << "| part | figure [interval] | interval | rule | verdict |\n|---|---|---|---|---|\n";
    for (const auto& p : c.parts) {
      char level[32];
      std::snprintf(level, sizeof level, "%.2f %%", 100 * p.level);
      md << "| " << p.label << " | " << p.figure << " | " << p.method
         << (p.method == std::string("exact") ? std::string() : std::string(", ") + level) << " | "
         << p.rule << " | " << verdict_text(p.verdict)
         << (p.verdict == Verdict::DoesNotHold ? " (misses by " + p.miss_text + ")" : std::string())
         << " |\n";
    }
    if (o.decide)
      md << "\nTrials: " << c.trials << " (look " << c.look + 1 << " of " << last_look + 1
         << (c.verdict == Verdict::Inconclusive ? "; still undecided: " + c.needed : std::string())
         << ").\n";
    md << '\n';
  }
  md << body.str() << "## Trace hashes\n\n"
     << "Each experiment's trace hash (every trial's, in trial order) and a command that "
        "reproduces it. This whole report: `"
     << reproduce_command(ro, o.only) << "`.\n\n| experiment | hash | command |\n|---|---|---|\n";
  for (const auto& e : report.experiments)
    md << "| " << e.name << " | `" << kernel::hash_hex(e.hash) << "` | `" << e.command << "` |\n";

  nlohmann::json j;
  j["command"] = reproduce_command(ro, o.only);
  j["scale"] = scale;
  j["seed"] = o.seed;
  std::vector<std::pair<std::string, std::int64_t>> counts;
  for (const auto& p : ran) p.run->counts_json(counts);
  j["trials"] = nlohmann::json::object();
  for (const auto& [key, n] : counts) j["trials"][key] = n;
  nlohmann::json claims = nlohmann::json::array();
  for (const auto& c : report.claims)
    claims.push_back({{"id", c.id},
                      {"paper", c.paper},
                      {"source", c.source},
                      {"claim", c.text},
                      {"rule", c.rule},
                      {"verdict", verdict_text(c.verdict)},
                      {"measured", c.measured},
                      {"why", c.why},
                      {"quote", c.quote},
                      {"experiment", c.experiment},
                      {"parts", parts_json(c.parts)}});
  j["claims"] = std::move(claims);
  nlohmann::json hashes = nlohmann::json::array();
  for (const auto& e : report.experiments)
    hashes.push_back(
        {{"experiment", e.name}, {"hash", kernel::hash_hex(e.hash)}, {"command", e.command}});
  j["experiments"] = std::move(hashes);
  j["summary"] = {
      {"holds", holds}, {"partly", partly}, {"does_not_hold", not_held}, {"inconclusive", open}};
  j["intervals"] = {{"bootstrap_resamples", kBootstrapResamples},
                    {"family_level", 0.95},
                    {"per_part_level", "1 - 0.05 / m for a claim of m parts with intervals"}};
  if (o.decide) {
    nlohmann::json factors = nlohmann::json::array(), alphas = nlohmann::json::array();
    for (int k = 0; k <= last_look; ++k)
      factors.push_back(look_factor(k)), alphas.push_back(look_alpha(k));
    j["decide"] = {
        {"looks", last_look + 1},
        {"factors", factors},
        {"budget_trials_per_arena", report.budget_trials},
        {"unit_budget", report.unit_budget},
        {"alpha_per_look", alphas},
        {"per_part_level", "1 - alpha_k / m at look k for a claim of m parts with intervals"},
        {"method",
         "alpha spending over an open-ended series of looks: alpha_k = 0.05 / ((k + 1)(k + 2))"}};
    for (std::size_t i = 0; i < report.claims.size(); ++i) {
      const auto& c = report.claims[i];
      j["claims"][i]["look"] = c.look;
      j["claims"][i]["trials"] = c.trials;
      j["claims"][i]["needed"] = c.needed;
    }
  }
  w.text("claims.json", j.dump(2) + "\n");
  w.text("README.md", md.str());
  report.files = w.files();
  return report;
}

} // namespace antkit::experiments
