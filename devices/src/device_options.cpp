// The options one device takes and another does not (device.hpp, DeviceOption): their words, the
// one refusal of an option a device did not declare, and the listing --help shows.
#include <algorithm>
#include <antkit/devices/device.hpp>
#include <antkit/kernel/input_error.hpp>
#include <vector>

namespace antkit::devices {

namespace {

struct OptionFacts {
  std::string_view word;
  bool record, emulate;
};

constexpr OptionFacts facts(DeviceOption option) noexcept {
  switch (option) {
  case DeviceOption::FloorMap:
    return {"floor map", true, true};
  case DeviceOption::StartSubCell:
    return {"start sub-cell", true, true};
  case DeviceOption::ArenaSpec:
    return {"arena spec", true, true};
  case DeviceOption::ControlPeriod:
    return {"control period", true, false};
  case DeviceOption::CameraCalibration:
    return {"camera calibration", true, false};
  case DeviceOption::StartHeading:
    return {"start heading", false, true};
  case DeviceOption::CameraNoise:
    return {"camera noise", false, true};
  case DeviceOption::DarkOffset:
    return {"dark offset", false, true};
  case DeviceOption::FadeHalfLife:
    return {"fade half-life", false, true};
  case DeviceOption::RotationError:
    return {"rotation error", false, true};
  case DeviceOption::Drift:
    return {"drift", false, true};
  case DeviceOption::Fault:
    return {"fault", false, true};
  case DeviceOption::Pacing:
    return {"pacing", false, true};
  case DeviceOption::ListenAddress:
    return {"listen address", false, true};
  }
  return {"?", false, false};
}

// Whether the options hold `option` (the command line gave it).
bool given(DeviceOption option, const RecordOptions& o) noexcept {
  switch (option) {
  case DeviceOption::FloorMap:
    return !o.map.empty();
  case DeviceOption::StartSubCell:
    return o.start.has_value();
  case DeviceOption::ArenaSpec:
    return !o.arena.empty();
  case DeviceOption::ControlPeriod:
    return o.period.has_value();
  case DeviceOption::CameraCalibration:
    return !o.calibration.empty();
  default:
    return false; // not one of record()'s
  }
}

bool given(DeviceOption option, const EmulateOptions& o) noexcept {
  switch (option) {
  case DeviceOption::FloorMap:
    return o.map.has_value();
  case DeviceOption::StartSubCell:
    return o.start.has_value();
  case DeviceOption::ArenaSpec:
    return o.arena.has_value();
  case DeviceOption::StartHeading:
    return o.heading.has_value();
  case DeviceOption::CameraNoise:
    return o.noise.has_value();
  case DeviceOption::DarkOffset:
    return o.dark_offset.has_value();
  case DeviceOption::FadeHalfLife:
    return o.fade_s.has_value();
  case DeviceOption::RotationError:
    return o.rotation_error.has_value();
  case DeviceOption::Drift:
    return o.drift.has_value();
  case DeviceOption::Fault:
    return !o.faults.empty();
  case DeviceOption::Pacing:
    return o.pace;
  case DeviceOption::ListenAddress:
    return o.listen.has_value();
  default:
    return false; // not one of emulate()'s
  }
}

// The device's declaration of `option`, or null.
const DeclaredOption* declaration(const Device& device, DeviceOption option) noexcept {
  for (const DeclaredOption& d : device.options())
    if (d.option == option) return &d;
  return nullptr;
}

bool takes(const Device& device, DeviceOption option) noexcept {
  const DeclaredOption* d = declaration(device, option);
  return d != nullptr && d->refused.empty();
}

template <class Options>
void refuse(const Device& device, const Options& options) {
  for (const DeviceOption option : kDeviceOptions) {
    if (!given(option, options) || takes(device, option)) continue;
    const DeclaredOption* d = declaration(device, option);
    if (d != nullptr)
      throw kernel::InputError(std::string(option_word(option)), std::string(d->refused));
    std::vector<std::string_view> takers;
    for (const Device* other : all_devices())
      if (takes(*other, option)) takers.push_back(other->name());
    // The words the devices refused these options in before they were declared (issue 43).
    std::string whose = takers.size() == 1 ? "the " + std::string(takers[0]) + " robot"
                                           : "the serial robots (" + option_takers(option) + ")";
    throw kernel::InputError(std::string(option_word(option)), " is an option of " + whose);
  }
}

} // namespace

std::string_view option_word(DeviceOption option) noexcept {
  return facts(option).word;
}

bool option_of(DeviceOption option, OptionUse use) noexcept {
  return use == OptionUse::Record ? facts(option).record : facts(option).emulate;
}

std::string option_takers(DeviceOption option) {
  std::string out;
  for (const Device* d : all_devices()) {
    if (!takes(*d, option)) continue;
    if (!out.empty()) out += ", ";
    out += d->name();
  }
  return out;
}

void refuse_undeclared(const Device& device, const RecordOptions& options) {
  refuse(device, options);
}

void refuse_undeclared(const Device& device, const EmulateOptions& options) {
  refuse(device, options);
}

PreparedRun Device::prepare(const RecordOptions& options) const {
  refuse_undeclared(*this, options);
  return prepare_run(options);
}

EmulateReport Device::emulate(const EmulateOptions& options,
                              const std::function<void(const std::string& port)>& ready) const {
  refuse_undeclared(*this, options);
  return serve(options, ready);
}

std::string options_by_device(OptionUse use,
                              const std::map<std::string, std::string, std::less<>>& flags) {
  const auto flag = [&](std::string_view word) {
    const auto it = flags.find(word);
    return it == flags.end() ? std::string(word) : it->second;
  };
  // One paragraph per set of declarations (the serial robots share theirs), in registry order.
  struct Paragraph {
    std::string devices;
    std::vector<std::pair<std::string, std::string_view>> lines; // flag, what
  };
  std::vector<Paragraph> paragraphs;
  for (const Device* d : all_devices()) {
    Paragraph p;
    for (const DeclaredOption& o : d->options())
      if (o.refused.empty() && option_of(o.option, use))
        p.lines.emplace_back(flag(option_word(o.option)), o.what);
    if (p.lines.empty()) continue;
    std::size_t i = 0;
    while (i < paragraphs.size() && paragraphs[i].lines != p.lines) ++i;
    if (i == paragraphs.size()) paragraphs.push_back(std::move(p));
    if (!paragraphs[i].devices.empty()) paragraphs[i].devices += ", ";
    paragraphs[i].devices += d->name();
  }
  std::size_t width = 0;
  for (const auto& p : paragraphs)
    for (const auto& [f, what] : p.lines) width = std::max(width, f.size());
  std::string out = "The options of one device or another (the others refuse them):\n";
  for (const auto& p : paragraphs) {
    out += "  " + p.devices + ":\n";
    for (const auto& [f, what] : p.lines)
      out += "    " + f + std::string(width - f.size() + 2, ' ') + std::string(what) + "\n";
  }
  return out;
}

} // namespace antkit::devices
