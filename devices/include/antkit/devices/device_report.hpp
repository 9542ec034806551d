#pragma once
// What a device reports beyond what every device has (device.hpp): of a recorded run
// (Session::report, RecordSummary::device_report: the marker-floor robot's tour) and of an
// emulator's sessions (EmulateReport::device_report: the marker-floor robot's floor truth).
//
// The shared loops only carry it. A command prints it as one block under the device's own key
// (`antkit record`'s "tour", `antkit emulate`'s "floor"), from the typed fields the report lists,
// without naming the device: report_json() writes them. A report also names the verdict it needs
// from the layers above the devices (verdict(): the marker-floor tour's "stc-tour", the oracle of
// `antkit check stc`), which those layers give by that name (experiments/recorded_run.hpp); the
// devices do not include the checkers (DESIGN.md, the layers). The device's own header says what
// its report holds as a type (stc_floor/report.hpp).
//
// No JSON in this header: the devices link nlohmann_json privately.
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace antkit::devices {

// A hash, printed as kernel::hash_hex's 16 hex digits.
struct ReportHash {
  std::uint64_t value = 0;
  friend bool operator==(const ReportHash&, const ReportHash&) = default;
};

// One field of a report's block: its key and its value. std::monostate is null; a Cell is [x, y];
// a path is [[x, y], ...]; fields are an object of their own (in their order).
struct ReportField {
  using Value = std::variant<std::monostate, bool, std::int64_t, double, std::string, kernel::Cell,
                             std::vector<kernel::Cell>, ReportHash, std::vector<ReportField>>;
  std::string name;
  Value value;
};
using ReportFields = std::vector<ReportField>;

class DeviceReport {
public:
  virtual ~DeviceReport() = default;
  // The key of the block in a command's summary ("tour", "floor").
  [[nodiscard]] virtual std::string_view key() const noexcept = 0;
  // The block's fields, in order; their keys are unique.
  [[nodiscard]] virtual ReportFields fields() const = 0;
  // The verdict the run needs from the layers above ("": none; the marker-floor tour: "stc-tour").
  [[nodiscard]] virtual std::string_view verdict() const noexcept { return {}; }
};

// The fields as one JSON object's text (compact), in their order: what a command puts under the
// report's key.
[[nodiscard]] std::string report_json(const ReportFields& fields);

} // namespace antkit::devices
