// One command, one validated reply, with resends (link.hpp).
#include <antkit/devices/link.hpp>
#include <thread>

namespace antkit::devices {

namespace {
using Clock = std::chrono::steady_clock;

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
} // namespace

RobotLink::RobotLink(SerialPort port, RobotKind robot, LinkOptions options)
    : port_(std::move(port)), codec_(robot), options_(options), last_ok_(Clock::now()) {
  if (options_.tries == 0) options_.tries = 1;
}

std::string RobotLink::transact(const std::string& command, std::vector<Exchange>& io) {
  std::string why;
  for (std::uint32_t attempt = 0; attempt < options_.tries; ++attempt) {
    if (attempt > 0) {
      ++stats_.retries;
      std::this_thread::sleep_for(options_.backoff *
                                  (1u << std::min<std::uint32_t>(attempt - 1, 8)));
      port_.flush_input();
    }
    const auto silent =
        std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - last_ok_);
    if (silent > options_.watchdog)
      throw LinkError(LinkError::Kind::Timeout,
                      port_.name() + ": watchdog: no valid reply for " +
                          std::to_string(silent.count()) + " ms" +
                          (why.empty() ? std::string() : " (last: " + why + ")"));
    io.push_back({command, {}});
    ++stats_.exchanges;
    try {
      port_.write_all(command, options_.timeout);
      const ReadResult r = port_.read_line(options_.timeout, LineEnd::Lf);
      io.back().received = r.bytes;
      if (r.overflow) {
        ++stats_.overflows;
        why = "a reply line over " + std::to_string(r.bytes.size()) + " bytes";
        continue;
      }
      if (!r.complete) {
        ++stats_.timeouts;
        why = r.bytes.empty()
                  ? "no reply within " + std::to_string(options_.timeout.count()) + " ms"
                  : "a partial reply '" + printable(r.bytes) + "'";
        continue;
      }
      const auto decoded = codec_.decode_reply(command, r.bytes);
      if (!decoded) {
        ++stats_.bad_replies;
        why = "reply '" + printable(r.bytes) + "': column " + std::to_string(decoded.error.column) +
              ": " + decoded.error.message;
        continue;
      }
      last_ok_ = Clock::now();
      return r.bytes;
    } catch (const LinkError&) {
      throw; // the attempt is already in io (with what arrived before the failure, if anything)
    }
  }
  throw LinkError(LinkError::Kind::Timeout, port_.name() + ": no valid reply to '" +
                                                printable(command) + "' after " +
                                                std::to_string(options_.tries) + " tries: " + why);
}

std::string RobotLink::safe_stop(std::vector<Exchange>& io) noexcept {
  std::string failed;
  try {
    for (const auto& command : codec_.safe_stop()) {
      io.push_back({command, {}});
      try {
        port_.flush_input();
        port_.write_all(command, options_.timeout);
        // A reply to the command that was under way when the run stopped may still arrive: lines
        // that are not this command's acknowledgement are logged and skipped until the timeout.
        const auto deadline = Clock::now() + options_.timeout;
        bool acknowledged = false;
        while (!acknowledged) {
          const auto left =
              std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
          if (left.count() <= 0) break;
          const ReadResult r = port_.read_line(left, LineEnd::Lf);
          io.back().received += r.bytes;
          if (!r.complete) break;
          acknowledged = static_cast<bool>(codec_.decode_reply(command, r.bytes));
        }
        if (!acknowledged)
          failed += (failed.empty() ? "" : "; ") + printable(command) + " not acknowledged";
      } catch (const LinkError& e) {
        failed += (failed.empty() ? "" : "; ") + printable(command) + ": " +
                  std::string(link_error_name(e.kind()));
        if (e.kind() == LinkError::Kind::Disconnected) break;
      }
    }
  } catch (const std::exception& e) { // allocation failure: nothing more can be said safely
    failed += std::string("; ") + e.what();
  }
  return failed;
}

} // namespace antkit::devices
