// The library names its inputs in its own words (InputError::where(): "largest map", "port",
// "controller parameter heading"); the command shows each as the option that carries it, from the
// words its subcommand registered (cli/commands.hpp) or the words every command shows alike
// (cli/main.cpp). Whole lines, byte for byte: the messages are what they were when the library
// threw the options' names itself.
#include "antkit_child.hpp"
#include "run_antkit.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

using antkit::test::run_antkit;

TEST_CASE("antkit: the library's words for its inputs are shown as each command's options",
          "[cli]") {
  const auto dir = antkit::test::scratch_dir("cli", "flag-words");
  const std::string d = dir.string();
  struct Case {
    std::string args, err;
  };
  const Case cases[] = {
      // campaign::validate: "time limit", "variants"
      {"campaign stc --cases 10 --time -1 --out " + d + "/camp",
       "--time: expected a time in seconds, 0 or more"},
      {"campaign los --cases 10 --variants frontier,zigzag --out " + d + "/camp",
       "--variants: 'zigzag' is not a los variant; expected some of fast-wall-follow, frontier, "
       "frontier-nolos"},
      // experiments::validate (reproduce): "families"
      {"reproduce --only los,sheng --out " + d + "/out",
       "--only: 'sheng' is not one of buffon, los, stc, uniform"},
      // run_buffon_figure: "figure", buffon-experiment's own word; the Buffon parameters' "steps
      // per visit", a word every command shows alike
      {"buffon-experiment --figure 4 --out " + d + "/out",
       "--figure: the figure must be 5, 6, 7, 8, 9 or 14"},
      {"buffon-experiment --figure 5 --steps 0 --out " + d + "/out",
       "--steps: the steps per visit must be in [1, 10000000]"},
      // devices: "fault", "dark offset", "port", "controller parameter heading", "start sub-cell",
      // "start heading", "camera noise"
      {"emulate khepera --fault foo=1",
       "--fault: unknown fault 'foo': expected delay, garbage, drop, cut, disconnect, silent or "
       "unterminated"},
      {"emulate khepera --dark-offset 2", "--dark-offset:  is an option of the stc-floor robot"},
      {"record --device khepera --port " + d + "/absent --controller buffon --out " + d +
           "/log.jsonl",
       "--port: cannot open '" + d + "/absent': No such file or directory"},
      {"record --device stc-floor --port /dev/null --controller ant --start 0,0 --param "
       "heading=4 --out " +
           d + "/log.jsonl",
       "--param heading: expected 0 (E), 1 (N), 2 (W) or 3 (S)"},
      // a device option's declared word ("start heading") and range (device_options.hpp)
      {"record --device stc-floor --port /dev/null --controller ant --start 0,0 --heading 4 "
       "--out " +
           d + "/log.jsonl",
       "--heading: '4' is out of range: expected a whole number in [0, 3]"},
      {"emulate stc-floor --noise 300", "--noise: '300' is out of range: expected a whole number "
                                        "in [0, 255]"},
      {"record --device stc-floor --port /dev/null --controller ant --out " + d + "/log.jsonl",
       "--start: without --map the robot's start sub-cell must be given (X,Y)"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const auto r = run_antkit(c.args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err == "antkit: error: " + c.err + "\n");
  }
  CHECK(std::filesystem::is_empty(dir.path()));
}
