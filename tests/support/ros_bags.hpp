#pragma once
// ROS 2 test bags written by independent writers under node (write_bags.mjs beside this file: what
// it writes and what the walks are). ros_bags_dir() writes them once per test process into a fresh
// folder and returns it; "" when node is absent (the caller says it skipped, and why). Node
// present but its packages missing (`npm ci` not run) is a failure, not a skip.
#include "scratch_dir.hpp"
#include "test_paths.hpp"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace antkit::test {

inline bool have_node() {
  return std::system("node --version >/dev/null 2>&1") == 0;
}

inline std::string ros_bags_dir() {
  static const std::string dir = [] {
    if (!have_node()) return std::string();
    // The folder goes when the test process ends (also when writing it fails).
    static const ScratchDir scratch("ros-bags");
    const auto d = scratch / "bags";
    const std::string cmd = "node '" + source_path("tests/support/write_bags.mjs") + "' '" +
                            d.string() + "' >/dev/null";
    if (std::system(cmd.c_str()) != 0)
      throw std::runtime_error("write_bags.mjs failed: run `npm ci` in the checkout (or "
                               "scripts/bootstrap.sh --node-packages)");
    return d.string();
  }();
  return dir;
}

} // namespace antkit::test
