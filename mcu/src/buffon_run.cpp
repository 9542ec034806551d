// One Buffon trial on the robot's own processor (issue 27): trial 0 of `antkit buffon --trials 1`,
// from the same sources as the host. The host sends the arena as its Q15.16 walls
// (buffon/mcu_input.hpp); the chip reads them into its arena and runs run_fixed_trial
// (buffon/fixed_trial.hpp: the world's buckets, the behaviour, the pheromone raster, the detector,
// the exact crossing count and run_trial's trace hash) in the rest of it; then the trial again
// with the C API's behaviour, detector and hash deciding ("c_api" in the JSON: c_api_trial), which
// proves antkit_buffon_behaviour_* and antkit_buffon_detector_* on the chip against the host.
#include "buffon_run.hpp"

#include "semihost.hpp"
#include "text.hpp"
#include "ticks.hpp"

#include <antkit/buffon/crossing_counter_core.hpp>
#include <antkit/buffon/fixed_trial.hpp>
#include <antkit/buffon/mcu_digest_input.hpp>
#include <antkit/buffon/mcu_input.hpp>
#include <antkit/buffon/visit.hpp>
#include <antkit/c/antkit.h>

namespace antkit::mcu {

using namespace antkit::buffon;

namespace {

template <class T>
T* at(std::span<std::uint8_t> buffer, std::uint64_t offset) noexcept {
  return reinterpret_cast<T*>(buffer.data() + offset);
}

// One visit with the C API deciding: antkit_buffon_behaviour_* (the behaviour and its state words)
// and antkit_trace_hash_add_u64; the readings, the move and the step's length are visit_step's
// (visit.hpp) and the hash words hash_visit_step's. on_step(position) after the start and every
// step.
template <class OnStep>
[[gnu::noinline]] void c_api_visit(const WorldCore& world, std::uint64_t seed, int v,
                                   std::int64_t steps, Pose pose, antkit_trace_hash& hash,
                                   std::uint64_t& blocked, std::int64_t& length, OnStep on_step) {
  VisitStreams streams(seed, kExperiment, 0, v);
  antkit_buffon_behaviour behaviour;
  antkit_buffon_behaviour_init(&behaviour, seed, kExperiment, 0, static_cast<std::uint64_t>(v));
  on_step(pose.position);
  for (std::int64_t s = 0; s < steps; ++s) {
    const Observation obs = world.sense(pose, &streams.noise);
    antkit_ir_reading reading;
    for (std::size_t i = 0; i < 6; ++i) reading.ir[i] = obs.ir[i].raw();
    const antkit_wheel_command c = antkit_buffon_behaviour_step(&behaviour, &reading);
    const Command cmd{Fx::from_raw(c.left), Fx::from_raw(c.right)};
    const FxPoint before = pose.position;
    if (!world.move(pose, cmd)) ++blocked;
    const std::int64_t dx = std::int64_t{pose.position.x.raw()} - before.x.raw();
    const std::int64_t dy = std::int64_t{pose.position.y.raw()} - before.y.raw();
    const Fx forward = world.body().speed * (cmd.left + cmd.right) * Fx::from_ratio(1, 2);
    length += static_cast<std::int64_t>(
        detail::step_length_raw(static_cast<std::uint64_t>(dx * dx + dy * dy), forward));
    on_step(pose.position);
    std::int32_t r = 0, wl = 0, wr = 0;
    antkit_buffon_behaviour_state(&behaviour, &r, &wl, &wr);
    antkit_trace_hash_add_u64(&hash,
                              detail::hash_word(pose.position.x.raw(), pose.position.y.raw()));
    antkit_trace_hash_add_u64(&hash,
                              detail::hash_word(static_cast<std::int32_t>(pose.heading.raw()), r));
    antkit_trace_hash_add_u64(&hash, detail::hash_word(wl, wr));
  }
}

// The trial again with the C API's behaviour, detector and hash (antkit/c/antkit.h: the calls a C
// firmware makes) over the same cores and buffer layout as run_fixed_trial (fixed_trial.hpp), so
// that its result must be run_fixed_trial's and `antkit buffon --trials 1`'s. Null or why not.
const char* c_api_trial(std::span<const FxSegment> walls, const McuBuffonRun& run,
                        std::span<std::uint8_t> buffer, FixedTrialResult& result) {
  WorldLayout layout;
  if (WorldCore::plan(walls, run.body, layout) != WorldError::None) return "the world";
  RasterCore raster;
  if (raster.init(layout.lower, layout.upper, run.width) != RasterError::None) return "the raster";
  const FixedTrialPlan plan = plan_fixed_trial(layout, raster, run.steps);
  if (plan.total > buffer.size()) return "the plan";
  WorldCore world;
  world.build(
      walls, run.body, layout,
      {at<std::uint32_t>(buffer, plan.start_at), static_cast<std::size_t>(layout.buckets + 1)},
      {at<BucketWall>(buffer, plan.members_at), static_cast<std::size_t>(layout.members)});
  const std::span<std::uint64_t> bits(at<std::uint64_t>(buffer, plan.raster_at),
                                      static_cast<std::size_t>(raster.words()));
  for (std::uint64_t& w : bits) w = 0;
  raster.bind(bits);
  Pose start1{}, start2{};
  VisitStreams s1(run.seed, kExperiment, 0, 1), s2(run.seed, kExperiment, 0, 2);
  if (world.place_start(s1.start, start1) != WorldError::None ||
      world.place_start(s2.start, start2) != WorldError::None)
    return "the start";
  antkit_trace_hash hash;
  antkit_trace_hash_init(&hash, run.seed);
  antkit_trace_hash_add_u64(&hash, 0);
  auto* trail = at<FxPoint>(buffer, plan.trail_at);
  std::size_t points = 0;
  std::uint64_t blocked1 = 0, blocked2 = 0;
  c_api_visit(world, run.seed, 1, run.steps, start1, hash, blocked1, result.length1_raw,
              [&](FxPoint p) {
                raster.lay(p);
                trail[points++] = p;
              });
  const std::span<const FxPoint> trail1(trail, points);
  CrossingLayout cl;
  if (!CrossingCounterCore::plan(trail1, cl)) return "the crossing index";
  if (plan.counter_at + cl.words() * 4 > plan.total) return "the crossing index's bound";
  auto* words = at<std::uint32_t>(buffer, plan.counter_at);
  CrossingCounterCore counter;
  counter.build(trail1, cl, {words, static_cast<std::size_t>(cl.buckets + 1)},
                {words + cl.buckets + 1, static_cast<std::size_t>(cl.ids)},
                {words + cl.buckets + 1 + cl.ids, static_cast<std::size_t>(cl.segments)});
  antkit_buffon_detector detector;
  antkit_buffon_detector_init(&detector);
  std::uint64_t bc = 0, crossings = 0;
  bool started = false;
  FxPoint previous{};
  c_api_visit(world, run.seed, 2, run.steps, start2, hash, blocked2, result.length2_raw,
              [&](FxPoint p) {
                if (antkit_buffon_detector_update(&detector, raster.at(p) ? 1 : 0) != 0) ++bc;
                if (started) crossings += counter.add(previous, p, [](std::uint32_t) {});
                started = true;
                previous = p;
              });
  antkit_trace_hash_add_u64(&hash, bc);
  antkit_trace_hash_add_u64(&hash, blocked1);
  antkit_trace_hash_add_u64(&hash, blocked2);
  antkit_trace_hash_add_u64(&hash, crossings);
  result.bc = bc;
  result.crossings_exact = crossings;
  result.blocked = blocked1 + blocked2;
  result.hash = antkit_trace_hash_finish(&hash);
  return nullptr;
}

} // namespace

bool read_walls(std::int32_t file, const std::uint8_t* head, std::size_t got, std::uint32_t count,
                FxSegment* walls) {
  // The bytes already read, then the file's, in pieces of 64 walls.
  std::uint8_t piece[64 * kMcuWallBytes];
  std::size_t have = got - kMcuBuffonHeaderBytes;
  for (std::size_t k = 0; k < have; ++k) piece[k] = head[kMcuBuffonHeaderBytes + k];
  std::size_t done = 0;
  while (done < count) {
    const std::size_t want = (count - done < 64 ? count - done : 64) * kMcuWallBytes - have;
    if (mcu::read(file, piece + have, want) != want) return false;
    const std::size_t n = (have + want) / kMcuWallBytes;
    for (std::size_t i = 0; i < n; ++i) walls[done + i] = read_mcu_wall(piece, i);
    done += n;
    have = 0;
  }
  return true;
}

int run_buffon(const char* path, std::int32_t file, std::int32_t size, const std::uint8_t* head,
               std::size_t got, std::uint8_t* arena, std::size_t bytes) {
  // The determinism matrix's input (mcu_digest_input.hpp): the same layout, another magic.
  const bool digest = got >= 8 && __builtin_memcmp(head, kMcuBuffonDigestMagic, 8) == 0;
  std::uint8_t header[kMcuBuffonHeaderBytes];
  for (std::size_t k = 0; k < kMcuBuffonHeaderBytes && k < got; ++k)
    header[k] = k < 8 && digest ? static_cast<std::uint8_t>(kMcuBuffonMagic[k]) : head[k];
  McuBuffonRun run;
  if (const McuBuffonError e = read_mcu_buffon_header(header, got, run); e != McuBuffonError::None)
    return refuse(path, describe(e));
  if (size < 0 || static_cast<std::uint64_t>(size) !=
                      kMcuBuffonHeaderBytes + std::uint64_t{run.walls} * kMcuWallBytes)
    return refuse(path, "its length is not the header and its walls");
  // The walls, as FxSegment, at the arena's start.
  auto* walls = reinterpret_cast<FxSegment*>(arena);
  if (!read_walls(file, head, got, run.walls, walls)) return refuse(path, "ends inside the walls");
  const std::size_t from = static_cast<std::size_t>(mcu_walls_bytes(run.walls));
  if (digest) {
    // Trials 0 .. 3 and their digest, as determinism/scenarios.cpp hashes run_trials.
    kernel::TraceHash all;
    Text t;
    t << "{\"steps\": " << run.steps << ", \"seed\": ";
    t.u64(run.seed) << ", \"trials\": [";
    for (std::uint64_t trial = 0; trial < kMcuBuffonDigestTrials; ++trial) {
      FixedTrialResult r;
      if (const char* why = run_fixed_trial({walls, run.walls}, run.body, run.width, run.seed,
                                            trial, run.steps, {arena + from, bytes - from}, r))
        return refuse(path, why);
      all.add_u64(r.hash);
      t << (trial == 0 ? "" : ", ") << "{\"trial\": " << static_cast<std::int64_t>(trial)
        << ", \"trial_hash\": \"";
      t.hex(r.hash) << "\"}";
    }
    t << "], \"hash\": \"";
    t.hex(all.finish()) << "\"}\n";
    t.flush();
    return 0;
  }
  mcu::ticks_start();
  FixedTrialResult r;
  if (const char* why = run_fixed_trial({walls, run.walls}, run.body, run.width, run.seed, 0,
                                        run.steps, {arena + from, bytes - from}, r))
    return refuse(path, why);
  const std::uint64_t ticks = mcu::ticks_now();
  FixedTrialResult c;
  if (const char* why = c_api_trial({walls, run.walls}, run, {arena + from, bytes - from}, c))
    return refuse(path, why);
  Text t;
  t << "{\"steps\": " << run.steps << ", \"seed\": ";
  t.u64(run.seed) << ", \"trials\": [{\"trial\": 0, \"bc\": ";
  t.u64(r.bc) << ", \"length1_raw\": " << r.length1_raw << ", \"length2_raw\": " << r.length2_raw
              << ", \"crossings_exact\": ";
  t.u64(r.crossings_exact) << ", \"blocked\": ";
  t.u64(r.blocked) << ", \"hash\": \"";
  t.hex(r.hash) << "\"}], \"c_api\": {\"bc\": ";
  t.u64(c.bc) << ", \"crossings_exact\": ";
  t.u64(c.crossings_exact) << ", \"blocked\": ";
  t.u64(c.blocked) << ", \"hash\": \"";
  t.hex(c.hash) << "\"}, \"walls\": " << std::int64_t{run.walls}
                << ", \"arena_bytes\": " << static_cast<std::int64_t>(from + r.bytes)
                << ", \"arena_limit\": " << static_cast<std::int64_t>(bytes)
                << ", \"moves\": " << 2 * run.steps
                << ", \"ticks\": " << static_cast<std::int64_t>(ticks) << "}\n";
  t.flush();
  return 0;
}

} // namespace antkit::mcu
