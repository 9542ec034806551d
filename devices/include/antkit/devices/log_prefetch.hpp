#pragma once
// A log's step records parsed on a second thread, one batch ahead of the caller: while the caller
// uses a batch, the next is being read (LogReader::next, the same records in the same order). What
// the caller writes from them is fixed by the records alone, so the bytes do not depend on the
// threads' timing. Used by the MCAP export, where parsing the log is a third of the work; the
// export also has the reading thread write each record's text that needs nothing but the record
// (`prepare`), so that the two threads share the work about evenly.
#include <antkit/devices/log.hpp>
#include <array>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace antkit::devices {

class LogPrefetch {
public:
  // Starts reading `reader`'s records at once (on a machine with one CPU, no thread is started and
  // next() reads each batch itself); `reader` must outlive this and is not to be used
  // until next() has returned an empty batch (or thrown).
  // What the reading thread makes of each record, beside it: any text, cut in up to four parts, and
  // up to four numbers. It is called once per record, in the log's order, on the reading thread
  // (so it may keep state from record to record, used by that thread alone).
  struct Prepared {
    std::string text; // its capacity is kept from batch to batch
    std::size_t cuts[4] = {};
    std::array<double, 4> numbers{}; // and a few numbers, when `numbered`
    bool numbered = false;
  };
  using Prepare = std::function<void(const LogRecord&, Prepared&)>;
  // Threads: a second thread unless the machine has one CPU (Auto), or none (Inline: next()
  // reads each batch itself; the same batches).
  enum class Threads : std::uint8_t { Auto, Inline };
  explicit LogPrefetch(LogReader& reader, Prepare prepare = {}, std::size_t batch = 4096,
                       Threads threads = Threads::Auto);
  ~LogPrefetch(); // stops the reader thread (a batch part read is dropped) and joins it
  LogPrefetch(const LogPrefetch&) = delete;
  LogPrefetch& operator=(const LogPrefetch&) = delete;

  struct Batch {
    std::span<const LogRecord> records; // empty: no records are left
    std::span<const Prepared> prepared; // one per record, when a Prepare was given
    bool last = false;                  // no record follows these
  };
  // The next batch, valid until the following call. A reader's error is thrown at the record it
  // was found at: the records before it are returned first.
  Batch next();

private:
  struct Slot {
    std::vector<LogRecord> records; // grown once, reused: no allocation per record after
    std::vector<Prepared> prepared;
    std::size_t count = 0;
    bool full = false; // handed to the caller (or waiting to be)
    bool last = false;
    std::exception_ptr error; // thrown after this slot's records
  };
  void run();
  bool fill(int slot); // reads into `slot`; true when it was the last batch
  // One record is read past each batch, so that a batch knows whether it is the last; it opens
  // the next batch (swapped into that slot's first place).
  LogRecord carry_;
  bool have_carry_ = false;

  LogReader& reader_;
  Prepare prepare_;
  std::size_t batch_;
  Slot slots_[2];
  std::mutex mutex_;
  std::condition_variable changed_;
  bool stop_ = false;
  int taken_ = -1; // the slot the caller holds
  int next_ = 0;   // the slot the caller takes next
  std::exception_ptr pending_;
  bool done_ = false;
  std::thread thread_;
};

} // namespace antkit::devices
