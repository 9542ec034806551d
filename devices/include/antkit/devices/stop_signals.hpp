#pragma once
// SIGINT (Ctrl-C), SIGTERM (kill, a service manager), SIGHUP (a closed terminal or SSH session) and
// SIGQUIT (Ctrl-\) as a request to stop -- the ways a person or a system ends a process; SIGPIPE is
// ignored meanwhile, so a peer that hung up is a disconnect, not the process's end: the handlers
// (installed without SA_RESTART, so a blocked poll returns EINTR) only record the signal; the
// record loop checks requested() between exchanges and stops the robot safely.
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
