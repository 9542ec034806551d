// The JSON of `antkit check stc|explore|cover` (json.hpp).
#include <antkit/commands/json.hpp>
#include <antkit/los/cell_state.hpp>

namespace antkit::commands {

nlohmann::json cell_json(kernel::Cell c) {
  return nlohmann::json::array({c.x, c.y});
}

namespace {
// The keys every check's report starts with; the map's name null when it has none.
nlohmann::json check_head(const char* check, bool ok, const std::string& map) {
  nlohmann::json j;
  j["check"] = check;
  j["ok"] = ok;
  j["map"] = map.empty() ? nlohmann::json(nullptr) : nlohmann::json(map);
  return j;
}
} // namespace

nlohmann::json first_violation_json(const testing::StcAudit& a) {
  if (a.ok()) return nullptr;
  return {{"rule", a.first.rule},
          {"step", a.first.step < 0 ? nlohmann::json(nullptr) : nlohmann::json(a.first.step)},
          {"subcell", cell_json(a.first.subcell)},
          {"detail", a.first.detail}};
}

nlohmann::json check_stc_json(const testing::StcCheckReport& r, const std::string& map) {
  const testing::StcAudit& a = r.audit;
  nlohmann::json j = check_head("stc", a.ok(), map);
  j["rule"] = std::string(testing::tour_rule_name(a.rule));
  j["width"] = r.width;
  j["height"] = r.height;
  j["start"] = cell_json(r.start);
  j["start_from"] = r.start_from;
  j["order"] = std::string(testing::tour_order_name(r.order));
  j["order_from"] = r.order_from_header ? "header" : "--order";
  j["cells"] = r.cells;
  j["start_cell"] = r.start_cell ? cell_json(*r.start_cell) : nlohmann::json(nullptr);
  j["positions"] = a.positions;
  j["closed_form"] = a.closed_form;
  j["reachable_subcells"] = a.reachable;
  j["covered"] = a.covered;
  j["missed"] = a.missed;
  j["repeats"] = a.repeats;
  j["illegal_moves"] = a.illegal_moves;
  j["off_limits"] = a.off_limits;
  j["end_distance"] = a.end_distance;
  nlohmann::json missed = nlohmann::json::array();
  for (const auto s : a.missed_sample) missed.push_back(cell_json(s));
  j["missed_sample"] = std::move(missed);
  j["first_violation"] = first_violation_json(a);
  return j;
}

nlohmann::json check_explore_json(const testing::ExploreCheckReport& r, const std::string& map) {
  const auto& a = r.audit;
  nlohmann::json j = check_head("explore", a.ok(), map);
  j["width"] = r.width;
  j["height"] = r.height;
  nlohmann::json states;
  for (const auto s : {los::CellState::F, los::CellState::S, los::CellState::LOS,
                       los::CellState::S_LOS, los::CellState::NLOS, los::CellState::O})
    states[std::string(1, los::code(s))] = a.by_state[static_cast<std::size_t>(s)];
  j["states"] = std::move(states);
  j["free_cells"] = a.free_cells;
  j["known_free"] = a.known_free;
  j["known_free_not_free"] = a.known_free_not_free;
  j["obstacle_but_free"] = a.obstacle_but_free;
  j["first_violation"] = a.ok() ? nlohmann::json(nullptr) : nlohmann::json(a.first);
  return j;
}

nlohmann::json check_cover_json(const testing::CoverCheckReport& r, const std::string& map) {
  const auto& a = r.audit;
  nlohmann::json j = check_head("cover", a.ok(), map);
  j["sensor"] = r.sensor;
  j["sensor_from"] = r.sensor_from;
  j["ticks"] = a.ticks;
  j["robots"] = a.robots;
  j["moves"] = a.moves;
  j["turns"] = a.turns;
  j["illegal_moves"] = a.illegal_moves;
  j["bad_turns"] = a.bad_turns;
  j["collisions"] = a.collisions;
  j["viewed"] = a.viewed;
  j["viewable"] = a.viewable;
  j["coverage"] = a.viewable == 0
                      ? 0.0
                      : 100.0 * static_cast<double>(a.viewed) / static_cast<double>(a.viewable);
  j["claim_viewed"] = r.claim_viewed ? nlohmann::json(*r.claim_viewed) : nlohmann::json(nullptr);
  j["claim_viewable"] =
      r.claim_viewable ? nlohmann::json(*r.claim_viewable) : nlohmann::json(nullptr);
  j["claims_match"] = a.claims_match;
  j["first_violation"] = a.ok() ? nlohmann::json(nullptr) : nlohmann::json(a.first);
  return j;
}

} // namespace antkit::commands
