#pragma once
// ROS 2 bags (rosbag2), read: a bag is an `.mcap` file (the ros2 profile: CDR messages, schemas
// named by their ROS 2 types), a sqlite3 `.db3` file (the stable columns alone: topics(id, name,
// type, serialization_format), messages(topic_id, timestamp, data), in timestamp order), or a bag
// folder whose metadata.yaml names its storage and files (read in the order it lists them). Part of
// the antkit_bags target (it links libsqlite3, libzstd and liblz4; antkit_io does not).
//
// Bad input is a kernel::InputError located in the bag: "FILE: byte N" in an MCAP file,
// "FILE: messages row N" in a .db3, "FILE:LINE:COL" in a metadata.yaml.
#include <antkit/io/ros_messages.hpp>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::io::bag {

enum class Storage { mcap, sqlite3 };
[[nodiscard]] std::string_view storage_name(Storage storage) noexcept; // "mcap", "sqlite3"

struct TopicInfo {
  std::string name, type, encoding; // encoding: "cdr" in ROS 2 bags
  std::uint64_t messages = 0;
  std::optional<std::uint64_t> first_ns, last_ns; // bag time; absent without messages
};

struct BagInfo {
  std::string path;
  Storage storage = Storage::mcap;
  std::vector<std::string> files; // the storage files read, in order
  std::vector<TopicInfo> topics;  // by name
  std::uint64_t messages = 0;
  std::optional<std::uint64_t> first_ns, last_ns;
};

// One message as the bag holds it; the views are valid until the next call to next().
struct Message {
  const TopicInfo* topic = nullptr; // its name, type and encoding (counts not filled in)
  std::uint64_t time_ns = 0;        // bag time: the MCAP log time, the .db3 timestamp
  std::string_view data;
};

class Reader {
public:
  // Opens a bag: an .mcap or .db3 file (by its contents, not its name), or a folder with a
  // metadata.yaml. Throws InputError(path, ...) when it is none of these.
  explicit Reader(const std::string& path);
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  // The next message (of any topic) in the storage's order; false after the last file's last.
  bool next(Message& out);
  // "FILE: byte N" / "FILE: messages row N": where the message next() returned is.
  [[nodiscard]] std::string where() const;
  [[nodiscard]] Storage storage() const noexcept { return storage_; }
  [[nodiscard]] const std::vector<std::string>& files() const noexcept { return files_; }
  // The topics known so far (a .db3's from its table; an MCAP file's as its channels are met).
  [[nodiscard]] std::vector<TopicInfo> topics() const;

  struct File; // one storage file being read (bag.cpp)

private:
  bool open_next_file();
  std::string path_;
  Storage storage_ = Storage::mcap;
  std::vector<std::string> files_;
  std::size_t next_file_ = 0;
  std::unique_ptr<File> file_;
  std::map<std::string, TopicInfo> seen_; // the topics of the files already read
};

// Every message read once: the topics with their counts and bag-time ranges.
[[nodiscard]] BagInfo bag_info(const std::string& path);

// Which time a pose carries: the bag's (when it was recorded) or the message's header.stamp.
enum class Stamp { bag, header };

struct TimedPose {
  double x = 0, y = 0, yaw = 0; // metres, radians
  std::uint64_t bag_ns = 0;
  std::optional<std::int64_t> header_ns; // absent for a Twist
  std::int64_t t_ns = 0;                 // the chosen one (Stamp)
};

struct PoseTrack {
  std::string path, topic, type;
  Stamp stamp = Stamp::bag;
  std::string child_frame; // TFMessage only
  std::vector<TimedPose> poses;
  std::uint64_t messages = 0; // on the topic (a TFMessage's without the child frame included)
};

// The poses of one topic, in the bag's order. A Twist topic's velocities are integrated over bag
// time from the origin, heading 0 (each message's velocities held until the next message's time;
// the heading moved by half the step's turn for the step's direction). Throws InputError for: a
// topic not in the bag (listing its topics), a type antkit does not decode, a message encoding
// other than "cdr", a message that does not decode (located), --stamp header on a Twist, a
// TFMessage topic without the child frame, and a topic without messages.
[[nodiscard]] PoseTrack read_poses(const std::string& path, const std::string& topic, Stamp stamp,
                                   const std::string& child_frame = "base_link");

} // namespace antkit::io::bag
