// The robots' ASCII protocols (protocol.hpp).
#include <algorithm>
#include <antkit/devices/protocol.hpp>
#include <charconv>
#include <stdexcept>

namespace antkit::devices {

namespace {

using kernel::Fx;

template <class T>
Decoded<T> error_at(std::size_t column, std::string message) {
  Decoded<T> d;
  d.error = {column, std::move(message)};
  return d;
}

// The values after a line's letter: from line[i], each a comma and a decimal in [lo, hi], at most
// max_n of them, appended to f; i is left after the last. An error names its column (from 1).
std::optional<DecodeError> scan_values(std::string_view line, std::size_t& i, Fields& f,
                                       std::int64_t lo, std::int64_t hi, std::size_t max_n) {
  while (i < line.size() && line[i] == ',') {
    ++i;
    const std::size_t start = i;
    bool negative = false;
    if (i < line.size() && line[i] == '-') negative = true, ++i;
    std::int64_t v = 0;
    std::size_t digits = 0;
    while (i < line.size() && line[i] >= '0' && line[i] <= '9') {
      if (digits++ == 10) return DecodeError{start + 1, "a value with too many digits"};
      v = v * 10 + (line[i++] - '0');
    }
    if (digits == 0) return DecodeError{i + 1, "expected a decimal value"};
    if (negative) v = -v;
    if (v < lo || v > hi)
      return DecodeError{start + 1, "value " + std::to_string(v) + " out of range [" +
                                        std::to_string(lo) + ", " + std::to_string(hi) + "]"};
    if (f.count == max_n)
      return DecodeError{start + 1, "more than " + std::to_string(max_n) + " values"};
    f.values[f.count++] = static_cast<std::int32_t>(v);
  }
  return std::nullopt;
}

Decoded<Fields> scan_text(std::string_view line, char letter) {
  if (line.empty() || line[0] != letter)
    return error_at<Fields>(1, std::string("expected the reply letter '") + letter + "'");
  std::size_t i = 1;
  if (i < line.size() && line[i] == ',') {
    ++i;
    while (i < line.size() && line[i] >= 0x20 && line[i] < 0x7F) ++i;
  }
  if (i + 2 != line.size() || line[i] != '\r' || line[i + 1] != '\n')
    return error_at<Fields>(i + 1, "expected printable text, then CR LF");
  Decoded<Fields> d;
  d.value = Fields{letter, {}, 0};
  return d;
}

// The letter, each value after a comma, the terminator: each value by to_chars, with no string
// of its own (a replay builds three commands a step; their temporaries were a tenth of its
// reply-side time), whatever the count of values.
std::string command(const RobotDescription& r, char letter, std::initializer_list<std::int32_t> v) {
  std::string s(1, letter);
  for (const auto x : v) {
    char digits[12]; // "-2147483648": 11
    s += ',';
    s.append(digits, std::to_chars(digits, digits + sizeof digits, x).ptr);
  }
  s += r.terminator;
  return s;
}

void check_speed(const RobotDescription& r, std::int32_t v) {
  if (v < r.speed_min || v > r.speed_max)
    throw std::out_of_range("wheel speed " + std::to_string(v) + " outside the robot's range");
}

} // namespace

Decoded<Fields> scan_reply(std::string_view line, char letter, std::size_t min_n, std::size_t max_n,
                           std::int64_t lo, std::int64_t hi) {
  if (line.empty()) return error_at<Fields>(1, "an empty reply");
  if (line[0] != letter)
    return error_at<Fields>(1, std::string("expected the reply letter '") + letter + "'");
  Fields f;
  f.letter = letter;
  std::size_t i = 1;
  if (auto e = scan_values(line, i, f, lo, hi, max_n))
    return error_at<Fields>(e->column, e->message);
  if (f.count < min_n)
    return error_at<Fields>(i + 1, "expected " + std::to_string(min_n) + " values, got " +
                                       std::to_string(f.count));
  if (i + 2 != line.size() || line[i] != '\r' || line[i + 1] != '\n') {
    if (i < line.size() && line[i] != '\r') return error_at<Fields>(i + 1, "unexpected byte");
    return error_at<Fields>(i + 1, "expected CR LF at the end of the reply");
  }
  Decoded<Fields> d;
  d.value = f;
  return d;
}

Decoded<Fields> scan_command(std::string_view line, bool lower_ok) {
  if (line.empty()) return error_at<Fields>(1, "an empty command");
  char letter = line[0];
  if (lower_ok && letter >= 'a' && letter <= 'z') letter = static_cast<char>(letter - 'a' + 'A');
  if (letter < 'A' || letter > 'Z') return error_at<Fields>(1, "expected a command letter");
  Fields f;
  f.letter = letter;
  std::size_t i = 1;
  if (auto e = scan_values(line, i, f, INT32_MIN, INT32_MAX, f.values.size()))
    return error_at<Fields>(e->column, e->message);
  if (i != line.size()) return error_at<Fields>(i + 1, "unexpected byte");
  Decoded<Fields> d;
  d.value = f;
  return d;
}

Codec::Codec(RobotKind robot)
    : robot_(&describe(robot)), read_proximity_(command(*robot_, 'N', {})),
      read_odometry_(robot_->has_odometry ? command(*robot_, robot_->odometry_read, {}) : "") {}

std::string Codec::set_speed(std::int32_t left, std::int32_t right) const {
  check_speed(*robot_, left);
  check_speed(*robot_, right);
  return command(*robot_, 'D', {left, right});
}
std::string Codec::read_speed() const {
  return command(*robot_, 'E', {});
}
std::string Codec::read_proximity() const {
  return read_proximity_;
}
std::string Codec::read_odometry() const {
  if (!robot_->has_odometry) throw std::logic_error("this robot has no wheel counters");
  return read_odometry_;
}
std::string Codec::set_odometry(std::int32_t left, std::int32_t right) const {
  if (!robot_->has_odometry) throw std::logic_error("this robot has no wheel counters");
  if (robot_->odometry_set == 0) // the Webots relay: G does nothing (robot.hpp)
    throw std::logic_error("this robot's wheel counters cannot be set");
  return command(*robot_, robot_->odometry_set, {left, right});
}
std::string Codec::set_led(std::int32_t led, std::int32_t action) const {
  if (led < 0 || led > 9 || action < 0 || action > 2) throw std::out_of_range("LED or action");
  return command(*robot_, 'L', {led, action});
}
std::string Codec::version() const {
  return command(*robot_, robot_->version_letter, {});
}
bool Codec::identifies(std::string_view version_reply) const {
  if (robot_->identifies == nullptr) return false;
  if (!scan_text(version_reply, reply_letter(robot_->version_letter))) return false;
  std::string_view text = version_reply.substr(1, version_reply.size() - 3); // letter .. CR LF
  if (!text.empty()) text.remove_prefix(1);                                  // the comma
  return robot_->identifies(text);
}

std::string identified_as(std::string_view version_command, std::string_view reply) {
  std::string out;
  for (const auto kind : serial_robots()) {
    const Codec codec(kind);
    if (codec.version() != version_command || !codec.identifies(reply)) continue;
    out += (out.empty() ? "" : ", ") + std::string(codec.robot().name);
  }
  return out;
}

std::vector<std::string> Codec::safe_stop() const {
  std::vector<std::string> out;
  for (const auto c : robot_->safe_stop)
    if (!c.empty()) out.push_back(std::string(c) + std::string(robot_->terminator));
  return out;
}

Decoded<bool> Codec::decode_ack(std::string_view line, char command_letter) const {
  const auto f = scan_reply(line, reply_letter(command_letter), 0, 0, 0, 0);
  if (!f) return error_at<bool>(f.error.column, f.error.message);
  Decoded<bool> d;
  d.value = true;
  return d;
}

Decoded<Proximity> Codec::decode_proximity(std::string_view line) const {
  const std::size_t extra = robot_->proximity_extra;
  const auto f = scan_reply(line, 'n', 8, 8 + extra, robot_->proximity_min, robot_->proximity_max);
  if (!f) return error_at<Proximity>(f.error.column, f.error.message);
  if (f.value->count != 8 && f.value->count != 8 + extra)
    return error_at<Proximity>(line.size() - 1, "expected 8 or 10 values");
  Decoded<Proximity> d;
  d.value.emplace();
  std::copy_n(f.value->values.begin(), 8, d.value->raw.begin());
  return d;
}

Decoded<WheelPair> Codec::decode_odometry(std::string_view line) const {
  if (!robot_->has_odometry) return error_at<WheelPair>(1, "this robot has no wheel counters");
  const auto f = scan_reply(line, reply_letter(robot_->odometry_read), 2, 2, INT32_MIN, INT32_MAX);
  if (!f) return error_at<WheelPair>(f.error.column, f.error.message);
  Decoded<WheelPair> d;
  d.value = WheelPair{f.value->values[0], f.value->values[1]};
  return d;
}

Decoded<WheelPair> Codec::decode_speed(std::string_view line) const {
  const auto f = scan_reply(line, 'e', 2, 2, robot_->speed_min, robot_->speed_max);
  if (!f) return error_at<WheelPair>(f.error.column, f.error.message);
  Decoded<WheelPair> d;
  d.value = WheelPair{f.value->values[0], f.value->values[1]};
  return d;
}

Decoded<Fields> Codec::decode_reply(std::string_view sent_command, std::string_view line) const {
  if (sent_command.empty()) return error_at<Fields>(1, "no command was sent");
  const char c = reply_letter(sent_command[0]);
  const auto& r = *robot_;
  if (c == 'n' || c == 'o') {
    const std::size_t extra = r.proximity_extra;
    const auto f = scan_reply(line, c, 8, 8 + extra, r.proximity_min, r.proximity_max);
    if (f && f.value->count != 8 && f.value->count != 8 + extra)
      return error_at<Fields>(line.size() - 1, "expected 8 or 10 values");
    return f;
  }
  if (c == 'e') return scan_reply(line, 'e', 2, 2, r.speed_min, r.speed_max);
  if (r.has_odometry && c == reply_letter(r.odometry_read))
    return scan_reply(line, c, 2, 2, INT32_MIN, INT32_MAX);
  if (c == 'b' || c == 'v') return scan_text(line, c);
  return scan_reply(line, c, 0, 0, 0, 0);
}

Decoded<Fields> Codec::parse_command(std::string_view line) const {
  return scan_command(line, robot_->lower_case_commands);
}

std::string Codec::reply(char command_letter, std::span<const std::int32_t> values) const {
  const char c = reply_letter(command_letter);
  std::string s(1, c);
  // HemiOS pads sensor readings to three digits (see protocol.hpp).
  const std::size_t pad = c == 'n' || c == 'o' ? robot_->reading_digits : 0;
  for (const auto v : values) {
    std::string digits = std::to_string(v);
    if (v >= 0 && digits.size() < pad) digits.insert(0, pad - digits.size(), '0');
    s += "," + digits;
  }
  return s + "\r\n";
}

std::string Codec::unknown_command_reply(std::string_view) const {
  return std::string(robot_->unknown_reply); // robot_<name>.cpp
}

Fx normalise_reading(const RobotDescription& robot, std::int32_t raw) {
  const std::int32_t v = std::clamp(raw, 0, robot.proximity_scale);
  return Fx::from_ratio(v, robot.proximity_scale);
}

ReadingNormaliser::ReadingNormaliser(const RobotDescription& robot)
    : robot_(&robot), raw_(static_cast<std::size_t>(std::max(robot.proximity_scale, 0)) + 1) {
  for (std::size_t v = 0; v < raw_.size(); ++v)
    raw_[v] = normalise_reading(robot, static_cast<std::int32_t>(v)).raw();
}

std::int32_t reading_to_raw(const RobotDescription& robot, Fx reading) {
  const std::int64_t v = (std::int64_t{reading.raw()} * robot.proximity_scale + 32768) >> 16;
  return static_cast<std::int32_t>(std::clamp<std::int64_t>(v, 0, robot.proximity_max));
}

std::int32_t to_wheel_command(const RobotDescription& robot, Fx m) {
  const std::int64_t v = (std::int64_t{m.raw()} * robot.speed_full + 32768) >> 16;
  return static_cast<std::int32_t>(std::clamp<std::int64_t>(v, robot.speed_min, robot.speed_max));
}

Fx from_wheel_command(const RobotDescription& robot, std::int32_t v) {
  return Fx::from_ratio(v, robot.speed_full);
}

} // namespace antkit::devices
