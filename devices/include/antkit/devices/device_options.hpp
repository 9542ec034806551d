#pragma once
// The options one device takes and another does not (issue 43, "each device declares its
// options"): a device declares each of its own (name, type, range, default, help; Device::options()
// in device.hpp), and the values given travel to it in one typed bag, DeviceValues, keyed by the
// declared name. `antkit record` and `antkit emulate` build their device flags and their --help
// from the declarations (the name is the flag without its dashes: "noise" is --noise), and the
// values are checked against them in one place (device.hpp: parse_device_options(),
// resolve_options()): a name the device did not declare is refused, a number out of its range is
// refused naming the range, and a declared default is applied when the option is not given.
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace antkit::devices {

// What an option holds.
enum class OptionType : std::uint8_t {
  Switch,  // given or not, no value (--pace)
  Integer, // a whole number in [min, max]
  Text,    // one word: a spec, a file, an address
  SubCell, // X,Y
  Texts,   // a word that may be given again and again (--fault)
};

// The command an option belongs to.
enum class OptionUse : std::uint8_t { Record, Emulate };

// A device's declaration of one of its options for one command. Refused options: a name another
// device takes that this one declares but does not take, with the reason (`refused` not empty: the
// marker-floor emulator's --listen).
struct DeclaredOption {
  std::string_view name; // the flag without its dashes ("dark-offset")
  std::string_view word; // the library's word for it, as kernel::InputError names it
  OptionUse use = OptionUse::Record;
  OptionType type = OptionType::Text;
  std::int64_t min = 0, max = 0; // Integer: the range, both ends allowed
  // The default, written as on the command line and applied when the option is not given ("":
  // none applied; then `default_note`, if any, says in --help what the device does instead).
  std::string_view fallback = {};
  std::string_view default_note = {};
  std::string_view label = {}; // the value's name in --help ("FILE"; "": from the type)
  std::string_view what = {};  // what it is for this device, for --help
  std::string_view refused = {};
};

// A value as its declaration types it: Switch bool, Integer std::int64_t, Text std::string,
// SubCell kernel::Cell, Texts std::vector<std::string>.
using OptionValue =
    std::variant<bool, std::int64_t, std::string, kernel::Cell, std::vector<std::string>>;

// A value of option `o` from the texts the command line gave it (none for a Switch, one per time
// given for Texts, one otherwise): kernel::InputError(o.word, ...) when they do not read as its
// type. Its range is resolve_options()'s to check (device.hpp).
[[nodiscard]] OptionValue parse_option_value(const DeclaredOption& o,
                                             const std::vector<std::string>& texts);

// The values of a device's own options, keyed by declared name; what the device reads instead of
// fields of a struct every device shares. Reading a name as another type than it holds is a
// programming error (std::logic_error).
class DeviceValues {
public:
  void set(std::string name, OptionValue value) { values_[std::move(name)] = std::move(value); }
  void erase(std::string_view name);
  [[nodiscard]] bool has(std::string_view name) const noexcept;
  [[nodiscard]] std::optional<std::int64_t> integer(std::string_view name) const;
  [[nodiscard]] std::optional<std::string> text(std::string_view name) const;
  [[nodiscard]] std::optional<kernel::Cell> cell(std::string_view name) const;
  [[nodiscard]] std::vector<std::string> texts(std::string_view name) const; // none: empty
  [[nodiscard]] bool on(std::string_view name) const;                        // a Switch
  [[nodiscard]] const std::map<std::string, OptionValue, std::less<>>& all() const noexcept {
    return values_;
  }
  bool operator==(const DeviceValues&) const = default;

private:
  std::map<std::string, OptionValue, std::less<>> values_;
};

} // namespace antkit::devices
