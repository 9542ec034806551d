// The signals that end a run, as a stop request (stop_signals.hpp).
#include <antkit/devices/stop_signals.hpp>
#include <atomic>
#include <csignal>
#include <cstddef>
#include <iterator>

namespace antkit::devices {

namespace {
// Set by the handler, read by the run's loop: a lock-free atomic, since the handler may run on
// any thread that does not block the signal (a volatile sig_atomic_t serves only the thread the
// handler interrupts; ThreadSanitizer found the race with the signal raised from another thread).
// Lock-free atomics are safe in a signal handler (C++17 [support.signal]).
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);
std::atomic<int> g_installs{0};
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
struct sigaction g_old[std::size(kStopSignals)];
struct sigaction g_old_pipe;

extern "C" void on_stop_signal(int sig) {
  g_signal.store(sig);
}
} // namespace

void StopSignals::install() {
  if (g_installs.fetch_add(1) != 0) return;
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0; // no SA_RESTART: a blocked poll returns EINTR
  for (std::size_t i = 0; i < std::size(kStopSignals); ++i)
    ::sigaction(kStopSignals[i], &sa, &g_old[i]);
  // A write to a TCP peer that hung up is EPIPE (a disconnect the link reports), not the end of
  // the process with the robot driving on.
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  ::sigaction(SIGPIPE, &ignore, &g_old_pipe);
}

void StopSignals::uninstall() {
  if (g_installs.fetch_sub(1) != 1) return;
  for (std::size_t i = 0; i < std::size(kStopSignals); ++i)
    ::sigaction(kStopSignals[i], &g_old[i], nullptr);
  ::sigaction(SIGPIPE, &g_old_pipe, nullptr);
}

bool StopSignals::requested() noexcept {
  return g_signal.load() != 0;
}

int StopSignals::signal() noexcept {
  return g_signal.load();
}

void StopSignals::reset() noexcept {
  g_signal.store(0);
}

} // namespace antkit::devices
