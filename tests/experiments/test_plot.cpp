// The figures' layout (experiments/plot.hpp): a picture as tall as its contents (no empty band
// above the caption), panels in rows, one legend per figure, a panel's own y axis, labelled
// reference lines and points, and the same bytes for the same figure.
#include "scratch_dir.hpp"

#include <algorithm>
#include <antkit/experiments/plot.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace ex = antkit::experiments;

namespace {

// One directory for the test process (ctest runs each test case in its own), removed when it ends.
const std::filesystem::path& scratch() {
  static const antkit::test::ScratchDir dir("plot-test");
  return dir.path();
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The SVG's size, from its viewBox "0 0 W H".
std::pair<double, double> svg_size(const std::filesystem::path& svg) {
  const std::string text = slurp(svg);
  const auto at = text.find("viewBox=\"0 0 ");
  REQUIRE(at != std::string::npos);
  std::istringstream in(text.substr(at + 13));
  double w = 0, h = 0;
  in >> w >> h;
  return {w, h};
}

ex::PlotSeries series(const std::string& name, const std::string& colour, double scale) {
  ex::PlotSeries s{name, colour, false, false, {}};
  for (int k = 1; k <= 5; ++k)
    s.points.push_back({10.0 * k, scale / (k * k), 0.9 * scale / (k * k), 1.1 * scale / (k * k)});
  return s;
}

ex::Figure one_panel(const std::string& caption) {
  ex::Figure f;
  f.title = "a figure";
  f.x_label = "x";
  f.y_label = "y";
  f.caption = caption;
  ex::PlotPanel p;
  p.series = {series("a", "#1e5bd8", 1), series("b", "#d81e1e", 2)};
  f.panels.push_back(p);
  return f;
}

std::pair<double, double> size_of(const ex::Figure& f, const std::string& stem) {
  const auto dir = scratch();
  ex::save_figure(f, dir / (stem + ".svg"), dir / (stem + ".png"));
  return svg_size(dir / (stem + ".svg"));
}

} // namespace

TEST_CASE("save_figure: the picture ends under its caption - no empty band", "[plot]") {
  const auto [w1, h1] = size_of(one_panel("one line"), "one");
  const auto [w3, h3] = size_of(one_panel("one line\ntwo lines\nthree lines"), "three");
  CHECK(w1 == 640);
  CHECK(w3 == 640);
  // Each caption line adds its own height and nothing else; the plot (300 px), its title, ticks,
  // x label and a one-row legend fit in well under the former fixed 560 px.
  CHECK(h3 - h1 == 32);
  CHECK(h1 < 480);
  CHECK(h1 > 300 + 64);
}

TEST_CASE("save_figure: panels in rows and one legend for the figure", "[plot]") {
  ex::Figure f = one_panel("caption");
  f.panels.resize(4, f.panels.front());
  const auto [w_row, h_row] = size_of(f, "row");
  CHECK(w_row == 4 * 420);
  f.columns = 2;
  const auto [w_grid, h_grid] = size_of(f, "grid");
  CHECK(w_grid == 2 * 420);
  CHECK(h_grid > h_row + 300);
  // One legend below every panel instead of one under each: the rows come closer together.
  f.legend = f.panels.front().series;
  const auto [w_one, h_one] = size_of(f, "one_legend");
  CHECK(w_one == w_grid);
  CHECK(h_one < h_grid);
}

TEST_CASE("save_figure: log axes, a panel's own y axis, labelled marks and points - the same "
          "bytes twice",
          "[plot]") {
  ex::Figure f = one_panel("log axes on the left, a linear efficiency on the right");
  f.x_axis = ex::Axis::Log;
  f.y_axis = ex::Axis::Log;
  f.panels.front().series.front().points.front().label = "d=10";
  ex::PlotPanel own;
  own.title = "efficiency";
  own.y_axis = ex::Axis::Linear;
  own.y_label = "efficiency";
  own.y_from_zero = true;
  own.series = {series("a", "#1e5bd8", 0.5)};
  own.marks = {{0.9, "threshold", "#b00000", true, false},
               {0.4, "in the legend", "#404040", false, true}};
  f.panels.push_back(own);
  f.legend = f.panels.front().series;
  const auto dir = scratch();
  ex::save_figure(f, dir / "a.svg", dir / "a.png");
  ex::save_figure(f, dir / "b.svg", dir / "b.png");
  CHECK(svg_size(dir / "a.svg").first == 840);
  CHECK(slurp(dir / "a.svg") == slurp(dir / "b.svg"));
  CHECK(slurp(dir / "a.png") == slurp(dir / "b.png"));
  CHECK(slurp(dir / "a.png").substr(1, 3) == "PNG");
}

TEST_CASE("save_figure: nothing to draw on a log axis is refused, no file left", "[plot]") {
  ex::Figure f = one_panel("caption");
  f.y_axis = ex::Axis::Log;
  for (auto& s : f.panels.front().series)
    for (auto& p : s.points) p.y = -p.y;
  const auto dir = scratch();
  CHECK_THROWS_AS(ex::save_figure(f, dir / "none.svg", dir / "none.png"),
                  antkit::kernel::InputError);
  CHECK_FALSE(std::filesystem::exists(dir / "none.svg"));
  CHECK_FALSE(std::filesystem::exists(dir / "none.png"));
}

TEST_CASE("save_figure: written whole or not at all - a PNG that cannot be written leaves no SVG "
          "and no temporary file",
          "[plot]") {
  const ex::Figure f = one_panel("caption");
  const auto dir = scratch() / "atomic";
  std::filesystem::create_directories(dir);
  try {
    ex::save_figure(f, dir / "fig.svg", dir / "absent" / "fig.png");
    FAIL("a PNG in a missing directory was written");
  } catch (const antkit::kernel::InputError& e) {
    CHECK(e.where() == (dir / "absent" / "fig.png").string());
    CHECK(e.message().rfind("could not write the figure: ", 0) == 0);
  }
  CHECK(std::filesystem::is_empty(dir));
  ex::save_figure(f, dir / "fig.svg", dir / "fig.png");
  ex::save_figure(f, "", dir / "only.png");
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"fig.png", "fig.svg", "only.png"});
}
