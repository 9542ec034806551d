// A run on a robot, audited (recorded_run.hpp).
#include <antkit/experiments/recorded_run.hpp>

namespace antkit::experiments {

RecordedRun record_run(const devices::RecordOptions& options,
                       const devices::RecordProgress& progress) {
  RecordedRun out;
  out.summary = devices::record(options, progress);
  if (!out.summary.tour) return out;
  const auto& tour = *out.summary.tour;
  if (tour.map) {
    out.audit = testing::audit_stc_tour(tour.map->cells, tour.start, tour.path,
                                        testing::TourRule::ExactlyOnce);
    out.tour_ok = out.audit->ok();
    if (!out.tour_ok) out.tour_broken = out.audit->first.describe();
  } else {
    out.tour_ok = tour.returned_to_start && tour.repeats == 0;
    if (!tour.returned_to_start)
      out.tour_broken = "the tour did not close next to the start";
    else if (tour.repeats != 0)
      out.tour_broken = std::to_string(tour.repeats) + " sub-cells entered more than once";
  }
  return out;
}

} // namespace antkit::experiments
