// A log's records read a batch ahead (log_prefetch.hpp).
#include <antkit/devices/log_prefetch.hpp>
#include <utility>

namespace antkit::devices {

LogPrefetch::LogPrefetch(LogReader& reader, Prepare prepare, std::size_t batch, Threads threads)
    : reader_(reader), prepare_(std::move(prepare)), batch_(batch < 1 ? 1 : batch) {
  for (auto& s : slots_) {
    s.records.resize(batch_);
    if (prepare_) s.prepared.resize(batch_);
  }
  // On one CPU a second thread only takes turns with this one: the batches are read in next().
  if (threads == Threads::Auto && std::thread::hardware_concurrency() != 1)
    thread_ = std::thread([this] { run(); });
}

LogPrefetch::~LogPrefetch() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void LogPrefetch::run() {
  for (int k = 0;; k ^= 1) {
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return stop_ || !slots_[k].full; });
      if (stop_) return;
    }
    if (fill(k)) return;
  }
}

bool LogPrefetch::fill(int k) {
  Slot& s = slots_[k];
  std::size_t n = 0;
  bool last = false;
  std::exception_ptr error;
  // Each record prepared as soon as it is read, so that the records before an error are whole.
  const auto prepare = [&](std::size_t i) {
    if (prepare_) prepare_(s.records[i], s.prepared[i]);
  };
  try {
    if (have_carry_) {
      std::swap(s.records[0], carry_);
      n = 1;
    } else if (reader_.next(s.records[0])) {
      n = 1;
    }
    if (n == 1) {
      prepare(0);
      for (; n < batch_ && reader_.next(s.records[n]); ++n) prepare(n);
    }
    have_carry_ = n == batch_ && reader_.next(carry_);
    last = !have_carry_;
  } catch (...) {
    error = std::current_exception();
    last = true;
  }
  {
    const std::lock_guard lock(mutex_);
    s.count = n;
    s.last = last;
    s.error = error;
    s.full = true;
  }
  changed_.notify_all();
  return last;
}

LogPrefetch::Batch LogPrefetch::next() {
  std::unique_lock lock(mutex_);
  if (taken_ >= 0) {
    slots_[taken_].full = false;
    taken_ = -1;
    changed_.notify_all();
  }
  if (pending_) std::rethrow_exception(std::exchange(pending_, nullptr));
  if (done_) return {};
  Slot& s = slots_[next_];
  if (!thread_.joinable()) {
    lock.unlock();
    fill(next_);
    lock.lock();
  }
  changed_.wait(lock, [&] { return s.full; });
  taken_ = next_;
  next_ ^= 1;
  done_ = s.last;
  if (s.error) {
    if (s.count == 0) std::rethrow_exception(s.error);
    pending_ = s.error;
  }
  return {{s.records.data(), s.count},
          {s.prepared.data(), s.prepared.empty() ? 0 : s.count},
          s.last && !s.error};
}

} // namespace antkit::devices
