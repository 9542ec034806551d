// The e-puck2's binary codec and its firmware emulator (epuck2.hpp).
#include <algorithm>
#include <antkit/devices/epuck2.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <charconv>

namespace antkit::devices::epuck2 {

namespace {

constexpr std::uint32_t kMillion = 1000000;
constexpr std::uint64_t kFaultPurpose = 43; // the e-puck2's binary faults' stream (issue 43)

void put16(std::string& out, std::int32_t v) {
  const auto u = static_cast<std::uint16_t>(static_cast<std::int16_t>(v));
  out += static_cast<char>(u & 0xFF);
  out += static_cast<char>(u >> 8);
}

std::uint16_t get16(std::string_view b, std::size_t at) noexcept {
  return static_cast<std::uint16_t>(
      static_cast<unsigned char>(b[at]) |
      (static_cast<unsigned>(static_cast<unsigned char>(b[at + 1])) << 8));
}

std::int32_t clamp_speed(std::int32_t v) noexcept {
  return std::clamp(v, -kSpeedLimit, kSpeedLimit);
}

template <class T>
Decoded<T> fail(std::size_t column, std::string message) {
  Decoded<T> d;
  d.error = {column, std::move(message)};
  return d;
}

// The argument bytes of each request the firmware knows (PROTOCOLS.md's table); -1: unknown.
int argument_count(char req) noexcept {
  switch (static_cast<unsigned char>(req)) {
  case 0xBC: // -'D'
  case 0xB0: // -'P'
    return 4;
  case 0xB4: // -'L'
  case 0xA7: // -'Y'
    return 2;
  case 0xA9: // -'W'
    return 3;
  case 0x89: // -'w'
    return 35;
  case 0xF7: // -0x09
    return 19;
  case 0xF6: // -0x0A
    return 12;
  case 0xF1:
  case 0xF0:
  case 0xEF:
    return 1;
  case 0xBB: // -'E'
  case 0xB2: // -'N'
  case 0xB1: // -'O'
  case 0xAF: // -'Q'
  case 0xBF: // -'A'
  case 0x9F: // -'a'
  case 0x9E: // -'b'
  case 0x99: // -'g'
  case 0xB3: // -'M'
  case 0x8B: // -'u'
  case 0x8C: // -'t'
  case 0xAB: // -'U'
  case 0xF8: // -0x08
  case 0xF5:
  case 0xF4:
  case 0xF3:
  case 0xF2:
    return 0;
  default:
    return -1;
  }
}

// The reply bytes of each request (PROTOCOLS.md's table, the e-puck2's sizes); 0: none, or not
// framed here (-'I', whose size depends on the camera's mode).
std::size_t reply_bytes(char req) noexcept {
  switch (static_cast<unsigned char>(req)) {
  case 0xF8: // -0x08 all sensors
    return 103;
  case 0xB2: // -'N'
  case 0xB1: // -'O'
    return 16;
  case 0xBF: // -'A'
    return 12;
  case 0xB3: // -'M'
  case 0xF4:
    return 8;
  case 0x9F: // -'a'
  case 0x99: // -'g'
  case 0x8B: // -'u'
    return 6;
  case 0xBB: // -'E'
  case 0xAF: // -'Q'
    return 4;
  case 0x9E: // -'b'
  case 0xF3:
    return 2;
  case 0x8C: // -'t'
  case 0xA7: // -'Y'
  case 0xF5:
  case 0xF2:
  case 0xF1:
  case 0xF0:
  case 0xEF:
    return 1;
  default:
    return 0;
  }
}

// Each request of a sequence, in order, with its argument count known (unknown bytes skipped, as
// the firmware skips them), up to the 0 that ends it.
template <class F>
void for_each_request(std::string_view sequence, F&& f) {
  for (std::size_t i = 0; i < sequence.size();) {
    const char c = sequence[i];
    if (c == 0) return;
    const int n = argument_count(c);
    ++i;
    if (n < 0) continue;
    f(c);
    i += static_cast<std::size_t>(n);
  }
}

// The values of an ASCII reply line of the e-puck emulator ("q,12,-3\r\n").
std::vector<std::int32_t> values_of(std::string_view line) {
  std::vector<std::int32_t> out;
  std::size_t at = line.find(',');
  while (at != std::string_view::npos) {
    const std::size_t from = at + 1;
    std::int32_t v = 0;
    const auto end = line.data() + line.size();
    const auto r = std::from_chars(line.data() + from, end, v);
    out.push_back(r.ec == std::errc() ? v : 0);
    at = line.find(',', from);
  }
  return out;
}

} // namespace

std::string step_sequence(std::int32_t left, std::int32_t right) {
  std::string out;
  out += request('D');
  put16(out, clamp_speed(left));
  put16(out, clamp_speed(right));
  out += request('N');
  out += request('Q');
  out += '\0';
  return out;
}

std::string start_sequence() {
  std::string out;
  out += request('P');
  out.append(4, '\0');
  out += request('Q');
  out += '\0';
  return out;
}

std::string stop_sequence() {
  std::string out;
  out += request('D');
  out.append(4, '\0');
  out += request('E');
  out += '\0';
  return out;
}

std::string resync_bytes() {
  return std::string(kResyncZeros, '\0');
}

Decoded<StepReply> decode_step(std::string_view bytes) {
  if (bytes.size() != kStepReplySize)
    return fail<StepReply>(std::min(bytes.size(), kStepReplySize) + 1,
                           "expected " + std::to_string(kStepReplySize) + " bytes, got " +
                               std::to_string(bytes.size()));
  StepReply r;
  for (std::size_t i = 0; i < 8; ++i) {
    const std::uint16_t v = get16(bytes, 2 * i);
    if (v >= kProximityLimit)
      return fail<StepReply>(2 * i + 1, "proximity IR" + std::to_string(i) + " reads " +
                                            std::to_string(v) + ": expected 0 to 4095");
    r.proximity.raw[i] = v;
  }
  r.left = static_cast<std::int16_t>(get16(bytes, 16));
  r.right = static_cast<std::int16_t>(get16(bytes, 18));
  Decoded<StepReply> out;
  out.value = r;
  return out;
}

Decoded<WheelPair> decode_pair(std::string_view bytes) {
  if (bytes.size() != kPairReplySize)
    return fail<WheelPair>(std::min(bytes.size(), kPairReplySize) + 1,
                           "expected " + std::to_string(kPairReplySize) + " bytes, got " +
                               std::to_string(bytes.size()));
  Decoded<WheelPair> out;
  out.value = WheelPair{static_cast<std::int16_t>(get16(bytes, 0)),
                        static_cast<std::int16_t>(get16(bytes, 2))};
  return out;
}

std::size_t reply_size(std::string_view sequence) noexcept {
  std::size_t n = 0;
  for_each_request(sequence, [&](char req) { n += reply_bytes(req); });
  return n;
}

bool identifies(std::string_view line) noexcept {
  constexpr std::string_view kPrefix = "v,Version ";
  if (!line.starts_with(kPrefix) || !line.ends_with("\r\n")) return false;
  const std::string_view text = line.substr(2, line.size() - 4);
  for (const char c : text)
    if (c < 0x20 || c > 0x7E) return false;
  std::size_t i = kPrefix.size();
  std::uint32_t major = 0;
  const std::size_t from = i;
  while (i < line.size() && line[i] >= '0' && line[i] <= '9' && i - from < 6)
    major = major * 10 + static_cast<std::uint32_t>(line[i++] - '0');
  return i > from && major >= 2;
}

Verdict SequenceFraming::classify(std::string_view request, std::string_view unit) const {
  Verdict v;
  if (request == kVersionRequest) {
    // A line: the reply when it is `v,` and printable text, CR LF; any other line read past.
    bool reply = unit.starts_with("v,") && unit.ends_with("\r\n");
    for (std::size_t i = 2; reply && i + 2 < unit.size(); ++i)
      reply = unit[i] >= 0x20 && unit[i] <= 0x7E;
    v.kind = reply ? ReplyKind::Reply : ReplyKind::Stale;
    return v;
  }
  const std::size_t n = reply_size(request);
  if (unit.size() != n) {
    v.why = "byte " + std::to_string(std::min(unit.size(), n) + 1) + ": expected " +
            std::to_string(n) + " bytes, got " + std::to_string(unit.size());
    return v;
  }
  std::size_t at = 0;
  for_each_request(request, [&](char req) {
    if (req == epuck2::request('N') && v.why.empty())
      for (std::size_t i = 0; i < 8 && v.why.empty(); ++i) {
        const std::uint16_t reading = get16(unit, at + 2 * i);
        if (reading >= kProximityLimit)
          v.why = "byte " + std::to_string(at + 2 * i + 1) + ": proximity IR" + std::to_string(i) +
                  " reads " + std::to_string(reading) + ": expected 0 to 4095";
      }
    at += reply_bytes(req);
  });
  if (v.why.empty()) v.kind = ReplyKind::Reply;
  return v;
}

StopPlan SequenceFraming::stop_plan() const {
  StopPlan plan;
  plan.resync_first = true;
  plan.read_back = stop_sequence();
  plan.read_back_stops = true;
  return plan;
}

std::string SequenceFraming::describe(std::string_view request) const {
  if (request == kVersionRequest) return "'" + printable(request) + "'";
  return "the sequence '" + printable(request) + "'";
}

std::int64_t unwrap(std::int64_t total, std::int16_t low) noexcept {
  const auto was = static_cast<std::uint16_t>(static_cast<std::uint64_t>(total));
  const auto delta =
      static_cast<std::int16_t>(static_cast<std::uint16_t>(static_cast<std::uint16_t>(low) - was));
  return total + delta;
}

// ---- the firmware ----

Emulator::Emulator(std::vector<kernel::FxSegment> walls, EmulatorOptions options)
    : body_(RobotKind::Epuck, std::move(walls),
            [&] {
              EmulatorOptions inner = options;
              inner.faults = {}; // the faults are the binary firmware's (below)
              inner.pace = false;
              return inner;
            }()),
      options_(options), faults_stream_(options.seed, kEmulatorExperiment, 0, 0, kFaultPurpose) {
  reset();
}

void Emulator::reset() {
  body_.reset();
  faults_stream_ = kernel::Stream(options_.seed, kEmulatorExperiment, 0, 0, kFaultPurpose);
  state_ = State::Top;
  line_.clear();
  args_.clear();
  reply_.clear();
  set_left_ = set_right_ = 0;
  banner_ = true; // the start-up text goes out first
  silent_ = false;
  session_units_ = 0;
}

void Emulator::new_session() {
  if (sessions_ > 0) reset();
  ++sessions_;
}

EmulatorResponse Emulator::feed(std::string_view bytes) {
  EmulatorResponse out;
  if (banner_) {
    out.bytes += kBanner;
    banner_ = false;
  }
  for (const char c : bytes) {
    if (out.hang_up) break;
    byte(c, out);
  }
  // `pace`: the answer leaves at the line's rate, 115 200 baud 8N1 (10 bit times a byte), after
  // the ASCII emulator's command latency (emulator.hpp, kCommandLatency): as FirmwareEmulator
  // paces its replies, so the two e-pucks compare on one footing.
  if (options_.pace && !out.bytes.empty())
    out.delay +=
        kCommandLatency + std::chrono::microseconds(out.bytes.size() * 10 * 1000000 / kBaud);
  return out;
}

void Emulator::byte(char c, EmulatorResponse& out) {
  const auto u = static_cast<unsigned char>(c);
  switch (state_) {
  case State::SkipCrLf:
    if (c == '\r' || c == '\n') return;
    // The byte after the skipped terminators starts an ASCII line whatever its value.
    state_ = State::Ascii;
    line_.assign(1, c);
    return;
  case State::Top:
    if (u == 0) return;
    if (u >= 0x80) {
      state_ = State::Sequence;
      reply_.clear();
      byte(c, out);
      return;
    }
    if (c == '\r' || c == '\n') {
      state_ = State::SkipCrLf;
      return;
    }
    state_ = State::Ascii;
    line_.assign(1, c);
    return;
  case State::Ascii:
    if (c == '\r' || c == '\n') {
      ascii_line(out);
      line_.clear();
      state_ = State::Top;
      return;
    }
    if (line_.size() < 256) line_ += c;
    return;
  case State::Arguments:
    args_ += c;
    if (args_.size() == need_) {
      run_request(request_, args_);
      state_ = State::Sequence;
    }
    return;
  case State::Sequence: {
    if (u == 0) {
      end_sequence(out);
      return;
    }
    const int n = argument_count(c);
    if (n < 0) return; // unknown: skipped
    request_ = c;
    args_.clear();
    if (n == 0) {
      run_request(c, {});
      return;
    }
    need_ = static_cast<std::size_t>(n);
    state_ = State::Arguments;
    return;
  }
  }
}

void Emulator::run_request(char req, std::string_view args) {
  if (silent_) return;
  switch (static_cast<unsigned char>(req)) {
  case 0xBC: { // -'D': 16-bit values, cast to int16 for the motors, which clamp at +-1100
    set_left_ = static_cast<std::int16_t>(get16(args, 0));
    set_right_ = static_cast<std::int16_t>(get16(args, 2));
    const auto model = [](std::int32_t v) { return std::clamp(clamp_speed(v), -1000, 1000); };
    (void)body_.handle("D," + std::to_string(model(set_left_)) + "," +
                       std::to_string(model(set_right_)));
    return;
  }
  case 0xB0: // -'P'
    (void)body_.handle("P," + std::to_string(static_cast<std::int16_t>(get16(args, 0))) + "," +
                       std::to_string(static_cast<std::int16_t>(get16(args, 2))));
    return;
  case 0xBB: // -'E': as last set
    put16(reply_, set_left_);
    put16(reply_, set_right_);
    return;
  case 0xB2: { // -'N': one control period, then the readings
    const auto v = values_of(body_.handle("N").bytes);
    for (std::size_t i = 0; i < 8; ++i)
      put16(reply_, std::clamp(i < v.size() ? v[i] : 0, 0, kProximityLimit - 1));
    return;
  }
  case 0xAF: { // -'Q': the counters' low 16 bits
    const auto v = values_of(body_.handle("Q").bytes);
    put16(reply_, v.size() > 0 ? v[0] : 0);
    put16(reply_, v.size() > 1 ? v[1] : 0);
    return;
  }
  default: { // the rest of the table: replies of their sizes, zeros (not modelled)
    static constexpr std::pair<unsigned char, std::size_t> kSizes[] = {
        {0xB1, 16}, {0xBF, 12}, {0x9F, 6}, {0x9E, 2},   {0x99, 6}, {0xB3, 8},
        {0x8B, 6},  {0x8C, 1},  {0xA7, 1}, {0xF8, 103}, {0xF5, 1}, {0xF4, 8},
        {0xF3, 2},  {0xF2, 1},  {0xF1, 1}, {0xF0, 1},   {0xEF, 1}};
    for (const auto& [code, size] : kSizes)
      if (code == static_cast<unsigned char>(req)) reply_.append(size, '\0');
    return;
  }
  }
}

void Emulator::end_sequence(EmulatorResponse& out) {
  state_ = State::Top;
  const FaultSpec& f = options_.faults;
  ++sequences_;
  ++session_units_;
  if (f.disconnect_after >= 0 && session_units_ > static_cast<std::uint64_t>(f.disconnect_after)) {
    ++faults_;
    out.hang_up = true;
    return;
  }
  if (f.silent_after >= 0 && session_units_ > static_cast<std::uint64_t>(f.silent_after)) {
    silent_ = true;
    reply_.clear();
  }
  if (reply_.empty()) return; // set-only: no reply
  const bool unterminated = faults_stream_.below(kMillion) < f.unterminated_ppm;
  if (unterminated) {
    // The 0 was lost on the line: the firmware goes on reading requests of this sequence.
    ++faults_;
    --sequences_;
    state_ = State::Sequence;
    return;
  }
  const bool delay = faults_stream_.below(kMillion) < f.delay_ppm;
  const bool garbage = faults_stream_.below(kMillion) < f.garbage_ppm;
  const bool drop = faults_stream_.below(kMillion) < f.drop_ppm;
  const bool cut = faults_stream_.below(kMillion) < f.cut_ppm;
  std::string reply = std::move(reply_);
  reply_.clear();
  if (delay) {
    ++faults_;
    out.delay += std::chrono::duration_cast<std::chrono::microseconds>(f.delay);
  }
  if (drop) {
    ++faults_;
    return;
  }
  if (cut) {
    ++faults_;
    reply.resize(reply.size() / 2);
  }
  if (garbage) {
    ++faults_;
    reply = std::string(kBanner) + reply;
  }
  out.bytes += reply;
}

void Emulator::ascii_line(EmulatorResponse& out) {
  ++lines_;
  ++session_units_;
  const FaultSpec& f = options_.faults;
  if (f.disconnect_after >= 0 && session_units_ > static_cast<std::uint64_t>(f.disconnect_after)) {
    ++faults_;
    out.hang_up = true;
    return;
  }
  if (f.silent_after >= 0 && session_units_ > static_cast<std::uint64_t>(f.silent_after))
    silent_ = true;
  if (silent_) return;
  char letter = line_.empty() ? 0 : line_[0];
  if (letter >= 'a' && letter <= 'z' && letter != 'b' && letter != 'g')
    letter = static_cast<char>(letter - 'a' + 'A');
  if (letter == 'R') return; // the e-puck2 neither resets nor answers
  if (letter == 'V') {
    out.bytes += "v,Version 2.0 antkit epuck2 emulator\r\nHW version: FFF7\r\n";
    return;
  }
  if (letter == 'E') { // the last speeds set, as 16-bit values (a negative one as 65536 + v)
    const auto u16 = [](std::int32_t v) { return std::to_string(static_cast<std::uint16_t>(v)); };
    out.bytes += "e," + u16(set_left_) + "," + u16(set_right_) + "\r\n";
    return;
  }
  std::string line = line_;
  if (!line.empty()) line[0] = letter;
  const EmulatorResponse r = body_.handle(line);
  if (letter == 'D' && r.bytes == "d\r\n") {
    const auto v = values_of(line);
    if (v.size() == 2) set_left_ = v[0], set_right_ = v[1];
  }
  out.bytes += r.bytes;
}

std::uint64_t Emulator::serve(Pty& pty, const std::atomic<bool>* stop, bool stop_on_signal) {
  const std::uint64_t first = commands();
  serve_pty(
      pty, [this](std::string_view bytes) { return feed(bytes); }, [this] { new_session(); }, stop,
      stop_on_signal, true);
  return commands() - first;
}

std::uint64_t Emulator::serve(TcpListener& listener, const std::atomic<bool>* stop,
                              bool stop_on_signal) {
  const std::uint64_t first = commands();
  serve_tcp(
      listener, [this](std::string_view bytes) { return feed(bytes); }, [this] { new_session(); },
      stop, stop_on_signal, true);
  return commands() - first;
}

} // namespace antkit::devices::epuck2
