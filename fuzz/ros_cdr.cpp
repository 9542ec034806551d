// Fuzz target: CDR decoding of the ROS 2 pose messages (io/ros_messages.hpp). The first byte picks
// the type (and, for a TFMessage, whether the child frame is "base_link" or "laser"); the rest is
// the serialized message, encapsulation header included. Any input decodes or is refused with
// InputError; a decoded yaw is in [-pi, pi] or NaN (from NaN or infinite quaternion components).
#include <antkit/io/ros_messages.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  using antkit::io::ros::MessageType;
  const auto type = static_cast<MessageType>(data[0] % 5);
  const std::string_view frame = (data[0] / 5) % 2 == 0 ? "base_link" : "laser";
  const std::string_view cdr(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    const auto d = antkit::io::ros::decode(type, cdr, frame);
    if (d.has_pose && !std::isnan(d.yaw) && std::abs(d.yaw) > 3.1415927) std::abort();
  } catch (const antkit::kernel::InputError&) {
  }
  return 0;
}
