// The marker-floor robot as a device (device.hpp), and the replay of its logs
// (stc_floor/record.hpp).
#include "registry.hpp"

#include <algorithm>
#include <antkit/devices/device.hpp>
#include <antkit/devices/stc_floor/record.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/world.hpp>
#include <cstdlib>

namespace antkit::devices::stc_floor {

namespace {

// One logged exchange of the floor robot's link: the command as this build encodes it ("" when
// the bytes are no command of the robot's set), whether its reply is valid, and whether the link
// may resend it (V, L and C; F and R never: a resent move would move twice).
struct FloorExchange {
  std::string again;
  char letter = 0;
  bool valid = false, resendable = true;
};

FloorExchange classify_floor(const Exchange& x) {
  FloorExchange out;
  const auto f = x.sent.empty() || x.sent.back() != '\r'
                     ? Decoded<Fields>{}
                     : scan_command(std::string_view(x.sent).substr(0, x.sent.size() - 1), false);
  if (!f) return out;
  out.letter = f.value->letter;
  if (f.value->count == 0 && f.value->letter == 'V') {
    out.again = version_command();
    out.valid = x.received.size() >= 3 && x.received[0] == 'v' &&
                x.received.substr(x.received.size() - 2) == "\r\n";
  } else if (f.value->count == 1) {
    const std::int32_t v = f.value->values[0];
    try {
      switch (f.value->letter) {
      case 'F':
        out.again = forward_command(v);
        out.valid = bool(decode_forward(x.received));
        out.resendable = false;
        break;
      case 'R':
        out.again = rotate_command(v);
        out.valid = bool(decode_ack(x.received, 'r'));
        out.resendable = false;
        break;
      case 'L':
        if (v == 0 || v == 1) out.again = leds_command(v == 1);
        out.valid = bool(decode_ack(x.received, 'l'));
        break;
      case 'C':
        if (v == 0 || v == 1) out.again = capture_command(v == 1);
        out.valid = bool(decode_frame_header(x.received));
        break;
      default:
        break;
      }
    } catch (const kernel::InputError&) { // a value out of the command's range
      out.again.clear();
    }
  }
  return out;
}

// Every exchange of a floor step as the link makes them (link.hpp): a command of the robot's set,
// encoded as this build encodes it; its reply valid, or else resent at once (V, L and C only: F
// and R are never resent, a resent move would move twice); a frame's valid header may be resent
// too (its bytes, not logged, failed their CRC); the step's last exchange answered.
std::optional<Divergence> check_floor_io(const LogRecord& r) {
  const auto at = [&](std::size_t i, const char* what) {
    return "io[" + std::to_string(i) + "]." + what;
  };
  for (std::size_t i = 0; i < r.io.size(); ++i) {
    const auto& x = r.io[i];
    const auto [again, letter, valid, resendable] = classify_floor(x);
    if (again.empty() || again != x.sent)
      return Divergence{r.step, at(i, "sent"), "'" + printable(x.sent) + "'",
                        again.empty() ? "a command of the floor robot's set"
                                      : "'" + printable(again) + "'"};
    const bool resent = i + 1 < r.io.size() && r.io[i + 1].sent == x.sent;
    const bool frame = letter == 'C';
    if (resent && !resendable)
      return Divergence{r.step, at(i + 1, "sent"), "'" + printable(x.sent) + "' again",
                        "no resend of a move"};
    if (!valid && !resent)
      return Divergence{r.step, at(i, "received"), "'" + printable(x.received) + "'",
                        i + 1 < r.io.size() ? "a valid reply, or a resend of the command next"
                                            : "a valid reply ending the step"};
    if (valid && resent && !frame)
      return Divergence{r.step, at(i + 1, "sent"), "'" + printable(x.sent) + "' again",
                        "no resend after a valid reply"};
  }
  return std::nullopt;
}

// The pilot lights the LEDs for the header's led_ms before a move exactly when the step marks
// (cmd[1]): every F of the step says so.
std::optional<Divergence> check_marking(const LogRecord& r, std::optional<std::int64_t> led_ms,
                                        std::span<const std::int64_t> cmd) {
  if (!led_ms || cmd.size() < 2) return std::nullopt;
  const std::string want = forward_command(static_cast<std::int32_t>(cmd[1] != 0 ? *led_ms : 0));
  for (std::size_t i = 0; i < r.io.size(); ++i)
    if (r.io[i].sent.rfind("F,", 0) == 0 && r.io[i].sent != want)
      return Divergence{r.step, "io[" + std::to_string(i) + "].sent",
                        "'" + printable(r.io[i].sent) + "'", "'" + printable(want) + "'"};
  return std::nullopt;
}

// The stop record against the run (the serial robots' check_stop in replay.cpp, for this robot):
// its reason in stop_reason()'s words; every byte sent a command of the robot's set as this build
// encodes it; the safe stop (LEDs off, resent until acknowledged) at its end, acknowledged exactly
// when the reason does not say it failed; and "the robot bumped" exactly when the last step's
// move was refused. The robot stands still between its moves: a reason saying it may be moving
// is not one this robot's runs write.
std::optional<Divergence> check_floor_stop(const LogStop& stop, bool last_refused) {
  const std::string& reason = stop.reason;
  static constexpr std::string_view kinds[] = {"done", "interrupted by SIG", "link: ", "error: "};
  bool known = false;
  for (const auto k : kinds) known = known || reason.rfind(k, 0) == 0;
  if (!known || reason.find(kRobotMayBeMoving) != std::string::npos)
    return Divergence{stop.step, "stop.reason", "'" + reason + "'",
                      "a reason that starts done, interrupted by SIG..., link: or error:, and "
                      "never says the robot may be moving"};
  const std::string bumped = "error: the robot bumped and did not move";
  if ((reason.rfind(bumped, 0) == 0) != last_refused)
    return Divergence{stop.step, "stop.reason", "'" + reason + "'",
                      last_refused ? "'" + bumped + "': the last step's move was refused"
                                   : "no bump: the last step's move was not refused"};
  if (reason.rfind("link: ", 0) == 0 && stop.io.empty() && stop.step == 0)
    return std::nullopt; // the port failed as it opened: nothing was sent
  for (std::size_t i = 0; i < stop.io.size(); ++i) {
    const auto& x = stop.io[i];
    if (x.sent.empty()) continue;
    const FloorExchange e = classify_floor(x);
    if (e.again.empty() || e.again != x.sent)
      return Divergence{
          stop.step, "stop.io[" + std::to_string(i) + "].sent", "'" + printable(x.sent) + "'",
          e.again.empty() ? "a command of the floor robot's set" : "'" + printable(e.again) + "'"};
  }
  const std::string off = leds_command(false);
  if (stop.io.empty() || stop.io.back().sent != off)
    return Divergence{stop.step, "stop.io", "no safe stop at the end",
                      "the safe stop's '" + printable(off) + "' last"};
  const bool acknowledged = classify_floor(stop.io.back()).valid;
  const bool claims_failed = reason.find("; safe stop: ") != std::string::npos;
  if (acknowledged == claims_failed)
    return Divergence{stop.step, "stop.reason", "'" + reason + "'",
                      acknowledged
                          ? "the safe stop acknowledged"
                          : "'; safe stop: ...': '" + printable(off) + "' was never acknowledged"};
  return std::nullopt;
}

constexpr std::int64_t kFloorStepsWithoutMap = 20000; // record's default bound without --map

// The pilot's options from the controller's name and params (record.hpp).
PilotOptions pilot_options(const ControllerSpec& spec) {
  PilotOptions p;
  const auto variant = stc::parse_variant(spec.name);
  if (!variant || (*variant != stc::Variant::Ant && *variant != stc::Variant::AntEdge))
    throw kernel::InputError("controller",
                             "the stc-floor robot runs ant or ant-edge, not '" + spec.name + "'");
  p.controller = *variant;
  std::vector<std::string> seen;
  for (const auto& param : spec.params) {
    // Not structured bindings: clang 14 cannot capture those in the lambda below.
    const std::string& key = param.first;
    const std::int64_t value = param.second;
    if (std::find(seen.begin(), seen.end(), key) != seen.end())
      throw kernel::InputError("controller parameter", "'" + key + "' given twice");
    seen.push_back(key);
    const auto in = [&](std::int64_t lo, std::int64_t hi, const char* what) {
      if (value < lo || value > hi) throw kernel::InputError("controller parameter " + key, what);
      return static_cast<std::int32_t>(value);
    };
    if (key == "heading")
      p.heading = in(0, 3, "expected 0 (E), 1 (N), 2 (W) or 3 (S)");
    else if (key == "quarter_turn_ms")
      p.quarter_turn_ms = in(1, kMaxTurnMs, "expected 1 to 60000 ms");
    else if (key == "led_ms")
      p.led_ms = in(0, kMaxLedMs, "expected 0 to 60000 ms");
    else
      throw kernel::InputError("controller parameter",
                               "the stc-floor robot takes heading, quarter_turn_ms "
                               "and led_ms, not '" +
                                   key + "'");
  }
  return p;
}

// The marker-floor robot's session: the pilot (pilot.hpp) over the link (link.hpp). Its record:
// obs and cmd as pilot.hpp writes them; odo the believed x, y (map sub-cells) and heading after
// the step, and T (ms); state the controller's state hash.
class FloorSession final : public Session {
public:
  FloorSession(SerialPort port, const LinkOptions& link, PilotOptions pilot, Calibration c,
               std::shared_ptr<const MapPlace> map)
      : robot_(std::move(port), link), view_(c, default_view(c)), options_(pilot),
        map_(std::move(map)) {}

  void start(std::vector<Exchange>& io) override {
    const TakeIo take{robot_, io};
    pilot_.emplace(robot_, view_, options_); // takes the dark frame
  }

  bool step(LogRecord& rec, std::vector<Exchange>& io) override {
    const TakeIo take{robot_, io};
    const PilotStep s = pilot_->step();
    rec.obs = s.obs;
    rec.cmd = s.cmd;
    rec.odo = {s.position.x, s.position.y, s.heading, s.turn_ms};
    rec.state = s.state;
    return !pilot_->ended();
  }

  // The marker-floor robot moves in discrete F and R commands, each run to its end by the robot:
  // between commands it stands still, so its safe stop (LEDs off) does not decide whether it is
  // stopped.
  SafeStopResult safe_stop(std::vector<Exchange>& io) noexcept override {
    SafeStopResult r;
    try {
      const TakeIo take{robot_, io};
      r.failure = robot_.safe_stop();
    } catch (...) {
      r.failure = "the safe stop's exchanges could not be kept";
    }
    r.stopped = true;
    r.acknowledged = r.complete = r.failure.empty();
    return r;
  }

  [[nodiscard]] LinkStats stats() const override { return robot_.stats(); }
  [[nodiscard]] std::string failure() const override {
    return pilot_ && pilot_->refused() ? "the robot bumped and did not move" : "";
  }

  [[nodiscard]] std::shared_ptr<const DeviceReport> report() const override {
    auto tour = std::make_shared<Tour>();
    Tour& t = *tour;
    t.start = options_.start;
    t.path = pilot_ ? pilot_->path() : std::vector<stc::SubCell>{options_.start};
    t.closed = pilot_ && pilot_->closed();
    const auto first = t.path.front(), last = t.path.back();
    t.returned_to_start = t.closed && std::abs(last.x - first.x) + std::abs(last.y - first.y) <= 1;
    const PathCounts counts = path_counts(t.path);
    t.covered = counts.covered;
    t.repeats = counts.repeats;
    t.turn_ms = pilot_ ? pilot_->turn_ms() : options_.quarter_turn_ms;
    if (map_) {
      t.reachable_subcells = stc::reachable_subcells(map_->cells, t.start, options_.controller);
      t.tour_hash = stc::tour_hash(map_->cells.width(), map_->cells.height(), t.path);
      t.map = map_;
    }
    return tour;
  }

private:
  // Moves the link's exchanges into the step's `io` on every way out of a call.
  struct TakeIo {
    LinkedRobot& robot;
    std::vector<Exchange>& io;
    ~TakeIo() {
      auto taken = robot.take_io();
      io.insert(io.end(), std::make_move_iterator(taken.begin()),
                std::make_move_iterator(taken.end()));
    }
  };
  LinkedRobot robot_;
  View view_;
  PilotOptions options_;
  std::shared_ptr<const MapPlace> map_;
  std::optional<Pilot> pilot_;
};

class FloorDevice final : public Device {
public:
  [[nodiscard]] std::string_view name() const noexcept override { return "stc-floor"; }
  // A choice: the XBee's link at its usual fast rate.
  [[nodiscard]] LineSettings line() const noexcept override { return {115200, 8, 1, Parity::None}; }

  [[nodiscard]] std::span<const DeclaredOption> options() const noexcept override {
    static constexpr DeclaredOption kOptions[] = {
        // record
        {.name = "map",
         .word = "floor map",
         .use = OptionUse::Record,
         .label = "FILE",
         .what = "the floor's map (MovingAI, ROS, ASCII): the start, reachable_subcells and the "
                 "tour hash"},
        {.name = "start",
         .word = "start sub-cell",
         .use = OptionUse::Record,
         .type = OptionType::SubCell,
         .what = "the start sub-cell X,Y (default: the map's, else as antkit stc; without --map "
                 "it must be given)"},
        {.name = "calibration",
         .word = "camera calibration",
         .use = OptionUse::Record,
         .default_note = "the ideal calibration",
         .label = "F.json",
         .what = "the camera's calibration file (antkit stc-floor-calibrate)"},
        // The controller's parameters by flags of their own (--param KEY=VALUE gives them too:
        // their defaults are the controller's).
        {.name = "heading",
         .word = "start heading",
         .use = OptionUse::Record,
         .type = OptionType::Integer,
         .min = 0,
         .max = 3,
         .default_note = "1",
         .label = "D",
         .what = "the heading at the start, 0 E 1 N 2 W 3 S (--param heading)"},
        {.name = "turn-ms",
         .word = "quarter-turn time",
         .use = OptionUse::Record,
         .type = OptionType::Integer,
         .min = 1,
         .max = kMaxTurnMs,
         .default_note = "1500",
         .label = "T",
         .what = "the first time T of a quarter turn, in ms (--param quarter_turn_ms)"},
        {.name = "led-ms",
         .word = "LED time",
         .use = OptionUse::Record,
         .type = OptionType::Integer,
         .min = 0,
         .max = kMaxLedMs,
         .default_note = "2000",
         .label = "L",
         .what = "LED time before each forward move, in ms (--param led_ms)"},
        // emulate
        {.name = "map",
         .word = "floor map",
         .use = OptionUse::Emulate,
         .label = "FILE",
         .what = "the floor's map (MovingAI, ROS, ASCII); the emulator needs one"},
        {.name = "start",
         .word = "start sub-cell",
         .use = OptionUse::Emulate,
         .type = OptionType::SubCell,
         .what = "the start sub-cell X,Y (default: the map's, else as antkit stc)"},
        {.name = "heading",
         .word = "start heading",
         .use = OptionUse::Emulate,
         .type = OptionType::Integer,
         .min = 0,
         .max = 3,
         .fallback = "1",
         .label = "D",
         .what = "the heading at the start, 0 E 1 N 2 W 3 S"},
        {.name = "noise",
         .word = "camera noise",
         .use = OptionUse::Emulate,
         .type = OptionType::Integer,
         .min = 0,
         .max = 255,
         .fallback = "0",
         .label = "A",
         .what = "camera noise, uniform +-A per channel"},
        {.name = "dark-offset",
         .word = "dark offset",
         .use = OptionUse::Emulate,
         .type = OptionType::Integer,
         .min = 0,
         .max = 255,
         .fallback = "12",
         .label = "A",
         .what = "dark-current pattern, 0..A per pixel"},
        {.name = "fade",
         .word = "fade half-life",
         .use = OptionUse::Emulate,
         .type = OptionType::Integer,
         .min = 0,
         .max = 86400,
         .fallback = "0",
         .label = "S",
         .what = "half-life of the marks' glow in seconds (0: no fading)"},
        {.name = "rotation-error",
         .word = "rotation error",
         .use = OptionUse::Emulate,
         .type = OptionType::Integer,
         .min = -500000,
         .max = 500000,
         .fallback = "0",
         .label = "PPM",
         .what = "turn rate against nominal, ppm"},
        {.name = "drift",
         .word = "drift",
         .use = OptionUse::Emulate,
         .type = OptionType::Integer,
         .min = 0,
         .max = 1000000,
         .fallback = "0",
         .label = "PPM",
         .what = "the turn rate falls by this many ppm a minute (battery)"},
        {.name = "listen",
         .word = "listen address",
         .use = OptionUse::Emulate,
         .refused = "the stc-floor emulator serves a pty (its frames are too large for one reply "
                    "over the Webots relay)"},
    };
    return kOptions;
  }

  [[nodiscard]] PreparedRun prepare_run(const RecordOptions& o) const override {
    // The controller's parameters given by flags of their own join those of --param (one given
    // both ways is refused as given twice).
    ControllerSpec spec = o.controller;
    const DeviceValues& v = o.device_options;
    for (const auto& [flag, param] :
         {std::pair{"heading", "heading"}, std::pair{"turn-ms", "quarter_turn_ms"},
          std::pair{"led-ms", "led_ms"}})
      if (const auto value = v.integer(flag)) spec.params.emplace_back(param, *value);
    PilotOptions pilot = pilot_options(spec);
    std::shared_ptr<const MapPlace> map;
    if (const auto file = v.text("map"))
      map = std::make_shared<const MapPlace>(read_map_place(*file));
    if (const auto given = v.cell("start"))
      pilot.start = *given;
    else if (map && map->start)
      pilot.start = *map->start;
    else if (map) {
      const auto start = stc::default_start(map->cells, pilot.controller);
      if (!start)
        throw kernel::InputError(map->file,
                                 "the map has no free cell (2 x 2 free sub-cells) to start in");
      pilot.start = *start;
    } else {
      throw kernel::InputError("start sub-cell",
                               "without --map the robot's start sub-cell must be given (X,Y)");
    }
    if (pilot.start.x < 0 || pilot.start.y < 0)
      throw kernel::InputError("start sub-cell", "expected a sub-cell X,Y >= 0");
    const auto calibration_file = v.text("calibration");
    const Calibration calibration =
        calibration_file ? read_calibration(*calibration_file) : ideal_calibration();
    PreparedRun run;
    run.header.robot = "stc-floor";
    run.header.controller = std::string(stc::variant_name(pilot.controller));
    run.header.params = {{"start_x", pilot.start.x},
                         {"start_y", pilot.start.y},
                         {"heading", pilot.heading & 3},
                         {"quarter_turn_ms", pilot.quarter_turn_ms},
                         {"led_ms", pilot.led_ms}};
    run.header.seed = 0;
    run.line = o.line ? *o.line : line();
    run.max_line = 512; // a frame's header line
    // A tour that never closes (marks that fade, a camera that misreads) must end: by default a
    // tour of the map's reachable sub-cells may take 8 steps each (a clean one takes about 2: a
    // move and a turn), plus 64; without a map, 20 000 steps (a 70 x 70-cell floor's clean tour
    // twice over). The run then ends as asked, and a tour that did not close is no success.
    run.steps = o.steps ? *o.steps
                : map ? 8 * stc::reachable_subcells(map->cells, pilot.start, pilot.controller) + 64
                      : kFloorStepsWithoutMap;
    run.connect = [pilot, calibration, map](SerialPort port, const LinkOptions& link) {
      return std::make_unique<FloorSession>(std::move(port), link, pilot, calibration, map);
    };
    return run;
  }

  [[nodiscard]] ReplayResult replay(LogReader& reader, const std::string& path,
                                    std::optional<std::int64_t> until) const override {
    return replay_log(reader, path, until);
  }

  [[nodiscard]] EmulateReport
  serve(const EmulateOptions& o,
        const std::function<void(const std::string&)>& ready) const override {
    const DeviceValues& v = o.device_options;
    const auto map_file = v.text("map");
    if (!map_file) throw kernel::InputError("floor map", "stc-floor needs a map (--map FILE)");
    const MapPlace map = read_map_place(*map_file);
    stc::SubCell start{};
    if (const auto given = v.cell("start"))
      start = *given;
    else if (map.start)
      start = *map.start;
    else if (const auto s = stc::default_start(map.cells, stc::Variant::AntEdge))
      start = *s;
    else
      throw kernel::InputError(map.file,
                               "the map has no free cell (2 x 2 free sub-cells) to start in");
    // The declared ranges (options()) hold: each fits its field, and the floor's own ranges
    // (FloorWorld) are the same.
    const auto in = [&v](std::string_view name) {
      return static_cast<std::int32_t>(v.integer(name).value());
    };
    FloorOptions f;
    f.seed = o.seed;
    f.noise = in("noise");
    f.dark_offset = in("dark-offset");
    f.fade_half_life_ms = std::int64_t{in("fade")} * 1000;
    f.rotation_error_ppm = in("rotation-error");
    f.drift_ppm_per_minute = in("drift");
    const int heading = in("heading");
    FloorEmulator emulator(map.cells, start, heading, f);
    Pty pty = Pty::open();
    ready(pty.slave_path());
    emulator.serve(pty);
    const auto& w = emulator.world();
    EmulateReport r;
    r.sessions = emulator.sessions();
    r.commands = emulator.commands();
    auto truth = std::make_shared<FloorTruth>();
    truth->map = *map_file;
    truth->start = start;
    truth->frames = w.frames();
    truth->positions = static_cast<std::int64_t>(w.path().size());
    truth->covered = w.covered();
    truth->repeats = w.repeats();
    truth->reachable_subcells = stc::reachable_subcells(map.cells, start, stc::Variant::AntEdge);
    truth->max_offset_subcells = static_cast<double>(w.max_offset()) / 65536.0;
    truth->max_heading_error_degrees =
        static_cast<double>(w.max_heading_error()) * 360.0 / 4294967296.0;
    truth->clock_s = static_cast<double>(w.clock_ms()) / 1000.0;
    r.device_report = std::move(truth);
    return r;
  }
};

const FloorDevice kFloor;

} // namespace

ReplayResult replay_log(LogReader& reader, const std::string& path,
                        std::optional<std::int64_t> until) {
  const LogHeader& header = reader.header();
  const auto variant = stc::parse_variant(header.controller);
  if (!variant || (*variant != stc::Variant::Ant && *variant != stc::Variant::AntEdge))
    throw kernel::InputError(path, 1, 1,
                             "the stc-floor robot runs controller ant or ant-edge, not '" +
                                 header.controller + "'");
  std::int64_t sx = 0, sy = 0, heading = 1;
  std::optional<std::int64_t> led_ms;
  int seen = 0;
  for (const auto& [k, v] : header.params) {
    if (k == "start_x")
      sx = v, seen |= 1;
    else if (k == "start_y")
      sy = v, seen |= 2;
    else if (k == "heading")
      heading = v, seen |= 4;
    else if (k == "led_ms")
      led_ms = v;
  }
  if (seen != 7 || sx < 0 || sy < 0 || sx > INT32_MAX || sy > INT32_MAX || heading < 0 ||
      heading > 3)
    throw kernel::InputError(path, 1, 1,
                             "the header needs params start_x, start_y (>= 0) and heading (0..3)");
  stc::SubCell pos{static_cast<std::int32_t>(sx), static_cast<std::int32_t>(sy)};
  FloorController controller(*variant, stc::quadrant_of(pos));
  auto h = static_cast<int>(heading);
  bool last_refused = false;
  return replay_records(
      reader, until,
      [&](const LogRecord& r, std::size_t line, std::vector<std::int64_t>& cmd) {
        std::optional<Divergence> d;
        if (auto bad = check_floor_io(r)) return bad;
        std::optional<bool> moved;
        for (std::size_t i = 0; i < r.io.size(); ++i) {
          const auto& x = r.io[i];
          if (!d && x.sent.rfind("C,", 0) == 0 && !x.received.empty() && x.received[0] == 'c' &&
              !decode_frame_header(x.received))
            d = Divergence{r.step, "io[" + std::to_string(i) + "]", "a frame header",
                           "one this build refuses"};
          if (x.sent.rfind("F,", 0) == 0)
            if (const auto f = decode_forward(x.received)) moved = *f.value;
        }
        try {
          controller.step(r.obs, cmd);
        } catch (const kernel::InputError& e) {
          throw kernel::InputError(path, line, 1, e.what());
        }
        if (compare_fields(r.cmd, cmd, r.step, "cmd", d) && controller.state_hash() != r.state &&
            !d)
          d = Divergence{r.step, "state", kernel::hash_hex(r.state),
                         kernel::hash_hex(controller.state_hash())};
        if (!d) d = check_marking(r, led_ms, cmd);
        last_refused = false;
        if (!d && cmd[0] != static_cast<std::int64_t>(stc::Move::Stop)) {
          h = static_cast<int>(cmd[0]);
          if (moved.value_or(false)) pos = stc::step(pos, h);
          last_refused = !moved.value_or(false);
        }
        const std::vector<std::int64_t> odo{pos.x, pos.y, h};
        compare_fields(std::span(r.odo).first(std::min<std::size_t>(r.odo.size(), 3)), odo, r.step,
                       "odo", d);
        return d;
      },
      [&](const LogStop& stop) { return check_floor_stop(stop, last_refused); });
}

} // namespace antkit::devices::stc_floor

namespace antkit::devices::detail {
ANTKIT_DEVICE(60, stc_floor_device) {
  return stc_floor::kFloor;
}
} // namespace antkit::devices::detail
