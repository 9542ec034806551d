// A failure as text (serialize, deserialize) and a campaign's output directory: summary.json and a
// map (or arena) per failure.
#include <antkit/campaign/campaign.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <nlohmann/json.hpp>

namespace antkit::campaign {

using kernel::InputError;
using kernel::OccupancyGrid;

std::string serialize(const Failure& f) {
  nlohmann::json j;
  j["case"] = f.case_index;
  j["variant"] = f.variant;
  j["rule"] = f.rule;
  j["width"] = f.map.width();
  j["height"] = f.map.height();
  std::string cells(f.map.size(), '.');
  for (std::size_t i = 0; i < f.map.size(); ++i)
    cells[i] = f.map.cells()[i] == kernel::Occupancy::Free      ? '.'
               : f.map.cells()[i] == kernel::Occupancy::Blocked ? '@'
                                                                : '?';
  j["cells"] = std::move(cells);
  j["start"] = {f.start.x, f.start.y};
  j["command"] = f.command;
  j["shrink_steps"] = f.shrink_steps;
  j["arena"] = f.arena_wkt;
  return j.dump();
}

Failure deserialize(std::string_view text) {
  const auto j = nlohmann::json::parse(text);
  Failure f;
  f.case_index = j.at("case").get<std::uint64_t>();
  f.variant = j.at("variant").get<std::string>();
  f.rule = j.at("rule").get<std::string>();
  f.map = OccupancyGrid(j.at("width").get<std::int32_t>(), j.at("height").get<std::int32_t>(),
                        kernel::Occupancy::Free);
  const auto cells = j.at("cells").get<std::string>();
  for (std::size_t i = 0; i < f.map.size() && i < cells.size(); ++i)
    f.map.cells()[i] = cells[i] == '.'   ? kernel::Occupancy::Free
                       : cells[i] == '@' ? kernel::Occupancy::Blocked
                                         : kernel::Occupancy::Unknown;
  f.start = {j.at("start").at(0).get<std::int32_t>(), j.at("start").at(1).get<std::int32_t>()};
  f.command = j.at("command").get<std::string>();
  f.shrink_steps = j.at("shrink_steps").get<std::uint64_t>();
  f.arena_wkt = j.at("arena").get<std::string>();
  return f;
}

std::string write_outputs(const Options& o, const Result& r, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(dir.string(), "cannot create the output directory");
  nlohmann::json j;
  j["family"] = std::string(family_name(o.family));
  j["seed"] = o.seed;
  j["first_case"] = o.first;
  j["cases_requested"] = o.cases;
  j["cases_run"] = r.cases_run;
  j["stopped_by_time"] = r.stopped_by_time;
  j["max_size"] = std::to_string(o.max_width) + "x" + std::to_string(o.max_height);
  j["variants"] = o.variants.empty() ? family_variants(o.family) : o.variants;
  j["moves_checked"] = r.moves;
  j["vacuous_cases"] = r.vacuous;
  if (!o.extra_rule_name.empty()) j["planted_rule"] = o.extra_rule_name;
  nlohmann::json failures = nlohmann::json::array();
  for (const auto& f : r.failures) {
    const bool arena = !f.arena_wkt.empty();
    const std::string name = "case-" + std::to_string(f.case_index) + (arena ? ".wkt" : ".map");
    if (arena) {
      io::write_file_atomic(dir / name, f.arena_wkt + "\n");
    } else {
      maps::GridMap m;
      m.cells = f.map;
      maps::save_map(dir / name, m);
    }
    std::string command = f.command;
    command.replace(command.find("{MAP}"), 5, name);
    failures.push_back({{"case", f.case_index},
                        {"variant", f.variant},
                        {"rule", f.rule},
                        {"map", name},
                        {"width", f.map.width()},
                        {"height", f.map.height()},
                        {"start", {f.start.x, f.start.y}},
                        {"command", command},
                        {"shrink_steps", f.shrink_steps}});
  }
  j["failures"] = std::move(failures);
  const std::string text = j.dump(2) + "\n";
  io::write_file_atomic(dir / "summary.json", text);
  return text;
}

} // namespace antkit::campaign
