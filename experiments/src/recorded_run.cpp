// A run on a robot, audited (recorded_run.hpp).
#include <antkit/devices/stc_floor/record.hpp>
#include <antkit/experiments/recorded_run.hpp>

namespace antkit::experiments {

RecordedRun record_run(const devices::RecordOptions& options,
                       const devices::RecordProgress& progress) {
  RecordedRun out;
  out.summary = devices::record(options, progress);
  const auto* floor_tour = devices::stc_floor::tour_of(out.summary);
  if (!floor_tour) return out;
  const auto& tour = *floor_tour;
  if (tour.map) {
    out.audit = testing::audit_stc_tour(tour.map->cells, tour.start, tour.path,
                                        testing::TourRule::ExactlyOnce);
    out.tour_ok = out.audit->ok();
    if (!out.tour_ok) out.tour_broken = out.audit->first.describe();
  } else {
    // Without the map nothing says how much floor there was: a tour that closed after one
    // sub-cell (a camera that misread every mark) looks like one that covered the floor. So the
    // run is not called a success; its summary still says what the tour did.
    out.tour_ok = false;
    if (!tour.returned_to_start)
      out.tour_broken = "the tour did not close next to the start";
    else if (tour.repeats != 0)
      out.tour_broken = std::to_string(tour.repeats) + " sub-cells entered more than once";
    else
      out.tour_broken = "without --map the tour cannot be checked against the floor (it closed "
                        "next to the start after " +
                        std::to_string(tour.covered) +
                        " sub-cells, none twice): give the map to check it";
  }
  return out;
}

} // namespace antkit::experiments
