#pragma once
// Runs the real `antkit` executable from a test and captures what it printed and its exit status.
#include "test_paths.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace antkit::test {

struct RunResult {
  int status = -1; // the exit status, or -1 if it did not exit normally
  std::string out; // standard output
  std::string err; // standard error
};

// `args` is appended to the command line as it is (quote paths that need it). A run is bounded
// (coreutils' timeout: 15 minutes, then killed; status 124 or 137): a command that should have
// refused its input and instead serves or waits forever fails its test instead of hanging it (the
// bad-input table once did, on an emulator option that had become valid).
inline RunResult run_antkit(const std::string& args) {
  static int counter = 0;
  const auto err_path =
      std::filesystem::temp_directory_path() /
      ("antkit-test-stderr-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  const std::string cmd =
      "timeout -k 10 900 " + std::string(antkit_exe()) + " " + args + " 2>" + err_path.string();
  RunResult r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int raw = ::pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  if (FILE* e = std::fopen(err_path.c_str(), "r")) {
    while ((n = std::fread(buf.data(), 1, buf.size(), e)) > 0) r.err.append(buf.data(), n);
    std::fclose(e);
  }
  std::filesystem::remove(err_path);
  return r;
}

// A real map file by its path below the repository's data/maps.
inline std::string shared_map(const std::string& relative) {
  return std::string(maps_dir()) + "/" + relative;
}

} // namespace antkit::test
