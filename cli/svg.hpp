#pragma once
// A small SVG writer for the figures the subcommands draw (maps, tours, trails). World coordinates
// are mapped to the picture by a scale and an offset; y may be flipped so that arenas (y up) and
// grids (y down, row 0 at the top) both draw the right way up.
#include <antkit/kernel/grid.hpp>
#include <filesystem>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace antkit::cli {

class Svg {
public:
  // The picture shows the world rectangle [x0, x1] x [y0, y1] at `scale` pixels per unit.
  // y_down: world y grows downward (grids); otherwise upward (arenas).
  Svg(double x0, double y0, double x1, double y1, double scale, bool y_down);

  // Cells of a grid drawn as unit squares at (x, y) .. (x+1, y+1), in world units of cells.
  void grid_cells(const kernel::OccupancyGrid& grid, const std::string& blocked_fill,
                  const std::string& unknown_fill);
  void rect(double x, double y, double w, double h, const std::string& fill, double opacity = 1.0);
  void polyline(std::span<const std::pair<double, double>> points, const std::string& stroke,
                double width, double opacity = 1.0);
  void polygon(std::span<const std::pair<double, double>> points, const std::string& fill,
               const std::string& stroke, double width);
  void line(double xa, double ya, double xb, double yb, const std::string& stroke, double width);
  void circle(double x, double y, double r, const std::string& fill);
  void text(double x, double y, const std::string& s, double size_px);

  [[nodiscard]] std::string str() const;
  // Writes atomically (antkit::geometry::write_file_atomic); throws InputError on failure.
  void save(const std::filesystem::path& path) const;

private:
  [[nodiscard]] double px(double x) const { return (x - x0_) * scale_; }
  [[nodiscard]] double py(double y) const {
    return y_down_ ? (y - y0_) * scale_ : (y1_ - y) * scale_;
  }
  double x0_, y0_, x1_, y1_, scale_;
  bool y_down_;
  std::ostringstream body_;
};

} // namespace antkit::cli
