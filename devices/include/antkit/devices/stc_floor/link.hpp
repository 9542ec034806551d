#pragma once
// The marker-floor robot on a serial link: its command set, the codec, the firmware emulator that
// answers it on a pseudo-terminal from the rendered floor (floor.hpp), and the pilot's side of the
// link (a FloorRobot over a SerialPort).
//
// The paper's robot is a Lego robot with a PIC-18 board driven over an XBee link by a PC program;
// the paper does not print its protocol. So the command set is ours, in the line grammar of the
// other robots (PROTOCOLS.md, "Common to all three": an upper-case letter and comma-separated
// decimals, ended by CR; the reply is the letter in lower case, its values, CR LF):
//   V        -> v,<text>               the firmware's name and version
//   F,L      -> f,1 | f,0              drive one sub-cell forward, the LEDs lit for L ms first
//                                      (0 <= L <= 60000); 0: the robot bumped and did not move
//   R,T      -> r                      turn on the spot for |T| ms, counter-clockwise when T > 0
//                                      (-60000 <= T <= 60000)
//   L,S      -> l                      the LEDs on (1) or off (0)
//   C,M      -> c,W,H,N,K CR LF + N bytes
//                                      a frame (M = 0) or a dark frame (M = 1, the room and the
//                                      LEDs dark): W x H RGB pixels, row-major, N = 3 W H bytes
//                                      after the header line, K their CRC-32 (IEEE 802.3)
//   other    -> z,Protocol error
// The paper's camera is a wireless analogue camera read by the PC, not by the robot's board; one
// link for both keeps the emulator and a log to one port (a choice). A real robot that sends
// frames elsewhere implements FloorRobot itself.
//
// The pilot's side sends each command once and reads its reply within the timeout. Unlike the
// sensor reads of the other robots, F and R are never resent: a resent move would move twice. V,
// L and C are resent after a fault (timeout, junk, a wrong letter, a bad frame) up to `tries`
// sends, flushing the input first, as drivers in the field do. Every exchange is kept for the log:
// a frame's reply is logged as its header line (which carries the frame's CRC), not its bytes.
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/serial.hpp>
#include <antkit/devices/stc_floor/floor.hpp>
#include <antkit/devices/stc_floor/pilot.hpp>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace antkit::devices::stc_floor {

inline constexpr std::int32_t kMaxLedMs = 60000, kMaxTurnMs = 60000;
inline constexpr std::int32_t kMaxFrameSide = 4096;

std::string version_command();
std::string forward_command(std::int32_t led_ms);
std::string rotate_command(std::int32_t ms);
std::string leds_command(bool on);
std::string capture_command(bool dark);

struct FrameHeader {
  std::int32_t width = 0, height = 0;
  std::uint32_t bytes = 0, crc = 0;
};

std::uint32_t crc32(std::span<const std::uint8_t> bytes) noexcept; // io::crc32 of the bytes

// Replies, validated completely (letter, arity, ranges, CR LF and nothing after it).
Decoded<bool> decode_forward(std::string_view line); // moved
Decoded<bool> decode_ack(std::string_view line, char letter);
Decoded<FrameHeader> decode_frame_header(std::string_view line); // N = 3 W H, sides 1..4096
// The frame's bytes against its header (size, CRC).
Decoded<Image> decode_frame(const FrameHeader& header, std::string_view bytes);

// The firmware: the rendered floor answering the protocol. Each client session starts afresh (a
// new floor, the robot at its start), as the other emulators do.
class FloorEmulator {
public:
  FloorEmulator(kernel::OccupancyGrid map, stc::SubCell start, int heading, FloorOptions options);
  EmulatorResponse handle(std::string_view line);
  void reset();
  std::uint64_t serve(Pty& pty, const std::atomic<bool>* stop = nullptr,
                      bool stop_on_signal = true);
  [[nodiscard]] const FloorWorld& world() const noexcept { return *world_; }
  [[nodiscard]] std::uint64_t commands() const noexcept { return commands_; }
  [[nodiscard]] std::uint64_t sessions() const noexcept { return sessions_; }

private:
  kernel::OccupancyGrid map_;
  stc::SubCell start_;
  int heading_;
  FloorOptions options_;
  std::unique_ptr<FloorWorld> world_;
  std::uint64_t commands_ = 0, sessions_ = 0;
};

// The pilot's robot over a serial port. Throws LinkError when a command cannot be carried out
// (after its tries, or at once for F and R).
class LinkedRobot : public FloorRobot {
public:
  LinkedRobot(SerialPort port, LinkOptions options = {});
  bool forward(std::int32_t led_ms) override;
  void rotate(std::int32_t ms) override;
  Image capture(bool dark) override;
  // The exchanges since the last call (for the log's step record).
  std::vector<Exchange> take_io();
  // Best effort, never throws: LEDs off. "" when acknowledged, else what failed.
  std::string safe_stop() noexcept;
  [[nodiscard]] const LinkStats& stats() const noexcept { return stats_; }
  [[nodiscard]] const SerialPort& port() const noexcept { return port_; }

private:
  std::string exchange(const std::string& command, std::uint32_t tries,
                       const std::function<bool(const std::string&)>& valid, Image* frame);
  SerialPort port_;
  LinkOptions options_;
  LinkStats stats_;
  std::vector<Exchange> io_;
};

} // namespace antkit::devices::stc_floor
