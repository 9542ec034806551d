// The C API (antkit/c/antkit.h) over the C++ controllers and the trace hash. Freestanding: it
// compiles with -fno-exceptions -fno-rtti for bare metal (mcu/) as for the host, and allocates
// nothing. Each C state struct holds the bytes of the C++ object it stands for (trivially copyable,
// sizes asserted below), so a step is the C++ step, not a second implementation.
#include <antkit/c/antkit.h>
#include <antkit/kernel/hash.hpp>
#include <antkit/stc/ant.hpp>
#include <antkit/stc/floor.hpp>
#include <cstring>
#include <type_traits>

namespace {

using antkit::kernel::TraceHash;
using antkit::stc::AntEdgeStc;
using antkit::stc::AntStc;

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

} // extern "C"
