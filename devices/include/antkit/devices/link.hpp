#pragma once
// A robot on a serial link: one request, one validated reply, with the resynchronisation that
// drivers in the field do (PROTOCOLS.md, Common: on junk, a partial line or a timeout they flush
// the input, resend, and give up after a few tries). The link drives any robot's wire format
// through its Framing (framing.hpp) and does not know which one it is: text lines (LineFraming,
// the text robots) or the e-puck2's binary sequences (epuck2::SequenceFraming).
//
// transact(request), one attempt after another, up to `tries` sends:
//   0. after a failed attempt: the back-off (`backoff`, doubling, at most `backoff_max`), then,
//      when the framing has one, a resynchronisation (resync() below);
//   1. drain: whatever is waiting on the line now cannot be this send's reply (a late reply to an
//      earlier send, the tail of junk); it is logged as an exchange with nothing sent, and dropped;
//   2. send the request (the attempt is appended to the caller's exchange list);
//   3. read until the timeout, unit by unit as the framing reads (Reading::Lines: a line;
//      Reading::Bytes: the reply's size, then whatever already waits after it, which is a fault).
//      A unit is the reply when the framing's classify() says so (text robots, classify_reply():
//      its letter is the command's, in lower case, and the codec validates it completely). A unit
//      the framing calls Stale (a complete, well-formed reply line of ANOTHER letter: a late
//      answer to an earlier command, PROTOCOLS.md: "a reply whose first letter is not the
//      expected one ... is not a reply to this command") is kept in the exchange's bytes,
//      counted, and skipped, and the wait goes on within the same timeout. Anything else -- a
//      timeout, a partial line or a short reply, junk, an over-long line, bytes after a binary
//      reply, a reply that does not validate -- is a fault: the next attempt.
// An exchange's `received` is every byte read between its send and the next send: its reply, when
// it has one, is its last unit, and any lines before it are stale. So a log holds exactly what
// went over the wire, in order, and replay (replay.hpp) re-runs this very classification on it.
//
// resync(): the framing's resync bytes sent (the e-puck2: 36 zeros, which end any sequence its
// firmware may still be reading) as an exchange of its own, and whatever comes back read until the
// line stays quiet for `backoff_max` (at least 20 ms, at most one timeout): the robot is back in a
// known state and the reply of a request this ended is gone. Nothing for a framing without one.
//
// What stays ambiguous without sequence numbers: a late reply with the SAME letter as the command
// now in flight (or, binary, a late reply that arrives whole and alone after a resend) is taken as
// its answer. For the requests resent here that is harmless: reads (N, E, H, Q) answer with the
// robot's state, and setting speeds or counters to given values is idempotent. The record loop
// never sends two commands of one letter in a row except the wanderer's sensor reads.
//
// A disconnect (EOF or EIO on the tty, a reset TCP connection) or a stop signal ends the exchange
// at once (LinkError Disconnected / Interrupted); so does the watchdog, when one is set, when no
// valid reply has arrived for `watchdog` (LinkError Timeout).
//
// The defaults, and the arithmetic behind them. The target: a 100 000-step run survives 5 % of
// replies dropped, 5 % garbled and 5 % cut at once, and a reply delayed to three times the timeout.
//  * One send fails with p = 1 - 0.95^3 = 0.143 (the three faults drawn independently).
//  * A Buffon step sends N, D and H: 3 x 10^5 commands. A command is lost when all its k sends
//    fail: p^k. P(the run ends early) <= 3e5 p^k: k = 8 gives 0.05, k = 10 gives 1.0e-3, k = 12
//    gives 2.1e-5. tries = 12.
//  * A reply delayed to 3 timeouts costs the first three sends (it arrives during the fourth and
//    is taken, see above); the other 9 still fail together with p^9 = 2.5e-8.
//  * The cost: a dead robot is noticed after tries x (timeout + backoff_max) = 12 x 290 ms = 3.5 s
//    at the defaults, which bounds how long a robot drives on after its link died. That bound is
//    per command, so no watchdog is set by default: one across commands (`watchdog`, opt-in) only
//    adds failures where a slow host stretches several commands' faults past it (seen in the
//    long-run test on a loaded 2-core machine: 1.4 s without a valid reply, every command within
//    its tries).
//  * The back-off is short (5 ms doubling to 40 ms): the robots answer within milliseconds, and a
//    long back-off would only add to the time a faulty link steals from the control period.
//
// safe_stop(link): the framing's stop plan (StopPlan, framing.hpp). Where set commands are
// acknowledged (the text robots): the robot's safe-stop commands (Codec::safe_stop(): wheels to
// zero first), each until acknowledged, in up to `stop_rounds` rounds of `tries` sends with the
// back-off between rounds; then, on robots that can read their speeds (E), the wheels are read
// back and must be 0, 0 -- the stop is confirmed by the robot's own state, not only by an
// acknowledgement that could be stale. Where nothing is acknowledged (the e-puck2 in binary
// mode): a resynchronisation, then the request that stops the wheels and reads their speeds back,
// in the same rounds, until they read 0, 0; acknowledged, stopped and complete are then all true,
// and otherwise all false. It never throws; its result says whether the wheels are known to be
// stopped, which a run's exit status follows (a robot that may still be driving is not a success).
// It is bounded (issue 43): it gives up `stop_within` after it began (no send starts after that, so
// it ends within stop_within plus one reply's timeout); the commands after the wheels' (LEDs off)
// are not sent when the wheels' stop was not acknowledged (a robot that did not answer the one
// command that matters is not asked for the others: with a silent robot that was 20 s of resends);
// and a stop signal during it (a second Ctrl-C) cuts it short at once. Each way it ends short, the
// result says so and claims nothing it did not see: the wheels are stopped only when acknowledged
// and, where they can be, read back at 0, 0. `on_stop_notice` hears what it is doing while it takes
// long (a round without an acknowledgement, giving up), for a person waiting at a terminal.
#include <antkit/devices/framing.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/serial.hpp>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::devices {

struct LinkOptions {
  std::chrono::milliseconds timeout{250}; // for one reply
  std::uint32_t tries = 12;               // sends of one command before giving up (see above)
  std::chrono::milliseconds backoff{5};   // before the first resend; doubled for each next one...
  std::chrono::milliseconds backoff_max{40}; // ...up to this
  std::chrono::milliseconds watchdog{0};     // 0: none (each command's tries bound it, above)
  std::uint32_t stop_rounds = 3;             // the safe stop: rounds of `tries` sends per command
  std::chrono::milliseconds stop_within{10000}; // the safe stop gives up after this (see above)
  std::function<void(const std::string&)> on_stop_notice{}; // what a long safe stop is doing
  // The run's clock origin: every exchange is stamped with its send's time since it (Exchange::
  // t_ns). record() sets it to the run's start, the origin of its records' t_ns.
  std::chrono::steady_clock::time_point origin{};
};

struct LinkStats {
  std::uint64_t exchanges = 0;   // commands sent, resends included
  std::uint64_t retries = 0;     // resends
  std::uint64_t timeouts = 0;    // no line within the timeout (nothing or part of a line came)
  std::uint64_t bad_replies = 0; // a complete line that is not the reply (junk, a bad value...)
  std::uint64_t overflows = 0;   // a line longer than the port's bound
  std::uint64_t stale = 0;       // late replies to earlier commands, dropped (lines and drains)
};

// What the record loop needs of a link: one request, its validated reply. RobotLink drives a real
// port; replay (logged_link.hpp) serves the same calls from a log's exchanges.
class CommandLink {
public:
  virtual ~CommandLink() = default;
  [[nodiscard]] virtual const Framing& framing() const noexcept = 0;
  [[nodiscard]] virtual const LinkOptions& options() const noexcept = 0;
  // Sends `request` (a text command with its terminator, a binary sequence with its 0) and
  // returns its validated reply (a text reply line with its CR LF; a binary reply's bytes).
  // Throws LinkError (Timeout after the last try; Disconnected; Interrupted). Every attempt is
  // appended to `io`, also when it throws.
  virtual std::string transact(const std::string& request, std::vector<Exchange>& io) = 0;
  // transact(), its reply as a view: of `reply` (by default, where transact()'s string is moved),
  // or of bytes the link holds until its next call (a replay's link: the log's own, not copied).
  virtual std::string_view transact_view(const std::string& request, std::vector<Exchange>& io,
                                         std::string& reply) {
    reply = transact(request, io);
    return reply;
  }
  // The values of the reply the last transact() or transact_view() returned, as the framing
  // decoded them when it judged that reply valid (Framing::kind), or null when this
  // link does not keep them (the live links: their body decodes the reply itself). A replay's
  // link keeps those of a reply it judged itself, so that the body (body.hpp) does not decode one
  // line twice (not those its reading thread judged ahead: see LoggedLink::reply_of).
  [[nodiscard]] virtual const Fields* reply_fields() const noexcept { return nullptr; }
  // The framing's resynchronisation on its own (see above; nothing when the framing has none):
  // the start's and the safe stop's first exchange where the robot's state is unknown.
  virtual void resync(std::vector<Exchange>& io) = 0;
  // Waits `d` (a back-off between safe-stop rounds; a replay does not wait).
  virtual void pause(std::chrono::milliseconds d) = 0;
  // Re-arms the watchdog: the safe stop is tried in full even after the link went quiet.
  virtual void rearm() noexcept = 0;
  // No send starts after `deadline` (transact throws Timeout instead); nullopt: none. The safe
  // stop's bound; a replay does not wait, so its link has none.
  virtual void
  set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline) noexcept {
    (void)deadline;
  }
  // Commands sent so far, resends included.
  [[nodiscard]] virtual std::uint64_t sends() const noexcept = 0;
  // The time of the last send (of the command whose reply transact() returned last), ns since
  // the run's start: the clock a robot without encoders reckons its travel by. A replay returns the
  // logged time (-1 where the log has none).
  [[nodiscard]] virtual std::int64_t last_send_ns() const noexcept = 0;
};

class RobotLink final : public CommandLink {
public:
  // A text robot (LineFraming).
  RobotLink(SerialPort port, RobotKind robot, LinkOptions options = {});
  RobotLink(SerialPort port, std::shared_ptr<const Framing> framing, LinkOptions options = {});

  [[nodiscard]] const Framing& framing() const noexcept override { return *framing_; }
  [[nodiscard]] const LinkOptions& options() const noexcept override { return options_; }
  [[nodiscard]] const LinkStats& stats() const noexcept { return stats_; }
  [[nodiscard]] const SerialPort& port() const noexcept { return port_; }

  std::string transact(const std::string& request, std::vector<Exchange>& io) override;
  void resync(std::vector<Exchange>& io) override;
  void pause(std::chrono::milliseconds d) override;
  void rearm() noexcept override { last_ok_ = std::chrono::steady_clock::now(); }
  void
  set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline) noexcept override {
    deadline_ = deadline;
  }
  [[nodiscard]] std::uint64_t sends() const noexcept override { return stats_.exchanges; }
  [[nodiscard]] std::int64_t last_send_ns() const noexcept override { return last_send_ns_; }

private:
  void drain(std::vector<Exchange>& io);
  [[nodiscard]] std::int64_t now_ns() const noexcept;
  std::int64_t last_send_ns_ = -1;
  SerialPort port_;
  std::shared_ptr<const Framing> framing_;
  LinkOptions options_;
  LinkStats stats_;
  std::chrono::steady_clock::time_point last_ok_;
  std::optional<std::chrono::steady_clock::time_point> deadline_;
};

struct SafeStopResult {
  bool stopped = false; // the wheels are known to be at zero (acknowledged, and read back as 0, 0
                        // where the robot can read its speeds)
  bool acknowledged = false; // the wheels' command was acknowledged (not yet read back)
  bool complete = false;     // every safe-stop command was acknowledged (LEDs off too)
  std::string failure;       // "" when complete, else what was not done
};

// See above. Never throws (a stop signal during it cuts it short, and the result says so).
SafeStopResult safe_stop(CommandLink& link, std::vector<Exchange>& io) noexcept;

namespace detail {
// The same steps, letting through what the link throws beyond LinkError: a replay's link
// (replay.cpp) throws its divergence from inside the safe stop, which the noexcept safe_stop
// would turn into std::terminate (found by the replay_log fuzz target).
SafeStopResult safe_stop_steps(CommandLink& link, std::vector<Exchange>& io);
} // namespace detail

} // namespace antkit::devices
