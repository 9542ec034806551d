// The C API (antkit/c/antkit.h) over the C++ controllers and the trace hash. Freestanding: it
// compiles with -fno-exceptions -fno-rtti for bare metal (mcu/) as for the host, and allocates
// nothing. Each C state struct holds the bytes of the C++ object it stands for (trivially copyable,
// sizes asserted below), so a step is the C++ step, not a second implementation.
#include <antkit/buffon/detector.hpp>
#include <antkit/buffon/exploration.hpp>
#include <antkit/c/antkit.h>
#include <antkit/kernel/hash.hpp>
#include <antkit/stc/ant.hpp>
#include <antkit/stc/floor.hpp>
#include <antkit/stc/online.hpp>
#include <antkit/uniform/step_turn.hpp>
#include <cstdint>
#include <cstring>
#include <new>
#include <type_traits>

namespace {

using antkit::kernel::TraceHash;
using antkit::stc::AntEdgeStc;
using antkit::stc::AntStc;
using antkit::stc::Floor;
using antkit::stc::FloorStorage;
using antkit::stc::Marker;
using OnlineChip = antkit::stc::BasicOnlineStc<antkit::stc::FixedCellMemory>;
static_assert(sizeof(OnlineChip) <= sizeof(antkit_online_stc) &&
              alignof(OnlineChip) <= alignof(antkit_online_stc));
static_assert(std::is_trivially_destructible_v<OnlineChip>);

// The C++ object a C struct's opaque bytes hold (placed there by its init function).
template <class T, class C>
T& object_in(C* c) noexcept {
  return *std::launder(reinterpret_cast<T*>(c->opaque));
}
template <class T, class C>
const T& object_in(const C* c) noexcept {
  return *std::launder(reinterpret_cast<const T*>(c->opaque));
}

// What antkit_stc_floor holds: the floor, its storage and its size, until start.
struct FloorState {
  Floor floor;
  FloorStorage storage;
  std::int32_t width = 0, height = 0;
  Marker marker = Marker::WholeSubCell;
  bool started = false;
};
static_assert(sizeof(FloorState) <= sizeof(antkit_stc_floor) &&
              alignof(FloorState) <= alignof(antkit_stc_floor));
static_assert(std::is_trivially_destructible_v<FloorState>);

bool valid_size(std::int32_t width, std::int32_t height) noexcept {
  return width >= 2 && height >= 2 && width <= 16384 && height <= 16384;
}

using antkit::buffon::CrossingDetector;
using antkit::buffon::ExplorationBehaviour;
static_assert(sizeof(ExplorationBehaviour) <= sizeof(antkit_buffon_behaviour) &&
              alignof(ExplorationBehaviour) <= alignof(antkit_buffon_behaviour) &&
              std::is_trivially_copyable_v<ExplorationBehaviour>);
static_assert(sizeof(CrossingDetector) <= sizeof(antkit_buffon_detector) &&
              alignof(CrossingDetector) <= alignof(antkit_buffon_detector) &&
              std::is_trivially_copyable_v<CrossingDetector>);

using antkit::uniform::StepTurnCore;
static_assert(sizeof(StepTurnCore) <= sizeof(antkit_step_turn_wanderer) &&
              alignof(StepTurnCore) <= alignof(antkit_step_turn_wanderer) &&
              std::is_trivially_copyable_v<StepTurnCore>);
static_assert(ANTKIT_WANDER_WAIT == static_cast<int>(antkit::uniform::Action::Wait) &&
              ANTKIT_WANDER_TURN_LEFT == static_cast<int>(antkit::uniform::Action::TurnLeft) &&
              ANTKIT_WANDER_TURN_RIGHT == static_cast<int>(antkit::uniform::Action::TurnRight) &&
              ANTKIT_WANDER_FORWARD == static_cast<int>(antkit::uniform::Action::Forward));

static_assert(sizeof(AntStc) <= sizeof(antkit_ant_stc) && std::is_trivially_copyable_v<AntStc>);
static_assert(sizeof(AntEdgeStc) <= sizeof(antkit_ant_edge_stc) &&
              std::is_trivially_copyable_v<AntEdgeStc>);
static_assert(sizeof(TraceHash) <= sizeof(antkit_trace_hash) &&
              alignof(TraceHash) <= alignof(antkit_trace_hash) &&
              std::is_trivially_copyable_v<TraceHash>);

template <class T, class C>
T load(const C* c) noexcept {
  T t(0);
  std::memcpy(static_cast<void*>(&t), c, sizeof t); // trivially copyable (asserted above)
  return t;
}
template <class T, class C>
void store(C* c, const T& t) noexcept {
  std::memcpy(c, &t, sizeof t);
}

antkit_stc_command to_c(antkit::stc::Command c) noexcept {
  return {static_cast<std::uint8_t>(c.move), static_cast<std::uint8_t>(c.mark ? 1 : 0)};
}

TraceHash load_hash(const antkit_trace_hash* h) noexcept {
  TraceHash t;
  std::memcpy(static_cast<void*>(&t), h, sizeof t);
  return t;
}

template <class F>
void with_hash(antkit_trace_hash* h, F&& f) noexcept {
  TraceHash t = load_hash(h);
  f(t);
  store(h, t);
}

} // namespace

extern "C" {

int antkit_stc_quadrant(int32_t x, int32_t y) {
  return antkit::stc::quadrant_of({x, y});
}

void antkit_ant_stc_init(antkit_ant_stc* state, int start_quadrant) {
  std::memset(state, 0, sizeof *state);
  store(state, AntStc(start_quadrant));
}

antkit_stc_command antkit_ant_stc_step(antkit_ant_stc* state, const antkit_mark_reading* r) {
  auto c = load<AntStc>(state);
  antkit::stc::MarkObservation o;
  o.free_neighbours = r->free_neighbours;
  o.here = r->here;
  for (int d = 0; d < 4; ++d) o.neighbour[static_cast<std::size_t>(d)] = r->neighbour[d];
  const antkit::stc::Command command = c.step(o);
  store(state, c);
  return to_c(command);
}

void antkit_ant_edge_stc_init(antkit_ant_edge_stc* state, int start_quadrant) {
  std::memset(state, 0, sizeof *state);
  store(state, AntEdgeStc(start_quadrant));
}

antkit_stc_command antkit_ant_edge_stc_step(antkit_ant_edge_stc* state,
                                            const antkit_edge_reading* r) {
  auto c = load<AntEdgeStc>(state);
  antkit::stc::EdgeObservation o;
  o.free_neighbours = r->free_neighbours;
  o.here = r->here;
  for (int d = 0; d < 4; ++d) o.neighbour[static_cast<std::size_t>(d)] = r->neighbour[d];
  const antkit::stc::Command command = c.step(o);
  store(state, c);
  return to_c(command);
}

size_t antkit_online_stc_bytes(size_t tiles) {
  return antkit::stc::FixedCellMemory::bytes_for(tiles);
}

int antkit_online_stc_init(antkit_online_stc* state, void* buffer, size_t bytes,
                           int start_quadrant) {
  if (buffer == nullptr || reinterpret_cast<std::uintptr_t>(buffer) % 8 != 0 ||
      antkit::stc::FixedCellMemory::capacity_for(bytes) == 0)
    return -1;
  new (state->opaque) OnlineChip(start_quadrant, antkit::stc::FixedCellMemory(buffer, bytes));
  return 0;
}

antkit_stc_command antkit_online_stc_step(antkit_online_stc* state,
                                          const antkit_cell_reading* reading) {
  return to_c(object_in<OnlineChip>(state).step({reading->free_neighbours}));
}

int antkit_online_stc_overflowed(const antkit_online_stc* state) {
  return object_in<OnlineChip>(state).overflowed() ? 1 : 0;
}
size_t antkit_online_stc_tiles(const antkit_online_stc* state) {
  return object_in<OnlineChip>(state).memory().tiles();
}
size_t antkit_online_stc_capacity(const antkit_online_stc* state) {
  return object_in<OnlineChip>(state).memory().capacity();
}

size_t antkit_stc_floor_bytes(int32_t width, int32_t height, int marker) {
  if (!valid_size(width, height) ||
      (marker != ANTKIT_MARKER_SUBCELL && marker != ANTKIT_MARKER_EDGE))
    return 0;
  return antkit::stc::floor_bytes(
      width, height, marker == ANTKIT_MARKER_EDGE ? Marker::Edge : Marker::WholeSubCell);
}

int antkit_stc_floor_init(antkit_stc_floor* floor, void* buffer, size_t size, int32_t width,
                          int32_t height, int marker) {
  const std::size_t need = antkit_stc_floor_bytes(width, height, marker);
  if (need == 0 || size < need || buffer == nullptr ||
      reinterpret_cast<std::uintptr_t>(buffer) % 8 != 0)
    return -1;
  auto* s = new (floor->opaque) FloorState{};
  std::memset(buffer, 0, need);
  s->marker = marker == ANTKIT_MARKER_EDGE ? Marker::Edge : Marker::WholeSubCell;
  s->storage = antkit::stc::floor_storage(buffer, width, height, s->marker);
  s->width = width;
  s->height = height;
  return 0;
}

void antkit_stc_floor_set_free(antkit_stc_floor* floor, int32_t x, int32_t y) {
  FloorState& s = object_in<FloorState>(floor);
  const auto fs = antkit::stc::floor_size(s.width, s.height);
  if (x < 0 || y < 0 || x >= 2 * fs.shape.cells_x || y >= 2 * fs.shape.cells_y) return;
  const std::size_t k =
      static_cast<std::size_t>(y) * static_cast<std::size_t>(2 * fs.shape.cells_x) +
      static_cast<std::size_t>(x);
  s.storage.free_bits[k >> 3] =
      static_cast<std::uint8_t>(s.storage.free_bits[k >> 3] | (1u << (k & 7)));
}

int antkit_stc_floor_start(antkit_stc_floor* floor, int32_t x, int32_t y) {
  FloorState& s = object_in<FloorState>(floor);
  const antkit::stc::SubCell start{x, y};
  const auto shape = antkit::stc::floor_size(s.width, s.height).shape;
  if (x < 0 || y < 0 || !shape.in_bounds(antkit::stc::cell_of(start))) return -1;
  s.floor.reset(s.width, s.height, s.storage, start, {}, s.marker);
  if (!s.floor.cell_free(antkit::stc::cell_of(start))) return -1;
  s.started = true;
  return 0;
}

void antkit_stc_floor_read_cells(antkit_stc_floor* floor, antkit_cell_reading* r) {
  FloorState& s = object_in<FloorState>(floor);
  r->free_neighbours = s.started ? s.floor.observe_cells().free_neighbours : 0;
}

void antkit_stc_floor_read_marks(antkit_stc_floor* floor, antkit_mark_reading* r) {
  FloorState& s = object_in<FloorState>(floor);
  *r = antkit_mark_reading{};
  if (!s.started || !s.storage.marks) return;
  const antkit::stc::MarkObservation o = s.floor.observe_marks();
  r->free_neighbours = o.free_neighbours;
  r->here = o.here;
  for (int d = 0; d < 4; ++d) r->neighbour[d] = o.neighbour[static_cast<std::size_t>(d)];
}

void antkit_stc_floor_read_edges(antkit_stc_floor* floor, antkit_edge_reading* r) {
  FloorState& s = object_in<FloorState>(floor);
  *r = antkit_edge_reading{};
  if (!s.started || !s.storage.edges) return;
  const antkit::stc::EdgeObservation o = s.floor.observe_edges();
  r->free_neighbours = o.free_neighbours;
  r->here = o.here;
  for (int d = 0; d < 4; ++d) r->neighbour[d] = o.neighbour[static_cast<std::size_t>(d)];
}

int antkit_stc_floor_apply(antkit_stc_floor* floor, antkit_stc_command c) {
  FloorState& s = object_in<FloorState>(floor);
  if (!s.started || c.move > ANTKIT_STOP) return 0;
  return s.floor.apply({static_cast<antkit::stc::Move>(c.move), c.mark != 0}) ? 1 : 0;
}

void antkit_stc_floor_position(const antkit_stc_floor* floor, int32_t* x, int32_t* y) {
  const antkit::stc::SubCell p = object_in<FloorState>(floor).floor.position();
  *x = p.x;
  *y = p.y;
}

int64_t antkit_stc_floor_covered(const antkit_stc_floor* floor) {
  return object_in<FloorState>(floor).floor.covered();
}
int64_t antkit_stc_floor_repeats(const antkit_stc_floor* floor) {
  return object_in<FloorState>(floor).floor.repeats();
}

void antkit_trace_hash_init(antkit_trace_hash* hash, uint64_t seed) {
  std::memset(hash, 0, sizeof *hash);
  store(hash, TraceHash(seed));
}
void antkit_trace_hash_add_u8(antkit_trace_hash* hash, uint8_t value) {
  with_hash(hash, [&](TraceHash& t) { t.add_u8(value); });
}
void antkit_trace_hash_add_u32(antkit_trace_hash* hash, uint32_t value) {
  with_hash(hash, [&](TraceHash& t) { t.add_u32(value); });
}
void antkit_trace_hash_add_i32(antkit_trace_hash* hash, int32_t value) {
  with_hash(hash, [&](TraceHash& t) { t.add_i32(value); });
}
void antkit_trace_hash_add_u64(antkit_trace_hash* hash, uint64_t value) {
  with_hash(hash, [&](TraceHash& t) { t.add_u64(value); });
}
uint64_t antkit_trace_hash_finish(const antkit_trace_hash* hash) {
  return load_hash(hash).finish();
}

void antkit_stc_tour_hash_begin(antkit_trace_hash* hash, int32_t width, int32_t height,
                                int32_t start_x, int32_t start_y) {
  std::memset(hash, 0, sizeof *hash);
  store(hash, antkit::stc::tour_hash_begin(width, height, {start_x, start_y}));
}
void antkit_stc_tour_hash_add(antkit_trace_hash* hash, int32_t x, int32_t y) {
  with_hash(hash, [&](TraceHash& t) { antkit::stc::tour_hash_add(t, {x, y}); });
}

void antkit_buffon_behaviour_init(antkit_buffon_behaviour* state, uint64_t seed,
                                  uint64_t experiment, uint64_t trial, uint64_t robot) {
  ::new (static_cast<void*>(state->opaque))
      ExplorationBehaviour(antkit::kernel::Stream(seed, experiment, trial, robot, 0));
}

antkit_wheel_command antkit_buffon_behaviour_step(antkit_buffon_behaviour* state,
                                                  const antkit_ir_reading* reading) {
  antkit::buffon::Observation obs;
  for (std::size_t i = 0; i < 6; ++i) obs.ir[i] = antkit::kernel::Fx::from_raw(reading->ir[i]);
  const antkit::buffon::Command c = object_in<ExplorationBehaviour>(state).step(obs);
  return {c.left.raw(), c.right.raw()};
}

void antkit_buffon_behaviour_state(const antkit_buffon_behaviour* state, int32_t* r,
                                   int32_t* w_left, int32_t* w_right) {
  const auto& b = object_in<ExplorationBehaviour>(state);
  if (r != nullptr) *r = b.r().raw();
  if (w_left != nullptr) *w_left = b.w_left().raw();
  if (w_right != nullptr) *w_right = b.w_right().raw();
}

void antkit_step_turn_wanderer_init(antkit_step_turn_wanderer* state, uint64_t seed, uint64_t trial,
                                    uint64_t robot) {
  ::new (static_cast<void*>(state->opaque)) StepTurnCore(seed, trial, robot);
}

int antkit_step_turn_wanderer_step(antkit_step_turn_wanderer* state, int front_free) {
  return static_cast<int>(object_in<StepTurnCore>(state).step(front_free != 0).action);
}

uint64_t antkit_step_turn_wanderer_steps(const antkit_step_turn_wanderer* state) {
  return object_in<StepTurnCore>(state).steps();
}

void antkit_buffon_detector_init(antkit_buffon_detector* state) {
  ::new (static_cast<void*>(state->opaque)) CrossingDetector();
}

int antkit_buffon_detector_update(antkit_buffon_detector* state, int pheromone) {
  return object_in<CrossingDetector>(state).update(pheromone != 0) ? 1 : 0;
}

} // extern "C"
