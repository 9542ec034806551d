// Figures with Cairo (plot.hpp).
#include "cairo_output.hpp"

#include <algorithm>
#include <antkit/experiments/plot.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cairo.h>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace antkit::experiments {

namespace {

// The layout, in pixels: a panel's plot is kPlot tall; its column is panel_width wide, of which
// kLeft and kRight are margins; the title takes kTop above the first row. Below a plot come its
// tick labels and x label (kBelowPlot), then its legend; rows of panels are kRowGap apart (room for
// the next row's panel titles). The picture ends under its caption: no empty band.
constexpr double kTop = 64, kPlot = 300, kLeft = 74, kRight = 30, kBelowPlot = 54, kRowGap = 46;
constexpr double kLegendRow = 17, kFont = 12;
// A lone panel gets room for a long title and caption; panels side by side 420 each; a lone panel
// of many named categories (the claims' forest plot) 36 px a category, so that their staggered
// labels (up to 12 characters: "002-rotation") do not collide.
double panel_width(std::size_t columns, std::size_t categories) {
  return columns == 1 ? std::max(640.0, kLeft + kRight + 36.0 * static_cast<double>(categories))
                      : 420;
}

using detail::rgb;
using detail::Rgb;
using detail::text;

// One axis: its data range, then its drawn range (decades on a log axis, or 1, 2, 5 times a power
// of ten when it spans little, "nice" round steps on a linear one) and its ticks.
struct AxisRange {
  bool log = false;
  bool fine = false; // a log axis short enough to label 2 and 5 times a decade too
  double lo = std::numeric_limits<double>::infinity(),
         hi = -std::numeric_limits<double>::infinity();
  double step = 1; // linear: the distance between labelled ticks
  void add(double v) {
    if (!std::isfinite(v) || (log && !(v > 0))) return;
    const double t = log ? std::log10(v) : v;
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  void finish(bool from_zero) {
    if (!(lo <= hi)) lo = hi = 0;
    if (log) {
      fine = hi - lo <= 2.5;
      if (!fine) {
        lo = std::floor(lo);
        hi = std::ceil(hi);
        if (hi <= lo) hi = lo + 1;
        return;
      }
      // The largest 1, 2 or 5 times a power of ten at or below lo, the smallest at or above hi.
      const double d_lo = std::floor(lo + 1e-9), d_hi = std::floor(hi - 1e-9);
      double nlo = d_lo, nhi = d_hi + 1;
      for (const double m : {5.0, 2.0, 1.0})
        if (d_lo + std::log10(m) <= lo + 1e-9) {
          nlo = d_lo + std::log10(m);
          break;
        }
      for (const double m : {1.0, 2.0, 5.0, 10.0})
        if (d_hi + std::log10(m) >= hi - 1e-9) {
          nhi = d_hi + std::log10(m);
          break;
        }
      lo = nlo;
      hi = nhi > nlo ? nhi : nlo + 1;
      return;
    }
    if (from_zero) lo = std::min(lo, 0.0);
    double span = hi - lo;
    if (span <= 0) span = std::max(std::abs(hi), 1.0);
    // A step of 1, 2 or 5 times a power of ten that gives 4 to 10 intervals.
    const double raw = span / 6, power = std::pow(10.0, std::floor(std::log10(raw)));
    step = power;
    for (const double m : {1.0, 2.0, 5.0, 10.0})
      if (raw <= m * power * 1.0000001) {
        step = m * power;
        break;
      }
    lo = std::floor(lo / step + 1e-9) * step;
    hi = std::ceil(hi / step - 1e-9) * step;
    if (hi <= lo) hi = lo + step;
  }
  // Room beyond lo and hi, so that points and bars at the ends are not on the frame.
  double pad_lo = 0, pad_hi = 0;
  void pad(bool below) {
    pad_hi = (log ? 0.05 : 0.04) * (hi - lo);
    pad_lo = below || log ? pad_hi : 0;
  }
  // 0 at lo - pad_lo, 1 at hi + pad_hi.
  [[nodiscard]] double unit(double v) const {
    const double t = log ? std::log10(v) : v;
    return (t - lo + pad_lo) / (hi - lo + pad_lo + pad_hi);
  }
};

std::string linear_label(double v, double step) {
  char buf[32];
  const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < step * 1e-6 ? 0.0 : v);
  return buf;
}

// m times 10^k as a plain number for the powers a reader meets here (0.0001 .. 10^7), thin
// groups of three from the right (10 000, 2 000 000); else "1e-6", "5e-6".
std::string log_label(int m, int k) {
  if (k >= 0 && k <= 7) {
    const std::string compact = std::to_string(m) + std::string(static_cast<std::size_t>(k), '0');
    std::string grouped;
    for (std::size_t i = 0; i < compact.size(); ++i) {
      if (i > 0 && (compact.size() - i) % 3 == 0 && compact.size() > 4) grouped += ' ';
      grouped += compact[i];
    }
    return grouped;
  }
  if (k < 0 && k >= -4) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", -k, m * std::pow(10.0, k));
    return buf;
  }
  return std::to_string(m) + "e" + std::to_string(k);
}

// The ticks of an axis: (value, labelled) pairs; a log axis has its decades labelled (and 2 and 5
// when it is fine) and the others as light lines, a linear one its steps; categories label 0, 1, 2.
std::vector<std::pair<double, std::string>>
ticks(const AxisRange& sc, const std::vector<std::string>& categories, std::vector<double>& minor) {
  std::vector<std::pair<double, std::string>> major;
  if (!categories.empty()) {
    for (std::size_t i = 0; i < categories.size(); ++i)
      major.emplace_back(static_cast<double>(i), categories[i]);
    return major;
  }
  if (sc.log) {
    for (auto d = static_cast<int>(std::floor(sc.lo + 1e-9));
         d <= static_cast<int>(std::ceil(sc.hi - 1e-9)); ++d)
      for (int m = 1; m <= 9; ++m) {
        const double v = m * std::pow(10.0, d), t = std::log10(v);
        if (t < sc.lo - 1e-9 || t > sc.hi + 1e-9) continue;
        if (m == 1 || (sc.fine && (m == 2 || m == 5)))
          major.emplace_back(v, log_label(m, d));
        else
          minor.push_back(v);
      }
    return major;
  }
  const auto n = static_cast<int>(std::lround((sc.hi - sc.lo) / sc.step));
  for (int k = 0; k <= n; ++k) {
    const double v = sc.lo + sc.step * k;
    major.emplace_back(v, linear_label(v, sc.step));
  }
  return major;
}

// Which labels of an x axis to draw: the decades' (a log axis' labels that start with "1") and
// every other that does not overlap one already placed, so that a short log axis labelled at
// 1, 2 and 5 never runs its wide numbers together.
template <class Px>
std::vector<bool> shown_x_labels(cairo_t* cr,
                                 const std::vector<std::pair<double, std::string>>& major,
                                 const Px& px, double size) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  std::vector<std::pair<double, double>> spans; // left, right of each label
  for (const auto& [v, label] : major) {
    cairo_text_extents_t e;
    cairo_text_extents(cr, label.c_str(), &e);
    spans.emplace_back(px(v) - e.width / 2, px(v) + e.width / 2);
  }
  std::vector<bool> shown(major.size(), false);
  const auto fits = [&](std::size_t i) {
    for (std::size_t j = 0; j < major.size(); ++j)
      if (shown[j] && spans[i].first < spans[j].second + 8 && spans[j].first < spans[i].second + 8)
        return false;
    return true;
  };
  for (const bool decades : {true, false})
    for (std::size_t i = 0; i < major.size(); ++i) {
      const bool decade = !major[i].second.empty() && major[i].second[0] == '1' &&
                          major[i].second.find_first_not_of("10 .") == std::string::npos;
      if (decade == decades && !shown[i] && fits(i)) shown[i] = true;
    }
  return shown;
}

// A legend's entries in two columns, unless a name would run into the second (about 26
// characters fit): the rows of the first column.
std::size_t legend_rows(const std::vector<PlotSeries>& entries) {
  std::size_t longest = 0;
  for (const auto& e : entries) longest = std::max(longest, e.name.size());
  return longest > 26 || entries.size() < 2 ? entries.size() : (entries.size() + 1) / 2;
}

// One legend entry: its line and marker (or open marker) at (lx, ly), then its name.
void legend_entry(cairo_t* cr, double lx, double ly, const PlotSeries& s) {
  const Rgb c = rgb(s.colour);
  cairo_new_path(cr);
  cairo_set_source_rgb(cr, c.r, c.g, c.b);
  if (s.hollow) {
    cairo_arc(cr, lx + 18, ly, 4, 0, 2 * M_PI);
    cairo_set_line_width(cr, 1.6);
    cairo_stroke(cr);
  } else {
    const double dash[] = {6, 4};
    cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
    cairo_set_line_width(cr, 2);
    cairo_move_to(cr, lx + 6, ly);
    cairo_line_to(cr, lx + 30, ly);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    if (!s.no_marker) {
      cairo_arc(cr, lx + 18, ly, 3.5, 0, 2 * M_PI);
      cairo_fill(cr);
    }
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, lx + 36, ly, s.name, kFont, 0, 0.5);
}

// The reference lines of a panel: its own, and the figure's when it shares the figure's y axis.
std::vector<PlotMark> marks_of(const Figure& f, const PlotPanel& panel) {
  std::vector<PlotMark> marks = panel.marks;
  if (!panel.y_axis) marks.insert(marks.end(), f.marks.begin(), f.marks.end());
  return marks;
}

// A panel's legend: its entries (or its series), then its reference lines labelled in the legend.
std::vector<PlotSeries> legend_of(const Figure& f, const PlotPanel& panel) {
  std::vector<PlotSeries> entries = panel.legend.empty() ? panel.series : panel.legend;
  for (const auto& m : marks_of(f, panel))
    if (m.in_legend && !m.label.empty()) {
      PlotSeries line{m.label, m.colour, true, false, {}};
      line.no_marker = true;
      entries.push_back(std::move(line));
    }
  return entries;
}

std::size_t caption_line_count(const std::string& caption) {
  return caption.empty()
             ? 0
             : 1 + static_cast<std::size_t>(std::count(caption.begin(), caption.end(), '\n'));
}

// Where everything goes: columns and rows of panels, the band below each plot, the figure's
// legend and its caption.
struct Layout {
  std::size_t columns = 1, rows = 1;
  double column_width = 640, width = 640, height = 560;
  double below = kBelowPlot; // from a plot's bottom to the end of its row's legend
  double legend_top = 0;     // the figure's legend, when it has one
  std::size_t legend_columns = 1;
  double caption_bottom = 0;
  [[nodiscard]] double plot_top(std::size_t row) const {
    return kTop + static_cast<double>(row) * (kPlot + below + kRowGap);
  }
};

Layout layout(const Figure& f) {
  Layout l;
  const std::size_t n = std::max<std::size_t>(1, f.panels.size());
  l.columns = f.columns == 0 ? n : std::min(f.columns, n);
  l.rows = (n + l.columns - 1) / l.columns;
  l.column_width = panel_width(l.columns, f.x_categories.size());
  l.width = l.column_width * static_cast<double>(l.columns);
  std::size_t panel_legend = 0;
  if (f.legend.empty())
    for (const auto& p : f.panels)
      panel_legend = std::max(panel_legend, legend_rows(legend_of(f, p)));
  l.below =
      kBelowPlot + (panel_legend > 0 ? 8 + kLegendRow * static_cast<double>(panel_legend) : 0);
  double y = l.plot_top(l.rows - 1) + kPlot + l.below;
  if (!f.legend.empty()) {
    l.legend_columns =
        std::clamp<std::size_t>(static_cast<std::size_t>(l.width / 250), 1, f.legend.size());
    const std::size_t rows = (f.legend.size() + l.legend_columns - 1) / l.legend_columns;
    l.legend_columns = (f.legend.size() + rows - 1) / rows; // the columns the rows need
    l.legend_top = y + 8 + kLegendRow / 2;
    y += 8 + kLegendRow * static_cast<double>(rows);
  }
  const auto lines = static_cast<double>(caption_line_count(f.caption));
  l.caption_bottom = y + 14 + 16 * lines - 8;
  l.height = std::ceil(y + 14 + 16 * lines + 6);
  return l;
}

// The y scale of the panels that share the figure's axis (own = false), or of one panel's own.
AxisRange y_scale(const Figure& f, const PlotPanel* own) {
  AxisRange yr;
  yr.log = (own != nullptr ? *own->y_axis : f.y_axis) == Axis::Log;
  const auto add_panel = [&](const PlotPanel& panel) {
    for (const auto& s : panel.series)
      for (const auto& p : s.points) {
        yr.add(p.y);
        if (p.lo && p.hi) yr.add(*p.lo), yr.add(*p.hi);
      }
    for (const auto& m : panel.marks) yr.add(m.y);
  };
  if (own != nullptr) {
    add_panel(*own);
  } else {
    for (const auto& panel : f.panels)
      if (!panel.y_axis) add_panel(panel);
    for (const double y : f.y_marks) yr.add(y);
    for (const auto& m : f.marks) yr.add(m.y);
  }
  const bool from_zero = own != nullptr ? own->y_from_zero : f.y_from_zero;
  yr.finish(from_zero);
  yr.pad(!from_zero);
  return yr;
}

void draw(cairo_t* cr, const Figure& f, const Layout& l) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  AxisRange xr;
  xr.log = f.x_axis == Axis::Log;
  for (const auto& panel : f.panels)
    for (const auto& s : panel.series)
      for (const auto& p : s.points) xr.add(p.x);
  if (!f.x_categories.empty()) {
    xr.lo = -0.5;
    xr.hi = static_cast<double>(f.x_categories.size()) - 0.5;
  } else {
    xr.finish(false);
    xr.pad(true);
  }
  const AxisRange shared_y = y_scale(f, nullptr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, l.width / 2, 22, f.title, 17, 0.5, 0.5, true);
  // The caption at 12 px, smaller if its longest line would not fit the picture's width.
  double caption_size = kFont;
  {
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, kFont);
    std::istringstream lines(f.caption);
    for (std::string line; std::getline(lines, line);) {
      cairo_text_extents_t e;
      cairo_text_extents(cr, line.c_str(), &e);
      if (e.width > l.width - 16)
        caption_size = std::min(caption_size, kFont * (l.width - 16) / e.width);
    }
  }
  detail::caption_lines(cr, f.caption, l.width / 2, l.caption_bottom, caption_size);
  std::vector<double> x_minor;
  const auto x_major = ticks(xr, f.x_categories, x_minor);
  for (std::size_t k = 0; k < f.panels.size(); ++k) {
    const PlotPanel& panel = f.panels[k];
    const AxisRange yr = panel.y_axis ? y_scale(f, &panel) : shared_y;
    std::vector<double> y_minor;
    const auto y_major = ticks(yr, {}, y_minor);
    const std::size_t column = k % l.columns, row = k / l.columns;
    const double x0 = l.column_width * static_cast<double>(column) + kLeft;
    const double x1 = l.column_width * static_cast<double>(column + 1) - kRight;
    const double y0 = l.plot_top(row), y1 = y0 + kPlot; // y0 top, y1 bottom
    auto px = [&](double v) { return x0 + xr.unit(v) * (x1 - x0); };
    auto py = [&](double v) { return y1 - yr.unit(v) * (y1 - y0); };
    // Grid and ticks: labelled ticks as grey lines, a log axis' others as light ones.
    cairo_set_line_width(cr, 1);
    const auto grid_line = [&](double xa, double ya, double xb, double yb, double grey) {
      cairo_set_source_rgb(cr, grey, grey, grey);
      cairo_move_to(cr, xa, ya);
      cairo_line_to(cr, xb, yb);
      cairo_stroke(cr);
    };
    for (const double v : x_minor) grid_line(px(v), y0, px(v), y1, 0.93);
    for (const double v : y_minor) grid_line(x0, py(v), x1, py(v), 0.93);
    // Category labels may be long: a smaller font, and every label on its own half-line when
    // there are many.
    const bool tight = !f.x_categories.empty() && f.x_categories.size() > 4;
    // On a log axis the 2 and 5 labels give way to the decades' where they would overlap.
    const auto x_shown =
        xr.log ? shown_x_labels(cr, x_major, px, kFont) : std::vector<bool>(x_major.size(), true);
    for (std::size_t i = 0; i < x_major.size(); ++i) {
      const auto& [v, label] = x_major[i];
      grid_line(px(v), y0, px(v), y1, 0.80);
      if (!x_shown[i]) continue;
      cairo_set_source_rgb(cr, 0, 0, 0);
      text(cr, px(v), y1 + 7 + (tight && i % 2 == 1 ? 13 : 0), label, tight ? 10.5 : kFont, 0.5, 0);
    }
    for (const auto& [v, label] : y_major) {
      grid_line(x0, py(v), x1, py(v), 0.80);
      cairo_set_source_rgb(cr, 0, 0, 0);
      text(cr, x0 - 6, py(v), label, kFont, 1, 0.5);
    }
    // Reference lines, dashed: the figure's unlabelled ones (e.g. the true value), then the
    // labelled ones (their labels are drawn over the series, below).
    const double dash[] = {3, 3};
    for (const double v : f.y_marks)
      if (!panel.y_axis) {
        cairo_set_dash(cr, dash, 2, 0);
        grid_line(x0, py(v), x1, py(v), 0.25);
        cairo_set_dash(cr, nullptr, 0, 0);
      }
    const std::vector<PlotMark> marks = marks_of(f, panel);
    for (const auto& m : marks) {
      const Rgb c = rgb(m.colour);
      const double dash_long[] = {7, 4};
      cairo_set_dash(cr, dash_long, 2, 0);
      cairo_set_source_rgb(cr, c.r, c.g, c.b);
      cairo_set_line_width(cr, 1.5);
      cairo_move_to(cr, x0, py(m.y));
      cairo_line_to(cr, x1, py(m.y));
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, x0, y0, x1 - x0, y1 - y0);
    cairo_stroke(cr);
    text(cr, (x0 + x1) / 2, y0 - 14, panel.title, 14, 0.5, 0.5, true);
    text(cr, (x0 + x1) / 2, y1 + 36, f.x_label, 13, 0.5, 0);
    const std::string& y_label = panel.y_axis ? panel.y_label : f.y_label;
    if (panel.y_axis || column == 0) {
      cairo_save(cr);
      cairo_translate(cr, x0 - 56, (y0 + y1) / 2);
      cairo_rotate(cr, -M_PI / 2);
      text(cr, 0, 0, y_label, 13, 0.5, 0.5);
      cairo_restore(cr);
    }
    // Series: IQR bars, lines, markers, labels.
    cairo_save(cr);
    cairo_rectangle(cr, x0, y0, x1 - x0, y1 - y0);
    cairo_clip(cr);
    for (const auto& s : panel.series) {
      const Rgb c = rgb(s.colour);
      cairo_new_path(cr);
      cairo_set_source_rgb(cr, c.r, c.g, c.b);
      cairo_set_line_width(cr, 1.2);
      for (const auto& p : s.points)
        if (p.lo && p.hi && (!yr.log || (*p.lo > 0 && *p.hi > 0))) {
          const double x = px(p.x);
          cairo_move_to(cr, x, py(*p.lo));
          cairo_line_to(cr, x, py(*p.hi));
          cairo_move_to(cr, x - 3, py(*p.lo));
          cairo_line_to(cr, x + 3, py(*p.lo));
          cairo_move_to(cr, x - 3, py(*p.hi));
          cairo_line_to(cr, x + 3, py(*p.hi));
          cairo_stroke(cr);
        }
      if (!s.hollow && s.points.size() > 1) {
        const double line_dash[] = {6, 4};
        cairo_new_path(cr);
        cairo_set_dash(cr, line_dash, s.dashed ? 2 : 0, 0);
        cairo_set_line_width(cr, 2);
        bool first = true;
        for (const auto& p : s.points) {
          if (first)
            cairo_move_to(cr, px(p.x), py(p.y));
          else
            cairo_line_to(cr, px(p.x), py(p.y));
          first = false;
        }
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
      }
      for (const auto& p : s.points) {
        cairo_new_path(cr);
        cairo_arc(cr, px(p.x), py(p.y), 4, 0, 2 * M_PI);
        if (s.hollow) {
          cairo_set_source_rgb(cr, 1, 1, 1);
          cairo_fill_preserve(cr);
          cairo_set_source_rgb(cr, c.r, c.g, c.b);
          cairo_set_line_width(cr, 1.6);
          cairo_stroke(cr);
        } else {
          cairo_fill(cr);
        }
      }
      for (const auto& p : s.points)
        if (!p.label.empty()) {
          cairo_set_source_rgb(cr, c.r * 0.8, c.g * 0.8, c.b * 0.8);
          text(cr, px(p.x) + 7, py(p.y), p.label, 10.5, 0, 0.5);
        }
    }
    cairo_restore(cr);
    // The reference lines' labels over the series, on a white ground, so that a bar or a line
    // behind one does not cross it out.
    for (const auto& m : marks) {
      if (m.label.empty() || m.in_legend) continue;
      cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
      cairo_set_font_size(cr, 11);
      cairo_text_extents_t e;
      cairo_text_extents(cr, m.label.c_str(), &e);
      const double tx = m.label_left ? x0 + 5 : x1 - 5 - e.width;
      cairo_set_source_rgb(cr, 1, 1, 1);
      cairo_rectangle(cr, tx - 2, py(m.y) - 17, e.width + 4, 14);
      cairo_fill(cr);
      const Rgb c = rgb(m.colour);
      cairo_set_source_rgb(cr, c.r, c.g, c.b);
      text(cr, tx, py(m.y) - 5, m.label, 11, 0, 1);
    }
    if (!panel.note.empty()) {
      cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
      text(cr, x0 + 8, y0 + 12, panel.note, 11, 0, 0.5);
    }
    if (!f.legend.empty()) continue;
    // The panel's legend below its x label, in two columns, so that it never hides a point.
    const auto entries = legend_of(f, panel);
    const std::size_t per_column = std::max<std::size_t>(1, legend_rows(entries));
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const double lx = x0 - 40 + (i < per_column ? 0.0 : (x1 - x0 + 40) / 2);
      const double ly =
          y1 + kBelowPlot + 8 + kLegendRow / 2 + kLegendRow * static_cast<double>(i % per_column);
      legend_entry(cr, lx, ly, entries[i]);
    }
  }
  // The figure's one legend, centred under every panel, column by column (entries that go
  // together, such as ours and the paper's, one under the other).
  if (!f.legend.empty()) {
    const double column = 250;
    const double left = (l.width - column * static_cast<double>(l.legend_columns)) / 2;
    const std::size_t rows = (f.legend.size() + l.legend_columns - 1) / l.legend_columns;
    for (std::size_t i = 0; i < f.legend.size(); ++i)
      legend_entry(cr, left + column * static_cast<double>(i / rows),
                   l.legend_top + kLegendRow * static_cast<double>(i % rows), f.legend[i]);
  }
}

} // namespace

void save_figure(const Figure& figure, const std::filesystem::path& svg,
                 const std::filesystem::path& png) {
  bool any = false;
  for (const auto& panel : figure.panels)
    for (const auto& s : panel.series)
      for (const auto& p : s.points)
        any = any || ((figure.x_axis == Axis::Linear || p.x > 0) &&
                      (figure.y_axis == Axis::Linear || p.y > 0));
  if (!any) throw kernel::InputError(svg.string(), "no point to draw");
  const Layout l = layout(figure);
  detail::render(
      l.width, l.height, [&](cairo_t* cr) { draw(cr, figure, l); }, svg, png);
}

} // namespace antkit::experiments
