// The marker-floor robot's reports as the fields of their blocks (stc_floor/report.hpp).
#include <antkit/devices/stc_floor/report.hpp>
#include <antkit/maps/map_io.hpp>

namespace antkit::devices::stc_floor {

MapPlace read_map_place(const std::string& file) {
  maps::GridMap map = maps::load_map(file);
  return {std::move(map.cells), map.start, file};
}

ReportFields Tour::fields() const {
  ReportFields f;
  f.push_back({"start", start});
  f.push_back({"path", path});
  if (reachable_subcells) f.push_back({"reachable_subcells", *reachable_subcells});
  f.push_back({"covered", covered});
  f.push_back({"repeats", repeats});
  f.push_back({"returned_to_start", returned_to_start});
  f.push_back(
      {"hash", tour_hash ? ReportField::Value(ReportHash{*tour_hash}) : ReportField::Value()});
  f.push_back({"turn_ms", turn_ms});
  return f;
}

const Tour* tour_of(const RecordSummary& summary) noexcept {
  return dynamic_cast<const Tour*>(summary.device_report.get());
}

ReportFields FloorTruth::fields() const {
  return {{"map", map},
          {"start", start},
          {"frames", frames},
          {"positions", positions},
          {"covered", covered},
          {"repeats", repeats},
          {"reachable_subcells", reachable_subcells},
          {"max_offset_subcells", max_offset_subcells},
          {"max_heading_error_degrees", max_heading_error_degrees},
          {"clock_s", clock_s}};
}

} // namespace antkit::devices::stc_floor
