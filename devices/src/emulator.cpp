// Firmware emulators on a pseudo-terminal or over TCP (emulator.hpp).
#include <algorithm>
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cctype>
#include <optional>
#include <sys/inotify.h>
#include <thread>
#include <unistd.h>

namespace antkit::devices {

namespace {

using kernel::Fx;
using kernel::InputError;

// The emulator's streams: purpose 1 the start heading (as World::start_pose takes it), 2 the
// faults.
enum : std::uint64_t { kStartPurpose = 1, kFaultPurpose = 2 };
constexpr std::uint32_t kMillion = 1000000;

// "0.05" -> 50000 ppm: a probability with up to six decimals, in [0, 1].
std::uint32_t parse_probability(std::string_view text, const std::string& spec) {
  const auto bad = [&] {
    return InputError("fault", "'" + spec +
                                   "': the probability must be a decimal in [0, 1] with at "
                                   "most six decimals, e.g. 0.05");
  };
  std::uint64_t whole = 0, frac = 0;
  std::size_t i = 0, digits = 0;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) && i < 2)
    whole = whole * 10 + static_cast<std::uint64_t>(text[i++] - '0');
  if (i == 0) throw bad();
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) && digits < 6) {
      frac = frac * 10 + static_cast<std::uint64_t>(text[i++] - '0');
      ++digits;
    }
    if (digits == 0) throw bad();
  }
  if (i != text.size()) throw bad();
  while (digits++ < 6) frac *= 10;
  const std::uint64_t ppm = whole * kMillion + frac;
  if (ppm > kMillion) throw bad();
  return static_cast<std::uint32_t>(ppm);
}

std::int64_t parse_count(std::string_view text, const std::string& spec, std::int64_t hi) {
  std::int64_t v = 0;
  if (text.empty() || text.size() > 10) v = -1;
  for (const char c : text) {
    if (v < 0 || !std::isdigit(static_cast<unsigned char>(c))) {
      v = -1;
      break;
    }
    v = v * 10 + (c - '0');
  }
  if (v < 0 || v > hi)
    throw InputError("fault",
                     "'" + spec + "': expected a whole number in [0, " + std::to_string(hi) + "]");
  return v;
}

__extension__ using i128 = __int128;

std::int32_t floor_div(i128 a, i128 b) {
  auto q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint64_t>(q)));
}

} // namespace

FaultSpec parse_faults(const std::vector<std::string>& specs) {
  FaultSpec f;
  for (const auto& spec : specs) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos)
      throw InputError("fault", "'" + spec +
                                    "': expected delay=P:MS, garbage=P, drop=P, cut=P, "
                                    "disconnect=N, silent=N or unterminated=P");
    const std::string kind = spec.substr(0, eq);
    const std::string_view value = std::string_view(spec).substr(eq + 1);
    if (kind == "delay") {
      const auto colon = value.find(':');
      if (colon == std::string_view::npos)
        throw InputError("fault", "'" + spec + "': expected delay=P:MS (e.g. delay=0.1:50)");
      f.delay_ppm = parse_probability(value.substr(0, colon), spec);
      f.delay = std::chrono::milliseconds(parse_count(value.substr(colon + 1), spec, 60000));
    } else if (kind == "garbage") {
      f.garbage_ppm = parse_probability(value, spec);
    } else if (kind == "drop") {
      f.drop_ppm = parse_probability(value, spec);
    } else if (kind == "cut") {
      f.cut_ppm = parse_probability(value, spec);
    } else if (kind == "disconnect") {
      f.disconnect_after = parse_count(value, spec, 1000000000);
    } else if (kind == "silent") {
      f.silent_after = parse_count(value, spec, 1000000000);
    } else if (kind == "unterminated") {
      f.unterminated_ppm = parse_probability(value, spec);
    } else {
      throw InputError("fault", "unknown fault '" + kind +
                                    "': expected delay, garbage, drop, cut, disconnect, silent or "
                                    "unterminated");
    }
  }
  return f;
}

FirmwareEmulator::FirmwareEmulator(RobotKind robot, std::vector<kernel::FxSegment> walls,
                                   EmulatorOptions options)
    : codec_(robot), world_(std::move(walls)), options_(options),
      fault_stream_(options.seed, kEmulatorExperiment, 0, 0, kFaultPurpose) {
  kernel::Stream start(options_.seed, kEmulatorExperiment, 0, 0, kStartPurpose);
  start_ = world_.start_pose(start);
  const auto& d = codec_.robot();
  range_ = std::min(buffon::kSensorRange, Fx::from_ratio(d.sensor_range_um, d.diameter_um));
  reset();
}

void FirmwareEmulator::reset() {
  pose_ = start_;
  speed_left_ = speed_right_ = 0;
  travel2_[0] = travel2_[1] = 0;
  offset_[0] = offset_[1] = 0;
  trail_.assign(1, pose_.position);
  fault_stream_ = kernel::Stream(options_.seed, kEmulatorExperiment, 0, 0, kFaultPurpose);
  session_commands_ = 0;
}

std::int32_t FirmwareEmulator::counter(int wheel) const noexcept {
  const auto& d = codec_.robot();
  if (!d.has_odometry) return 0;
  // pulses = travel / pulse = (travel2 / 2) [raw um] * 1000 / (65536 * pulse_nm)
  const i128 num = travel2_[wheel] * 1000, den = i128{2} * 65536 * d.odometry_pulse_nm;
  // The Webots relay casts 50 * angle / pi to int: toward zero; the firmwares count whole pulses.
  const auto pulses = d.webots_relay ? static_cast<std::int32_t>(static_cast<std::uint32_t>(
                                           static_cast<std::uint64_t>(num / den)))
                                     : floor_div(num, den);
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(pulses) +
                                   static_cast<std::uint32_t>(offset_[wheel]));
}

void FirmwareEmulator::advance() {
  const auto& d = codec_.robot();
  const buffon::Command cmd{from_wheel_command(d, speed_left_),
                            from_wheel_command(d, speed_right_)};
  const bool moved = world_.move(pose_, cmd); // false: blocked, turned on the spot
  const Travel2 t = step_travel2(d, world_.body().speed, cmd.left, cmd.right, moved);
  travel2_[0] += t.left;
  travel2_[1] += t.right;
  trail_.push_back(pose_.position);
}

void FirmwareEmulator::sense(std::array<std::int32_t, 8>& raw) const {
  const auto& d = codec_.robot();
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (d.ground[i]) {
      raw[i] = kFloorReading;
      continue;
    }
    const Fx reading =
        world_.ray_reading(pose_, kernel::Angle::from_degrees(d.proximity_angle_deg[i]), range_);
    raw[i] = reading_to_raw(d, reading);
  }
}

std::string FirmwareEmulator::answer(const Fields& cmd) {
  const auto& d = codec_.robot();
  const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(cmd.letter)));
  const auto args = [&](std::uint8_t n) { return cmd.count == n; };
  const auto values = [&](std::initializer_list<std::int32_t> v) {
    return codec_.reply(letter, std::span<const std::int32_t>(v.begin(), v.size()));
  };
  if (letter == 'D' && args(2)) {
    if (cmd.values[0] < d.speed_min || cmd.values[0] > d.speed_max || cmd.values[1] < d.speed_min ||
        cmd.values[1] > d.speed_max)
      return {};
    speed_left_ = cmd.values[0];
    speed_right_ = cmd.values[1];
    return codec_.reply('D');
  }
  if (letter == 'E' && args(0)) return values({speed_left_, speed_right_});
  if (letter == 'N' && args(0)) {
    advance();
    std::array<std::int32_t, 8> raw{};
    sense(raw);
    return codec_.reply('N', raw);
  }
  if (letter == 'O' && args(0)) {
    std::array<std::int32_t, 8> ambient{};
    ambient.fill(d.proximity_max / 2); // an evenly lit room (a choice)
    return codec_.reply('O', ambient);
  }
  if (d.has_odometry && letter == d.odometry_read && args(0))
    return values({counter(0), counter(1)});
  if (d.has_odometry && letter == d.odometry_set && args(2)) {
    for (int w = 0; w < 2; ++w) {
      offset_[w] = 0;
      offset_[w] = static_cast<std::int32_t>(
          static_cast<std::uint32_t>(cmd.values[static_cast<std::size_t>(w)]) -
          static_cast<std::uint32_t>(counter(w)));
    }
    return codec_.reply(letter);
  }
  if (letter == 'L' && args(2)) return codec_.reply('L');
  if (letter == d.version_letter) return std::string(d.version_reply);
  if (d.stop_letter != 0 && letter == d.stop_letter && args(0)) {
    speed_left_ = speed_right_ = 0;
    return codec_.reply('S');
  }
  return {};
}

std::string FirmwareEmulator::relay_answer(std::string_view line) {
  const auto& d = codec_.robot();
  const char letter = line.empty() ? '\0' : line[0];
  const auto parsed = codec_.parse_command(line);
  const bool two = parsed && parsed.value->count == 2;
  switch (letter) {
  case 'D': // sscanf "D,%d,%d" then wb_motor_set_velocity, which clamps to maxVelocity
    if (two) {
      speed_left_ = std::clamp(parsed.value->values[0], d.speed_min, d.speed_max);
      speed_right_ = std::clamp(parsed.value->values[1], d.speed_min, d.speed_max);
    }
    return codec_.reply('D');
  case 'L':
  case 'G': // the position counters are not reset
    return codec_.reply(letter);
  case 'B':
    return std::string(d.version_reply);
  case 'N': {
    advance();
    std::array<std::int32_t, 8> raw{};
    sense(raw);
    return codec_.reply('N', raw);
  }
  case 'H':
    return codec_.reply('H', std::array<std::int32_t, 2>{counter(0), counter(1)});
  case 'O': {
    std::array<std::int32_t, 8> ambient{};
    ambient.fill(d.proximity_max / 2); // an evenly lit room (a choice)
    return codec_.reply('O', ambient);
  }
  default:
    return codec_.unknown_command_reply(line);
  }
}

FirmwareEmulator::Response FirmwareEmulator::handle(std::string_view line) {
  ++commands_;
  ++session_commands_;
  Response out;
  // The fault draws come first and always four, so the stream stays aligned whatever is enabled.
  const auto& f = options_.faults;
  const bool delay = fault_stream_.below(kMillion) < f.delay_ppm;
  const bool garbage = fault_stream_.below(kMillion) < f.garbage_ppm;
  const bool drop = fault_stream_.below(kMillion) < f.drop_ppm;
  const bool cut = fault_stream_.below(kMillion) < f.cut_ppm;
  if (f.disconnect_after >= 0 &&
      session_commands_ > static_cast<std::uint64_t>(f.disconnect_after)) {
    ++faults_;
    out.hang_up = true;
    return out;
  }
  if (f.silent_after >= 0 && session_commands_ > static_cast<std::uint64_t>(f.silent_after)) {
    ++faults_; // read, never answered, never acted on: the line stays open
    return out;
  }
  std::string reply;
  if (codec_.robot().webots_relay) {
    // What one read returned: the relay acts on its first command only (emulator.hpp); a second
    // one in the same read is lost.
    line = line.substr(0, line.find_first_of("\r\n"));
    if (line.substr(0, 4) == "exit") { // tcpip.c: strncmp(buffer, "exit", 4) closes the socket
      out.close_session = true;
      return out;
    }
    reply = relay_answer(line);
  } else {
    const auto parsed = codec_.parse_command(line);
    reply = parsed ? answer(*parsed.value) : std::string();
    if (reply.empty()) reply = codec_.unknown_command_reply(line);
  }
  if (delay) {
    ++faults_;
    out.delay = f.delay;
  }
  if (drop) {
    ++faults_;
    reply.clear();
  } else if (cut && reply.size() > 2) {
    ++faults_;
    reply.resize(std::max<std::size_t>(1, (reply.size() - 2) / 2));
  } else if (garbage) {
    ++faults_;
    std::string junk(1 + fault_stream_.below(8), '\0');
    for (auto& c : junk) {
      // Any byte but CR and LF: junk that runs into the reply line and spoils it.
      do c = static_cast<char>(fault_stream_.below(256));
      while (c == '\r' || c == '\n');
    }
    reply = junk + reply;
  }
  if (options_.pace && !reply.empty()) {
    const auto& line_settings = codec_.robot().line;
    const std::uint64_t bits = 1u + line_settings.data_bits + line_settings.stop_bits +
                               (line_settings.parity == Parity::None ? 0u : 1u);
    out.delay += kCommandLatency + std::chrono::microseconds(reply.size() * bits * 1000000 /
                                                             std::max(1u, line_settings.baud));
  }
  out.bytes = std::move(reply);
  return out;
}

namespace {

// Appends what was read to `pending`; true, with `pending` trimmed to the command, when a whole
// non-empty line has come (the firmware ends a line at CR or LF and skips empty ones).
bool command_line(std::string& pending, const ReadResult& r) {
  pending += r.bytes;
  if (!r.complete) return false;
  while (!pending.empty() && (pending.back() == '\r' || pending.back() == '\n')) pending.pop_back();
  return !pending.empty();
}

// One unit of input: a command line, or (raw: a byte-stream firmware) whatever bytes came, at most
// max_read of them (0: no bound).
bool read_unit(SerialPort& port, std::string& pending, bool raw, std::size_t max_read) {
  if (!raw)
    return command_line(pending, port.read_line(std::chrono::milliseconds(50), LineEnd::CrOrLf));
  pending = port.read_bytes(1, std::chrono::milliseconds(50));
  if (pending.empty()) return false;
  if (max_read > 0) {
    pending += port.read_bytes(max_read - 1, std::chrono::milliseconds(0));
    return true;
  }
  for (std::string more; !(more = port.read_bytes(65536, std::chrono::milliseconds(0))).empty();)
    pending += more;
  return true;
}

// Writes a reply (nothing when empty); false when the client is gone or not reading.
bool write_reply(SerialPort& port, const std::string& bytes) {
  if (bytes.empty()) return true;
  try {
    port.write_all(bytes, std::chrono::milliseconds(2000));
    return true;
  } catch (const LinkError&) {
    return false;
  }
}

} // namespace

void serve_pty(Pty& pty, const std::function<EmulatorResponse(std::string_view)>& handle,
               const std::function<void()>& new_session, const std::atomic<bool>* stop,
               bool stop_on_signal, bool raw, std::size_t max_read) {
  SerialPort& port = pty.master();
  // Without a slave fd of its own the master sees EIO whenever no client has the tty open: that is
  // how a session's end shows when nobody comes at once. Two clients back to back (two `antkit
  // record` runs in a script) may leave no moment without a client for the master to see, and the
  // second would continue the first's session; so the opens and closes of the slave are watched
  // (inotify; they are queued before the client can write): a session starts when the number of
  // clients goes from 0 to 1 and ends when it falls back to 0. A refused second client (port busy)
  // opens and closes without touching the session. Without inotify, EIO alone decides.
  pty.close_slave_keeper();
  int events = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (events >= 0 && ::inotify_add_watch(events, pty.slave_path().c_str(),
                                         IN_OPEN | IN_CLOSE_WRITE | IN_CLOSE_NOWRITE) < 0) {
    ::close(events);
    events = -1;
  }
  struct Closer {
    int fd;
    ~Closer() {
      if (fd >= 0) ::close(fd);
    }
  } closer{events};
  std::int64_t clients = 0;
  std::string pending;
  bool in_session = false;
  const auto follow_clients = [&] {
    if (events < 0) return;
    alignas(inotify_event) char buf[4096];
    for (;;) {
      const ssize_t n = ::read(events, buf, sizeof buf);
      if (n <= 0) return;
      for (ssize_t at = 0; at < n;) {
        const auto* e = reinterpret_cast<const inotify_event*>(buf + at);
        if ((e->mask & IN_OPEN) != 0 && clients++ == 0) in_session = false; // a new client
        if ((e->mask & (IN_CLOSE_WRITE | IN_CLOSE_NOWRITE)) != 0 && --clients <= 0) {
          clients = 0;
          in_session = false;
        }
        at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
      }
    }
  };
  while (!(stop != nullptr && stop->load()) && !(stop_on_signal && StopSignals::requested())) {
    bool unit = false;
    try {
      unit = read_unit(port, pending, raw, max_read);
    } catch (const LinkError& e) {
      if (e.kind() == LinkError::Kind::Interrupted) {
        if (stop_on_signal) break;
        continue;
      }
      // No client on the line: the session (if any) is over; wait for the next client.
      in_session = false;
      pending.clear();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    if (!unit) continue;
    follow_clients();
    if (!in_session) {
      new_session();
      in_session = true;
    }
    const EmulatorResponse response = handle(pending);
    pending.clear();
    if (response.delay.count() > 0) std::this_thread::sleep_for(response.delay);
    if (response.hang_up) {
      pty.hang_up();
      break;
    }
    // A client that is gone or not reading: a real robot would not notice either.
    write_reply(port, response.bytes);
  }
}

namespace {

// One TCP client's session: its command lines answered until it goes. True when a hang-up response
// (a disconnect fault) ends the serving, or a stop is asked for.
bool serve_client(SerialPort& port, const std::function<EmulatorResponse(std::string_view)>& handle,
                  const std::function<void()>& new_session, const std::function<bool()>& stopped,
                  bool stop_on_signal, bool raw, std::size_t max_read) {
  std::string pending;
  bool in_session = false;
  while (!stopped()) {
    bool unit = false;
    try {
      unit = read_unit(port, pending, raw, max_read);
    } catch (const LinkError& e) {
      if (e.kind() == LinkError::Kind::Interrupted) {
        if (stop_on_signal) return true;
        continue;
      }
      return false; // the client has gone (closed, reset): the session is over
    }
    if (!unit) continue;
    if (!in_session) {
      new_session();
      in_session = true;
    }
    const EmulatorResponse response = handle(pending);
    pending.clear();
    if (response.delay.count() > 0) std::this_thread::sleep_for(response.delay);
    if (response.hang_up) return true;
    if (!write_reply(port, response.bytes)) return false; // the client has gone
    if (response.close_session) return false;
  }
  return true;
}

} // namespace

void serve_tcp(TcpListener& listener,
               const std::function<EmulatorResponse(std::string_view)>& handle,
               const std::function<void()>& new_session, const std::atomic<bool>* stop,
               bool stop_on_signal, bool raw, std::size_t max_read, bool accept_once) {
  const auto stopped = [&] {
    return (stop != nullptr && stop->load()) || (stop_on_signal && StopSignals::requested());
  };
  while (!stopped()) {
    std::optional<SerialPort> client;
    try {
      client = listener.accept(std::chrono::milliseconds(50));
    } catch (const LinkError& e) {
      if (e.kind() == LinkError::Kind::Interrupted) {
        if (stop_on_signal) break;
        continue;
      }
      throw;
    }
    if (!client) continue;
    if (accept_once) {
      // The Webots relay (emulator.hpp): this client, and no other, ever. The listener stays open
      // with its backlog of 1 and is never accepted from again, so a second client connects and is
      // never served, now or after this one has gone.
      const bool end =
          serve_client(*client, handle, new_session, stopped, stop_on_signal, raw, max_read);
      client->close();
      while (!end && !stopped()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
      break;
    }
    // One client at a time: connects are refused while this one is served (serial.hpp).
    listener.pause();
    const bool end =
        serve_client(*client, handle, new_session, stopped, stop_on_signal, raw, max_read);
    // Listening again before the close: a client that sees its connection closed by the server
    // (`exit`) finds the port open for its next session.
    if (!end) listener.resume();
    client->close();
    if (end) break;
  }
}

void FirmwareEmulator::new_session() {
  if (commands_ > 0) reset(); // a new client: the robot back at its start
  ++sessions_;
}

std::uint64_t FirmwareEmulator::serve(Pty& pty, const std::atomic<bool>* stop,
                                      bool stop_on_signal) {
  const std::uint64_t first = commands_;
  // The Webots relay acts on what one read returned (emulator.hpp): bytes, not lines.
  const bool relay = robot().webots_relay;
  serve_pty(
      pty, [this](std::string_view line) { return handle(line); }, [this] { new_session(); }, stop,
      stop_on_signal, relay, relay ? kRelayReadBytes : 0);
  return commands_ - first;
}

std::uint64_t FirmwareEmulator::serve(TcpListener& listener, const std::atomic<bool>* stop,
                                      bool stop_on_signal) {
  const std::uint64_t first = commands_;
  const bool relay = robot().webots_relay;
  serve_tcp(
      listener, [this](std::string_view line) { return handle(line); }, [this] { new_session(); },
      stop, stop_on_signal, relay, relay ? kRelayReadBytes : 0, relay);
  return commands_ - first;
}

} // namespace antkit::devices
