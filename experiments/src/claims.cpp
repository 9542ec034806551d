// The generic side of the claims (claims.hpp): a spec's parts evaluated, their intervals and
// verdicts, and the text the report prints. The claims themselves are in claims_000.cpp ...
#include <antkit/experiments/claims.hpp>
#include <antkit/experiments/format.hpp>
#include <cmath>
#include <cstdio>
#include <utility>

namespace antkit::experiments {

namespace {

std::string format_value(double v, Unit unit, int decimals) {
  char buf[64];
  if (unit == Unit::Percent)
    std::snprintf(buf, sizeof buf, "%.*f %%", decimals, 100 * v);
  else
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string join_labels(const std::vector<Part>& parts, Verdict which, bool figures) {
  std::string out;
  for (const auto& p : parts)
    if (p.verdict == which)
      out += (out.empty() ? "" : ", ") + p.label + (figures ? " (" + p.format(p.value) + ")" : "");
  return out;
}

} // namespace

const char* interval_method_text(IntervalMethod m) {
  switch (m) {
  case IntervalMethod::Exact:
    return "exact";
  case IntervalMethod::Bootstrap:
    return "bootstrap";
  case IntervalMethod::ClopperPearson:
    return "Clopper-Pearson";
  }
  return "?";
}

std::string Part::format(double v) const {
  return format_value(v, unit, decimals);
}

std::string Part::figure() const {
  if (method == IntervalMethod::Exact) return format(value);
  return format(value) + " [" + format(ci.lo) + ", " + format(ci.hi) + "]";
}

namespace {

// The fields every kind of part sets.
Part part_of(std::string label, Rule rule, IntervalMethod method, Unit unit, int decimals) {
  Part p;
  p.label = std::move(label);
  p.rule = rule;
  p.method = method;
  p.unit = unit;
  p.decimals = decimals;
  return p;
}

} // namespace

Part exact_part(std::string label, double value, Rule rule, Unit unit, int decimals) {
  Part p = part_of(std::move(label), rule, IntervalMethod::Exact, unit, decimals);
  p.exact = value;
  return p;
}

Part count_part(std::string label, std::uint64_t successes, std::uint64_t trials, Rule rule) {
  Part p = part_of(std::move(label), rule, IntervalMethod::ClopperPearson, Unit::Percent, 1);
  p.successes = successes;
  p.trials = trials;
  return p;
}

Part bootstrap_part(std::string label, Samples samples, std::size_t block, Statistic statistic,
                    Rule rule, Unit unit, int decimals) {
  Part p = part_of(std::move(label), rule, IntervalMethod::Bootstrap, unit, decimals);
  p.samples = std::move(samples);
  p.block = block;
  p.statistic = std::move(statistic);
  return p;
}

std::string rule_text(const Rule& rule, Unit unit, int decimals) {
  const std::string t = format_value(rule.threshold, unit, decimals);
  switch (rule.side) {
  case Side::Below:
    return "below " + t;
  case Side::Above:
    return "above " + t;
  case Side::Within:
    return "within +-" + t;
  }
  return "?";
}

double relative(double a, double b) {
  return b != 0 ? a / b - 1 : 0.0;
}

std::vector<Part> evaluate_parts(const ClaimSpec& spec, const ClaimInputs& inputs,
                                 std::uint64_t seed, double alpha) {
  std::vector<Part> parts = spec.parts(inputs);
  std::size_t uncertain = 0;
  for (const auto& p : parts) uncertain += p.method != IntervalMethod::Exact;
  const double level = uncertain > 0 ? 1 - alpha / static_cast<double>(uncertain) : 1.0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Part& p = parts[i];
    switch (p.method) {
    case IntervalMethod::Exact:
      p.value = p.exact;
      p.ci = {p.exact, p.exact};
      p.level = 1;
      break;
    case IntervalMethod::ClopperPearson:
      p.value = p.trials > 0 ? static_cast<double>(p.successes) / static_cast<double>(p.trials) : 0;
      p.ci = p.trials > 0 ? clopper_pearson(p.successes, p.trials, level) : Interval{0, 1};
      p.level = level;
      break;
    case IntervalMethod::Bootstrap:
      p.value = p.statistic(p.samples);
      p.ci = bootstrap(p.samples, p.block, p.statistic, level, {seed, claim_key(spec.id), i},
                       kBootstrapResamples);
      p.level = level;
      break;
    }
    p.verdict = decide(p.ci, p.rule);
  }
  return parts;
}

double miss_of(const Part& p) {
  switch (p.rule.side) {
  case Side::Below:
    return p.value - p.rule.threshold;
  case Side::Above:
    return p.rule.threshold - p.value;
  case Side::Within:
    return std::fabs(p.value) - p.rule.threshold;
  }
  return 0;
}

Claim evaluate(const ClaimSpec& spec, const ClaimInputs& inputs, std::uint64_t seed, double alpha) {
  return claim_of(spec, inputs, evaluate_parts(spec, inputs, seed, alpha));
}

Claim claim_of(const ClaimSpec& spec, const ClaimInputs& inputs, const std::vector<Part>& parts) {
  std::vector<Verdict> verdicts;
  for (const auto& p : parts) verdicts.push_back(p.verdict);
  Claim c;
  c.id = spec.id;
  c.paper = std::string(spec.id).substr(0, 3);
  c.source = spec.source;
  c.text = spec.text;
  c.rule = spec.rule;
  c.quote = spec.quote;
  c.experiment = spec.experiment;
  c.verdict = combine(verdicts);
  std::size_t holds = 0, not_held = 0;
  for (const auto v : verdicts) holds += v == Verdict::Holds, not_held += v == Verdict::DoesNotHold;
  std::string measured = spec.note ? spec.note(inputs, parts) : std::string();
  if (parts.size() <= 4) {
    for (const auto& p : parts)
      measured += (measured.empty() ? "" : "; ") + p.label + ": " + p.figure();
  } else {
    measured += (measured.empty() ? "" : "; ") + std::to_string(holds) + " of " +
                std::to_string(parts.size()) + " parts hold, " + std::to_string(not_held) +
                " do not, " + std::to_string(parts.size() - holds - not_held) + " undecided";
  }
  c.measured = measured;
  if (c.verdict != Verdict::Holds) {
    std::string why;
    const std::string off = join_labels(parts, Verdict::DoesNotHold, parts.size() > 4);
    const std::string open = join_labels(parts, Verdict::Inconclusive, false);
    if (!off.empty()) why += "does not hold at " + off + ". ";
    if (!open.empty()) why += "Undecided (the interval spans the threshold) at " + open + ". ";
    if (spec.why) why += spec.why(inputs, parts);
    while (!why.empty() && why.back() == ' ') why.pop_back();
    c.why = why;
  }
  for (const auto& p : parts) {
    c.parts.push_back({p.label, rule_text(p.rule, p.unit, p.decimals), p.value, p.ci, p.level,
                       interval_method_text(p.method), p.figure(), p.verdict});
    c.parts.back().side = p.rule.side;
    c.parts.back().threshold = p.rule.threshold;
    c.parts.back().miss = miss_of(p);
    c.parts.back().miss_text = p.format(std::fabs(c.parts.back().miss));
  }
  return c;
}

} // namespace antkit::experiments
