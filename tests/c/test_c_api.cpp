// The C API (antkit/c/antkit.h) against the C++ it wraps: the same commands from the same readings,
// the same hashes, and a whole tour driven through the C functions over the floor giving run_stc's
// hash and counts on random maps (noisy too).
#include <algorithm>
#include <antkit/buffon/detector.hpp>
#include <antkit/buffon/exploration.hpp>
#include <antkit/c/antkit.h>
#include <antkit/kernel/hash.hpp>
#include <antkit/stc/ant.hpp>
#include <antkit/stc/floor.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/generators.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck/catch.h>
#include <vector>

using namespace antkit;
using namespace antkit::stc;
namespace gen = antkit::testing::gen;

namespace {

// The C ant controller behind the C++ controller interface, for drive_tour.
struct CAnt {
  using Observation = MarkObservation;
  antkit_ant_stc state{};
  explicit CAnt(int q) { antkit_ant_stc_init(&state, q); }
  Command step(const MarkObservation& o) {
    antkit_mark_reading r{o.free_neighbours, o.here, {}};
    for (int d = 0; d < 4; ++d) r.neighbour[d] = o.neighbour[static_cast<std::size_t>(d)];
    const antkit_stc_command c = antkit_ant_stc_step(&state, &r);
    return {static_cast<Move>(c.move), c.mark != 0};
  }
};

struct CAntEdge {
  using Observation = EdgeObservation;
  antkit_ant_edge_stc state{};
  explicit CAntEdge(int q) { antkit_ant_edge_stc_init(&state, q); }
  Command step(const EdgeObservation& o) {
    antkit_edge_reading r{o.free_neighbours, o.here, {}};
    for (int d = 0; d < 4; ++d) r.neighbour[d] = o.neighbour[static_cast<std::size_t>(d)];
    const antkit_stc_command c = antkit_ant_edge_stc_step(&state, &r);
    return {static_cast<Move>(c.move), c.mark != 0};
  }
};

} // namespace

TEST_CASE("C API: the ant controllers give the C++ controllers' commands from any readings",
          "[c][property]") {
  rc::prop("ant and ant-edge, random reading sequences", [] {
    const int q = *rc::gen::inRange(0, 4);
    const auto steps = *rc::gen::inRange(1, 40);
    AntStc ant(q);
    AntEdgeStc edge(q);
    CAnt c_ant(q);
    CAntEdge c_edge(q);
    for (int i = 0; i < steps; ++i) {
      MarkObservation m;
      m.free_neighbours = *rc::gen::inRange<std::uint8_t>(0, 16);
      m.here = *rc::gen::inRange<std::uint8_t>(0, 16);
      for (auto& n : m.neighbour) n = *rc::gen::inRange<std::uint8_t>(0, 16);
      RC_ASSERT(c_ant.step(m) == ant.step(m));
      EdgeObservation e;
      e.free_neighbours = m.free_neighbours;
      e.here = *rc::gen::inRange<std::uint16_t>(0, 4096);
      for (auto& n : e.neighbour) n = *rc::gen::inRange<std::uint16_t>(0, 4096);
      RC_ASSERT(c_edge.step(e) == edge.step(e));
    }
  });
}

TEST_CASE("C API: the trace hash is the kernel's, byte for byte", "[c][property]") {
  rc::prop("random mixes of u8, u32, i32 and u64", [] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto ops =
        *rc::gen::container<std::vector<std::uint64_t>>(rc::gen::arbitrary<std::uint64_t>());
    kernel::TraceHash h(seed);
    antkit_trace_hash c;
    antkit_trace_hash_init(&c, seed);
    for (std::uint64_t v : ops) {
      switch (v % 4) {
      case 0:
        h.add_u8(static_cast<std::uint8_t>(v >> 8));
        antkit_trace_hash_add_u8(&c, static_cast<std::uint8_t>(v >> 8));
        break;
      case 1:
        h.add_u32(static_cast<std::uint32_t>(v >> 8));
        antkit_trace_hash_add_u32(&c, static_cast<std::uint32_t>(v >> 8));
        break;
      case 2:
        h.add_i32(static_cast<std::int32_t>(v >> 16));
        antkit_trace_hash_add_i32(&c, static_cast<std::int32_t>(v >> 16));
        break;
      default:
        h.add_u64(v);
        antkit_trace_hash_add_u64(&c, v);
      }
      RC_ASSERT(antkit_trace_hash_finish(&c) == h.finish());
    }
  });
}

TEST_CASE("C API: a tour driven through the C functions over the floor is run_stc's tour",
          "[c][property]") {
  rc::prop("ant and ant-edge on random maps, with and without marker noise", [] {
    const auto [map, start] = *gen::stc_case({.partial_cells = true, .start_in_free_cell = true});
    const bool edge = *rc::gen::arbitrary<bool>();
    const std::uint32_t ppm = *rc::gen::element<std::uint32_t>(0, 0, 20'000, 300'000);
    const NoiseModel noise{ppm, *rc::gen::inRange<std::uint64_t>(0, 1000), 0};
    RunOptions options;
    options.noise = noise;
    const RunResult expected = run_stc(map, start, edge ? Variant::AntEdge : Variant::Ant, options);

    const FloorSize size = floor_size(map.width(), map.height());
    std::vector<std::uint8_t> free_bits(size.bit_bytes), entered(size.bit_bytes);
    std::vector<std::uint8_t> marks(size.cells);
    std::vector<std::uint16_t> edges(size.cells);
    fill_free_bits(map, free_bits);
    Floor floor;
    floor.reset(map.width(), map.height(),
                {free_bits.data(), entered.data(), edge ? nullptr : marks.data(),
                 edge ? edges.data() : nullptr},
                start, noise, edge ? Marker::Edge : Marker::WholeSubCell);
    antkit_trace_hash h;
    antkit_stc_tour_hash_begin(&h, map.width(), map.height(), start.x, start.y);
    antkit_stc_tour_hash_add(&h, start.x, start.y);
    kernel::TraceHash unused;
    const std::int64_t max_moves = 16 * std::int64_t{map.width()} * map.height() + 16;
    TourEnd end;
    auto on = [&](SubCell s) { antkit_stc_tour_hash_add(&h, s.x, s.y); };
    if (edge) {
      CAntEdge c(antkit_stc_quadrant(start.x, start.y));
      end = drive_tour(
          c, [&] { return floor.observe_edges(); }, floor, unused, max_moves, on);
    } else {
      CAnt c(antkit_stc_quadrant(start.x, start.y));
      end = drive_tour(
          c, [&] { return floor.observe_marks(); }, floor, unused, max_moves, on);
    }
    RC_ASSERT(antkit_trace_hash_finish(&h) == expected.hash);
    RC_ASSERT(end.moves + 1 == expected.positions);
    RC_ASSERT(end.closed == expected.closed);
    RC_ASSERT(floor.covered() == expected.covered);
    RC_ASSERT(floor.repeats() == expected.repeats);
  });
}

TEST_CASE("C API: a tour run entirely through C functions (floor, controller, hash) is antkit "
          "stc's",
          "[c][property]") {
  rc::prop("ant and ant-edge on random maps", [] {
    const auto [map, start] = *gen::stc_case({.partial_cells = true, .start_in_free_cell = true});
    const bool edge = *rc::gen::arbitrary<bool>();
    const RunResult expected = run_stc(map, start, edge ? Variant::AntEdge : Variant::Ant);
    const int marker = edge ? ANTKIT_MARKER_EDGE : ANTKIT_MARKER_SUBCELL;
    const std::size_t bytes = antkit_stc_floor_bytes(map.width(), map.height(), marker);
    RC_ASSERT(bytes > 0);
    std::vector<std::uint64_t> buffer((bytes + 7) / 8);
    antkit_stc_floor floor;
    RC_ASSERT(antkit_stc_floor_init(&floor, buffer.data(), bytes - 1, map.width(), map.height(),
                                    marker) == -1); // one byte short
    RC_ASSERT(antkit_stc_floor_init(&floor, buffer.data(), bytes, map.width(), map.height(),
                                    marker) == 0);
    for (std::int32_t y = 0; y < map.height(); ++y)
      for (std::int32_t x = 0; x < map.width(); ++x)
        if (map[{x, y}] == kernel::Occupancy::Free) antkit_stc_floor_set_free(&floor, x, y);
    RC_ASSERT(antkit_stc_floor_start(&floor, start.x, start.y) == 0);
    antkit_trace_hash h;
    antkit_stc_tour_hash_begin(&h, map.width(), map.height(), start.x, start.y);
    antkit_stc_tour_hash_add(&h, start.x, start.y);
    antkit_ant_stc ant;
    antkit_ant_edge_stc ant_edge;
    antkit_ant_stc_init(&ant, antkit_stc_quadrant(start.x, start.y));
    antkit_ant_edge_stc_init(&ant_edge, antkit_stc_quadrant(start.x, start.y));
    std::int64_t positions = 1;
    for (;;) {
      antkit_stc_command c;
      if (edge) {
        antkit_edge_reading r;
        antkit_stc_floor_read_edges(&floor, &r);
        c = antkit_ant_edge_stc_step(&ant_edge, &r);
      } else {
        antkit_mark_reading r;
        antkit_stc_floor_read_marks(&floor, &r);
        c = antkit_ant_stc_step(&ant, &r);
      }
      if (c.move == ANTKIT_STOP) break;
      RC_ASSERT(antkit_stc_floor_apply(&floor, c) == 1);
      std::int32_t x = 0, y = 0;
      antkit_stc_floor_position(&floor, &x, &y);
      antkit_stc_tour_hash_add(&h, x, y);
      ++positions;
      RC_ASSERT(positions <= expected.positions);
    }
    RC_ASSERT(antkit_trace_hash_finish(&h) == expected.hash);
    RC_ASSERT(positions == expected.positions);
    RC_ASSERT(antkit_stc_floor_covered(&floor) == expected.covered);
    RC_ASSERT(antkit_stc_floor_repeats(&floor) == expected.repeats);
  });
}

TEST_CASE("C API: the floor refuses what it cannot hold", "[c]") {
  CHECK(antkit_stc_floor_bytes(1, 10, ANTKIT_MARKER_SUBCELL) == 0);
  CHECK(antkit_stc_floor_bytes(10, 16385, ANTKIT_MARKER_EDGE) == 0);
  CHECK(antkit_stc_floor_bytes(10, 10, 7) == 0);
  // 10 x 10 sub-cells: 25 cells, 13 bytes per bit array, 49 cells with the border.
  CHECK(antkit_stc_floor_bytes(10, 10, ANTKIT_MARKER_SUBCELL) == 32 + 49);
  CHECK(antkit_stc_floor_bytes(10, 10, ANTKIT_MARKER_EDGE) == 32 + 98);
  alignas(8) std::uint8_t buffer[256];
  antkit_stc_floor floor;
  CHECK(antkit_stc_floor_init(&floor, buffer + 1, 200, 10, 10, ANTKIT_MARKER_SUBCELL) == -1);
  REQUIRE(antkit_stc_floor_init(&floor, buffer, sizeof buffer, 10, 10, ANTKIT_MARKER_SUBCELL) == 0);
  CHECK(antkit_stc_floor_start(&floor, 2, 2) == -1); // every sub-cell still blocked
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) antkit_stc_floor_set_free(&floor, x, y);
  antkit_stc_floor_set_free(&floor, 99, 99); // ignored
  CHECK(antkit_stc_floor_start(&floor, 4, 4) == -1);
  CHECK(antkit_stc_floor_start(&floor, 20, 0) == -1);
  REQUIRE(antkit_stc_floor_start(&floor, 0, 0) == 0);
  CHECK(antkit_stc_floor_apply(&floor, {ANTKIT_WEST, 0}) == 0); // off the map
  CHECK(antkit_stc_floor_apply(&floor, {ANTKIT_STOP, 0}) == 0);
  CHECK(antkit_stc_floor_apply(&floor, {ANTKIT_EAST, 1}) == 1);
  std::int32_t x = -1, y = -1;
  antkit_stc_floor_position(&floor, &x, &y);
  CHECK((x == 1 && y == 0));
  CHECK(antkit_stc_floor_covered(&floor) == 2);
}

namespace {

// Online STC through the C API over the C floor, from `start`, with a memory of `tiles` tiles;
// the positions of the tour, the start first.
std::vector<SubCell> online_tour(const kernel::OccupancyGrid& map, SubCell start, std::size_t tiles,
                                 bool& overflowed) {
  const std::size_t bytes =
      antkit_stc_floor_bytes(map.width(), map.height(), ANTKIT_MARKER_SUBCELL);
  std::vector<std::uint64_t> floor_buffer((bytes + 7) / 8);
  antkit_stc_floor floor;
  REQUIRE(antkit_stc_floor_init(&floor, floor_buffer.data(), bytes, map.width(), map.height(),
                                ANTKIT_MARKER_SUBCELL) == 0);
  for (std::int32_t y = 0; y < map.height(); ++y)
    for (std::int32_t x = 0; x < map.width(); ++x)
      if (map[{x, y}] == kernel::Occupancy::Free) antkit_stc_floor_set_free(&floor, x, y);
  REQUIRE(antkit_stc_floor_start(&floor, start.x, start.y) == 0);
  std::vector<std::uint64_t> memory((antkit_online_stc_bytes(tiles) + 7) / 8);
  antkit_online_stc online;
  REQUIRE(antkit_online_stc_init(&online, memory.data(), memory.size() * 8,
                                 antkit_stc_quadrant(start.x, start.y)) == 0);
  REQUIRE(antkit_online_stc_capacity(&online) == tiles);
  std::vector<SubCell> path{start};
  for (;;) {
    antkit_cell_reading r;
    antkit_stc_floor_read_cells(&floor, &r);
    const antkit_stc_command c = antkit_online_stc_step(&online, &r);
    if (c.move == ANTKIT_STOP) break;
    REQUIRE(antkit_stc_floor_apply(&floor, c) == 1);
    std::int32_t x = 0, y = 0;
    antkit_stc_floor_position(&floor, &x, &y);
    path.push_back({x, y});
  }
  overflowed = antkit_online_stc_overflowed(&online) != 0;
  CHECK(antkit_online_stc_tiles(&online) <= tiles);
  return path;
}

} // namespace

TEST_CASE("C API: online STC in a fixed memory takes the host's tour while it has room, and "
          "stops when it has none",
          "[c][property]") {
  rc::prop("random maps, enough tiles and one tile", [] {
    const auto [map, start] = *gen::stc_case({.partial_cells = true, .start_in_free_cell = true});
    const RunResult expected = run_stc(map, start, Variant::Online);
    const auto cells_x = static_cast<std::size_t>(map.width() / 2);
    const auto cells_y = static_cast<std::size_t>(map.height() / 2);
    bool overflowed = true;
    const auto full = online_tour(map, start, (cells_x / 16 + 2) * (cells_y / 16 + 2), overflowed);
    RC_ASSERT(!overflowed);
    RC_ASSERT(full == expected.path);
    // One tile: a prefix of the same tour, and overflowed exactly when the tour left the tile.
    const auto short_tour = online_tour(map, start, 1, overflowed);
    RC_ASSERT(short_tour.size() <= full.size());
    RC_ASSERT(std::equal(short_tour.begin(), short_tour.end(), full.begin()));
    RC_ASSERT(overflowed == (short_tour.size() < full.size()));
  });
}

TEST_CASE("C API: online STC on a map wider than its memory stops with overflowed", "[c]") {
  kernel::OccupancyGrid map(80, 4, kernel::Occupancy::Free); // 40 x 2 cells: three tiles wide
  bool overflowed = false;
  const auto tour = online_tour(map, {0, 0}, 1, overflowed);
  CHECK(overflowed);
  CHECK(tour.size() < 160);
  CHECK(antkit_online_stc_bytes(1) == 256 + 2 * 12);
  CHECK(antkit_online_stc_bytes(3) == 3 * 256 + 8 * 12);
  antkit_online_stc online;
  std::uint64_t too_small[4];
  CHECK(antkit_online_stc_init(&online, too_small, sizeof too_small, 0) == -1);
}

TEST_CASE("C API: the Buffon behaviour and detector are the C++ ones, step for step",
          "[c][property]") {
  rc::prop("random readings and pheromone bits", [] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto trial = *rc::gen::inRange<std::uint64_t>(0, 100);
    const auto robot = *rc::gen::inRange<std::uint64_t>(1, 3);
    antkit::buffon::ExplorationBehaviour cpp(antkit::kernel::Stream(seed, 4, trial, robot, 0));
    antkit_buffon_behaviour c;
    antkit_buffon_behaviour_init(&c, seed, 4, trial, robot);
    antkit::buffon::CrossingDetector cpp_detector;
    antkit_buffon_detector c_detector;
    antkit_buffon_detector_init(&c_detector);
    const auto steps = *rc::gen::inRange(1, 60);
    for (int i = 0; i < steps; ++i) {
      antkit::buffon::Observation obs;
      antkit_ir_reading reading;
      for (std::size_t k = 0; k < 6; ++k) {
        // Mostly far from walls (0), sometimes a wall in range.
        const std::int32_t v = *rc::gen::weightedOneOf<std::int32_t>(
            {{3, rc::gen::just(0)}, {2, rc::gen::inRange(0, 65537)}});
        obs.ir[k] = antkit::kernel::Fx::from_raw(v);
        reading.ir[k] = v;
      }
      const antkit::buffon::Command want = cpp.step(obs);
      const antkit_wheel_command got = antkit_buffon_behaviour_step(&c, &reading);
      RC_ASSERT(got.left == want.left.raw());
      RC_ASSERT(got.right == want.right.raw());
      const bool bit = *rc::gen::arbitrary<bool>();
      RC_ASSERT(antkit_buffon_detector_update(&c_detector, bit ? 1 : 0) ==
                (cpp_detector.update(bit) ? 1 : 0));
    }
  });
}
