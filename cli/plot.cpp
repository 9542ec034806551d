// Log-log figures with Cairo (plot.hpp).
#include "plot.hpp"

#include <algorithm>
#include <antkit/kernel/input_error.hpp>
#include <cairo-svg.h>
#include <cairo.h>
#include <cmath>
#include <cstdio>
#include <fontconfig/fontconfig.h>
#include <limits>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

namespace antkit::cli {

namespace {

constexpr double kWidthPerPanel = 420, kHeight = 530;
constexpr double kLeft = 70, kRight = 30, kTop = 64, kBottom = 166; // margins of a panel's plot

struct Rgb {
  double r, g, b;
};
Rgb rgb(const std::string& hex) {
  unsigned v = 0;
  if (hex.size() == 7 && hex[0] == '#' && std::sscanf(hex.c_str() + 1, "%6x", &v) == 1)
    return {((v >> 16) & 0xFF) / 255.0, ((v >> 8) & 0xFF) / 255.0, (v & 0xFF) / 255.0};
  return {0, 0, 0};
}

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = 0; // in log10, decade-rounded later
  void add(double v) {
    if (!(v > 0) || !std::isfinite(v)) return;
    lo = std::min(lo, std::log10(v));
    hi = std::max(hi, std::log10(v));
  }
  void round_to_decades() {
    lo = std::floor(lo);
    hi = std::ceil(hi);
    if (hi <= lo) hi = lo + 1;
  }
};

void text(cairo_t* cr, double x, double y, const std::string& s, double size, double align_x,
          double align_y, bool bold = false) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_move_to(cr, x - align_x * e.width - e.x_bearing, y - align_y * e.height - e.y_bearing);
  cairo_show_text(cr, s.c_str());
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

void draw(cairo_t* cr, const LogLogFigure& f, double width) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  Range xr, yr;
  for (const auto& panel : f.panels)
    for (const auto& s : panel.series)
      for (const auto& p : s.points) {
        xr.add(p.x);
        yr.add(p.y);
        if (p.lo && p.hi) yr.add(*p.lo), yr.add(*p.hi);
      }
  xr.round_to_decades();
  yr.round_to_decades();
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, width / 2, 22, f.title, 17, 0.5, 0.5, true);
  // The caption, one line per '\n', at the bottom.
  std::vector<std::string> lines{""};
  for (const char ch : f.caption) {
    if (ch == '\n')
      lines.emplace_back();
    else
      lines.back() += ch;
  }
  for (std::size_t i = 0; i < lines.size(); ++i)
    text(cr, width / 2, kHeight - 10 - 15 * static_cast<double>(lines.size() - 1 - i), lines[i], 11,
         0.5, 0.5);
  for (std::size_t k = 0; k < f.panels.size(); ++k) {
    const PlotPanel& panel = f.panels[k];
    const double x0 = kWidthPerPanel * static_cast<double>(k) + kLeft;
    const double x1 = kWidthPerPanel * static_cast<double>(k + 1) - kRight;
    const double y0 = kTop, y1 = kHeight - kBottom; // y0 top, y1 bottom
    auto px = [&](double v) { return x0 + (std::log10(v) - xr.lo) / (xr.hi - xr.lo) * (x1 - x0); };
    auto py = [&](double v) { return y1 - (std::log10(v) - yr.lo) / (yr.hi - yr.lo) * (y1 - y0); };
    // Grid and ticks: every decade labelled, 2..9 as light lines.
    cairo_set_line_width(cr, 1);
    for (int d = static_cast<int>(xr.lo); d <= static_cast<int>(xr.hi); ++d)
      for (int m = 1; m <= 9 && (m == 1 || d < static_cast<int>(xr.hi)); ++m) {
        const double v = m * std::pow(10.0, d), x = px(v);
        cairo_set_source_rgb(cr, m == 1 ? 0.80 : 0.93, m == 1 ? 0.80 : 0.93, m == 1 ? 0.80 : 0.93);
        cairo_move_to(cr, x, y0);
        cairo_line_to(cr, x, y1);
        cairo_stroke(cr);
        if (m == 1) {
          cairo_set_source_rgb(cr, 0, 0, 0);
          text(cr, x, y1 + 6, decade_label(d), 11, 0.5, 0);
        }
      }
    for (int d = static_cast<int>(yr.lo); d <= static_cast<int>(yr.hi); ++d)
      for (int m = 1; m <= 9 && (m == 1 || d < static_cast<int>(yr.hi)); ++m) {
        const double v = m * std::pow(10.0, d), y = py(v);
        cairo_set_source_rgb(cr, m == 1 ? 0.80 : 0.93, m == 1 ? 0.80 : 0.93, m == 1 ? 0.80 : 0.93);
        cairo_move_to(cr, x0, y);
        cairo_line_to(cr, x1, y);
        cairo_stroke(cr);
        if (m == 1) {
          cairo_set_source_rgb(cr, 0, 0, 0);
          text(cr, x0 - 5, y, decade_label(d), 11, 1, 0.5);
        }
      }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, x0, y0, x1 - x0, y1 - y0);
    cairo_stroke(cr);
    text(cr, (x0 + x1) / 2, y0 - 12, panel.title, 14, 0.5, 0.5, true);
    text(cr, (x0 + x1) / 2, y1 + 30, f.x_label, 12, 0.5, 0);
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
        if (p.lo && p.hi && *p.lo > 0 && *p.hi > 0) {
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
    const std::size_t per_column = (entries.size() + 1) / 2;
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const PlotSeries& s = entries[i];
      const double lx = x0 - 40 + (i < per_column ? 0.0 : (x1 - x0 + 40) / 2);
      const double ly = y1 + 62 + 17 * static_cast<double>(i % per_column);
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

// A temporary name beside `path`, renamed over it once complete.
std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  return path.parent_path() /
         ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()));
}

void check(cairo_status_t status, const std::filesystem::path& path) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw kernel::InputError(path.string(), std::string("could not write the figure: ") +
                                                cairo_status_to_string(status));
}

void publish(const std::filesystem::path& tmp, const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw kernel::InputError(path.string(), "could not write the figure: " + ec.message());
  }
}

} // namespace

void release_drawing_caches() noexcept {
  // Cairo's font caches hold fontconfig objects; fontconfig's configuration is global. Both are
  // rebuilt on the next use.
  cairo_debug_reset_static_data();
  FcFini();
}

void save_figure(const LogLogFigure& figure, const std::filesystem::path& svg,
                 const std::filesystem::path& png) {
  bool any = false;
  for (const auto& panel : figure.panels)
    for (const auto& s : panel.series)
      for (const auto& p : s.points) any = any || (p.x > 0 && p.y > 0);
  if (!any) throw kernel::InputError(svg.string(), "no point to draw");
  const double width = kWidthPerPanel * static_cast<double>(figure.panels.size());
  const std::filesystem::path svg_tmp = temporary_beside(svg), png_tmp = temporary_beside(png);
  auto cleanup = [&] {
    std::error_code ec;
    std::filesystem::remove(svg_tmp, ec);
    std::filesystem::remove(png_tmp, ec);
  };
  try {
    {
      std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
          cairo_svg_surface_create(svg_tmp.c_str(), width, kHeight), &cairo_surface_destroy);
      check(cairo_surface_status(surface.get()), svg);
      std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()),
                                                            &cairo_destroy);
      draw(cr.get(), figure, width);
      check(cairo_status(cr.get()), svg);
      cairo_surface_finish(surface.get());
      check(cairo_surface_status(surface.get()), svg);
    }
    {
      std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
          cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(width),
                                     static_cast<int>(kHeight)),
          &cairo_surface_destroy);
      check(cairo_surface_status(surface.get()), png);
      std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()),
                                                            &cairo_destroy);
      draw(cr.get(), figure, width);
      check(cairo_status(cr.get()), png);
      check(cairo_surface_write_to_png(surface.get(), png_tmp.c_str()), png);
    }
    publish(svg_tmp, svg);
    publish(png_tmp, png);
  } catch (...) {
    cleanup();
    throw;
  }
}

} // namespace antkit::cli
