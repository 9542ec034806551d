// The options one device takes and another does not (device_options.hpp): the typed bag, the one
// place their values are checked against the declarations, and the --help listings.
#include <algorithm>
#include <antkit/algorithms/options.hpp>
#include <antkit/devices/device.hpp>
#include <antkit/kernel/input_error.hpp>
#include <stdexcept>
#include <vector>

namespace antkit::devices {

namespace {

const OptionValue* find_value(const std::map<std::string, OptionValue, std::less<>>& values,
                              std::string_view name) {
  const auto it = values.find(name);
  return it == values.end() ? nullptr : &it->second;
}

template <class T>
std::optional<T> typed(const std::map<std::string, OptionValue, std::less<>>& values,
                       std::string_view name) {
  const OptionValue* v = find_value(values, name);
  if (v == nullptr) return std::nullopt;
  if (const T* t = std::get_if<T>(v)) return *t;
  throw std::logic_error("device option '" + std::string(name) + "' read as another type");
}

// Whether a value is of the type its declaration says.
bool of_type(const OptionValue& v, OptionType type) noexcept {
  switch (type) {
  case OptionType::Switch:
    return std::holds_alternative<bool>(v);
  case OptionType::Integer:
    return std::holds_alternative<std::int64_t>(v);
  case OptionType::Text:
    return std::holds_alternative<std::string>(v);
  case OptionType::SubCell:
    return std::holds_alternative<kernel::Cell>(v);
  case OptionType::Texts:
    return std::holds_alternative<std::vector<std::string>>(v);
  }
  return false;
}

std::string range_words(const DeclaredOption& o) {
  return "a whole number in [" + std::to_string(o.min) + ", " + std::to_string(o.max) + "]";
}

bool takes(const Device& device, OptionUse use, std::string_view name) noexcept {
  const DeclaredOption* d = declared(device, use, name);
  return d != nullptr && d->refused.empty();
}

// Some device's declaration of `name` for `use` (the first, in registry order), or null.
const DeclaredOption* any_declaration(OptionUse use, std::string_view name) noexcept {
  for (const Device* d : all_devices())
    if (const DeclaredOption* o = declared(*d, use, name)) return o;
  return nullptr;
}

// The refusal of option `name`, given to `device`, which does not take it.
[[noreturn]] void refuse(const Device& device, OptionUse use, std::string_view name) {
  if (const DeclaredOption* d = declared(device, use, name))
    throw kernel::InputError(std::string(d->word), std::string(d->refused));
  std::vector<std::string_view> takers;
  for (const Device* other : all_devices())
    if (takes(*other, use, name)) takers.push_back(other->name());
  const DeclaredOption* some = any_declaration(use, name);
  if (takers.empty() || some == nullptr)
    throw kernel::InputError(std::string(name), "is an option of no device");
  // The words the devices refused these options in before they were declared (issue 43).
  const std::string whose = takers.size() == 1
                                ? "the " + std::string(takers[0]) + " robot"
                                : "the serial robots (" + option_takers(use, name) + ")";
  throw kernel::InputError(std::string(some->word), " is an option of " + whose);
}

// The declared default, parsed as a value given would be.
OptionValue fallback_value(const DeclaredOption& o) {
  if (o.type == OptionType::Texts) return std::vector<std::string>{std::string(o.fallback)};
  return parse_option_value(o, {std::string(o.fallback)});
}

std::string_view type_label(const DeclaredOption& o) noexcept {
  if (!o.label.empty()) return o.label;
  switch (o.type) {
  case OptionType::Switch:
    return "";
  case OptionType::Integer:
    return "N";
  case OptionType::Text:
  case OptionType::Texts:
    return "TEXT";
  case OptionType::SubCell:
    return "X,Y";
  }
  return "";
}

} // namespace

OptionValue parse_option_value(const DeclaredOption& o, const std::vector<std::string>& texts) {
  const std::string where(o.word);
  if (o.type == OptionType::Switch) return true;
  if (o.type == OptionType::Texts) return texts;
  if (texts.size() != 1)
    throw kernel::InputError(where, "expected one value, not " + std::to_string(texts.size()));
  const std::string& text = texts.front();
  switch (o.type) {
  case OptionType::Integer:
    return algorithms::parse_integer(where, text, range_words(o));
  case OptionType::SubCell:
    return algorithms::parse_cell(where, text);
  default:
    return text;
  }
}

void DeviceValues::erase(std::string_view name) {
  const auto it = values_.find(name);
  if (it != values_.end()) values_.erase(it);
}

bool DeviceValues::has(std::string_view name) const noexcept {
  return values_.find(name) != values_.end();
}

std::optional<std::int64_t> DeviceValues::integer(std::string_view name) const {
  return typed<std::int64_t>(values_, name);
}

std::optional<std::string> DeviceValues::text(std::string_view name) const {
  return typed<std::string>(values_, name);
}

std::optional<kernel::Cell> DeviceValues::cell(std::string_view name) const {
  return typed<kernel::Cell>(values_, name);
}

std::vector<std::string> DeviceValues::texts(std::string_view name) const {
  return typed<std::vector<std::string>>(values_, name).value_or(std::vector<std::string>{});
}

bool DeviceValues::on(std::string_view name) const {
  return typed<bool>(values_, name).value_or(false);
}

const DeclaredOption* declared(const Device& device, OptionUse use,
                               std::string_view name) noexcept {
  for (const DeclaredOption& d : device.options())
    if (d.use == use && d.name == name) return &d;
  return nullptr;
}

DeviceValues resolve_options(const Device& device, OptionUse use, const DeviceValues& given) {
  DeviceValues out;
  for (const auto& [name, value] : given.all()) {
    if (!takes(device, use, name)) refuse(device, use, name);
    const DeclaredOption& o = *declared(device, use, name);
    if (!of_type(value, o.type))
      throw kernel::InputError(std::string(o.word), "a value of another type than declared");
    if (o.type == OptionType::Integer) {
      const std::int64_t v = std::get<std::int64_t>(value);
      if (v < o.min || v > o.max)
        throw kernel::InputError(std::string(o.word), "'" + std::to_string(v) +
                                                          "' is out of range: expected " +
                                                          range_words(o));
    }
    out.set(name, value);
  }
  for (const DeclaredOption& o : device.options())
    if (o.use == use && o.refused.empty() && !o.fallback.empty() && !out.has(o.name))
      out.set(std::string(o.name), fallback_value(o));
  return out;
}

DeviceValues parse_device_options(const Device& device, OptionUse use, const GivenTexts& given) {
  // Every option refused first: the device's word for what is wrong is about the option, not its
  // value.
  for (const auto& [name, texts] : given)
    if (!takes(device, use, name)) refuse(device, use, name);
  DeviceValues values;
  for (const auto& [name, texts] : given)
    values.set(name, parse_option_value(*declared(device, use, name), texts));
  return resolve_options(device, use, values);
}

std::vector<DeclaredOption> declared_options(OptionUse use) {
  std::vector<DeclaredOption> out;
  for (const Device* d : all_devices())
    for (const DeclaredOption& o : d->options())
      if (o.use == use && std::none_of(out.begin(), out.end(),
                                       [&](const DeclaredOption& x) { return x.name == o.name; }))
        out.push_back(o);
  return out;
}

std::string option_takers(OptionUse use, std::string_view name) {
  std::string out;
  for (const Device* d : all_devices()) {
    if (!takes(*d, use, name)) continue;
    if (!out.empty()) out += ", ";
    out += d->name();
  }
  return out;
}

PreparedRun Device::prepare(const RecordOptions& options) const {
  RecordOptions resolved = options;
  resolved.device_options = resolve_options(*this, OptionUse::Record, options.device_options);
  return prepare_run(resolved);
}

EmulateReport Device::emulate(const EmulateOptions& options,
                              const std::function<void(const std::string& port)>& ready) const {
  EmulateOptions resolved = options;
  resolved.device_options = resolve_options(*this, OptionUse::Emulate, options.device_options);
  return serve(resolved, ready);
}

std::string device_options_help(const Device& device, OptionUse use) {
  std::string out, refused;
  for (const DeclaredOption& o : device.options()) {
    if (o.use != use) continue;
    const std::string flag = "--" + std::string(o.name);
    if (!o.refused.empty()) {
      refused += "  " + flag + ": " + std::string(o.refused) + "\n";
      continue;
    }
    std::string head = "  " + flag;
    if (const auto label = type_label(o); !label.empty()) head += " " + std::string(label);
    std::vector<std::string> facts;
    if (o.type == OptionType::Integer) facts.push_back(range_words(o));
    if (o.type == OptionType::Texts) facts.emplace_back("may be repeated");
    if (!o.fallback.empty())
      facts.push_back("default " + std::string(o.fallback));
    else if (!o.default_note.empty())
      facts.push_back("default " + std::string(o.default_note));
    for (std::size_t i = 0; i < facts.size(); ++i)
      head += (i == 0 ? "  (" : "; ") + facts[i] + (i + 1 == facts.size() ? ")" : "");
    out += head + "\n      " + std::string(o.what) + "\n";
  }
  const std::string who(device.name());
  std::string text =
      out.empty() ? who + " takes no options of its own here.\n" : who + "'s own options:\n" + out;
  if (!refused.empty()) text += "Refused by " + who + ":\n" + refused;
  return text;
}

std::string devices_options_help(OptionUse use, std::string_view command) {
  std::string out = "Each device's own options (the others refuse them; `antkit " +
                    std::string(command) + (use == OptionUse::Record ? " --device NAME" : " NAME") +
                    " --help`\nlists one device's with their values, ranges and defaults):\n";
  std::size_t width = 0;
  for (const Device* d : all_devices()) width = std::max(width, d->name().size());
  for (const Device* d : all_devices()) {
    std::string flags;
    for (const DeclaredOption& o : d->options())
      if (o.use == use && o.refused.empty()) flags += " --" + std::string(o.name);
    out += "  " + std::string(d->name()) + ":" + std::string(width - d->name().size(), ' ') +
           (flags.empty() ? " (none)" : flags) + "\n";
  }
  return out;
}

} // namespace antkit::devices
