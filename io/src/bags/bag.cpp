// ROS 2 bags (bag.hpp): MCAP files, sqlite3 .db3 files and bag folders with a metadata.yaml.
#include <algorithm>
#include <antkit/io/bag.hpp>
#include <antkit/io/mcap_reader.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sqlite3.h>

namespace antkit::io::bag {

namespace {

using kernel::InputError;
namespace fs = std::filesystem;

constexpr std::string_view kSqliteMagic{"SQLite format 3\0", 16};
constexpr std::string_view kMcapMagic{"\x89MCAP0\r\n", 8};

std::string first_bytes(const std::string& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the bag");
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  std::string v(s.substr(b, e - b + 1));
  if (v.size() >= 2 && (v.front() == '"' || v.front() == '\'') && v.back() == v.front())
    v = v.substr(1, v.size() - 2);
  return v;
}

// metadata.yaml, the part of it that is needed: rosbag2_bagfile_information's storage_identifier,
// compression_format and relative_file_paths (a block list).
struct Metadata {
  std::string storage, compression;
  std::vector<std::string> files;
};

Metadata read_metadata(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open the bag's metadata");
  Metadata m;
  std::string line;
  std::size_t number = 0, list_indent = std::string::npos;
  bool seen_root = false, seen_storage = false;
  while (std::getline(in, line)) {
    ++number;
    const auto indent = line.find_first_not_of(' ');
    if (indent == std::string::npos || line[indent] == '#') continue;
    const std::string_view rest = std::string_view(line).substr(indent);
    if (list_indent != std::string::npos) {
      if (indent >= list_indent && rest.starts_with("- ")) {
        m.files.push_back(trim(rest.substr(2)));
        if (m.files.back().empty())
          throw InputError(path, number, indent + 3, "an empty file name in relative_file_paths");
        continue;
      }
      list_indent = std::string::npos;
    }
    if (rest.starts_with("rosbag2_bagfile_information:")) seen_root = true;
    const auto colon = rest.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string key(rest.substr(0, colon));
    const std::string value = trim(rest.substr(colon + 1));
    if (key == "storage_identifier") {
      m.storage = value;
      seen_storage = true;
      if (value != "sqlite3" && value != "mcap")
        throw InputError(path, number, indent + colon + 3,
                         "storage_identifier '" + value + "' (expected sqlite3 or mcap)");
    } else if (key == "compression_format") {
      m.compression = value;
      if (!value.empty())
        throw InputError(path, number, indent + colon + 3,
                         "compression_format '" + value +
                             "': bags compressed file by file are not read (per-chunk MCAP "
                             "compression is; expected \"\")");
    } else if (key == "relative_file_paths" && value.empty()) {
      list_indent = indent;
    }
  }
  if (!seen_root)
    throw InputError(path, 1, 1, "not a rosbag2 metadata.yaml (no rosbag2_bagfile_information)");
  if (!seen_storage)
    throw InputError(path, 1, 1, "no storage_identifier (expected sqlite3 or mcap)");
  if (m.files.empty()) throw InputError(path, 1, 1, "no relative_file_paths: the bag has no files");
  return m;
}

Storage storage_of_file(const std::string& path) {
  const std::string head = first_bytes(path, 16);
  if (head.starts_with(kMcapMagic)) return Storage::mcap;
  if (head == kSqliteMagic) return Storage::sqlite3;
  throw InputError(path, "not a bag: neither an MCAP file nor a sqlite3 database (expected an "
                         ".mcap, a .db3 or a folder with a metadata.yaml)");
}

} // namespace

std::string_view storage_name(Storage storage) noexcept {
  return storage == Storage::mcap ? "mcap" : "sqlite3";
}

// One storage file being read.
struct Reader::File {
  virtual ~File() = default;
  virtual bool next(Message& out) = 0;
  [[nodiscard]] virtual std::string where() const = 0;
  virtual void topics(std::map<std::string, TopicInfo>& into) const = 0;
};

namespace {

class McapFile final : public Reader::File {
public:
  explicit McapFile(const std::string& path) : reader_(path) {}
  bool next(Message& out) override {
    if (!reader_.next(view_)) return false;
    const auto id = view_.channel->id;
    auto it = topics_.find(id);
    if (it == topics_.end()) {
      TopicInfo t;
      t.name = view_.channel->topic;
      t.encoding = view_.channel->message_encoding;
      if (const auto* s = reader_.schema_of(*view_.channel)) t.type = s->name;
      it = topics_.emplace(id, std::move(t)).first;
    }
    out.topic = &it->second;
    out.time_ns = view_.log_time;
    out.data = view_.data;
    return true;
  }
  [[nodiscard]] std::string where() const override { return reader_.where(view_); }
  void topics(std::map<std::string, TopicInfo>& into) const override {
    for (const auto& [id, c] : reader_.channels()) {
      TopicInfo t;
      t.name = c.topic;
      t.encoding = c.message_encoding;
      if (const auto* s = reader_.schema_of(c)) t.type = s->name;
      into.emplace(t.name, std::move(t));
    }
  }

private:
  mcap::Reader reader_;
  mcap::MessageView view_;
  std::map<std::uint16_t, TopicInfo> topics_;
};

class Db3File final : public Reader::File {
public:
  // The database and its statements are owned by unique_ptrs, so that a constructor that throws
  // (a file that is not a database, a table missing) still closes what it opened.
  explicit Db3File(const std::string& path) : path_(path) {
    sqlite3* db = nullptr;
    const int opened = sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
    db_.reset(db); // sqlite3_open_v2 gives a handle to close even when it fails
    if (opened != SQLITE_OK) fail("cannot open as a sqlite3 database");
    const Statement t =
        prepare("SELECT id, name, type, serialization_format FROM topics", "topics");
    int rc = 0;
    while ((rc = sqlite3_step(t.get())) == SQLITE_ROW) {
      TopicInfo info;
      info.name = text(t.get(), 1);
      info.type = text(t.get(), 2);
      info.encoding = text(t.get(), 3);
      topics_[sqlite3_column_int64(t.get(), 0)] = std::move(info);
    }
    if (rc != SQLITE_DONE) fail("table topics: " + std::string(sqlite3_errmsg(db_.get())));
    messages_ = prepare("SELECT id, topic_id, timestamp, data FROM messages ORDER BY timestamp, id",
                        "messages");
  }
  Db3File(const Db3File&) = delete;
  Db3File& operator=(const Db3File&) = delete;

  bool next(Message& out) override {
    sqlite3_stmt* const messages = messages_.get();
    const int rc = sqlite3_step(messages);
    if (rc == SQLITE_DONE) return false;
    if (rc != SQLITE_ROW) fail("table messages: " + std::string(sqlite3_errmsg(db_.get())));
    row_ = sqlite3_column_int64(messages, 0);
    const auto topic = sqlite3_column_int64(messages, 1);
    const auto it = topics_.find(topic);
    if (it == topics_.end())
      throw InputError(where(), "topic_id " + std::to_string(topic) + " is not in table topics");
    const auto time = sqlite3_column_int64(messages, 2);
    if (time < 0) throw InputError(where(), "a negative timestamp");
    const void* blob = sqlite3_column_blob(messages, 3);
    const int size = sqlite3_column_bytes(messages, 3);
    out.topic = &it->second;
    out.time_ns = static_cast<std::uint64_t>(time);
    out.data = blob == nullptr ? std::string_view{}
                               : std::string_view(static_cast<const char*>(blob),
                                                  static_cast<std::size_t>(size));
    return true;
  }
  [[nodiscard]] std::string where() const override {
    return path_ + ": messages row " + std::to_string(row_);
  }
  void topics(std::map<std::string, TopicInfo>& into) const override {
    for (const auto& [id, t] : topics_) into.emplace(t.name, t);
  }

private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_, what + " (expected a rosbag2 .db3: tables topics and messages)");
  }
  using Statement = std::unique_ptr<sqlite3_stmt, decltype(&sqlite3_finalize)>;
  Statement prepare(const char* sql, const char* table) {
    sqlite3_stmt* s = nullptr;
    const int rc = sqlite3_prepare_v2(db_.get(), sql, -1, &s, nullptr);
    Statement owned(s, &sqlite3_finalize);
    if (rc != SQLITE_OK) fail(std::string("table ") + table + ": " + sqlite3_errmsg(db_.get()));
    return owned;
  }
  static std::string text(sqlite3_stmt* s, int column) {
    const auto* p = sqlite3_column_text(s, column);
    return p == nullptr ? std::string() : std::string(reinterpret_cast<const char*>(p));
  }

  std::string path_;
  std::unique_ptr<sqlite3, decltype(&sqlite3_close)> db_{nullptr, &sqlite3_close};
  Statement messages_{nullptr, &sqlite3_finalize}; // after db_: finalized before it closes
  std::map<std::int64_t, TopicInfo> topics_;
  std::int64_t row_ = 0;
};

} // namespace

Reader::Reader(const std::string& path) : path_(path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    const std::string yaml = (fs::path(path) / "metadata.yaml").string();
    if (!fs::exists(yaml, ec))
      throw InputError(path, "a folder without metadata.yaml is not a bag (expected an .mcap, a "
                             ".db3 or a rosbag2 folder)");
    const Metadata m = read_metadata(yaml);
    storage_ = m.storage == "mcap" ? Storage::mcap : Storage::sqlite3;
    for (const auto& f : m.files) files_.push_back((fs::path(path) / f).string());
  } else {
    storage_ = storage_of_file(path);
    files_.push_back(path);
  }
  open_next_file();
}

Reader::~Reader() = default;

bool Reader::open_next_file() {
  if (file_) file_->topics(seen_);
  file_.reset();
  if (next_file_ == files_.size()) return false;
  const std::string& f = files_[next_file_++];
  if (files_.size() > 1 || f != path_) {
    const Storage s = storage_of_file(f);
    if (s != storage_)
      throw InputError(f, "a " + std::string(storage_name(s)) +
                              " file in a bag whose metadata.yaml "
                              "says " +
                              std::string(storage_name(storage_)));
  }
  if (storage_ == Storage::mcap)
    file_ = std::make_unique<McapFile>(f);
  else
    file_ = std::make_unique<Db3File>(f);
  return true;
}

bool Reader::next(Message& out) {
  while (file_) {
    if (file_->next(out)) return true;
    if (!open_next_file()) return false;
  }
  return false;
}

std::string Reader::where() const {
  return file_ ? file_->where() : path_;
}

std::vector<TopicInfo> Reader::topics() const {
  std::map<std::string, TopicInfo> all = seen_;
  if (file_) file_->topics(all);
  std::vector<TopicInfo> out;
  for (auto& [name, t] : all) out.push_back(std::move(t));
  return out;
}

BagInfo bag_info(const std::string& path) {
  Reader reader(path);
  BagInfo info;
  info.path = path;
  info.storage = reader.storage();
  info.files = reader.files();
  std::map<std::string, TopicInfo> topics;
  for (auto& t : reader.topics()) topics.emplace(t.name, std::move(t));
  Message m;
  while (reader.next(m)) {
    auto it = topics.find(m.topic->name);
    if (it == topics.end()) it = topics.emplace(m.topic->name, *m.topic).first;
    TopicInfo& t = it->second;
    ++t.messages;
    t.first_ns = std::min(t.first_ns.value_or(m.time_ns), m.time_ns);
    t.last_ns = std::max(t.last_ns.value_or(m.time_ns), m.time_ns);
    ++info.messages;
    info.first_ns = std::min(info.first_ns.value_or(m.time_ns), m.time_ns);
    info.last_ns = std::max(info.last_ns.value_or(m.time_ns), m.time_ns);
  }
  for (auto& t : reader.topics()) topics.emplace(t.name, std::move(t)); // channels without messages
  for (auto& [name, t] : topics) info.topics.push_back(std::move(t));
  return info;
}

namespace {

std::string topic_names(const std::vector<TopicInfo>& topics) {
  std::string s;
  for (const auto& t : topics) s += (s.empty() ? "" : ", ") + t.name;
  return s.empty() ? "none" : s;
}

} // namespace

PoseTrack read_poses(const std::string& path, const std::string& topic, Stamp stamp,
                     const std::string& child_frame) {
  Reader reader(path);
  PoseTrack track;
  track.path = path;
  track.topic = topic;
  track.stamp = stamp;
  std::optional<ros::MessageType> type;
  const auto check_topic = [&](const TopicInfo& t) {
    track.type = t.type;
    type = ros::message_type(t.type);
    if (!type)
      throw InputError(path, "topic " + topic + " has type '" + t.type +
                                 "', which antkit does not decode (it decodes " +
                                 ros::decoded_type_names() + ")");
    if (t.encoding != "cdr")
      throw InputError(path, "topic " + topic + " has message encoding '" + t.encoding +
                                 "' (expected cdr)");
    if (*type == ros::MessageType::twist && stamp == Stamp::header)
      throw InputError("stamp", "topic " + topic +
                                    " is a geometry_msgs/msg/Twist, which has no header.stamp "
                                    "(expected bag)");
    if (*type == ros::MessageType::tf_message) track.child_frame = child_frame;
  };
  // A .db3's topics are known before its messages; an MCAP file's when its channel is met.
  bool known = false;
  for (const auto& t : reader.topics())
    if (t.name == topic) check_topic(t), known = true;
  if (!known && reader.storage() == Storage::sqlite3)
    throw InputError(path, "topic " + topic + " is not in the bag (its topics: " +
                               topic_names(reader.topics()) + ")");
  Message m;
  std::error_code ec;
  double vx = 0, vy = 0, wz = 0;
  while (reader.next(m)) {
    if (m.topic->name != topic) continue;
    if (!type) check_topic(*m.topic);
    if (track.messages == 0) {
      // Room for as many poses as messages of this size the bag could hold (an upper bound when
      // the messages are of one size): reserved, not touched, so unused room costs no memory, and
      // the list is not copied as it grows (a million poses, 56 MB, copied twice over is a third
      // of the time of reading them).
      std::uint64_t bytes = 0;
      for (const auto& f : reader.files()) bytes += fs::file_size(f, ec);
      track.poses.reserve(static_cast<std::size_t>(
          std::min<std::uint64_t>(bytes / (m.data.size() + 31), std::uint64_t{1} << 26)));
    }
    ++track.messages;
    ros::Decoded d;
    try {
      d = ros::decode(*type, m.data, child_frame);
    } catch (const InputError& e) {
      throw InputError(reader.where(), topic + " (" + track.type + "): " + e.message());
    }
    TimedPose p;
    p.bag_ns = m.time_ns;
    if (*type == ros::MessageType::twist) {
      if (!track.poses.empty()) {
        const TimedPose& last = track.poses.back();
        const double dt = (static_cast<double>(m.time_ns) - static_cast<double>(last.bag_ns)) / 1e9;
        const double heading = last.yaw + wz * dt / 2;
        p.x = last.x + (vx * std::cos(heading) - vy * std::sin(heading)) * dt;
        p.y = last.y + (vx * std::sin(heading) + vy * std::cos(heading)) * dt;
        p.yaw = std::remainder(last.yaw + wz * dt, 2 * std::numbers::pi);
      }
      vx = d.vx, vy = d.vy, wz = d.wz;
    } else {
      if (!d.has_pose) continue; // a TFMessage without the child frame
      p.x = d.x, p.y = d.y, p.yaw = d.yaw;
      p.header_ns = d.stamp_ns;
    }
    p.t_ns =
        stamp == Stamp::header && p.header_ns ? *p.header_ns : static_cast<std::int64_t>(p.bag_ns);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw))
      throw InputError(reader.where(), topic + ": a pose that is not finite");
    track.poses.push_back(p);
  }
  if (!type)
    throw InputError(path, "topic " + topic + " is not in the bag (its topics: " +
                               topic_names(reader.topics()) + ")");
  if (track.poses.empty())
    throw InputError(path, "topic " + topic +
                               (track.messages == 0
                                    ? std::string(" has no messages")
                                    : " has no transform whose child frame is '" + child_frame +
                                          "' (choose one with the child frame)"));
  return track;
}

} // namespace antkit::io::bag
