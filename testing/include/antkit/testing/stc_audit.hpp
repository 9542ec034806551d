#pragma once
// An oracle for any coverage planner's tour on a grid map (issue 18, `antkit check stc`): the tour
// is read from a file (JSON or CSV), held against the map by our own search, and every violation
// is counted, not only the first.
//
// Two rules:
//   * ExactlyOnce (what STC promises): the tour starts at the start sub-cell, enters every sub-cell
//     of every free cell (2 x 2 free sub-cells) 4-connected to the start's cell exactly once,
//     moves between 4-adjacent sub-cells of such cells, and ends next to the start (its last
//     sub-cell 4-adjacent to the start, so that one more move closes it) - StcTourChecker's
//     check_exact, invariants 1-4.
//   * Coverage (Full-STC, boustrophedon, any planner that does not promise exactly once): every
//     free sub-cell of the cell area 4-connected to the start sub-cell at least once, repeats
//     counted, moves between 4-adjacent free sub-cells, ending on the start or next to it -
//     check_full, with the repeats the path itself has.
// Coordinates are sub-cells, as `antkit stc` uses them: one map cell of the file is one robot-sized
// sub-cell, x to the right, y downward from the file's first row; the cell area is the map cut to
// even width and height.
//
// A tour that ends on its first position is read as closed: that last entry is the return to the
// start, not a second visit (planners differ on whether they list it; STC's own does not).
#include <antkit/kernel/grid.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/testing/stc.hpp>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::testing {

enum class TourRule : std::uint8_t { ExactlyOnce, Coverage };

struct StcAudit {
  TourRule rule = TourRule::ExactlyOnce;
  StcCheck first;                 // the first broken rule (ok when the tour passes)
  bool closed_form = false;       // the path listed its start again at the end (dropped)
  std::int64_t positions = 0;     // positions of the tour (after dropping the closing entry)
  std::int64_t reachable = 0;     // sub-cells the rule asks for
  std::int64_t covered = 0;       // of those, entered at least once
  std::int64_t missed = 0;        // reachable - covered
  std::int64_t repeats = 0;       // positions on a sub-cell entered before
  std::int64_t illegal_moves = 0; // moves to a position not 4-adjacent to the previous one
  std::int64_t off_limits = 0;    // positions on no sub-cell the rule allows (blocked, off the
                                  // map, a partly blocked cell, unreachable)
  std::int64_t end_distance = 0;  // Manhattan distance from the last position to the start
  std::vector<kernel::Cell> missed_sample; // the first missed sub-cells, row-major (at most 16)

  [[nodiscard]] bool ok() const noexcept { return first.ok; }
};

[[nodiscard]] StcAudit audit_stc_tour(const kernel::OccupancyGrid& map, kernel::Cell start,
                                      std::span<const kernel::Cell> path, TourRule rule);

// The order of a tour's pairs: x,y (column, row: antkit's) or row,col (y,x: numpy's, most image
// and matrix code's).
enum class TourOrder : std::uint8_t { XY, RowCol };
[[nodiscard]] std::string_view tour_order_name(TourOrder order) noexcept; // "xy" / "rc"

// A tour read from a file, and the start it names (antkit stc's JSON output has one), in x,y.
struct TourFile {
  std::vector<kernel::Cell> path;
  std::optional<kernel::Cell> start;
  TourOrder order = TourOrder::XY; // the order the file's pairs were read in
  bool order_from_header = false;  // a CSV header said it (x,y; row,col or y,x)
};

// Reads a tour. A file that starts with "ANTKPTH1" is antkit's binary path (stc/path_format.hpp:
// two bits per move, and the start). Otherwise the format is decided by the first character that
// is not white space:
//   '[' a JSON array of [x, y] pairs;  '{' a JSON object with "path" (that array) and optionally
//   "start" ([x, y]), as `antkit stc --format json` prints it (other keys are ignored);
//   anything else: CSV, one "x,y" per line (spaces and tabs around the numbers, CRLF and blank
//   lines allowed, an optional first line "x,y", or "row,col" or "y,x" for pairs in that order).
// `order` is the order of the pairs when the file does not say it (JSON pairs and the "start",
// headerless CSV); a CSV header overrides it. antkit's binary path is always x,y. The pairs are
// returned as x,y.
// Coordinates are whole numbers in [-2^31, 2^31). At most 2^28 positions. Errors are
// kernel::InputError naming `source` and the place: "SOURCE:LINE:COL" for syntax,
// "SOURCE: path[i]" for a well-formed JSON value of the wrong shape.
[[nodiscard]] TourFile read_tour(std::string_view text, const std::string& source,
                                 TourOrder order = TourOrder::XY);
// Reads a file (at most 1 GiB); one that cannot be read is an InputError naming it.
[[nodiscard]] TourFile read_tour_file(const std::filesystem::path& path,
                                      TourOrder order = TourOrder::XY);

// `antkit check stc`: the map file, the tour file and the start. The start is --start when given,
// else the tour file's "start", else the map's own start ('S' in an ASCII map), else the tour's
// first position.
struct StcCheckRequest {
  std::string map_file;
  std::string tour_file;
  std::optional<kernel::Cell> start;
  TourRule rule = TourRule::ExactlyOnce;
  TourOrder order = TourOrder::XY; // the tour file's pairs when it does not say (read_tour)
  // The map, the start and the tour file's start are in robot-sized cells, as planners that merge
  // 2 x 2 sub-cells give them: each map cell becomes 2 x 2 sub-cells (blocked or free as the
  // cell), the tour stays in sub-cells, and its first position may be any sub-cell of the start
  // cell (which then is the start). "Reachable" is then every sub-cell of the free cells
  // 4-connected to the start cell.
  bool cells = false;
};

struct StcCheckReport {
  StcAudit audit;
  kernel::Cell start{};
  std::string start_from; // "--start", "tour file", "map" or "first position"
  TourOrder order = TourOrder::XY;
  bool order_from_header = false;
  bool cells = false; // the request's `cells`: width, height and start are sub-cells
  std::optional<kernel::Cell> start_cell; // with `cells`: the start cell the start lies in
  std::int32_t width = 0, height = 0;
};

[[nodiscard]] StcCheckReport check_stc_files(const StcCheckRequest& request);

// The same on a map and a tour in memory (the Python package's check_stc): `request`'s map_file
// and tour_file only name them in messages; its order is the one `tour` was read in.
[[nodiscard]] StcCheckReport check_stc(maps::GridMap map, const TourFile& tour,
                                       const StcCheckRequest& request);

[[nodiscard]] std::string_view tour_rule_name(TourRule rule) noexcept;

} // namespace antkit::testing
