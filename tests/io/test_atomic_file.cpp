// write_file_atomic and write_file_atomic_at (io/atomic_file.hpp): an output file appears
// whole or not at all (DESIGN.md, Errors). A writer that throws, a file that cannot be opened or a
// directory that does not exist leave the target as it was and no temporary file beside it.
#include "scratch_dir.hpp"

#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace fs = std::filesystem;
namespace io = antkit::io;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

} // namespace

TEST_CASE("write_file_atomic: whole or not at all", "[io]") {
  const antkit::test::ScratchDir scratch("atomic");
  const fs::path& dir = scratch.path();
  const fs::path target = dir / "out.txt";

  io::write_file_atomic(target, "first\n");
  CHECK(slurp(target) == "first\n");
  io::write_file_atomic(target, [](std::ostream& out) { out << "second\n"; });
  CHECK(slurp(target) == "second\n");
  CHECK(entries(dir) == 1);

  SECTION("a writer that throws leaves the old file and no temporary") {
    CHECK_THROWS_AS(io::write_file_atomic(target,
                                          [](std::ostream& out) {
                                            out << "half";
                                            throw std::runtime_error("stop");
                                          }),
                    std::runtime_error);
    CHECK_THROWS_AS(io::write_file_atomic_at(target,
                                             [](const fs::path& tmp) {
                                               std::ofstream(tmp) << "half";
                                               throw std::runtime_error("stop");
                                             }),
                    std::runtime_error);
    CHECK(slurp(target) == "second\n");
    CHECK(entries(dir) == 1);
  }
  SECTION("write_file_atomic_at: the writer opens the temporary beside the target by its name") {
    fs::path seen;
    io::write_file_atomic_at(target, [&](const fs::path& tmp) {
      seen = tmp;
      CHECK(tmp.parent_path() == dir);
      CHECK(tmp != target);
      std::ofstream(tmp, std::ios::binary) << "third\n";
    });
    CHECK(slurp(target) == "third\n");
    CHECK_FALSE(fs::exists(seen));
    CHECK(entries(dir) == 1);
  }
  SECTION("a directory that does not exist: InputError naming the file, nothing made") {
    try {
      io::write_file_atomic(dir / "absent" / "out.txt", "x");
      FAIL("written into a missing directory");
    } catch (const antkit::kernel::InputError& e) {
      CHECK(e.where() == (dir / "absent" / "out.txt").string());
      CHECK(e.message() == "cannot open for writing");
    }
    CHECK_FALSE(fs::exists(dir / "absent"));
  }
  SECTION("a writer that leaves no file: the rename fails, named by the target") {
    try {
      io::write_file_atomic_at(dir / "never.txt", [](const fs::path&) {});
      FAIL("a file that was never written appeared");
    } catch (const antkit::kernel::InputError& e) {
      CHECK(e.where() == (dir / "never.txt").string());
      CHECK(e.message().rfind("cannot rename into place: ", 0) == 0);
    }
    CHECK(entries(dir) == 1);
  }
}
