// Replay of a hardware log through its controller (replay.hpp).
#include "body.hpp"
#include "logged_link.hpp"
#include "replay_steps.hpp"

#include <antkit/devices/controllers.hpp>
#include <antkit/devices/device.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <array>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

namespace antkit::devices {

namespace {

using detail::Attempt;
using detail::LoggedLink;

// The stop record against the run: its reason in the words stop_reason() writes, and its safe
// stop re-run on its exchanges. The exchanges of an unfinished step come first; the safe stop is
// the shortest tail, starting with the safe stop's first command, on which safe_stop() replays to
// the verdict the reason states (replay_steps.hpp). Returns the difference, if any.
std::optional<Divergence> check_stop(const LogStop& stop, const LineFraming& framing) {
  const Codec& codec = framing.codec();
  const std::string& reason = stop.reason;
  if (auto d = detail::check_stop_kind(stop)) return d;
  const std::string may_move = "; " + std::string(kRobotMayBeMoving) + ": ";
  const bool claims_moving = reason.find(may_move) != std::string::npos;
  const bool claims_partial = reason.find("; safe stop: ") != std::string::npos;
  if (reason.rfind("link: disconnected", 0) == 0 && stop.io.empty() && stop.step == 0)
    return std::nullopt; // never connected: nothing was sent
  // Every byte sent in the stop record is a command of this robot, as its codec encodes it.
  for (std::size_t i = 0; i < stop.io.size(); ++i) {
    const auto& sent = stop.io[i].sent;
    if (sent.empty()) continue;
    const auto term = codec.robot().terminator;
    const bool ends = sent.size() > term.size() && sent.substr(sent.size() - term.size()) == term;
    if (!ends || !codec.parse_command(std::string_view(sent).substr(0, sent.size() - term.size())))
      return Divergence{stop.step, "stop.io[" + std::to_string(i) + "].sent",
                        "'" + printable(sent) + "'", "a command of this robot"};
  }
  const std::string first = codec.safe_stop().front();
  return detail::check_safe_stop_tails(
      stop, framing, first,
      [&](const SafeStopResult& r) -> std::optional<Divergence> {
        // The bytes decide the claim where they can: a safe stop acknowledged and read back at
        // zero in the log was one live (the live link reads the same bytes the same way), and one
        // with no acknowledgement of the wheels' command at all left the robot possibly moving.
        // In between (acknowledged, not confirmed) a lost link may explain either words.
        const bool lie = (r.stopped && r.complete && (claims_moving || claims_partial)) ||
                         (!r.acknowledged && !claims_moving);
        if (!lie) return std::nullopt;
        return Divergence{stop.step, "stop.reason", "'" + reason + "'",
                          r.stopped && r.complete
                              ? "the safe stop acknowledged and read back at 0, 0"
                              : "no acknowledgement of '" + printable(first) +
                                    "': " + std::string(kRobotMayBeMoving)};
      },
      "the safe stop's '" + printable(first) + "' and its exchanges");
}

// The text robots' body (body.hpp) over the log's exchanges: the same code as record()'s.
class ReplayedSerialBody final : public detail::ReplayedBody {
public:
  ReplayedSerialBody(LoggedLink& link, const Codec& codec) : body_(link, codec) {}
  // A robot without encoders reckons its odometry from the times its commands were sent.
  void check_record(const LogRecord& r, const std::string& path, std::size_t line) const override {
    const RobotDescription& robot = body_.robot();
    if (!robot.has_odometry)
      for (const Exchange& e : r.io)
        if (!e.sent.empty() && e.t_ns < 0)
          throw kernel::InputError(
              path, line, 1,
              "an exchange without its time: the " + std::string(robot.name) +
                  " has no wheel encoders and its odometry is reckoned from the times its "
                  "commands were sent (a log written before they were logged: re-record "
                  "the run)");
  }
  void identify(std::vector<Exchange>& io) override { body_.identify(io); }
  void start(std::vector<Exchange>& io) override { body_.start(io); }
  Proximity read_sensors(std::vector<Exchange>& io) override { return body_.read_sensors(io); }
  void act(bool wander, std::span<const std::int64_t> cmd, std::vector<Exchange>& io) override {
    detail::act(body_, wander, cmd, io);
  }
  std::array<std::int64_t, 2> odometry(std::vector<Exchange>& io) override {
    const WheelTravel odo = body_.odometry(io);
    return {odo.left, odo.right};
  }

private:
  detail::Body body_;
};

} // namespace

bool compare_fields(std::span<const std::int64_t> expected, std::span<const std::int64_t> actual,
                    std::int64_t step, const char* field, std::optional<Divergence>& out) {
  const std::size_t n = std::max(expected.size(), actual.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (i < expected.size() && i < actual.size() && expected[i] == actual[i]) continue;
    if (!out)
      out = Divergence{step, std::string(field) + "[" + std::to_string(i) + "]",
                       i < expected.size() ? std::to_string(expected[i]) : "(none)",
                       i < actual.size() ? std::to_string(actual[i]) : "(none)"};
    return false;
  }
  return true;
}

namespace {

// The records of a log in order, each with the line it was read from: read on the calling thread,
// or (`ahead`) by a second thread into batches while the caller checks the ones before. A record
// handed out stays valid until the next call. The reader's error is rethrown at the record where
// it was met, as the reader alone would throw it; the reader's state (stop(), truncated()) is
// final once next() has returned null or thrown. The destructor stops and joins the thread.
class RecordSource {
public:
  // `link`: when reading ahead, the records' exchanges are also read as their attempts there
  // (LoggedLink::read_attempt), for next() to hand out with each record: every record's when
  // `every_attempt`, else those of the batches read while the ring is at least half full (the
  // reading thread is ahead: the checks, not the reading, are what the replay waits for).
  RecordSource(LogReader& reader, bool ahead, const LoggedLink* link, bool every_attempt)
      : reader_(reader), ahead_(ahead), every_attempt_(every_attempt), link_(link) {
    if (ahead_) thread_ = std::thread([this] { produce(); });
  }
  ~RecordSource() {
    if (!thread_.joinable()) return;
    {
      const std::lock_guard lock(m_);
      stop_ = true;
    }
    producer_cv_.notify_all();
    thread_.join();
  }
  RecordSource(const RecordSource&) = delete;
  RecordSource& operator=(const RecordSource&) = delete;

  // `attempts`: the record's attempts when read ahead (one per exchange), else empty.
  const LogRecord* next(std::size_t& line, std::span<const Attempt>& attempts) {
    attempts = {};
    if (done_) return nullptr;
    if (!ahead_) {
      if (!reader_.next(own_)) return nullptr;
      line = reader_.line();
      return &own_;
    }
    for (;;) {
      Batch& b = ring_[at_];
      if (!holding_) {
        std::unique_lock lock(m_);
        // Batches are filled and released in the same order: the consumer's batch, the oldest not
        // released, is full exactly when some batch is.
        if (full_ == 0) {
          consumer_waiting_ = true;
          consumer_cv_.wait(lock, [&] { return full_ >= kRefill || (full_ > 0 && finished_); });
          consumer_waiting_ = false;
        }
        holding_ = true;
        pos_ = 0;
      }
      if (pos_ < b.n) {
        line = b.lines[pos_];
        attempts = std::span<const Attempt>(b.attempts)
                       .subspan(b.attempts_at[pos_], b.attempts_at[pos_ + 1] - b.attempts_at[pos_]);
        return &b.records[pos_++];
      }
      if (b.last) {
        thread_.join(); // the reader's state is the producer's last
        done_ = true;
        if (b.error) std::rethrow_exception(std::exchange(b.error, nullptr));
        return nullptr;
      }
      bool wake = false;
      {
        const std::lock_guard lock(m_);
        --full_;
        ++free_;
        wake = producer_waiting_ && free_ >= kRefill;
      }
      if (wake) producer_cv_.notify_one();
      holding_ = false;
      at_ = (at_ + 1) % ring_.size();
    }
  }

private:
  static constexpr std::size_t kBatch = 256;
  static constexpr std::size_t kRing = 8;
  // A producer that found the ring full sleeps until this many batches are free again, and a
  // consumer that found its batch not full until this many are full (or the last one is): a
  // sleep for several batches, not one per batch (a wake costs a system call, and the woken
  // thread, on a virtual machine, tens of microseconds before it runs).
  static constexpr std::size_t kRefill = kRing / 2;
  struct Batch {
    std::vector<LogRecord> records = std::vector<LogRecord>(kBatch);
    std::vector<std::size_t> lines = std::vector<std::size_t>(kBatch);
    // Record i's attempts: attempts[attempts_at[i], attempts_at[i + 1]) (none without a link).
    std::vector<Attempt> attempts;
    std::vector<std::size_t> attempts_at = std::vector<std::size_t>(kBatch + 1);
    std::size_t n = 0;
    bool last = false;
    std::exception_ptr error;
  };

  void produce() {
    for (std::size_t k = 0;; k = (k + 1) % ring_.size()) {
      Batch& b = ring_[k];
      bool attempts = false; // this batch's attempts are read here
      {
        std::unique_lock lock(m_);
        if (!stop_ && free_ == 0) {
          producer_waiting_ = true;
          producer_cv_.wait(lock, [&] { return stop_ || free_ >= kRefill; });
          producer_waiting_ = false;
        }
        if (stop_) return;
        --free_; // batches are freed in the order they are filled: this one is free
        attempts = link_ != nullptr && (every_attempt_ || full_ >= kRefill);
      }
      b.n = 0;
      b.attempts.clear();
      try {
        while (b.n < kBatch && !b.last) {
          if (reader_.next(b.records[b.n])) {
            if (attempts) read_attempts(b.records[b.n], b.attempts);
            b.lines[b.n] = reader_.line();
            b.attempts_at[++b.n] = b.attempts.size();
          } else
            b.last = true;
        }
      } catch (...) {
        b.error = std::current_exception();
        b.last = true;
      }
      bool wake = false;
      {
        const std::lock_guard lock(m_);
        ++full_;
        finished_ = b.last;
        wake = consumer_waiting_ && (full_ >= kRefill || finished_);
      }
      if (wake) consumer_cv_.notify_one();
      if (b.last) return;
    }
  }

  // The record's attempts appended to `out` (none when reading them failed: the check then reads
  // them itself, and fails there as the reading alone would).
  void read_attempts(const LogRecord& r, std::vector<Attempt>& out) const noexcept {
    const std::size_t first = out.size();
    try {
      for (const Exchange& e : r.io)
        out.push_back(e.sent.empty() ? Attempt{} : link_->read_attempt(e));
    } catch (...) {
      out.resize(first);
    }
  }

  LogReader& reader_;
  bool ahead_, every_attempt_, done_ = false;
  const LoggedLink* link_;
  LogRecord own_;                 // the record read here (no thread)
  std::array<Batch, kRing> ring_; // filled by the producer in turn, taken in turn
  std::size_t at_ = 0, pos_ = 0;  // the consumer's batch and its next record
  bool holding_ = false;          // the consumer holds ring_[at_] (it is full)
  std::mutex m_;                  // guards the counts, the flags and stop_
  std::size_t free_ = kRing;      // batches neither full nor being filled
  std::size_t full_ = 0;          // batches full (filled, not yet released)
  bool finished_ = false;         // the producer has filled its last batch
  bool producer_waiting_ = false; // the producer sleeps on producer_cv_ (the ring was full)
  bool consumer_waiting_ = false; // the consumer sleeps on consumer_cv_ (its batch not full)
  std::condition_variable producer_cv_, consumer_cv_;
  bool stop_ = false;
  std::thread thread_;
};

std::atomic<detail::ReadAhead> read_ahead{detail::ReadAhead::Auto};

} // namespace

void detail::set_read_ahead(ReadAhead mode) noexcept {
  read_ahead.store(mode, std::memory_order_relaxed);
}

ReplayResult replay_records(
    LogReader& reader, std::optional<std::int64_t> until,
    const std::function<std::optional<Divergence>(const LogRecord& r, std::size_t line,
                                                  std::vector<std::int64_t>& cmd)>& check,
    const std::function<std::optional<Divergence>(const LogStop& stop)>& check_stop) {
  return detail::replay_records_with_attempts(
      reader, until, nullptr,
      [&](const LogRecord& r, std::size_t line, std::span<const Attempt>,
          std::vector<std::int64_t>& cmd) { return check(r, line, cmd); },
      check_stop);
}

ReplayResult detail::replay_records_with_attempts(
    LogReader& reader, std::optional<std::int64_t> until, const LoggedLink* link,
    const CheckRecord& check,
    const std::function<std::optional<Divergence>(const LogStop& stop)>& check_stop) {
  ReplayResult out;
  out.header = reader.header();
  RunHash run;
  std::vector<std::int64_t> cmd;
  std::int64_t last_t = 0;
  // Read ahead only for the whole log: with `until` the reader must stop where the replay does.
  const auto mode = read_ahead.load(std::memory_order_relaxed);
  RecordSource source(
      reader,
      !until && mode != detail::ReadAhead::Never &&
          (mode != detail::ReadAhead::Auto || std::thread::hardware_concurrency() > 1),
      link, mode == detail::ReadAhead::AlwaysAttempts);
  std::size_t line = 0;
  std::span<const Attempt> attempts;
  const LogRecord* next = nullptr;
  while ((!until || out.steps < *until) && (next = source.next(line, attempts)) != nullptr) {
    const LogRecord& r = *next;
    // Every device's times never decrease (the recording's steady clock): the records' and the
    // exchanges' (those that have one), each exchange no later than its step's end.
    auto d = r.time_ns < last_t ? std::optional<Divergence>(Divergence{
                                      r.step, "t_ns", std::to_string(r.time_ns),
                                      "a time >= the previous step's " + std::to_string(last_t)})
                                : std::nullopt;
    for (std::size_t k = 0; !d && k < r.io.size(); ++k) {
      const std::int64_t t = r.io[k].t_ns;
      if (t < 0) continue;
      if (t < last_t || t > r.time_ns)
        d = Divergence{r.step, "io[" + std::to_string(k) + "].t", std::to_string(t),
                       "a time in [" + std::to_string(last_t) + ", " + std::to_string(r.time_ns) +
                           "]: after the exchange before it, before the step's end"};
      else if (t > detail::kMaxRunNs)
        d = Divergence{r.step, "io[" + std::to_string(k) + "].t", std::to_string(t),
                       "a time below 2^55 ns (about a year: the longest run reckoned)"};
      last_t = std::max(last_t, t);
    }
    if (!d) d = check(r, line, attempts, cmd);
    last_t = r.time_ns;
    if (d) {
      out.identical = false;
      out.first_divergence = std::move(d);
      break;
    }
    run.add(r.step, r.obs, cmd, r.state);
    ++out.steps;
  }
  // After a divergence the rest is read unchecked, so that the result still says whether the log
  // is whole (its stop record, a cut last line): the divergence stays the finding, and a line the
  // reader refuses after it ends the reading there.
  if (!out.identical && !until) {
    try {
      while (source.next(line, attempts) != nullptr) {
      }
    } catch (const kernel::InputError&) {
    }
  }
  out.truncated = reader.truncated();
  out.stop = reader.stop();
  out.complete = out.stop.has_value() && !out.truncated;
  out.hash = run.value();
  // The stop record's exchanges come after the last step: their times are no earlier than its end
  // and never decrease (so the last step's t_ns is held from both sides).
  if (out.identical && !until && out.stop) {
    std::int64_t t = last_t;
    for (std::size_t k = 0; k < out.stop->io.size() && out.identical; ++k) {
      const std::int64_t tk = out.stop->io[k].t_ns;
      if (tk < 0) continue;
      if (tk < t || tk > detail::kMaxRunNs) {
        out.identical = false;
        out.first_divergence =
            Divergence{out.stop->step, "stop.io[" + std::to_string(k) + "].t", std::to_string(tk),
                       "a time in [" + std::to_string(t) +
                           ", 2^55]: after the last step's end and the exchange before it"};
      }
      t = std::max(t, tk);
    }
  }
  if (check_stop && out.identical && !until && out.stop)
    if (auto d = check_stop(*out.stop)) {
      out.identical = false;
      out.first_divergence = std::move(d);
    }
  return out;
}

ReplayResult replay(const std::string& path, std::optional<std::int64_t> until) {
  LogReader reader(path);
  return replay(reader, path, until);
}

ReplayResult replay(LogReader& reader, const std::string& path, std::optional<std::int64_t> until) {
  const Device* dev = find_device(reader.header().robot);
  if (dev == nullptr)
    throw kernel::InputError(
        path, 1, 1, "unknown robot '" + reader.header().robot + "': expected " + device_names());
  return dev->replay(reader, path, until);
}

namespace detail {

ReplayResult replay_serial(LogReader& reader, const std::string& path,
                           std::optional<std::int64_t> until, RobotKind kind) {
  const LineFraming framing(kind);
  const RobotDescription& robot = framing.codec().robot();
  // The same body as record() (body.hpp), over the log's exchanges.
  LoggedLink link(framing, {});
  ReplayedSerialBody body(link, framing.codec());
  return replay_controller_run(
      reader, path, until,
      {robot, link, body, "io[0].received",
       "a reply identifying a " + std::string(robot.name) + ": " + std::string(robot.identity)},
      [&](const LogStop& stop) { return check_stop(stop, framing); });
}

} // namespace detail

} // namespace antkit::devices
