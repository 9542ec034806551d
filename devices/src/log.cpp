// Hardware logs: the JSON Lines writer and a strict, allocation-free (in the steady state) reader
// (log.hpp). The reader's lexer is its own, for replay's speed, and is held to nlohmann-json by a
// property test and the fuzz target (tests/support/log_json_oracle.hpp says why and how).
#include <antkit/devices/log.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <bit>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace antkit::devices {

void append_json_bytes(std::string& out, std::string_view bytes) {
  constexpr char hex[] = "0123456789abcdef";
  out += '"';
  for (const char ch : bytes) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c >= 0x20 && c < 0x7F) {
      out += ch;
    } else {
      out += "\\u00";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  out += '"';
}

using namespace std::literals;

namespace {

using kernel::InputError;

// ---- writing ----

void put_int(std::string& out, std::int64_t v) {
  char buf[24];
  const int n = std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v));
  out.append(buf, static_cast<std::size_t>(n));
}

void put_ints(std::string& out, const std::vector<std::int64_t>& v) {
  out += '[';
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) out += ',';
    put_int(out, v[i]);
  }
  out += ']';
}

void put_io(std::string& out, const std::vector<Exchange>& io) {
  out += '[';
  for (std::size_t i = 0; i < io.size(); ++i) {
    if (i) out += ',';
    out += '[';
    append_json_bytes(out, io[i].sent);
    out += ',';
    append_json_bytes(out, io[i].received);
    if (io[i].t_ns >= 0) {
      out += ',';
      put_int(out, io[i].t_ns);
    }
    out += ']';
  }
  out += ']';
}

// ---- reading ----

enum Key : unsigned {
  kStep = 1u << 0,
  kTime = 1u << 1,
  kIo = 1u << 2,
  kObs = 1u << 3,
  kCmd = 1u << 4,
  kOdo = 1u << 5,
  kState = 1u << 6,
  kStop = 1u << 7,
};

// The byte a one-letter JSON escape stands for (\" \\ \/ \b \f \n \r \t), or -1; and a hex digit's
// value (either case), or -1. Both readers below use them.
int simple_escape(char c) noexcept {
  switch (c) {
  case '"':
  case '\\':
  case '/':
    return c;
  case 'b':
    return '\b';
  case 'f':
    return '\f';
  case 'n':
    return '\n';
  case 'r':
    return '\r';
  case 't':
    return '\t';
  default:
    return -1;
  }
}
int hex_digit(char h) noexcept {
  return h >= '0' && h <= '9'   ? h - '0'
         : h >= 'a' && h <= 'f' ? h - 'a' + 10
         : h >= 'A' && h <= 'F' ? h - 'A' + 10
                                : -1;
}

class Cursor {
public:
  Cursor(const std::string& name, std::size_t line, const char* begin, const char* end)
      : name_(name), line_(line), b_(begin), p_(begin), e_(end) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(name_, line_, static_cast<std::size_t>(p_ - b_) + 1, what);
  }
  void ws() {
    while (p_ < e_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r')) ++p_;
  }
  bool at(char c) {
    ws();
    return p_ < e_ && *p_ == c;
  }
  void expect(char c, const char* what) {
    ws();
    if (p_ >= e_ || *p_ != c) fail(std::string("expected ") + what);
    ++p_;
  }
  [[nodiscard]] bool done() {
    ws();
    return p_ == e_;
  }

  // A JSON string into bytes (one byte per character, \u00XX at most).
  void string(std::string& out) {
    ws();
    if (p_ >= e_ || *p_ != '"') fail("expected a string");
    ++p_;
    out.clear();
    for (;;) {
      if (p_ >= e_) fail("unterminated string");
      const char c = *p_;
      if (c == '"') {
        ++p_;
        return;
      }
      if (static_cast<unsigned char>(c) < 0x20) fail("a control byte inside a string (escape it)");
      if (static_cast<unsigned char>(c) >= 0x80)
        fail("a non-ASCII byte inside a string (escape it as \\u00XX)");
      if (c != '\\') {
        // A run of plain characters in one append.
        const char* q = p_ + 1;
        while (q < e_ && *q != '"' && *q != '\\' && static_cast<unsigned char>(*q) >= 0x20 &&
               static_cast<unsigned char>(*q) < 0x80)
          ++q;
        out.append(p_, static_cast<std::size_t>(q - p_));
        p_ = q;
        continue;
      }
      if (++p_ >= e_) fail("unterminated escape");
      if (const int byte = simple_escape(*p_); byte >= 0) {
        out += static_cast<char>(byte);
      } else if (*p_ == 'u') {
        unsigned v = 0;
        for (int k = 0; k < 4; ++k) {
          if (++p_ >= e_) fail("a \\u escape needs four hex digits");
          const int d = hex_digit(*p_);
          if (d < 0) fail("a \\u escape needs four hex digits");
          v = v * 16 + static_cast<unsigned>(d);
        }
        if (v > 0xFF) fail("\\u escape above \\u00ff: not a byte");
        out += static_cast<char>(v);
      } else {
        fail("unknown escape");
      }
      ++p_;
    }
  }

  std::int64_t integer() {
    ws();
    const char* start = p_;
    bool negative = false;
    if (p_ < e_ && *p_ == '-') negative = true, ++p_;
    if (p_ >= e_ || *p_ < '0' || *p_ > '9') fail("expected an integer");
    if (*p_ == '0' && p_ + 1 < e_ && p_[1] >= '0' && p_[1] <= '9') fail("a leading zero");
    unsigned long long v = 0;
    const unsigned long long limit = negative ? 9223372036854775808ULL : 9223372036854775807ULL;
    while (p_ < e_ && *p_ >= '0' && *p_ <= '9') {
      const unsigned d = static_cast<unsigned>(*p_ - '0');
      if (v > (limit - d) / 10) {
        p_ = start;
        fail("integer out of the 64-bit range");
      }
      v = v * 10 + d;
      ++p_;
    }
    if (p_ < e_ && (*p_ == '.' || *p_ == 'e' || *p_ == 'E')) fail("only integers are allowed here");
    return negative ? static_cast<std::int64_t>(0 - v) : static_cast<std::int64_t>(v);
  }

  void ints(std::vector<std::int64_t>& out) {
    out.clear();
    expect('[', "'['");
    if (at(']')) {
      ++p_;
      return;
    }
    for (;;) {
      out.push_back(integer());
      if (at(',')) {
        ++p_;
        continue;
      }
      expect(']', "',' or ']'");
      return;
    }
  }

  void io(std::vector<Exchange>& out) {
    std::size_t n = 0;
    expect('[', "'['");
    if (at(']')) {
      ++p_;
      out.clear();
      return;
    }
    for (;;) {
      if (n == out.size()) out.emplace_back();
      expect('[', "an exchange [sent, received]");
      string(out[n].sent);
      expect(',', "','");
      string(out[n].received);
      out[n].t_ns = -1;
      if (at(',')) { // the send's time (older logs have none)
        ++p_;
        out[n].t_ns = integer();
        if (out[n].t_ns < 0) fail("an exchange's time is a count of nanoseconds >= 0");
      }
      expect(']', "']' after an exchange's two strings and its time");
      ++n;
      if (at(',')) {
        ++p_;
        continue;
      }
      expect(']', "',' or ']'");
      break;
    }
    out.resize(n);
  }

  std::uint64_t hex16() {
    ws();
    const char* start = p_;
    if (p_ >= e_ || *p_ != '"') fail("expected the state hash as a string of 16 hex digits");
    ++p_;
    std::uint64_t v = 0;
    for (int k = 0; k < 16; ++k, ++p_) {
      const char h = p_ < e_ ? *p_ : '\0';
      const int d = h >= '0' && h <= '9' ? h - '0' : h >= 'a' && h <= 'f' ? h - 'a' + 10 : -1;
      if (d < 0) {
        p_ = start;
        fail("the state hash must be 16 lower-case hex digits");
      }
      v = v * 16 + static_cast<std::uint64_t>(d);
    }
    if (p_ >= e_ || *p_ != '"') {
      p_ = start;
      fail("the state hash must be 16 lower-case hex digits");
    }
    ++p_;
    return v;
  }

  // Skips any JSON value (for a header's unknown keys, reported after the schema check).
  void skip_value(int depth = 0) {
    if (depth > 64) fail("nested too deeply");
    ws();
    if (p_ >= e_) fail("expected a value");
    if (*p_ == '"') {
      std::string s;
      string(s);
    } else if (*p_ == '{' || *p_ == '[') {
      const char close = *p_ == '{' ? '}' : ']';
      const bool object = *p_ == '{';
      ++p_;
      if (at(close)) {
        ++p_;
        return;
      }
      for (;;) {
        if (object) {
          std::string k;
          string(k);
          expect(':', "':'");
        }
        skip_value(depth + 1);
        if (at(',')) {
          ++p_;
          continue;
        }
        expect(close, object ? "',' or '}'" : "',' or ']'");
        return;
      }
    } else if (e_ - p_ >= 4 &&
               (std::strncmp(p_, "true", 4) == 0 || std::strncmp(p_, "null", 4) == 0)) {
      p_ += 4;
    } else if (e_ - p_ >= 5 && std::strncmp(p_, "false", 5) == 0) {
      p_ += 5;
    } else {
      integer();
    }
  }

  // Calls on_key(key) for each key of an object; on_key parses the value. Duplicate keys are
  // caught by the callers' seen-bits.
  template <class F>
  void object(std::string& key, F&& on_key) {
    expect('{', "'{'");
    if (at('}')) {
      ++p_;
      return;
    }
    for (;;) {
      string(key);
      expect(':', "':'");
      on_key(key);
      if (at(',')) {
        ++p_;
        continue;
      }
      expect('}', "',' or '}'");
      return;
    }
  }

  const char* pos() const noexcept { return p_; }
  void set(const char* p) noexcept { p_ = p; }

private:
  const std::string& name_;
  std::size_t line_;
  const char* b_;
  const char* p_;
  const char* e_;
};

// ---- the fast path: a step record exactly as format_record writes it ----
//
// Nearly every line a replay reads is one the writer wrote, so that form is read first by a
// reader that knows it: the keys in the writer's order, no whitespace, each token checked against
// the bytes it must be. At the first byte that is not of that form it gives up, having decided
// nothing, and the general reader (Cursor, above) reads the line from its start and is the judge
// of what it means or of what is wrong with it (its errors and columns are the only ones a user
// sees). So it accepts a subset of what the general reader accepts, to the same record: integers
// of at most 18 digits (no overflow to check), the escapes the general reader reads, \u00XX only.
// tests/devices/test_log.cpp holds the lines it accepts to nlohmann-json, edited lines among them.
class Canonical {
public:
  Canonical(const char* begin, const char* end) noexcept : p_(begin), e_(end) {}

  bool record(LogRecord& out, std::int64_t& step) { return record_prefix(out, step) == e_; }
  // The record at the start of the bytes: where it ends (the caller checks what follows), or null.
  const char* record_prefix(LogRecord& out, std::int64_t& step) {
    std::int64_t time_ns = 0;
    if (!lit("{\"step\":") || !integer(step) || !lit(",\"t_ns\":") || !integer(time_ns) ||
        !lit(",\"io\":[") || !io(out.io) || !lit(",\"obs\":") || !ints(out.obs) ||
        !lit(",\"cmd\":") || !ints(out.cmd) || !lit(",\"odo\":") || !ints(out.odo) ||
        !lit(",\"state\":\"") || !hex16(out.state) || !lit("\"}"))
      return nullptr;
    out.time_ns = time_ns;
    return p_;
  }

private:
  template <std::size_t N>
  bool lit(const char (&s)[N]) noexcept {
    constexpr std::size_t n = N - 1;
    if (static_cast<std::size_t>(e_ - p_) < n || std::memcmp(p_, s, n) != 0) return false;
    p_ += n;
    return true;
  }
  bool at(char c) const noexcept { return p_ < e_ && *p_ == c; }

  static int digit(char c) noexcept {
    const auto d = static_cast<unsigned>(static_cast<unsigned char>(c) - '0');
    return d < 10 ? static_cast<int>(d) : -1;
  }

  bool integer(std::int64_t& v) noexcept {
    const char* q = p_;
    const bool negative = q < e_ && *q == '-';
    if (negative) ++q;
    const char* first = q;
    std::uint64_t x = 0;
    for (int d; q < e_ && (d = digit(*q)) >= 0; ++q) x = x * 10 + static_cast<unsigned>(d);
    const auto n = q - first;
    if (n == 0 || n > 18 || (n > 1 && *first == '0')) return false;
    v = negative ? -static_cast<std::int64_t>(x) : static_cast<std::int64_t>(x);
    p_ = q;
    return true; // the caller's next literal rejects a fraction or an exponent
  }

  bool ints(std::vector<std::int64_t>& out) noexcept {
    out.clear();
    if (!lit("[")) return false;
    if (at(']')) return ++p_, true;
    for (;;) {
      std::int64_t v = 0;
      if (!integer(v)) return false;
      out.push_back(v);
      if (at(',')) {
        ++p_;
        continue;
      }
      return lit("]");
    }
  }

  // Decoded byte by byte into a buffer on the stack, copied out once (a step record's strings are
  // a few dozen bytes, an escape every few: appending run by run and escape by escape was a fifth
  // of this reader's time). On false `out` holds a part, as before: the general reader rereads.
  bool string(std::string& out) {
    if (!lit("\"")) return false;
    out.clear();
    char buf[128];
    std::size_t n = 0;
    for (;;) {
      if (n == sizeof buf) {
        out.append(buf, n);
        n = 0;
      }
      if (p_ == e_) return false;
      const auto c = static_cast<unsigned char>(*p_);
      if (c >= 0x20 && c < 0x80 && c != '"' && c != '\\') {
        buf[n++] = static_cast<char>(c);
        ++p_;
        continue;
      }
      if (c == '"') {
        out.append(buf, n);
        return ++p_, true;
      }
      if (c != '\\' || e_ - p_ < 2) return false;
      if (const int x = simple_escape(p_[1]); x >= 0) {
        buf[n++] = static_cast<char>(x);
        p_ += 2;
        continue;
      }
      if (p_[1] != 'u' || e_ - p_ < 6 || p_[2] != '0' || p_[3] != '0') return false;
      const int hi = hex_digit(p_[4]), lo = hex_digit(p_[5]);
      if (hi < 0 || lo < 0) return false;
      buf[n++] = static_cast<char>(hi * 16 + lo);
      p_ += 6;
    }
  }

  // After "io":[ up to and with its ']'.
  bool io(std::vector<Exchange>& out) {
    std::size_t n = 0;
    if (!at(']')) {
      for (;;) {
        if (n == out.size()) out.emplace_back();
        Exchange& x = out[n];
        if (!lit("[") || !string(x.sent) || !lit(",") || !string(x.received)) return false;
        x.t_ns = -1;
        if (at(',')) {
          ++p_;
          if (!integer(x.t_ns) || x.t_ns < 0) return false;
        }
        if (!lit("]")) return false;
        ++n;
        if (!at(',')) break;
        ++p_;
      }
    }
    out.resize(n);
    return lit("]");
  }

  // 16 lower-case hex digits, eight at a time: the lanes checked and converted side by side (the
  // state hash was half of this reader's own time, digit after digit).
  bool hex16(std::uint64_t& v) noexcept {
    if (e_ - p_ < 16) return false;
    std::uint64_t hi = 0, lo = 0;
    std::memcpy(&hi, p_, 8);
    std::memcpy(&lo, p_ + 8, 8);
    if (!hex8_ok(hi) || !hex8_ok(lo)) return false;
    v = hex8(hi) << 32 | hex8(lo);
    p_ += 16;
    return true;
  }
  static constexpr std::uint64_t kOnes = 0x0101010101010101ULL;
  static constexpr std::uint64_t kHigh = 0x8080808080808080ULL;
  // Every byte of x in '0'..'9' or 'a'..'f'. Bytes below 0x80 plus (0x80 - c) stay within their
  // byte, and carry into its high bit exactly when the byte is >= c.
  static bool hex8_ok(std::uint64_t x) noexcept {
    if ((x & kHigh) != 0) return false;
    const auto at_least = [x](std::uint64_t c) { return (x + kOnes * (0x80 - c)) & kHigh; };
    const std::uint64_t digit = at_least('0') & ~at_least('9' + 1);
    const std::uint64_t letter = at_least('a') & ~at_least('f' + 1);
    return (digit | letter) == kHigh;
  }
  // Eight checked hex digits (the first the most significant) as a 32-bit value.
  static std::uint64_t hex8(std::uint64_t x) noexcept {
    if constexpr (std::endian::native == std::endian::little) x = __builtin_bswap64(x);
    // Now the last digit is the lowest byte. '0'..'9' -> 0..9, 'a'..'f' -> 1..6 + 9.
    x = (x & kOnes * 0x0F) + 9 * ((x >> 6) & kOnes);
    x = (x | (x >> 4)) & 0x00FF00FF00FF00FFULL;
    x = (x | (x >> 8)) & 0x0000FFFF0000FFFFULL;
    return (x | (x >> 16)) & 0x00000000FFFFFFFFULL;
  }

  const char* p_;
  const char* e_;
};

void once(Cursor& c, unsigned& seen, unsigned bit, const std::string& key) {
  if (seen & bit) c.fail("key \"" + key + "\" given twice");
  seen |= bit;
}

} // namespace

namespace detail {
bool read_canonical_step(std::string_view line, LogRecord& out) {
  std::int64_t step = 0;
  if (!Canonical(line.data(), line.data() + line.size()).record(out, step)) return false;
  out.step = step;
  return true;
}
} // namespace detail

std::string format_header(const LogHeader& h) {
  std::string out = "{\"schema\":";
  put_int(out, h.schema);
  out += ",\"antkit\":";
  append_json_bytes(out, h.antkit_version);
  out += ",\"robot\":";
  append_json_bytes(out, h.robot);
  out += ",\"port\":{\"path\":";
  append_json_bytes(out, h.port);
  out += ",\"baud\":";
  put_int(out, h.baud);
  out += ",\"framing\":";
  append_json_bytes(out, h.framing);
  out += "},\"controller\":{\"name\":";
  append_json_bytes(out, h.controller);
  out += ",\"params\":{";
  for (std::size_t i = 0; i < h.params.size(); ++i) {
    if (i) out += ',';
    append_json_bytes(out, h.params[i].first);
    out += ':';
    put_int(out, h.params[i].second);
  }
  out += "}},\"seed\":";
  put_int(out, static_cast<std::int64_t>(h.seed));
  if (!h.arena.empty()) {
    out += ",\"arena\":";
    append_json_bytes(out, h.arena);
  }
  out += '}';
  return out;
}

std::string format_record(const LogRecord& r) {
  std::string out = "{\"step\":";
  put_int(out, r.step);
  out += ",\"t_ns\":";
  put_int(out, r.time_ns);
  out += ",\"io\":";
  put_io(out, r.io);
  out += ",\"obs\":";
  put_ints(out, r.obs);
  out += ",\"cmd\":";
  put_ints(out, r.cmd);
  out += ",\"odo\":";
  put_ints(out, r.odo);
  out += ",\"state\":\"" + kernel::hash_hex(r.state) + "\"}";
  return out;
}

std::string format_stop(const LogStop& s) {
  std::string out = "{\"stop\":";
  append_json_bytes(out, s.reason);
  out += ",\"step\":";
  put_int(out, s.step);
  out += ",\"io\":";
  put_io(out, s.io);
  out += '}';
  return out;
}

namespace {
constexpr const char* kLogExists = "the log exists: give another --out, or --force to replace it";
} // namespace

void check_new_log(const std::string& path, bool replace) {
  struct stat st {};
  if (!replace && ::stat(path.c_str(), &st) == 0) throw InputError(path, kLogExists);
}

LogWriter::LogWriter(const std::string& path, const LogHeader& header, std::uint32_t sync_every,
                     bool replace)
    : path_(path), sync_every_(sync_every) {
  file_ = std::fopen(path.c_str(), replace ? "wb" : "wbx"); // x: O_EXCL (C11, glibc)
  if (file_ == nullptr && errno == EEXIST) throw InputError(path, kLogExists);
  if (file_ == nullptr)
    throw InputError(path, std::string("cannot create the log: ") + std::strerror(errno));
  try {
    put(format_header(header));
  } catch (const LogWriteError&) {
    const int err = errno;
    std::fclose(file_);
    file_ = nullptr;
    ::unlink(path.c_str()); // nothing of the run is in it
    throw InputError(path, std::string("cannot write the log: ") + std::strerror(err));
  }
}

LogWriter::~LogWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

void LogWriter::put(const std::string& line) {
  if (file_ == nullptr) throw std::logic_error("log " + path_ + " already finished");
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() ||
      std::fputc('\n', file_) == EOF || std::fflush(file_) != 0)
    throw LogWriteError("writing the log " + path_ + ": " + std::strerror(errno));
}

void LogWriter::write(const LogRecord& r) {
  put(format_record(r));
  ++records_;
  if (sync_every_ != 0 && records_ % sync_every_ == 0) ::fdatasync(::fileno(file_));
}

void LogWriter::finish(const LogStop& s) {
  put(format_stop(s));
  // Only the errors that lose data count (a pipe or a tty cannot be synced: EINVAL).
  const bool synced =
      ::fdatasync(::fileno(file_)) == 0 || (errno != EIO && errno != ENOSPC && errno != EDQUOT);
  const int err = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!synced || !closed)
    throw LogWriteError("writing the log " + path_ + ": " + std::strerror(synced ? errno : err));
}

LogReader::LogReader(const std::string& path) : name_(path) {
  // The whole log in memory: mapped read-only when it is a regular file (a day of a robot at 10
  // steps a second is about 200 MB; copying it was a quarter of a replay's time), else read in
  // large blocks.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(path, std::string("cannot read the log: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    void* m = ::mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ,
                     MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (m != MAP_FAILED) {
      map_ = m;
      map_size_ = static_cast<std::size_t>(st.st_size);
      ::madvise(map_, map_size_, MADV_SEQUENTIAL);
    }
  }
  if (map_ == nullptr) {
    std::vector<char> block(1 << 16);
    for (;;) {
      const ssize_t n = ::read(fd, block.data(), block.size());
      if (n > 0) {
        owned_.append(block.data(), static_cast<std::size_t>(n));
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        const int err = errno;
        ::close(fd);
        throw InputError(path, std::string("cannot read the log: ") + std::strerror(err));
      }
      break;
    }
  }
  ::close(fd);
  data_ = map_ != nullptr ? std::string_view(static_cast<const char*>(map_), map_size_)
                          : std::string_view(owned_);
  try {
    read_header();
  } catch (...) {
    if (map_ != nullptr) ::munmap(map_, map_size_);
    map_ = nullptr;
    throw;
  }
}

LogReader::LogReader(std::string name, std::string contents)
    : name_(std::move(name)), owned_(std::move(contents)), data_(owned_) {
  read_header();
}

LogReader::~LogReader() {
  if (map_ != nullptr) ::munmap(map_, map_size_);
}

void LogReader::read_header() {
  if (data_.empty()) throw InputError(name_, 1, 1, "an empty log: expected a header line");
  const auto nl = data_.find('\n');
  const std::size_t end = nl == std::string::npos ? data_.size() : nl;
  line_ = 1;
  Cursor c(name_, 1, data_.data(), data_.data() + end);
  std::string key, text;
  unsigned seen = 0;
  bool have_schema = false;
  const char* unknown_at = nullptr;
  std::string unknown;
  c.object(key, [&](const std::string& k) {
    if (k == "schema") {
      once(c, seen, 1, k);
      const auto v = c.integer();
      if (v < 0 || v > 0xFFFFFFFF) c.fail("the schema version must be a small whole number");
      header_.schema = static_cast<std::uint32_t>(v);
      have_schema = true;
    } else if (k == "antkit") {
      once(c, seen, 2, k);
      c.string(header_.antkit_version);
    } else if (k == "robot") {
      once(c, seen, 4, k);
      c.string(header_.robot);
    } else if (k == "port") {
      once(c, seen, 8, k);
      unsigned inner = 0;
      std::string k2;
      c.object(k2, [&](const std::string& pk) {
        if (pk == "path")
          once(c, inner, 1, pk), c.string(header_.port);
        else if (pk == "baud") {
          once(c, inner, 2, pk);
          const auto v = c.integer();
          if (v < 0 || v > 100000000) c.fail("baud out of range");
          header_.baud = static_cast<std::uint32_t>(v);
        } else if (pk == "framing")
          once(c, inner, 4, pk), c.string(header_.framing);
        else
          c.fail("unknown key \"" + pk + "\" in \"port\": expected path, baud, framing");
      });
      if (inner != 7) c.fail("\"port\" needs path, baud and framing");
    } else if (k == "controller") {
      once(c, seen, 16, k);
      unsigned inner = 0;
      std::string k2;
      c.object(k2, [&](const std::string& ck) {
        if (ck == "name")
          once(c, inner, 1, ck), c.string(header_.controller);
        else if (ck == "params") {
          once(c, inner, 2, ck);
          header_.params.clear();
          std::string k3;
          c.object(k3, [&](const std::string& name) {
            for (const auto& p : header_.params)
              if (p.first == name) c.fail("parameter \"" + name + "\" given twice");
            header_.params.emplace_back(name, c.integer());
          });
        } else
          c.fail("unknown key \"" + ck + "\" in \"controller\": expected name, params");
      });
      if (inner != 3) c.fail("\"controller\" needs name and params");
    } else if (k == "seed") {
      once(c, seen, 32, k);
      const auto v = c.integer();
      if (v < 0) c.fail("the seed must be >= 0");
      header_.seed = static_cast<std::uint64_t>(v);
    } else if (k == "arena") {
      once(c, seen, 64, k);
      c.string(header_.arena);
      if (header_.arena.empty()) c.fail("\"arena\" is written only when known: expected a spec");
    } else {
      if (unknown_at == nullptr) unknown_at = c.pos(), unknown = k;
      c.skip_value();
    }
  });
  if (!c.done()) c.fail("unexpected bytes after the header object");
  if (have_schema && !can_replay_schema(header_.schema)) {
    c.set(data_.data());
    c.fail("schema version " + std::to_string(header_.schema) + "; this antkit reads schemas " +
           std::to_string(kOldestLogSchema) + " to " + std::to_string(kLogSchemaVersion));
  }
  if (unknown_at != nullptr) {
    c.set(unknown_at);
    c.fail("unknown key \"" + unknown + "\" in the header");
  }
  if ((seen & 63) != 63)
    c.fail("the header needs schema, antkit, robot, port, controller and seed");
  pos_ = nl == std::string::npos ? data_.size() : nl + 1;
}

std::size_t LogReader::records_ahead() const noexcept {
  std::size_t lines = 0;
  std::string_view last;
  bool last_cut = false;
  for (std::size_t at = pos_; at < data_.size();) {
    const auto nl = data_.find('\n', at);
    const std::size_t end = nl == std::string_view::npos ? data_.size() : nl;
    const std::string_view line = data_.substr(at, end - at);
    if (line.find_first_not_of(" \t\r") != std::string_view::npos) {
      ++lines;
      last = line;
      last_cut = nl == std::string_view::npos;
    }
    at = end + 1;
  }
  if (lines == 0) return 0;
  const auto close = last.find_last_not_of(" \t\r");
  const bool cut = last_cut && last[close] != '}';
  const bool stop = last.find("\"stop\":") != std::string_view::npos;
  return lines - (cut || stop ? 1 : 0);
}

bool LogReader::next(LogRecord& out) {
  // The fast path first, over the rest of the log: a record it reads whole ends at a newline or
  // at the log's end, and holds no newline before (it accepts none, raw, anywhere), so that is its
  // line; the scan for the newline (an eighth of this reader's time) is spared.
  if (pos_ < data_.size() && !stop_) {
    const char* const first = data_.data() + pos_;
    const char* const last = data_.data() + data_.size();
    std::int64_t step = 0;
    Canonical c(first, last);
    if (const char* end = c.record_prefix(out, step);
        end != nullptr && (end == last || *end == '\n') && step == next_step_) {
      pos_ = end == last ? data_.size() : static_cast<std::size_t>(end - data_.data()) + 1;
      ++line_;
      out.step = step;
      ++next_step_;
      return true;
    }
  }
  while (pos_ < data_.size()) {
    const auto nl = data_.find('\n', pos_);
    const bool last_cut = nl == std::string::npos;
    const std::size_t end = last_cut ? data_.size() : nl;
    const std::size_t start = pos_;
    pos_ = last_cut ? data_.size() : nl + 1;
    ++line_;
    // The fast path above has tried this line in the writer's form already: judged here in full.
    Cursor c(name_, line_, data_.data() + start, data_.data() + end);
    if (c.done()) {
      if (last_cut) return false;
      c.fail("an empty line");
    }
    try {
      if (stop_) c.fail("a line after the stop record");
      unsigned seen = 0;
      std::string key;
      std::string reason;
      std::int64_t step = 0;
      // Keys as string_views: a length check before any byte compare (a replay's hot loop).
      c.object(key, [&](const std::string& key_text) {
        const std::string_view k = key_text;
        if (k == "step"sv)
          once(c, seen, kStep, key_text), step = c.integer();
        else if (k == "t_ns"sv)
          once(c, seen, kTime, key_text), out.time_ns = c.integer();
        else if (k == "io"sv)
          once(c, seen, kIo, key_text), c.io(out.io);
        else if (k == "obs"sv)
          once(c, seen, kObs, key_text), c.ints(out.obs);
        else if (k == "cmd"sv)
          once(c, seen, kCmd, key_text), c.ints(out.cmd);
        else if (k == "odo"sv)
          once(c, seen, kOdo, key_text), c.ints(out.odo);
        else if (k == "state"sv)
          once(c, seen, kState, key_text), out.state = c.hex16();
        else if (k == "stop"sv)
          once(c, seen, kStop, key_text), c.string(reason);
        else
          c.fail("unknown key \"" + key_text + "\"");
      });
      if (!c.done()) c.fail("unexpected bytes after the record");
      if (seen & kStop) {
        if (seen != (kStop | kStep | kIo))
          c.fail("a stop record has exactly the keys stop, step and io");
        LogStop s;
        s.reason = std::move(reason);
        s.step = step;
        s.io = out.io;
        if (step != next_step_)
          c.fail("the stop record says " + std::to_string(step) + " steps, the log has " +
                 std::to_string(next_step_));
        stop_ = std::move(s);
        // Nothing may follow the stop record (blank lines aside).
        std::size_t at = pos_;
        while (at < data_.size()) {
          const auto next_nl = data_.find('\n', at);
          const std::size_t stop_at = next_nl == std::string::npos ? data_.size() : next_nl;
          ++line_;
          if (data_.find_first_not_of(" \t\r", at) < stop_at)
            throw InputError(name_, line_, 1, "a line after the stop record");
          at = stop_at + 1;
        }
        pos_ = data_.size();
        return false;
      }
      if (seen != (kStep | kTime | kIo | kObs | kCmd | kOdo | kState))
        c.fail("a step record needs step, t_ns, io, obs, cmd, odo and state");
      if (step != next_step_)
        c.fail("step " + std::to_string(step) + " where step " + std::to_string(next_step_) +
               " was expected");
      out.step = step;
      ++next_step_;
      return true;
    } catch (const InputError&) {
      if (last_cut) { // the final line was cut short while being written
        truncated_ = true;
        return false;
      }
      throw;
    }
  }
  return false;
}

} // namespace antkit::devices
