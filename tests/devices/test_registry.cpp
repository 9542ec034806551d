// The registry of devices (device.hpp): one robot model, every robot found by its name, and each
// device declaring its own options and refusing the others' before anything is opened.
#include "test_paths.hpp"

#include <algorithm>
#include <antkit/devices/device.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <variant>
#include <vector>

namespace devices = antkit::devices;
using antkit::kernel::InputError;

namespace {

// A robot's registry line as its own file writes it (devices/src/registry.hpp), read here again
// from the sources, independently of the build's reading (devices/registry_list.cmake).
struct Registered {
  int place = 0;
  bool serial = false;
  std::string file; // robot_<name>.cpp or device_<name>.cpp
  // The device name the file is named for: its name with '_' for '-'.
  [[nodiscard]] std::string device_name() const {
    std::string n = file.substr(file.find('_') + 1);
    n.resize(n.size() - 4); // .cpp
    std::replace(n.begin(), n.end(), '_', '-');
    return n;
  }
};

// The devices whose own declarations (Device::options()) take option `name` for `use` (declared,
// and not declared as refused with the device's own reason), in the registry's order, as messages
// list them: a robot added later is among them by its declaration.
std::string declarers(devices::OptionUse use, std::string_view name) {
  std::string out;
  for (const devices::Device* d : devices::all_devices())
    for (const auto& o : d->options())
      if (o.use == use && o.name == name && o.refused.empty()) {
        out += (out.empty() ? "" : ", ") + std::string(d->name());
        break;
      }
  return out;
}

// Whether the list "a, b, c" names `name`.
bool named_in(const std::string& list, std::string_view name) {
  return (", " + list + ", ").find(", " + std::string(name) + ", ") != std::string::npos;
}

std::vector<Registered> registered_in_sources() {
  std::vector<Registered> out;
  const std::regex line(R"(^ANTKIT_(SERIAL_ROBOT|DEVICE)\(([0-9]+), *\w+\))");
  for (const auto& f :
       std::filesystem::directory_iterator(antkit::test::source_path("devices/src"))) {
    if (f.path().extension() != ".cpp") continue;
    std::ifstream in(f.path());
    std::string text;
    while (std::getline(in, text)) {
      std::smatch m;
      if (!std::regex_search(text, m, line)) continue;
      out.push_back(
          {std::stoi(m[2].str()), m[1].str() == "SERIAL_ROBOT", f.path().filename().string()});
    }
  }
  std::sort(out.begin(), out.end(),
            [](const Registered& a, const Registered& b) { return a.place < b.place; });
  return out;
}

} // namespace

TEST_CASE("the registry: every robot is one device, registered in its own file and found by its "
          "name",
          "[devices]") {
  // The registry is what the robots' files declare, in their places' order, each robot named as
  // its file is (robot_khepera_webots.cpp: "khepera-webots"; device_stc_floor.cpp: "stc-floor").
  const auto registered = registered_in_sources();
  REQUIRE(registered.size() == devices::all_devices().size());
  std::size_t serial = 0;
  std::string names, serial_names;
  for (std::size_t i = 0; i < registered.size(); ++i) {
    const Registered& r = registered[i];
    const devices::Device* d = devices::all_devices()[i];
    INFO(r.file);
    CHECK(r.file.starts_with(r.serial ? "robot_" : "device_"));
    CHECK(d->name() == r.device_name());
    CHECK(devices::find_device(r.device_name()) == d);
    if (i > 0) CHECK(registered[i - 1].place < r.place); // one robot per place
    names += (names.empty() ? "" : ", ") + r.device_name();
    if (!r.serial) {
      CHECK_FALSE(devices::parse_robot(d->name())); // a device of its own, no text-line robot
      continue;
    }
    // A serial robot: its description, its kind and its device agree.
    serial_names += (serial_names.empty() ? "" : ", ") + r.device_name();
    REQUIRE(serial < devices::serial_robots().size());
    const auto kind = devices::serial_robots()[serial++];
    const auto& robot = devices::describe(kind);
    CHECK(kind.name() == d->name());
    CHECK(robot.name == d->name());
    CHECK(devices::RobotKind::of(robot) == kind);
    CHECK(devices::parse_robot(robot.name) == kind);
    CHECK(d->line() == robot.line);
    CHECK(d->body() == &robot);
    // Every robot's safe stop starts with the wheels' stop, as the replay expects.
    CHECK(robot.safe_stop[0] == "D,0,0");
  }
  CHECK(serial == devices::serial_robots().size());
  CHECK(devices::device_names() == names);
  CHECK(devices::robot_names() == serial_names);
  // The robots RobotKind names for tests and examples are registered.
  for (const auto kind : {devices::RobotKind::Khepera, devices::RobotKind::Hemisson,
                          devices::RobotKind::Epuck, devices::RobotKind::KheperaWebots})
    CHECK(devices::describe(kind).name == kind.name());
  CHECK(devices::find_device("roomba") == nullptr);
  CHECK_FALSE(devices::parse_robot("roomba"));
  try {
    (void)devices::device("roomba", "--device");
    FAIL("an unknown device was found");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("--device") != std::string::npos);
    CHECK(std::string(e.what()).find(devices::device_names()) != std::string::npos);
  }
}

TEST_CASE("the registry: each device says the body its logs run with, and body_of asks it",
          "[devices]") {
  for (const devices::Device* d : devices::all_devices()) {
    INFO(d->name());
    const devices::RobotDescription* body = d->body();
    const auto kind = devices::body_of(d->name());
    CHECK(kind.has_value() == (body != nullptr));
    if (body != nullptr) {
      CHECK(*kind == devices::RobotKind::of(*body));
      CHECK(&devices::describe(*kind) == body);
    }
    // A serial robot runs with its own description.
    if (const auto own = devices::parse_robot(d->name())) CHECK(kind == own);
  }
  // The e-puck2 borrows the e-puck's body; the marker-floor robot has none; nor has a name that
  // no device has.
  CHECK(devices::body_of("epuck2") == devices::RobotKind::Epuck);
  CHECK_FALSE(devices::body_of("stc-floor"));
  CHECK_FALSE(devices::body_of("roomba"));
  CHECK_FALSE(devices::body_of(""));
}

TEST_CASE("the registry: a device refuses the options of another before anything is opened",
          "[devices]") {
  struct Case {
    std::string device, controller, where;
    void (*edit)(devices::RecordOptions&);
  };
  const Case cases[] = {
      {"khepera", "buffon", "floor map",
       [](devices::RecordOptions& o) { o.device_options.set("map", std::string("x.map")); }},
      {"epuck", "buffon", "start sub-cell",
       [](devices::RecordOptions& o) {
         o.device_options.set("start", antkit::kernel::Cell{0, 0});
       }},
      {"hemisson", "rs", "camera calibration",
       [](devices::RecordOptions& o) {
         o.device_options.set("calibration", std::string("c.json"));
       }},
      {"epuck2", "buffon", "quarter-turn time",
       [](devices::RecordOptions& o) { o.device_options.set("turn-ms", std::int64_t{900}); }},
      {"khepera", "ant", "controller", [](devices::RecordOptions&) {}},
      {"stc-floor", "buffon", "controller",
       [](devices::RecordOptions& o) {
         o.device_options.set("start", antkit::kernel::Cell{0, 0});
       }},
      {"stc-floor", "ant", "arena spec",
       [](devices::RecordOptions& o) {
         o.device_options.set("start", antkit::kernel::Cell{0, 0});
         o.device_options.set("arena", std::string("standard"));
       }},
      {"stc-floor", "ant", "control period",
       [](devices::RecordOptions& o) {
         o.device_options.set("start", antkit::kernel::Cell{0, 0});
         o.device_options.set("period", std::int64_t{5});
       }},
      {"stc-floor", "ant-edge", "controller parameter heading",
       [](devices::RecordOptions& o) {
         o.device_options.set("start", antkit::kernel::Cell{0, 0});
         o.controller.params = {{"heading", 4}};
       }},
      {"stc-floor", "ant-edge", "start sub-cell", [](devices::RecordOptions&) {}},
      // Out of the declared range, in the declaration's word.
      {"stc-floor", "ant-edge", "start heading",
       [](devices::RecordOptions& o) {
         o.device_options.set("start", antkit::kernel::Cell{0, 0});
         o.device_options.set("heading", std::int64_t{4});
       }},
      {"hemisson", "buffon", "control period",
       [](devices::RecordOptions& o) { o.device_options.set("period", std::int64_t{60001}); }},
      // One of its own, but of another type than declared.
      {"khepera", "buffon", "control period",
       [](devices::RecordOptions& o) { o.device_options.set("period", std::string("5")); }},
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

namespace {

// A value of the type `o` declares, in its range.
devices::OptionValue some_value(const devices::DeclaredOption& o) {
  switch (o.type) {
  case devices::OptionType::Switch:
    return true;
  case devices::OptionType::Integer:
    return o.min;
  case devices::OptionType::SubCell:
    return antkit::kernel::Cell{0, 0};
  case devices::OptionType::Texts:
    return std::vector<std::string>{"x"};
  case devices::OptionType::Text:
    break;
  }
  return std::string("x");
}

} // namespace

TEST_CASE("the registry: each device declares its options (name, type, range, default, help)",
          "[devices]") {
  for (const auto use : {devices::OptionUse::Record, devices::OptionUse::Emulate}) {
    for (const devices::Device* d : devices::all_devices()) {
      std::vector<std::string_view> names;
      for (const auto& o : d->options()) {
        if (o.use != use) continue;
        INFO(d->name() << " --" << o.name);
        // Once per device and command, a flag's name, a word for the library's errors, help.
        CHECK(std::find(names.begin(), names.end(), o.name) == names.end());
        names.push_back(o.name);
        CHECK_FALSE(o.word.empty());
        CHECK((o.name.find_first_of(" =") == std::string_view::npos && !o.name.empty()));
        CHECK((o.refused.empty() ? !o.what.empty() : o.what.empty()));
        if (o.type == devices::OptionType::Integer) CHECK(o.min <= o.max);
        // A default applied is a value of the option's type, in its range.
        if (!o.fallback.empty()) {
          const auto v = devices::parse_option_value(o, {std::string(o.fallback)});
          if (const auto* n = std::get_if<std::int64_t>(&v)) CHECK((o.min <= *n && *n <= o.max));
        }
        // Every device that declares this name declares it alike: one flag, one type, one word.
        for (const auto& other : devices::declared_options(use))
          if (other.name == o.name) {
            CHECK(other.type == o.type);
            CHECK(other.word == o.word);
          }
      }
    }
    // One word, one flag.
    const auto all = devices::declared_options(use);
    for (std::size_t i = 0; i < all.size(); ++i)
      for (std::size_t j = i + 1; j < all.size(); ++j) CHECK(all[i].word != all[j].word);
  }
  // Who takes an option: the devices that declare it, in the registry's order. The marker-floor
  // robot alone takes a map; every serial robot and the e-puck2 an arena, --pace and --listen.
  CHECK(devices::option_takers(devices::OptionUse::Record, "map") == "stc-floor");
  for (const auto& [use, name] : {std::pair{devices::OptionUse::Record, "arena"},
                                  std::pair{devices::OptionUse::Emulate, "pace"},
                                  std::pair{devices::OptionUse::Emulate, "listen"}}) {
    INFO(name);
    const std::string takers = devices::option_takers(use, name);
    CHECK(takers == declarers(use, name));
    for (const auto kind : devices::serial_robots()) CHECK(named_in(takers, kind.name()));
    CHECK(named_in(takers, "epuck2"));
    CHECK_FALSE(named_in(takers, "stc-floor"));
  }
}

TEST_CASE("the registry: one refusal of another device's option names who takes it", "[devices]") {
  // A device refuses every record option it did not declare, before anything is opened, in the
  // option's word; the message names the devices that take it.
  for (const devices::Device* d : devices::all_devices()) {
    for (const auto& option : devices::declared_options(devices::OptionUse::Record)) {
      if (devices::declared(*d, devices::OptionUse::Record, option.name) != nullptr) continue;
      INFO(d->name() << " --" << option.name);
      devices::RecordOptions o;
      o.device = std::string(d->name());
      o.controller.name = d->name() == "stc-floor" ? "ant" : "buffon";
      o.port = "/nonexistent/port";
      o.out = "/nonexistent/dir/log.jsonl";
      if (d->name() == "stc-floor") o.device_options.set("start", antkit::kernel::Cell{0, 0});
      o.device_options.set(std::string(option.name), some_value(option));
      try {
        (void)d->prepare(o);
        FAIL("accepted");
      } catch (const InputError& e) {
        CHECK(e.where() == option.word);
        CHECK(e.message().find(devices::option_takers(devices::OptionUse::Record, option.name)) !=
              std::string::npos);
      }
    }
  }
  // The emulators' refusals: another device's option, and a declared one refused with a reason.
  const auto refused = [](std::string_view device, auto edit) -> std::string {
    devices::EmulateOptions o;
    edit(o.device_options);
    try {
      (void)devices::device(device, "robot").emulate(o, [](const std::string&) {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return "accepted";
  };
  CHECK(refused("khepera", [](devices::DeviceValues& v) { v.set("drift", std::int64_t{3}); }) ==
        "drift:  is an option of the stc-floor robot");
  CHECK(refused("stc-floor", [](devices::DeviceValues& v) { v.set("pace", true); }) ==
        "pacing:  is an option of the serial robots (" +
            declarers(devices::OptionUse::Emulate, "pace") + ")");
  CHECK(refused("stc-floor", [](devices::DeviceValues& v) {
          v.set("listen", std::string("127.0.0.1:0"));
        }).find("listen address: the stc-floor emulator serves a pty") == 0);
  CHECK(refused("khepera", [](devices::DeviceValues& v) { v.set("colour", std::string("red")); }) ==
        "colour: is an option of no device");
  // A number out of its declared range, before anything is served: the range named.
  CHECK(refused("stc-floor", [](devices::DeviceValues& v) {
          v.set("map", std::string("x.map"));
          v.set("noise", std::int64_t{256});
        }) == "camera noise: '256' is out of range: expected a whole number in [0, 255]");
  CHECK(refused("stc-floor", [](devices::DeviceValues& v) {
          v.set("map", std::string("x.map"));
          v.set("rotation-error", std::int64_t{-500001});
        }).find("[-500000, 500000]") != std::string::npos);
}

TEST_CASE("the registry: the command line's texts are read by the declarations, defaults applied",
          "[devices]") {
  const auto& floor = devices::device("stc-floor", "robot");
  const auto& khepera = devices::device("khepera", "robot");
  // Emulate: every declared default is applied when not given; a given value is kept.
  const auto v = devices::parse_device_options(
      floor, devices::OptionUse::Emulate,
      {{"map", {"floor.map"}}, {"start", {"3,4"}}, {"noise", {"20"}}});
  CHECK(v.text("map") == "floor.map");
  CHECK(v.cell("start") == antkit::kernel::Cell{3, 4});
  CHECK(v.integer("noise") == 20);
  CHECK(v.integer("dark-offset") == 12);
  CHECK(v.integer("heading") == 1);
  CHECK(v.integer("fade") == 0);
  CHECK(v.integer("rotation-error") == 0);
  CHECK(v.integer("drift") == 0);
  CHECK_FALSE(v.has("listen"));
  const auto k = devices::parse_device_options(khepera, devices::OptionUse::Emulate,
                                               {{"fault", {"drop=0.1", "cut=0.2"}}, {"pace", {}}});
  CHECK(k.text("arena") == "standard");
  CHECK(k.texts("fault") == std::vector<std::string>{"drop=0.1", "cut=0.2"});
  CHECK(k.on("pace"));
  // Record: a default the device works out itself (the period, the controller's heading) is only
  // said in --help, not applied: the device tells given from not given.
  const auto r = devices::resolve_options(khepera, devices::OptionUse::Record, {});
  CHECK(r.all().empty());
  CHECK(devices::resolve_options(floor, devices::OptionUse::Record, {}).all().empty());
  // Texts that do not read as the type, in the declaration's word; another device's option first.
  const auto error = [](const devices::Device& d, const devices::GivenTexts& given) {
    try {
      (void)devices::parse_device_options(d, devices::OptionUse::Emulate, given);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(error(floor, {{"noise", {"lots"}}}) == "camera noise: 'lots' is not a whole number in "
                                               "[0, 255]");
  CHECK(error(floor, {{"start", {"3;4"}}}).find("start sub-cell: ") == 0);
  CHECK(error(floor, {{"noise", {"lots"}}, {"fault", {"drop=1"}}}) ==
        "fault:  is an option of the serial robots (" +
            declarers(devices::OptionUse::Emulate, "fault") + ")");
}

TEST_CASE("the registry: --help of one device lists its own options from its declarations",
          "[devices]") {
  const auto& epuck2 = devices::device("epuck2", "robot");
  const std::string record = devices::device_options_help(epuck2, devices::OptionUse::Record);
  CHECK(record.find("epuck2's own options:\n  --arena SPEC\n") == 0);
  CHECK(record.find("  --period MS  (a whole number in [0, 60000]; default 0, as fast as the link "
                    "allows)\n      the shortest time") != std::string::npos);
  CHECK(record.find("--map") == std::string::npos);
  const std::string emulate = devices::device_options_help(epuck2, devices::OptionUse::Emulate);
  CHECK(emulate.find("  --fault F  (may be repeated)\n") != std::string::npos);
  CHECK(emulate.find("  --arena SPEC|F.wkt  (default standard)\n") != std::string::npos);
  CHECK(emulate.find("  --pace\n") != std::string::npos);
  const std::string hemisson = devices::device_options_help(devices::device("hemisson", "robot"),
                                                            devices::OptionUse::Record);
  CHECK(hemisson.find("default the motion model's period") != std::string::npos);
  const std::string floor = devices::device_options_help(devices::device("stc-floor", "robot"),
                                                         devices::OptionUse::Emulate);
  CHECK(floor.find("  --noise A  (a whole number in [0, 255]; default 0)\n") != std::string::npos);
  CHECK(floor.find("  --dark-offset A  (a whole number in [0, 255]; default 12)\n") !=
        std::string::npos);
  CHECK(floor.find("--arena") == std::string::npos);
  // A declared refusal, with its reason.
  CHECK(floor.find("Refused by stc-floor:\n  --listen: the stc-floor emulator serves a pty") !=
        std::string::npos);
  // Without a device: each device and the flags of its own options.
  const std::string all = devices::devices_options_help(devices::OptionUse::Record, "record");
  CHECK(all.find("`antkit record --device NAME --help`") != std::string::npos);
  CHECK(all.find("  epuck2:         --arena --period\n") != std::string::npos);
  CHECK(all.find("  stc-floor:      --map --start --calibration --heading --turn-ms --led-ms\n") !=
        std::string::npos);
}
