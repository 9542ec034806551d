// The Cortex-M image (issue 27): one run of ant-like STC (`ant`, `ant-edge` or `online`), one
// Buffon trial (buffon_run.cpp, when the input is a Buffon one), one Randomized Search walk
// (rs_run.cpp) or one step-turn wanderer run (wanderer_run.cpp) on the robot's own processor, or
// the ant-like STC decision over a range of its whole input domain (decide_run.cpp). It
// reads its input (stc/mcu_input.hpp: the map's free sub-cells, the start, the marker and the
// noise) from the host file named on its semihosting command line, runs the controller through the
// C API (antkit/c/antkit.h) over the floor of floor.hpp — the host's StcWorld steps the same floor
// — and prints one JSON object: the tour's trace hash and counts, as `antkit stc
// --format json` gives them, and the floor's bytes against the image's arena.
//
// Exit status (through semihosting): 0 the tour ran (whatever it found), 2 bad input (the message
// on the host's standard output, "error: ..."), 3 a processor fault (startup.cpp).
#include "buffon_run.hpp"
#include "decide_run.hpp"
#include "semihost.hpp"
#include "text.hpp"
#include "ticks.hpp"

#include <antkit/buffon/mcu_digest_input.hpp>
#include <antkit/buffon/mcu_input.hpp>
#include <antkit/buffon/rs_mcu_input.hpp>
#include <antkit/c/antkit.h>
#include <antkit/stc/floor.hpp>
#include <antkit/stc/mcu_input.hpp>
#include <antkit/uniform/wanderer_mcu_input.hpp>
#include <cstddef>
#include <cstdint>

namespace {

using namespace antkit::stc;
namespace mcu = antkit::mcu;
using mcu::refuse;
using mcu::Text;

// The floor's storage: the only large object of the image (mcu_input.hpp).
alignas(8) std::uint8_t g_arena[kMcuFloorBytes];
std::uint8_t g_header[kMcuHeaderBytes];

// The C API's controllers behind the interface drive_tour expects.
struct OnlineController {
  antkit_online_stc state;
  OnlineController(int q, void* memory, std::size_t bytes) noexcept {
    antkit_online_stc_init(&state, memory, bytes, q);
  }
  Command step(const CellObservation& o) noexcept {
    const antkit_cell_reading r{o.free_neighbours};
    const antkit_stc_command c = antkit_online_stc_step(&state, &r);
    return {static_cast<Move>(c.move), c.mark != 0};
  }
};

struct AntController {
  antkit_ant_stc state;
  explicit AntController(int q) noexcept { antkit_ant_stc_init(&state, q); }
  Command step(const MarkObservation& o) noexcept {
    antkit_mark_reading r{o.free_neighbours, o.here, {}};
    for (int d = 0; d < 4; ++d) r.neighbour[d] = o.neighbour[static_cast<std::size_t>(d)];
    const antkit_stc_command c = antkit_ant_stc_step(&state, &r);
    return {static_cast<Move>(c.move), c.mark != 0};
  }
};

struct AntEdgeController {
  antkit_ant_edge_stc state;
  explicit AntEdgeController(int q) noexcept { antkit_ant_edge_stc_init(&state, q); }
  Command step(const EdgeObservation& o) noexcept {
    antkit_edge_reading r{o.free_neighbours, o.here, {}};
    for (int d = 0; d < 4; ++d) r.neighbour[d] = o.neighbour[static_cast<std::size_t>(d)];
    const antkit_stc_command c = antkit_ant_edge_stc_step(&state, &r);
    return {static_cast<Move>(c.move), c.mark != 0};
  }
};

// One tour (kept out of line so that the map file shows the step path's size).
template <class Controller, class Observe>
__attribute__((noinline)) TourEnd tour(Controller& controller, Floor& floor,
                                       antkit::kernel::TraceHash& hash, std::int64_t max_moves,
                                       Observe observe) {
  return drive_tour(controller, observe, floor, hash, max_moves, [](SubCell) {});
}

} // namespace

int main() {
  char line[256];
  if (!mcu::command_line(line, sizeof line)) return refuse("command line", "longer than 255 bytes");
  // "antkit_mcu INPUT": the input is the second word.
  const char* path = line;
  while (*path != 0 && *path != ' ') ++path;
  while (*path == ' ') ++path;
  if (*path == 0) return refuse("command line", "no input file (antkit_mcu INPUT)");
  // "antkit_mcu decide FIRST COUNT [FLIP]": the ant-like STC decision over a range of its whole
  // input domain (decide_run.cpp); no input file.
  if (__builtin_memcmp(path, "decide", 6) == 0 && (path[6] == ' ' || path[6] == 0)) {
    const char* args = path + 6;
    while (*args == ' ') ++args;
    return mcu::run_decide(args);
  }
  const std::int32_t file = mcu::open_read(path);
  if (file < 0) return refuse(path, "cannot be opened");
  const std::int32_t size = mcu::file_length(file);
  McuRun run;
  const std::size_t got = mcu::read(file, g_header, sizeof g_header);
  // A Buffon trial (buffon/mcu_input.hpp) in the same arena.
  static_assert(antkit::buffon::kMcuArenaBytes == kMcuFloorBytes);
  if (got >= 8 && (__builtin_memcmp(g_header, antkit::buffon::kMcuBuffonMagic, 8) == 0 ||
                   __builtin_memcmp(g_header, antkit::buffon::kMcuBuffonDigestMagic, 8) == 0))
    return mcu::run_buffon(path, file, size, g_header, got, g_arena, sizeof g_arena);
  // A Randomized Search walk (buffon/rs_mcu_input.hpp), likewise.
  if (got >= 8 && __builtin_memcmp(g_header, antkit::buffon::kMcuRsMagic, 8) == 0)
    return mcu::run_rs(path, file, size, g_header, got, g_arena, sizeof g_arena);
  // A step-turn wanderer run (uniform/wanderer_mcu_input.hpp), likewise.
  static_assert(antkit::uniform::kMcuWandererArenaBytes == kMcuFloorBytes);
  if (got >= 8 && __builtin_memcmp(g_header, antkit::uniform::kMcuWandererMagic, 8) == 0)
    return mcu::run_wanderer(path, file, size, g_header, got, g_arena, sizeof g_arena);
  if (const McuInputError e = read_mcu_header(g_header, got, run); e != McuInputError::None)
    return refuse(path, describe(e));
  const FloorSize fs = floor_size(run.width, run.height);
  if (size < 0 || static_cast<std::size_t>(size) != kMcuHeaderBytes + fs.bit_bytes)
    return refuse(path, "its length is not the header and the map's free sub-cells");
  // The arena: the floor (floor_storage's layout), then online STC's memory.
  const FloorStorage storage = floor_storage(g_arena, run.width, run.height, run.marker);
  const std::size_t memory_at =
      (floor_bytes(run.width, run.height, run.marker) + 7) & ~std::size_t{7};
  if (mcu::read(file, storage.free_bits, fs.bit_bytes) != fs.bit_bytes)
    return refuse(path, "ends inside the map");
  mcu::close(file);
  static Floor floor;
  floor.reset(run.width, run.height, storage, run.start, run.noise, run.marker);
  // The start must lie in a free cell (the exact variants' rule, checked on the host too).
  if (!floor.cell_free(cell_of(run.start)))
    return refuse(path, "the start lies in a cell with a blocked sub-cell");
  antkit::kernel::TraceHash hash = tour_hash_begin(run.width, run.height, run.start);
  tour_hash_add(hash, run.start);
  const std::int64_t max_moves = 16 * std::int64_t{run.width} * run.height + 16;
  const int q = quadrant_of(run.start);
  mcu::ticks_start();
  TourEnd end;
  std::int64_t tiles = 0, capacity = 0;
  bool overflowed = false;
  if (run.variant == McuVariant::Online) {
    OnlineController controller(q, g_arena + memory_at, kMcuFloorBytes - memory_at);
    end = tour(controller, floor, hash, max_moves, [] { return floor.observe_cells(); });
    tiles = static_cast<std::int64_t>(antkit_online_stc_tiles(&controller.state));
    capacity = static_cast<std::int64_t>(antkit_online_stc_capacity(&controller.state));
    overflowed = antkit_online_stc_overflowed(&controller.state) != 0;
  } else if (run.variant == McuVariant::AntEdge) {
    AntEdgeController controller(q);
    end = tour(controller, floor, hash, max_moves, [] { return floor.observe_edges(); });
  } else {
    AntController controller(q);
    end = tour(controller, floor, hash, max_moves, [] { return floor.observe_marks(); });
  }
  const std::uint64_t ticks = mcu::ticks_now();
  const SubCell last = floor.position();
  const bool returned =
      end.closed && !overflowed && (last == run.start || adjacent(last, run.start));
  const char* name = run.variant == McuVariant::Online    ? "online"
                     : run.variant == McuVariant::AntEdge ? "ant-edge"
                                                          : "ant";
  Text t;
  t << "{\"variant\": \"" << name << "\", \"width\": " << std::int64_t{run.width}
    << ", \"height\": " << std::int64_t{run.height} << ", \"start\": [" << std::int64_t{run.start.x}
    << ", " << std::int64_t{run.start.y} << "], \"positions\": " << end.moves + 1
    << ", \"covered\": " << floor.covered() << ", \"repeats\": " << floor.repeats()
    << ", \"closed\": " << (end.closed ? "true" : "false")
    << ", \"returned_to_start\": " << (returned ? "true" : "false") << ", \"hash\": \"";
  t.hex(hash.finish()) << "\", \"noise_ppm\": " << std::int64_t{run.noise.ppm}
                       << ", \"floor_bytes\": "
                       << static_cast<std::int64_t>(floor_bytes(run.width, run.height, run.marker));
  if (run.variant == McuVariant::Online)
    t << ", \"memory_tiles\": " << tiles << ", \"memory_capacity\": " << capacity
      << ", \"memory_overflowed\": " << (overflowed ? "true" : "false");
  t << ", \"floor_limit\": " << static_cast<std::int64_t>(kMcuFloorBytes)
    << ", \"ticks\": " << static_cast<std::int64_t>(ticks) << "}\n";
  t.flush();
  return 0;
}
