#pragma once
// Internal to antkit_experiments: one drawing function rendered twice, to SVG and to PNG, and the
// text helper the figures share.
#include <atomic>
#include <cairo.h>
#include <filesystem>
#include <functional>
#include <string>

namespace antkit::experiments::detail {

// Draws `draw` on a width x height SVG surface and on a PNG image of the same size; each file is
// written to a temporary name beside it and renamed, so no partial file is left (an empty path:
// that file is not made). Throws
// kernel::InputError(path, ...) when a file cannot be written.
// Set by render(); cleared by release_drawing_caches().
extern std::atomic<bool> drawn;

void render(double width, double height, const std::function<void(cairo_t*)>& draw,
            const std::filesystem::path& svg, const std::filesystem::path& png);

// Text at (x, y), aligned by the fractions align_x, align_y of its extents (0.5, 0.5: centred).
void text(cairo_t* cr, double x, double y, const std::string& s, double size, double align_x,
          double align_y, bool bold = false);

// A caption, one line per '\n', centred on cx, its last line at height `bottom`.
void caption_lines(cairo_t* cr, const std::string& caption, double cx, double bottom,
                   double size = 11);

struct Rgb {
  double r, g, b;
};
// "#rrggbb"; black for anything else.
Rgb rgb(const std::string& hex);

} // namespace antkit::experiments::detail
