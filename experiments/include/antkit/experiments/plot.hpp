#pragma once
// Figures drawn with Cairo, one drawing code path for both SVG and PNG (issue 17's cost of
// precision, the figures of `antkit reproduce`): panels side by side sharing their axes, linear or
// log axes (decade ticks) or named categories along x, series as points joined by lines with
// interquartile bars, a legend per panel naming every colour, a title, axis labels and a caption.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace antkit::experiments {

struct PlotPoint {
  double x = 0, y = 0;
  std::optional<double> lo, hi; // an error bar from lo to hi, when both are given
};

struct PlotSeries {
  std::string name;   // the legend's text
  std::string colour; // "#rrggbb"
  bool dashed = false;
  bool hollow = false; // open markers (and no line)
  std::vector<PlotPoint> points;
};

struct PlotPanel {
  std::string title;
  std::string note; // a line inside the plot's lower right corner (e.g. fitted exponents)
  std::vector<PlotSeries> series;
  // The legend: one entry per series when empty; otherwise these entries (name, colour and style
  // of each; their points are not drawn), for a figure whose series combine a colour and a style.
  std::vector<PlotSeries> legend;
};

enum class Axis { Linear, Log };

struct Figure {
  std::string title, x_label, y_label, caption;
  std::vector<PlotPanel> panels;
  Axis x_axis = Axis::Linear, y_axis = Axis::Linear;
  // Names for x = 0, 1, 2, ... (a categorical axis) instead of numbers; empty: numeric.
  std::vector<std::string> x_categories;
  bool y_from_zero = false;    // a linear y axis that starts at 0 (or below)
  std::vector<double> y_marks; // dashed reference lines across every panel (e.g. the true value)
};

// Writes the figure to `svg` and `png` (each written to a temporary name in the same directory,
// then renamed, so no partial file is left). Throws kernel::InputError(path, ...) when a file
// cannot be written, or when there is no point to draw (none positive, on a log axis).
void save_figure(const Figure& figure, const std::filesystem::path& svg,
                 const std::filesystem::path& png);

// Frees Cairo's and fontconfig's process-wide caches (font faces, the fontconfig configuration),
// which otherwise live until exit and would be reported as leaks by LeakSanitizer (the debug
// preset). Called at exit after any drawing; call it earlier when no more figures will be drawn
// for a while. Drawing again afterwards rebuilds them. Not while another thread draws.
void release_drawing_caches() noexcept;

} // namespace antkit::experiments
