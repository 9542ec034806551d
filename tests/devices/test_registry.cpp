// The registry of devices (device.hpp): one robot model, every robot found by its name, and each
// device refusing the options it does not take before anything is opened.
#include <algorithm>
#include <antkit/devices/device.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <map>
#include <string>
#include <vector>

namespace devices = antkit::devices;
using antkit::kernel::InputError;

TEST_CASE("the registry: every robot is one device, found by its name", "[devices]") {
  CHECK(devices::device_names() == "khepera, khepera-webots, hemisson, epuck, epuck2, stc-floor");
  // The serial robots, the e-puck2 in binary mode and the marker-floor robot.
  CHECK(devices::all_devices().size() == std::size(devices::kSerialRobots) + 2);
  for (const auto kind : devices::kSerialRobots) {
    const auto& robot = devices::describe(kind);
    INFO(robot.name);
    CHECK(robot.kind == kind);
    CHECK(devices::parse_robot(robot.name) == kind);
    const devices::Device* d = devices::find_device(robot.name);
    REQUIRE(d != nullptr);
    CHECK(d->name() == robot.name);
    CHECK(d->line() == robot.line);
    // Every robot's safe stop starts with the wheels' stop, as the replay expects.
    CHECK(robot.safe_stop[0] == "D,0,0");
  }
  REQUIRE(devices::find_device("stc-floor") != nullptr);
  REQUIRE(devices::find_device("epuck2") != nullptr);
  CHECK_FALSE(devices::parse_robot("epuck2")); // not a text-line robot: a device of its own
  CHECK(devices::find_device("roomba") == nullptr);
  try {
    (void)devices::device("roomba", "--device");
    FAIL("an unknown device was found");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("--device") != std::string::npos);
    CHECK(std::string(e.what()).find(devices::device_names()) != std::string::npos);
  }
}

TEST_CASE("the registry: a device refuses the options of another before anything is opened",
          "[devices]") {
  struct Case {
    std::string device, controller, where;
    void (*edit)(devices::RecordOptions&);
  };
  const Case cases[] = {
      {"khepera", "buffon", "floor map", [](devices::RecordOptions& o) { o.map = "x.map"; }},
      {"epuck", "buffon", "start sub-cell",
       [](devices::RecordOptions& o) {
         o.start = {{0, 0}};
       }},
      {"hemisson", "rs", "camera calibration",
       [](devices::RecordOptions& o) { o.calibration = "c.json"; }},
      {"khepera", "ant", "controller", [](devices::RecordOptions&) {}},
      {"stc-floor", "buffon", "controller",
       [](devices::RecordOptions& o) {
         o.start = {{0, 0}};
       }},
      {"stc-floor", "ant", "arena spec",
       [](devices::RecordOptions& o) {
         o.start = {{0, 0}};
         o.arena = "standard";
       }},
      {"stc-floor", "ant", "control period",
       [](devices::RecordOptions& o) {
         o.start = {{0, 0}};
         o.period = std::chrono::milliseconds(5);
       }},
      {"stc-floor", "ant-edge", "controller parameter heading",
       [](devices::RecordOptions& o) {
         o.start = {{0, 0}};
         o.controller.params = {{"heading", 4}};
       }},
      {"stc-floor", "ant-edge", "start sub-cell", [](devices::RecordOptions&) {}},
  };
  for (const auto& c : cases) {
    INFO(c.device << " " << c.where);
    devices::RecordOptions o;
    o.device = c.device;
    o.controller.name = c.controller;
    o.port = "/nonexistent/port";
    o.out = "/nonexistent/dir/log.jsonl";
    c.edit(o);
    try {
      (void)devices::device(c.device, "--device").prepare(o);
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK(e.where() == c.where);
    }
  }
}

TEST_CASE("the registry: each device declares its options, and one refusal names who takes them",
          "[devices]") {
  // Every option of one device or another is taken by some device, under a word of its own.
  std::vector<std::string_view> words;
  for (const auto option : devices::kDeviceOptions) {
    const auto word = devices::option_word(option);
    INFO(word);
    CHECK_FALSE(devices::option_takers(option).empty());
    CHECK(std::find(words.begin(), words.end(), word) == words.end());
    words.push_back(word);
    CHECK((devices::option_of(option, devices::OptionUse::Record) ||
           devices::option_of(option, devices::OptionUse::Emulate)));
  }
  CHECK(devices::option_takers(devices::DeviceOption::FloorMap) == "stc-floor");
  CHECK(devices::option_takers(devices::DeviceOption::ArenaSpec) ==
        "khepera, khepera-webots, hemisson, epuck, epuck2");
  CHECK(devices::option_takers(devices::DeviceOption::Pacing) ==
        "khepera, khepera-webots, hemisson, epuck, epuck2");
  // A device refuses every record option it did not declare, before anything is opened, in the
  // option's word; the message names the devices that take it (or the device's own reason).
  for (const devices::Device* d : devices::all_devices()) {
    for (const auto option : devices::kDeviceOptions) {
      const bool declared = std::any_of(d->options().begin(), d->options().end(),
                                        [&](const auto& o) { return o.option == option; });
      if (declared || !devices::option_of(option, devices::OptionUse::Record)) continue;
      INFO(d->name() << " " << devices::option_word(option));
      devices::RecordOptions o;
      o.device = std::string(d->name());
      o.controller.name = d->name() == "stc-floor" ? "ant" : "buffon";
      o.port = "/nonexistent/port";
      o.out = "/nonexistent/dir/log.jsonl";
      o.map = "x.map";
      o.start = {{0, 0}};
      o.arena = "standard";
      o.period = std::chrono::milliseconds(5);
      o.calibration = "c.json";
      // Only this one option among those the device does not declare.
      for (const auto other : devices::kDeviceOptions) {
        const bool other_declared = std::any_of(d->options().begin(), d->options().end(),
                                                [&](const auto& x) { return x.option == other; });
        if (other == option || other_declared) continue;
        if (other == devices::DeviceOption::FloorMap) o.map.clear();
        if (other == devices::DeviceOption::StartSubCell) o.start.reset();
        if (other == devices::DeviceOption::ArenaSpec) o.arena.clear();
        if (other == devices::DeviceOption::ControlPeriod) o.period.reset();
        if (other == devices::DeviceOption::CameraCalibration) o.calibration.clear();
      }
      try {
        (void)d->prepare(o);
        FAIL("accepted");
      } catch (const InputError& e) {
        CHECK(e.where() == devices::option_word(option));
        CHECK(e.message().find(devices::option_takers(option)) != std::string::npos);
      }
    }
  }
  // The emulators' refusals: another device's option, and a declared one refused with a reason.
  const auto refused = [](std::string_view device, auto edit) -> std::string {
    devices::EmulateOptions o;
    edit(o);
    try {
      (void)devices::device(device, "robot").emulate(o, [](const std::string&) {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return "accepted";
  };
  CHECK(refused("khepera", [](devices::EmulateOptions& o) { o.drift = 3; }) ==
        "drift:  is an option of the stc-floor robot");
  CHECK(refused("stc-floor", [](devices::EmulateOptions& o) { o.pace = true; }) ==
        "pacing:  is an option of the serial robots (khepera, khepera-webots, hemisson, epuck, "
        "epuck2)");
  CHECK(refused("stc-floor", [](devices::EmulateOptions& o) {
          o.listen = "127.0.0.1:0";
        }).find("listen address: the stc-floor emulator serves a pty") == 0);
  // --help's listing, from the declarations: devices that declare alike share a paragraph.
  const std::map<std::string, std::string, std::less<>> flags{{"floor map", "--map"}};
  const std::string help = devices::options_by_device(devices::OptionUse::Record, flags);
  CHECK(help.find("  khepera, khepera-webots, hemisson, epuck, epuck2:\n    arena spec ") !=
        std::string::npos);
  CHECK(help.find("  stc-floor:\n    --map ") != std::string::npos);
  CHECK(help.find("fade half-life") == std::string::npos); // emulate's
}
