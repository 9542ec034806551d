// The marker-floor robot on a serial link (stc_floor/link.hpp).
#include <antkit/devices/stc_floor/link.hpp>
#include <antkit/io/crc32.hpp>
#include <antkit/kernel/input_error.hpp>
#include <array>
#include <thread>

namespace antkit::devices::stc_floor {

namespace {

template <class T>
Decoded<T> fail(std::size_t column, std::string message) {
  Decoded<T> d;
  d.error = {column, std::move(message)};
  return d;
}

std::string command(char letter, std::int32_t value) {
  return std::string(1, letter) + "," + std::to_string(value) + "\r";
}

} // namespace

std::string version_command() {
  return "V\r";
}
std::string forward_command(std::int32_t led_ms) {
  if (led_ms < 0 || led_ms > kMaxLedMs)
    throw kernel::InputError("forward", "LED time out of range [0, 60000] ms");
  return command('F', led_ms);
}
std::string rotate_command(std::int32_t ms) {
  if (ms < -kMaxTurnMs || ms > kMaxTurnMs)
    throw kernel::InputError("rotate", "turn time out of range [-60000, 60000] ms");
  return command('R', ms);
}
std::string leds_command(bool on) {
  return command('L', on ? 1 : 0);
}
std::string capture_command(bool dark) {
  return command('C', dark ? 1 : 0);
}

std::uint32_t crc32(std::span<const std::uint8_t> bytes) noexcept {
  return io::crc32({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

Decoded<bool> decode_forward(std::string_view line) {
  const auto f = scan_reply(line, 'f', 1, 1, 0, 1);
  if (!f) return fail<bool>(f.error.column, f.error.message);
  Decoded<bool> d;
  d.value = f.value->values[0] == 1;
  return d;
}

Decoded<bool> decode_ack(std::string_view line, char letter) {
  const auto f = scan_reply(line, letter, 0, 0, 0, 0);
  if (!f) return fail<bool>(f.error.column, f.error.message);
  Decoded<bool> d;
  d.value = true;
  return d;
}

Decoded<FrameHeader> decode_frame_header(std::string_view line) {
  // The CRC is a 32-bit unsigned value: scan it apart from the three sizes.
  const std::size_t comma = line.rfind(',');
  if (comma == std::string_view::npos || comma == 0)
    return fail<FrameHeader>(1, "expected c,W,H,N,K");
  const auto f = scan_reply(std::string(line.substr(0, comma)) + "\r\n", 'c', 3, 3, 1,
                            3 * kMaxFrameSide * kMaxFrameSide);
  if (!f) return fail<FrameHeader>(f.error.column, f.error.message);
  std::uint64_t crc = 0;
  std::size_t i = comma + 1, digits = 0;
  while (i < line.size() && line[i] >= '0' && line[i] <= '9' && digits < 11) {
    crc = crc * 10 + static_cast<std::uint64_t>(line[i++] - '0');
    ++digits;
  }
  if (digits == 0 || crc > 0xFFFFFFFFu)
    return fail<FrameHeader>(comma + 2, "expected the frame's CRC-32 as a decimal");
  if (i + 2 != line.size() || line[i] != '\r' || line[i + 1] != '\n')
    return fail<FrameHeader>(i + 1, "expected CR LF at the end of the reply");
  FrameHeader h{f.value->values[0], f.value->values[1],
                static_cast<std::uint32_t>(f.value->values[2]), static_cast<std::uint32_t>(crc)};
  if (h.width > kMaxFrameSide || h.height > kMaxFrameSide)
    return fail<FrameHeader>(3, "a frame side above 4096 pixels");
  if (std::int64_t{h.bytes} != 3 * std::int64_t{h.width} * h.height)
    return fail<FrameHeader>(3, "N must be 3 W H (RGB bytes)");
  Decoded<FrameHeader> d;
  d.value = h;
  return d;
}

Decoded<Image> decode_frame(const FrameHeader& h, std::string_view bytes) {
  if (bytes.size() != h.bytes)
    return fail<Image>(1, "the frame has " + std::to_string(bytes.size()) + " bytes, not " +
                              std::to_string(h.bytes));
  const auto* p = reinterpret_cast<const std::uint8_t*>(bytes.data());
  if (crc32({p, bytes.size()}) != h.crc) return fail<Image>(1, "the frame's CRC-32 differs");
  Decoded<Image> d;
  d.value = Image(h.width, h.height, 3);
  std::copy(p, p + bytes.size(), d.value->pixels.begin());
  return d;
}

// ---- the firmware ----

FloorEmulator::FloorEmulator(kernel::OccupancyGrid map, stc::SubCell start, int heading,
                             FloorOptions options)
    : map_(std::move(map)), start_(start), heading_(heading), options_(options),
      world_(std::make_unique<FloorWorld>(map_, start_, heading_, options_)) {}

void FloorEmulator::reset() {
  world_ = std::make_unique<FloorWorld>(map_, start_, heading_, options_);
}

EmulatorResponse FloorEmulator::handle(std::string_view line) {
  ++commands_;
  EmulatorResponse r;
  const auto c = scan_command(line, false);
  const Fields* f = c ? &*c.value : nullptr;
  auto arity = [&](char letter, std::uint8_t n) {
    return f != nullptr && f->letter == letter && f->count == n;
  };
  if (arity('V', 0)) {
    r.bytes = "v,antkit stc-floor emulator 1\r\n";
  } else if (arity('F', 1) && f->values[0] >= 0 && f->values[0] <= kMaxLedMs) {
    r.bytes = world_->forward(f->values[0]) ? "f,1\r\n" : "f,0\r\n";
  } else if (arity('R', 1) && f->values[0] >= -kMaxTurnMs && f->values[0] <= kMaxTurnMs) {
    world_->rotate(f->values[0]);
    r.bytes = "r\r\n";
  } else if (arity('L', 1) && (f->values[0] == 0 || f->values[0] == 1)) {
    world_->leds(f->values[0] == 1);
    r.bytes = "l\r\n";
  } else if (arity('C', 1) && (f->values[0] == 0 || f->values[0] == 1)) {
    const Image img = world_->capture(f->values[0] == 1);
    r.bytes = "c," + std::to_string(img.width) + "," + std::to_string(img.height) + "," +
              std::to_string(img.pixels.size()) + "," + std::to_string(crc32(img.pixels)) + "\r\n";
    r.bytes.append(img.pixels.begin(), img.pixels.end());
  } else {
    r.bytes = "z,Protocol error\r\n";
  }
  return r;
}

std::uint64_t FloorEmulator::serve(Pty& pty, const std::atomic<bool>* stop, bool stop_on_signal) {
  const std::uint64_t first = commands_;
  serve_pty(
      pty, [this](std::string_view line) { return handle(line); },
      [this] {
        if (commands_ > 0) reset();
        ++sessions_;
      },
      stop, stop_on_signal);
  return commands_ - first;
}

// ---- the pilot's side ----

LinkedRobot::LinkedRobot(SerialPort port, LinkOptions options)
    : port_(std::move(port)), options_(options) {}

std::string LinkedRobot::exchange(const std::string& cmd, std::uint32_t tries,
                                  const std::function<bool(const std::string&)>& valid,
                                  Image* frame) {
  std::string why;
  auto backoff = options_.backoff;
  for (std::uint32_t attempt = 1; attempt <= tries; ++attempt) {
    if (attempt > 1) {
      ++stats_.retries;
      std::this_thread::sleep_for(backoff);
      backoff = std::min(backoff * 2, std::max(options_.backoff, options_.backoff_max));
    }
    // Whatever waits now came before this send (the straggling bytes of a frame that timed out, a
    // late reply): it cannot be this command's reply. Dropped before every send, not only before a
    // resend, so that it is never read as the answer to a move, which is not resent.
    port_.flush_input();
    ++stats_.exchanges;
    port_.write_all(cmd, options_.timeout);
    const ReadResult line = port_.read_line(options_.timeout);
    io_.push_back({cmd, line.bytes});
    if (line.overflow) {
      ++stats_.overflows;
      why = "an over-long reply";
      continue;
    }
    if (!line.complete) {
      ++stats_.timeouts;
      why = line.bytes.empty() ? "no reply" : "a partial reply";
      continue;
    }
    if (!valid(line.bytes)) {
      ++stats_.bad_replies;
      why = "an invalid reply";
      continue;
    }
    if (frame == nullptr) return line.bytes;
    const auto h = decode_frame_header(line.bytes);
    // The frame's bytes: at least 10 kB/s (a choice: above any serial link a camera would use).
    const auto wait = options_.timeout + std::chrono::milliseconds(h.value->bytes / 10000);
    const std::string bytes = port_.read_bytes(h.value->bytes, wait);
    auto img = decode_frame(*h.value, bytes);
    if (!img) {
      ++stats_.bad_replies;
      why = "a bad frame: " + img.error.message;
      continue;
    }
    *frame = std::move(*img.value);
    return line.bytes;
  }
  throw LinkError(LinkError::Kind::Timeout, port_.name() + ": '" + cmd.substr(0, cmd.size() - 1) +
                                                "' failed after " + std::to_string(tries) +
                                                (tries == 1 ? " send" : " sends") + ": " + why);
}

bool LinkedRobot::forward(std::int32_t led_ms) {
  const std::string line = exchange(
      forward_command(led_ms), 1, [](const std::string& l) { return bool(decode_forward(l)); },
      nullptr);
  return *decode_forward(line).value;
}

void LinkedRobot::rotate(std::int32_t ms) {
  exchange(
      rotate_command(ms), 1, [](const std::string& l) { return bool(decode_ack(l, 'r')); },
      nullptr);
}

Image LinkedRobot::capture(bool dark) {
  Image img;
  exchange(
      capture_command(dark), options_.tries,
      [](const std::string& l) { return bool(decode_frame_header(l)); }, &img);
  return img;
}

std::vector<Exchange> LinkedRobot::take_io() {
  return std::exchange(io_, {});
}

std::string LinkedRobot::safe_stop() noexcept {
  try {
    // LEDs off is idempotent: resent like the other commands that may be, within `tries`.
    exchange(
        leds_command(false), options_.tries,
        [](const std::string& l) { return bool(decode_ack(l, 'l')); }, nullptr);
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

} // namespace antkit::devices::stc_floor
