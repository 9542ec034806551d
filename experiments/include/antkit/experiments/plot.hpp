#pragma once
// Figures drawn with Cairo, one drawing code path for both SVG and PNG (issue 17's cost of
// precision, the figures of `antkit reproduce`): panels side by side (or in rows) sharing their x
// axis and, unless a panel has its own, their y axis; linear or log axes (decade ticks, and 2 and 5
// labelled when the axis spans little more than two decades) or named categories along x; series
// as points joined by lines with interquartile bars, points optionally labelled; dashed reference
// lines, optionally labelled; a legend per panel or one for the figure; a title, axis labels and a
// caption. The picture is as tall as its contents.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace antkit::experiments {

struct PlotPoint {
  double x = 0, y = 0;
  std::optional<double> lo, hi; // an error bar from lo to hi, when both are given
  std::string label{};          // a short text right of the marker (e.g. "2 robots"), in its colour
};

struct PlotSeries {
  std::string name;   // the legend's text
  std::string colour; // "#rrggbb"
  bool dashed = false;
  bool hollow = false; // open markers (and no line)
  std::vector<PlotPoint> points;
  bool no_marker{}; // a legend entry that is a line only (a reference line's)
};

enum class Axis { Linear, Log };

// A dashed horizontal reference line (a baseline, a threshold), its label above one end.
struct PlotMark {
  double y = 0;
  std::string label{};
  std::string colour = "#404040";
  bool label_left{}; // the label above the left end (else the right end)
  bool in_legend{};  // the label in the legend, beside a dashed line, instead of on the plot
};

struct PlotPanel {
  std::string title;
  std::string note; // a line inside the plot's lower right corner (e.g. fitted exponents)
  std::vector<PlotSeries> series;
  // The legend: one entry per series when empty; otherwise these entries (name, colour and style
  // of each; their points are not drawn), for a figure whose series combine a colour and a style.
  std::vector<PlotSeries> legend;
  // This panel's own y axis (scale, range and label) instead of the figure's: a panel of another
  // quantity beside the others, e.g. an efficiency beside the counts it is made of.
  std::optional<Axis> y_axis{};
  std::string y_label{};
  bool y_from_zero{};
  std::vector<PlotMark> marks{}; // reference lines of this panel only
};

struct Figure {
  std::string title, x_label, y_label, caption;
  std::vector<PlotPanel> panels;
  Axis x_axis = Axis::Linear, y_axis = Axis::Linear;
  // Names for x = 0, 1, 2, ... (a categorical axis) instead of numbers; empty: numeric.
  std::vector<std::string> x_categories;
  bool y_from_zero = false;      // a linear y axis that starts at 0 (or below)
  std::vector<double> y_marks;   // dashed reference lines across every panel (e.g. the true value)
  std::vector<PlotMark> marks{}; // labelled reference lines across every panel sharing the y axis
  // One legend for the whole figure, below every panel, instead of one per panel (for panels that
  // all show the same series). Empty: each panel has its own.
  std::vector<PlotSeries> legend{};
  std::size_t columns{}; // panels per row; 0: all in one row
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
