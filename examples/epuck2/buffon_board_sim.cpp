// buffon_board.h on a computer: antkit's host world (buffon::World: the arena's walls, the IR
// model with its noise, the wheels' kinematics) and pheromone raster stand in for the e-puck2's
// IR sensors, wheels and trail, so that the unchanged loop of buffon_loop.c runs on a desk and its
// trial can be compared with `antkit buffon --trials 1`'s (check_buffon_sim.sh does, under ctest).
// This file is the test's harness, in C++ because it borrows the host's world; the loop it drives
// is the C99 a firmware copies.
//
//   epuck2_buffon_sim ARENA STEPS SEED [NOISE]
//                                        prints {"bc": ..., "blocked": ..., "length1_raw": ...,
//                                        "length2_raw": ..., "loop_hash1": ..., "loop_hash2": ...}
//
// for trial 0: the visits start where `antkit buffon` starts them (World::start_pose on the
// visit's start stream), the IR noise is the visit's noise stream, visit 1 lays the trail at its
// start and after every step, and a step's length is its exact floor root as the host measures it.
// The body (but for the IR noise amplitude NOISE, default 0) and the trail width are
// `antkit buffon`'s defaults. Exit status 2 for bad arguments.
#include "buffon_board.h"
#include "buffon_loop.h"

#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/step_root.hpp>
#include <antkit/buffon/visit.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <optional>

namespace {

namespace buffon = antkit::buffon;
using antkit::kernel::Fx;

struct Board {
  const buffon::World* world = nullptr;
  buffon::PheromoneRaster* raster = nullptr;
  buffon::Pose pose{};
  std::optional<antkit::kernel::Stream> noise;
  bool laid_start = false;
  std::int64_t length_raw = 0;
  std::uint64_t blocked = 0;
};
Board g_board;

} // namespace

extern "C" void buffon_board_read_ir(antkit_ir_reading* reading) {
  const buffon::Observation obs = g_board.world->sense(g_board.pose, &*g_board.noise);
  for (int k = 0; k < 6; ++k) reading->ir[k] = obs.ir[static_cast<std::size_t>(k)].raw();
}

extern "C" int buffon_board_read_trail(void) {
  return g_board.raster->at(g_board.pose.position) ? 1 : 0;
}

extern "C" void buffon_board_step(antkit_wheel_command wheels, int lay_trail) {
  if (lay_trail && !g_board.laid_start) {
    g_board.raster->lay(g_board.pose.position); // the marker is down from the start
    g_board.laid_start = true;
  }
  const buffon::Command cmd{Fx::from_raw(wheels.left), Fx::from_raw(wheels.right)};
  const antkit::kernel::FxPoint before = g_board.pose.position;
  if (!g_board.world->move(g_board.pose, cmd)) ++g_board.blocked;
  const std::int64_t dx = std::int64_t{g_board.pose.position.x.raw()} - before.x.raw();
  const std::int64_t dy = std::int64_t{g_board.pose.position.y.raw()} - before.y.raw();
  g_board.length_raw += static_cast<std::int64_t>(
      buffon::isqrt_proved(static_cast<std::uint64_t>(dx * dx + dy * dy)));
  if (lay_trail) g_board.raster->lay(g_board.pose.position);
}

extern "C" void buffon_board_stop(void) {}

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::fprintf(stderr,
                 "epuck2_buffon_sim: error: usage: epuck2_buffon_sim ARENA STEPS SEED [NOISE]\n");
    return 2;
  }
  try {
    char* end = nullptr;
    const long long steps = std::strtoll(argv[2], &end, 10);
    if (*end != '\0' || steps < 1 || steps > 10000000)
      throw antkit::kernel::InputError("STEPS", "expected steps per visit in [1, 10000000]");
    const unsigned long long seed = std::strtoull(argv[3], &end, 10);
    if (*end != '\0') throw antkit::kernel::InputError("SEED", "expected an unsigned integer");
    buffon::BodyParams body;
    if (argc == 5) {
      const double noise = std::strtod(argv[4], &end);
      if (*end != '\0' || !(noise >= 0.0 && noise <= 1.0))
        throw antkit::kernel::InputError("NOISE", "expected an amplitude in [0, 1]");
      body.noise = antkit::geometry::fixed_from_double<Fx>(noise, "NOISE");
    }
    const buffon::World world(antkit::geometry::build_arena_spec(argv[1], "ARENA").arena.walls_fx(),
                              body);
    const buffon::TrialParams defaults;
    buffon::PheromoneRaster raster(world.lower(), world.upper(), defaults.width);
    g_board.world = &world;
    g_board.raster = &raster;
    std::int64_t lengths[2] = {0, 0};
    std::uint64_t loop_hashes[2] = {0, 0};
    std::uint32_t bc = 0;
    for (int visit = 1; visit <= 2; ++visit) {
      buffon::VisitStreams streams(seed, buffon::kExperiment, 0, visit);
      g_board.pose = world.start_pose(streams.start);
      g_board.noise.emplace(streams.noise);
      g_board.length_raw = 0;
      buffon_visit_log log;
      buffon_visit(seed, 0, visit, static_cast<std::uint32_t>(steps), &log);
      lengths[visit - 1] = g_board.length_raw;
      loop_hashes[visit - 1] = antkit_trace_hash_finish(&log.hash);
      if (visit == 2) bc = log.crossings;
    }
    std::printf("{\"bc\": %" PRIu32 ", \"blocked\": %" PRIu64 ", \"length1_raw\": %" PRId64
                ", \"length2_raw\": %" PRId64 ", \"loop_hash1\": \"%016" PRIx64
                "\", \"loop_hash2\": \"%016" PRIx64 "\"}\n",
                bc, g_board.blocked, lengths[0], lengths[1], loop_hashes[0], loop_hashes[1]);
  } catch (const antkit::kernel::InputError& e) {
    std::fprintf(stderr, "epuck2_buffon_sim: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
