#pragma once
// Oracles for the outputs of exploration and coverage runs, antkit's or anyone's (issue 18,
// `antkit check explore` and `antkit check cover`). Like stc_audit.hpp: read a file, hold it
// against the true map by our own computation, count every violation beside the first.
#include <antkit/kernel/grid.hpp>
#include <antkit/los/cell_state.hpp>
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::testing {

// ---- LOS exploration: are the cell states sound against the true map? -------------------------
// Sound (paper 001's model, los/cell_state.hpp): S, LOS and S+LOS cells are free in the true map;
// O cells are not free (blocked or unknown). F (unexplored) and NLOS say nothing.
struct LosCellsAudit {
  std::string first;                      // the first unsound cell, row-major; empty when sound
  std::array<std::int64_t, 6> by_state{}; // cells in state F, S, LOS, S+LOS, NLOS, O
  std::int64_t free_cells = 0;            // free in the true map
  std::int64_t known_free = 0;            // S, LOS or S+LOS (all free when sound)
  std::int64_t known_free_not_free = 0;   // S, LOS or S+LOS on a cell that is not free
  std::int64_t obstacle_but_free = 0;     // O on a free cell

  [[nodiscard]] bool ok() const noexcept { return first.empty(); }
};

[[nodiscard]] LosCellsAudit audit_los_cells(const kernel::OccupancyGrid& truth,
                                            const kernel::Grid<los::CellState>& states);

// Reads cell states, one row per line or string, one letter per cell (F S L B N O; B for S+LOS,
// los::code): a JSON object with "cells" (an array of row strings, as `antkit explore --format
// json` prints it), a JSON array of row strings, or plain text rows (blank lines ignored). Rows
// must be equally long. Errors are kernel::InputError: "SOURCE:LINE:COL" in text,
// "SOURCE: cells[i]" in JSON.
[[nodiscard]] kernel::Grid<los::CellState> read_los_cells(std::string_view text,
                                                          const std::string& source);

struct ExploreCheckReport {
  LosCellsAudit audit;
  std::int32_t width = 0, height = 0;
};

// `antkit check explore`: the map and the states must have the same size (bad input otherwise).
[[nodiscard]] ExploreCheckReport check_explore_files(const std::string& map_file,
                                                     const std::string& cells_file);
// The same on a map and states in memory; `cells_source` names the states in messages.
[[nodiscard]] ExploreCheckReport check_explore(const kernel::OccupancyGrid& map,
                                               const kernel::Grid<los::CellState>& states,
                                               const std::string& cells_source);

// ---- Uniform coverage: is the run legal, and does it cover what it claims? ----------------------
// A trace is every robot's pose after every tick, tick 0 the start (`antkit cover --trace`):
//
//   # sensor: 5                      (comment lines start with '#'; these two keys are read)
//   tick,robot,x,y,bearing           (optional header)
//   0,0,3,4,2
//   ...
//   # claim viewed: 812              (optional: what the run reported)
//   # claim viewable: 900
//
// Ticks count up from 0 without a gap; each tick lists robots 0..n-1 in order, n the same in every
// tick; bearings are 0..7 (0 east, counter-clockwise in 45-degree steps as drawn with y down:
// kernel::kNeighbours8).
struct CoverTrace {
  std::int32_t robots = 0;
  std::vector<std::vector<kernel::Cell>> cells; // [tick][robot]
  std::vector<std::vector<std::uint8_t>> bearings;
  std::optional<std::int32_t> sensor;
  std::optional<std::uint64_t> claim_viewed, claim_viewable;
};

[[nodiscard]] CoverTrace read_cover_trace(std::string_view text, const std::string& source);

// The rules (paper 004's movement model, uniform/world.hpp), between consecutive ticks for each
// robot: it stays (and turns its bearing by at most one eighth) or moves to one of its eight
// neighbours, a Free cell, without cutting a corner (a diagonal move needs both side cells Free),
// and then faces the way it moved; at the end of every tick robots stand on distinct Free cells.
// Coverage is recomputed: a robot views every cell within Euclidean distance `sensor` in line of
// sight (kernel::line_of_sight, brute force) from every cell it stands on; viewed counts the Free
// cells viewed, viewable the Free cells of the 4-connected components the robots start in.
struct CoverAudit {
  std::string first; // the first broken rule, with the tick, robot and cell; empty when none
  std::int64_t first_tick = -1; // its tick; -1 when none, or when it is about the whole run
  std::int64_t ticks = 0, robots = 0;
  std::int64_t moves = 0, turns = 0; // between ticks: cell changes, bearing-only changes
  std::int64_t illegal_moves = 0;    // not a neighbour, onto a cell not Free, a cut corner
  std::int64_t bad_turns = 0;        // a bearing changed by more than one eighth, or not the
                                     // way a robot moved
  std::int64_t collisions = 0;       // two robots on one cell at the end of a tick
  std::uint64_t viewed = 0, viewable = 0;
  bool claims_match = true; // every claim in the trace equals the recomputed figure

  [[nodiscard]] bool ok() const noexcept { return first.empty(); }
};

[[nodiscard]] CoverAudit audit_cover_trace(const kernel::OccupancyGrid& map,
                                           const CoverTrace& trace, std::int32_t sensor);

struct CoverCheckReport {
  CoverAudit audit;
  std::int32_t sensor = 0;
  std::string sensor_from; // "--sensor" or "trace"
  std::optional<std::uint64_t> claim_viewed, claim_viewable;
};

// `antkit check cover`: the sensor range is `sensor` when given (an InputError "sensor distance"
// outside [0, uniform::kMaxSensorRange]), else the trace's "# sensor:".
[[nodiscard]] CoverCheckReport check_cover_files(const std::string& map_file,
                                                 const std::string& trace_file,
                                                 std::optional<std::int64_t> sensor);
// The same on a map and a trace in memory; `trace_source` names the trace in messages.
[[nodiscard]] CoverCheckReport check_cover(const kernel::OccupancyGrid& map,
                                           const CoverTrace& trace,
                                           std::optional<std::int64_t> sensor,
                                           const std::string& trace_source);
// An InputError "sensor distance" for a range outside [0, uniform::kMaxSensorRange].
void check_sensor_range(std::optional<std::int64_t> sensor);

// Reads a whole text file (at most `max_bytes`); one that cannot be read is an InputError naming
// it, `what` saying what it should have been ("tour", "trace", ...).
[[nodiscard]] std::string read_text_file(const std::filesystem::path& path, const char* what,
                                         std::size_t max_bytes);

} // namespace antkit::testing
