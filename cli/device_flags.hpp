#pragma once
// The device options of `antkit record` and `antkit emulate`, as the devices declare them
// (devices/device_options.hpp): one flag per declared name, out of CLI11's own listing (each
// command's --help shows the chosen device's from the declarations, device_options_help()), and
// the texts given handed to the library as they were given (parse_device_options() reads and
// checks them against the chosen device's declarations).
#include "commands.hpp"

#include <antkit/devices/device.hpp>
#include <map>
#include <string>
#include <vector>

namespace antkit::cli {

struct DeviceFlags {
  struct Flag {
    devices::OptionType type = devices::OptionType::Text;
    std::string text;
    std::vector<std::string> texts;
    bool on = false;
    CLI::Option* option = nullptr;
  };
  std::map<std::string, Flag> by_name;
};

// Adds each device option of `use` that some device declares to `sub` (hidden: the footer lists
// them), and its word to the command's words (commands.hpp) so that the library's errors show it
// as its flag.
inline void add_device_flags(CLI::App& sub, DeviceFlags& flags, devices::OptionUse use,
                             FlagWords& words) {
  for (const devices::DeclaredOption& o : devices::declared_options(use)) {
    const std::string name(o.name), flag = "--" + name;
    DeviceFlags::Flag& f = flags.by_name[name];
    f.type = o.type;
    if (o.type == devices::OptionType::Switch)
      f.option = sub.add_flag(flag, f.on, std::string(o.what));
    else if (o.type == devices::OptionType::Texts)
      f.option = sub.add_option(flag, f.texts, std::string(o.what));
    else
      f.option = sub.add_option(flag, f.text, std::string(o.what));
    f.option->group("");
    words.emplace(std::string(o.word), flag);
  }
}

// The device options given, by name, with their texts.
inline devices::GivenTexts given_device_options(const DeviceFlags& flags) {
  devices::GivenTexts given;
  for (const auto& [name, f] : flags.by_name) {
    if (f.option->count() == 0) continue;
    if (f.type == devices::OptionType::Switch)
      given.emplace_back(name, std::vector<std::string>{});
    else if (f.type == devices::OptionType::Texts)
      given.emplace_back(name, f.texts);
    else
      given.emplace_back(name, std::vector<std::string>{f.text});
  }
  return given;
}

// The footer of `command`'s --help: the chosen device's options, or without one (or an unknown
// one) the devices and their flags.
inline std::string device_options_footer(const std::string& device, devices::OptionUse use,
                                         std::string_view command) {
  if (const devices::Device* d = devices::find_device(device))
    return devices::device_options_help(*d, use);
  return devices::devices_options_help(use, command);
}

} // namespace antkit::cli
