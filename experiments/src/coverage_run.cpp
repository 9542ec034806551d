#include <antkit/experiments/coverage_run.hpp>
#include <antkit/experiments/drawing.hpp>
#include <antkit/io/atomic_file.hpp>
#include <cstdio>
#include <ostream>

namespace antkit::experiments {

uniform::CoverageResult run_coverage_traced(uniform::CoverageWorld& world,
                                            uniform::Algorithm algorithm, std::uint64_t seed,
                                            std::uint64_t trial, std::uint64_t limit,
                                            std::int64_t sensor,
                                            const std::filesystem::path& trace) {
  uniform::CoverageResult r;
  io::write_file_atomic(trace, [&](std::ostream& out) {
    out << "# antkit cover trace: the poses after each tick (tick 0: the start)\n"
        << "# sensor: " << sensor << "\ntick,robot,x,y,bearing\n";
    const uniform::TickObserver observer = [&out](const uniform::CoverageWorld& w,
                                                  std::uint64_t tick) {
      for (std::size_t i = 0; i < w.robot_count(); ++i) {
        const auto& p = w.robot(i);
        out << tick << ',' << i << ',' << p.cell.x << ',' << p.cell.y << ',' << int{p.bearing}
            << '\n';
      }
    };
    r = uniform::run_coverage(world, algorithm, seed, trial, limit, observer);
    out << "# claim viewed: " << r.viewed << "\n# claim viewable: " << r.viewable << '\n';
  });
  return r;
}

void save_coverage_figure(const std::string& algorithm, const uniform::CoverageWorld& world,
                          const uniform::CoverageResult& r, std::int64_t sensor,
                          const std::filesystem::path& svg, const std::filesystem::path& png) {
  const auto& map = world.map();
  GridPanel p;
  p.states = kernel::Grid<std::uint8_t>(map.width(), map.height(), 0);
  for (std::int32_t y = 0; y < map.height(); ++y)
    for (std::int32_t x = 0; x < map.width(); ++x) {
      const auto c = map[{x, y}];
      p.states[{x, y}] = c == kernel::Occupancy::Blocked   ? 2
                         : c == kernel::Occupancy::Unknown ? 3
                         : world.is_viewed({x, y})         ? 0
                                                           : 1;
    }
  for (const auto& robot : world.robots())
    p.robots.emplace_back(robot.cell.x + 0.5, robot.cell.y + 0.5);
  GridLegend legend;
  legend.states = {{"#ffffff", "free, viewed"},
                   {"#9e9e9e", "free, not viewed"},
                   {"#202020", "blocked"},
                   {"#606060", "unknown"}};
  legend.robot = {"#d62728", "robots at the end"};
  char coverage[32];
  std::snprintf(coverage, sizeof coverage, "%.2f",
                100.0 * static_cast<double>(r.viewed) / static_cast<double>(r.viewable));
  const std::string caption =
      std::to_string(r.robots) + " robot(s), sensor distance " + std::to_string(sensor) + ": " +
      coverage + " % of the viewable free cells viewed in " + std::to_string(r.movements) +
      " movements (stop: " + std::string(uniform::stop_reason_name(r.stop)) + ").";
  save_grid_figure(algorithm + " coverage (paper 004)", caption, {p}, legend, svg, png);
}

} // namespace antkit::experiments
