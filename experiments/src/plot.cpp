// Figures with Cairo (plot.hpp).
#include "cairo_output.hpp"

#include <algorithm>
#include <antkit/experiments/plot.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cairo.h>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace antkit::experiments {

namespace {

constexpr double kHeight = 560;
// A lone panel gets room for a long title and caption; panels side by side 420 each.
double panel_width(std::size_t panels) {
  return panels == 1 ? 640 : 420;
}
constexpr double kLeft = 70, kRight = 30, kTop = 64, kBottom = 196; // margins of a panel's plot

using detail::rgb;
using detail::Rgb;
using detail::text;

// One axis: its data range, then its drawn range (decades on a log axis, "nice" round steps on a
// linear one) and its ticks.
struct Scale {
  bool log = false;
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
      lo = std::floor(lo);
      hi = std::ceil(hi);
      if (hi <= lo) hi = lo + 1;
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
  // Room beyond lo and hi (linear axes), so that points and bars at the ends are not on the frame.
  double pad_lo = 0, pad_hi = 0;
  void pad(bool below) {
    if (log) return;
    pad_hi = 0.04 * (hi - lo);
    pad_lo = below ? pad_hi : 0;
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

std::string decade_label(int k) {
  // 10^k as a plain number for the decades a reader meets here (1 .. 10^7), else "1e<k>".
  if (k >= 0 && k <= 7) {
    std::string compact = "1" + std::string(static_cast<std::size_t>(k), '0');
    // Thin groups of three from the right: 10 000, 100 000, 1 000 000.
    std::string grouped;
    for (std::size_t i = 0; i < compact.size(); ++i) {
      if (i > 0 && (compact.size() - i) % 3 == 0 && compact.size() > 4) grouped += ' ';
      grouped += compact[i];
    }
    return grouped;
  }
  return "1e" + std::to_string(k);
}

// The ticks of an axis: (value, labelled) pairs; a log axis has its decades labelled and 2..9 as
// light lines, a linear one its steps; categories label 0, 1, 2, ...
std::vector<std::pair<double, std::string>>
ticks(const Scale& sc, const std::vector<std::string>& categories, std::vector<double>& minor) {
  std::vector<std::pair<double, std::string>> major;
  if (!categories.empty()) {
    for (std::size_t i = 0; i < categories.size(); ++i)
      major.emplace_back(static_cast<double>(i), categories[i]);
    return major;
  }
  if (sc.log) {
    for (int d = static_cast<int>(sc.lo); d <= static_cast<int>(sc.hi); ++d)
      for (int m = 1; m <= 9 && (m == 1 || d < static_cast<int>(sc.hi)); ++m) {
        const double v = m * std::pow(10.0, d);
        if (m == 1)
          major.emplace_back(v, decade_label(d));
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

void draw(cairo_t* cr, const Figure& f, double width) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  Scale xr, yr;
  xr.log = f.x_axis == Axis::Log;
  yr.log = f.y_axis == Axis::Log;
  for (const auto& panel : f.panels)
    for (const auto& s : panel.series)
      for (const auto& p : s.points) {
        xr.add(p.x);
        yr.add(p.y);
        if (p.lo && p.hi) yr.add(*p.lo), yr.add(*p.hi);
      }
  for (const double y : f.y_marks) yr.add(y);
  if (!f.x_categories.empty()) {
    xr.lo = -0.5;
    xr.hi = static_cast<double>(f.x_categories.size()) - 0.5;
  } else {
    xr.finish(false);
    xr.pad(true);
  }
  yr.finish(f.y_from_zero);
  yr.pad(!f.y_from_zero);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, width / 2, 22, f.title, 17, 0.5, 0.5, true);
  detail::caption_lines(cr, f.caption, width / 2, kHeight - 10);
  std::vector<double> x_minor, y_minor;
  const auto x_major = ticks(xr, f.x_categories, x_minor);
  const auto y_major = ticks(yr, {}, y_minor);
  for (std::size_t k = 0; k < f.panels.size(); ++k) {
    const PlotPanel& panel = f.panels[k];
    const double pw = panel_width(f.panels.size());
    const double x0 = pw * static_cast<double>(k) + kLeft;
    const double x1 = pw * static_cast<double>(k + 1) - kRight;
    const double y0 = kTop, y1 = kHeight - kBottom; // y0 top, y1 bottom
    auto px = [&](double v) { return x0 + xr.unit(v) * (x1 - x0); };
    auto py = [&](double v) { return y1 - yr.unit(v) * (y1 - y0); };
    // Grid and ticks: labelled ticks as grey lines, a log axis' 2..9 as light ones.
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
    for (std::size_t i = 0; i < x_major.size(); ++i) {
      const auto& [v, label] = x_major[i];
      grid_line(px(v), y0, px(v), y1, 0.80);
      cairo_set_source_rgb(cr, 0, 0, 0);
      text(cr, px(v), y1 + 6 + (tight && i % 2 == 1 ? 12 : 0), label, tight ? 9.5 : 11, 0.5, 0);
    }
    for (const auto& [v, label] : y_major) {
      grid_line(x0, py(v), x1, py(v), 0.80);
      cairo_set_source_rgb(cr, 0, 0, 0);
      text(cr, x0 - 5, py(v), label, 11, 1, 0.5);
    }
    // Reference lines (e.g. the true value), dashed black.
    for (const double v : f.y_marks) {
      const double dash[] = {3, 3};
      cairo_set_dash(cr, dash, 2, 0);
      grid_line(x0, py(v), x1, py(v), 0.25);
      cairo_set_dash(cr, nullptr, 0, 0);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, x0, y0, x1 - x0, y1 - y0);
    cairo_stroke(cr);
    text(cr, (x0 + x1) / 2, y0 - 12, panel.title, 14, 0.5, 0.5, true);
    text(cr, (x0 + x1) / 2, y1 + 34, f.x_label, 12, 0.5, 0);
    if (k == 0) {
      cairo_save(cr);
      cairo_translate(cr, 16, (y0 + y1) / 2);
      cairo_rotate(cr, -M_PI / 2);
      text(cr, 0, 0, f.y_label, 12, 0.5, 0.5);
      cairo_restore(cr);
    }
    // Series: IQR bars, lines, markers.
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
        const double dash[] = {6, 4};
        cairo_new_path(cr);
        cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
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
    }
    cairo_restore(cr);
    if (!panel.note.empty()) {
      cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
      text(cr, x0 + 8, y0 + 12, panel.note, 10.5, 0, 0.5);
    }
    // Legend below the panel's x label, in two columns, so that it never hides a point.
    const auto& entries = panel.legend.empty() ? panel.series : panel.legend;
    // Two columns, unless a name would run into the second column (about 26 characters fit).
    std::size_t longest = 0;
    for (const auto& e : entries) longest = std::max(longest, e.name.size());
    const std::size_t per_column =
        longest > 26 || entries.size() < 2 ? entries.size() : (entries.size() + 1) / 2;
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const PlotSeries& s = entries[i];
      const double lx = x0 - 40 + (i < per_column ? 0.0 : (x1 - x0 + 40) / 2);
      const double ly =
          y1 + 62 + 16 * static_cast<double>(i % std::max<std::size_t>(1, per_column));
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
        cairo_arc(cr, lx + 18, ly, 3.5, 0, 2 * M_PI);
        cairo_fill(cr);
      }
      cairo_set_source_rgb(cr, 0, 0, 0);
      text(cr, lx + 36, ly, s.name, 11, 0, 0.5);
    }
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
  const double width =
      panel_width(figure.panels.size()) * static_cast<double>(figure.panels.size());
  detail::render(
      width, kHeight, [&](cairo_t* cr) { draw(cr, figure, width); }, svg, png);
}

} // namespace antkit::experiments
