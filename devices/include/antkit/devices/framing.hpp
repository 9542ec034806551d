#pragma once
// A robot's wire format as the link sees it (issue 43, "a codec is an interface"). The link
// (link.hpp: RobotLink live, and the replay's link over a log's exchanges), the safe stop and the
// record loop drive any robot through this interface and do not know which framing is behind it:
//   reading()       how the bytes after a send are read off the line: lines (up to LF, kept) or
//                   a run of bytes of the size the request's reply has (reply_size());
//   classify()      what one unit read after a send is: its reply, a late reply to an earlier
//                   request (read on past it), or a fault (why, for the message);
//   resync()        what to send after a failed attempt to bring the robot back to a state where
//                   the resend is understood ("": nothing; the link only drains);
//   stop_plan()     the safe stop its protocol allows, and decode_speeds() for its read-back;
//   describe()      how a request is named in messages (and so in a stop record's reason).
// What a log records of the bytes is the same for every framing: every byte sent and received,
// verbatim, per exchange, with its send's time (log.hpp; binary bytes as \u00XX escapes,
// log_schema.hpp), so a replay re-runs this very classification on them.
//
// The framings:
//   LineFraming              (below) the text robots of paper 000's family (khepera,
//                            khepera-webots, hemisson, epuck): one command line, one reply line
//                            ending CR LF, its letter the command's in lower case (protocol.hpp);
//   epuck2::SequenceFraming  (epuck2.hpp) the e-puck2's binary sercom: a sequence of requests
//                            ended by a 0, a reply of a known size with no terminator.
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/robot.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::devices {

// What a unit read after sending a request is.
enum class ReplyKind : std::uint8_t {
  Reply, // the request's reply, validated by the codec
  Stale, // a well-formed reply to another request: a late answer to an earlier one, skipped
  Bad    // anything else: junk, a wrong value, a reply that does not validate
};

// How the bytes after a send are read.
enum class Reading : std::uint8_t {
  // Lines ending at LF (the terminator kept), within the port's line bound; a reply is one line,
  // and lines after it stay on the line for the next send's drain.
  Lines,
  // Exactly reply_size(request) bytes; a reply has no terminator, so bytes already waiting after
  // it make the attempt a fault (a banner or text in front of it, a late reply).
  Bytes
};

struct Verdict {
  ReplyKind kind = ReplyKind::Bad;
  std::string why; // a Bad unit: what is wrong ("column 3: ...", "byte 5: ..."); may be ""
};

// The safe stop a protocol allows (link.hpp, safe_stop). Where set requests are acknowledged, each
// command is sent until acknowledged (the wheels' first), then the speeds are read back until 0, 0
// (`read_back`, "" when the robot cannot read them), the wheels' command resent between readings.
// Where nothing is acknowledged (`read_back_stops`), the read-back request stops the wheels itself
// and is sent until the speeds read 0, 0: that is the only confirmation there is.
struct StopPlan {
  bool resync_first = false;         // a resynchronisation before anything (resync())
  std::vector<std::string> commands; // each until acknowledged, the wheels' stop first
  std::string read_back;             // sent until the speeds read back 0, 0 ("": none)
  bool read_back_stops = false;      // read_back stops the wheels too (no acknowledgements)
};

class Framing {
public:
  virtual ~Framing() = default;
  [[nodiscard]] virtual Reading reading() const noexcept = 0;
  // How the reply to `request` is read: reading(), but for a request of another framing that the
  // robot also understands (the e-puck2's ASCII version request, V, whose reply is lines).
  [[nodiscard]] virtual Reading reading_for(std::string_view request) const {
    (void)request;
    return reading();
  }
  // Reading::Bytes: the exact size of the reply to `request` (0: it gets none).
  [[nodiscard]] virtual std::size_t reply_size(std::string_view request) const = 0;
  // One unit read after sending `request`: a whole line (Reading::Lines), or reply_size() bytes.
  [[nodiscard]] virtual Verdict classify(std::string_view request, std::string_view unit) const = 0;
  // classify()'s kind alone, and the values the framing's judgement decoded when the unit is the
  // reply (the text robots' codec validates a reply by decoding it: Codec::decode_reply), else
  // `fields` cleared (letter 0). A framing whose classify() builds a reason it can skip overrides
  // it (a replay judges every reply and never reads the reason of one that is not bad), and a
  // replay's link hands the values to the body with the reply, so that it does not decode the
  // same line a second time (CommandLink::reply_fields).
  [[nodiscard]] virtual ReplyKind kind(std::string_view request, std::string_view unit,
                                       Fields& fields) const {
    fields = {};
    return classify(request, unit).kind;
  }
  // Sent after a failed attempt, before the resend ("": nothing).
  [[nodiscard]] virtual std::string resync() const = 0;
  [[nodiscard]] virtual StopPlan stop_plan() const = 0;
  // The speeds in a reply to stop_plan().read_back.
  [[nodiscard]] virtual Decoded<WheelPair> decode_speeds(std::string_view reply) const = 0;
  // A request in messages: 'D,0,0\r' (printable(), quoted).
  [[nodiscard]] virtual std::string describe(std::string_view request) const;
};

// Printable form of wire bytes for messages: \r, \n, \xHH.
std::string printable(std::string_view bytes);

// What a line read after sending `command` is, for the text robots (LineFraming::classify): its
// reply when its letter is the command's in lower case and the codec validates it
// (Codec::decode_reply; its values are left in `*fields` when it is given, else it is cleared);
// a late reply when it is a well-formed reply line of another letter; else bad.
ReplyKind classify_reply(const Codec& codec, std::string_view command, std::string_view line,
                         Fields* fields = nullptr);

// The text robots' framing (protocol.hpp's Codec): reply lines classified by classify_reply; no
// resynchronisation beyond draining; the safe stop: the robot's safe_stop commands until
// acknowledged, then, where it reads its speeds (E), read back until 0, 0.
class LineFraming final : public Framing {
public:
  explicit LineFraming(RobotKind robot) : codec_(robot) {}
  [[nodiscard]] const Codec& codec() const noexcept { return codec_; }
  [[nodiscard]] Reading reading() const noexcept override { return Reading::Lines; }
  [[nodiscard]] std::size_t reply_size(std::string_view) const override { return 0; }
  [[nodiscard]] Verdict classify(std::string_view request, std::string_view unit) const override;
  [[nodiscard]] ReplyKind kind(std::string_view request, std::string_view unit,
                               Fields& fields) const override {
    return classify_reply(codec_, request, unit, &fields);
  }
  [[nodiscard]] std::string resync() const override { return {}; }
  [[nodiscard]] StopPlan stop_plan() const override;
  [[nodiscard]] Decoded<WheelPair> decode_speeds(std::string_view reply) const override {
    return codec_.decode_speed(reply);
  }

private:
  Codec codec_;
};

} // namespace antkit::devices
