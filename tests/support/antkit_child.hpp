#pragma once
// The real `antkit` executable in a child process, its standard output read through a pipe: the
// emulators (`antkit emulate` prints its port on the first line and serves until a signal) and
// recorders that the CLI tests run beside one another. And a scratch directory per test.
#include "scratch_dir.hpp"
#include "test_paths.hpp"

#include <catch2/catch.hpp>
#include <csignal>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>
#include <vector>

namespace antkit::test {

// A fresh directory under the system's temporary directory, named by the test and the process,
// removed with everything in it when the test ends (scratch_dir.hpp).
inline ScratchDir scratch_dir(const std::string& prefix, const std::string& name) {
  return ScratchDir(prefix + "-" + name);
}

// A file's bytes, and its number of lines (a log being written: how far a run has got).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
inline std::size_t lines_in(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

// `antkit ARGS` in a child process.
class AntkitChild {
public:
  explicit AntkitChild(const std::vector<std::string>& args) {
    int fds[2];
    REQUIRE(::pipe(fds) == 0);
    pid_ = ::fork();
    REQUIRE(pid_ >= 0);
    if (pid_ == 0) {
      ::dup2(fds[1], STDOUT_FILENO);
      ::close(fds[0]);
      ::close(fds[1]);
      std::vector<std::string> all{antkit::test::antkit_exe()};
      all.insert(all.end(), args.begin(), args.end());
      std::vector<char*> argv;
      for (auto& a : all) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(antkit::test::antkit_exe(), argv.data());
      ::_exit(127);
    }
    ::close(fds[1]);
    out_ = ::fdopen(fds[0], "r");
  }
  AntkitChild(const AntkitChild&) = delete;
  AntkitChild& operator=(const AntkitChild&) = delete;
  ~AntkitChild() {
    if (pid_ > 0) finish(SIGKILL);
  }
  [[nodiscard]] pid_t pid() const noexcept { return pid_; }
  // The next line it printed, without its newline.
  std::string first_line() {
    char line[256] = {};
    REQUIRE(std::fgets(line, sizeof line, out_) != nullptr);
    std::string s = line;
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    return s;
  }
  // Sends `sig`, then the exit status and the rest of what it printed.
  std::pair<int, std::string> finish(int sig) {
    ::kill(pid_, sig);
    std::string rest;
    char buf[512];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, out_)) > 0) rest.append(buf, n);
    std::fclose(out_);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, rest};
  }

private:
  pid_t pid_ = -1;
  FILE* out_ = nullptr;
};

// `antkit emulate ARGS`: its port (a pty path, or tcp:HOST:PORT) is its first line of output;
// finish() stops it with SIGTERM, as a person would, for its summary.
class Emulator {
public:
  explicit Emulator(std::vector<std::string> args) : child_(with_emulate(std::move(args))) {
    port_ = child_.first_line();
  }
  ~Emulator() {
    if (child_.pid() > 0) finish();
  }
  [[nodiscard]] const std::string& port() const noexcept { return port_; }
  std::pair<int, std::string> finish() { return child_.finish(SIGTERM); }

private:
  static std::vector<std::string> with_emulate(std::vector<std::string> args) {
    args.insert(args.begin(), "emulate");
    return args;
  }
  AntkitChild child_;
  std::string port_;
};

} // namespace antkit::test
