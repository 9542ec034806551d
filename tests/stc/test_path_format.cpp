// The binary tour of path_format.hpp, case by case: every move direction's code and bits, every
// length of the last byte's padding, the empty tour, a move that is not 4-adjacent, and the
// streamed writer (`antkit stc --path-out`) against the whole-tour encoder. The property over
// random tours of every variant is in test_stc_properties.cpp.
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/path_format.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

using antkit::kernel::Cell;
namespace path_format = antkit::stc::path_format;

namespace {

constexpr std::uint64_t kMax = std::uint64_t{1} << 20;

// A tour from `start` making the moves `codes` (0 east, 1 north, 2 west, 3 south).
std::vector<Cell> walk(Cell start, const std::vector<int>& codes) {
  constexpr std::int32_t dx[4] = {1, 0, -1, 0}, dy[4] = {0, -1, 0, 1};
  std::vector<Cell> path{start};
  for (const int c : codes) path.push_back({path.back().x + dx[c], path.back().y + dy[c]});
  return path;
}

std::string streamed(bool binary, std::int32_t width, std::int32_t height,
                     const std::vector<Cell>& path) {
  std::stringstream out;
  path_format::TourWriter writer(out, binary, width, height, path.front());
  for (const Cell c : path) writer.add(c);
  writer.finish();
  return out.str();
}

} // namespace

TEST_CASE("path_format: each direction has its code, in the kernel's order", "[stc]") {
  const Cell a{5, 5};
  CHECK(path_format::move_code(a, {6, 5}) == 0); // east
  CHECK(path_format::move_code(a, {5, 4}) == 1); // north
  CHECK(path_format::move_code(a, {4, 5}) == 2); // west
  CHECK(path_format::move_code(a, {5, 6}) == 3); // south
  CHECK(path_format::move_code(a, a) == -1);
  CHECK(path_format::move_code(a, {6, 6}) == -1);
  CHECK(path_format::move_code(a, {7, 5}) == -1);
}

TEST_CASE("path_format: the header and the packed bits of one move of each direction", "[stc]") {
  // East, north, west, south: codes 0, 1, 2, 3 in bits 0-1, 2-3, 4-5, 6-7 of the first byte.
  const auto path = walk({2, 3}, {0, 1, 2, 3});
  const std::string bytes = path_format::encode(7, 9, path);
  REQUIRE(bytes.size() == path_format::kHeaderBytes + 1);
  CHECK(bytes.substr(0, 8) == "ANTKPTH1");
  CHECK(path_format::get_le(bytes, 8, 4) == 7);
  CHECK(path_format::get_le(bytes, 12, 4) == 9);
  CHECK(path_format::get_le(bytes, 16, 4) == 2);
  CHECK(path_format::get_le(bytes, 20, 4) == 3);
  CHECK(path_format::get_le(bytes, 24, 8) == 4);
  CHECK(static_cast<unsigned char>(bytes[32]) == (0 | 1 << 2 | 2 << 4 | 3 << 6));
  const auto d = path_format::decode(bytes, "moves", kMax);
  CHECK(d.width == 7);
  CHECK(d.height == 9);
  CHECK(d.start == Cell{2, 3});
  CHECK(d.path == path);
}

TEST_CASE("path_format: decode(encode(tour)) for every direction and every length to 13 moves",
          "[stc]") {
  // Lengths 0 to 13 moves: every remainder mod 4 (the last byte's unused bits) several times,
  // odd lengths included; each direction in each of the four bit positions of a byte.
  for (int first = 0; first < 4; ++first)
    for (int moves = 0; moves <= 13; ++moves) {
      std::vector<int> codes;
      for (int k = 0; k < moves; ++k) codes.push_back((first + k * (k + 1) / 2) % 4);
      const auto path = walk({10, 10}, codes);
      INFO("first " << first << ", " << moves << " moves");
      const std::string bytes = path_format::encode(32, 32, path);
      CHECK(bytes.size() == path_format::kHeaderBytes + static_cast<std::size_t>(moves + 3) / 4);
      // The unused bits of the last byte are 0.
      if (moves % 4 != 0)
        CHECK((static_cast<unsigned char>(bytes.back()) >> (2 * (moves % 4))) == 0);
      const auto d = path_format::decode(bytes, "moves", kMax);
      CHECK(d.start == path.front());
      CHECK(d.path == path);
      // What the command streams is the same bytes.
      CHECK(streamed(true, 32, 32, path) == bytes);
    }
}

TEST_CASE("path_format: one position is a tour of no moves, and an empty tour has no start",
          "[stc]") {
  const std::string one = path_format::encode(4, 4, {{1, 2}});
  CHECK(one.size() == path_format::kHeaderBytes);
  const auto d = path_format::decode(one, "one", kMax);
  CHECK(d.path == std::vector<Cell>{{1, 2}});
  try {
    (void)path_format::encode(4, 4, {});
    FAIL("an empty tour was encoded");
  } catch (const antkit::kernel::InputError& e) {
    CHECK(e.where() == "path");
    CHECK(e.message() == "an empty tour has no start");
  }
}

TEST_CASE("path_format: a move that is not 4-adjacent is refused at its position", "[stc]") {
  auto path = walk({0, 0}, {0, 0, 3});
  path.push_back({path.back().x + 1, path.back().y + 1}); // diagonal
  try {
    (void)path_format::encode(8, 8, path);
    FAIL("a diagonal move was encoded");
  } catch (const antkit::kernel::InputError& e) {
    CHECK(e.where() == "path");
    CHECK(e.message() == "position 4 is not 4-adjacent to the one before it");
  }
  std::stringstream out;
  path_format::TourWriter writer(out, true, 8, 8, path.front());
  for (std::size_t i = 0; i + 1 < path.size(); ++i) writer.add(path[i]);
  CHECK_THROWS_AS(writer.add(path.back()), std::logic_error);
}

TEST_CASE("path_format: the CSV writer writes a header and one x,y line per position", "[stc]") {
  CHECK(streamed(false, 8, 8, walk({3, 1}, {2, 3, 3})) == "x,y\n3,1\n2,1\n2,2\n2,3\n");
  CHECK(streamed(false, 8, 8, {{0, 0}}) == "x,y\n0,0\n");
}
