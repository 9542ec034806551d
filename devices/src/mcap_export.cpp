// A hardware log as MCAP (mcap_export.hpp).
#include <algorithm>
#include <antkit/devices/mcap_export.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/io/mcap.hpp>
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/int_ops.hpp>
#include <array>
#include <bit>
#include <charconv>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

namespace antkit::devices {

namespace {

namespace mcap = io::mcap;

// The schemas: JSON Schema texts written for antkit, naming the fields of Foxglove's message types
// that antkit fills (the names and types of foxglove/schemas' jsonschema/*.json).
constexpr std::string_view kTime =
    R"({"type":"object","properties":{"sec":{"type":"integer","minimum":0},)"
    R"("nsec":{"type":"integer","minimum":0,"maximum":999999999}}})";
std::string vec3() {
  return R"({"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"},)"
         R"("z":{"type":"number"}}})";
}
std::string pose_schema() {
  return R"({"type":"object","properties":{"position":)" + vec3() +
         R"(,"orientation":{"type":"object","properties":{"x":{"type":"number"},)"
         R"("y":{"type":"number"},"z":{"type":"number"},"w":{"type":"number"}}}}})";
}
std::string object_schema(std::string_view title, const std::string& properties) {
  return R"({"title":")" + std::string(title) + R"(","type":"object","properties":{)" + properties +
         "}}";
}
std::string timestamp_property() {
  return R"("timestamp":)" + std::string(kTime);
}
const std::string kInts = R"({"type":"array","items":{"type":"integer"}})";

} // namespace

std::string mcap_schema(std::string_view name) {
  if (name == "foxglove.Grid") {
    const std::string count = R"({"type":"integer","minimum":0})";
    return object_schema(name,
                         timestamp_property() + R"(,"frame_id":{"type":"string"},"pose":)" +
                             pose_schema() + R"(,"column_count":)" + count +
                             R"(,"cell_size":{"type":"object","properties":{"x":{"type":"number"},)"
                             R"("y":{"type":"number"}}},"row_stride":)" +
                             count + R"(,"cell_stride":)" + count +
                             R"(,"fields":{"type":"array","items":{"type":"object","properties":{)"
                             R"("name":{"type":"string"},"offset":)" +
                             count +
                             R"(,"type":{"type":"integer","minimum":0,"maximum":8}}}},)"
                             R"("data":{"type":"string","contentEncoding":"base64"})");
  }
  if (name == "foxglove.PoseInFrame")
    return object_schema(name, timestamp_property() + R"(,"frame_id":{"type":"string"},"pose":)" +
                                   pose_schema());
  if (name == "foxglove.PosesInFrame")
    return object_schema(name, timestamp_property() +
                                   R"(,"frame_id":{"type":"string"},"poses":{"type":"array",)"
                                   R"("items":)" +
                                   pose_schema() + "}");
  if (name == "foxglove.Log")
    return object_schema(name,
                         timestamp_property() +
                             R"(,"level":{"type":"integer","minimum":0,"maximum":5},)"
                             R"("message":{"type":"string"},"name":{"type":"string"},)"
                             R"("file":{"type":"string"},"line":{"type":"integer","minimum":0})");
  if (name == "foxglove.SceneUpdate") {
    const std::string array = R"({"type":"array"})";
    const std::string line =
        R"({"type":"object","properties":{"type":{"type":"integer","minimum":0,"maximum":2},)"
        R"("pose":)" +
        pose_schema() +
        R"(,"thickness":{"type":"number"},"scale_invariant":{"type":"boolean"},)"
        R"("points":{"type":"array","items":)" +
        vec3() +
        R"(},"color":{"type":"object","properties":{"r":{"type":"number"},)"
        R"("g":{"type":"number"},"b":{"type":"number"},"a":{"type":"number"}}},)"
        R"("colors":{"type":"array"},"indices":{"type":"array","items":{"type":"integer"}}}})";
    std::string entity = R"({"type":"object","properties":{)" + timestamp_property() +
                         R"(,"frame_id":{"type":"string"},"id":{"type":"string"},"lifetime":)" +
                         std::string(kTime) +
                         R"(,"frame_locked":{"type":"boolean"},"metadata":{"type":"array"},)";
    for (const char* p :
         {"arrows", "cubes", "spheres", "cylinders", "triangles", "texts", "models"})
      entity += "\"" + std::string(p) + "\":" + array + ",";
    entity += R"("lines":{"type":"array","items":)" + line + "}}}";
    return object_schema(name, R"("deletions":{"type":"array"},"entities":{"type":"array",)"
                               R"("items":)" +
                                   entity + "}");
  }
  if (name == "antkit.Step")
    return object_schema(name, timestamp_property() + R"(,"step":{"type":"integer"},"obs":)" +
                                   kInts + R"(,"cmd":)" + kInts + R"(,"odo":)" + kInts +
                                   R"(,"state":{"type":"string"})");
  if (name == "antkit.ReplayedStep")
    return object_schema(
        name, timestamp_property() +
                  R"(,"step":{"type":"integer"},"identical":{"type":"boolean"})"
                  R"(,"obs":)" +
                  kInts + R"(,"cmd":)" + kInts + R"(,"odo":)" + kInts +
                  R"(,"state":{"type":"string"},"divergence":{"type":"object","properties":{)"
                  R"("field":{"type":"string"},"recorded":{"type":"string"},)"
                  R"("replayed":{"type":"string"}}})");
  // antkit.Exchanges
  return object_schema(
      name, timestamp_property() +
                R"(,"step":{"type":"integer"},"io":{"type":"array","items":{"type":"object",)"
                R"("properties":{"sent":{"type":"string","contentEncoding":"base64"},)"
                R"("received":{"type":"string","contentEncoding":"base64"},)"
                R"("t_ns":{"type":["integer","null"]}}}})");
}

namespace {

// JSON text, written by hand so that every byte is fixed by the values (strings as the log
// writes its byte strings, log.hpp), appended in place: the per-step messages go straight into
// the MCAP writer's chunk (Chunk::begin_message), with no string built per field.
//
// Text appends through a pointer into room made at the string's end, so that a field costs a
// bounds check and a copy, not a call into the library's string (std::string's members are
// compiled in libstdc++, out of line); the destructor cuts the string to what was written. While
// a Text is open nothing else may append to its string.
class Text {
public:
  explicit Text(std::string& s) : s_(s) {
    const std::size_t at = s_.size();
    s_.resize(at + kRoom);
    p_ = s_.data() + at;
    e_ = s_.data() + s_.size();
  }
  ~Text() { s_.resize(static_cast<std::size_t>(p_ - s_.data())); }
  Text(const Text&) = delete;
  Text& operator=(const Text&) = delete;

  Text& lit(std::string_view v) {
    need(v.size());
    std::memcpy(p_, v.data(), v.size());
    p_ += v.size();
    return *this;
  }
  // A literal: its length known here, so the copy is a few moves, not a call.
  template <std::size_t N>
  Text& lit(const char (&v)[N]) {
    need(N - 1);
    std::memcpy(p_, v, N - 1);
    p_ += N - 1;
    return *this;
  }
  Text& ch(char c) {
    need(1);
    *p_++ = c;
    return *this;
  }
  // Decimal, as std::to_chars writes it: the digits counted, then written from the last.
  Text& u64(std::uint64_t v) {
    need(20);
    if (v < 10) {
      *p_++ = static_cast<char>('0' + v);
      return *this;
    }
    std::size_t n = 1;
    for (std::uint64_t t = 10; n < 20 && v >= t; t *= 10) ++n;
    char* q = p_ + n;
    while (v >= 100) {
      const auto r = static_cast<std::size_t>(v % 100);
      v /= 100;
      q -= 2;
      std::memcpy(q, kPairs.data() + 2 * r, 2);
    }
    if (v >= 10) {
      q -= 2;
      std::memcpy(q, kPairs.data() + 2 * v, 2);
    } else {
      *--q = static_cast<char>('0' + v);
    }
    p_ += n;
    return *this;
  }
  Text& i64(std::int64_t v) {
    if (v >= 0) return u64(static_cast<std::uint64_t>(v));
    ch('-');
    return u64(0 - static_cast<std::uint64_t>(v));
  }
  // The shortest text that reads back as v (std::to_chars).
  Text& number(double v) {
    need(32);
    p_ = std::to_chars(p_, p_ + 32, v).ptr;
    return *this;
  }
  Text& ints(const std::vector<std::int64_t>& v) {
    ch('[');
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i > 0) ch(',');
      i64(v[i]);
    }
    return ch(']');
  }
  Text& hash(std::uint64_t h) { // kernel::hash_hex, quoted
    constexpr char digits[] = "0123456789abcdef";
    need(18);
    p_[0] = p_[17] = '"';
    for (int i = 16; i >= 1; --i, h >>= 4) p_[i] = digits[h & 0xFU];
    p_ += 18;
    return *this;
  }
  // "timestamp":{"sec":S,"nsec":N}
  Text& timestamp(std::uint64_t t) {
    lit(R"("timestamp":{"sec":)").u64(t / 1000000000U).lit(",\"nsec\":");
    return u64(t % 1000000000U).ch('}');
  }
  // `bytes` in base64 (RFC 4648, padded), quoted: base64 needs no JSON escapes.
  Text& base64(std::string_view bytes) {
    static constexpr char kAlphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    need((bytes.size() + 2) / 3 * 4 + 2);
    char* o = p_;
    *o++ = '"';
    const auto byte = [&](std::size_t k) {
      return static_cast<std::uint32_t>(static_cast<std::uint8_t>(bytes[k]));
    };
    std::size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
      const std::uint32_t v = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
      o[0] = kAlphabet[(v >> 18) & 63U];
      o[1] = kAlphabet[(v >> 12) & 63U];
      o[2] = kAlphabet[(v >> 6) & 63U];
      o[3] = kAlphabet[v & 63U];
      o += 4;
    }
    if (const std::size_t rest = bytes.size() - i; rest > 0) {
      std::uint32_t v = byte(i) << 16;
      if (rest == 2) v |= byte(i + 1) << 8;
      *o++ = kAlphabet[(v >> 18) & 63U];
      *o++ = kAlphabet[(v >> 12) & 63U];
      *o++ = rest == 2 ? kAlphabet[(v >> 6) & 63U] : '=';
      *o++ = '=';
    }
    *o++ = '"';
    p_ = o;
    return *this;
  }

private:
  static constexpr std::size_t kRoom = 256;
  static constexpr std::array<char, 200> kPairs = [] {
    std::array<char, 200> d{};
    for (std::size_t k = 0; k < 100; ++k) {
      d[2 * k] = static_cast<char>('0' + k / 10);
      d[2 * k + 1] = static_cast<char>('0' + k % 10);
    }
    return d;
  }();
  void need(std::size_t n) {
    if (static_cast<std::size_t>(e_ - p_) < n) grow(n);
  }
  void grow(std::size_t n) {
    const auto at = static_cast<std::size_t>(p_ - s_.data());
    s_.resize(at + std::max(n, s_.size() - at) + kRoom);
    p_ = s_.data() + at;
    e_ = s_.data() + s_.size();
  }
  std::string& s_;
  char* p_;
  char* e_;
};

void put_number(std::string& out, double v) {
  Text(out).number(v);
}

std::uint64_t log_time(std::int64_t t_ns) {
  return t_ns < 0 ? 0 : static_cast<std::uint64_t>(t_ns);
}
std::string timestamp(std::uint64_t t) {
  std::string out;
  Text(out).timestamp(t);
  return out;
}

// A pose: the position as integers of 10^-decimals units (nanometres for the serial robots'
// dead reckoning, whole sub-cells for the marker-floor robot), the rotation about z as a
// quaternion's z and w.
struct Pose {
  std::int64_t x = 0, y = 0;
  int decimals = 0;
  double qz = 0, qw = 1;
};
// An integer of 10^-decimals units as a JSON number: its decimal digits, the point set in, the
// fraction's trailing zeros dropped (-0.000340729, 0.5, 12): exact, and no double formatted.
void put_fixed(Text& out, std::int64_t v, int decimals) {
  if (v < 0) out.ch('-');
  const std::uint64_t a = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
  std::uint64_t scale = 1;
  for (int k = 0; k < decimals; ++k) scale *= 10;
  out.u64(a / scale);
  std::uint64_t frac = a % scale;
  if (frac == 0) return;
  int digits = decimals;
  while (frac % 10 == 0) frac /= 10, --digits;
  std::array<char, 20> b{};
  for (int k = digits - 1; k >= 0; --k, frac /= 10)
    b[static_cast<std::size_t>(k)] = static_cast<char>('0' + frac % 10);
  out.ch('.').lit({b.data(), static_cast<std::size_t>(digits)});
}
void put_position(Text& out, const Pose& p) {
  out.lit(R"({"position":{"x":)");
  put_fixed(out, p.x, p.decimals);
  out.lit(",\"y\":");
  put_fixed(out, p.y, p.decimals);
}
Pose pose_of(std::int64_t x, std::int64_t y, int decimals, kernel::Angle heading) {
  // The rotation by `heading` about z: (0, 0, sin h/2, cos h/2), by the kernel's sine; h in
  // (-pi, pi], so that w >= 0 (q and -q are the same rotation; this one is the usual spelling).
  const auto half = kernel::Angle::from_raw(static_cast<std::uint32_t>(heading.signed_raw() / 2));
  constexpr double kOne = 65536.0;
  return {x, y, decimals, kernel::sin(half).raw() / kOne, kernel::cos(half).raw() / kOne};
}
// Q15.16 body diameters in nanometres, to the nearest (ties away from zero): the dead
// reckoning's step is 1/65536 of a diameter (0.8 um for the Khepera's 55 mm), a thousand times
// coarser, so the rounding loses nothing the odometry holds.
std::int64_t nanometres(std::int64_t raw, std::int64_t diameter_um) {
  const kernel::int128 num = kernel::int128(raw) * diameter_um * 1000;
  const kernel::int128 half = 32768;
  return static_cast<std::int64_t>(num >= 0 ? (num + half) / 65536 : -((-num + half) / 65536));
}

// The pose after each step, where the log says it: the serial robots' dead reckoning (metres),
// stc-floor's believed sub-cell and quarter-turn heading.
class Poser {
public:
  explicit Poser(const LogHeader& header) {
    if (const auto kind = body_of(header.robot)) {
      robot_ = &describe(*kind);
      frame_ = "odom";
    } else if (header.robot == "stc-floor") {
      floor_ = true;
      frame_ = "map";
    }
  }
  [[nodiscard]] const std::string& frame() const noexcept { return frame_; }
  std::optional<Pose> after(const LogRecord& r) {
    if (floor_ && r.odo.size() >= 3)
      return pose_of(r.odo[0], r.odo[1], 0,
                     kernel::Angle::from_raw(static_cast<std::uint32_t>((r.odo[2] & 3) << 30)));
    if (robot_ == nullptr || r.odo.size() != 2 || robot_->wheel_base_um <= 0) return std::nullopt;
    const WheelTravel w{r.odo[0], r.odo[1]};
    if (!dr_)
      dr_.emplace(*robot_, w);
    else
      dr_->update(w);
    return pose_of(nanometres(dr_->position().x.raw(), robot_->diameter_um),
                   nanometres(dr_->position().y.raw(), robot_->diameter_um), 9, dr_->heading());
  }
  // Metres per body diameter (the arena's unit), 0 when the robot has none.
  [[nodiscard]] double diameter_m() const noexcept {
    return robot_ != nullptr ? robot_->diameter_um / 1e6 : 0;
  }

private:
  const RobotDescription* robot_ = nullptr;
  bool floor_ = false;
  std::string frame_;
  std::optional<DeadReckoning> dr_;
};

// A pose's JSON ({"position":{x,y,z},"orientation":{x,y,z,w}}), keeping the orientation's text
// while it repeats (a walk's heading holds between turns): fewer numbers formatted.
class PoseText {
public:
  void put(Text& out, const Pose& p) {
    put_position(out, p);
    if (!valid_ || std::bit_cast<std::uint64_t>(p.qz) != std::bit_cast<std::uint64_t>(qz_) ||
        std::bit_cast<std::uint64_t>(p.qw) != std::bit_cast<std::uint64_t>(qw_)) {
      rest_.clear();
      Text(rest_)
          .lit(R"(,"z":0},"orientation":{"x":0,"y":0,"z":)")
          .number(p.qz)
          .lit(",\"w\":")
          .number(p.qw)
          .lit("}}");
      qz_ = p.qz;
      qw_ = p.qw;
      valid_ = true;
    }
    out.lit(rest_);
  }

private:
  bool valid_ = false;
  double qz_ = 0, qw_ = 0;
  std::string rest_;
};

// One step of the log as the export reads it: the record, the pose after it, and what only the
// reading thread can know (the trail so far, whether the replay's divergence is written here).
struct StepIn {
  LogRecord record;
  std::optional<Pose> pose;
  std::string trail;       // the /trail message, when one is due at this step; else empty
  bool divergence = false; // the replay's first divergence is written after this step
};

// The channels of one run (recorded or exported) and the messages of a step, formatted straight
// into a chunk. Shared read-only by the threads that format (write_mcap).
class RunChannels {
public:
  RunChannels(mcap::Writer& w, const std::function<std::uint16_t(std::string_view)>& schema,
              const std::string& prefix, const std::string& frame) {
    // Exported: /pose, /trail, /antkit/step, /antkit/io; a replay's: /recorded/...
    const std::string own = prefix.empty() ? "/antkit" : prefix;
    pose_ = w.add_channel(schema("foxglove.PoseInFrame"), prefix + "/pose", "json");
    trail_ = w.add_channel(schema("foxglove.PosesInFrame"), prefix + "/trail", "json");
    step_ = w.add_channel(schema("antkit.Step"), own + "/step", "json");
    io_ = w.add_channel(schema("antkit.Exchanges"), own + "/io", "json");
    frame_ = ",\"frame_id\":";
    append_json_bytes(frame_, frame);
  }
  // {"timestamp":...,"frame_id":"...","poses":[   (a /trail message's head)
  void put_trail_head(Text& m, std::uint64_t t) const {
    m.ch('{').timestamp(t).lit(frame_).lit(",\"poses\":[");
  }
  void write(mcap::Chunk& c, const StepIn& in, PoseText& pose_text) const {
    const LogRecord& r = in.record;
    const auto t = log_time(r.time_ns);
    const auto seq = static_cast<std::uint32_t>(r.step);
    if (in.pose) {
      {
        Text m(c.begin_message(pose_, seq, t, t));
        m.ch('{').timestamp(t).lit(frame_).lit(",\"pose\":");
        pose_text.put(m, *in.pose);
        m.ch('}');
      }
      c.end_message();
    }
    if (!in.trail.empty()) c.begin_message(trail_, seq, t, t).append(in.trail), c.end_message();
    {
      Text m(c.begin_message(step_, seq, t, t));
      put_step_head(m, r);
      put_step_fields(m, r);
    }
    c.end_message();
    {
      Text m(c.begin_message(io_, seq, t, t));
      put_step_head(m, r);
      m.lit(",\"io\":[");
      for (std::size_t k = 0; k < r.io.size(); ++k) {
        if (k > 0) m.ch(',');
        m.lit("{\"sent\":").base64(r.io[k].sent).lit(",\"received\":").base64(r.io[k].received);
        m.lit(",\"t_ns\":");
        if (r.io[k].t_ns < 0)
          m.lit("null");
        else
          m.i64(r.io[k].t_ns);
        m.ch('}');
      }
      m.lit("]}");
    }
    c.end_message();
  }
  // {"timestamp":...,"step":N
  static void put_step_head(Text& m, const LogRecord& r) {
    m.ch('{').timestamp(log_time(r.time_ns)).lit(",\"step\":").i64(r.step);
  }
  // ,"obs":[...],"cmd":[...],"odo":[...],"state":"..."}
  static void put_step_fields(Text& m, const LogRecord& r) {
    m.lit(",\"obs\":").ints(r.obs).lit(",\"cmd\":").ints(r.cmd).lit(",\"odo\":").ints(r.odo);
    m.lit(",\"state\":").hash(r.state).ch('}');
  }
  static constexpr std::size_t kTrailPoses = 1000;

private:
  std::uint16_t pose_ = 0, trail_ = 0, step_ = 0, io_ = 0;
  std::string frame_; // ,"frame_id":"..."
};

std::string log_message(std::uint64_t t, int level, const std::string& text) {
  std::string m = "{" + timestamp(t) + ",\"level\":" + std::to_string(level) + ",\"message\":";
  append_json_bytes(m, text);
  m += R"(,"name":"antkit","file":"","line":0})";
  return m;
}

std::string arena_message(const std::vector<kernel::FxSegment>& walls, double metres) {
  std::string m = R"({"deletions":[],"entities":[{)" + timestamp(0) +
                  R"(,"frame_id":"arena","id":"arena","lifetime":{"sec":0,"nsec":0},)"
                  R"("frame_locked":true,"metadata":[],"arrows":[],"cubes":[],"spheres":[],)"
                  R"("cylinders":[],"triangles":[],"texts":[],"models":[],"lines":[{"type":2,)"
                  R"("pose":)";
  {
    Text text(m);
    PoseText().put(text, Pose{});
  }
  m += R"(,"thickness":2,"scale_invariant":true,"points":[)";
  const double unit = metres / 65536.0;
  bool first = true;
  for (const auto& s : walls)
    for (const auto& p : {s.a, s.b}) {
      if (!first) m += ',';
      first = false;
      m += "{\"x\":";
      put_number(m, p.x.raw() * unit);
      m += ",\"y\":";
      put_number(m, p.y.raw() * unit);
      m += ",\"z\":0}";
    }
  m += R"(],"color":{"r":0.2,"g":0.2,"b":0.2,"a":1},"colors":[],"indices":[]}]}]})";
  return m;
}

std::string header_text(const LogHeader& h) {
  std::string s = "robot " + h.robot + ", controller " + h.controller;
  for (const auto& [k, v] : h.params) s += ", " + k + "=" + std::to_string(v);
  s += ", seed " + std::to_string(h.seed);
  if (!h.arena.empty()) s += ", arena " + h.arena;
  return s;
}

} // namespace

std::string base64(std::string_view bytes) {
  std::string quoted;
  Text(quoted).base64(bytes);
  return quoted.substr(1, quoted.size() - 2);
}

namespace {

// Steps a chunk: each chunk of the run holds the messages of this many steps, whatever the thread
// count (about 0.8 MiB for a serial robot's steps; the writer's own chunks close at 1 MiB).
constexpr std::size_t kChunkSteps = 1024;

// A chunk's worth of steps, read on the calling thread and formatted on any (write_mcap).
struct Batch {
  // steps[0, n) are this batch's; the rest are buffers kept for reuse. Never resized: the reading
  // thread holds a pointer to the step before.
  std::vector<StepIn> steps = std::vector<StepIn>(kChunkSteps);
  std::size_t n = 0;
  mcap::Chunk chunk;
  bool done = false;
  std::exception_ptr error;
};

// Formats batches on `threads - 1` threads and the caller's, and writes them in the order they
// were submitted, whichever thread finished the next one (one at a time): the file's bytes are the
// same for any thread count, and the reading thread does no writing. The caller fills a batch
// (take), submits it, and at the end waits for all to be written (finish). The first error, in
// formatting or writing, stops the writing and is rethrown to the caller by take or finish; the
// destructor stops and joins the threads (an exception on the caller's side leaves by it).
class BatchPipeline {
public:
  BatchPipeline(unsigned threads, std::function<void(Batch&)> format,
                std::function<void(Batch&)> write)
      : format_(std::move(format)), write_(std::move(write)), depth_(2 * std::size_t{threads} + 2) {
    for (unsigned k = 1; k < threads; ++k) workers_.emplace_back([this] { work(); });
  }
  ~BatchPipeline() {
    {
      const std::lock_guard lock(m_);
      stop_ = true;
    }
    cv_.notify_all();
    for (auto& t : workers_) t.join();
  }
  BatchPipeline(const BatchPipeline&) = delete;
  BatchPipeline& operator=(const BatchPipeline&) = delete;

  // An empty batch: a new one while fewer than the depth exist, else one written, formatting
  // queued batches while it waits.
  Batch& take() {
    std::unique_lock lock(m_);
    if (free_.empty() && all_.size() < depth_) {
      all_.push_back(std::make_unique<Batch>());
      return *all_.back();
    }
    wait(lock, [&] { return !free_.empty(); });
    Batch* b = free_.back();
    free_.pop_back();
    b->n = 0;
    b->done = false;
    b->error = nullptr;
    return *b;
  }
  void submit(Batch& b) {
    {
      const std::lock_guard lock(m_);
      queue_.push_back(&b);
      order_.push_back(&b);
    }
    cv_.notify_one();
  }
  // Returns once every batch submitted is written.
  void finish() {
    std::unique_lock lock(m_);
    wait(lock, [&] { return order_.empty() && !writing_; });
  }

private:
  // Waits, under `lock`, until `ready` or an error; formats queued batches meanwhile.
  template <class Ready>
  void wait(std::unique_lock<std::mutex>& lock, const Ready& ready) {
    for (;;) {
      if (error_) std::rethrow_exception(error_);
      if (ready()) return;
      if (!queue_.empty())
        run_one(lock);
      else
        cv_.wait(lock);
    }
  }
  // Formats the queue's first batch (the lock released meanwhile), then writes what is ready.
  void run_one(std::unique_lock<std::mutex>& lock) {
    Batch* b = queue_.front();
    queue_.pop_front();
    lock.unlock();
    try {
      format_(*b);
    } catch (...) {
      b->error = std::current_exception();
    }
    lock.lock();
    b->done = true;
    write_ready(lock);
    cv_.notify_all();
  }
  // Writes the batches at the front of the order that are formatted, unless another thread is
  // writing (it will find them).
  void write_ready(std::unique_lock<std::mutex>& lock) {
    if (writing_) return;
    writing_ = true;
    while (!error_ && !order_.empty() && order_.front()->done) {
      Batch* b = order_.front();
      order_.pop_front();
      if (b->error) {
        error_ = b->error;
        break;
      }
      lock.unlock();
      try {
        write_(*b);
      } catch (...) {
        lock.lock();
        error_ = std::current_exception();
        break;
      }
      lock.lock();
      free_.push_back(b);
      cv_.notify_all();
    }
    writing_ = false;
  }
  void work() {
    std::unique_lock lock(m_);
    for (;;) {
      cv_.wait(lock, [&] { return stop_ || (!queue_.empty() && !error_); });
      if (stop_) return;
      run_one(lock);
    }
  }

  std::function<void(Batch&)> format_, write_;
  std::size_t depth_;
  std::vector<std::unique_ptr<Batch>> all_; // the caller's only
  // All under m_: free batches; to format; submitted and not yet written, in order.
  std::vector<Batch*> free_;
  std::deque<Batch*> queue_, order_;
  bool writing_ = false, stop_ = false;
  std::exception_ptr error_;
  std::mutex m_;
  std::condition_variable cv_;
  std::vector<std::thread> workers_;
};

// The file, streamed to `bytes` as the log is read, a record ahead (a malformed log throws part
// way; export_mcap writes beside the target and renames, so nothing half-written is left). The
// calling thread reads the log, follows the pose and keeps the trail; batches of kChunkSteps
// steps are formatted into chunks on options.threads threads and written in order by the thread
// that finishes the next one (BatchPipeline).
void write_mcap(std::ostream& bytes, LogReader& reader, const std::string& log_name,
                const McapOptions& options, const ReplayResult* replay, McapSummary* summary) {
  const LogHeader& header = reader.header();
  Poser poser(header);
  std::vector<kernel::FxSegment> walls;
  if (!header.arena.empty() && options.arena_walls && poser.diameter_m() > 0) try {
      walls = options.arena_walls(header.arena);
    } catch (const kernel::InputError& e) {
      throw kernel::InputError(log_name, 1, 1,
                               "the header's arena '" + header.arena + "': " + e.message());
    }

  mcap::Writer w(bytes);
  // Schemas first, one per name, in a fixed order.
  std::vector<std::pair<std::string, std::uint16_t>> schema_ids;
  for (const char* name :
       {"foxglove.PoseInFrame", "foxglove.PosesInFrame", "antkit.Step", "antkit.Exchanges",
        "foxglove.Log", "foxglove.SceneUpdate", "antkit.ReplayedStep"}) {
    if (std::string_view(name) == "antkit.ReplayedStep" && replay == nullptr) continue;
    if (std::string_view(name) == "foxglove.SceneUpdate" && walls.empty()) continue;
    schema_ids.emplace_back(name, w.add_schema(name, "jsonschema", mcap_schema(name)));
  }
  const auto id_of = [&](std::string_view name) -> std::uint16_t {
    for (const auto& [known, id] : schema_ids)
      if (known == name) return id;
    return 0;
  };
  const RunChannels run(w, id_of, replay != nullptr ? "/recorded" : "", poser.frame());
  const std::uint16_t log = w.add_channel(id_of("foxglove.Log"), "/log", "json");
  const std::uint16_t arena =
      walls.empty() ? 0 : w.add_channel(id_of("foxglove.SceneUpdate"), "/arena", "json");
  const std::uint16_t replayed =
      replay == nullptr ? 0 : w.add_channel(id_of("antkit.ReplayedStep"), "/replayed/step", "json");

  w.write({log, 0, 0, 0, log_message(0, 2, header_text(header))});
  if (arena != 0) w.write({arena, 0, 0, 0, arena_message(walls, poser.diameter_m())});

  const std::optional<Divergence> divergence =
      replay != nullptr ? replay->first_divergence : std::nullopt;
  const auto add_divergence = [&](mcap::Chunk& c, std::uint64_t t, std::uint32_t seq) {
    const Divergence& d = *divergence;
    std::string m = "{" + timestamp(t) + ",\"step\":" + std::to_string(d.step) +
                    R"(,"identical":false,"divergence":{"field":)";
    append_json_bytes(m, d.field);
    m += ",\"recorded\":";
    append_json_bytes(m, d.expected);
    m += ",\"replayed\":";
    append_json_bytes(m, d.actual);
    m += "}}";
    c.add({replayed, seq, t, t, std::move(m)});
    c.add({log, seq, t, t,
           log_message(t, 4,
                       "step " + std::to_string(d.step) + ": " + d.field + ": the log holds " +
                           d.expected + ", the replay derived " + d.actual)});
  };

  // A batch's messages, on whichever thread takes it.
  const auto format = [&](Batch& b) {
    PoseText pose_text;
    for (std::size_t i = 0; i < b.n; ++i) {
      const StepIn& in = b.steps[i];
      run.write(b.chunk, in, pose_text);
      const LogRecord& r = in.record;
      const auto t = log_time(r.time_ns);
      const auto seq = static_cast<std::uint32_t>(r.step);
      if (replay != nullptr && r.step < replay->steps) {
        // /antkit/step's text with "identical" after the step number.
        {
          Text m(b.chunk.begin_message(replayed, seq, t, t));
          RunChannels::put_step_head(m, r);
          m.lit(",\"identical\":true");
          RunChannels::put_step_fields(m, r);
        }
        b.chunk.end_message();
      } else if (in.divergence) {
        add_divergence(b.chunk, t, seq);
      }
    }
    b.chunk.seal();
  };
  const unsigned threads =
      options.threads != 0 ? options.threads : std::max(1U, std::thread::hardware_concurrency());
  BatchPipeline pipeline(threads, format, [&](Batch& b) { w.write_chunk(b.chunk); });

  // The trail: every stride-th pose (at most kTrailPoses over the run, the first among them),
  // each formatted once, as a growing list; a /trail message every 1 % of the steps and at the
  // last gives the list so far and the step's pose.
  const std::size_t ahead_count = reader.records_ahead();
  const std::size_t every = std::max<std::size_t>(1, (ahead_count + 99) / 100);
  const std::size_t stride = std::max<std::size_t>(1, (ahead_count + RunChannels::kTrailPoses - 1) /
                                                          RunChannels::kTrailPoses);
  std::string trail_poses; // the poses kept, comma-separated
  PoseText trail_text;
  std::size_t pose_count = 0;

  bool divergence_written = false;
  std::size_t n = 0;        // steps read
  std::uint64_t last_t = 0; // the last step's time
  Batch* cur = &pipeline.take();
  Batch* full = nullptr; // a full batch, submitted once its last step knows whether it is the last
  StepIn* prev = nullptr;
  for (;;) {
    if (cur->n == kChunkSteps) {
      full = cur;
      cur = &pipeline.take();
    }
    StepIn& s = cur->steps[cur->n];
    const bool got = reader.next(s.record);
    if (prev != nullptr) { // the step before: its trail, now that it is known whether it is last
      prev->trail.clear();
      if (prev->pose && (n % every == 0 || !got)) {
        Text m(prev->trail);
        run.put_trail_head(m, log_time(prev->record.time_ns));
        m.lit(trail_poses);
        if ((pose_count - 1) % stride != 0) {
          if (!trail_poses.empty()) m.ch(',');
          trail_text.put(m, *prev->pose);
        }
        m.lit("]}");
      }
    }
    if (full != nullptr) {
      pipeline.submit(*full);
      full = nullptr;
    }
    if (!got) break;
    const LogRecord& r = s.record;
    s.pose = poser.after(r);
    if (s.pose) {
      if (pose_count % stride == 0) {
        Text m(trail_poses);
        if (pose_count > 0) m.ch(',');
        trail_text.put(m, *s.pose);
      }
      ++pose_count;
    }
    s.divergence = false;
    if (replay != nullptr && !(r.step < replay->steps) && divergence &&
        divergence->step == r.step && !divergence_written) {
      s.divergence = true;
      divergence_written = true;
    }
    last_t = log_time(r.time_ns);
    ++n;
    prev = &s;
    ++cur->n;
  }
  if (cur->n > 0) pipeline.submit(*cur);
  pipeline.finish();

  const auto& stop = reader.stop();
  const auto last_seq =
      static_cast<std::uint32_t>(stop ? stop->step : static_cast<std::int64_t>(n));
  mcap::Chunk tail;
  if (divergence && !divergence_written) add_divergence(tail, last_t, last_seq);
  if (stop)
    tail.add({log, last_seq, last_t, last_t,
              log_message(last_t, stop->reason == "done" ? 2 : 3, "stop: " + stop->reason)});
  else
    tail.add({log, last_seq, last_t, last_t,
              log_message(last_t, 3,
                          reader.truncated() ? "the log's last line is cut short"
                                             : "the log has no stop record")});
  if (replay != nullptr && replay->identical)
    tail.add({log, last_seq, last_t, last_t,
              log_message(last_t, 2,
                          "replay identical: " + std::to_string(replay->steps) + " steps, hash " +
                              kernel::hash_hex(replay->hash))});
  w.write_chunk(tail);
  w.finish();
  if (summary != nullptr) {
    summary->bytes = w.bytes();
    summary->messages = w.messages();
    summary->channels = w.channel_counts();
  }
}

} // namespace

std::string mcap_of_log(LogReader& reader, const std::string& log_name, const McapOptions& options,
                        const ReplayResult* replay, McapSummary* summary) {
  std::ostringstream bytes;
  write_mcap(bytes, reader, log_name, options, replay, summary);
  return std::move(bytes).str();
}

McapSummary export_mcap(const std::string& log, const std::string& out,
                        const McapOptions& options) {
  LogReader reader(log);
  McapSummary s;
  io::write_file_atomic(out,
                        [&](std::ostream& o) { write_mcap(o, reader, log, options, nullptr, &s); });
  return s;
}

McapSummary export_replay_mcap(const std::string& log, const ReplayResult& result,
                               const std::string& out, const McapOptions& options) {
  LogReader reader(log);
  McapSummary s;
  io::write_file_atomic(out,
                        [&](std::ostream& o) { write_mcap(o, reader, log, options, &result, &s); });
  return s;
}

} // namespace antkit::devices
