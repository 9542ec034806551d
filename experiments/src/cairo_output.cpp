#include "cairo_output.hpp"

#include <antkit/experiments/plot.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <atomic>
#include <cairo-svg.h>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fontconfig/fontconfig.h>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

namespace antkit::experiments {

namespace detail {

namespace {

void check(cairo_status_t status, const std::filesystem::path& path) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw kernel::InputError(path.string(), std::string("could not write the figure: ") +
                                                cairo_status_to_string(status));
}

// Cairo names the SVG's groups after a process-wide count of the surfaces it has made
// (id="surface37"), so the same drawing made twice in one process differs in those names. They are
// renumbered here in order of appearance (references move with them), so that a figure's bytes
// depend only on the drawing.
void renumber_surfaces(const std::filesystem::path& svg) {
  std::string text;
  {
    std::ifstream in(svg, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  std::map<std::string, std::string> names;
  std::string out;
  out.reserve(text.size());
  const std::string key = "surface";
  std::size_t at = 0;
  for (std::size_t hit; (hit = text.find(key, at)) != std::string::npos;) {
    std::size_t end = hit + key.size();
    while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end])) != 0) ++end;
    out.append(text, at, hit - at);
    const std::string name = text.substr(hit, end - hit);
    if (end == hit + key.size()) {
      out += name;
    } else {
      auto [it, fresh] = names.try_emplace(name, "");
      if (fresh) it->second = key + std::to_string(names.size());
      out += it->second;
    }
    at = end;
  }
  out.append(text, at, std::string::npos);
  std::ofstream rewrite(svg, std::ios::binary | std::ios::trunc);
  rewrite << out;
  if (!rewrite.flush()) throw kernel::InputError(svg.string(), "could not write the figure");
}

} // namespace

void text(cairo_t* cr, double x, double y, const std::string& s, double size, double align_x,
          double align_y, bool bold) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e, cap;
  cairo_text_extents(cr, s.c_str(), &e);
  // Vertically the box is the capitals' height, whatever the letters: texts side by side (a
  // legend's names, with and without descenders) share one baseline.
  cairo_text_extents(cr, "H", &cap);
  cairo_move_to(cr, x - align_x * e.width - e.x_bearing, y + (1 - align_y) * cap.height);
  cairo_show_text(cr, s.c_str());
}

void caption_lines(cairo_t* cr, const std::string& caption, double cx, double bottom, double size) {
  std::vector<std::string> lines{""};
  for (const char ch : caption) {
    if (ch == '\n')
      lines.emplace_back();
    else
      lines.back() += ch;
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  for (std::size_t i = 0; i < lines.size(); ++i)
    text(cr, cx, bottom - std::round(size * 1.36) * static_cast<double>(lines.size() - 1 - i),
         lines[i], size, 0.5, 0.5);
}

Rgb rgb(const std::string& hex) {
  unsigned v = 0;
  if (hex.size() == 7 && hex[0] == '#' && std::sscanf(hex.c_str() + 1, "%6x", &v) == 1)
    return {((v >> 16) & 0xFF) / 255.0, ((v >> 8) & 0xFF) / 255.0, (v & 0xFF) / 255.0};
  return {0, 0, 0};
}

std::atomic<bool> drawn{false};

void render(double width, double height, const std::function<void(cairo_t*)>& draw,
            const std::filesystem::path& svg, const std::filesystem::path& png) {
  // The caches are released at exit too (so that LeakSanitizer, which checks at exit after the
  // handlers registered later than its own, finds nothing of Cairo's or fontconfig's), for a
  // program that never calls release_drawing_caches.
  static const bool at_exit = [] {
    std::atexit([] { release_drawing_caches(); });
    return true;
  }();
  (void)at_exit;
  drawn = true;
  // Each file is written under a temporary name and renamed into place when whole
  // (io::write_file_atomic_at): a failed drawing leaves neither.
  const auto write_svg = [&](const std::filesystem::path& svg_tmp) {
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_svg_surface_create(svg_tmp.c_str(), width, height), &cairo_surface_destroy);
    check(cairo_surface_status(surface.get()), svg);
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()),
                                                          &cairo_destroy);
    draw(cr.get());
    check(cairo_status(cr.get()), svg);
    cairo_surface_finish(surface.get());
    check(cairo_surface_status(surface.get()), svg);
    renumber_surfaces(svg_tmp);
  };
  const auto write_png = [&](const std::filesystem::path& png_tmp) {
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(width),
                                   static_cast<int>(height)),
        &cairo_surface_destroy);
    check(cairo_surface_status(surface.get()), png);
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()),
                                                          &cairo_destroy);
    draw(cr.get());
    check(cairo_status(cr.get()), png);
    check(cairo_surface_write_to_png(surface.get(), png_tmp.c_str()), png);
  };
  if (!svg.empty() && !png.empty())
    io::write_file_atomic_at(svg, [&](const std::filesystem::path& svg_tmp) {
      write_svg(svg_tmp);
      io::write_file_atomic_at(png, write_png);
    });
  else if (!svg.empty())
    io::write_file_atomic_at(svg, write_svg);
  else if (!png.empty())
    io::write_file_atomic_at(png, write_png);
}

} // namespace detail

void release_drawing_caches() noexcept {
  // Cairo's font caches hold fontconfig objects; fontconfig's configuration is global. Both are
  // rebuilt on the next use. Only after a drawing: fontconfig is not to be finalised twice.
  if (!detail::drawn.exchange(false)) return;
  cairo_debug_reset_static_data();
  FcFini();
}

} // namespace antkit::experiments
