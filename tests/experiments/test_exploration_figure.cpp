// save_exploration_figure (experiments/explore_tables.hpp), the picture of `antkit explore`: the
// same exploration drawn twice gives the same bytes, and a file that cannot be written is refused
// by its name with nothing left.
#include "scratch_dir.hpp"

#include <antkit/experiments/explore_tables.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/los/explore.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
namespace los = antkit::los;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

TEST_CASE("save_exploration_figure: the same exploration, the same picture", "[los]") {
  antkit::kernel::OccupancyGrid grid(12, 10, antkit::kernel::Occupancy::Free);
  grid.at({5, 4}) = antkit::kernel::Occupancy::Blocked;
  const auto pair = los::start_pair(grid, los::default_start(grid));
  const auto r = los::explore(grid, pair[0], pair[1], los::ExploreOptions{});
  REQUIRE(r.completed);
  const antkit::test::ScratchDir scratch("explore-figure");
  const fs::path& dir = scratch.path();
  antkit::experiments::save_exploration_figure("frontier", r, dir / "a.svg", "");
  antkit::experiments::save_exploration_figure("frontier", r, dir / "b.svg", "");
  const std::string a = slurp(dir / "a.svg");
  CHECK_FALSE(a.empty());
  CHECK(a == slurp(dir / "b.svg"));
  CHECK_THROWS_AS(
      antkit::experiments::save_exploration_figure("frontier", r, dir / "absent" / "c.svg", ""),
      antkit::kernel::InputError);
  CHECK_FALSE(fs::exists(dir / "absent"));
}
