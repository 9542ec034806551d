#pragma once
// A run on a robot, audited (`antkit record`): devices::record() (the one record loop, every
// device) and, when the run is a tour (the marker-floor robot), its verdict by the oracle of
// `antkit check stc` (testing/stc_audit.hpp). It sits here, above the devices and the checkers,
// because it needs both (DESIGN.md, the layers).
#include <antkit/devices/record_loop.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <optional>
#include <string>

namespace antkit::experiments {

struct RecordedRun {
  devices::RecordSummary summary;
  // A tour's verdict. With a map: the believed tour held against it by the oracle, rule
  // ExactlyOnce (every reachable sub-cell entered exactly once, back next to the start). Without
  // one the tour cannot be checked (a tour that closed after one sub-cell looks like a whole one),
  // so it never passes; tour_broken says what it did.
  std::optional<testing::StcAudit> audit; // with a map
  bool tour_ok = true;
  std::string tour_broken; // the broken rule in words ("" when the tour passes or there is none)

  // What exit status 0 follows: the robot is known to be stopped, and the run did what it set out
  // to do (every step; a tour closed and passed its verdict). A run stopped by a signal did not
  // (record_loop.hpp, RecordSummary::succeeded()).
  [[nodiscard]] bool succeeded() const noexcept { return summary.succeeded() && tour_ok; }
};

// Throws kernel::InputError for bad options (devices::record()).
RecordedRun record_run(const devices::RecordOptions& options,
                       const devices::RecordProgress& progress = {});

} // namespace antkit::experiments
