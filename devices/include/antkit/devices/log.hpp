#pragma once
// Hardware logs: JSON Lines (DESIGN.md, Files and formats). Line 1 is the header, then one record
// per control step, then a stop record that says how the run ended:
//   {"schema":1,"antkit":"0.1.0","robot":"khepera","port":{"path":"/dev/pts/3","baud":9600,
//    "framing":"8N2"},"controller":{"name":"buffon","params":{"trial":0,"visit":1}},"seed":1}
//   {"step":0,"t_ns":1234,"io":[["N\r","n,0,0,0,0,0,0,0,0\r\n",812],["D,3,4\r","d\r\n",1101]],
//    "obs":[0,0],"cmd":[1,-2],"odo":[10,20],"state":"0123456789abcdef"}
//   {"stop":"done","step":1000,"io":[["D,0,0\r","d\r\n"]]}
// An exchange is one send and every byte read after it until the next send: its reply, when it got
// one, is the last line, and any lines before it are late replies to earlier commands (link.hpp);
// an exchange with nothing sent holds bytes drained from the line before a send (late, so dropped).
// Its third element is the time of the send (of the drain, for drained bytes) in nanoseconds since
// the run started, on the clock of "t_ns" (a record's time, taken when its step ended): a robot
// without wheel encoders (the Hemisson) derives its odometry from these times, and a replay from
// the same logged times. Logs written before exchange times were logged have two elements; they
// read as times -1 (unknown), and a Hemisson log without them cannot be replayed.
// The header may end with "arena":"SPEC" (the emulator's arena, when `antkit record --arena` gave
// it); it is written only when known.
// The writer emits exactly this form (keys in this order, no spaces). Bytes on the wire are JSON
// strings with one character per byte: printable ASCII as itself but '"' and '\' (escaped), \r \n
// \t, every other byte \u00XX; a log is pure ASCII. The reader takes any JSON of these shapes (keys
// in any order, whitespace between tokens, every string escape up to \u00FF) and refuses anything
// else with its line and column: unknown, missing or repeated keys, fractions, exponents, integers
// out of range, a state that is not 16 hex digits, steps that do not count up by one, a line after
// the stop record. A last line without its newline that does not parse is a cut (a crash or a power
// cut while writing): truncated() says so and every record before it was read.
//
// Logs are the one output written in place rather than through a temporary file and a rename:
// each record is written and flushed before the next step starts, so that whatever stops the run,
// every step before it is on disk.
#include <antkit/devices/log_schema.hpp>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace antkit::devices {

struct Exchange {
  std::string sent;
  std::string received;
  std::int64_t t_ns = -1; // when it was sent (drained), ns since the run's start; -1 unknown
  friend bool operator==(const Exchange&, const Exchange&) = default;
};

struct LogHeader {
  std::uint32_t schema = kLogSchemaVersion;
  std::string antkit_version;
  std::string robot;
  std::string port;
  std::uint32_t baud = 0;
  std::string framing;
  std::string controller;
  std::vector<std::pair<std::string, std::int64_t>> params;
  std::uint64_t seed = 0;
  // The arena the run took place in, when known (an emulator's named spec or WKT file, as given to
  // `antkit record --arena`); written only when not empty, so that older logs read unchanged.
  std::string arena;
  friend bool operator==(const LogHeader&, const LogHeader&) = default;
};

struct LogRecord {
  std::int64_t step = 0;
  std::int64_t time_ns = 0;
  std::vector<Exchange> io;
  std::vector<std::int64_t> obs;
  std::vector<std::int64_t> cmd;
  std::vector<std::int64_t> odo;
  std::uint64_t state = 0;
  friend bool operator==(const LogRecord&, const LogRecord&) = default;
};

struct LogStop {
  std::int64_t step = 0;
  std::string reason;
  std::vector<Exchange> io;
  friend bool operator==(const LogStop&, const LogStop&) = default;
};

std::string format_header(const LogHeader& h);
// Appends `bytes` as the log writes a byte string: a JSON string, one character per byte, `"`, `\`,
// CR, LF and TAB escaped, other bytes outside printable ASCII as \u00XX (the MCAP export writes its
// strings the same way).
void append_json_bytes(std::string& out, std::string_view bytes);
std::string format_record(const LogRecord& r);
std::string format_stop(const LogStop& s);

namespace detail {
// LogReader's fast path, open to tests: reads `line` (no newline) into `out` when it is a step
// record exactly as format_record writes it, and returns false, deciding nothing, at the first
// byte of any other form (LogReader then reads the line with its general reader, which judges it).
bool read_canonical_step(std::string_view line, LogRecord& out);
} // namespace detail

// Refuses (kernel::InputError(path, ...)) a log that exists unless `replace`: what LogWriter does,
// checked before a recording opens its port, so that a refused --out leaves the robot untouched.
void check_new_log(const std::string& path, bool replace);

// A log that could not be written on (a full disk, a file size limit, an I/O error).
class LogWriteError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class LogWriter {
public:
  // Throws kernel::InputError(path, ...) when the file cannot be created, or exists and `replace`
  // is false (created exclusively: two recorders cannot share one log either), or its header
  // cannot be written. write() and finish() throw LogWriteError.
  LogWriter(const std::string& path, const LogHeader& header, std::uint32_t sync_every = 0,
            bool replace = false);
  LogWriter(const LogWriter&) = delete;
  LogWriter& operator=(const LogWriter&) = delete;
  ~LogWriter();
  void write(const LogRecord& r);
  void finish(const LogStop& s);
  [[nodiscard]] std::uint64_t records() const noexcept { return records_; }

private:
  void put(const std::string& line);
  std::string path_;
  std::FILE* file_ = nullptr;
  std::uint32_t sync_every_;
  std::uint64_t records_ = 0;
};

class LogReader {
public:
  explicit LogReader(const std::string& path);
  LogReader(std::string name, std::string contents);
  ~LogReader();
  LogReader(const LogReader&) = delete;
  LogReader& operator=(const LogReader&) = delete;
  [[nodiscard]] const LogHeader& header() const noexcept { return header_; }
  bool next(LogRecord& out);
  [[nodiscard]] bool truncated() const noexcept { return truncated_; }
  [[nodiscard]] const std::optional<LogStop>& stop() const noexcept { return stop_; }
  [[nodiscard]] std::size_t line() const noexcept { return line_; }
  // The step records still to read, counted from the lines ahead without parsing them (one scan
  // for newlines): the non-blank lines, less a last one that holds a "stop" key or is cut short
  // (no newline and no closing brace). Exact for a log that reads whole; for a damaged one it may
  // be off, as next() is the judge. The MCAP export spaces its trail messages by it.
  [[nodiscard]] std::size_t records_ahead() const noexcept;

private:
  void read_header();
  std::string name_;
  std::string owned_;   // the log, when given in memory or read (not mapped)
  void* map_ = nullptr; // the log's file, mapped read-only (a replay copies nothing)
  std::size_t map_size_ = 0;
  std::string_view data_; // the log's bytes
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
  LogHeader header_;
  std::optional<LogStop> stop_;
  bool truncated_ = false;
  std::int64_t next_step_ = 0;
};

} // namespace antkit::devices
