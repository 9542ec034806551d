#pragma once
// SIGINT / SIGTERM as a request to stop: the handlers (installed without SA_RESTART, so a blocked
// poll returns EINTR) only record the signal; the record loop checks requested() between
// exchanges and stops the robot safely.
namespace antkit::devices {

class StopSignals {
public:
  static void install();
  static void uninstall();
  [[nodiscard]] static bool requested() noexcept;
  [[nodiscard]] static int signal() noexcept;
  static void reset() noexcept;
  // Installs for its lifetime (nested scopes install once).
  class Scope {
  public:
    Scope() { install(); }
    ~Scope() { uninstall(); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
  };
};

} // namespace antkit::devices
