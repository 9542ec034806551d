#pragma once
// An STC tour's first broken rule as the commands print it (`check stc`, `record --device
// stc-floor`): null when the tour passes, else {"rule", "step" (null for a whole-tour rule),
// "subcell" [x, y], "detail"}.
#include <antkit/testing/stc_audit.hpp>
#include <nlohmann/json.hpp>

namespace antkit::cli {

inline nlohmann::json first_violation_json(const antkit::testing::StcAudit& a) {
  if (a.ok()) return nullptr;
  return {{"rule", a.first.rule},
          {"step", a.first.step < 0 ? nlohmann::json(nullptr) : nlohmann::json(a.first.step)},
          {"subcell", {a.first.subcell.x, a.first.subcell.y}},
          {"detail", a.first.detail}};
}

} // namespace antkit::cli
