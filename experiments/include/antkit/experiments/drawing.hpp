#pragma once
// Pictures of runs drawn with Cairo (SVG and PNG from one drawing path, like plot.hpp): an STC tour
// on its map and Buffon trails in their arenas. Each picture has a title, a legend naming every
// colour and a caption, so that it reads without the code.
#include <antkit/kernel/grid.hpp>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace antkit::experiments {

using XY = std::pair<double, double>;

// A tour on a grid map (sub-cell coordinates, x right, y down): blocked cells dark, the spanning
// tree (an edge between two cells' centres where the tour first crosses between them) in light
// grey, outside the tour's colour scale, the tour coloured along its length from violet (start)
// through blue and green to yellow (end) so that its order can be followed, and the start as a red
// dot. Throws kernel::InputError for a file that cannot be
// written.
void save_tour_figure(const kernel::OccupancyGrid& map, std::span<const kernel::Cell> path,
                      const std::string& title, const std::string& caption,
                      const std::filesystem::path& svg, const std::filesystem::path& png);

// One arena of a trails figure: its walls (closed rings, arena units, y up) and the two visits'
// trails (a jump longer than one unit breaks a trail into pieces).
struct TrailPanel {
  std::string title;
  std::vector<std::vector<XY>> rings;
  std::vector<XY> trail1, trail2;
};

// Arenas side by side, each scaled to its panel; visit 1 blue, visit 2 red.
void save_trails_figure(const std::string& title, const std::string& caption,
                        const std::vector<TrailPanel>& panels, const std::filesystem::path& svg,
                        const std::filesystem::path& png);

// A grid picture: each cell's state (an index into the legend's states) drawn in that state's
// colour, trails (polylines through cell centres, a dot at the last point) and robots (dots).
struct GridPanel {
  std::string title;
  kernel::Grid<std::uint8_t> states;
  std::vector<std::vector<XY>> trails; // trail k in legend.trails[k]'s colour
  std::vector<XY> robots;              // in legend.robot's colour
};

struct GridLegendEntry {
  std::string colour; // "#rrggbb"
  std::string name;
  std::string casing{}; // a trail's edge, drawn wider beneath it, so it stands out on any cell
};

struct GridLegend {
  std::vector<GridLegendEntry> states, trails;
  GridLegendEntry robot{"#d62728", "robot"};
};

// Panels side by side, with a legend naming every state, trail and the robots, and a caption.
void save_grid_figure(const std::string& title, const std::string& caption,
                      const std::vector<GridPanel>& panels, const GridLegend& legend,
                      const std::filesystem::path& svg, const std::filesystem::path& png);

// Paper 001's palette (Table 1): states are los::CellState codes (0 F fresh, 1 S scanned free,
// 2 LOS free by line of sight, 3 S+LOS, 4 NLOS potentially occupied, 5 O occupied); trail 0 is
// robot A (the wall follower; pink in the paper, here cyan edged in black, which no cell colour
// hides, for colour-blind readers too), trail 1 robot B (black, edged in white, as in the paper).
[[nodiscard]] GridLegend exploration_legend();

} // namespace antkit::experiments
