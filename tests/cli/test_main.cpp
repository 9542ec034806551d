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

TEST_CASE("the plumbing commands live under antkit dev, out of the user's list", "[cli]") {
  const auto help = run_antkit("--help");
  CHECK(help.status == 0);
  CHECK(help.out.find("mcu-input") == std::string::npos);
  CHECK(help.out.find("\nPlumbing:\n  dev ") != std::string::npos);
  const auto dev = run_antkit("dev --help");
  CHECK(dev.status == 0);
  CHECK(dev.out.find("Plumbing for the project's own scripts and tests") != std::string::npos);
  for (const char* name :
       {"buffon-mcu-input", "rs-mcu-input", "stc-mcu-input", "wanderer-mcu-input"})
    CHECK(dev.out.find(std::string("  ") + name + " ") != std::string::npos);
  // The old name is refused (exit 2) with where the command went; an unknown word after dev is
  // named with dev's commands.
  const auto old = run_antkit("stc-mcu-input --map x --variant ant --out y");
  CHECK(old.status == 2);
  CHECK(old.err == "antkit: error: 'stc-mcu-input' is plumbing for the project's scripts: antkit "
                   "dev stc-mcu-input\n");
  const auto unknown = run_antkit("dev sweep");
  CHECK(unknown.status == 2);
  CHECK(unknown.err.find("unknown subcommand 'sweep'; expected one of buffon-mcu-input, "
                         "rs-mcu-input, stc-mcu-input, wanderer-mcu-input") != std::string::npos);
}
