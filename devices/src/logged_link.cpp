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

Attempt LoggedLink::read_attempt(const Exchange& e) const {
  Fields unused;
  return read_attempt(e, unused);
}

Attempt LoggedLink::read_attempt(const Exchange& e, Fields& fields) const {
  fields = {}; // the framing leaves values only for a reply
  const std::string& request = e.sent;
  const std::string_view bytes = e.received;
  if (framing_.reading_for(request) == Reading::Bytes) {
    // The reply's size exactly (fewer: the live link timed out; more: bytes after the reply).
    if (bytes.size() == framing_.reply_size(request) &&
        framing_.kind(request, bytes, fields) == ReplyKind::Reply) {
      return {Attempt::Kind::Reply, 0, bytes.size()};
    }
    return {};
  }
  // The attempt's bytes, line by line, as the live link read them.
  std::size_t from = 0;
  while (from < bytes.size()) {
    const auto nl = bytes.find('\n', from);
    if (nl == std::string_view::npos) break; // a partial line: the attempt timed out
    const std::string_view line = bytes.substr(from, nl + 1 - from);
    const std::size_t b = from;
    from = nl + 1;
    const ReplyKind kind = framing_.kind(request, line, fields);
    if (kind == ReplyKind::Stale) continue;
    if (from < bytes.size()) {
      fields = {}; // the line may have been a reply: what follows it makes this no reply
      return {Attempt::Kind::After, b, from};
    }
    if (kind == ReplyKind::Reply) return {Attempt::Kind::Reply, b, from};
    break; // a bad line: the live link resent
  }
  return {};
}

std::string_view LoggedLink::reply_of(const std::string& request) {
  fields_ = {};
  const bool resyncs = !resync_.empty();
  for (std::uint32_t attempt = 0;; ++attempt) {
    if (attempt > 0 && resyncs) (void)expect(resync_, false);
    // A resend follows its own failed attempt directly only where nothing resynchronises.
    const Exchange& e = expect(request, attempt > 0 && !resyncs);
    const std::size_t at = k_ - 1;
    ++sends_;
    last_send_ns_ = e.t_ns;
    // e.sent is `request` (expect): its reading, ahead or now.
    // Read here, the reply's values are kept for the body; read ahead, they stayed on the reading
    // thread (carrying them across costs the checking thread more than decoding them again).
    const Attempt a = at < attempts_.size() ? attempts_[at] : read_attempt(e, fields_);
    const std::string_view unit = std::string_view(e.received).substr(a.begin, a.end - a.begin);
    if (a.kind == Attempt::Kind::Reply) return unit;
    if (a.kind == Attempt::Kind::After)
      throw Diverged{{step_, field_ + "[" + std::to_string(at) + "].received",
                      "'" + printable(e.received) + "'",
                      "nothing read after the line '" + printable(unit) + "'"}};
  }
}

} // namespace antkit::devices::detail
