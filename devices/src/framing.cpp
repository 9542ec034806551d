// The text robots' framing, and what every framing shares (framing.hpp).
#include <antkit/devices/framing.hpp>

namespace antkit::devices {

std::string Framing::describe(std::string_view request) const {
  return "'" + printable(request) + "'";
}

Verdict LineFraming::classify(std::string_view request, std::string_view unit) const {
  Verdict v;
  v.kind = classify_reply(codec_, request, unit);
  if (v.kind == ReplyKind::Bad) {
    const auto decoded = codec_.decode_reply(request, unit);
    if (!decoded)
      v.why = "column " + std::to_string(decoded.error.column) + ": " + decoded.error.message;
  }
  return v;
}

StopPlan LineFraming::stop_plan() const {
  StopPlan plan;
  plan.commands = codec_.safe_stop();
  if (codec_.robot().reads_speed) plan.read_back = codec_.read_speed();
  return plan;
}

} // namespace antkit::devices
