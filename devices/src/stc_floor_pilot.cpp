// The program that drives the marker-floor robot (stc_floor/pilot.hpp).
#include <antkit/devices/run_hash.hpp>
#include <antkit/devices/stc_floor/floor.hpp>
#include <antkit/devices/stc_floor/pilot.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/int_ops.hpp>
#include <array>
#include <bit>
#include <set>

namespace antkit::devices::stc_floor {

void check_controller(stc::Variant v, const std::string& where) {
  if (v != stc::Variant::Ant && v != stc::Variant::AntEdge)
    throw kernel::InputError(where, "the marker-floor robot runs the ant-like controllers: "
                                    "expected ant or ant-edge");
}

FloorController::FloorController(stc::Variant v, int start_quadrant)
    : variant_(v), ant_(start_quadrant), edge_(start_quadrant) {
  check_controller(v, "controller");
}

std::vector<std::int64_t> FloorController::observation(const stc::EdgeObservation& e) const {
  if (variant_ == stc::Variant::AntEdge)
    return {e.free_neighbours, e.here,         e.neighbour[0],
            e.neighbour[1],    e.neighbour[2], e.neighbour[3]};
  return {e.free_neighbours,
          stc::covered_from_edges(e.here),
          stc::covered_from_edges(e.neighbour[0]),
          stc::covered_from_edges(e.neighbour[1]),
          stc::covered_from_edges(e.neighbour[2]),
          stc::covered_from_edges(e.neighbour[3])};
}

void FloorController::step(std::span<const std::int64_t> obs, std::vector<std::int64_t>& cmd) {
  if (obs.size() != 6)
    throw kernel::InputError("obs", "expected 6 values (free neighbours, here, E, N, W, S)");
  const std::int64_t limit = variant_ == stc::Variant::AntEdge ? 0xFFF : 0xF;
  for (std::size_t i = 0; i < 6; ++i)
    if (obs[i] < 0 || obs[i] > (i == 0 ? 0xF : limit))
      throw kernel::InputError("obs", "value " + std::to_string(i) + " out of range");
  stc::Command c;
  if (variant_ == stc::Variant::AntEdge) {
    stc::EdgeObservation o;
    o.free_neighbours = static_cast<std::uint8_t>(obs[0]);
    o.here = static_cast<std::uint16_t>(obs[1]);
    for (std::size_t d = 0; d < 4; ++d) o.neighbour[d] = static_cast<std::uint16_t>(obs[2 + d]);
    c = edge_.step(o);
  } else {
    stc::MarkObservation o;
    o.free_neighbours = static_cast<std::uint8_t>(obs[0]);
    o.here = static_cast<std::uint8_t>(obs[1]);
    for (std::size_t d = 0; d < 4; ++d) o.neighbour[d] = static_cast<std::uint8_t>(obs[2 + d]);
    c = ant_.step(o);
  }
  cmd.assign({static_cast<std::int64_t>(c.move), c.mark ? 1 : 0});
}

std::uint64_t FloorController::state_hash() const noexcept {
  kernel::TraceHash h;
  if (variant_ == stc::Variant::AntEdge) {
    const auto bytes = std::bit_cast<std::array<std::uint8_t, sizeof(stc::AntEdgeStc)>>(edge_);
    h.add_bytes(bytes);
  } else {
    const auto bytes = std::bit_cast<std::array<std::uint8_t, sizeof(stc::AntStc)>>(ant_);
    h.add_bytes(bytes);
  }
  return h.finish();
}

std::uint64_t frame_digest(const Image& frame) noexcept {
  kernel::TraceHash h;
  h.add_i32(frame.width).add_i32(frame.height).add_i32(frame.channels).add_bytes(frame.pixels);
  return h.finish();
}

PathCounts path_counts(std::span<const stc::SubCell> path) {
  PathCounts c;
  std::set<std::pair<std::int32_t, std::int32_t>> seen;
  for (const auto& p : path) {
    if (seen.insert({p.x, p.y}).second)
      ++c.covered;
    else
      ++c.repeats;
  }
  return c;
}

bool SimulatedRobot::forward(std::int32_t led_ms) {
  return world_.forward(led_ms);
}
void SimulatedRobot::rotate(std::int32_t ms) {
  world_.rotate(ms);
}
Image SimulatedRobot::capture(bool dark) {
  return world_.capture(dark);
}

Pilot::Pilot(FloorRobot& robot, const View& view, const PilotOptions& options)
    : robot_(robot), view_(view), o_(options),
      controller_(options.controller, stc::quadrant_of(options.start)), path_{options.start},
      pos_(options.start), h_(options.heading & 3), T_(options.quarter_turn_ms),
      dark_(robot.capture(true)) {}

// One quarter turn (sign +1 left, -1 right) with the paper's calibration; `before` is the
// unwarped marks image before it and becomes the one after it.
void Pilot::quarter_turn(int sign, Image& before, PilotStep& s) {
  const std::int64_t quarter = kernel::Angle::kQuarterTurn;
  const std::int32_t pps = view_.calibration().pixels_per_subcell;
  robot_.rotate(static_cast<std::int32_t>(sign * T_));
  ++s.turns;
  Image after = view_.marks_image(robot_.capture(false), dark_);
  for (std::int32_t k = 0; k <= o_.max_corrections; ++k) {
    const auto dev = measure_turn(before, after, sign, view_.params(), pps);
    if (!dev) break;
    if (k == 0) ++measured_;
    if ((*dev >= 0 ? *dev : -*dev) <= o_.tolerance || k == o_.max_corrections) break;
    if (k == 0) // T from the full quarter turn only: it turned quarter - sign * dev
      T_ = calibrate_rotation(T_, quarter - sign * *dev, o_.max_change_ppm);
    const auto ms = static_cast<std::int32_t>(
        (static_cast<kernel::int128>(*dev) * T_ + (*dev >= 0 ? quarter / 2 : -quarter / 2)) /
        quarter);
    if (ms == 0) break;
    robot_.rotate(ms);
    ++s.corrections;
    ++corrections_;
    after = view_.marks_image(robot_.capture(false), dark_);
  }
  before = std::move(after);
}

PilotStep Pilot::step() {
  PilotStep s;
  s.step = steps_;
  const Image frame = robot_.capture(false);
  s.frame = frame_digest(frame);
  Seen seen = view_.see(frame, dark_, stc::quadrant_of(pos_), h_);
  s.obs = controller_.observation(seen.edges);
  controller_.step(s.obs, s.cmd);
  s.state = controller_.state_hash();
  const auto move = static_cast<stc::Move>(s.cmd[0]);
  if (move != stc::Move::Stop) {
    const int d = static_cast<int>(move);
    const int turn = (d - h_) & 3;
    if (turn != 0) {
      Image before = std::move(seen.marks);
      if (turn == 3) {
        quarter_turn(-1, before, s);
      } else {
        for (int t = 0; t < turn; ++t) quarter_turn(+1, before, s);
      }
      h_ = d;
    }
    s.moved = robot_.forward(s.cmd[1] != 0 ? o_.led_ms : 0);
    if (s.moved) {
      pos_ = stc::step(pos_, d);
      path_.push_back(pos_);
    }
  }
  s.position = pos_;
  s.heading = h_;
  s.turn_ms = T_;
  run_.add(s.step, s.obs, s.cmd, s.state);
  ++steps_;
  if (move == stc::Move::Stop)
    closed_ = true;
  else if (!s.moved)
    refused_ = true;
  return s;
}

PilotResult Pilot::result() const {
  PilotResult r;
  r.path = path_;
  r.steps = steps_;
  r.closed = closed_;
  r.refused = refused_;
  const PathCounts counts = path_counts(path_);
  r.covered = counts.covered;
  r.repeats = counts.repeats;
  r.turn_ms = T_;
  r.measured = measured_;
  r.corrections = corrections_;
  r.hash = run_.value();
  return r;
}

PilotResult run_pilot(FloorRobot& robot, const View& view, const PilotOptions& o,
                      const std::function<void(const PilotStep&)>& on_step) {
  check_controller(o.controller, "controller");
  Pilot pilot(robot, view, o);
  for (std::int64_t step = 0; step < o.max_steps && !pilot.ended(); ++step) {
    const PilotStep s = pilot.step();
    if (on_step) on_step(s);
  }
  return pilot.result();
}

} // namespace antkit::devices::stc_floor
