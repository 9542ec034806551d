// One command, one validated reply, with resends; the confirmed safe stop (link.hpp).
#include <antkit/devices/link.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <functional>
#include <thread>

namespace antkit::devices {

namespace {
using Clock = std::chrono::steady_clock;

char lower(char c) noexcept {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

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

ReplyKind classify_reply(const Codec& codec, std::string_view command, std::string_view line) {
  if (command.empty()) return ReplyKind::Bad;
  if (!line.empty() && line[0] == lower(command[0]))
    return codec.decode_reply(command, line) ? ReplyKind::Reply : ReplyKind::Bad;
  return reply_shaped(line) ? ReplyKind::Stale : ReplyKind::Bad;
}

RobotLink::RobotLink(SerialPort port, RobotKind robot, LinkOptions options)
    : port_(std::move(port)), codec_(robot), options_(options), last_ok_(Clock::now()) {
  if (options_.tries == 0) options_.tries = 1;
}

void RobotLink::pause(std::chrono::milliseconds d) {
  std::this_thread::sleep_for(d);
}

void RobotLink::drain(std::vector<Exchange>& io) {
  // Whatever waits now arrived before this send: it cannot be its reply. Read without waiting.
  std::string bytes;
  for (;;) {
    const ReadResult r = port_.read_line(std::chrono::milliseconds(0), LineEnd::Lf);
    if (r.bytes.empty()) break;
    bytes += r.bytes;
    if (!r.complete && !r.overflow) break; // a partial line: all there was
  }
  if (bytes.empty()) return;
  ++stats_.stale;
  io.push_back({{}, std::move(bytes), now_ns()});
}

std::int64_t RobotLink::now_ns() const noexcept {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - options_.origin)
      .count();
}

std::string RobotLink::transact(const std::string& command, std::vector<Exchange>& io) {
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
      drain(io);
    } catch (const LinkError&) {
      // A line already gone: the attempt is still logged, so that a log shows every command tried
      // (replay finds the safe stop by its first command even when nothing could be sent).
      io.push_back({command, {}, now_ns()});
      ++stats_.exchanges;
      throw;
    }
    last_send_ns_ = now_ns();
    io.push_back({command, {}, last_send_ns_});
    const std::size_t at = io.size() - 1;
    ++stats_.exchanges;
    port_.write_all(command, options_.timeout);
    const auto deadline = Clock::now() + options_.timeout;
    for (;;) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      const ReadResult r =
          port_.read_line(std::max(left, std::chrono::milliseconds(0)), LineEnd::Lf);
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
                  : "a partial reply '" + printable(r.bytes) + "'";
        break;
      }
      const ReplyKind kind = classify_reply(codec_, command, r.bytes);
      if (kind == ReplyKind::Stale) {
        ++stats_.stale;
        continue;
      }
      if (kind == ReplyKind::Bad) {
        ++stats_.bad_replies;
        const auto decoded = codec_.decode_reply(command, r.bytes);
        why = "reply '" + printable(r.bytes) + "'" +
              (decoded ? std::string()
                       : ": column " + std::to_string(decoded.error.column) + ": " +
                             decoded.error.message);
        break;
      }
      last_ok_ = Clock::now();
      return r.bytes;
    }
  }
  throw LinkError(LinkError::Kind::Timeout, port_.name() + ": no valid reply to '" +
                                                printable(command) + "' after " +
                                                std::to_string(options_.tries) + " tries: " + why);
}

namespace detail {

SafeStopResult safe_stop_steps(CommandLink& link, std::vector<Exchange>& io) {
  SafeStopResult out;
  const Codec& codec = link.codec();
  const auto& o = link.options();
  const auto rounds = std::max<std::uint32_t>(1, o.stop_rounds);
  const auto commands = codec.safe_stop();
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
  // One command until acknowledged: its rounds of tries, with a word between rounds when the
  // robot has not answered.
  const auto until_acknowledged = [&](const std::string& command, const std::string& name,
                                      const std::function<bool(const std::string&)>& accept,
                                      std::string& why) {
    for (std::uint32_t round = 0; round < rounds; ++round) {
      if (round > 0) {
        if (time_up()) {
          late = true;
          return false;
        }
        notice("no acknowledgement of " + name + " yet (" + why + "); round " +
               std::to_string(round + 1) + " of " + std::to_string(rounds) +
               " (Ctrl-C again to give up)");
        link.pause(o.backoff_max);
      }
      link.rearm();
      try {
        if (accept(link.transact(command, io))) return true;
      } catch (const LinkError& e) {
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
      }
    }
    return false;
  };

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
    const bool acknowledged = until_acknowledged(
        commands[i], "'" + printable(commands[i]) + "'", [](const std::string&) { return true; },
        why);
    if (i == 0) wheels_acknowledged = acknowledged;
    if (!acknowledged) add(printable(commands[i]) + " not acknowledged (" + why + ")");
  }
  out.acknowledged = out.stopped = wheels_acknowledged;
  // Confirmed by the robot's own state: the speeds read back as zero.
  if (wheels_acknowledged && codec.robot().reads_speed) {
    out.stopped = false;
    if (cut || gone || late) {
      add("wheels not confirmed at 0 (not read back)");
    } else {
      std::string why = "no reading";
      out.stopped = until_acknowledged(
          codec.read_speed(), "the wheels at 0, 0",
          [&](const std::string& reply) {
            const auto speeds = codec.decode_speed(reply);
            if (speeds && speeds.value->left == 0 && speeds.value->right == 0) return true;
            why = speeds ? "the robot reads back speeds " + std::to_string(speeds.value->left) +
                               ", " + std::to_string(speeds.value->right)
                         : "a bad speed reply";
            // Not at zero: the wheels command again before the next reading.
            link.transact(commands[0], io);
            return false;
          },
          why);
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
