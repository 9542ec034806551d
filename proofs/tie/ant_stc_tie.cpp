// The tie between the Coq proof of ant-like STC and the shipped code (issue 28).
//
//   proof_tie_ant_stc decide GOLDEN [--flip-table K | --flip-code K]
//     GOLDEN is proofs/golden/AntDecide.out: the decision table coqc computes from AntDecide.v's
//     `decide`, the function AntStcWorld.v proves covers every map. Requires the shipped
//     stc::ant_decide to give the table's decision on its whole domain: every current quadrant,
//     both values of `done`, and every 4-bit free mask, here mask and mask of each of the four
//     neighbours (4 x 2 x 16^6 = 134 217 728 inputs, every observation Floor::observe_marks can
//     produce). The table is indexed by the reduction AntDecide.v proves `decide` reads its input
//     through (decide_reads_the_view, decide_view_ext; decide_done for `done`).
//
//   proof_tie_ant_stc world|world-edge GOLDEN [--drop-mark K]
//     The world step. The shipped world (stc::Floor, the floor StcWorld, the C API and the
//     Cortex-M image step, over a buffer of this program's, driven by drive_tour as run_stc drives
//     it, with AntStc or AntEdgeStc) against AntStcWorld.v's world `run`, transcribed below
//     (observe the five cells' marks; decide; Stop ends the run; a move into a cell that is not
//     free is refused; otherwise mark the sub-cell left and move one sub-cell), the model using
//     the Coq table's decisions rather than the shipped ant_decide. On every cell map of up to 12
//     cells in a box of up to 4 x 4 cells, from every start sub-cell, they must agree on every
//     position, on the marks of every cell after every move (for world-edge: what the edge rule
//     reads from the lit edges), on the covered and repeat counts after every move, on how the run
//     ends and on the trace hash (the model hashes the stream floor.hpp documents, field by field).
//     Each map and start is run four times: as it is, with an odd last column, an odd last row,
//     and both (outside the cell area: floor.hpp's layout then differs from a plain width x height
//     one); in about half the runs (a fixed function of the map, the start and the size) every
//     cell that is not free has a random set of free sub-cells, never all four (a partly free
//     cell, which the floor must treat as not free). proofs/z3/stc_floor.cpp proves the step about
//     the same source on every map; this tie is the correspondence run end to end, reset()
//     included.
// The teeth (ctest proof.teeth.*): --flip-table K changes the K-th table entry, --flip-code K
// changes the shipped decision on the K-th input, --drop-mark K makes the shipped world forget the
// mark of its K-th move. Each must make the check fail (exit 1, "MISMATCH ..."); the tests pass
// only then.
#include "ant_decide_table.hpp"

#include <antkit/kernel/grid.hpp>
#include <antkit/stc/ant.hpp>
#include <antkit/stc/floor.hpp>
#include <antkit/stc/world.hpp>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace antkit::stc;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;

// ---- the decision table -----------------------------------------------------------------------

// The table and the reduction: ant_decide_table.hpp.
using namespace antkit::proofs;

char flipped(char c) {
  // Any other valid entry: Stop becomes a walk east into quadrant 0, a move becomes Stop.
  return c == '.' ? 'a' : '.';
}

int check_decide(const std::string& golden, long long flip_table, long long flip_code) {
  auto table = read_table(golden);
  if (!table) {
    std::fprintf(stderr, "error: %s: expected four strings of 8192 entries (Compute table ...)\n",
                 golden.c_str());
    return 2;
  }
  if (flip_table >= 0) {
    auto& s = (*table)[static_cast<std::size_t>(flip_table / 8192) % 4];
    char& c = s[static_cast<std::size_t>(flip_table % 8192)];
    c = flipped(c);
    std::printf("teeth: table entry %lld flipped\n", flip_table);
  }
  long long inputs = 0, mismatches = 0;
  for (int cur = 0; cur < 4; ++cur)
    for (int done_in = 0; done_in < 2; ++done_in)
      for (int free = 0; free < 16; ++free)
        for (int here = 0; here < 16; ++here)
          for (std::uint32_t nbs = 0; nbs < (1u << 16); ++nbs) {
            const std::array<std::uint8_t, 4> nb{static_cast<std::uint8_t>(nbs & 15),
                                                 static_cast<std::uint8_t>((nbs >> 4) & 15),
                                                 static_cast<std::uint8_t>((nbs >> 8) & 15),
                                                 static_cast<std::uint8_t>((nbs >> 12) & 15)};
            int q = cur;
            bool done = done_in != 0;
            Command got = ant_decide(q, done, static_cast<std::uint8_t>(free),
                                     static_cast<std::uint8_t>(here), nb);
            if (inputs == flip_code) {
              got = got.move == Move::Stop ? Command{Move::East, true} : Command{};
              std::printf("teeth: the shipped decision on input %lld flipped\n", flip_code);
            }
            // decide_done: with done set, Stop. Otherwise the table's entry.
            const Expected want =
                done_in
                    ? Expected{}
                    : decode((
                          *table)[static_cast<std::size_t>(cur)][table_index(here, free, nb, cur)]);
            const bool ok =
                want.stop ? (got == Command{} && done && q == cur)
                          : (got == Command{move_towards(want.move), true} && !done && q == want.q);
            if (!ok && ++mismatches <= 5)
              std::printf(
                  "MISMATCH decide: quadrant %d, done %d, free %d, here %d, neighbours "
                  "%d %d %d %d: the proof's decide says %s, the shipped ant_decide "
                  "returns move %d mark %d, quadrant %d, done %d\n",
                  cur, done_in, free, here, nb[0], nb[1], nb[2], nb[3],
                  want.stop
                      ? "Stop"
                      : ("Go " + std::to_string(want.move) + " " + std::to_string(want.q)).c_str(),
                  static_cast<int>(got.move), got.mark ? 1 : 0, q, done ? 1 : 0);
            ++inputs;
          }
  std::printf("decide: %lld inputs, %lld mismatches\n", inputs, mismatches);
  return mismatches == 0 ? 0 : 1;
}

// ---- the world step ---------------------------------------------------------------------------

// AntStcWorld.v's world (`run`), transcribed: free cells, marks per sub-cell, the robot's sub-cell
// and the controller's quadrant. Its decisions come from the Coq table, not from the shipped code.
enum class Outcome { Moved, Stopped, Refused };

class ModelWorld {
public:
  // A map of cells_x x cells_y cells inside a width x height sub-cell map (an odd last column or
  // row lies outside the cell area); free_mask: the free cells (bit y * cells_x + x).
  ModelWorld(int width, int height, int cells_x, int cells_y, std::uint32_t free_mask,
             SubCell start, const std::array<std::string, 4>& table)
      : cx_(cells_x), cy_(cells_y), width_(width), free_(free_mask), pos_(start),
        q_(quadrant_of(start)), table_(table),
        marks_(static_cast<std::size_t>(cells_x * cells_y), 0),
        entered_(static_cast<std::size_t>(width * height), 0) {
    // The trace hash as floor.hpp documents it: u32 width, u32 height, i32 start.x, i32 start.y,
    // then i32 x, i32 y per position, the start first (written here field by field).
    hash_.add_u32(static_cast<std::uint32_t>(width)).add_u32(static_cast<std::uint32_t>(height));
    hash_.add_i32(start.x).add_i32(start.y);
    enter(start);
  }

  bool free_cell(Cell c) const {
    return c.x >= 0 && c.y >= 0 && c.x < cx_ && c.y < cy_ && ((free_ >> (c.y * cx_ + c.x)) & 1);
  }
  // Bit q: sub-cell q of cell c is marked (0 outside the map).
  std::uint8_t marks(Cell c) const {
    if (c.x < 0 || c.y < 0 || c.x >= cx_ || c.y >= cy_) return 0;
    return marks_[static_cast<std::size_t>(c.y * cx_ + c.x)];
  }
  SubCell position() const { return pos_; }
  // Sub-cells entered at least once, entries into one entered before, and the trace hash.
  std::int64_t covered() const { return covered_; }
  std::int64_t repeats() const { return repeats_; }
  std::uint64_t hash() const { return hash_.finish(); }

  // One step of `run`: Stop ends the run; a move into a cell that is not free is refused (before
  // anything is marked); otherwise the sub-cell left is marked and the robot moves.
  Outcome step() {
    const Cell c = cell_of(pos_);
    int free = 0;
    std::array<std::uint8_t, 4> nb{};
    for (int d = 0; d < 4; ++d) {
      const Cell n = antkit::stc::step(c, d);
      if (!free_cell(n)) continue;
      free |= 1 << d;
      nb[static_cast<std::size_t>(d)] = marks(n);
    }
    const Expected x =
        decode(table_[static_cast<std::size_t>(q_)][table_index(marks(c), free, nb, q_)]);
    if (x.stop) return Outcome::Stopped;
    const SubCell target = antkit::stc::step(pos_, x.move);
    if (!free_cell(cell_of(target))) return Outcome::Refused;
    marks_[static_cast<std::size_t>(c.y * cx_ + c.x)] =
        static_cast<std::uint8_t>(marks(c) | (1u << quadrant_of(pos_)));
    pos_ = target;
    q_ = x.q;
    enter(target);
    return Outcome::Moved;
  }
  int believed_quadrant() const { return q_; }

private:
  void enter(SubCell s) {
    hash_.add_i32(s.x).add_i32(s.y);
    auto& e = entered_[static_cast<std::size_t>(s.y * width_ + s.x)];
    if (e != 0) {
      ++repeats_;
    } else {
      ++covered_;
      e = 1;
    }
  }

  int cx_, cy_, width_;
  std::uint32_t free_;
  SubCell pos_;
  int q_;
  const std::array<std::string, 4>& table_;
  std::vector<std::uint8_t> marks_;
  std::vector<std::uint8_t> entered_;
  std::int64_t covered_ = 0, repeats_ = 0;
  antkit::kernel::TraceHash hash_;
};

// The shipped floor (the one StcWorld, the C API and the Cortex-M image run), over a buffer of
// our own so that the teeth can reach into its marks. drive_tour calls apply() and position().
class ShippedWorld {
public:
  // The map: width x height sub-cells (2 cells_x + 0 or 1 by 2 cells_y + 0 or 1); the cells in
  // free_mask are free; every other cell of the grid has the free sub-cells of its 4-bit pattern
  // in `partial` (bit q: sub-cell q; never all four), so it is not free but may be partly.
  ShippedWorld(int width, int height, int cells_x, int cells_y, std::uint32_t free_mask,
               std::uint64_t partial, SubCell start, Marker marker, long long drop_mark)
      : width_(width), height_(height), marker_(marker),
        buffer_((floor_bytes(width_, height_, marker) + 7) / 8),
        storage_(floor_storage(buffer_.data(), width_, height_, marker)),
        stride_(static_cast<std::size_t>(cells_x) + 2), drop_mark_(drop_mark) {
    const FloorSize size = floor_size(width_, height_);
    for (std::size_t i = 0; i < size.bit_bytes; ++i) storage_.free_bits[i] = 0;
    for (int cy = 0; cy < cells_y; ++cy)
      for (int cx = 0; cx < cells_x; ++cx) {
        const int j = cy * cells_x + cx;
        const unsigned free_subcells =
            ((free_mask >> j) & 1) != 0 ? 15u : static_cast<unsigned>((partial >> (4 * j)) & 15);
        for (int q = 0; q < 4; ++q) {
          if (((free_subcells >> q) & 1) == 0) continue;
          // floor.hpp's layout of free_bits: row-major over the cell area, 2 cells_x bits a row.
          const SubCell s = subcell_of({cx, cy}, q);
          const auto k = static_cast<std::size_t>(s.y * 2 * cells_x + s.x);
          storage_.free_bits[k >> 3] =
              static_cast<std::uint8_t>(storage_.free_bits[k >> 3] | (1u << (k & 7)));
        }
      }
    floor_.reset(width_, height_, storage_, start, NoiseModel{}, marker);
  }

  MarkObservation observe_marks() { return floor_.observe_marks(); }
  EdgeObservation observe_edges() { return floor_.observe_edges(); }
  bool apply(const Command& c) {
    const SubCell left = floor_.position();
    const bool moved = floor_.apply(c);
    if (moved && moves_++ == drop_mark_) {
      // The teeth: forget the mark just left (floor.hpp's layout: one entry per cell, a border of
      // one cell; bit q for sub-cell q's mark, or, for edges, the edge lit behind the robot, which
      // is one of the two boxes the edge rule reads for sub-cell q).
      const Cell cell = cell_of(left);
      const std::size_t i =
          static_cast<std::size_t>(cell.y + 1) * stride_ + static_cast<std::size_t>(cell.x + 1);
      const int q = quadrant_of(left);
      if (storage_.marks)
        storage_.marks[i] = static_cast<std::uint8_t>(storage_.marks[i] & ~(1u << q));
      else
        storage_.edges[i] =
            static_cast<std::uint16_t>(storage_.edges[i] & ~((1u << q) | (1u << (4 + q))));
      static bool told = false;
      if (!told) std::printf("teeth: the shipped world drops the mark of move %lld\n", drop_mark_);
      told = true;
    }
    return moved;
  }
  SubCell position() const { return floor_.position(); }
  std::int64_t covered() const { return floor_.covered(); }
  std::int64_t repeats() const { return floor_.repeats(); }
  // The sub-cells of cell c that count as covered (bit q): their marks, or (edges) what the
  // edge rule reads from the cell's lit edges.
  std::uint8_t marks(Cell c) const {
    if (marker_ == Marker::WholeSubCell) return floor_.cell_marks(c);
    return covered_from_edges(floor_.cell_edges(c));
  }

private:
  std::int32_t width_, height_;
  Marker marker_;
  std::vector<std::uint64_t> buffer_;
  FloorStorage storage_;
  Floor floor_;
  std::size_t stride_;
  long long drop_mark_;
  long long moves_ = 0;
};

// A map of the world tie: its cells (free_mask over a cells_x x cells_y grid), and how it is
// dressed: an odd last column and row (outside the cell area) and partly free cells.
struct WorldMap {
  int cells_x = 1, cells_y = 1;
  std::uint32_t free_mask = 1;
  int odd_x = 0, odd_y = 0;  // width = 2 cells_x + odd_x, height = 2 cells_y + odd_y
  std::uint64_t partial = 0; // free sub-cells of the cells that are not free (4 bits a cell)
  int width() const { return 2 * cells_x + odd_x; }
  int height() const { return 2 * cells_y + odd_y; }
};

// One run of each world from one start; returns a description of the first difference.
std::optional<std::string> compare_run(const WorldMap& map, SubCell start,
                                       const std::array<std::string, 4>& table, Marker marker,
                                       long long drop_mark) {
  const int cw = map.cells_x, ch = map.cells_y;
  ShippedWorld shipped(map.width(), map.height(), cw, ch, map.free_mask, map.partial, start, marker,
                       drop_mark);
  ModelWorld model(map.width(), map.height(), cw, ch, map.free_mask, start, table);
  // As run_stc and the Cortex-M image hash a tour: the header, then the start as its first
  // position, then drive_tour adds each position entered.
  antkit::kernel::TraceHash hash = tour_hash_begin(map.width(), map.height(), start);
  tour_hash_add(hash, start);
  std::optional<std::string> diff;
  long long move = 0;
  const std::int64_t max_moves = 4LL * 4 * cw * ch + 4;
  auto on_position = [&](SubCell s) {
    ++move;
    if (diff) return;
    if (model.step() != Outcome::Moved) {
      diff =
          "move " + std::to_string(move) + ": the model stops or refuses, the shipped robot moves";
      return;
    }
    if (model.position() != s || model.believed_quadrant() != quadrant_of(s)) {
      diff = "move " + std::to_string(move) + ": positions differ";
      return;
    }
    if (model.covered() != shipped.covered() || model.repeats() != shipped.repeats()) {
      diff = "move " + std::to_string(move) + ": covered/repeats " +
             std::to_string(shipped.covered()) + "/" + std::to_string(shipped.repeats()) +
             ", the model's " + std::to_string(model.covered()) + "/" +
             std::to_string(model.repeats());
      return;
    }
    for (int y = 0; y < ch; ++y)
      for (int x = 0; x < cw; ++x)
        if (model.marks({x, y}) != shipped.marks({x, y})) {
          diff = "move " + std::to_string(move) + ": the marks of cell (" + std::to_string(x) +
                 ", " + std::to_string(y) + ") differ";
          return;
        }
  };
  if (model.covered() != shipped.covered() || model.repeats() != shipped.repeats())
    return "the counts after entering the start differ";
  TourEnd end;
  if (marker == Marker::WholeSubCell) {
    AntStc controller(quadrant_of(start));
    end = drive_tour(
        controller, [&] { return shipped.observe_marks(); }, shipped, hash, max_moves, on_position);
  } else {
    AntEdgeStc controller(quadrant_of(start));
    end = drive_tour(
        controller, [&] { return shipped.observe_edges(); }, shipped, hash, max_moves, on_position);
  }
  if (diff) return diff;
  if (!end.closed && !end.refused) return "the shipped robot did not stop";
  const Outcome last = model.step();
  if (end.closed && last != Outcome::Stopped) return "the shipped robot stops, the model does not";
  if (end.refused && last != Outcome::Refused)
    return "the shipped floor refuses a move, the model does not";
  // Both refusing would be agreement on the world step, and a failure of the theorem.
  if (end.refused) return "both worlds refuse a move";
  if (hash.finish() != model.hash()) return "the trace hashes differ";
  return std::nullopt;
}

// splitmix64: the dressing of each run, a fixed function of the map and the start.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

int check_world(const std::string& golden, Marker marker, long long drop_mark) {
  const auto table = read_table(golden);
  if (!table) {
    std::fprintf(stderr, "error: %s: expected four strings of 8192 entries\n", golden.c_str());
    return 2;
  }
  long long runs = 0, mismatches = 0, odd = 0, partly = 0;
  for (int cw = 1; cw <= 4; ++cw)
    for (int ch = 1; ch <= 4; ++ch) {
      if (cw * ch > 12) continue;
      for (std::uint32_t mask = 1; mask < (1u << (cw * ch)); ++mask)
        for (int i = 0; i < cw * ch; ++i) {
          if (((mask >> i) & 1) == 0) continue;
          for (int q = 0; q < 4; ++q)
            for (int v = 0; v < 4; ++v) {
              // Each map and start is run four times: the cell area alone, with an odd last column,
              // with an odd last row, with both. In about half the runs (a fixed function of the
              // map, the start and v) every cell that is not free has a random set of free
              // sub-cells, never all four.
              const std::uint64_t h =
                  mix((std::uint64_t{mask} << 16) ^ (std::uint64_t(cw * 4 + ch) << 8) ^
                      static_cast<std::uint64_t>(i * 4 + q));
              WorldMap map;
              map.cells_x = cw;
              map.cells_y = ch;
              map.free_mask = mask;
              map.odd_x = v & 1;
              map.odd_y = v >> 1;
              if (((h >> v) & 1) != 0) {
                const std::uint64_t bits = mix(h + static_cast<std::uint64_t>(v));
                for (int j = 0; j < cw * ch; ++j) {
                  std::uint64_t pattern = (bits >> (4 * j)) & 15;
                  if (pattern == 15) pattern = 7; // never all four: the cell is not free
                  if (((mask >> j) & 1) == 0) map.partial |= pattern << (4 * j);
                }
              }
              odd += (map.odd_x | map.odd_y) != 0 ? 1 : 0;
              partly += map.partial != 0 ? 1 : 0;
              const SubCell start = subcell_of({i % cw, i / cw}, q);
              const auto diff = compare_run(map, start, *table, marker, drop_mark);
              ++runs;
              if (diff && ++mismatches <= 5)
                std::printf(
                    "MISMATCH world: %d x %d sub-cells (%d x %d cells), free mask %u, partly "
                    "free %llx, start (%d, %d): %s\n",
                    map.width(), map.height(), cw, ch, mask,
                    static_cast<unsigned long long>(map.partial), start.x, start.y, diff->c_str());
            }
        }
    }
  std::printf("world (%s): %lld runs (%lld with an odd width or height, %lld with partly free "
              "cells), %lld mismatches\n",
              marker == Marker::Edge ? "ant-edge" : "ant", runs, odd, partly, mismatches);
  return mismatches == 0 ? 0 : 1;
}

int usage() {
  std::fprintf(stderr, "usage: proof_tie_ant_stc decide GOLDEN [--flip-table K | --flip-code K]\n"
                       "       proof_tie_ant_stc world|world-edge GOLDEN [--drop-mark K]\n");
  return 2;
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string mode = argv[1], golden = argv[2];
  long long flip_table = -1, flip_code = -1, drop_mark = -1;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string opt = argv[i];
    char* end = nullptr;
    const long long v = std::strtoll(argv[i + 1], &end, 10);
    if (*end != '\0' || v < 0) return usage();
    if (opt == "--flip-table")
      flip_table = v;
    else if (opt == "--flip-code")
      flip_code = v;
    else if (opt == "--drop-mark")
      drop_mark = v;
    else
      return usage();
  }
  if (argc % 2 == 0) return usage();
  if (mode == "decide") return check_decide(golden, flip_table, flip_code);
  if (mode == "world") return check_world(golden, Marker::WholeSubCell, drop_mark);
  if (mode == "world-edge") return check_world(golden, Marker::Edge, drop_mark);
  return usage();
}
