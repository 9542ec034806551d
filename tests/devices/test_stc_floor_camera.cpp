// The marker-floor camera pipeline's first stages (issue 14): dark frame, channel split, mark
// finding, the heading line and the rotation calibration, against their definitions.
#include <antkit/devices/stc_floor/camera.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

namespace sf = antkit::devices::stc_floor;
using antkit::kernel::Angle;

namespace {

sf::Image random_image(std::int32_t w, std::int32_t h, std::int32_t c) {
  sf::Image img(w, h, c);
  img.pixels = *rc::gen::container<std::vector<std::uint8_t>>(img.pixels.size(),
                                                              rc::gen::arbitrary<std::uint8_t>());
  return img;
}

} // namespace

TEST_CASE("stc floor: the dark frame is subtracted per byte, saturating at 0",
          "[devices][property]") {
  rc::prop("subtract_dark", [] {
    const auto w = *rc::gen::inRange(1, 9), h = *rc::gen::inRange(1, 9);
    const auto frame = random_image(w, h, 3), dark = random_image(w, h, 3);
    const auto out = sf::subtract_dark(frame, dark);
    RC_ASSERT(out.width == w && out.height == h && out.channels == 3);
    for (std::size_t i = 0; i < out.pixels.size(); ++i)
      RC_ASSERT(int{out.pixels[i]} == std::max(0, int{frame.pixels[i]} - int{dark.pixels[i]}));
  });
  CHECK_THROWS_AS(sf::subtract_dark(sf::Image(4, 3, 3), sf::Image(3, 4, 3)),
                  antkit::kernel::InputError);
  CHECK_THROWS_AS(sf::subtract_dark(sf::Image(4, 3, 3), sf::Image(4, 3, 1)),
                  antkit::kernel::InputError);
  sf::Image cut(4, 3, 3);
  cut.pixels.pop_back();
  CHECK_THROWS_AS(sf::subtract_dark(cut, cut), antkit::kernel::InputError);
}

TEST_CASE("stc floor: red lights go to the obstacle image, the rest's green to the marks image",
          "[devices][property]") {
  rc::prop("split_channels", [] {
    const auto frame = random_image(*rc::gen::inRange(1, 9), *rc::gen::inRange(1, 9), 3);
    const auto threshold = *rc::gen::arbitrary<std::uint8_t>();
    const auto c = sf::split_channels(frame, threshold);
    for (std::int32_t y = 0; y < frame.height; ++y)
      for (std::int32_t x = 0; x < frame.width; ++x) {
        const bool red = frame.at(x, y, 0) > threshold;
        RC_ASSERT(c.obstacles.at(x, y) == (red ? frame.at(x, y, 0) : 0));
        RC_ASSERT(c.marks.at(x, y) == (red ? 0 : frame.at(x, y, 1)));
      }
  });
  CHECK_THROWS_AS(sf::split_channels(sf::Image(2, 2, 1), 100), antkit::kernel::InputError);
}

TEST_CASE("stc floor: a single mark is found at every position of a small image, exactly",
          "[devices]") {
  for (std::int32_t window = 1; window <= 3; ++window)
    for (std::int32_t y = 0; y + window <= 10; ++y)
      for (std::int32_t x = 0; x + window <= 12; ++x) {
        sf::Image img(12, 10, 1, 3); // a dim floor: 3 everywhere
        for (std::int32_t dy = 0; dy < window; ++dy)
          for (std::int32_t dx = 0; dx < window; ++dx) img.at(x + dx, y + dy) = 200;
        const auto marks =
            sf::find_marks(img, window, 100u * static_cast<std::uint32_t>(window * window), 5);
        REQUIRE(marks.size() == 1);
        CHECK(marks[0].x == x);
        CHECK(marks[0].y == y);
        CHECK(marks[0].sum == 200u * static_cast<std::uint32_t>(window * window));
      }
}

TEST_CASE("stc floor: planted marks are all found, brightest first, and nothing else",
          "[devices][property]") {
  rc::prop("find_marks", [] {
    const std::int32_t window = *rc::gen::inRange(1, 4);
    const std::int32_t w = 40, h = 30;
    sf::Image img(w, h, 1);
    // Noise below any mark: at most 20 per pixel.
    for (auto& p : img.pixels) p = *rc::gen::inRange<std::uint8_t>(0, 21);
    // Marks on a coarse lattice (never touching), with distinct brightness.
    const auto count = static_cast<std::size_t>(*rc::gen::inRange(0, 6));
    std::vector<std::pair<std::int32_t, std::int32_t>> spots;
    for (std::int32_t gy = 0; gy < 4; ++gy)
      for (std::int32_t gx = 0; gx < 5; ++gx) spots.emplace_back(1 + 8 * gx, 1 + 7 * gy);
    const auto chosen = *rc::gen::unique<std::vector<int>>(count, rc::gen::inRange(0, 20));
    std::vector<std::tuple<std::uint32_t, std::int32_t, std::int32_t>> planted;
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      const auto [x, y] = spots[static_cast<std::size_t>(chosen[k])];
      const auto v = static_cast<std::uint8_t>(255 - 10 * k);
      for (std::int32_t dy = 0; dy < window; ++dy)
        for (std::int32_t dx = 0; dx < window; ++dx) img.at(x + dx, y + dy) = v;
      planted.emplace_back(v, x, y);
    }
    const auto area = static_cast<std::uint32_t>(window * window);
    const auto marks = sf::find_marks(img, window, 100 * area, 10);
    RC_ASSERT(marks.size() == planted.size());
    for (std::size_t k = 0; k < marks.size(); ++k) { // planted in falling brightness
      RC_ASSERT(marks[k].x == std::get<1>(planted[k]));
      RC_ASSERT(marks[k].y == std::get<2>(planted[k]));
    }
  });
  CHECK_THROWS_AS(sf::find_marks(sf::Image(5, 4, 1), 5, 1, 1), antkit::kernel::InputError);
  CHECK_THROWS_AS(sf::find_marks(sf::Image(5, 4, 3), 2, 1, 1), antkit::kernel::InputError);
}

TEST_CASE("stc floor: the heading of marks on a line is the line's direction", "[devices]") {
  // Three marks one sub-cell apart (as the robot lays them), along integer directions all round.
  const std::int32_t window = 3;
  for (std::int32_t dx = -12; dx <= 12; ++dx)
    for (std::int32_t dy = -12; dy <= 12; ++dy) {
      if (dx == 0 && dy == 0) continue;
      std::vector<sf::Mark> marks;
      for (std::int32_t k = 0; k < 3; ++k) marks.push_back({100 + k * dx, 100 + k * dy, 0});
      const auto heading = sf::line_heading(marks, window);
      REQUIRE(heading.has_value());
      // The direction of (dx, -dy) (image y grows downward), modulo half a turn.
      const Angle want =
          Angle::from_raw(antkit::kernel::atan2(-dy, dx).raw() & (Angle::kHalfTurn - 1));
      INFO("dx " << dx << ", dy " << dy);
      CHECK(std::llabs(sf::heading_change(want, *heading)) <= 4096); // 2^-20 turn
    }
  const std::vector<sf::Mark> one{{5, 5, 0}}, same{{5, 5, 0}, {5, 5, 0}};
  CHECK_FALSE(sf::line_heading(one, 3).has_value());
  CHECK_FALSE(sf::line_heading(same, 3).has_value());
}

TEST_CASE("stc floor: heading changes fold into a quarter turn either way", "[devices]") {
  const auto deg = [](std::int32_t d) { return Angle::from_turns(d, 360); };
  CHECK(sf::heading_change(deg(10), deg(20)) == deg(10).raw());
  CHECK(sf::heading_change(deg(20), deg(10)) == -static_cast<std::int64_t>(deg(10).raw()));
  CHECK(sf::heading_change(deg(170), deg(10)) == deg(20).raw()); // lines: 190 is 10
  CHECK(sf::heading_change(deg(0), deg(90)) == Angle::kQuarterTurn);
}

TEST_CASE("stc floor: the rotation calibration makes the next turn a quarter, within its bound",
          "[devices][property]") {
  const std::int64_t quarter = Angle::kQuarterTurn;
  CHECK(sf::calibrate_rotation(1000, quarter, 500000) == 1000);
  CHECK(sf::calibrate_rotation(1000, quarter * 4 / 5, 500000) == 1250);
  CHECK(sf::calibrate_rotation(1000, quarter / 2, 500000) == 1500); // bounded: 1.5 at most
  CHECK(sf::calibrate_rotation(1000, quarter * 4, 500000) == 667);  // and 1 / 1.5 at least
  CHECK(sf::calibrate_rotation(1000, 0, 500000) == 1000);
  rc::prop("a motor that turns r per time unit turns a quarter after one correction", [] {
    const std::int64_t t = *rc::gen::inRange<std::int64_t>(1000, 1000000);
    // r: the turn per time unit, so that t turns between 0.8 and 1.25 quarter turns.
    const std::int64_t turned = *rc::gen::inRange<std::int64_t>(quarter * 4 / 5, quarter * 5 / 4);
    const std::int64_t next = sf::calibrate_rotation(t, turned, 300000);
    const auto turned_next = static_cast<long double>(turned) * next / t;
    RC_ASSERT(std::abs(turned_next - quarter) <= static_cast<long double>(turned) / t);
  });
}
