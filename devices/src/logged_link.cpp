// The replay's link (logged_link.hpp).
#include "logged_link.hpp"

namespace antkit::devices::detail {

const Exchange& LoggedLink::expect(const std::string& sent, bool resend) {
  while (k_ < io_->size() && (*io_)[k_].sent.empty()) ++k_; // drained bytes
  if (k_ >= io_->size()) {
    if (end_is_failure_)
      throw LinkError(LinkError::Kind::Timeout, "the log ends before a valid reply");
    throw Diverged{{step_, field_ + "[" + std::to_string(k_) + "]", "(no exchange)",
                    std::string(resend ? "a resend" : "a send") + " of '" + printable(sent) + "'"}};
  }
  const Exchange& e = (*io_)[k_];
  if (e.sent != sent) {
    // In the stop record a request may end unanswered, or not be sent at all (the watchdog fires
    // before a send): the safe stop's verdict, checked against the reason, says which.
    if (end_is_failure_)
      throw LinkError(LinkError::Kind::Timeout, "no valid reply (the log goes on)");
    throw Diverged{{step_, field_ + "[" + std::to_string(k_) + "].sent",
                    "'" + printable(e.sent) + "'", "'" + printable(sent) + "'"}};
  }
  ++k_;
  return e;
}

void LoggedLink::resync(std::vector<Exchange>&) {
  if (!resync_.empty()) (void)expect(resync_, false);
}

std::string LoggedLink::transact(const std::string& request, std::vector<Exchange>&) {
  return std::string(reply_of(request));
}

std::string_view LoggedLink::transact_view(const std::string& request, std::vector<Exchange>&,
                                           std::string&) {
  return reply_of(request);
}

std::string_view LoggedLink::reply_of(const std::string& request) {
  const bool resyncs = !resync_.empty();
  for (std::uint32_t attempt = 0;; ++attempt) {
    if (attempt > 0 && resyncs) (void)expect(resync_, false);
    // A resend follows its own failed attempt directly only where nothing resynchronises.
    const Exchange& e = expect(request, attempt > 0 && !resyncs);
    const std::size_t at = k_ - 1;
    ++sends_;
    last_send_ns_ = e.t_ns;
    if (framing_.reading_for(request) == Reading::Bytes) {
      // The reply's size exactly (fewer: the live link timed out; more: bytes after the reply).
      if (e.received.size() == framing_.reply_size(request) &&
          kind_of(request, e.received) == ReplyKind::Reply)
        return e.received;
      continue;
    }
    // The attempt's bytes, line by line, as the live link read them.
    std::string_view rest = e.received;
    while (!rest.empty()) {
      const auto nl = rest.find('\n');
      if (nl == std::string_view::npos) break; // a partial line: the attempt timed out
      const std::string_view line = rest.substr(0, nl + 1);
      rest.remove_prefix(nl + 1);
      const ReplyKind kind = kind_of(request, line);
      if (kind == ReplyKind::Stale) continue;
      if (!rest.empty())
        throw Diverged{{step_, field_ + "[" + std::to_string(at) + "].received",
                        "'" + printable(e.received) + "'",
                        "nothing read after the line '" + printable(line) + "'"}};
      if (kind == ReplyKind::Reply) return line;
      break; // a bad line: the live link resent
    }
  }
}

} // namespace antkit::devices::detail
