// The JSON of `antkit buffon` (json.hpp; the keys are documented at cli/buffon.cpp).
#include <antkit/commands/json.hpp>
#include <antkit/kernel/hash.hpp>
#include <string>

namespace antkit::commands {

namespace {

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json();
}

const char* stop_name(buffon::TrialStop stop) {
  switch (stop) {
  case buffon::TrialStop::precision:
    return "precision";
  case buffon::TrialStop::visit1_cap:
    return "visit 1 cap";
  case buffon::TrialStop::visit2_cap:
    return "visit 2 cap";
  case buffon::TrialStop::budget:
    return "budget";
  }
  return "";
}

// One trial's JSON.
nlohmann::json trial_json(const buffon::AreaTrial& a, bool budgeted, bool online1) {
  const buffon::TrialResult& t = a.run;
  const auto& cf = a.closed_form;
  nlohmann::json j = {
      {"trial", t.trial},
      {"bc", t.bc},
      {"nbc", a.nbc},
      {"length1", a.length1},
      {"length2", a.length2},
      {"crossings_exact", t.crossings_exact},
      {"area_closed_form", cf.area ? nlohmann::json(*cf.area) : nlohmann::json()},
      {"area_closed_form_ci", {cf.lower, cf.upper ? nlohmann::json(*cf.upper) : nlohmann::json()}},
      {"blocked", t.blocked},
      {"hash", kernel::hash_hex(t.hash)}};
  if (a.precision) {
    const buffon::PrecisionEstimate& estimate = *a.precision;
    j["reached_precision"] = t.reached_precision;
    j["precision_ci"] = {optional_json(estimate.ci.lower), optional_json(estimate.ci.upper)};
    j["variance_visit1"] = t.variance_visit1;
    j["variance_visit2"] = t.variance_visit2;
    j["wall_encounters"] = t.wall_encounters;
    j["area_corrected"] = optional_json(estimate.area_corrected);
    j["area_corrected_ci"] = {optional_json(estimate.corrected_ci.lower),
                              optional_json(estimate.corrected_ci.upper)};
    if (budgeted) j["precision_reached"] = optional_json(estimate.precision_reached);
  }
  if (budgeted) {
    j["steps1"] = t.steps1;
    j["steps2"] = t.steps2;
    j["length_total"] = a.length1 + a.length2;
    if (a.stopped) j["stopped"] = stop_name(*a.stopped);
  }
  if (online1) {
    j["first_visit_reached"] = t.first_visit_reached;
    j["self_crossings"] = t.self_crossings;
    j["area_pilot"] = optional_json(a.area_pilot);
  }
  return j;
}

} // namespace

nlohmann::json buffon_json(const buffon::AreaMeasurement& m,
                           const buffon::AreaMeasurementParams& params, const std::string& spec,
                           double area) {
  const bool precision = params.precision_millionths != 0;
  const bool online1 = precision && params.rule == buffon::PrecisionRule::online;
  const bool budgeted = buffon::budgeted(params);
  nlohmann::json trials = nlohmann::json::array();
  for (const auto& a : m.trials) trials.push_back(trial_json(a, budgeted, online1));
  const buffon::AreaSummary& s = m.summary;
  nlohmann::json result;
  result["arena"] = {{"spec", spec}, {"area", area}};
  result["trials"] = trials;
  result["summary"] = {{"nbc_median", s.nbc_median},
                       {"nbc_q1", s.nbc_q1},
                       {"nbc_q3", s.nbc_q3},
                       {"area_closed_form_median", optional_json(s.area_closed_form_median)}};
  if (precision) {
    result["summary"]["precision"] =
        static_cast<double>(params.precision_millionths) / buffon::kPrecisionDenominator;
    result["summary"]["reached_precision"] = s.reached_precision;
    result["summary"]["length2_median"] = s.length2_median;
    result["summary"]["area_corrected_median"] = optional_json(s.area_corrected_median);
  }
  if (budgeted) {
    result["summary"]["rule"] = std::string(buffon::rule_name(params.rule));
    result["summary"]["length1_median"] = s.length1_median;
    result["summary"]["length_total_median"] = s.length_total_median;
  }
  if (online1) result["summary"]["first_visit_reached"] = s.first_visit_reached;
  result["hash"] = kernel::hash_hex(s.hash);
  return result;
}

} // namespace antkit::commands
