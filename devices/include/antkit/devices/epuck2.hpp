#pragma once
// The e-puck2 in binary mode (advanced sercom, `--device epuck2`): its binary codec, and its
// firmware emulator. Wire facts from ../shared/devices/PROTOCOLS.md, "e-puck (advanced sercom,
// binary mode)" (e-puck2 firmware `src/epuck1x/Asercom2.c`, run_asercom2; GCtronic's EPuckMonitor
// `CommThread.cpp` for the byte order a driver uses):
//  * a request byte is the negated command letter (-'D' = 0xBC); a sequence is requests, each with
//    its fixed number of raw argument bytes, ended by a 0 byte; its reply is the replies of its
//    requests concatenated, with no header, length, terminator or checksum; a sequence of only
//    set requests gets no reply; 16-bit values little-endian.
//  * -'D' 0xBC: 4 argument bytes, left and right int16 LE steps/s, no reply; the motors clamp at
//    +-1100 steps/s (MOTOR_SPEED_LIMIT). -'E' 0xBB: 4 bytes, the speeds as last set. -'N' 0xB2:
//    16 bytes, IR0..IR7 uint16 LE, 0 .. 4095. -'P' 0xB0: 4 argument bytes, no reply. -'Q' 0xAF:
//    4 bytes, the step counters' low 16 bits LE (read as int16).
//  * the firmware has no timeout: a sequence whose 0 never comes keeps it reading requests.
//
// One control step is one round trip (step_sequence): [-'D' l r][-'N'][-'Q'][0], 9 bytes out and
// 20 back. The speeds sent are the previous step's command (the first step's: 0, 0); the wheels
// then turn at them until the next step's sequence, so the proximity read in the same sequence
// sees the robot where the last command took it -- the same order as the ASCII e-puck's N, D, Q
// (the emulators step the body at each proximity read), and the same run.
//
// Choices where the sources are silent (named here; see also device_epuck2.cpp):
//  * Speeds beyond +-1100 are clamped by the codec before they are sent (the firmware would clamp
//    them too, but E would read the unclamped value back).
//  * Reply validation: a reply has exactly the size its sequence asks for; proximity readings are
//    below 4096 (a 12-bit ADC difference, floored at 0: PROTOCOLS.md), which refuses most text
//    (ASCII, the banner) read where binary was expected, since its high bytes are >= 0x20. The
//    counters and speeds can be any int16: only the size checks them.
//  * Resynchronisation: kResyncZeros 0 bytes end any sequence the firmware may still be reading
//    (the longest argument list in the firmware's table is -'w''s 35 bytes: 35 zeros fill it and
//    one more ends the sequence; zeros at the top of the loop are ignored). A sequence left open
//    inside -'D''s arguments runs that -'D' with zero bytes in it before the resend sets the
//    speeds again. An ASCII line left open (only line noise could open one: this driver sends no
//    ASCII) is not resynchronised: it shows as faults until the tries run out.
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/framing.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/serial.hpp>
#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::devices::epuck2 {

inline constexpr char request(char letter) noexcept {
  return static_cast<char>(-static_cast<signed char>(letter));
}
inline constexpr std::int32_t kSpeedLimit = 1100;     // MOTOR_SPEED_LIMIT, motors.h
inline constexpr std::uint32_t kBaud = 115200;        // 8N1, UART3 to the radio module
inline constexpr std::int32_t kProximityLimit = 4096; // readings are below this
inline constexpr std::size_t kResyncZeros = 36;       // -'w''s 35 argument bytes, and a 0
inline constexpr std::size_t kStepReplySize = 20;     // -'N' 16, -'Q' 4
inline constexpr std::size_t kPairReplySize = 4;      // -'Q' or -'E'
// The start-up text (PROTOCOLS.md: a form feed, a bell and two CR LF lines beginning "WELCOME to
// the SerCom protocol on e-Puck"; the second line is the e-puck library's Asercom.c banner's).
inline constexpr std::string_view kBanner = "\f\aWELCOME to the SerCom protocol on e-Puck\r\n"
                                            "the EPFL education robot type \"H\" for help\r\n";

// [-'D' l r][-'N'][-'Q'][0]: speeds clamped to +-kSpeedLimit.
std::string step_sequence(std::int32_t left, std::int32_t right);
// [-'P' 0 0][-'Q'][0]: the counters to zero, read back (the start's baseline).
std::string start_sequence();
// [-'D' 0 0][-'E'][0]: the wheels stopped, their speeds read back (the safe stop).
std::string stop_sequence();
// kResyncZeros zero bytes.
std::string resync_bytes();

// The identification at connect (record_loop.hpp, "First, at connect"; device_epuck2.cpp): binary
// mode has no version request, so the ASCII one, `V` ended by a single CR (PROTOCOLS.md: a CR LF
// would make the firmware take the next binary byte for an ASCII line). Its reply is two lines,
// `v,Version 2.0 January 2018 GCtronic` and `HW version: FFF7`; the e-puck1's first line is
// `v,Version 1.2.2 August 2008 GCtronic`.
inline constexpr std::string_view kVersionRequest = "V\r";
// The rule: a reply line `v,Version N...` with N, the firmware's major version, 2 or more (the
// e-puck2's firmware; the e-puck1's is 1 and its binary mode differs: 16-bit counters, the
// motors' clamp at 1000). Never throws.
bool identifies(std::string_view reply_line) noexcept;
inline constexpr std::string_view kIdentity =
    "v,Version 2... (the e-puck2's advanced sercom; the e-puck1's is 1...)";

struct StepReply {
  Proximity proximity;
  std::int16_t left = 0, right = 0; // the counters' low 16 bits
};
// Exactly kStepReplySize bytes, every reading below kProximityLimit. Never throws.
Decoded<StepReply> decode_step(std::string_view bytes);
// Exactly kPairReplySize bytes: two int16 LE (counters, or speeds). Never throws.
Decoded<WheelPair> decode_pair(std::string_view bytes);

// The size of the reply to a sequence: its requests' reply sizes added up (PROTOCOLS.md's table),
// walking each request's argument bytes, up to the 0 that ends it; unknown bytes add nothing, as
// the firmware skips them. -'I' (the camera image, its size depends on the camera's mode) is not
// framed here (0).
std::size_t reply_size(std::string_view sequence) noexcept;

// The e-puck2's binary framing (framing.hpp), for the link, its replay and the safe stop:
//  * a reply is read as exactly reply_size() bytes (Reading::Bytes); bytes after it are a fault;
//  * it is validated by its requests' parts: every -'N' reading below kProximityLimit (as
//    decode_step; a byte column counts from 1 in the whole reply); the rest by its size only;
//  * after a failed attempt, resync_bytes() (36 zeros) end any sequence the firmware still reads;
//  * the safe stop: no acknowledgement exists in binary mode, so a resynchronisation, then
//    stop_sequence() until the speeds read back 0, 0 (decode_pair);
//  * a request is named "the sequence '...'" in messages.
class SequenceFraming final : public Framing {
public:
  [[nodiscard]] Reading reading() const noexcept override { return Reading::Bytes; }
  // The ASCII version request's reply is lines (kVersionRequest): a `v,` line with printable text
  // and CR LF is its reply, and any other whole line (the start-up banner, the second line of an
  // earlier V) is read past as stale.
  [[nodiscard]] Reading reading_for(std::string_view request) const override {
    return request == kVersionRequest ? Reading::Lines : Reading::Bytes;
  }
  [[nodiscard]] std::size_t reply_size(std::string_view request) const override {
    return epuck2::reply_size(request);
  }
  [[nodiscard]] Verdict classify(std::string_view request, std::string_view unit) const override;
  [[nodiscard]] std::string resync() const override { return resync_bytes(); }
  [[nodiscard]] StopPlan stop_plan() const override;
  [[nodiscard]] Decoded<WheelPair> decode_speeds(std::string_view reply) const override {
    return decode_pair(reply);
  }
  [[nodiscard]] std::string describe(std::string_view request) const override;
};

// The 16-bit counter's continuation: `total` (the running count) moved by the int16 difference
// from its low 16 bits to `low` (steps between two reads stay far below 32768).
std::int64_t unwrap(std::int64_t total, std::int16_t low) noexcept;

// The e-puck2's firmware on one byte stream (Asercom2.c's loop): a byte with bit 7 set starts a
// binary sequence, 1..127 an ASCII line, 0 at the top is ignored; unknown requests are skipped;
// the sequence's reply goes out at its 0; nothing times out. Its body is the e-puck's emulated
// body (FirmwareEmulator, RobotKind::Epuck: the e-puck2's axle and wheel are taken as the
// e-puck1's, PROTOCOLS.md), stepped at each proximity read, binary or ASCII. The motors clamp at
// +-1100 steps/s; the body's model (the e-puck's description) runs speeds over 1000 at 1000, a
// limit of the emulator (controllers command at most 1000). -'E' reads back the speeds as set.
// ASCII lines go to the e-puck's ASCII emulator, but V (the e-puck2's two lines) and R (nothing).
// A session starts with the banner (sent in front of the first reply).
//
// Faults (FaultSpec), per binary sequence that has a reply: drop (the reply not sent), cut (its
// first half only), garbage (the banner first, as after a restart), delay, unterminated (the
// sequence's 0 lost on the line: the firmware keeps reading requests), silent=N and
// disconnect=N (counted in sequences and ASCII lines).
// `pace` (EmulatorOptions): each answer waits the ASCII emulator's command latency and its bytes'
// time on a 115 200 baud 8N1 line, as FirmwareEmulator's replies do.
class Emulator {
public:
  Emulator(std::vector<kernel::FxSegment> walls, EmulatorOptions options = {});
  // Bytes from the line in, the firmware's answer out.
  EmulatorResponse feed(std::string_view bytes);
  void reset();
  std::uint64_t serve(Pty& pty, const std::atomic<bool>* stop = nullptr,
                      bool stop_on_signal = true);
  std::uint64_t serve(TcpListener& listener, const std::atomic<bool>* stop = nullptr,
                      bool stop_on_signal = true);
  [[nodiscard]] const FirmwareEmulator& body() const noexcept { return body_; }
  [[nodiscard]] std::uint64_t sequences() const noexcept { return sequences_; }
  [[nodiscard]] std::uint64_t commands() const noexcept { return sequences_ + lines_; }
  [[nodiscard]] std::uint64_t sessions() const noexcept { return sessions_; }
  [[nodiscard]] std::uint64_t faults() const noexcept { return faults_; }

private:
  void new_session();
  void byte(char c, EmulatorResponse& out);
  void end_sequence(EmulatorResponse& out);
  void run_request(char req, std::string_view args);
  void ascii_line(EmulatorResponse& out);
  enum class State : std::uint8_t { Top, Ascii, SkipCrLf, Sequence, Arguments };
  FirmwareEmulator body_;
  EmulatorOptions options_;
  kernel::Stream faults_stream_;
  State state_ = State::Top;
  std::string line_, args_, reply_;
  char request_ = 0;
  std::size_t need_ = 0;
  std::int32_t set_left_ = 0, set_right_ = 0;
  bool banner_ = false, silent_ = false;
  std::uint64_t sequences_ = 0, lines_ = 0, sessions_ = 0, faults_ = 0, session_units_ = 0;
};

} // namespace antkit::devices::epuck2
