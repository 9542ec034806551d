// ROS map_server maps: the yaml subset, PGM P5 and P2, the trinary thresholds (strict, in double,
// 205 against free_thresh 0.196), negate, and the image path relative to the yaml.
#include "map_test_support.hpp"
#include "scratch_dir.hpp"

#include <antkit/maps/map_io.hpp>
#include <catch2/catch.hpp>
#include <fstream>
#include <unistd.h>

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::maps::classify_trinary;
using antkit::maps::parse_pgm;
using antkit::maps::parse_ros_yaml;
using antkit::maps::RosMapYaml;
using antkit::maps::test::contains;
using antkit::maps::test::error_of;

namespace {

const std::string kYaml = "image: m.pgm\nresolution: 0.05\norigin: [-10.0, -2.5, 0.1]\nnegate: 0\n"
                          "occupied_thresh: 0.65\nfree_thresh: 0.196\n";

RosMapYaml thresholds(double occupied, double free, bool negate = false) {
  RosMapYaml y;
  y.occupied_thresh = occupied;
  y.free_thresh = free;
  y.negate = negate;
  return y;
}

// A fresh directory under the system temporary directory, removed at the end of the scope
// (scratch_dir.hpp).
struct TempDir {
  antkit::test::ScratchDir scratch{"maps-test"};
  std::filesystem::path path = scratch.path();
  void write(const std::string& name, const std::string& content) const {
    std::ofstream(path / name, std::ios::binary) << content;
  }
};

} // namespace

TEST_CASE("ROS yaml: the map_server fields are read", "[maps][ros]") {
  const auto y = parse_ros_yaml(kYaml, "m.yaml");
  CHECK(y.image == "m.pgm");
  CHECK(y.image_line == 1);
  CHECK(y.image_column == 8);
  CHECK(y.resolution == 0.05);
  CHECK(y.origin_x == -10.0);
  CHECK(y.origin_y == -2.5);
  CHECK(y.origin_yaw == 0.1);
  CHECK_FALSE(y.negate);
  CHECK(y.occupied_thresh == 0.65);
  CHECK(y.free_thresh == 0.196);
  CHECK(y.mode == antkit::maps::RosMode::Trinary);
}

TEST_CASE("ROS yaml: comments, quotes, CRLF, key order, a document marker and mode are accepted",
          "[maps][ros]") {
  const auto a = parse_ros_yaml(
      "---\r\n# a map\r\nfree_thresh: 0.196  # strict\r\nimage: \"m.pgm\"\r\nmode: trinary\r\n"
      "negate: false\r\n\r\norigin: [ -10.0 ,-2.5,  0.1 ] # pose\r\noccupied_thresh: +0.65\r\n"
      "resolution: 5e-2\r\n",
      "a.yaml");
  const auto b = parse_ros_yaml(kYaml, "b.yaml");
  CHECK(a.image == b.image);
  CHECK(a.resolution == b.resolution);
  CHECK(a.origin_x == b.origin_x);
  CHECK(a.origin_y == b.origin_y);
  CHECK(a.origin_yaw == b.origin_yaw);
  CHECK(a.negate == b.negate);
  CHECK(a.occupied_thresh == b.occupied_thresh);
  CHECK(a.free_thresh == b.free_thresh);
  CHECK(parse_ros_yaml("image: 'it''s #1.pgm'\n" + kYaml.substr(kYaml.find('\n') + 1), "q").image ==
        "it's #1.pgm");
  std::string negated = kYaml;
  negated.replace(negated.find("negate: 0"), 9, "negate: true");
  CHECK(parse_ros_yaml(negated, "n").negate);
}

TEST_CASE("ROS yaml: what is outside the subset or out of range is an InputError at its place",
          "[maps][ros]") {
  auto without = [](const std::string& key) {
    std::string s = kYaml;
    const auto at = s.find(key + ":");
    return s.erase(at, s.find('\n', at) + 1 - at);
  };
  auto replaced = [&](const std::string& key, const std::string& line) {
    return without(key) + line + "\n";
  };
  struct Case {
    std::string text;
    std::size_t line, column;
    std::string says;
  };
  const std::vector<Case> cases{
      {without("image"), 6, 1, "no `image:`"},
      {without("negate"), 6, 1, "no `negate:`"},
      {without("origin"), 6, 1, "no `origin:`"},
      {kYaml + "image: x.pgm\n", 7, 1, "a second 'image' (the first is on line 1)"},
      {kYaml + "colour: red\n", 7, 1, "unknown key 'colour'"},
      {kYaml + "  nested: 1\n", 7, 1, "indented line"},
      {kYaml + "---\n", 7, 1, "a second YAML document"},
      {kYaml + "just text\n", 7, 5, "expected `key: value`"},
      {kYaml + "mode:trinary\n", 7, 5, "expected `key: value`"},
      {kYaml + "mode: scaled\n", 7, 7, "unknown mode 'scaled'"},
      {replaced("image", "image:"), 6, 7, "no value for 'image'"},
      {replaced("image", "image: \"m.pgm"), 6, 8, "unterminated quoted value"},
      {replaced("image", "image: \"a\\b.pgm\""), 6, 10, "backslash escapes"},
      {replaced("image", "image: 'a' b"), 6, 12, "after the value"},
      {replaced("image", "image: &anchor m.pgm"), 6, 8, "unsupported YAML '&'"},
      {replaced("image", "image: - m.pgm"), 6, 8, "unsupported YAML '-'"},
      {replaced("image", "image: ''"), 6, 8, "empty image path"},
      {replaced("resolution", "resolution: fast"), 6, 13, "bad resolution 'fast'"},
      {replaced("resolution", "resolution: 0"), 6, 13, "not positive"},
      {replaced("resolution", "resolution: -0.05"), 6, 13, "not positive"},
      {replaced("resolution", "resolution: .inf"), 6, 13, "finite decimal number"},
      {replaced("resolution", "resolution: nan"), 6, 13, "finite decimal number"},
      {replaced("resolution", "resolution: 1e999"), 6, 13, "finite decimal number"},
      {replaced("resolution", "resolution: 0x10"), 6, 13, "finite decimal number"},
      {replaced("origin", "origin: 1, 2, 3"), 6, 9, "flow list"},
      {replaced("origin", "origin: [1, 2, 3"), 6, 17, "unterminated origin"},
      {replaced("origin", "origin: [1, 2]"), 6, 14, "has 2 values"},
      {replaced("origin", "origin: [1, 2, 3, 4]"), 6, 19, "more than three"},
      {replaced("origin", "origin: [1, , 3]"), 6, 13, "bad origin y ''"},
      {replaced("origin", "origin: [1, 2, 3] x"), 6, 19, "after the value"},
      {replaced("negate", "negate: 2"), 6, 9, "bad negate '2'"},
      {replaced("occupied_thresh", "occupied_thresh: 1.5"), 6, 18, "outside [0, 1]"},
      {replaced("free_thresh", "free_thresh: -0.1"), 6, 14, "outside [0, 1]"},
      {replaced("free_thresh", "free_thresh: 0.7"), 6, 14, "above occupied_thresh"},
  };
  for (const auto& c : cases) {
    INFO(c.text);
    const auto e = error_of([&] { (void)parse_ros_yaml(c.text, "bad.yaml"); });
    REQUIRE(e.thrown);
    CHECK(e.line == c.line);
    CHECK(e.column == c.column);
    CHECK(contains(e.what, c.says));
  }
}

TEST_CASE("ROS trinary: the README's thresholds over every 8-bit grey value",
          "[maps][ros][proof]") {
  // data/maps/README.md: with 0.65 / 0.196, free <=> v >= 206, occupied <=> v <= 89,
  // unknown <=> 90 <= v <= 205 (205 gives p = 0.19608, just above 0.196: strict comparisons).
  const auto y = thresholds(0.65, 0.196);
  for (int v = 0; v <= 255; ++v) {
    INFO(v);
    const auto want = v >= 206  ? Occupancy::Free
                      : v <= 89 ? Occupancy::Blocked
                                : Occupancy::Unknown;
    CHECK(classify_trinary(static_cast<std::uint16_t>(v), 255, y) == want);
    // negate reverses the grey scale, and only that.
    CHECK(classify_trinary(static_cast<std::uint16_t>(255 - v), 255,
                           thresholds(0.65, 0.196, true)) == want);
  }
  // lab.yaml's free_thresh 0.25 turns the map_saver unknown, 205, free.
  CHECK(classify_trinary(205, 255, thresholds(0.65, 0.25)) == Occupancy::Free);
  // A p equal to a threshold is neither above nor below it: unknown.
  CHECK(classify_trinary(0, 255, thresholds(1.0, 0.0)) == Occupancy::Unknown);
  CHECK(classify_trinary(255, 255, thresholds(1.0, 0.0)) == Occupancy::Unknown);
  // A 16-bit image means what its picture shows: the same fractions of maxval.
  CHECK(classify_trinary(65535, 65535, thresholds(0.65, 0.196)) == Occupancy::Free);
  CHECK(classify_trinary(0, 65535, thresholds(0.65, 0.196)) == Occupancy::Blocked);
  CHECK(classify_trinary(32768, 65535, thresholds(0.65, 0.196)) == Occupancy::Unknown);
}

TEST_CASE("PGM: P5 and P2 with comments read the same pixels", "[maps][ros]") {
  const std::string data{'\x00', '\xfe', '\xcd', '\x05', '\x10', '\xff'};
  const auto p5 = parse_pgm("P5\n# CREATOR: map_saver.cpp 0.050 m/pix\n3 2\n255\n" + data, "a.pgm");
  const auto p2 = parse_pgm("P2 # plain\n3 # width\n2\n255\n0 254 205\n# row 2\n5 16 255\n", "b");
  const std::vector<std::uint16_t> want{0, 254, 205, 5, 16, 255};
  CHECK(p5.width == 3);
  CHECK(p5.height == 2);
  CHECK(p5.maxval == 255);
  CHECK(p5.pixels == want);
  CHECK(p2.width == 3);
  CHECK(p2.height == 2);
  CHECK(p2.pixels == want);
  // maxval over 255: two bytes per sample, most significant first.
  const auto wide =
      parse_pgm(std::string("P5 1 2 1000\n") + '\x03' + '\xe8' + '\x00' + '\x07', "w");
  CHECK(wide.pixels == std::vector<std::uint16_t>{1000, 7});
}

TEST_CASE("PGM: every malformed image is an InputError at its place", "[maps][ros]") {
  struct Case {
    std::string bytes;
    std::size_t line, column;
    std::string says;
  };
  const std::vector<Case> cases{
      {"", 1, 1, "not a PGM image"},
      {"P6\n1 1\n255\n...", 1, 1, "colour PPM"},
      {"\x89PNG\r\n", 1, 1, "PNG image is not supported"},
      {"P5x", 1, 3, "whitespace after the magic"},
      {"P5\n", 2, 1, "ends before the width"},
      {"P5\n3 2", 2, 4, "ends before the maxval"},
      {"P5\nw 2\n255\n", 2, 1, "expected the width"},
      {"P5\n3x 2\n255\n", 2, 2, "unexpected 'x' in the width"},
      {"P5\n0 2\n255\n", 2, 1, "outside the supported range"},
      {"P5\n# big\n2000000 1\n255\n", 3, 1, "outside the supported range"},
      {"P5\n99999999999999999999 1\n255\n", 2, 1, "is over"},
      {"P5\n20000 20000\n255\n", 2, 1, "over the cap"},
      {"P5\n1 1\n0\n\x00", 3, 1, "maxval 0"},
      {"P5\n1 1\n65536\n\x00", 3, 1, "is over 65535"},
      {"P5\n2 2\n255\n\x01\x02\x03", 4, 4, "truncated PGM: 3 bytes of image data; expected 2 x 2"},
      {"P5\n1 1\n255\n\x01\n", 4, 2, "1 bytes after the 1 x 1 image data"},
      {"P5\n1 1\n255", 3, 4, "single whitespace byte after maxval"},
      {std::string("P5\n2 1\n100\n\x01\xc8", 13), 4, 2,
       "sample 200 of pixel (1, 0) is over maxval 100"},
      {"P2\n2 2\n255\n1 2 3", 4, 6, "truncated PGM: 3 samples; expected 2 x 2 = 4"},
      {"P2\n2 1\n255\n1 x", 4, 3, "expected the sample"},
      {"P2\n2 1\n15\n1 16", 4, 3, "sample 16 is over maxval 15"},
      {"P2\n1 1\n255\n1 2", 4, 3, "after the 1 samples"},
  };
  for (const auto& c : cases) {
    INFO(c.bytes);
    const auto e = error_of([&] { (void)parse_pgm(c.bytes, "bad.pgm"); });
    REQUIRE(e.thrown);
    CHECK(e.line == c.line);
    CHECK(e.column == c.column);
    CHECK(contains(e.what, c.says));
  }
}

TEST_CASE("PGM: P5 and P2 of the same picture read the same", "[maps][ros][property]") {
  rc::prop("P5 <-> P2", [] {
    const auto w = *rc::gen::inRange<std::int32_t>(1, 9);
    const auto h = *rc::gen::inRange<std::int32_t>(1, 9);
    const auto maxval = static_cast<std::uint16_t>(*rc::gen::inRange<int>(1, 65536));
    const auto pixels = *rc::gen::container<std::vector<std::uint16_t>>(
        static_cast<std::size_t>(w * h),
        rc::gen::map(rc::gen::inRange<int>(0, maxval + 1),
                     [](int v) { return static_cast<std::uint16_t>(v); }));
    std::string p5 =
        "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n" + std::to_string(maxval) + "\n";
    std::string p2 =
        "P2 " + std::to_string(w) + " " + std::to_string(h) + " " + std::to_string(maxval) + "\n";
    for (const auto v : pixels) {
      if (maxval >= 256) p5 += static_cast<char>(v >> 8);
      p5 += static_cast<char>(v & 0xff);
      p2 += std::to_string(v) + " ";
    }
    const auto a = parse_pgm(p5, "a.pgm");
    const auto b = parse_pgm(p2, "b.pgm");
    RC_ASSERT(a.pixels == pixels);
    RC_ASSERT(b.pixels == pixels);
    RC_ASSERT(a.width == w);
    RC_ASSERT(b.height == h);
  });
}

TEST_CASE("ROS: a yaml and its image become a grid, image row 0 at the top", "[maps][ros]") {
  TempDir dir;
  std::filesystem::create_directories(dir.path / "sub");
  // 254 free, 0 occupied, 205 unknown, as map_saver writes them.
  dir.write("sub/m.pgm", std::string("P5 3 2 255\n\xfe\x00\xcd\xcd\xfe\xfe", 17));
  dir.write("m.yaml", "image: sub/m.pgm\nresolution: 0.5\norigin: [1, 2, 0]\nnegate: 0\n"
                      "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const auto m = antkit::maps::load_map(dir.path / "m.yaml");
  REQUIRE(m.cells.width() == 3);
  REQUIRE(m.cells.height() == 2);
  CHECK(m.cells[Cell{0, 0}] == Occupancy::Free);
  CHECK(m.cells[Cell{1, 0}] == Occupancy::Blocked);
  CHECK(m.cells[Cell{2, 0}] == Occupancy::Unknown);
  CHECK(m.cells[Cell{0, 1}] == Occupancy::Unknown);
  CHECK(m.cells[Cell{2, 1}] == Occupancy::Free);
  CHECK(m.resolution == 0.5);
  CHECK(m.origin_x == 1.0);
  CHECK(m.origin_y == 2.0);

  // An absolute image path is used as it is.
  dir.write("abs.yaml", "image: " + (dir.path / "sub/m.pgm").string() +
                            "\nresolution: 0.5\norigin: [1, 2, 0]\nnegate: 0\n"
                            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  CHECK(antkit::maps::load_map(dir.path / "abs.yaml") == m);

  // negate: 1 turns the picture around.
  dir.write("neg.yaml", "image: sub/m.pgm\nresolution: 0.5\norigin: [1, 2, 0]\nnegate: 1\n"
                        "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const auto neg = antkit::maps::load_map(dir.path / "neg.yaml");
  CHECK(neg.cells[Cell{0, 0}] == Occupancy::Blocked);
  CHECK(neg.cells[Cell{1, 0}] == Occupancy::Free);
}

TEST_CASE("ROS: a missing image, a bad image and an unsupported mode name their place",
          "[maps][ros]") {
  TempDir dir;
  const std::string rest = "resolution: 0.5\norigin: [1, 2, 0]\nnegate: 0\n"
                           "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  dir.write("missing.yaml", "image: nowhere.pgm\n" + rest);
  auto e = error_of([&] { (void)antkit::maps::load_map(dir.path / "missing.yaml"); });
  REQUIRE(e.thrown);
  CHECK(e.what.rfind((dir.path / "missing.yaml").string() + ":1:8: cannot read the image " +
                         "'nowhere.pgm'",
                     0) == 0);

  dir.write("short.pgm", "P5 4 4 255\nabc");
  dir.write("short.yaml", "image: short.pgm\n" + rest);
  e = error_of([&] { (void)antkit::maps::load_map(dir.path / "short.yaml"); });
  REQUIRE(e.thrown);
  CHECK(e.what.rfind((dir.path / "short.pgm").string() + ":2:4: truncated PGM", 0) == 0);

  for (const char* mode : {"scale", "raw"}) {
    dir.write("mode.yaml", "image: nowhere.pgm\nmode: " + std::string(mode) + "\n" + rest);
    e = error_of([&] { (void)antkit::maps::load_map(dir.path / "mode.yaml"); });
    REQUIRE(e.thrown);
    CHECK(e.line == 2);
    CHECK(e.column == 7);
    CHECK(contains(e.what, std::string("mode ") + mode + " is not supported"));
  }

  e = error_of([&] { (void)antkit::maps::load_map(dir.path / "absent.yaml"); });
  REQUIRE(e.thrown);
  CHECK(contains(e.what, "cannot open for reading"));
  e = error_of([&] { (void)antkit::maps::load_map(dir.path / "map.png"); });
  REQUIRE(e.thrown);
  CHECK(contains(e.what, "unknown map extension '.png'"));
  e = error_of(
      [&] { (void)antkit::maps::save_map(dir.path / "out.yaml", antkit::maps::GridMap{}); });
  REQUIRE(e.thrown);
  CHECK(contains(e.what, "read-only"));
  CHECK_FALSE(std::filesystem::exists(dir.path / "out.yaml"));
}
