#pragma once
// ScratchDir: a fresh directory for a test's files under the system's temporary directory, named
// antkit-PREFIX-PID-N, and removed with everything in it when the ScratchDir goes (so also when a
// REQUIRE fails or an exception leaves the test). Every test that writes files writes them in one.
// ANTKIT_KEEP_TEST_FILES=1 (any non-empty value) keeps them for inspection: each kept directory's
// path is printed once on standard error when it is made.
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <unistd.h>

namespace antkit::test {

class ScratchDir {
public:
  explicit ScratchDir(const std::string& prefix) {
    static std::atomic<unsigned> counter{0};
    path_ =
        std::filesystem::temp_directory_path() /
        ("antkit-" + prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    // A directory of this name is a leftover of an earlier process with this PID (one kept with
    // ANTKIT_KEEP_TEST_FILES, or one killed before it could clean up): it is not ours to read.
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
    const char* keep = std::getenv("ANTKIT_KEEP_TEST_FILES");
    keep_ = keep != nullptr && *keep != '\0';
    if (keep_) std::cerr << "ANTKIT_KEEP_TEST_FILES: keeping " << path_.string() << '\n';
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  ~ScratchDir() {
    if (keep_) return;
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }

  [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }
  // A file or folder inside it (not created).
  [[nodiscard]] std::filesystem::path operator/(const std::filesystem::path& name) const {
    return path_ / name;
  }
  [[nodiscard]] std::string string() const { return path_.string(); }

private:
  std::filesystem::path path_;
  bool keep_ = false;
};

} // namespace antkit::test
