#include "svg.hpp"

#include <antkit/geometry/atomic_file.hpp>
#include <cmath>
#include <iomanip>

namespace antkit::cli {

namespace {
std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '&':
      out += "&amp;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  }
  return out;
}
} // namespace

Svg::Svg(double x0, double y0, double x1, double y1, double scale, bool y_down)
    : x0_(x0), y0_(y0), x1_(x1), y1_(y1), scale_(scale), y_down_(y_down) {
  body_ << std::fixed << std::setprecision(2);
}

void Svg::grid_cells(const kernel::OccupancyGrid& grid, const std::string& blocked_fill,
                     const std::string& unknown_fill) {
  // One rectangle per horizontal run of equal cells keeps large maps small.
  for (std::int32_t y = 0; y < grid.height(); ++y) {
    std::int32_t x = 0;
    while (x < grid.width()) {
      const auto v = grid[{x, y}];
      std::int32_t end = x + 1;
      while (end < grid.width() && grid[{end, y}] == v) ++end;
      if (v == kernel::Occupancy::Blocked) rect(x, y, end - x, 1, blocked_fill);
      if (v == kernel::Occupancy::Unknown) rect(x, y, end - x, 1, unknown_fill);
      x = end;
    }
  }
}

void Svg::rect(double x, double y, double w, double h, const std::string& fill, double opacity) {
  const double top = y_down_ ? py(y) : py(y + h);
  body_ << "<rect x=\"" << px(x) << "\" y=\"" << top << "\" width=\"" << w * scale_
        << "\" height=\"" << h * scale_ << "\" fill=\"" << fill
        << "\" shape-rendering=\"crispEdges\"";
  if (opacity < 1.0) body_ << " fill-opacity=\"" << opacity << "\"";
  body_ << "/>\n";
}

void Svg::polyline(std::span<const std::pair<double, double>> points, const std::string& stroke,
                   double width, double opacity) {
  if (points.empty()) return;
  body_ << "<polyline fill=\"none\" stroke=\"" << stroke << "\" stroke-width=\"" << width
        << "\" stroke-linejoin=\"round\"";
  if (opacity < 1.0) body_ << " stroke-opacity=\"" << opacity << "\"";
  body_ << " points=\"";
  for (const auto& [x, y] : points) body_ << px(x) << ',' << py(y) << ' ';
  body_ << "\"/>\n";
}

void Svg::polygon(std::span<const std::pair<double, double>> points, const std::string& fill,
                  const std::string& stroke, double width) {
  body_ << "<polygon fill=\"" << fill << "\" stroke=\"" << stroke << "\" stroke-width=\"" << width
        << "\" fill-rule=\"evenodd\" points=\"";
  for (const auto& [x, y] : points) body_ << px(x) << ',' << py(y) << ' ';
  body_ << "\"/>\n";
}

void Svg::line(double xa, double ya, double xb, double yb, const std::string& stroke,
               double width) {
  body_ << "<line x1=\"" << px(xa) << "\" y1=\"" << py(ya) << "\" x2=\"" << px(xb) << "\" y2=\""
        << py(yb) << "\" stroke=\"" << stroke << "\" stroke-width=\"" << width << "\"/>\n";
}

void Svg::circle(double x, double y, double r, const std::string& fill) {
  body_ << "<circle cx=\"" << px(x) << "\" cy=\"" << py(y) << "\" r=\"" << r * scale_
        << "\" fill=\"" << fill << "\"/>\n";
}

void Svg::text(double x, double y, const std::string& s, double size_px) {
  body_ << "<text x=\"" << px(x) << "\" y=\"" << py(y)
        << "\" font-family=\"sans-serif\" font-size=\"" << size_px << "\">" << escape(s)
        << "</text>\n";
}

std::string Svg::str() const {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  const double w = std::ceil((x1_ - x0_) * scale_), h = std::ceil((y1_ - y0_) * scale_);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
      << "\" viewBox=\"0 0 " << w << ' ' << h << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << body_.str() << "</svg>\n";
  return out.str();
}

void Svg::save(const std::filesystem::path& path) const {
  geometry::write_file_atomic(path, str());
}

} // namespace antkit::cli
