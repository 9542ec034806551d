// Fuzz target: the four STC controllers of paper 002 (stc::OnlineStc, AntStc, AntEdgeStc, FullStc)
// fed observations read from the fuzzer's bytes.
//  * online, ant, ant-edge with a body: a sub-cell map read from the bytes and the simulated
//    StcWorld (marks or lit edges, misread with a probability the bytes choose, up to always),
//    with the bytes deciding when the observation lies: free-neighbour bits flipped, all
//    neighbours walls, every mark set, marks contradicting each other.
//  * the same three with no body: every observation straight from the bytes.
//  * full: a sub-cell map and a start read from the bytes (a bad start must be a located
//    kernel::InputError), the tour stepped to its end.
//
// Every step checks the command is valid for the body: a move is East / North / West / South or
// Stop, and once a controller stops it stays stopped; a move that leaves the robot's cell goes in a
// direction the observation reported free (tracked by dead reckoning from the start sub-cell, as
// the controller itself knows nothing of the map); online STC never asks for a mark, and its memory
// grows by at most one tile per step; with a body and no lie about the neighbours' freedom so
// far, the world accepts the move (a free sub-cell inside the cell area); FullStc's moves
// stay on free sub-cells and its tour ends within 4 moves per sub-cell. A twin controller fed the
// same observations must answer the same commands.
#include "fuzz_bytes.hpp"

#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/ant.hpp>
#include <antkit/stc/full.hpp>
#include <antkit/stc/online.hpp>
#include <antkit/stc/subcell.hpp>
#include <antkit/stc/world.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <type_traits>

namespace {

using namespace antkit;
using kernel::Cell;
using stc::Move;

constexpr std::size_t kMaxSteps = 6000;

kernel::OccupancyGrid read_map(fuzzing::Bytes& in, std::int32_t w, std::int32_t h) {
  kernel::OccupancyGrid map(w, h, kernel::Occupancy::Free);
  const unsigned density = in.below(4); // 0: none blocked .. 3: about 3 in 8
  for (std::int32_t y = 0; y < h; ++y)
    for (std::int32_t x = 0; x < w; ++x)
      if (in.below(8) < density)
        map[{x, y}] = in.u8() & 1 ? kernel::Occupancy::Blocked : kernel::Occupancy::Unknown;
  return map;
}

// The dead-reckoned sub-cell of the robot and the commands' checks common to the three
// observation-driven variants. A move that leaves the robot's cell must go in a direction this
// step's observation reports free; online STC, which remembers the cells it has been in, may also
// go back to one of those (it returns to a parent without looking: a static world keeps it free).
class Tracker {
public:
  Tracker(int q0, bool remembers) : at_(stc::subcell_of({0, 0}, q0)), remembers_(remembers) {
    if (remembers_) been_.insert(key({0, 0}));
  }
  void check(const stc::Command& c, std::uint8_t free_neighbours) {
    const auto m = static_cast<unsigned>(c.move);
    ANTKIT_FUZZ_REQUIRE(m <= static_cast<unsigned>(Move::Stop));
    ANTKIT_FUZZ_REQUIRE(!stopped_ || c.move == Move::Stop);
    if (c.move == Move::Stop) {
      stopped_ = true;
      return;
    }
    const int d = static_cast<int>(m);
    const stc::SubCell next = stc::step(at_, d);
    const Cell cell = stc::cell_of(next);
    if (cell != stc::cell_of(at_)) {
      const bool known = remembers_ && been_.count(key(cell)) != 0;
      ANTKIT_FUZZ_REQUIRE(((free_neighbours >> d) & 1) != 0 || known);
      if (remembers_) been_.insert(key(cell));
    }
    at_ = next;
  }

private:
  static std::uint64_t key(Cell c) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.x)) << 32 |
           static_cast<std::uint32_t>(c.y);
  }
  stc::SubCell at_;
  bool remembers_;
  bool stopped_ = false;
  std::set<std::uint64_t> been_;
};

enum class Variant { Online, Ant, AntEdge };

template <class Ctl, class Obs, class Observe, class Lie, class Arbitrary>
void run(fuzzing::Bytes& in, Variant variant, Observe observe, Lie lie, Arbitrary arbitrary) {
  const int q0 = static_cast<int>(in.below(4));
  Ctl a(q0), b(q0);
  Tracker track(q0, variant == Variant::Online);
  std::optional<stc::StcWorld> world;
  if (in.u8() & 1) {
    const auto w = static_cast<std::int32_t>(2 + in.below(30));
    const auto h = static_cast<std::int32_t>(2 + in.below(30));
    auto map = read_map(in, w, h);
    const Cell cell{static_cast<std::int32_t>(in.below(static_cast<unsigned>(w / 2))),
                    static_cast<std::int32_t>(in.below(static_cast<unsigned>(h / 2)))};
    for (int q = 0; q < 4; ++q) map[stc::subcell_of(cell, q)] = kernel::Occupancy::Free;
    stc::NoiseModel noise;
    const unsigned level = in.below(4); // none, 1 %, 50 %, always
    noise.ppm = level == 0 ? 0 : level == 1 ? 10'000 : level == 2 ? 500'000 : 1'000'000;
    noise.seed = in.u8();
    world.emplace(map, stc::subcell_of(cell, q0), noise,
                  variant == Variant::AntEdge ? stc::Marker::Edge : stc::Marker::WholeSubCell);
  }
  std::size_t tiles = 0; // online STC's memory tiles after the last step (or at the start)
  if constexpr (std::is_same_v<Ctl, stc::OnlineStc>) tiles = a.memory().tiles();
  bool desynced = false; // a lie about freedom made the controller and the world part ways
  for (std::size_t step = 0; step < kMaxSteps && !in.empty(); ++step) {
    Obs o{};
    if (world) {
      o = observe(*world);
      desynced = lie(in, o) || desynced;
    } else {
      o = arbitrary(in);
    }
    const stc::Command c = a.step(o);
    ANTKIT_FUZZ_REQUIRE(c == b.step(o));
    track.check(c, o.free_neighbours);
    if constexpr (std::is_same_v<Ctl, stc::OnlineStc>) {
      ANTKIT_FUZZ_REQUIRE(!c.mark);
      ANTKIT_FUZZ_REQUIRE(a.memory().tiles() <= tiles + 1);
      tiles = a.memory().tiles();
    }
    if (c.move == Move::Stop) break;
    if (world) {
      const bool moved = world->apply(c);
      ANTKIT_FUZZ_REQUIRE(moved || desynced);
    }
  }
}

std::uint8_t flip_free(fuzzing::Bytes& in, std::uint8_t bits, bool& lied) {
  switch (in.below(8)) {
  case 0:
    lied = true;
    return static_cast<std::uint8_t>(bits ^ (1u << in.below(4)));
  case 1:
    lied = true;
    return 0; // walls all round
  default:
    return bits;
  }
}

void online(fuzzing::Bytes& in) {
  run<stc::OnlineStc, stc::CellObservation>(
      in, Variant::Online, [](stc::StcWorld& w) { return w.observe_cells(); },
      [](fuzzing::Bytes& b, stc::CellObservation& o) {
        bool lied = false;
        o.free_neighbours = flip_free(b, o.free_neighbours, lied);
        return lied;
      },
      [](fuzzing::Bytes& b) { return stc::CellObservation{static_cast<std::uint8_t>(b.u8())}; });
}

void ant(fuzzing::Bytes& in) {
  run<stc::AntStc, stc::MarkObservation>(
      in, Variant::Ant, [](stc::StcWorld& w) { return w.observe_marks(); },
      [](fuzzing::Bytes& b, stc::MarkObservation& o) {
        bool lied = false;
        o.free_neighbours = flip_free(b, o.free_neighbours, lied);
        switch (b.below(8)) {
        case 0:
          o.here = 0x0F;
          break; // every sub-cell marked
        case 1:
          o.neighbour.fill(0x0F);
          break;
        case 2:
          o.here = static_cast<std::uint8_t>(b.u8());
          break; // bits 4-7 too
        default:
          break;
        }
        return lied;
      },
      [](fuzzing::Bytes& b) {
        stc::MarkObservation o;
        o.free_neighbours = b.u8();
        o.here = b.u8();
        for (auto& m : o.neighbour) m = b.u8();
        return o;
      });
}

void ant_edge(fuzzing::Bytes& in) {
  run<stc::AntEdgeStc, stc::EdgeObservation>(
      in, Variant::AntEdge, [](stc::StcWorld& w) { return w.observe_edges(); },
      [](fuzzing::Bytes& b, stc::EdgeObservation& o) {
        bool lied = false;
        o.free_neighbours = flip_free(b, o.free_neighbours, lied);
        switch (b.below(8)) {
        case 0:
          o.here = 0xFFFF;
          break; // every edge lit, and the unused bits
        case 1:
          o.neighbour[b.below(4)] = b.u16();
          break;
        default:
          break;
        }
        return lied;
      },
      [](fuzzing::Bytes& b) {
        stc::EdgeObservation o;
        o.free_neighbours = b.u8();
        o.here = b.u16();
        for (auto& m : o.neighbour) m = b.u16();
        return o;
      });
}

void full(fuzzing::Bytes& in) {
  const auto w = static_cast<std::int32_t>(1 + in.below(24));
  const auto h = static_cast<std::int32_t>(1 + in.below(24));
  const auto map = read_map(in, w, h);
  // Any start, including off the map, blocked, or in the odd row or column no cell holds.
  const stc::SubCell start{static_cast<std::int32_t>(in.below(28)) - 2,
                           static_cast<std::int32_t>(in.below(28)) - 2};
  std::optional<stc::FullStc> ctl;
  try {
    ctl.emplace(map, start);
  } catch (const kernel::InputError& e) {
    ANTKIT_FUZZ_REQUIRE(!e.where().empty());
    return;
  }
  const std::size_t limit = 4 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h) + 1;
  stc::SubCell at = start;
  for (std::size_t step = 0;; ++step) {
    ANTKIT_FUZZ_REQUIRE(step <= limit);
    const stc::Command c = ctl->step({});
    if (c.move == Move::Stop) break;
    ANTKIT_FUZZ_REQUIRE(static_cast<unsigned>(c.move) <= 3);
    at = stc::step(at, static_cast<int>(c.move));
    ANTKIT_FUZZ_REQUIRE(stc::cell_shape(map).in_bounds(stc::cell_of(at)));
    ANTKIT_FUZZ_REQUIRE(map[at] == kernel::Occupancy::Free);
  }
  for (int k = 0; k < 3; ++k) // stopped for good
    ANTKIT_FUZZ_REQUIRE(ctl->step({}).move == Move::Stop);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzzing::Bytes in(data, size);
  switch (in.below(4)) {
  case 0:
    online(in);
    break;
  case 1:
    ant(in);
    break;
  case 2:
    ant_edge(in);
    break;
  default:
    full(in);
    break;
  }
  return 0;
}
