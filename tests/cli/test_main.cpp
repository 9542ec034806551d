#include "run_antkit.hpp"

#include <catch2/catch.hpp>

using antkit::test::run_antkit;

TEST_CASE("antkit --version names the program and its version", "[cli]") {
  const auto r = run_antkit("--version");
  CHECK(r.status == 0);
  CHECK(r.out.rfind("antkit ", 0) == 0);
}

TEST_CASE("an unknown subcommand or option is bad input: exit 2 and one clear message", "[cli]") {
  for (const char* args : {"no-such-command", "--no-such-option"}) {
    const auto r = run_antkit(args);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("antkit: error: ", 0) == 0);
    CHECK(r.out.empty());
  }
}
