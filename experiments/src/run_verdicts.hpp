#pragma once
// The verdicts that devices' reports of a run may ask for (DeviceReport::verdict(),
// recorded_run.hpp), by name, each audit in a file of its own. A device whose runs need a verdict
// adds its audit's file and one line in run_verdicts.cpp.
#include <antkit/devices/device_report.hpp>
#include <antkit/experiments/recorded_run.hpp>
#include <span>
#include <string_view>

namespace antkit::experiments::detail {

struct VerdictAudit {
  std::string_view verdict; // the name a report asks for
  RunVerdict (*audit)(const devices::DeviceReport& report);
};

// Every audit, once by name.
[[nodiscard]] std::span<const VerdictAudit> verdict_audits() noexcept;

// The marker-floor robot's tour, "stc-tour" (stc_tour_verdict.cpp).
[[nodiscard]] RunVerdict stc_tour_verdict(const devices::DeviceReport& report);

} // namespace antkit::experiments::detail
