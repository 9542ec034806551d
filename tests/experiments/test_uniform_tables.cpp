// write_tables and tables_summary (experiments/uniform_tables.hpp), what `antkit cover-experiment`
// writes and prints: the two files are tables_csv's and tables_markdown's bytes, the summary's
// numbers are the rows' means rounded as the Markdown prints them, its hash the rows' in order, and
// a file that cannot be written is refused by its name with nothing left behind.
#include "scratch_dir.hpp"

#include <antkit/experiments/uniform_tables.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
namespace ex = antkit::experiments::uniform_tables;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

TEST_CASE("write_tables: the files and the summary of cover-experiment", "[uniform]") {
  ex::TablesConfig c;
  c.width = 16;
  c.height = 16;
  c.runs = 1;
  c.sensor = 3;
  const auto rows = ex::run_tables(c, antkit::algorithms::Runner{});
  REQUIRE(rows.size() == ex::kPaperTables.size());
  const antkit::test::ScratchDir scratch("uniform-tables");
  const fs::path& dir = scratch.path();
  const auto s = ex::write_tables(rows, c, dir);
  CHECK(s.csv == dir / "uniform_tables.csv");
  CHECK(s.markdown == dir / "uniform_tables.md");
  CHECK(slurp(s.csv) == ex::tables_csv(rows, c));
  CHECK(slurp(s.markdown) == ex::tables_markdown(rows, c));
  REQUIRE(s.rows.size() == rows.size());
  antkit::kernel::TraceHash digest;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    digest.add_u64(rows[k].hash);
    CHECK(s.rows[k].density_percent == rows[k].paper->density_percent);
    CHECK(s.rows[k].robots == rows[k].paper->robots);
    REQUIRE(s.rows[k].columns.size() == ex::kTableColumns);
    for (std::size_t a = 0; a < ex::kTableColumns; ++a) {
      const auto& col = s.rows[k].columns[a];
      CHECK(col.algorithm == ex::kTableAlgorithms[a]);
      CHECK(col.coverage == Approx(rows[k].coverage[a]).margin(0.005));
      CHECK(col.movements == Approx(rows[k].movements[a]).margin(0.05));
      CHECK(col.moves == Approx(rows[k].moves[a]).margin(0.05));
      CHECK(antkit::experiments::fixed(col.coverage, 2) ==
            antkit::experiments::fixed(rows[k].coverage[a], 2));
    }
  }
  CHECK(s.hash == digest.finish());
  CHECK(ex::tables_summary(rows, c).hash == s.hash);

  SECTION("the disk sensor model reports the paper's three algorithms") {
    c.sensor_model = ex::SensorModel::Disk;
    CHECK(ex::tables_summary(rows, c).rows[0].columns.size() == 3);
  }
  SECTION("a directory that does not exist: refused by the file's name, nothing written") {
    try {
      (void)ex::write_tables(rows, c, dir / "absent");
      FAIL("a missing directory was written to");
    } catch (const antkit::kernel::InputError& e) {
      CHECK(e.where() == (dir / "absent" / "uniform_tables.csv").string());
    }
    CHECK_FALSE(fs::exists(dir / "absent"));
  }
}
