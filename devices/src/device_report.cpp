// A device's report as the JSON of its block (device_report.hpp).
#include <antkit/devices/device_report.hpp>
#include <antkit/kernel/hash.hpp>
#include <nlohmann/json.hpp>
#include <type_traits>

namespace antkit::devices {

namespace {

nlohmann::ordered_json cell_json(kernel::Cell c) {
  return nlohmann::ordered_json::array({c.x, c.y});
}

nlohmann::ordered_json fields_json(const ReportFields& fields);

nlohmann::ordered_json value_json(const ReportField::Value& value) {
  return std::visit(
      [](const auto& v) -> nlohmann::ordered_json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>)
          return nullptr;
        else if constexpr (std::is_same_v<T, kernel::Cell>)
          return cell_json(v);
        else if constexpr (std::is_same_v<T, std::vector<kernel::Cell>>) {
          nlohmann::ordered_json path = nlohmann::ordered_json::array();
          for (const auto& c : v) path.push_back(cell_json(c));
          return path;
        } else if constexpr (std::is_same_v<T, ReportHash>)
          return kernel::hash_hex(v.value);
        else if constexpr (std::is_same_v<T, ReportFields>)
          return fields_json(v);
        else
          return v;
      },
      value);
}

nlohmann::ordered_json fields_json(const ReportFields& fields) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& f : fields) j[f.name] = value_json(f.value);
  return j;
}

} // namespace

std::string report_json(const ReportFields& fields) {
  return fields_json(fields).dump();
}

} // namespace antkit::devices
