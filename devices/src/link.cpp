// One command, one validated reply, with resends; the confirmed safe stop (link.hpp).
#include <antkit/devices/link.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <functional>
#include <thread>

namespace antkit::devices {

namespace {
using Clock = std::chrono::steady_clock;

// The quiet that ends a resynchronisation's read, at least (a choice: a robot answers within a few
// milliseconds; a host under load, or an emulator between two polls, a little later).
constexpr std::chrono::milliseconds kSettleMin{20};

std::chrono::milliseconds backoff_for(const LinkOptions& o, std::uint32_t attempt) noexcept {
  // attempt >= 1: backoff x 2^(attempt - 1), at most backoff_max.
  auto d = o.backoff;
  for (std::uint32_t k = 1; k < attempt && d < o.backoff_max; ++k) d *= 2;
  return std::min(d, std::max(o.backoff, o.backoff_max));
}

// A line shaped as some reply: a lower-case letter, then nothing or ',' and printable text, then
// CR LF. Only such lines can be late answers; junk cannot pass for one.
bool reply_shaped(std::string_view line) noexcept {
  if (line.size() < 3 || line[0] < 'a' || line[0] > 'z') return false;
  if (line.substr(line.size() - 2) != "\r\n") return false;
  const auto body = line.substr(1, line.size() - 3);
  if (!body.empty() && body[0] != ',') return false;
  for (const char c : body)
    if (c < 0x20 || c > 0x7E) return false;
  return true;
}

} // namespace

std::string printable(std::string_view bytes) {
  std::string out;
  for (const char ch : bytes) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\r')
      out += "\\r";
    else if (c == '\n')
      out += "\\n";
    else if (c < 0x20 || c >= 0x7F) {
      constexpr char hex[] = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else
      out += ch;
  }
  return out;
}

ReplyKind classify_reply(const Codec& codec, std::string_view command, std::string_view line,
                         Fields* fields) {
  if (fields != nullptr) *fields = {};
  if (command.empty()) return ReplyKind::Bad;
  if (!line.empty() && line[0] == reply_letter(command[0])) {
    const auto decoded = codec.decode_reply(command, line);
    if (!decoded) return ReplyKind::Bad;
    if (fields != nullptr) *fields = *decoded.value;
    return ReplyKind::Reply;
  }
  return reply_shaped(line) ? ReplyKind::Stale : ReplyKind::Bad;
}

RobotLink::RobotLink(SerialPort port, RobotKind robot, LinkOptions options)
    : RobotLink(std::move(port), std::make_shared<const LineFraming>(robot), std::move(options)) {}

RobotLink::RobotLink(SerialPort port, std::shared_ptr<const Framing> framing, LinkOptions options)
    : port_(std::move(port)), framing_(std::move(framing)), options_(std::move(options)),
      last_ok_(Clock::now()) {
  if (options_.tries == 0) options_.tries = 1;
}

void RobotLink::pause(std::chrono::milliseconds d) {
  std::this_thread::sleep_for(d);
}

void RobotLink::drain(std::vector<Exchange>& io) {
  // Whatever waits now arrived before this send: it cannot be its reply. Read without waiting,
  // as the framing reads (whole lines; or every byte there is).
  std::string bytes;
  if (framing_->reading() == Reading::Lines) {
    for (;;) {
      const ReadResult r = port_.read_line(std::chrono::milliseconds(0), LineEnd::Lf);
      if (r.bytes.empty()) break;
      bytes += r.bytes;
      if (!r.complete && !r.overflow) break; // a partial line: all there was
    }
  } else {
    for (std::string b; !(b = port_.read_bytes(65536, std::chrono::milliseconds(0))).empty();)
      bytes += b;
  }
  if (bytes.empty()) return;
  ++stats_.stale;
  io.push_back({{}, std::move(bytes), now_ns()});
}

void RobotLink::resync(std::vector<Exchange>& io) {
  std::string bytes = framing_->resync();
  if (bytes.empty()) return;
  io.push_back({std::move(bytes), {}, now_ns()});
  const std::size_t at = io.size() - 1;
  ++stats_.exchanges;
  port_.write_all(io[at].sent, options_.timeout);
  const auto settle = std::min(std::max(options_.backoff_max, kSettleMin), options_.timeout);
  const auto end = Clock::now() + options_.timeout;
  while (Clock::now() < end) {
    std::string b = port_.read_bytes(1, settle);
    if (b.empty()) break;
    io[at].received += b;
    io[at].received += port_.read_bytes(65536, std::chrono::milliseconds(0));
  }
  if (!io[at].received.empty()) ++stats_.stale;
}

std::int64_t RobotLink::now_ns() const noexcept {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - options_.origin)
      .count();
}

std::string RobotLink::transact(const std::string& request, std::vector<Exchange>& io) {
  const Framing& framing = *framing_;
  const bool lines = framing.reading_for(request) == Reading::Lines;
  const bool resyncs = !framing.resync().empty();
  std::string why;
  for (std::uint32_t attempt = 0; attempt < options_.tries; ++attempt) {
    if (attempt > 0) {
      ++stats_.retries;
      std::this_thread::sleep_for(backoff_for(options_, attempt));
    }
    // A stop signal that came between two waits (a blocked wait returns EINTR at once): no new
    // send after it.
    if (StopSignals::requested())
      throw LinkError(LinkError::Kind::Interrupted,
                      port_.name() + ": interrupted by a stop signal");
    if (deadline_ && Clock::now() >= *deadline_)
      throw LinkError(LinkError::Kind::Timeout,
                      port_.name() + ": the safe stop's time is up" +
                          (why.empty() ? std::string() : " (last: " + why + ")"));
    const auto silent =
        std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - last_ok_);
    if (options_.watchdog.count() > 0 && silent > options_.watchdog)
      throw LinkError(LinkError::Kind::Timeout,
                      port_.name() + ": watchdog: no valid reply for " +
                          std::to_string(silent.count()) + " ms" +
                          (why.empty() ? std::string() : " (last: " + why + ")"));
    try {
      if (attempt > 0 && resyncs) resync(io);
      drain(io);
    } catch (const LinkError&) {
      // A line already gone: the attempt is still logged, so that a log shows every request tried
      // (replay finds the safe stop by its first request even when nothing could be sent).
      io.push_back({request, {}, now_ns()});
      ++stats_.exchanges;
      throw;
    }
    last_send_ns_ = now_ns();
    io.push_back({request, {}, last_send_ns_});
    const std::size_t at = io.size() - 1;
    ++stats_.exchanges;
    port_.write_all(request, options_.timeout);
    const std::size_t n = lines ? 0 : framing.reply_size(request);
    const auto deadline = Clock::now() + options_.timeout;
    for (;;) {
      const auto left =
          std::max(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()),
                   std::chrono::milliseconds(0));
      ReadResult r;
      if (lines) {
        r = port_.read_line(left, LineEnd::Lf);
      } else {
        r.bytes = port_.read_bytes(n, left);
        r.complete = r.bytes.size() == n;
      }
      io[at].received += r.bytes;
      if (r.overflow) {
        ++stats_.overflows;
        why = "a reply line over " + std::to_string(r.bytes.size()) + " bytes";
        break;
      }
      if (!r.complete) {
        ++stats_.timeouts;
        why = r.bytes.empty()
                  ? "no reply within " + std::to_string(options_.timeout.count()) + " ms"
              : lines ? "a partial reply '" + printable(r.bytes) + "'"
                      : "a short reply of " + std::to_string(r.bytes.size()) + " of " +
                            std::to_string(n) + " bytes";
        break;
      }
      if (!lines) {
        // A reply without a terminator: bytes already waiting after it mean it was not the reply
        // alone (a banner or text in front of it, a late reply).
        const std::string extra = port_.read_bytes(65536, std::chrono::milliseconds(0));
        io[at].received += extra;
        if (!extra.empty()) {
          ++stats_.bad_replies;
          why = std::to_string(extra.size()) + " bytes after the " + std::to_string(n) +
                "-byte reply '" + printable(io[at].received) + "'";
          break;
        }
      }
      const Verdict v = framing.classify(request, r.bytes);
      if (v.kind == ReplyKind::Stale) {
        ++stats_.stale;
        continue;
      }
      if (v.kind == ReplyKind::Bad) {
        ++stats_.bad_replies;
        why = "reply '" + printable(r.bytes) + "'" + (v.why.empty() ? std::string() : ": " + v.why);
        break;
      }
      last_ok_ = Clock::now();
      return r.bytes;
    }
  }
  throw LinkError(LinkError::Kind::Timeout, port_.name() + ": no valid reply to " +
                                                framing.describe(request) + " after " +
                                                std::to_string(options_.tries) + " tries: " + why);
}

namespace detail {

SafeStopResult safe_stop_steps(CommandLink& link, std::vector<Exchange>& io) {
  SafeStopResult out;
  const Framing& framing = link.framing();
  const auto& o = link.options();
  const auto rounds = std::max<std::uint32_t>(1, o.stop_rounds);
  const StopPlan plan = framing.stop_plan();
  const auto& commands = plan.commands;
  const auto began = Clock::now();
  const auto deadline = began + o.stop_within;
  link.set_deadline(deadline);
  const auto notice = [&](const std::string& what) {
    if (o.on_stop_notice) o.on_stop_notice(what);
  };
  const auto time_up = [&] { return Clock::now() >= deadline; };
  const auto add = [&](const std::string& what) {
    out.failure += (out.failure.empty() ? "" : "; ") + what;
  };
  const auto gave_up = [&] {
    return "gave up after " + std::to_string(o.stop_within.count()) + " ms (--stop-within)";
  };
  // A stop signal during the stop (a second Ctrl-C; the record loop took the first) ends it here.
  bool cut = false, gone = false, late = false;
  // A link failure: whether the stop can go on (a timeout while time is left).
  const auto goes_on = [&](const LinkError& e, std::string& why) {
    why = e.what();
    if (e.kind() == LinkError::Kind::Interrupted) {
      cut = true;
      return false;
    }
    if (e.kind() == LinkError::Kind::Disconnected) {
      gone = true;
      return false;
    }
    if (time_up()) {
      late = true;
      return false;
    }
    return true;
  };
  // One request until accepted: its rounds of tries, with a word between rounds when the robot
  // has not answered (`waiting`: "no acknowledgement of 'D,0,0\r'", what has not come yet).
  const auto until_accepted = [&](const std::string& request, const std::string& waiting,
                                  const std::function<bool(const std::string&)>& accept,
                                  std::string& why) {
    for (std::uint32_t round = 0; round < rounds; ++round) {
      if (round > 0) {
        if (time_up()) {
          late = true;
          return false;
        }
        notice(waiting + " yet (" + why + "); round " + std::to_string(round + 1) + " of " +
               std::to_string(rounds) + " (Ctrl-C again to give up)");
        link.pause(o.backoff_max);
      }
      link.rearm();
      try {
        if (accept(link.transact(request, io))) return true;
      } catch (const LinkError& e) {
        if (!goes_on(e, why)) return false;
      }
    }
    return false;
  };
  // The speeds read back: 0, 0 accepts; otherwise `why` says what was read, and where the
  // read-back does not stop the wheels itself, the wheels' command goes again before the next.
  const auto at_zero = [&](const std::string& reply, std::string& why) {
    const auto speeds = framing.decode_speeds(reply);
    if (speeds && speeds.value->left == 0 && speeds.value->right == 0) return true;
    why = speeds ? "the robot reads back speeds " + std::to_string(speeds.value->left) + ", " +
                       std::to_string(speeds.value->right)
                 : "a bad speed reply";
    if (!plan.read_back_stops) link.transact(commands.at(0), io);
    return false;
  };

  std::string resync_why;
  if (plan.resync_first) {
    // The robot's state is unknown (a sequence may be open): back to a known one first.
    try {
      link.resync(io);
    } catch (const LinkError& e) {
      (void)goes_on(e, resync_why);
    }
  }
  bool wheels_acknowledged = false;
  for (std::size_t i = 0; i < commands.size(); ++i) {
    if (i > 0 && (!wheels_acknowledged || cut || gone || late)) {
      // The wheels' stop was not acknowledged (the rest, LEDs off, would only cost more time), or
      // the stop ended.
      std::string rest;
      for (std::size_t k = i; k < commands.size(); ++k)
        rest += (rest.empty() ? "" : ", ") + printable(commands[k]);
      add(rest + " not sent" +
          (wheels_acknowledged ? "" : " (the wheels' stop was not acknowledged)"));
      break;
    }
    std::string why;
    const bool acknowledged = until_accepted(
        commands[i], "no acknowledgement of " + framing.describe(commands[i]),
        [](const std::string&) { return true; }, why);
    if (i == 0) wheels_acknowledged = acknowledged;
    if (!acknowledged) add(printable(commands[i]) + " not acknowledged (" + why + ")");
  }
  out.acknowledged = out.stopped = wheels_acknowledged;
  if (plan.read_back_stops) {
    // No acknowledgement exists: the wheels are stopped when, and only when, they read back at
    // 0, 0.
    std::string why = resync_why.empty() ? "no reply" : resync_why;
    if (!cut && !gone && !late)
      out.stopped = until_accepted(
          plan.read_back, "the wheels not read back at 0, 0",
          [&](const std::string& reply) { return at_zero(reply, why); }, why);
    out.acknowledged = out.stopped;
    if (!out.stopped) add("wheels not read back at 0, 0 (" + why + ")");
  } else if (wheels_acknowledged && !plan.read_back.empty()) {
    // Confirmed by the robot's own state: the speeds read back as zero.
    out.stopped = false;
    if (cut || gone || late) {
      add("wheels not confirmed at 0 (not read back)");
    } else {
      std::string why = "no reading";
      out.stopped = until_accepted(
          plan.read_back, "no acknowledgement of the wheels at 0, 0",
          [&](const std::string& reply) { return at_zero(reply, why); }, why);
      if (!out.stopped) add("wheels not confirmed at 0 (" + why + ")");
    }
  }
  if (cut) add("cut short by a stop signal");
  if (late) {
    add(gave_up());
    notice("the safe stop " + gave_up());
  }
  link.set_deadline(std::nullopt);
  out.complete = out.failure.empty();
  return out;
}

} // namespace detail

SafeStopResult safe_stop(CommandLink& link, std::vector<Exchange>& io) noexcept {
  try {
    return detail::safe_stop_steps(link, io);
  } catch (const std::exception& e) { // allocation failure: nothing more can be said safely
    SafeStopResult out;
    out.failure = std::string("the safe stop failed: ") + e.what();
    return out;
  } catch (...) {
    SafeStopResult out;
    out.failure = "the safe stop failed";
    return out;
  }
}

} // namespace antkit::devices
