// SIGINT / SIGTERM as a stop request (stop_signals.hpp).
#include <antkit/devices/stop_signals.hpp>
#include <atomic>
#include <csignal>

namespace antkit::devices {

namespace {
volatile std::sig_atomic_t g_signal = 0;
std::atomic<int> g_installs{0};
struct sigaction g_old_int, g_old_term;

extern "C" void on_stop_signal(int sig) {
  g_signal = sig;
}
} // namespace

void StopSignals::install() {
  if (g_installs.fetch_add(1) != 0) return;
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0; // no SA_RESTART: a blocked poll returns EINTR
  ::sigaction(SIGINT, &sa, &g_old_int);
  ::sigaction(SIGTERM, &sa, &g_old_term);
}

void StopSignals::uninstall() {
  if (g_installs.fetch_sub(1) != 1) return;
  ::sigaction(SIGINT, &g_old_int, nullptr);
  ::sigaction(SIGTERM, &g_old_term, nullptr);
}

bool StopSignals::requested() noexcept {
  return g_signal != 0;
}

int StopSignals::signal() noexcept {
  return g_signal;
}

void StopSignals::reset() noexcept {
  g_signal = 0;
}

} // namespace antkit::devices
