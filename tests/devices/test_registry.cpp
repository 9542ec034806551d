// The registry of devices (device.hpp): one robot model, every robot found by its name, and each
// device refusing the options it does not take before anything is opened.
#include <antkit/devices/device.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <string>

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
