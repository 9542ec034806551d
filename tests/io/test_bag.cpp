// The ROS 2 bag readers (io/bag.hpp, mcap_reader.hpp, ros_messages.hpp) on bags written by
// independent writers under node (tests/support/write_bags.mjs: @mcap/core, rosmsg2-serialization,
// wasm-zstd, lz4js, sql.js), on bytes built here by hand (big-endian CDR, XCDR2) and with antkit's
// own MCAP writer (the reader reads back whatever it writes), and on broken bags: each refused with
// an InputError that says where.
#include "ros_bags.hpp"
#include "scratch_dir.hpp"

#include <antkit/io/bag.hpp>
#include <antkit/io/mcap.hpp>
#include <antkit/io/mcap_reader.hpp>
#include <antkit/io/ros_messages.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <sstream>

namespace bag = antkit::io::bag;
namespace ros = antkit::io::ros;
namespace fs = std::filesystem;
using antkit::kernel::InputError;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

constexpr std::uint64_t kT0 = 1700000000000000000ULL;

// The bags' folder, or "" when node is absent (then the test says so and passes).
std::string bags() {
  const std::string dir = antkit::test::ros_bags_dir();
  if (dir.empty()) WARN("SKIPPED: node (Node.js 20) is not installed: no test bags are written");
  return dir;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::string spill(const std::string& name, const std::string& bytes) {
  // Removed when the test process ends.
  static const antkit::test::ScratchDir dir("bag-case");
  const auto path = dir / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

// The message of the InputError that reading every message of `path` throws ("" if none).
std::string read_error(const std::string& path) {
  try {
    (void)bag::bag_info(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void check_walk1(const bag::PoseTrack& t) {
  REQUIRE(t.poses.size() == 11);
  for (std::size_t i = 0; i < t.poses.size(); ++i) {
    CHECK(t.poses[i].x == Approx(static_cast<double>(i)));
    CHECK(t.poses[i].y == Approx(0).margin(1e-12));
    CHECK(t.poses[i].yaw == Approx(0).margin(1e-12));
    CHECK(t.poses[i].bag_ns == kT0 + i * 100000000ULL);
  }
}

void check_walk2(const bag::PoseTrack& t) {
  REQUIRE(t.poses.size() == 10);
  for (std::size_t i = 0; i < t.poses.size(); ++i) {
    CHECK(t.poses[i].x == Approx(0.25 + static_cast<double>(i)));
    CHECK(t.poses[i].y == Approx(i % 2 != 0 ? -1.0 : 1.0));
    CHECK(t.poses[i].yaw == Approx(std::atan(1.0)));
  }
}

// An MCAP file from antkit's writer with one channel of `type` and the given messages' data.
std::string one_channel(const std::string& type, const std::string& encoding,
                        const std::vector<std::string>& data) {
  std::ostringstream out;
  antkit::io::mcap::Writer w(out, {"ros2"});
  const auto s = w.add_schema(type, "ros2msg", "");
  const auto c = w.add_channel(s, "/x", encoding);
  std::uint64_t t = 1;
  for (const auto& d : data) w.write({c, 0, t, t, d}), ++t;
  w.finish();
  return out.str();
}

void put_be32(std::string& s, std::uint32_t v) {
  for (int i = 3; i >= 0; --i) s += static_cast<char>((v >> (8 * i)) & 0xFF);
}
void put_be64(std::string& s, double d) {
  std::uint64_t v = 0;
  std::memcpy(&v, &d, 8);
  for (int i = 7; i >= 0; --i) s += static_cast<char>((v >> (8 * i)) & 0xFF);
}

} // namespace

TEST_CASE("bags: odometry from MCAP (uncompressed, zstd, lz4), .db3 and a bag folder",
          "[io][bag]") {
  const std::string d = bags();
  if (d.empty()) return;
  check_walk1(bag::read_poses(d + "/walk1.mcap", "/odom", bag::Stamp::bag));
  check_walk1(bag::read_poses(d + "/walk1.db3", "/odom", bag::Stamp::bag));
  check_walk2(bag::read_poses(d + "/walk2_zstd.mcap", "/odom", bag::Stamp::bag));
  check_walk2(bag::read_poses(d + "/walk2_lz4.mcap", "/odom", bag::Stamp::bag));
  check_walk2(bag::read_poses(d + "/walk2_bag", "/odom", bag::Stamp::bag));
  // header.stamp: bag time - 0.25 s
  const auto h = bag::read_poses(d + "/walk1.db3", "/odom", bag::Stamp::header);
  CHECK(h.poses[3].t_ns == static_cast<std::int64_t>(kT0 + 300000000ULL - 250000000ULL));
  CHECK(h.poses[3].header_ns == h.poses[3].t_ns);
}

TEST_CASE("bags: every pose type, TF's chosen child frame and an integrated Twist", "[io][bag]") {
  const std::string d = bags();
  if (d.empty()) return;
  const std::string b = d + "/walk1.mcap";
  check_walk1(bag::read_poses(b, "/pose", bag::Stamp::bag));
  check_walk1(bag::read_poses(b, "/amcl_pose", bag::Stamp::bag));
  check_walk1(bag::read_poses(b, "/tf", bag::Stamp::bag, "base_link"));
  const auto laser = bag::read_poses(b, "/tf", bag::Stamp::bag, "/laser");
  REQUIRE(laser.poses.size() == 11);
  CHECK(laser.poses[5].x == Approx(0.1));
  // 1 m/s and 0.5 rad/s held for 10 steps of 0.1 s: the heading turns 0.5 rad, the walk is an arc
  // of radius 2 (each step a chord along the mean heading).
  const auto twist = bag::read_poses(b, "/cmd_vel", bag::Stamp::bag);
  REQUIRE(twist.poses.size() == 11);
  CHECK(twist.poses[0].x == 0);
  CHECK(twist.poses[1].x == Approx(0.1 * std::cos(0.025)));
  CHECK(twist.poses[10].yaw == Approx(0.5));
  CHECK(twist.poses[10].x == Approx(2 * std::sin(0.5)).epsilon(1e-3));
  CHECK_THROWS_WITH(bag::read_poses(b, "/cmd_vel", bag::Stamp::header), Contains("no header"));
  CHECK_THROWS_WITH(bag::read_poses(b, "/tf", bag::Stamp::bag, "wheel"),
                    Contains("no transform whose child frame is 'wheel'"));
}

TEST_CASE("bags: bag info lists topics, types, counts and the time range", "[io][bag]") {
  const std::string d = bags();
  if (d.empty()) return;
  const auto info = bag::bag_info(d + "/walk1.mcap");
  CHECK(info.storage == bag::Storage::mcap);
  CHECK(info.messages == 66);
  REQUIRE(info.topics.size() == 6);
  CHECK(info.topics[0].name == "/amcl_pose");
  CHECK(info.topics[0].type == "geometry_msgs/msg/PoseWithCovarianceStamped");
  CHECK(info.topics[0].messages == 11);
  CHECK(info.first_ns == kT0);
  CHECK(info.last_ns == kT0 + 1000000000ULL);
  const auto folder = bag::bag_info(d + "/walk2_bag");
  CHECK(folder.storage == bag::Storage::sqlite3);
  CHECK(folder.files.size() == 1);
  CHECK(folder.messages == 10);
}

TEST_CASE("bags: refused topics say what the bag holds", "[io][bag]") {
  const std::string d = bags();
  if (d.empty()) return;
  CHECK_THROWS_WITH(bag::read_poses(d + "/walk1.db3", "/scan", bag::Stamp::bag),
                    StartsWith(d + "/walk1.db3: topic /scan is not in the bag (its topics: "
                                   "/chatter, /odom)"));
  CHECK_THROWS_WITH(bag::read_poses(d + "/walk1.mcap", "/scan", bag::Stamp::bag),
                    Contains("is not in the bag"));
  CHECK_THROWS_WITH(bag::read_poses(d + "/walk1.mcap", "/chatter", bag::Stamp::bag),
                    Contains("type 'std_msgs/msg/String', which antkit does not decode"));
}

TEST_CASE("bags: broken MCAP files are located errors", "[io][bag][errors]") {
  const std::string d = bags();
  if (d.empty()) return;
  const std::string good = slurp(d + "/walk1.mcap");
  // truncated
  const auto cut = spill("cut.mcap", good.substr(0, good.size() - 100));
  CHECK_THAT(read_error(cut), StartsWith(cut + ": byte ") && Contains("truncated"));
  // a byte of a message changed inside a chunk: the chunk's CRC
  std::string flipped = good;
  const auto at = flipped.find("base_link");
  REQUIRE(at != std::string::npos);
  flipped[at] = 'c';
  const auto crc = spill("crc.mcap", flipped);
  CHECK_THAT(read_error(crc), StartsWith(crc + ": byte ") && Contains("CRC"));
  // the first record after the Header says it is longer than the file
  std::string longer = good;
  std::uint64_t header_length = 0;
  std::memcpy(&header_length, longer.data() + 9, 8);
  const std::size_t record = 8 + 9 + header_length;
  const std::uint64_t huge = 1ULL << 40;
  std::memcpy(longer.data() + record + 1, &huge, 8);
  const auto past = spill("past.mcap", longer);
  CHECK_THAT(read_error(past),
             StartsWith(past + ": byte " + std::to_string(record)) && Contains("runs past"));
  // an unknown compression (the summary's CRC zeroed: "not computed", as the spec allows)
  std::string lz4 = slurp(d + "/walk2_lz4.mcap");
  const std::string name("\x03\x00\x00\x00lz4", 7);
  for (auto p = lz4.find(name); p != std::string::npos; p = lz4.find(name, p + 1)) lz4[p + 6] = 'x';
  std::memset(lz4.data() + lz4.size() - 8 - 4, 0, 4);
  const auto unknown = spill("unknown.mcap", lz4);
  CHECK_THAT(read_error(unknown), Contains("unknown compression 'lzx'"));
  // not a bag at all
  const auto text = spill("text.mcap", "hello\n");
  CHECK_THAT(read_error(text), Contains("not a bag"));
}

TEST_CASE("bags: CDR shorter than its type, XCDR2, another encoding", "[io][bag][errors]") {
  // An Odometry of 20 bytes: a header and no pose.
  std::string shortmsg("\x00\x01\x00\x00", 4);
  shortmsg += std::string(16, '\0');
  const auto s = spill("short.mcap", one_channel("nav_msgs/msg/Odometry", "cdr", {shortmsg}));
  CHECK_THROWS_WITH(bag::read_poses(s, "/x", bag::Stamp::bag),
                    StartsWith(s + ": byte ") && Contains("before the end of its type"));
  const std::string xcdr2("\x00\x07\x00\x00\x00\x00\x00\x00", 8);
  const auto x = spill("xcdr2.mcap", one_channel("geometry_msgs/msg/Twist", "cdr", {xcdr2}));
  CHECK_THROWS_WITH(bag::read_poses(x, "/x", bag::Stamp::bag), Contains("XCDR2"));
  const auto j = spill("json.mcap", one_channel("geometry_msgs/msg/Twist", "json", {"{}"}));
  CHECK_THROWS_WITH(bag::read_poses(j, "/x", bag::Stamp::bag),
                    Contains("message encoding 'json' (expected cdr)"));
}

TEST_CASE("cdr: a big-endian PoseStamped, aligned after the encapsulation header", "[io][cdr]") {
  std::string m("\x00\x00\x00\x00", 4); // CDR big-endian
  put_be32(m, 12);                      // stamp.sec
  put_be32(m, 5);                       // stamp.nanosec
  put_be32(m, 3);                       // frame_id "ab" with its NUL: body offset 15
  m += std::string("ab\0", 3);
  m += '\0'; // padding to 16, the doubles' alignment
  for (const double v : {1.5, -2.25, 0.0, 0.0, 0.0, std::sin(0.3), std::cos(0.3)}) put_be64(m, v);
  const auto d = ros::decode(ros::MessageType::pose_stamped, m, "");
  CHECK(d.x == 1.5);
  CHECK(d.y == -2.25);
  CHECK(d.yaw == Approx(0.6));
  CHECK(d.stamp_ns == 12000000005);
  CHECK_THROWS_WITH(ros::decode(ros::MessageType::pose_stamped, m.substr(0, m.size() - 1), ""),
                    Contains("before the end of its type"));
  CHECK_THROWS_WITH(ros::decode(ros::MessageType::twist, std::string("\x00\x03\x00\x00", 4), ""),
                    Contains("parameter-list"));
}

TEST_CASE("mcap reader: reads back whatever antkit's writer writes", "[io][mcap][property]") {
  rc::prop("messages in, the same messages out", [] {
    const auto n = *rc::gen::inRange<std::size_t>(0, 60);
    const auto chunk = *rc::gen::inRange<std::uint64_t>(1, 600);
    std::ostringstream out;
    antkit::io::mcap::Writer w(out, {"", "antkit", chunk});
    const auto s = w.add_schema("s", "ros2msg", "x");
    const std::uint16_t channels[] = {w.add_channel(s, "/a", "cdr"), w.add_channel(0, "/b", "x")};
    std::vector<antkit::io::mcap::Message> written;
    for (std::size_t i = 0; i < n; ++i) {
      antkit::io::mcap::Message m;
      m.channel_id = channels[*rc::gen::inRange(0, 2)];
      m.sequence = static_cast<std::uint32_t>(i);
      m.log_time = *rc::gen::inRange<std::uint64_t>(0, 1000000);
      m.publish_time = m.log_time;
      m.data = *rc::gen::container<std::string>(rc::gen::arbitrary<char>());
      w.write(m);
      written.push_back(m);
    }
    w.finish();
    const std::string bytes = out.str();
    antkit::io::mcap::Reader r(bytes, "written.mcap");
    antkit::io::mcap::MessageView v;
    std::size_t i = 0;
    while (r.next(v)) {
      RC_ASSERT(i < written.size());
      RC_ASSERT(v.channel->id == written[i].channel_id);
      RC_ASSERT(v.log_time == written[i].log_time);
      RC_ASSERT(std::string(v.data) == written[i].data);
      ++i;
    }
    RC_ASSERT(i == written.size());
  });
}
