#pragma once
// A robot on a serial link: one command, one validated reply, with the resynchronisation that
// drivers in the field do (PROTOCOLS.md, Common: on junk, a partial line or a timeout they flush
// the input, resend, and give up after a few tries; RoadNarrows' Hemisson driver: 3 sends).
//
// transact(command): write the command; read one line within the timeout; the codec validates it
// as the reply to that command (letter, CR LF, arity, ranges, no stray bytes). Anything else -- a
// timeout, a partial line, a line that does not parse, an over-long line -- is a fault: the input
// is flushed, the link waits a back-off (doubling from `backoff`) and resends, up to `tries` sends
// in all. Every send and what came back is appended to the caller's exchange list, faults included,
// so a log holds exactly what went over the wire. A disconnect (EOF or EIO on the tty) or a stop
// signal ends the exchange at once (LinkError Disconnected / Interrupted); so does the watchdog
// when no valid reply has arrived for `watchdog` (LinkError Timeout).
//
// safe_stop(): wheels to zero, then LEDs off (the codec's safe_stop() commands), each sent once
// with a short timeout; it never throws, and reports what it could not do.
#include <antkit/devices/log.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/serial.hpp>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace antkit::devices {

struct LinkOptions {
  std::chrono::milliseconds timeout{250}; // for one reply
  std::uint32_t tries = 3;                // sends of one command before giving up
  std::chrono::milliseconds backoff{10};  // before the first resend; doubled for each next one
  std::chrono::milliseconds watchdog{3000};
};

struct LinkStats {
  std::uint64_t exchanges = 0;   // commands sent, resends included
  std::uint64_t retries = 0;     // resends
  std::uint64_t timeouts = 0;    // no line within the timeout (nothing or part of a line came)
  std::uint64_t bad_replies = 0; // a complete line that is not the reply (junk, wrong letter...)
  std::uint64_t overflows = 0;   // a line longer than the port's bound
};

class RobotLink {
public:
  RobotLink(SerialPort port, RobotKind robot, LinkOptions options = {});

  [[nodiscard]] const Codec& codec() const noexcept { return codec_; }
  [[nodiscard]] const LinkOptions& options() const noexcept { return options_; }
  [[nodiscard]] const LinkStats& stats() const noexcept { return stats_; }
  [[nodiscard]] const SerialPort& port() const noexcept { return port_; }

  // Sends `command` (terminator included) and returns its validated reply line (with its CR LF).
  // Throws LinkError (Timeout after the last try, with what went wrong; Disconnected;
  // Interrupted). Every attempt is appended to `io`, also when it throws.
  std::string transact(const std::string& command, std::vector<Exchange>& io);

  // Best effort: every command of codec().safe_stop(), one try each. Returns "" when each was
  // acknowledged, else what failed (for the log's stop reason).
  std::string safe_stop(std::vector<Exchange>& io) noexcept;

private:
  SerialPort port_;
  Codec codec_;
  LinkOptions options_;
  LinkStats stats_;
  std::chrono::steady_clock::time_point last_ok_;
};

} // namespace antkit::devices
