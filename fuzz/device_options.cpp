// Fuzz target: the devices' option parsers: `antkit emulate --fault` (parse_faults), the
// controller spec of `antkit record` and of a log header (make_spec), and a device's preparation
// of a run (Device::prepare, every device of the registry). Each input line is one --fault value,
// or with a leading '@', a controller name and KEY=VALUE parameters separated by spaces, or with a
// leading '#', a device name, then the same. Bad input must be an InputError; an accepted fault
// spec must hold probabilities in [0, 1e6] ppm; an accepted controller spec must be canonical
// (make_spec of itself is itself) and build a controller; an accepted run must name its device in
// its header and have a way to connect, and preparing it twice must give the same header.
#include <antkit/devices/controllers.hpp>
#include <antkit/devices/device.hpp>
#include <antkit/devices/emulator.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  for (const char c : text + " ") {
    if (c == ' ') {
      if (!word.empty()) words.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  return words;
}

// KEY=VALUE words from `from` on, with small non-negative values; false for anything else.
bool params_of(const std::vector<std::string>& words, std::size_t from,
               antkit::devices::Params& params) {
  for (std::size_t i = from; i < words.size(); ++i) {
    const auto eq = words[i].find('=');
    if (eq == std::string::npos) return false;
    std::int64_t v = 0;
    for (const char c : words[i].substr(eq + 1)) {
      if (c < '0' || c > '9' || v > 100000000000000000) return false;
      v = v * 10 + (c - '0');
    }
    params.emplace_back(words[i].substr(0, eq), v);
  }
  return true;
}

// "#DEVICE CONTROLLER KEY=VALUE ...": a run prepared on the device (no port is opened).
void device_line(const std::string& line) {
  const auto words = split(line.substr(1));
  if (words.size() < 2) return;
  antkit::devices::RecordOptions o;
  o.device = words[0];
  o.controller.name = words[1];
  if (!params_of(words, 2, o.controller.params)) return;
  o.device_options.set(
      "start", antkit::kernel::Cell{0, 0}); // the marker-floor robot needs one without a map
  o.port = "/nonexistent/port";
  o.out = "/nonexistent/log.jsonl";
  try {
    const auto& device = antkit::devices::device(o.device, "--device");
    const auto run = device.prepare(o);
    if (run.header.robot != device.name() || !run.connect || run.steps <= 0) __builtin_trap();
    if (device.prepare(o).header != run.header) __builtin_trap();
  } catch (const antkit::kernel::InputError&) {
  }
}

void controller_line(const std::string& line) {
  const auto words = split(line.substr(1));
  if (words.empty()) return;
  antkit::devices::Params params;
  if (!params_of(words, 1, params)) return;
  try {
    const auto spec = antkit::devices::make_spec(words[0], 1, params, "--controller");
    const auto again = antkit::devices::make_spec(spec.name, spec.seed, spec.params, "x");
    if (again.params != spec.params) __builtin_trap();
    if (!antkit::devices::make_controller(spec)) __builtin_trap();
  } catch (const antkit::kernel::InputError&) {
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> faults;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto end = text.find('\n', start);
    const std::string line =
        text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!line.empty() && line[0] == '@')
      controller_line(line);
    else if (!line.empty() && line[0] == '#')
      device_line(line);
    else
      faults.push_back(line);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  try {
    const auto f = antkit::devices::parse_faults(faults);
    for (const auto ppm : {f.delay_ppm, f.garbage_ppm, f.drop_ppm, f.cut_ppm})
      if (ppm > 1000000) __builtin_trap();
    if (f.delay.count() < 0 || f.delay.count() > 60000) __builtin_trap();
  } catch (const antkit::kernel::InputError&) {
  }
  return 0;
}
