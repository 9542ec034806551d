#pragma once
// Where the tests find the antkit executable, the checkout and its maps. The paths are defined in
// one generated file (tests/CMakeLists.txt writes test_paths.cpp into the build tree), not as
// compile definitions: a definition holding an absolute path is part of every test file's compile
// command, so ccache could not reuse a test object compiled in another clone (CI's clean clone).

#include <string>

namespace antkit::test {

// The antkit command of this build.
const char* antkit_exe();
// The checkout's root.
const char* source_dir();
// The checkout's data/maps.
const char* maps_dir();

// A file by its path below the checkout's root.
inline std::string source_path(const std::string& relative) {
  return std::string(source_dir()) + "/" + relative;
}

} // namespace antkit::test
