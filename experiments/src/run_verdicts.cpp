// The verdicts devices' reports may ask for (run_verdicts.hpp).
#include "run_verdicts.hpp"

#include <antkit/devices/stc_floor/report.hpp>

namespace antkit::experiments::detail {

std::span<const VerdictAudit> verdict_audits() noexcept {
  static constexpr VerdictAudit kAudits[] = {
      {devices::stc_floor::Tour::kVerdict, &stc_tour_verdict},
  };
  return kAudits;
}

} // namespace antkit::experiments::detail
