#include "cairo_output.hpp"

#include <algorithm>
#include <antkit/experiments/drawing.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <set>

namespace antkit::experiments {

using detail::caption_lines;
using detail::text;

namespace {

// Blue to yellow through green (an approximation of viridis by five stops), t in [0, 1].
detail::Rgb along(double t) {
  static constexpr double stops[5][3] = {{0.267, 0.005, 0.329},
                                         {0.230, 0.322, 0.546},
                                         {0.128, 0.567, 0.551},
                                         {0.369, 0.789, 0.383},
                                         {0.993, 0.906, 0.144}};
  t = std::clamp(t, 0.0, 1.0) * 4;
  const int i = std::min(3, static_cast<int>(t));
  const double f = t - i;
  return {stops[i][0] + f * (stops[i + 1][0] - stops[i][0]),
          stops[i][1] + f * (stops[i + 1][1] - stops[i][1]),
          stops[i][2] + f * (stops[i + 1][2] - stops[i][2])};
}

// The spanning tree's light grey: no hue of the tour's violet-to-yellow scale, lighter than the
// blocked cells, darker than the free ones.
constexpr detail::Rgb kTree{0.72, 0.72, 0.72};

// The lines of a caption (one per '\n', plus one), for the room under a picture's legend.
std::size_t line_count(const std::string& caption) {
  return 1 + static_cast<std::size_t>(std::count(caption.begin(), caption.end(), '\n'));
}

// A white page with its title centred at height y.
void page(cairo_t* cr, double width, double y, const std::string& title) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, width / 2, y, title, 16, 0.5, 0.5, true);
}

void legend_line(cairo_t* cr, double x, double y, detail::Rgb c, double width,
                 const std::string& label) {
  cairo_set_source_rgb(cr, c.r, c.g, c.b);
  cairo_set_line_width(cr, width);
  cairo_move_to(cr, x, y);
  cairo_line_to(cr, x + 26, y);
  cairo_stroke(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, x + 32, y, label, 11, 0, 0.5);
}

} // namespace

void save_tour_figure(const kernel::OccupancyGrid& map, std::span<const kernel::Cell> path,
                      const std::string& title, const std::string& caption,
                      const std::filesystem::path& svg, const std::filesystem::path& png) {
  const double w = map.width(), h = map.height();
  const double side = std::max(w, h);
  const double scale = std::clamp(760.0 / side, 1.0, 24.0);
  const std::size_t caption_rows = line_count(caption);
  // Two legend rows, then the caption right under them: no empty band.
  const double top = 44, left = 20, legend = 76 + 15 * static_cast<double>(caption_rows);
  const double width = std::max(w * scale + 2 * left, 640.0), height = top + h * scale + legend;
  const double ox = (width - w * scale) / 2;
  detail::render(
      width, height,
      [&](cairo_t* cr) {
        page(cr, width, 22, title);
        const auto X = [&](double x) { return ox + x * scale; };
        const auto Y = [&](double y) { return top + y * scale; };
        // The map: free white, blocked dark grey, unknown light grey, one rectangle per run of
        // equal cells in a row (small SVG files on large maps), without antialiasing so that rows
        // meet without a seam.
        cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
        for (std::int32_t y = 0; y < map.height(); ++y)
          for (std::int32_t x = 0; x < map.width();) {
            const kernel::Occupancy o = map[{x, y}];
            std::int32_t end = x + 1;
            while (end < map.width() && map[{end, y}] == o) ++end;
            if (o != kernel::Occupancy::Free) {
              const double g = o == kernel::Occupancy::Blocked ? 0.25 : 0.7;
              cairo_set_source_rgb(cr, g, g, g);
              cairo_rectangle(cr, X(x), Y(y), (end - x) * scale, scale);
              cairo_fill(cr);
            }
            x = end;
          }
        cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, 1);
        cairo_rectangle(cr, X(0), Y(0), w * scale, h * scale);
        cairo_stroke(cr);
        // The spanning tree.
        std::set<std::pair<kernel::Cell, kernel::Cell>> edges;
        cairo_set_source_rgb(cr, kTree.r, kTree.g, kTree.b);
        cairo_set_line_width(cr, std::max(1.0, 0.35 * scale));
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
        for (std::size_t i = 1; i < path.size(); ++i) {
          const kernel::Cell a{path[i - 1].x / 2, path[i - 1].y / 2};
          const kernel::Cell b{path[i].x / 2, path[i].y / 2};
          if (a == b || !edges.insert({std::min(a, b), std::max(a, b)}).second) continue;
          cairo_move_to(cr, X(2 * a.x + 1), Y(2 * a.y + 1));
          cairo_line_to(cr, X(2 * b.x + 1), Y(2 * b.y + 1));
        }
        cairo_stroke(cr);
        // The tour, coloured along its length: 256 strokes of one colour each.
        const std::size_t n = path.size();
        if (n > 1) {
          cairo_set_line_width(cr, std::max(0.8, 0.22 * scale));
          cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
          const std::size_t chunks = std::min<std::size_t>(256, n - 1);
          for (std::size_t c = 0; c < chunks; ++c) {
            const std::size_t from = c * (n - 1) / chunks, to = (c + 1) * (n - 1) / chunks;
            const detail::Rgb col = along(static_cast<double>(c) / static_cast<double>(chunks));
            cairo_set_source_rgb(cr, col.r, col.g, col.b);
            cairo_move_to(cr, X(path[from].x + 0.5), Y(path[from].y + 0.5));
            for (std::size_t i = from + 1; i <= to; ++i)
              cairo_line_to(cr, X(path[i].x + 0.5), Y(path[i].y + 0.5));
            cairo_stroke(cr);
          }
        }
        if (!path.empty()) {
          cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
          cairo_arc(cr, X(path.front().x + 0.5), Y(path.front().y + 0.5),
                    std::max(4.0, 0.35 * scale), 0, 2 * M_PI);
          cairo_fill(cr);
        }
        // Legend: the tour's colour bar, the tree, the start, obstacles.
        const double ly = top + h * scale + 24;
        const double lx = width / 2 - 290;
        for (int k = 0; k < 100; ++k) {
          const detail::Rgb col = along(k / 99.0);
          cairo_set_source_rgb(cr, col.r, col.g, col.b);
          cairo_rectangle(cr, lx + 1.2 * k, ly - 5, 1.3, 10);
          cairo_fill(cr);
        }
        cairo_set_source_rgb(cr, 0, 0, 0);
        text(cr, lx + 126, ly, "tour, from start to end", 11, 0, 0.5);
        legend_line(cr, lx + 290, ly, kTree, 4, "spanning tree (cell centres)");
        cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
        cairo_arc(cr, lx + 13, ly + 24, 5, 0, 2 * M_PI);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        text(cr, lx + 32, ly + 24, "start", 11, 0, 0.5);
        cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
        cairo_rectangle(cr, lx + 290, ly + 19, 26, 10);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        text(cr, lx + 322, ly + 24, "blocked (grey: unknown)", 11, 0, 0.5);
        caption_lines(cr, caption, width / 2, height - 14);
      },
      svg, png);
}

void save_trails_figure(const std::string& title, const std::string& caption,
                        const std::vector<TrailPanel>& panels, const std::filesystem::path& svg,
                        const std::filesystem::path& png) {
  const std::size_t caption_rows = line_count(caption);
  // One legend row, then the caption right under it: no empty band.
  const double pw = 360, top = 50, inner = 320,
               bottom = 58 + 15 * static_cast<double>(caption_rows);
  const double width =
      std::max(pw * static_cast<double>(std::max<std::size_t>(1, panels.size())), 640.0);
  const double left = (width - pw * static_cast<double>(panels.size())) / 2;
  const double height = top + inner + bottom;
  detail::render(
      width, height,
      [&](cairo_t* cr) {
        page(cr, width, 20, title);
        for (std::size_t k = 0; k < panels.size(); ++k) {
          const TrailPanel& p = panels[k];
          double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
          for (const auto& ring : p.rings)
            for (const auto& [x, y] : ring) {
              x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y),
              y1 = std::max(y1, y);
            }
          if (!(x1 > x0) || !(y1 > y0)) continue;
          const double s = inner / std::max(x1 - x0, y1 - y0);
          const double cx = left + pw * static_cast<double>(k) + (pw - (x1 - x0) * s) / 2;
          const double cy = top + (inner - (y1 - y0) * s) / 2;
          const auto X = [&](double x) { return cx + (x - x0) * s; };
          const auto Y = [&](double y) { return cy + (y1 - y) * s; };
          cairo_set_source_rgb(cr, 0, 0, 0);
          text(cr, left + pw * (static_cast<double>(k) + 0.5), top - 10, p.title, 12, 0.5, 0.5,
               true);
          const auto trail = [&](const std::vector<XY>& pts, detail::Rgb c) {
            cairo_set_source_rgba(cr, c.r, c.g, c.b, 0.75);
            cairo_set_line_width(cr, std::max(0.6, 0.1 * s));
            for (std::size_t i = 0; i < pts.size(); ++i) {
              const bool jump = i == 0 || std::hypot(pts[i].first - pts[i - 1].first,
                                                     pts[i].second - pts[i - 1].second) > 1.0;
              if (jump)
                cairo_move_to(cr, X(pts[i].first), Y(pts[i].second));
              else
                cairo_line_to(cr, X(pts[i].first), Y(pts[i].second));
            }
            cairo_stroke(cr);
          };
          trail(p.trail1, {0.12, 0.36, 0.85});
          trail(p.trail2, {0.85, 0.12, 0.12});
          cairo_set_source_rgb(cr, 0, 0, 0);
          cairo_set_line_width(cr, 2);
          for (const auto& ring : p.rings) {
            for (std::size_t i = 0; i < ring.size(); ++i)
              (i == 0 ? cairo_move_to : cairo_line_to)(cr, X(ring[i].first), Y(ring[i].second));
            cairo_close_path(cr);
            cairo_stroke(cr);
          }
        }
        const double ly = top + inner + 26;
        legend_line(cr, width / 2 - 230, ly, {0.12, 0.36, 0.85}, 3, "visit 1 (first trail)");
        legend_line(cr, width / 2 + 20, ly, {0.85, 0.12, 0.12}, 3, "visit 2 (counts crossings)");
        caption_lines(cr, caption, width / 2, height - 14);
      },
      svg, png);
}

GridLegend exploration_legend() {
  GridLegend l;
  l.states = {{"#9e9e9e", "F: fresh"},
              {"#8d5524", "S: free, scanned"},
              {"#e53935", "LOS: free, line of sight"},
              {"#fdd835", "S+LOS: both"},
              {"#1e88e5", "NLOS: maybe occupied"},
              {"#fb8c00", "O: occupied"}};
  l.trails = {{"#00e5ff", "robot A (wall follower), trail and position", "#000000"},
              {"#000000", "robot B, trail and position", "#ffffff"}};
  return l;
}

void save_grid_figure(const std::string& title, const std::string& caption,
                      const std::vector<GridPanel>& panels, const GridLegend& legend,
                      const std::filesystem::path& svg, const std::filesystem::path& png) {
  const double pw = panels.size() == 1 ? 520 : 250, inner = panels.size() == 1 ? 480 : 220;
  const double top = 50;
  bool any_robot = false;
  for (const auto& p : panels) any_robot = any_robot || !p.robots.empty();
  const std::size_t legend_rows =
      (legend.states.size() + 2) / 3 + (legend.trails.size() + 1) / 2 + (any_robot ? 1 : 0);
  const std::size_t caption_rows = line_count(caption);
  // The legend, then the caption right under it: no empty band.
  const double bottom =
      34 + 18 * static_cast<double>(legend_rows) + 15 * static_cast<double>(caption_rows);
  const double width = std::max(pw * static_cast<double>(panels.size()), 760.0);
  const double height = top + inner + bottom;
  const double left = (width - pw * static_cast<double>(panels.size())) / 2;
  detail::render(
      width, height,
      [&](cairo_t* cr) {
        page(cr, width, 20, title);
        for (std::size_t k = 0; k < panels.size(); ++k) {
          const auto& p = panels[k];
          const double w = p.states.width(), h = p.states.height();
          if (w <= 0 || h <= 0) continue;
          const double sc = inner / std::max(w, h);
          const double ox = left + pw * static_cast<double>(k) + (pw - w * sc) / 2;
          const double oy = top + (inner - h * sc) / 2;
          cairo_set_source_rgb(cr, 0, 0, 0);
          text(cr, left + pw * (static_cast<double>(k) + 0.5), top - 10, p.title, 11.5, 0.5, 0.5,
               true);
          // One rectangle per run of equal states in a row, without antialiasing (no seams).
          cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
          for (std::int32_t y = 0; y < p.states.height(); ++y)
            for (std::int32_t x = 0; x < p.states.width();) {
              const std::uint8_t v = p.states[{x, y}];
              std::int32_t end = x + 1;
              while (end < p.states.width() && p.states[{end, y}] == v) ++end;
              const auto c = detail::rgb(v < legend.states.size() ? legend.states[v].colour : "");
              cairo_set_source_rgb(cr, c.r, c.g, c.b);
              cairo_rectangle(cr, ox + x * sc, oy + y * sc, (end - x) * sc, sc);
              cairo_fill(cr);
              x = end;
            }
          cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
          cairo_set_source_rgb(cr, 0, 0, 0);
          cairo_set_line_width(cr, 1);
          cairo_rectangle(cr, ox, oy, w * sc, h * sc);
          cairo_stroke(cr);
          // Trails last to first, so that trail 0 is on top.
          for (std::size_t t = p.trails.size(); t-- > 0;) {
            const auto& pts = p.trails[t];
            if (pts.empty()) continue;
            const auto c =
                detail::rgb(t < legend.trails.size() ? legend.trails[t].colour : "#000000");
            const std::string casing = t < legend.trails.size() ? legend.trails[t].casing : "";
            // The casing first, wider, then the trail on it; the same for the last position.
            for (const bool edge : {true, false}) {
              if (edge && casing.empty()) continue;
              const auto col = edge ? detail::rgb(casing) : c;
              const double extra = edge ? 2.5 : 0;
              cairo_set_source_rgb(cr, col.r, col.g, col.b);
              cairo_set_line_width(cr, std::max(1.5, sc / 4) + extra);
              cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
              for (std::size_t i = 0; i < pts.size(); ++i)
                (i == 0 ? cairo_move_to : cairo_line_to)(cr, ox + pts[i].first * sc,
                                                         oy + pts[i].second * sc);
              cairo_stroke(cr);
              cairo_arc(cr, ox + pts.back().first * sc, oy + pts.back().second * sc,
                        std::max(2.5, sc / 2.5) + extra / 2, 0, 2 * M_PI);
              cairo_fill(cr);
            }
          }
          const auto rc = detail::rgb(legend.robot.colour);
          cairo_set_source_rgb(cr, rc.r, rc.g, rc.b);
          for (const auto& [x, y] : p.robots) {
            cairo_arc(cr, ox + x * sc, oy + y * sc, std::max(2.5, sc / 2.5), 0, 2 * M_PI);
            cairo_fill(cr);
          }
        }
        // Legend: the states three to a row, then the trails two to a row, then the robots.
        double ly = top + inner + 22;
        for (std::size_t i = 0; i < legend.states.size(); ++i) {
          const double lx = width / 2 - 360 + 240 * static_cast<double>(i % 3);
          const double y = ly + 18 * static_cast<double>(i / 3);
          const auto c = detail::rgb(legend.states[i].colour);
          cairo_set_source_rgb(cr, c.r, c.g, c.b);
          cairo_rectangle(cr, lx, y - 6, 14, 12);
          cairo_fill_preserve(cr);
          cairo_set_source_rgb(cr, 0.5, 0.5, 0.5);
          cairo_set_line_width(cr, 0.5);
          cairo_stroke(cr);
          cairo_set_source_rgb(cr, 0, 0, 0);
          text(cr, lx + 20, y, legend.states[i].name, 11, 0, 0.5);
        }
        ly += 18 * static_cast<double>((legend.states.size() + 2) / 3) + 4;
        for (std::size_t i = 0; i < legend.trails.size(); ++i) {
          const double tx = width / 2 - 360 + 420 * static_cast<double>(i % 2);
          const double ty = ly + 18 * static_cast<double>(i / 2);
          if (!legend.trails[i].casing.empty())
            legend_line(cr, tx, ty, detail::rgb(legend.trails[i].casing), 5.5, "");
          legend_line(cr, tx, ty, detail::rgb(legend.trails[i].colour), 3, legend.trails[i].name);
        }
        ly += 18 * static_cast<double>((legend.trails.size() + 1) / 2);
        if (any_robot) {
          const auto rc = detail::rgb(legend.robot.colour);
          cairo_set_source_rgb(cr, rc.r, rc.g, rc.b);
          cairo_arc(cr, width / 2 - 353, ly, 4, 0, 2 * M_PI);
          cairo_fill(cr);
          cairo_set_source_rgb(cr, 0, 0, 0);
          text(cr, width / 2 - 340, ly, legend.robot.name, 11, 0, 0.5);
        }
        caption_lines(cr, caption, width / 2, height - 14);
      },
      svg, png);
}

} // namespace antkit::experiments
