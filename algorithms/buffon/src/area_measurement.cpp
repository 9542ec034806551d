#include <antkit/algorithms/units.hpp>
#include <antkit/buffon/area_measurement.hpp>
#include <antkit/buffon/two_markers.hpp>
#include <antkit/kernel/hash.hpp>
#include <utility>
#include <vector>

namespace antkit::buffon {

namespace {

double fx_to_double(std::int64_t raw) {
  return static_cast<double>(raw) / 65536.0;
}

TrialParams trial_params(const AreaMeasurementParams& m) {
  TrialParams p;
  p.seed = m.seed;
  p.steps = m.steps;
  p.width = m.width;
  if (m.precision_millionths != 0) {
    p.precision_millionths = m.precision_millionths;
    p.visit2_steps = m.visit2_steps;
    p.online_first_visit = m.rule == PrecisionRule::online;
    p.total_steps =
        budgeted(m) ? (m.total_steps != 0 ? m.total_steps : kDefaultPrecisionBudget) : 0;
  }
  return p;
}

// One trial's reporting-side fields (the order of the operations is the printed numbers').
AreaTrial reduce(TrialResult t, const AreaMeasurementParams& m) {
  AreaTrial a;
  a.length1 = fx_to_double(t.length1_raw);
  a.length2 = fx_to_double(t.length2_raw);
  a.nbc = a.length2 > 0 ? static_cast<double>(t.bc) / a.length2 : 0.0;
  // Two markers count the pairs of pieces apart in time only (two_markers.hpp): pair_share.
  a.closed_form = closed_form_area(a.length1 * t.pair_share, a.length2, t.crossings_exact);
  if (m.precision_millionths != 0)
    a.precision = precision_estimate({a.closed_form.area, t.crossings_exact, t.variance_visit1,
                                      t.variance_visit2, t.wall_encounters, a.length1 + a.length2});
  if (budgeted(m)) {
    if (m.rule == PrecisionRule::markers)
      a.stopped = t.reached_precision ? TrialStop::precision : TrialStop::budget;
    else
      a.stopped = t.reached_precision     ? TrialStop::precision
                  : t.first_visit_reached ? TrialStop::visit2_cap
                                          : TrialStop::visit1_cap;
  }
  if (m.precision_millionths != 0 && m.rule == PrecisionRule::online && t.self_crossings > 0) {
    constexpr double pi = 3.14159265358979323846;
    a.area_pilot = a.length1 * a.length1 / (pi * static_cast<double>(t.self_crossings));
  }
  a.run = std::move(t);
  return a;
}

} // namespace

AreaMeasurement measure_area(const World& world, const AreaMeasurementParams& m) {
  const TrialParams params = trial_params(m);
  const bool markers = m.precision_millionths != 0 && m.rule == PrecisionRule::markers;
  std::vector<TrialResult> results(m.trials);
  algorithms::for_each_unit(m.trials, m.threads, [&](std::uint64_t i, unsigned) {
    TrialParams p = params;
    p.keep_trails = i == 0 && m.keep_first_trails;
    results[i] = markers ? run_two_marker_trial(world, p, i) : run_trial(world, p, i);
  });

  AreaMeasurement out;
  out.trials.reserve(results.size());
  std::vector<double> nbcs, areas, lengths1, lengths2, totals, corrected;
  AreaSummary& s = out.summary;
  kernel::TraceHash all(m.seed);
  for (auto& t : results) {
    const AreaTrial& a = out.trials.emplace_back(reduce(std::move(t), m));
    nbcs.push_back(a.nbc);
    if (a.closed_form.area) areas.push_back(*a.closed_form.area);
    all.add_u64(a.run.hash);
    lengths2.push_back(a.length2);
    if (a.precision) {
      s.reached_precision += a.run.reached_precision ? 1 : 0;
      if (a.precision->area_corrected) corrected.push_back(*a.precision->area_corrected);
    }
    if (budgeted(m)) {
      if (!a.run.reached_precision) ++s.out_of_steps;
      totals.push_back(a.length1 + a.length2);
      lengths1.push_back(a.length1);
    }
    if (budgeted(m) && m.rule == PrecisionRule::online)
      s.first_visit_reached += a.run.first_visit_reached ? 1 : 0;
  }
  s.nbc_median = quantile(nbcs, 0.5);
  s.nbc_q1 = quantile(nbcs, 0.25);
  s.nbc_q3 = quantile(nbcs, 0.75);
  if (!areas.empty()) s.area_closed_form_median = quantile(areas, 0.5);
  if (m.precision_millionths != 0) {
    s.length2_median = quantile(lengths2, 0.5);
    if (!corrected.empty()) s.area_corrected_median = quantile(corrected, 0.5);
  }
  if (budgeted(m)) {
    s.length1_median = quantile(lengths1, 0.5);
    s.length_total_median = quantile(totals, 0.5);
  }
  s.hash = all.finish();
  return out;
}

} // namespace antkit::buffon
