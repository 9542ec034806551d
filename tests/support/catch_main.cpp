// The one Catch2 main of the test suite. Before the tests run it prints the rapidcheck
// configuration to stderr, so that any failing property in a CI log can be replayed:
//   RC_PARAMS="seed=<seed>" ./test_xxx "<test name>"
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <cstdlib>
#include <iostream>
#include <string_view>

int main(int argc, char* argv[]) {
  bool listing = false; // test discovery lists names: keep its output clean
  for (int i = 1; i < argc; ++i)
    listing = listing || std::string_view(argv[i]).rfind("--list", 0) == 0;
  if (listing) return Catch::Session().run(argc, argv);
  const char* rc = std::getenv("RC_PARAMS");
  std::cerr << "rapidcheck: RC_PARAMS=\"" << (rc ? rc : "") << "\"" << (rc ? "" : " (random seed)")
            << '\n';
  return Catch::Session().run(argc, argv);
}
