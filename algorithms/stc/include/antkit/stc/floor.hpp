#pragma once
// The floor the marker variants of STC run on, and the loop that drives a controller over it: the
// world's step, written once for the host and for a robot's microcontroller (issue 27).
//
// Freestanding: no heap, no exceptions, no iostream, nothing that grows. The caller provides the
// storage (FloorStorage): the host's StcWorld owns it in vectors, the Cortex-M image (mcu/) in one
// static array, and the bytes it needs are known before the run (floor_bytes). The same functions
// step both, so the tour hash the chip prints is the host's by construction, and tests/mcu checks
// it on every shared map that fits.
//
// The floor holds, for the cell area (2 * cells_x by 2 * cells_y sub-cells; an odd last row or
// column of the map is outside it, subcell.hpp):
//   * free_bits, entered_bits: one bit per sub-cell, row-major (bit k & 7 of byte k >> 3, with
//     k = y * 2 * cells_x + x): whether the sub-cell is free (the caller fills this in before
//     reset), and whether the robot has entered it (reset clears it);
//   * marks (ant) and edges (ant-edge): per cell, with a border of one blocked cell so that the
//     neighbours of any cell are read without a bounds check. Bit q of marks is sub-cell q's mark,
//     edges holds the cell's twelve edges as documented in ant.hpp (an exterior edge is stored in
//     both cells it separates). Bit 7 of marks and bit 15 of edges say whether the cell is free
//     (never lit: marks use bits 0-3, edges 0-11), so an observation reads the neighbours' freedom
//     from the words it loads anyway. Either array may be absent (null) when the run does not
//     need it; the freedom bit is then read from the other.
// The floor is one template, BasicFloor<P>, over the integer and memory types it computes with;
// what ships is Floor = BasicFloor<FloorMachine> (plain C++ types: the machine code is the
// non-template floor's). proofs/z3/stc_floor.cpp instantiates the same source with Z3 words and Z3
// arrays and proves its step on every map up to kMaxGridSide (issue 41).
// Marker noise lives here, on the sensing side: each mark bit the robot reads is misread (a missed
// mark or a phantom) with probability noise.ppm / 1'000'000, drawn from the keyed stream
// (seed, kNoiseExperiment, trial, robot 0, kNoisePurpose). The controllers stay deterministic
// functions of what they read.
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/stc/ant.hpp>
#include <antkit/stc/online.hpp>
#include <antkit/stc/subcell.hpp>
#include <cstddef>
#include <cstdint>

namespace antkit::stc {

// Keys of the noise stream.
inline constexpr std::uint64_t kNoiseExperiment = 3;       // issue 3
inline constexpr std::uint64_t kNoisePurpose = 0x6D61726B; // "mark"

struct NoiseModel {
  std::uint32_t ppm = 0; // misread probability, parts per million (0 .. 1'000'000)
  std::uint64_t seed = 0;
  std::uint64_t trial = 0;
};

// What the robot leaves when a command says `mark`: a mark on the sub-cell it leaves (`ant`), or
// the lit edge behind it (`ant-edge`, the paper's real robot).
enum class Marker : std::uint8_t { WholeSubCell, Edge };

struct FloorStorage {
  std::uint8_t* free_bits = nullptr;    // bit_bytes, filled in by the caller
  std::uint8_t* entered_bits = nullptr; // bit_bytes
  std::uint8_t* marks = nullptr;        // cells entries, or null
  std::uint16_t* edges = nullptr;       // cells entries, or null
};

// The types the floor computes with. The floor is written once, over a policy P, and shipped as
// Floor = BasicFloor<FloorMachine>: the plain C++ types below, so the machine code is what it was
// before the template. proofs/z3/stc_floor.cpp instantiates the very same source with Z3 words and
// Z3 arrays for memory and proves one step of it, for every map up to kMaxGridSide (issue 41). A
// policy gives:
//   Bool      a truth value (`if` on it: the Z3 instantiation forks the run, one path per outcome)
//   Coord     sub-cell and cell coordinates (int32)
//   Index     indices into the arrays (size_t: the stride arithmetic wraps modulo 2^64)
//   Byte      an element of free_bits, entered_bits and marks; Word: an element of edges
//   Bits      a mask being assembled (unsigned); Count: the covered and repeat counts (int64)
//   SubCell   {Coord x, y} (also used for cells); Shape: {Coord cells_x, cells_y}
//   Storage   FloorStorage's four arrays, each indexed by Index and testable for presence
//   MarkObservation, EdgeObservation: what the controllers read
struct FloorMachine {
  using Bool = bool;
  using Coord = std::int32_t;
  using Index = std::size_t;
  using Byte = std::uint8_t;
  using Word = std::uint16_t;
  using Bits = unsigned;
  using Count = std::int64_t;
  using SubCell = stc::SubCell;
  using Shape = CellGridShape;
  using Storage = FloorStorage;
  using MarkObservation = stc::MarkObservation;
  using EdgeObservation = stc::EdgeObservation;
};

// Sizes of the floor's arrays for a map of width x height sub-cells.
template <class P>
struct BasicFloorSize {
  typename P::Shape shape{};
  typename P::Index bit_bytes = 0; // free_bits and entered_bits, each
  typename P::Index cells = 0;     // entries of marks and of edges (the cells and their border)
};
using FloorSize = BasicFloorSize<FloorMachine>;

template <class P>
[[nodiscard]] constexpr BasicFloorSize<P> basic_floor_size(typename P::Coord width,
                                                           typename P::Coord height) noexcept {
  using Index = typename P::Index;
  BasicFloorSize<P> s;
  s.shape = {width / 2, height / 2};
  const auto cx = static_cast<Index>(s.shape.cells_x);
  const auto cy = static_cast<Index>(s.shape.cells_y);
  s.bit_bytes = (4 * cx * cy + 7) / 8;
  s.cells = (cx + 2) * (cy + 2);
  return s;
}

[[nodiscard]] constexpr FloorSize floor_size(std::int32_t width, std::int32_t height) noexcept {
  return basic_floor_size<FloorMachine>(width, height);
}

// The bytes a run of one marker needs in one buffer (floor_storage's layout): both bit arrays,
// then that marker's array at an 8-byte boundary.
[[nodiscard]] constexpr std::size_t floor_bytes(std::int32_t width, std::int32_t height,
                                                Marker marker) noexcept {
  const FloorSize s = floor_size(width, height);
  return ((2 * s.bit_bytes + 7) & ~std::size_t{7}) + s.cells * (marker == Marker::Edge ? 2 : 1);
}

// Lays a floor's storage out in `buffer` (8-byte aligned, floor_bytes long): free bits, entered
// bits, then the marker's array (marks for WholeSubCell, edges for Edge). Nothing is written.
[[nodiscard]] inline FloorStorage floor_storage(void* buffer, std::int32_t width,
                                                std::int32_t height, Marker marker) noexcept {
  const FloorSize s = floor_size(width, height);
  auto* bytes = static_cast<std::uint8_t*>(buffer);
  FloorStorage f;
  f.free_bits = bytes;
  f.entered_bits = bytes + s.bit_bytes;
  std::uint8_t* cells = bytes + ((2 * s.bit_bytes + 7) & ~std::size_t{7});
  if (marker == Marker::Edge)
    f.edges = reinterpret_cast<std::uint16_t*>(cells);
  else
    f.marks = cells;
  return f;
}

template <class P>
class BasicFloor {
public:
  using Bool = typename P::Bool;
  using Coord = typename P::Coord;
  using Index = typename P::Index;
  using Byte = typename P::Byte;
  using Word = typename P::Word;
  using Bits = typename P::Bits;
  using Count = typename P::Count;
  using SubCell = typename P::SubCell;
  using Cell = typename P::SubCell;
  using Shape = typename P::Shape;
  using Storage = typename P::Storage;
  using MarkObservation = typename P::MarkObservation;
  using EdgeObservation = typename P::EdgeObservation;

  static constexpr unsigned kMarkFreeBit = 7;
  static constexpr unsigned kEdgeFreeBit = 15;

  // Starts a run on a map of width x height sub-cells whose free sub-cells are already in
  // storage.free_bits: derives the cells' freedom, clears marks, edges and entries, and enters
  // `start` (a free sub-cell of the cell area: the runners check). At least one of marks and edges.
  void reset(Coord width, Coord height, Storage storage, SubCell start, NoiseModel noise,
             Marker marker) noexcept {
    const BasicFloorSize<P> size = layout(width, height, storage, noise, marker);
    for (Index i = 0; i < size.bit_bytes; ++i) s_.entered_bits[i] = 0;
    for (Index i = 0; i < size.cells; ++i) {
      if (s_.marks) s_.marks[i] = 0;
      if (s_.edges) s_.edges[i] = 0;
    }
    for (Coord cy = 0; cy < shape_.cells_y; ++cy)
      for (Coord cx = 0; cx < shape_.cells_x; ++cx) {
        bool all = true;
        for (int q = 0; q < 4; ++q) all = all && bit(s_.free_bits, subcell_of({cx, cy}, q));
        if (!all) continue;
        const Index i = cell_index({cx, cy});
        if (s_.marks) s_.marks[i] = Byte{1} << kMarkFreeBit;
        if (s_.edges) s_.edges[i] = Word{1} << kEdgeFreeBit;
      }
    position_ = start;
    covered_ = 0;
    repeats_ = 0;
    enter(start);
  }

  // Takes up a run where it stands: the layout of a width x height floor over `storage`, whose
  // arrays already hold the run's marks, edges and entries (nothing is read or written), the robot
  // at `position`, with `covered` and `repeats` so far. reset() is the same layout, then a clean
  // floor and the start; the Z3 proof (proofs/z3/stc_floor.cpp) steps the floor from here, from
  // any state that keeps the floor's invariant.
  void restore(Coord width, Coord height, Storage storage, SubCell position, Count covered,
               Count repeats, NoiseModel noise, Marker marker) noexcept {
    layout(width, height, storage, noise, marker);
    position_ = position;
    covered_ = covered;
    repeats_ = repeats;
  }

  [[nodiscard]] Coord width() const noexcept { return width_; }
  [[nodiscard]] Coord height() const noexcept { return height_; }
  [[nodiscard]] Shape shape() const noexcept { return shape_; }
  [[nodiscard]] SubCell position() const noexcept { return position_; }
  // Sub-cells entered at least once, and entries into a sub-cell entered before.
  [[nodiscard]] Count covered() const noexcept { return covered_; }
  [[nodiscard]] Count repeats() const noexcept { return repeats_; }

  [[nodiscard]] Bool inside(SubCell s) const noexcept {
    return s.x >= 0 && s.y >= 0 && s.x < 2 * shape_.cells_x && s.y < 2 * shape_.cells_y;
  }
  [[nodiscard]] Bool sub_free(SubCell s) const noexcept {
    // Not `inside(s) && bit(...)`: written so that the bit is read only inside, for the Z3
    // instantiation too (whose && evaluates both sides; the proof checks every index read).
    if (!inside(s)) return false;
    return bit(s_.free_bits, s);
  }
  // Every sub-cell of c is free (false outside the map).
  [[nodiscard]] bool cell_free(Cell c) const noexcept {
    return in_cells(c) && free_at(cell_index(c));
  }
  [[nodiscard]] bool marked(SubCell s) const noexcept {
    return ((cell_marks(cell_of(s)) >> quadrant_of(s)) & 1) != 0;
  }
  [[nodiscard]] Byte cell_marks(Cell c) const noexcept {
    return in_cells(c) && s_.marks ? static_cast<Byte>(s_.marks[cell_index(c)] & 0x0Fu) : Byte{0};
  }
  // The 12-bit edge mask of a cell (bits as documented in ant.hpp).
  [[nodiscard]] Word cell_edges(Cell c) const noexcept {
    return in_cells(c) && s_.edges ? static_cast<Word>(s_.edges[cell_index(c)] & 0x0FFFu) : Word{0};
  }

  [[nodiscard]] CellObservation observe_cells() const noexcept {
    const Index i = cell_index(cell_containing(position_));
    unsigned bits = 0;
    for (std::size_t d = 0; d < 4; ++d) bits |= static_cast<unsigned>(free_at(i + offset_[d])) << d;
    return {static_cast<std::uint8_t>(bits)};
  }

  [[nodiscard]] MarkObservation observe_marks() noexcept {
    const Index i = cell_index(cell_containing(position_));
    MarkObservation o;
    const Byte here = s_.marks[i];
    o.here = static_cast<Byte>(here & 0x0Fu);
    Bits free = 0;
    for (std::size_t d = 0; d < 4; ++d) {
      const Byte m = s_.marks[i + offset_[d]];
      o.neighbour[d] = static_cast<Byte>(m & 0x0Fu);
      free |= static_cast<Bits>(m >> kMarkFreeBit) << d;
    }
    o.free_neighbours = static_cast<Byte>(free);
    if (noise_.ppm != 0) {
      o.here = misread(o.here, 4);
      for (auto& m : o.neighbour) m = misread(m, 4);
    }
    return o;
  }

  // Written out beside observe_marks rather than shared as a template over the word type: the
  // shared form measured 12 % slower for ant-edge on 4096^2 (21.2 -> 18.7 M sub-cells/s, same
  // quiet run).
  [[nodiscard]] EdgeObservation observe_edges() noexcept {
    const Index i = cell_index(cell_containing(position_));
    EdgeObservation o;
    const Word here = s_.edges[i];
    o.here = static_cast<Word>(here & 0x0FFFu);
    Bits free = 0;
    for (std::size_t d = 0; d < 4; ++d) {
      const Word e = s_.edges[i + offset_[d]];
      o.neighbour[d] = static_cast<Word>(e & 0x0FFFu);
      free |= static_cast<Bits>(e >> kEdgeFreeBit) << d;
    }
    o.free_neighbours = static_cast<Byte>(free);
    if (noise_.ppm != 0) {
      o.here = misread(o.here, 12);
      for (auto& m : o.neighbour) m = misread(m, 12);
    }
    return o;
  }

  // Lights the edge of sub-cell s (inside the cell area) in direction d. The edge is kept in the
  // 12-bit masks of the cells it belongs to (ant.hpp): an interior edge in its cell only, an
  // exterior edge in both cells it separates.
  void light_edge(SubCell s, int d) noexcept {
    d &= 3;
    const Cell c = cell_containing(s);
    const int e = quadrant_in_cell(s);
    if (!in_cells(c)) return; // two ifs, not ||: the Z3 instantiation's Bool has its own ||
    if (!s_.edges) return;
    auto light = [&](Cell cell, int b) {
      if (in_cells(cell)) s_.edges[cell_index(cell)] |= static_cast<Word>(1u << b);
    };
    if (d == dir_add(e, 2)) {
      light(c, e); // the cross box of e: interior, between e and e - 1
    } else if (d == dir_add(e, 1)) {
      light(c, dir_add(e, 1)); // interior, between e + 1 and e: the cross box of e + 1
    } else if (d == dir_add(e, 3)) {
      light(c, 4 + e); // the turn box of e...
      light(step_towards(c, d),
            8 + dir_add(e, 1)); // ...the own exterior edge of the sub-cell across
    } else {
      light(c, 8 + e);                              // e's own exterior edge (direction e)...
      light(step_towards(c, d), 4 + dir_add(e, 3)); // ...the turn box of the sub-cell across
    }
  }

  // Carries out a command: leaves the mark, then moves. Returns false, without moving, for Stop
  // and for a move off the cell area or into a sub-cell that is not free.
  Bool apply(const Command& command) noexcept {
    if (command.move == Move::Stop) return false;
    const int d = static_cast<int>(command.move);
    const SubCell target = step_towards(position_, d);
    if (!sub_free(target)) return false;
    if (command.mark) {
      if (marker_ == Marker::Edge)
        light_edge(position_, opposite(d)); // the LEDs at the robot's back
      else if (s_.marks)
        s_.marks[cell_index(cell_containing(position_))] |=
            static_cast<Byte>(1u << quadrant_in_cell(position_));
    }
    position_ = target;
    enter(target);
    return true;
  }

private:
  // The layout of a width x height floor over `storage`: the cell grid, the strides and the four
  // neighbour offsets of the cell arrays. Nothing in the arrays is read or written.
  BasicFloorSize<P> layout(Coord width, Coord height, Storage storage, NoiseModel noise,
                           Marker marker) noexcept {
    width_ = width;
    height_ = height;
    const BasicFloorSize<P> size = basic_floor_size<P>(width, height);
    shape_ = size.shape;
    bit_stride_ = static_cast<Index>(2 * shape_.cells_x);
    stride_ = static_cast<Index>(shape_.cells_x) + 2;
    offset_ = {Index{1}, 0 - stride_, 0 - Index{1}, stride_};
    s_ = storage;
    marker_ = marker;
    noise_ = noise;
    stream_ = kernel::Stream(noise.seed, kNoiseExperiment, noise.trial, 0, kNoisePurpose);
    return size;
  }

  // subcell.hpp's cell_of, quadrant_of and step, written over the policy's types (the same
  // arithmetic; the quadrant's two tests fork the Z3 run into its four quadrants).
  [[nodiscard]] static Cell cell_containing(SubCell s) noexcept { return {s.x >> 1, s.y >> 1}; }
  [[nodiscard]] static int quadrant_in_cell(SubCell s) noexcept {
    const auto dx = s.x & 1, dy = s.y & 1;
    // (1,1) SE 0, (1,0) NE 1, (0,0) NW 2, (0,1) SW 3
    return dx != 0 ? (dy != 0 ? 0 : 1) : (dy != 0 ? 3 : 2);
  }
  [[nodiscard]] static SubCell step_towards(SubCell s, int d) noexcept {
    const kernel::Cell o = kernel::kNeighbours4[static_cast<std::size_t>(d)];
    return {s.x + o.x, s.y + o.y};
  }
  [[nodiscard]] Bool in_cells(Cell c) const noexcept {
    return c.x >= 0 && c.y >= 0 && c.x < shape_.cells_x && c.y < shape_.cells_y;
  }

  [[nodiscard]] Index bit_index(SubCell s) const noexcept {
    return static_cast<Index>(s.y) * bit_stride_ + static_cast<Index>(s.x);
  }
  template <class Bytes>
  [[nodiscard]] Bool bit(const Bytes& bits, SubCell s) const noexcept {
    const Index k = bit_index(s);
    const Byte b = bits[k >> 3];
    return ((b >> (k & 7)) & 1) != 0;
  }
  // Index into the cell arrays, which have a one-cell border.
  [[nodiscard]] Index cell_index(Cell c) const noexcept {
    return static_cast<Index>(c.y + 1) * stride_ + static_cast<Index>(c.x + 1);
  }
  [[nodiscard]] unsigned free_at(Index i) const noexcept {
    return s_.marks ? static_cast<unsigned>(s_.marks[i] >> kMarkFreeBit)
                    : static_cast<unsigned>(s_.edges[i] >> kEdgeFreeBit);
  }
  template <class W>
  W misread(W word, int count) noexcept {
    auto bits = static_cast<Bits>(word);
    for (int i = 0; i < count; ++i)
      if (stream_.chance(noise_.ppm, 1'000'000)) bits ^= static_cast<Bits>(1u << i);
    return static_cast<W>(bits);
  }

  void enter(SubCell s) noexcept {
    const Index k = bit_index(s);
    auto&& byte = s_.entered_bits[k >> 3];
    const auto mask = static_cast<Byte>(1u << (k & 7));
    if ((byte & mask) == 0) {
      covered_ += 1;
      byte = static_cast<Byte>(byte | mask);
    } else {
      repeats_ += 1;
    }
  }

  Coord width_ = 0, height_ = 0;
  Shape shape_{};
  Index bit_stride_ = 0;
  Index stride_ = 2;
  std::array<Index, 4> offset_{}; // cell index steps E, N, W, S
  Storage s_{};
  Marker marker_ = Marker::WholeSubCell;
  Count covered_ = 0, repeats_ = 0;
  SubCell position_{};
  NoiseModel noise_{};
  kernel::Stream stream_{0};
};

// The floor every runner steps (StcWorld, the C API, the Cortex-M image).
using Floor = BasicFloor<FloorMachine>;

// ---- the tour's trace hash and the loop that drives a controller --------------------------------
//
// Trace hash (DESIGN.md rule 5), over the canonical little-endian stream:
//   u32 width, u32 height (sub-cells), i32 start.x, i32 start.y, then per position of the tour
//   (the start first) i32 x, i32 y.
// Only positions enter it, so two variants that produce the same tour have the same hash.

[[nodiscard]] constexpr kernel::TraceHash tour_hash_begin(std::int32_t width, std::int32_t height,
                                                          SubCell start) noexcept {
  kernel::TraceHash h;
  h.add_u32(static_cast<std::uint32_t>(width)).add_u32(static_cast<std::uint32_t>(height));
  h.add_i32(start.x).add_i32(start.y);
  return h;
}

constexpr void tour_hash_add(kernel::TraceHash& h, SubCell s) noexcept {
  // The same bytes as add_i32(x), add_i32(y); one aligned word.
  h.add_u64(std::uint64_t{static_cast<std::uint32_t>(s.x)} |
            (std::uint64_t{static_cast<std::uint32_t>(s.y)} << 32));
}

[[nodiscard]] constexpr bool adjacent(SubCell a, SubCell b) noexcept {
  const Cell d = a - b;
  return (d.x == 0 && (d.y == 1 || d.y == -1)) || (d.y == 0 && (d.x == 1 || d.x == -1));
}

// How a driven tour ended.
struct TourEnd {
  std::int64_t moves = 0; // moves made (positions after the start)
  bool closed = false;    // the controller stopped
  bool refused = false;   // the controller asked for a move the floor refused
};

// Drives `controller` from observation to command until it stops, asks for an impossible move, or
// has made max_moves moves. Each position entered is added to `hash` and passed to on_position.
// `World` is the floor or anything with apply() and position(); `observe` returns the controller's
// Observation.
template <class Controller, class Observe, class World, class OnPosition>
TourEnd drive_tour(Controller& controller, Observe&& observe, World& world, kernel::TraceHash& hash,
                   std::int64_t max_moves, OnPosition&& on_position) {
  TourEnd end;
  for (; end.moves < max_moves; ++end.moves) {
    const Command c = controller.step(observe());
    if (c.move == Move::Stop) {
      end.closed = true;
      return end;
    }
    if (!world.apply(c)) {
      end.refused = true;
      return end;
    }
    const SubCell s = world.position();
    tour_hash_add(hash, s);
    on_position(s);
  }
  return end;
}

} // namespace antkit::stc
