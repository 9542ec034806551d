#pragma once
// The ROS 2 messages antkit reads poses from, decoded from CDR (XCDR1, the encoding rosbag2 and
// every ROS 2 middleware write: OMG DDS-XTypes 1.3, section 7.4.3.5), written from the
// specification and the messages' definitions. Part of the antkit_bags target.
//
// A CDR message starts with a 4-byte encapsulation header: 0x00, then 0x00 (CDR, big-endian) or
// 0x01 (CDR, little-endian), then two option bytes. Primitives are aligned to their size, counted
// from the first byte after the header. Strings are a uint32 length (with the terminating NUL) and
// the bytes; sequences a uint32 count and the elements; fixed arrays the elements alone.
// XCDR2 (encapsulations 0x06 to 0x0b) and parameter lists (0x02, 0x03) are refused by name.
//
// The types, by their ROS 2 names (the MCAP schema name, the .db3 `topics.type`):
//   nav_msgs/msg/Odometry                      header, child_frame_id, pose.pose (covariance and
//                                              twist are read past)
//   geometry_msgs/msg/PoseStamped              header, pose
//   geometry_msgs/msg/PoseWithCovarianceStamped header, pose.pose
//   geometry_msgs/msg/Twist                    linear, angular: velocities (no header, no pose)
//   tf2_msgs/msg/TFMessage                     transforms[]: each a header, child_frame_id and a
//                                              transform; the one whose child frame is chosen
// Bad input is a kernel::InputError with an empty where() (the caller knows the file and the
// message): a message shorter than its type, a string without its NUL, an unknown encapsulation.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace antkit::io::ros {

enum class MessageType { odometry, pose_stamped, pose_with_covariance_stamped, twist, tf_message };

// The type of a ROS 2 type name, or nullopt for one antkit does not decode.
[[nodiscard]] std::optional<MessageType> message_type(std::string_view name) noexcept;
[[nodiscard]] std::string_view type_name(MessageType type) noexcept;
// "nav_msgs/msg/Odometry, ...": the names message_type() knows, for error messages.
[[nodiscard]] std::string decoded_type_names();

// One decoded message: a planar pose (metres, radians in (-pi, pi], from the quaternion's yaw),
// the header's stamp (ns since the epoch; sec * 10^9 + nanosec), and a Twist's velocities.
struct Decoded {
  bool has_pose = false; // a TFMessage without the chosen child frame has none; a Twist neither
  double x = 0, y = 0, yaw = 0;
  bool has_stamp = false;
  std::int64_t stamp_ns = 0;
  double vx = 0, vy = 0, wz = 0; // Twist: linear.x, linear.y (m/s), angular.z (rad/s)
};

// Decodes `cdr` (the whole serialized message, encapsulation header included) as `type`; for a
// TFMessage, the first transform whose child_frame_id is `child_frame` (a leading '/' ignored on
// either side).
[[nodiscard]] Decoded decode(MessageType type, std::string_view cdr, std::string_view child_frame);

// The yaw of a unit quaternion (rotation about z), radians in [-pi, pi].
[[nodiscard]] double yaw_of(double x, double y, double z, double w) noexcept;

} // namespace antkit::io::ros
