#pragma once
// A run on a robot, audited (`antkit record`): devices::record() (the one record loop, every
// device), then the verdict the device's report asks for (DeviceReport::verdict(),
// devices/device_report.hpp) by the audit of that name (src/run_verdicts.hpp lists them, one file
// each: the marker-floor robot's "stc-tour", the oracle of `antkit check stc`,
// testing/stc_audit.hpp, in stc_tour_verdict.cpp). It sits here, above the devices and the
// checkers, because it needs both (DESIGN.md, the layers): a device names the verdict it needs,
// and does not include the checkers.
#include <antkit/devices/device_report.hpp>
#include <antkit/devices/record_loop.hpp>
#include <string>

namespace antkit::experiments {

// The verdict on a device's report of a run.
struct RunVerdict {
  bool ok = true;
  std::string failure; // why not, in words (the exit message; "" when ok)
  // What the verdict adds to the report's block (the tour's tour_ok and first_violation).
  devices::ReportFields fields;
};

struct RecordedRun {
  devices::RecordSummary summary;
  // The verdict the device's report asks for: ok, with no fields, when there is no report or it
  // asks for none. A report asking for a verdict no audit gives is not ok (failure says so).
  RunVerdict verdict;

  // What exit status 0 follows: the robot is known to be stopped, and the run did what it set out
  // to do (every step; its report passed its verdict). A run stopped by a signal did not
  // (record_loop.hpp, RecordSummary::succeeded()).
  [[nodiscard]] bool succeeded() const noexcept { return summary.succeeded() && verdict.ok; }
};

// Throws kernel::InputError for bad options (devices::record()).
RecordedRun record_run(const devices::RecordOptions& options,
                       const devices::RecordProgress& progress = {});

} // namespace antkit::experiments
