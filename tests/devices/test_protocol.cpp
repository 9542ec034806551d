// The robots' protocols (devices/protocol.hpp, robot.hpp): byte-exact commands, replies as the
// robots send them accepted, near-misses refused at the right column, round trips as properties,
// and the fixed-point normalisation.
#include <antkit/devices/framing.hpp>
#include <antkit/devices/protocol.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

namespace devices = antkit::devices;
using antkit::kernel::Fx;
using devices::Codec;
using devices::RobotKind;

namespace {
const RobotKind kRobots[] = {RobotKind::Khepera, RobotKind::Hemisson, RobotKind::Epuck};
}

TEST_CASE("commands are encoded byte for byte", "[devices]") {
  const Codec k(RobotKind::Khepera), h(RobotKind::Hemisson), e(RobotKind::Epuck);
  CHECK(k.set_speed(10, -10) == "D,10,-10\r");
  CHECK(k.read_proximity() == "N\r");
  CHECK(k.read_odometry() == "H\r");
  CHECK(k.set_odometry(0, 0) == "G,0,0\r");
  CHECK(k.set_led(1, 2) == "L,1,2\r");
  CHECK(k.version() == "B\r");
  CHECK(h.set_speed(-9, 9) == "D,-9,9\r");
  CHECK(e.read_odometry() == "Q\r");
  CHECK(e.set_odometry(5, -5) == "P,5,-5\r");
  CHECK(e.version() == "V\r");
  CHECK(k.safe_stop() == std::vector<std::string>{"D,0,0\r", "L,0,0\r", "L,1,0\r"});
  CHECK(h.safe_stop() == std::vector<std::string>{"D,0,0\r"});
  CHECK(e.safe_stop() == std::vector<std::string>{"D,0,0\r", "S\r"});
  CHECK_THROWS_AS(h.set_speed(10, 0), std::out_of_range);
  CHECK_THROWS_AS(k.set_speed(0, -128), std::out_of_range);
  CHECK_THROWS_AS(h.read_odometry(), std::logic_error);
  // The line settings of PROTOCOLS.md.
  CHECK(k.robot().line.framing() == "8N2");
  CHECK(k.robot().line.baud == 9600);
  CHECK(h.robot().line.framing() == "8N1");
  CHECK(h.robot().line.baud == 115200);
  CHECK(e.robot().line.baud == 115200);
}

TEST_CASE("replies as the robots send them are accepted", "[devices]") {
  const Codec k(RobotKind::Khepera), h(RobotKind::Hemisson), e(RobotKind::Epuck);
  auto p = k.decode_proximity("n,0,12,1023,5,0,0,3,9\r\n");
  REQUIRE(p);
  CHECK(p.value->raw == std::array<std::int32_t, 8>{0, 12, 1023, 5, 0, 0, 3, 9});
  // HemiOS pads to three digits (RoadNarrows' driver expects an N reply of >= 33 characters).
  p = h.decode_proximity("n,000,012,255,005,000,000,200,200\r\n");
  REQUIRE(p);
  CHECK(p.value->raw[2] == 255);
  CHECK(h.reply('N', p.value->raw) == "n,000,012,255,005,000,000,200,200\r\n");
  // e-puck: 8 values, or 10 on lab firmwares; calibrated values may dip below 0.
  CHECK(e.decode_proximity("n,10,-3,4000,5,0,0,3,9\r\n"));
  CHECK(e.decode_proximity("n,10,3,4000,5,0,0,3,9,77,88\r\n"));
  CHECK(k.decode_ack("d\r\n", 'D'));
  CHECK(k.decode_odometry("h,-120,34567\r\n").value->right == 34567);
  CHECK(e.decode_odometry("q,1,2\r\n").value->left == 1);
  CHECK(k.decode_reply("B\r", "b,5.02,5.01\r\n"));
  CHECK(e.decode_reply("V\r", "v,Version 1.2.2 August 2008\r\n"));
  CHECK(e.decode_reply("S\r", "s\r\n"));
  CHECK(k.decode_reply("L,0,0\r", "l\r\n"));
}

TEST_CASE("near-miss replies are refused at the right column", "[devices]") {
  const Codec k(RobotKind::Khepera), h(RobotKind::Hemisson), e(RobotKind::Epuck);
  struct Bad {
    const Codec* codec;
    const char* sent;
    const char* line;
    std::size_t column;
  };
  const Bad cases[] = {
      {&k, "N\r", "d,0,0,0,0,0,0,0,0\r\n", 1},     // another command's letter
      {&k, "N\r", "N,0,0,0,0,0,0,0,0\r\n", 1},     // upper-case echo
      {&k, "N\r", "n,0,0,0,0,0,0,0,0\n", 18},      // no CR
      {&k, "N\r", "n,0,0,0,0,0,0,0,0\r", 18},      // no LF
      {&k, "N\r", "n,0,0,0,0,0,0,0,0\r\nx", 18},   // bytes after CR LF
      {&k, "N\r", "n,0,0,0,0,0,0,0\r\n", 16},      // seven values
      {&k, "N\r", "n,0,0,0,0,0,0,0,0,0\r\n", 19},  // nine values
      {&k, "N\r", "n,0,0,0,0,0,0,0,1024\r\n", 17}, // out of range
      {&h, "N\r", "n,0,0,0,0,0,0,0,256\r\n", 17},  // Hemisson: 8-bit
      {&k, "N\r", "n,0,0,0,0,0,0,0,+5\r\n", 17},   // '+'
      {&k, "N\r", "n,0,0,0,0,0,0,0,--1\r\n", 18},  // '--'
      {&k, "N\r", "n,0,0,0,0,0,0,0, 1\r\n", 17},   // a space
      {&k, "N\r", "n,0,,0,0,0,0,0,0\r\n", 5},      // an empty value
      {&k, "H\r", "h,99999999999,0\r\n", 3},       // too many digits
      {&k, "H\r", "h,4294967296,0\r\n", 3},        // beyond 32 bits
      {&k, "D,1,1\r", "d,1\r\n", 3},               // an ack with values
      {&e, "N\r", "n,1,2,3,4,5,6,7,8,9\r\n", 20},  // e-puck: 9 values
      {&k, "N\r", "n,0,0,0,0,0,0,0,\xff\r\n", 17}, // non-ASCII
      {&k, "N\r", "", 1},                          // nothing
  };
  for (const auto& c : cases) {
    INFO(c.line);
    const auto d = c.codec->decode_reply(c.sent, c.line);
    CHECK(!d);
    CHECK(d.error.column == c.column);
    CHECK(!d.error.message.empty());
  }
}

TEST_CASE("every reply the firmware side encodes decodes to its values", "[devices][property]") {
  rc::prop("reply -> decode_reply round trip, every robot", [] {
    const auto robot = *rc::gen::element(RobotKind::Khepera, RobotKind::Hemisson, RobotKind::Epuck);
    const Codec c(robot);
    const auto& d = c.robot();
    std::array<std::int32_t, 8> raw{};
    for (auto& v : raw) v = *rc::gen::inRange(d.proximity_min, d.proximity_max + 1);
    const auto p = c.decode_proximity(c.reply('N', raw));
    RC_ASSERT(p);
    RC_ASSERT(p.value->raw == raw);
    const std::int32_t l = *rc::gen::inRange(d.speed_min, d.speed_max + 1);
    const std::int32_t r = *rc::gen::inRange(d.speed_min, d.speed_max + 1);
    const auto s = c.decode_speed(c.reply('E', std::array<std::int32_t, 2>{l, r}));
    RC_ASSERT(s);
    RC_ASSERT(s.value->left == l);
    RC_ASSERT(s.value->right == r);
    // The firmware parses what the driver encodes.
    const auto f = c.parse_command(c.set_speed(l, r).substr(0, c.set_speed(l, r).size() - 1));
    RC_ASSERT(f);
    RC_ASSERT(f.value->letter == 'D');
    RC_ASSERT(f.value->count == 2);
    RC_ASSERT(f.value->values[0] == l);
    RC_ASSERT(f.value->values[1] == r);
    if (d.has_odometry) {
      const auto a = *rc::gen::arbitrary<std::int32_t>(), b = *rc::gen::arbitrary<std::int32_t>();
      const auto o = c.decode_odometry(c.reply(d.odometry_read, std::array<std::int32_t, 2>{a, b}));
      RC_ASSERT(o);
      RC_ASSERT(o.value->left == a);
      RC_ASSERT(o.value->right == b);
    }
  });
}

// A replay's body takes a reply's values from the framing's judgement of it (classify_reply:
// Codec::decode_reply of the request sent) instead of decoding the line again (Body::proximity_of,
// odometry_of, body.hpp): that judgement must accept exactly the lines the body's own decoder
// accepts, with the same values, and leave the letter and count the body checks before it trusts
// them. Replies the firmware side writes, then up to three bytes edited, inserted or removed.
TEST_CASE("a reply's values as its framing judged it are the body's decoder's",
          "[devices][property]") {
  rc::prop("classify_reply fields == decode_proximity / decode_odometry, every serial robot", [] {
    const auto robots = devices::serial_robots();
    const auto robot = *rc::gen::elementOf(std::vector<RobotKind>(robots.begin(), robots.end()));
    const Codec c(robot);
    const auto& d = c.robot();
    const bool odometry = d.has_odometry && *rc::gen::arbitrary<bool>();
    const std::string request = odometry ? c.read_odometry() : c.read_proximity();
    std::vector<std::int32_t> values(
        odometry ? 2 : 8 + (*rc::gen::arbitrary<bool>() ? d.proximity_extra : 0));
    for (auto& v : values)
      v = odometry ? *rc::gen::arbitrary<std::int32_t>()
                   : *rc::gen::inRange(d.proximity_min, d.proximity_max + 1);
    std::string line = c.reply(request[0], values);
    const auto edits = *rc::gen::inRange(0, 4);
    for (int k = 0; k < edits && !line.empty(); ++k) {
      const auto at = *rc::gen::inRange<std::size_t>(0, line.size());
      const char b =
          *rc::gen::element(',', '-', '0', '7', '9', 'n', 'N', 'h', 'q', '\r', '\n', ' ');
      switch (*rc::gen::inRange(0, 3)) {
      case 0:
        line[at] = b;
        break;
      case 1:
        line.insert(at, 1, b);
        break;
      default:
        line.erase(at, 1);
        break;
      }
    }
    devices::Fields f;
    const bool reply = devices::classify_reply(c, request, line, &f) == devices::ReplyKind::Reply;
    RC_TAG(reply ? "a reply" : "not a reply");
    if (odometry) {
      const auto o = c.decode_odometry(line);
      RC_ASSERT(reply == static_cast<bool>(o));
      if (!reply) RC_SUCCEED("refused by both");
      RC_ASSERT(f.letter == (d.odometry_read | 0x20));
      RC_ASSERT(f.count == 2);
      RC_ASSERT(f.values[0] == o.value->left);
      RC_ASSERT(f.values[1] == o.value->right);
    } else {
      const auto p = c.decode_proximity(line);
      RC_ASSERT(reply == static_cast<bool>(p));
      if (!reply) RC_SUCCEED("refused by both");
      RC_ASSERT(f.letter == 'n');
      RC_ASSERT(f.count >= 8);
      RC_ASSERT(std::equal(p.value->raw.begin(), p.value->raw.end(), f.values.begin()));
    }
  });
}

// The controllers normalise by table (ReadingNormaliser): every reading a reply can carry, and
// the ends of the 32-bit range, must give normalise_reading()'s value, for every serial robot.
TEST_CASE("the normalising table is normalise_reading on every reading", "[devices][proof]") {
  for (const RobotKind kind : devices::serial_robots()) {
    const Codec c(kind);
    const auto& d = c.robot();
    INFO(d.name);
    const devices::ReadingNormaliser table(d);
    REQUIRE(&table.robot() == &d);
    std::int64_t checked = 0, differ = 0;
    const auto check = [&](std::int32_t raw) {
      ++checked;
      if (table(raw) != devices::normalise_reading(d, raw)) ++differ;
    };
    for (std::int32_t raw = std::min(d.proximity_min, 0) - 2;
         raw <= std::max(d.proximity_max, d.proximity_scale) + 2; ++raw)
      check(raw);
    for (const std::int32_t raw : {INT32_MIN, INT32_MIN + 1, INT32_MAX - 1, INT32_MAX}) check(raw);
    CHECK(checked > d.proximity_max - d.proximity_min);
    CHECK(differ == 0);
  }
}

TEST_CASE("normalisation: readings to [0, 1] and back, speeds to wheel commands and back",
          "[devices][property]") {
  rc::prop("reading_to_raw(normalise_reading(raw)) == raw on the scale", [] {
    const auto robot = *rc::gen::element(RobotKind::Khepera, RobotKind::Hemisson, RobotKind::Epuck);
    const auto& d = devices::describe(robot);
    const auto raw = *rc::gen::inRange(0, d.proximity_scale + 1);
    const Fx n = devices::normalise_reading(d, raw);
    RC_ASSERT(n >= Fx{});
    RC_ASSERT(n <= Fx::one());
    RC_ASSERT(devices::reading_to_raw(d, n) == raw);
    // Out of the scale: clamped.
    RC_ASSERT(devices::normalise_reading(d, d.proximity_scale + 1 + raw) == Fx::one());
    RC_ASSERT(devices::normalise_reading(d, -1 - raw) == Fx{});
    const auto v = *rc::gen::inRange(d.speed_min, d.speed_max + 1);
    if (v >= -d.speed_full && v <= d.speed_full)
      RC_ASSERT(devices::to_wheel_command(d, devices::from_wheel_command(d, v)) == v);
    const auto m = Fx::from_raw(*rc::gen::inRange(-65536, 65537));
    const auto w = devices::to_wheel_command(d, m);
    RC_ASSERT(w >= d.speed_min);
    RC_ASSERT(w <= d.speed_max);
  });
  // The Buffon behaviour's six sensors come from the robot's own layout.
  const auto& h = devices::describe(RobotKind::Hemisson);
  CHECK(h.proximity_angle_deg[h.front_six[0]] == 90);
  CHECK(h.proximity_angle_deg[h.front_six[5]] == -90);
  const auto& e = devices::describe(RobotKind::Epuck);
  for (std::size_t i = 0; i < 5; ++i)
    CHECK(e.proximity_angle_deg[e.front_six[i]] > e.proximity_angle_deg[e.front_six[i + 1]]);
}

TEST_CASE("the firmware side parses commands as each firmware does", "[devices]") {
  const Codec k(RobotKind::Khepera), e(RobotKind::Epuck);
  CHECK(k.parse_command("D,10,-10"));
  CHECK(!k.parse_command("d,10,-10"));                     // Khepera: upper case only
  CHECK(e.parse_command("d,10,-10").value->letter == 'D'); // asercom accepts lower case
  CHECK(!k.parse_command("D,1,"));
  CHECK(!k.parse_command("D,1,x"));
  CHECK(!k.parse_command(""));
  CHECK(!k.parse_command("D,99999999999,0"));
  CHECK(k.unknown_command_reply("X") == "z,Protocol error\r\n");
  CHECK(e.unknown_command_reply("X") == "z,Command not found\r\n");
}
