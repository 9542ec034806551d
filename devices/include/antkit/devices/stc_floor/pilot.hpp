#pragma once
// The program that drives the marker-floor robot (paper 002: "The Robot is wireless-controlled by
// a computer program which runs the STC Algorithm"): frames in, the camera pipeline (view.hpp),
// the ant-like controller, and the moves out, with the paper's rotation calibration. The robot is
// anything that can drive, turn and take a frame (FloorRobot): the simulated floor in process,
// or a robot or emulator over a serial link (link.hpp).
//
// One step:
//   1. take a frame; the pipeline reads the five cells at the believed quadrant q and heading h;
//   2. the controller (stc/ant.hpp: `ant-edge` reads the edge masks, `ant` the sub-cell masks
//      the paper's rule gives from them) decides a move, or stops: the tour is closed;
//   3. turn to the move's direction, a quarter turn at a time (left for +1, right for -1, two
//      lefts to turn about). After each quarter turn a frame is taken and the turn is measured
//      (measure_turn); when it is off by more than the tolerance, T <- 90/d * T (bounded,
//      camera.hpp) and a correcting turn is sent, "to let it complete the 90 degrees rotation it
//      was supposed to perform", up to max_corrections times;
//   4. drive one sub-cell with the LEDs on for led_ms (when the command marks).
// What this cannot do, and the experiments show: a turn is measured against the frame before it,
// so whatever error a turn leaves (within the tolerance, or the measurement's own) stays in the
// heading, and forward moves turn a heading error into a sideways drift. With the rate drifting,
// the turns within the tolerance are all off the same way and add up. (We tried an absolute
// check of the heading against the lit edges' calibrated places: the marks are laid by the same
// drifting robot, so they are off the grid by its past errors, and the check chased them.)
// The controller's state is its own O(1) state; the pilot keeps what a robot's program keeps:
// the believed position (for the path it reports), the heading, and T.
//
// The controller's observation and command as integers (the log's obs and cmd):
//   ant-edge obs: free_neighbours, here, neighbour E, N, W, S (12-bit edge masks)
//   ant      obs: free_neighbours, here, neighbour E, N, W, S (4-bit covered-sub-cell masks)
//   cmd:          move (0 E, 1 N, 2 W, 3 S, 4 stop), mark (0 / 1)
// Its state hash: kernel::TraceHash over the controller object's bytes (two: q and done).
#include <antkit/devices/run_hash.hpp>
#include <antkit/devices/stc_floor/view.hpp>
#include <antkit/stc/ant.hpp>
#include <antkit/stc/subcell.hpp>
#include <antkit/stc/world.hpp>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace antkit::devices::stc_floor {

class FloorRobot {
public:
  virtual ~FloorRobot() = default;
  virtual bool forward(std::int32_t led_ms) = 0; // false: the robot bumped and did not move
  virtual void rotate(std::int32_t ms) = 0;      // counter-clockwise for ms > 0
  [[nodiscard]] virtual Image capture(bool dark) = 0;
};

struct PilotOptions {
  stc::Variant controller = stc::Variant::AntEdge; // AntEdge or Ant
  stc::SubCell start{};                            // map sub-cells (the reported path's origin)
  int heading = 1;                                 // the robot's heading at the start: north
  std::int32_t quarter_turn_ms = 1500;             // the first T
  std::int32_t led_ms = 2000;
  // A turn off by at most this is left as it is ("if the robot has done the rotation accurate
  // enough, no calibration is needed"): 1 degree in binary-angle units, above the measurement's
  // own error on the rendered floor (at most 0.6 degree over the noise-free test runs).
  std::int64_t tolerance = 11930465;
  std::uint32_t max_change_ppm = 250000; // one correction moves T by at most 25 %
  std::int32_t max_corrections = 2;
  std::int64_t max_steps = 100000;
};

struct PilotStep {
  std::int64_t step = 0;
  std::uint64_t frame = 0; // kernel::TraceHash of the step's frame bytes
  std::vector<std::int64_t> obs, cmd;
  std::uint64_t state = 0;
  stc::SubCell position{};  // believed, after the step
  int heading = 0;          // after the step
  std::int64_t turn_ms = 0; // T after the step
  std::int32_t turns = 0, corrections = 0;
  bool moved = false;
};

struct PilotResult {
  std::vector<stc::SubCell> path; // believed, the start first
  std::int64_t steps = 0;
  bool closed = false;                   // the controller stopped
  bool refused = false;                  // the robot bumped
  std::int64_t covered = 0, repeats = 0; // over the believed path
  std::int64_t turn_ms = 0;              // the last T
  std::int64_t measured = 0, corrections = 0;
  std::uint64_t hash = 0; // the run's RunHash (controllers.hpp) over every step
};

// The controller's names for logs: "ant" / "ant-edge". Throws kernel::InputError(where) for
// another variant.
void check_controller(stc::Variant v, const std::string& where);

// A controller as the log sees it (replay rebuilds it from the header).
class FloorController {
public:
  FloorController(stc::Variant v, int start_quadrant);
  // obs as documented above; cmd overwritten. Throws kernel::InputError("obs") for a wrong length.
  void step(std::span<const std::int64_t> obs, std::vector<std::int64_t>& cmd);
  [[nodiscard]] std::uint64_t state_hash() const noexcept;
  // The controller's observation from the pipeline's edges.
  [[nodiscard]] std::vector<std::int64_t> observation(const stc::EdgeObservation& e) const;

private:
  stc::Variant variant_;
  stc::AntStc ant_;
  stc::AntEdgeStc edge_;
};

[[nodiscard]] std::uint64_t frame_digest(const Image& frame) noexcept;

// The distinct sub-cells of a path (covered) and its entries into one entered before (repeats).
struct PathCounts {
  std::int64_t covered = 0, repeats = 0;
};
[[nodiscard]] PathCounts path_counts(std::span<const stc::SubCell> path);

// The pilot one step at a time (what record()'s loop drives, devices/device.hpp): the dark frame
// is taken at construction; step() runs one step as above. The run has ended when the controller
// stopped (closed) or the robot bumped (refused); step() may not be called after that.
class Pilot {
public:
  Pilot(FloorRobot& robot, const View& view, const PilotOptions& options);
  PilotStep step();
  [[nodiscard]] bool ended() const noexcept { return closed_ || refused_; }
  [[nodiscard]] bool closed() const noexcept { return closed_; }
  [[nodiscard]] bool refused() const noexcept { return refused_; }
  [[nodiscard]] const std::vector<stc::SubCell>& path() const noexcept { return path_; }
  [[nodiscard]] std::int64_t turn_ms() const noexcept { return T_; }
  // The run so far as run_pilot() reports it.
  [[nodiscard]] PilotResult result() const;

private:
  void quarter_turn(int sign, Image& before, PilotStep& s);
  FloorRobot& robot_;
  const View& view_;
  PilotOptions o_;
  FloorController controller_;
  std::vector<stc::SubCell> path_;
  stc::SubCell pos_;
  int h_;
  std::int64_t T_;
  Image dark_;
  std::int64_t steps_ = 0, measured_ = 0, corrections_ = 0;
  bool closed_ = false, refused_ = false;
  RunHash run_;
};

// Runs a Pilot until it ends or max_steps ran.
PilotResult run_pilot(FloorRobot& robot, const View& view, const PilotOptions& options,
                      const std::function<void(const PilotStep&)>& on_step = {});

// The simulated floor as a FloorRobot (in process, no link).
class FloorWorld;
class SimulatedRobot : public FloorRobot {
public:
  explicit SimulatedRobot(FloorWorld& world) : world_(world) {}
  bool forward(std::int32_t led_ms) override;
  void rotate(std::int32_t ms) override;
  Image capture(bool dark) override;

private:
  FloorWorld& world_;
};

} // namespace antkit::devices::stc_floor
