// A run on a robot, audited (recorded_run.hpp).
#include "run_verdicts.hpp"

#include <antkit/experiments/recorded_run.hpp>

namespace antkit::experiments {

RecordedRun record_run(const devices::RecordOptions& options,
                       const devices::RecordProgress& progress) {
  RecordedRun out;
  out.summary = devices::record(options, progress);
  const auto& report = out.summary.device_report;
  if (!report || report->verdict().empty()) return out;
  for (const auto& a : detail::verdict_audits())
    if (a.verdict == report->verdict()) {
      out.verdict = a.audit(*report);
      return out;
    }
  out.verdict.ok = false;
  out.verdict.failure = "no audit gives the verdict '" + std::string(report->verdict()) +
                        "' that the device's report asks for";
  return out;
}

} // namespace antkit::experiments
