// One Randomized Search walk on the robot's own processor (issue 27): what `antkit dev rs-mcu-input
// --host` runs on the host (buffon/checkpoints.hpp run_rs), from the same sources. The host sends
// the arena as its Q15.16 walls (buffon/rs_mcu_input.hpp); the chip reads them into its arena and
// runs run_fixed_rs (buffon/randomized_search.hpp: the world's buckets, the behaviour's visit 3,
// RS's raster of 0.1 x 0.1 cells marked under the body, and the walk's trace hash) in the rest;
// then the same walk with the C API's behaviour and hash as run_fixed_rs's parts ("c_api" in the
// JSON), which proves the C API's antkit_buffon_behaviour_* on the chip against the host.
#include "buffon_run.hpp"
#include "c_api_parts.hpp"
#include "semihost.hpp"
#include "text.hpp"
#include "ticks.hpp"

#include <antkit/buffon/rs_mcu_input.hpp>
#include <antkit/c/antkit.h>

namespace antkit::mcu {

using namespace antkit::buffon;

namespace {

// The walk through the core (kept out of line so that the map file shows the step path's size).
[[gnu::noinline]] FixedRsResult walk(FixedRs& rs, const McuRsRun& run) {
  return run_fixed_rs(rs, run.seed, 0, run.steps);
}

// The same walk with the C API's behaviour and hash (antkit_buffon_behaviour_*,
// antkit_trace_hash_*: the calls a C firmware makes) as run_fixed_rs's parts (c_api_parts.hpp), so
// that the result must be run_fixed_rs's, and run_rs's on the host. RS's marks are cleared first.
[[gnu::noinline]] FixedRsResult walk_c_api(FixedRs& rs, const McuRsRun& run) {
  for (std::uint64_t k = 0; k < rs.raster.cells(); ++k) rs.raster.v[k] = 0;
  return run_fixed_rs<CApiParts>(rs, run.seed, 0, run.steps);
}

} // namespace

int run_rs(const char* path, std::int32_t file, std::int32_t size, const std::uint8_t* head,
           std::size_t got, std::uint8_t* arena, std::size_t bytes) {
  McuRsRun run;
  if (const McuBuffonError e = read_mcu_rs_header(head, got, run); e != McuBuffonError::None)
    return refuse(path, describe_rs(e));
  if (size < 0 || static_cast<std::uint64_t>(size) !=
                      kMcuRsHeaderBytes + std::uint64_t{run.walls} * kMcuWallBytes)
    return refuse(path, "its length is not the header and its walls");
  auto* walls = reinterpret_cast<FxSegment*>(arena);
  if (!read_walls(file, head, got, run.walls, walls)) return refuse(path, "ends inside the walls");
  const std::size_t from = static_cast<std::size_t>(mcu_walls_bytes(run.walls));
  static FixedRs rs;
  if (const char* why = prepare_fixed_rs({walls, run.walls}, run.body, run.seed, 0,
                                         {arena + from, bytes - from}, rs))
    return refuse(path, why);
  mcu::ticks_start();
  const FixedRsResult r = walk(rs, run);
  const std::uint64_t ticks = mcu::ticks_now();
  const FixedRsResult c = walk_c_api(rs, run);
  Text t;
  t << "{\"steps\": " << run.steps << ", \"seed\": ";
  t.u64(run.seed) << ", \"cells\": ";
  t.u64(r.cells) << ", \"cell_raw\": " << kRsCellRaw << ", \"length_raw\": " << r.length_raw
                 << ", \"blocked\": ";
  t.u64(r.blocked) << ", \"hash\": \"";
  t.hex(r.hash) << "\", \"c_api\": {\"cells\": ";
  t.u64(c.cells) << ", \"length_raw\": " << c.length_raw << ", \"blocked\": ";
  t.u64(c.blocked) << ", \"hash\": \"";
  t.hex(c.hash) << "\"}, \"walls\": " << std::int64_t{run.walls}
                << ", \"arena_bytes\": " << static_cast<std::int64_t>(from + r.bytes)
                << ", \"arena_limit\": " << static_cast<std::int64_t>(bytes)
                << ", \"moves\": " << run.steps
                << ", \"ticks\": " << static_cast<std::int64_t>(ticks) << "}\n";
  t.flush();
  return 0;
}

} // namespace antkit::mcu
