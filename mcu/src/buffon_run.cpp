// One Buffon trial on the robot's own processor (issue 27): trial 0 of `antkit buffon --trials 1`,
// from the same sources as the host. The host sends the arena as its Q15.16 walls
// (buffon/mcu_input.hpp); the chip reads them into its arena and runs run_fixed_trial
// (buffon/fixed_trial.hpp: the world's buckets, the behaviour, the pheromone raster, the detector,
// the exact crossing count and run_trial's trace hash) in the rest of it; then the trial again
// with the C API's behaviour, detector and hash as its parts ("c_api" in the JSON: c_api_trial,
// c_api_parts.hpp), which proves antkit_buffon_behaviour_* and antkit_buffon_detector_* on the
// chip against the host.
#include "buffon_run.hpp"

#include "c_api_parts.hpp"
#include "semihost.hpp"
#include "text.hpp"
#include "ticks.hpp"

#include <antkit/buffon/fixed_trial.hpp>
#include <antkit/buffon/mcu_digest_input.hpp>
#include <antkit/buffon/mcu_input.hpp>
#include <antkit/c/antkit.h>

namespace antkit::mcu {

using namespace antkit::buffon;

namespace {

// The trial again with the C API's behaviour, detector and hash (antkit/c/antkit.h: the calls a C
// firmware makes) as the parts of the same run_fixed_trial_with (fixed_trial.hpp) over the same
// buffer, so that its result must be run_fixed_trial's and `antkit buffon --trials 1`'s. Null or
// why not.
const char* c_api_trial(std::span<const FxSegment> walls, const McuBuffonRun& run,
                        std::span<std::uint8_t> buffer, FixedTrialResult& result) {
  return run_fixed_trial_with<CApiParts>(walls, run.body, run.width, run.seed, 0, run.steps, buffer,
                                         result);
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
