// CDR (XCDR1) decoding of the ROS 2 messages antkit reads poses from (ros_messages.hpp).
#include <antkit/io/ros_messages.hpp>
#include <antkit/kernel/input_error.hpp>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>

namespace antkit::io::ros {

namespace {

using kernel::InputError;

constexpr std::array<std::pair<std::string_view, MessageType>, 5> kTypes{{
    {"nav_msgs/msg/Odometry", MessageType::odometry},
    {"geometry_msgs/msg/PoseStamped", MessageType::pose_stamped},
    {"geometry_msgs/msg/PoseWithCovarianceStamped", MessageType::pose_with_covariance_stamped},
    {"geometry_msgs/msg/Twist", MessageType::twist},
    {"tf2_msgs/msg/TFMessage", MessageType::tf_message},
}};

// XCDR1 over one message: alignment counts from the byte after the encapsulation header.
class CdrReader {
public:
  explicit CdrReader(std::string_view message) {
    if (message.size() < 4)
      throw InputError("", "a CDR message of " + std::to_string(message.size()) +
                               " bytes, shorter than its 4-byte encapsulation header");
    const auto kind = static_cast<unsigned char>(message[1]);
    if (message[0] != 0 || kind > 0x0b)
      throw InputError("", "unknown CDR encapsulation " + hex(message) +
                               " (expected 00 01, CDR little-endian, or 00 00, big-endian)");
    if (kind >= 0x06)
      throw InputError("", "XCDR2 encapsulation " + hex(message) +
                               " (antkit decodes XCDR1: 00 01 or 00 00)");
    if (kind == 0x02 || kind == 0x03)
      throw InputError("", "parameter-list CDR encapsulation " + hex(message) +
                               " (antkit decodes plain XCDR1: 00 01 or 00 00)");
    if (kind > 0x03) throw InputError("", "unknown CDR encapsulation " + hex(message));
    little_ = kind == 0x01;
    body_ = message.substr(4);
  }

  void align(std::size_t n) {
    const std::size_t aligned = (at_ + n - 1) / n * n;
    need(aligned - at_);
    at_ = aligned;
  }
  std::uint32_t u32() {
    align(4);
    need(4);
    std::uint32_t v = 0;
    std::memcpy(&v, body_.data() + at_, 4);
    at_ += 4;
    return little_ == (std::endian::native == std::endian::little) ? v : __builtin_bswap32(v);
  }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  double f64() {
    align(8);
    need(8);
    std::uint64_t v = 0;
    std::memcpy(&v, body_.data() + at_, 8);
    at_ += 8;
    if (little_ != (std::endian::native == std::endian::little)) v = __builtin_bswap64(v);
    return std::bit_cast<double>(v);
  }
  void skip_f64(std::size_t n) {
    align(8);
    need(8 * n);
    at_ += 8 * n;
  }
  std::string_view string() {
    const std::uint32_t n = u32();
    if (n == 0) return {}; // some writers send an empty string as length 0
    need(n);
    const std::string_view s = body_.substr(at_, n);
    at_ += n;
    if (s.back() != '\0') throw InputError("", "a CDR string without its terminating NUL");
    return s.substr(0, n - 1);
  }

private:
  void need(std::size_t n) const {
    if (body_.size() - at_ < n)
      throw InputError("", "the CDR message ends at byte " + std::to_string(body_.size() + 4) +
                               ", before the end of its type (it needs " +
                               std::to_string(at_ + n + 4) + " bytes or more)");
  }
  static std::string hex(std::string_view m) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string s;
    for (std::size_t i = 0; i < 2; ++i) {
      const auto b = static_cast<unsigned char>(m[i]);
      if (i != 0) s += ' ';
      s += digits[b >> 4];
      s += digits[b & 15];
    }
    return s;
  }

  std::string_view body_;
  std::size_t at_ = 0;
  bool little_ = true;
};

void header(CdrReader& r, Decoded& d) {
  const std::int32_t sec = r.i32();
  const std::uint32_t nanosec = r.u32();
  r.string(); // frame_id
  d.has_stamp = true;
  d.stamp_ns = std::int64_t{sec} * 1000000000 + std::int64_t{nanosec};
}

void pose(CdrReader& r, Decoded& d) {
  d.x = r.f64();
  d.y = r.f64();
  r.f64(); // z
  const double qx = r.f64(), qy = r.f64(), qz = r.f64(), qw = r.f64();
  d.yaw = yaw_of(qx, qy, qz, qw);
  d.has_pose = true;
}

std::string_view without_slash(std::string_view frame) {
  return !frame.empty() && frame.front() == '/' ? frame.substr(1) : frame;
}

} // namespace

std::optional<MessageType> message_type(std::string_view name) noexcept {
  for (const auto& [n, t] : kTypes)
    if (n == name) return t;
  return std::nullopt;
}

std::string_view type_name(MessageType type) noexcept {
  for (const auto& [n, t] : kTypes)
    if (t == type) return n;
  return "";
}

std::string decoded_type_names() {
  std::string s;
  for (const auto& [n, t] : kTypes) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

double yaw_of(double x, double y, double z, double w) noexcept {
  return std::atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
}

Decoded decode(MessageType type, std::string_view cdr, std::string_view child_frame) {
  CdrReader r(cdr);
  Decoded d;
  switch (type) {
  case MessageType::odometry:
    header(r, d);
    r.string(); // child_frame_id
    pose(r, d);
    r.skip_f64(36); // pose.covariance
    r.skip_f64(6);  // twist.twist
    r.skip_f64(36); // twist.covariance
    break;
  case MessageType::pose_stamped:
    header(r, d);
    pose(r, d);
    break;
  case MessageType::pose_with_covariance_stamped:
    header(r, d);
    pose(r, d);
    r.skip_f64(36);
    break;
  case MessageType::twist:
    d.vx = r.f64();
    d.vy = r.f64();
    r.f64(); // linear.z
    r.f64(); // angular.x
    r.f64(); // angular.y
    d.wz = r.f64();
    break;
  case MessageType::tf_message: {
    const std::uint32_t n = r.u32();
    const std::string_view wanted = without_slash(child_frame);
    for (std::uint32_t i = 0; i < n; ++i) {
      Decoded t;
      header(r, t);
      const std::string_view child = without_slash(r.string());
      t.x = r.f64();
      t.y = r.f64();
      r.f64();
      const double qx = r.f64(), qy = r.f64(), qz = r.f64(), qw = r.f64();
      if (!d.has_pose && child == wanted) {
        d = t;
        d.yaw = yaw_of(qx, qy, qz, qw);
        d.has_pose = true;
      }
    }
    break;
  }
  }
  return d;
}

} // namespace antkit::io::ros
