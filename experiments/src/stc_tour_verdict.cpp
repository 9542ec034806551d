// The verdict "stc-tour" on the marker-floor robot's tour (run_verdicts.hpp): with the map, the
// believed tour held against it by the oracle of `antkit check stc` (testing/stc_audit.hpp), rule
// ExactlyOnce (every reachable sub-cell entered exactly once, back next to the start). Without
// one the tour cannot be checked (a tour that closed after one sub-cell looks like a whole one),
// so it never passes; the failure says what it did. Its fields in the "tour" block: tour_ok, and
// first_violation (null, or {"rule", "step" (null for a whole-tour rule), "subcell" [x, y],
// "detail"}: `antkit check stc`'s, commands/json.hpp).
#include "run_verdicts.hpp"

#include <antkit/devices/stc_floor/report.hpp>
#include <antkit/testing/stc_audit.hpp>

namespace antkit::experiments::detail {

RunVerdict stc_tour_verdict(const devices::DeviceReport& report) {
  RunVerdict out;
  const auto* floor_tour = dynamic_cast<const devices::stc_floor::Tour*>(&report);
  if (!floor_tour) {
    out.ok = false;
    out.failure = "the report asking for verdict stc-tour is not a marker-floor robot's tour";
    return out;
  }
  const auto& tour = *floor_tour;
  std::string broken;
  devices::ReportField::Value first_violation; // null
  if (tour.map) {
    const auto audit = testing::audit_stc_tour(tour.map->cells, tour.start, tour.path,
                                               testing::TourRule::ExactlyOnce);
    out.ok = audit.ok();
    if (!out.ok) {
      broken = audit.first.describe();
      const auto& f = audit.first;
      first_violation =
          devices::ReportFields{{"rule", f.rule},
                                {"step", f.step < 0 ? devices::ReportField::Value()
                                                    : devices::ReportField::Value(f.step)},
                                {"subcell", f.subcell},
                                {"detail", f.detail}};
    }
  } else {
    // Without the map nothing says how much floor there was: a tour that closed after one
    // sub-cell (a camera that misread every mark) looks like one that covered the floor. So the
    // run is not called a success; its summary still says what the tour did.
    out.ok = false;
    if (!tour.returned_to_start)
      broken = "the tour did not close next to the start";
    else if (tour.repeats != 0)
      broken = std::to_string(tour.repeats) + " sub-cells entered more than once";
    else
      broken = "without --map the tour cannot be checked against the floor (it closed next to "
               "the start after " +
               std::to_string(tour.covered) + " sub-cells, none twice): give the map to check it";
  }
  if (!out.ok) out.failure = "the tour is not a coverage tour: " + broken;
  out.fields = {{"tour_ok", out.ok}, {"first_violation", std::move(first_violation)}};
  return out;
}

} // namespace antkit::experiments::detail
